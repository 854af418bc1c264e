//! The scene model: plain data that the language produces and that a library user could
//! build by hand. Every transform is already baked into world space here (the evaluator
//! composes transforms as it meets them), so the renderer never has to replay modifier order.
//! Nothing in this module knows how to render.

mod camera;
mod fog;
mod julia;
mod light;
mod media;
mod object;
pub mod path_spline;
mod photons;
mod radiosity;
mod rainbow;
pub mod spline;
pub mod text;
mod texture;

pub use camera::{
    Camera, CameraFace, CameraMesh, CameraSpec, MeshCamera, MeshDistribution, MeshView, Projection,
};
pub use fog::{Fog, FogKind, FogTurbulence};
pub use julia::{JuliaAlgebra, JuliaFractal, JuliaFunction};
pub use light::{AreaLight, Light, LightKind};
pub use media::{Media, MediaSampling, Phase, Scattering};
pub use object::{
    BicubicPatch, Blob, BlobComponent, BlobComponentKind, Clipping, Cone, Cylinder, Disc, Glyph,
    HeightField, Isosurface, Lathe, LightGroup, Mesh, MeshFace, Object, ObjectFlags, Placement,
    Prism, Shape, SmoothTriangle, Sor,
};
pub use photons::{LightPhotons, ObjectPhotons, PhotonSettings};
pub use radiosity::{GREY_WEIGHTS, Radiosity, RadiosityCache};
pub use rainbow::Rainbow;
pub use spline::{
    PrismProfile, Segment, SorSegment, SplineKind, lathe_profile, prism_profile, sor_profile,
};
pub use texture::{
    BlackHole, BumpMap, Crackle, Finish, Fractal, FractalColouring, FractalFormula, HeightImage,
    ImageData, ImageMap, IndexImage, Interior, Interpolate, Irid, MapType, MappingKind,
    MappingWarp, MaterialImage, Normal, ObjectPattern, Orientation, Pattern, PatternKind, Pavement,
    Pigment, PigmentKind, Quilted, Reflection, RepeatWarp, Slope, SlopeEntry, Texture, TextureMap,
    Turbulence, VoxelGrid, Warp, Wave,
};

use glam::DVec3;

pub use crate::geometry::Transform;

/// A POV-Ray colour: linear RGB plus filter and transmit.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Colour {
    pub rgb: DVec3,
    pub filter: f64,
    pub transmit: f64,
}

impl Colour {
    pub const BLACK: Colour = Colour {
        rgb: DVec3::ZERO,
        filter: 0.0,
        transmit: 0.0,
    };

    pub fn rgb(r: f64, g: f64, b: f64) -> Colour {
        Colour {
            rgb: DVec3::new(r, g, b),
            filter: 0.0,
            transmit: 0.0,
        }
    }

    /// Opacity of a surface with this pigment. POV-Ray 3.7 uses `1 - f - t`; scenes that
    /// declare an older `#version` use `1 - (f * max(r,g,b) + t)`.
    pub fn opacity(&self, legacy: bool) -> f64 {
        if legacy {
            1.0 - (self.filter * self.rgb.max_element() + self.transmit)
        } else {
            1.0 - self.filter - self.transmit
        }
    }
}

/// `sky_sphere { pigment {...} ... }`: pigments evaluated at the direction of a ray that
/// leaves the scene, the first listed at the bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct SkySphere {
    pub pigments: Vec<Pigment>,
    pub emission: DVec3,
}

/// Settings from `global_settings`, with POV-Ray's defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct GlobalSettings {
    pub assumed_gamma: Option<f64>,
    pub max_trace_level: u32,
    /// POV-Ray's deterministic weight cut-off. penumbra reads it but replaces it with
    /// unbiased Russian roulette, whose expectation is the uncut, depth-capped tree.
    pub adc_bailout: f64,
    pub ambient_light: DVec3,
    /// `noise_generator` in global_settings: the default for patterns that name none
    /// (applies to patterns read after it).
    pub noise_generator: u8,
    /// `irid_wavelength`: the wavelengths (in POV-Ray's units) of r, g and b for `irid`.
    pub irid_wavelength: DVec3,
    /// `radiosity { }`: diffuse interreflection, when the block is there.
    pub radiosity: Option<Radiosity>,
    /// `photons { }`: caustics, when the block is there.
    pub photons: Option<PhotonSettings>,
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            assumed_gamma: None,
            max_trace_level: 5,
            adc_bailout: 1.0 / 255.0,
            ambient_light: DVec3::ONE,
            noise_generator: 2,
            // Measured: povray's default interference at normal incidence has phase
            // 4 pi d / lambda with lambda 0.70, 0.52, 0.48.
            irid_wavelength: DVec3::new(0.70, 0.52, 0.48),
            radiosity: None,
            photons: None,
        }
    }
}

/// A whole scene as the language describes it.
#[derive(Clone, Debug)]
pub struct Scene {
    pub camera: Camera,
    pub lights: Vec<Light>,
    pub objects: Vec<Object>,
    pub background: Colour,
    /// Seen by rays that hit nothing, by direction, over the background.
    pub sky_sphere: Option<SkySphere>,
    /// Every `fog { }`, in order (their effects combine: see render::fog).
    pub fogs: Vec<Fog>,
    /// Every `rainbow { }`, in order.
    pub rainbows: Vec<Rainbow>,
    /// Every top-level `media { }`: atmospheric media, filling space outside solid objects.
    pub media: Vec<Media>,
    pub settings: GlobalSettings,
    /// The `#version` in force at the end of parsing; below 3.7 some formulas differ.
    pub version: f64,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            camera: Camera::default(),
            lights: Vec::new(),
            objects: Vec::new(),
            background: Colour::BLACK,
            sky_sphere: None,
            fogs: Vec::new(),
            rainbows: Vec::new(),
            media: Vec::new(),
            settings: GlobalSettings::default(),
            version: 3.7,
        }
    }
}

impl Scene {
    /// Whether pre-3.7 formulas (opacity) apply.
    pub fn legacy(&self) -> bool {
        self.version < 3.7 - 1e-9
    }
}
