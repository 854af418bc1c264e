use glam::DVec3;

use super::{Colour, Transform};

/// A texture as POV-Ray layers it: what colour (pigment), how the surface is bumped
/// (normal), and how light interacts (finish). A texture with a `map` is patterned: its
/// own pigment, normal and finish are unused, the map's entries are shown instead.
/// `below` holds the layers under this one (`texture {A} texture {B}` puts B on top of A),
/// nearest first, so the top layer owns the whole stack.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Texture {
    pub pigment: Pigment,
    pub normal: Option<Normal>,
    pub finish: Finish,
    pub map: Option<Box<TextureMap>>,
    pub below: Vec<Texture>,
}

impl Texture {
    pub fn transform_by(&mut self, t: &Transform) {
        self.pigment.transform_by(t);
        if let Some(n) = &mut self.normal {
            n.transform_by(t);
        }
        if let Some(m) = &mut self.map
            && !m.uv_mapping
        {
            m.transform = m.transform.then(t);
            for (_, e) in &mut m.entries {
                e.transform_by(t);
            }
        }
        for b in &mut self.below {
            b.transform_by(t);
        }
    }

    /// Whether any part of the texture reads the surface's (u, v).
    pub fn uses_uv(&self) -> bool {
        self.pigment.uses_uv()
            || self
                .map
                .as_ref()
                .is_some_and(|m| m.uv_mapping || m.entries.iter().any(|(_, e)| e.uses_uv()))
            || self.below.iter().any(Texture::uses_uv)
    }
}

/// `texture_map { [v texture {...}] ... }` under a pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureMap {
    pub pattern: Pattern,
    pub transform: Transform,
    pub entries: Vec<(f64, Texture)>,
    /// `texture { uv_mapping pattern texture_map {...} }`: the pattern reads (u, v, 0).
    pub uv_mapping: bool,
}

/// POV-Ray's wave types, applied to a pattern's value after frequency and phase.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Wave {
    Ramp,
    Sine,
    Triangle,
    Scallop,
    Cubic,
    Poly(f64),
}

/// Classic turbulence (and `warp { turbulence }`): amount per axis and the fractal sum's
/// octaves, omega (amplitude ratio) and lambda (frequency ratio).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turbulence {
    pub amount: DVec3,
    pub octaves: u32,
    pub omega: f64,
    pub lambda: f64,
}

impl Default for Turbulence {
    fn default() -> Self {
        Turbulence {
            amount: DVec3::ZERO,
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        }
    }
}

/// A step in a pattern's warp chain, kept in source order so that transforms written
/// before a warp are warped with the pattern and those after it move the warped pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Warp {
    Turbulence(Turbulence),
    Transform(Transform),
    Repeat(RepeatWarp),
    BlackHole(BlackHole),
    /// `cylindrical`, `spherical`, `toroidal`, `cubic`: the point becomes (angle, height or
    /// second angle, distance), then `orientation`'s matrix moves it.
    Mapping(MappingWarp),
    /// `planar <normal>, d`: (x, y, d) through the normal's orientation matrix.
    Planar {
        orient: Orientation,
        distance: f64,
    },
}

/// `warp { repeat <w along one axis> offset <v> flip <axes> }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RepeatWarp {
    pub axis: usize,
    pub width: f64,
    pub offset: DVec3,
    /// 1 on each axis that odd repetitions mirror, 0 elsewhere.
    pub flip: DVec3,
}

/// `warp { black_hole <c>, r falloff f strength s inverse repeat <v> turbulence <v> }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlackHole {
    pub centre: DVec3,
    pub radius: f64,
    pub falloff: f64,
    pub strength: f64,
    pub inverse: bool,
    /// Cell size per axis, 0 where the hole does not repeat.
    pub repeat: DVec3,
    /// Each repeated hole's random displacement per axis.
    pub jitter: DVec3,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MappingKind {
    Cylindrical,
    Spherical,
    Toroidal { major_radius: f64 },
    Cubic,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MappingWarp {
    pub kind: MappingKind,
    pub dist_exp: f64,
    pub orient: Orientation,
}

/// The matrix a mapping warp's `orientation` (or planar's normal) applies to its result:
/// columns (o.y + o.z, 0, -o.x), (0, o.x + o.z, o.y), (o.x, -o.y, o.z) for the unit vector o.
/// Measured with povray's printed function values for x, y, -z, <1,1,0> and <0.3,-0.5,0.8>
/// (and their negatives): not a rotation in general, but what POV-Ray computes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orientation(pub glam::DMat3);

impl Orientation {
    pub fn new(o: DVec3) -> Orientation {
        let o = o.normalize_or(DVec3::Z);
        Orientation(glam::DMat3::from_cols(
            DVec3::new(o.y + o.z, 0.0, -o.x),
            DVec3::new(0.0, o.x + o.z, o.y),
            DVec3::new(o.x, -o.y, o.z),
        ))
    }
}

/// A df3 file's voxels (x fastest, then y, then z), scaled to [0, 1] by their type's
/// largest value; `trilinear` is `interpolate 1`.
#[derive(Clone, Debug, PartialEq)]
pub struct VoxelGrid {
    pub size: [usize; 3],
    pub values: Vec<f32>,
    pub trilinear: bool,
}

/// The pattern functions; each gives a value in [0, 1] (list patterns an entry index).
#[derive(Clone, Debug, PartialEq)]
pub enum PatternKind {
    Checker,
    Hexagon,
    /// Unit squares in the x-z plane, four entries around each corner.
    Square,
    /// Equilateral triangles of side 1 in the x-z plane, six entries.
    Triangular,
    Brick {
        size: DVec3,
        mortar: f64,
    },
    Gradient(DVec3),
    Onion,
    Radial,
    Spiral1(f64),
    Spiral2(f64),
    Leopard,
    Marble,
    Wood,
    Agate {
        turbulence: f64,
    },
    Bozo,
    Spotted,
    Granite,
    Wrinkles,
    Bumps,
    Dents,
    Ripples,
    Waves,
    Planar,
    Spherical,
    Cylindrical,
    Boxed,
    Crackle(Crackle),
    /// `average`: no value of its own; a pigment_map's entries are averaged, weighted by
    /// their map values (read only with a pigment_map).
    Average,
    /// `density_file df3 "file" [interpolate k]`: a voxel grid over the unit cube.
    DensityFile(std::sync::Arc<VoxelGrid>),
    /// `function { ... }`: the function's value at the point, wrapped as gradient's is.
    Function(std::sync::Arc<crate::function::Program>),
    /// `pigment_pattern { ... }`: the grey value (0.297 r + 0.589 g + 0.114 b) of a pigment.
    PigmentPattern(Box<Pigment>),
    /// `quilted`: a rounded bulge in each unit cube (src/appearance/pattern.rs).
    Quilted(Quilted),
    /// `mandel`, `julia`, `magnet`: escape-time fractals in the x-y plane
    /// (src/appearance/fractal.rs).
    Fractal(Fractal),
    /// `cells`: one random value in [0, 1) per unit cube.
    Cells,
    /// `slope { <d> [, lo, hi] [altitude <a> [, lo, hi]] }`: how far the surface's normal
    /// turns towards d, optionally mixed with the height along a (src/appearance/pattern.rs).
    Slope(Slope),
    /// `bump_map { png "file" ... }` in a normal: heights from an image (it tilts the
    /// normal itself: src/appearance/normal.rs; as a value, 0).
    BumpMap(BumpMap),
    /// `material_map { png "file" texture {...} ... }`: the texture whose number the
    /// image's pixel holds (a list pattern over the textures).
    MaterialMap(MaterialImage),
    /// `image_pattern { png "file" }`: the image's grey (0.297 r + 0.589 g + 0.114 b) or,
    /// with `use_alpha`, its transparency.
    ImagePattern {
        image: std::sync::Arc<ImageMap>,
        use_alpha: bool,
    },
    /// `tiling n`: one of POV-Ray's bevelled tilings of the x-z plane
    /// (src/appearance/tiling.rs).
    Tiling(u8),
    /// `pavement`: the x-z plane paved with one polyform tile, bevelled
    /// (src/appearance/tiling.rs).
    Pavement(Pavement),
    /// `object { Obj A, B }`: entry 1 inside the object's solid, 0 outside (a list
    /// pattern of two).
    Object(ObjectPattern),
}

/// `pavement`'s choice of tile: the basic polygon's sides (3, 4 or 6), how many make the
/// tile, which of their arrangements (from 1), and the corner styles (0, 1 or 2; form 3
/// for squares).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pavement {
    pub sides: u8,
    pub tiles: u8,
    pub pattern: u8,
    pub form: u8,
    pub interior: u8,
    pub exterior: u8,
}

impl Default for Pavement {
    /// POV-Ray's defaults (measured: a bare `pavement` renders as `number_of_sides 3
    /// number_of_tiles 1 pattern 1`).
    fn default() -> Pavement {
        Pavement {
            sides: 3,
            tiles: 1,
            pattern: 1,
            form: 0,
            interior: 0,
            exterior: 0,
        }
    }
}

/// The object an `object` pattern tests points against, built for that test (its BVH and
/// CSG) when the pattern is read.
#[derive(Clone)]
pub struct ObjectPattern(pub std::sync::Arc<crate::geometry::World>);

impl ObjectPattern {
    pub fn holds(&self, p: DVec3) -> bool {
        self.0.holds(p)
    }
}

/// Patterns compare equal when they test the same built object.
impl PartialEq for ObjectPattern {
    fn eq(&self, other: &ObjectPattern) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0)
    }
}

impl std::fmt::Debug for ObjectPattern {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "ObjectPattern({} primitives)", self.0.primitive_count())
    }
}

impl PatternKind {
    /// Marble, wood and agate read the classic turbulence themselves instead of warping.
    pub fn handles_turbulence(&self) -> bool {
        matches!(
            self,
            PatternKind::Marble | PatternKind::Wood | PatternKind::Agate { .. }
        )
    }

    /// Patterns that select one of a fixed number of entries.
    pub fn list_size(&self) -> Option<usize> {
        match self {
            PatternKind::Checker | PatternKind::Brick { .. } | PatternKind::Object(_) => Some(2),
            PatternKind::Hexagon => Some(3),
            PatternKind::Square => Some(4),
            PatternKind::Triangular => Some(6),
            PatternKind::MaterialMap(m) => Some(m.count),
            _ => None,
        }
    }

    /// Marble, wood and the spirals default to a triangle wave (measured with POV-Ray 3.7).
    pub fn default_wave(&self) -> Wave {
        match self {
            PatternKind::Marble
            | PatternKind::Wood
            | PatternKind::Spiral1(_)
            | PatternKind::Spiral2(_) => Wave::Triangle,
            _ => Wave::Ramp,
        }
    }
}

/// `crackle`'s settings (src/appearance/crackle.rs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crackle {
    /// Weights of the distances to the nearest, second and third nearest cell points.
    pub form: DVec3,
    /// The Minkowski exponent of the distance.
    pub metric: f64,
    pub offset: f64,
    /// One value per cell.
    pub solid: bool,
}

impl Default for Crackle {
    fn default() -> Self {
        Crackle {
            form: DVec3::new(-1.0, 1.0, 0.0),
            metric: 2.0,
            offset: 0.0,
            solid: false,
        }
    }
}

/// `slope`'s settings, as measured with POV-Ray 3.7 on a unit sphere: the slope part is
/// 0.5 + asin(n . d) / pi for the unit normal n and unit d (1 facing d, 0.5 across, 0 away),
/// mapped by (v - lo) / (hi - lo); the altitude part is p . a (unit a, pattern space) mapped
/// by its own (lo, hi); with both, they mix weighted by the lengths of d and a
/// (`slope { y*3 altitude y, -1, 1 }` reads (3 s + h) / 4). The normal is the world's: the
/// texture's own transforms leave the slope part unchanged (rotate z*30 and scale <1,3,1>
/// read the same values as none).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slope {
    pub direction: DVec3,
    pub range: (f64, f64),
    /// The unit altitude direction, its weight against the slope's and its (lo, hi).
    pub altitude: Option<(DVec3, f64, (f64, f64))>,
    /// The slope part's weight: the length of the slope vector.
    pub weight: f64,
}

/// `quilted`'s settings: the two inner control points of the cubic Bezier curve that
/// shapes each cube's bulge (POV-Ray's defaults: both 1, measured).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quilted {
    pub control0: f64,
    pub control1: f64,
}

impl Default for Quilted {
    fn default() -> Self {
        Quilted {
            control0: 1.0,
            control1: 1.0,
        }
    }
}

/// The iteration a fractal pattern runs: `z^exponent + c` (mandel and julia, exponent 2 to
/// 33) or one of the two magnet maps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FractalFormula {
    Power(u32),
    Magnet1,
    Magnet2,
}

/// What a fractal pattern's value is made of, by POV-Ray's `interior` / `exterior` type
/// number (0 to 6); `Count` is 1: the escape iteration over `max_iteration` outside, the
/// smallest |z| of the orbit inside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FractalColouring {
    One,
    Count,
    Real,
    Imaginary,
    RealSquared,
    ImaginarySquared,
    Absolute,
}

impl FractalColouring {
    /// The colouring of POV-Ray's type number, None outside 0 to 6.
    pub fn from_type(n: i64) -> Option<FractalColouring> {
        use FractalColouring::*;
        [
            One,
            Count,
            Real,
            Imaginary,
            RealSquared,
            ImaginarySquared,
            Absolute,
        ]
        .get(usize::try_from(n).ok()?)
        .copied()
    }
}

/// `mandel`, `julia` and `magnet`'s settings (src/appearance/fractal.rs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal {
    pub formula: FractalFormula,
    /// The julia parameter c; None for the Mandelbrot forms, where c is the point.
    pub julia: Option<[f64; 2]>,
    pub max_iteration: u32,
    /// (colouring, factor) of the points that escape; POV-Ray's default is type 1.
    pub exterior: (FractalColouring, f64),
    /// (colouring, factor) of the points that do not; POV-Ray's default is type 0.
    pub interior: (FractalColouring, f64),
}

impl Fractal {
    pub fn new(formula: FractalFormula, julia: Option<[f64; 2]>, max_iteration: u32) -> Self {
        Fractal {
            formula,
            julia,
            max_iteration,
            exterior: (FractalColouring::Count, 1.0),
            interior: (FractalColouring::One, 1.0),
        }
    }
}

/// A pattern with its value modifiers (frequency, phase, wave, turbulence, warps).
#[derive(Clone, Debug, PartialEq)]
pub struct Pattern {
    pub kind: PatternKind,
    pub frequency: f64,
    pub phase: f64,
    pub wave: Wave,
    pub turbulence: Option<Turbulence>,
    pub warps: Vec<Warp>,
    pub noise_generator: u8,
}

impl Pattern {
    pub fn new(kind: PatternKind) -> Pattern {
        Pattern {
            wave: kind.default_wave(),
            kind,
            frequency: 1.0,
            phase: 0.0,
            turbulence: None,
            warps: Vec::new(),
            noise_generator: 2,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum PigmentKind {
    Solid(Colour),
    /// A pattern that picks one of several sub-pigments (checker's two, for instance).
    List {
        pattern: Pattern,
        entries: Vec<Pigment>,
    },
    /// A pattern value looked up in a colour map (sorted by value).
    ColourMap {
        pattern: Pattern,
        map: Vec<(f64, Colour)>,
    },
    /// A pattern value blending between pigments (sorted by value).
    PigmentMap {
        pattern: Pattern,
        map: Vec<(f64, Pigment)>,
    },
    Image(ImageMap),
}

/// How an image wraps onto pattern space (`map_type`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MapType {
    /// 0: the unit square of the x-y plane, repeated, projected along z.
    Planar,
    /// 1: longitude and latitude around the y axis.
    Spherical,
    /// 2: around the y axis, y from 0 to 1.
    Cylindrical,
    /// 5: around a torus of major radius 1 about the y axis, u the angle around the axis
    /// and v the angle around the tube.
    Torus,
}

/// Decoded pixels, linear (PNG's sRGB decoded), row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageData {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<Colour>,
}

/// An image's pixels as numbers: a palette image's indices, or an 8-bit colour image's red
/// byte (POV-Ray's material_map reads them so; measured).
#[derive(Debug, PartialEq)]
pub struct IndexImage {
    pub width: usize,
    pub height: usize,
    pub index: Vec<u8>,
    /// The palette's number of entries; 0 for a colour image.
    pub palette: usize,
}

/// `bump_map`'s image as heights: a grey PNG's value / max or a colour one's brightness
/// (in [0, 1]), or with `use_index` the palette index itself (0 to 255).
#[derive(Debug, PartialEq)]
pub struct HeightImage {
    pub width: usize,
    pub height: usize,
    pub heights: Vec<f32>,
}

/// `bump_map { png "file" [once] [interpolate n] [bump_size s] [use_index] }`, mapped
/// onto the x-y plane.
#[derive(Clone, Debug, PartialEq)]
pub struct BumpMap {
    pub image: std::sync::Arc<HeightImage>,
    pub map_type: MapType,
    pub once: bool,
    /// Heights bilinear between pixel centres (`interpolate 2` or 4) instead of the
    /// nearest pixel's.
    pub bilinear: bool,
}

/// `material_map`'s image, mapped as an image_map is, and the number of its textures
/// (which texture a pixel's number picks: `appearance::pigment::material_index`).
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialImage {
    pub image: std::sync::Arc<IndexImage>,
    pub map_type: MapType,
    pub once: bool,
    pub count: usize,
}

/// How an image map reads between its pixels (`interpolate n`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interpolate {
    /// The pixel under the point (no `interpolate`, or 0).
    Nearest,
    /// `interpolate 2`: bilinear between the four pixel centres around the point.
    Bilinear,
    /// `interpolate 4`: those four weighted by the inverse square of their distance.
    InverseSquare,
}

/// `image_map { png "file" map_type n interpolate n once filter all f transmit all t }`.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageMap {
    pub image: std::sync::Arc<ImageData>,
    pub map_type: MapType,
    pub interpolate: Interpolate,
    /// `once`: one copy; outside it the pigment is fully transparent (measured).
    pub once: bool,
    pub filter_all: f64,
    pub transmit_all: f64,
    /// The pigment's classic turbulence and warp chain: an image has no pattern to hold
    /// them, yet POV-Ray warps the image's space like any pattern's.
    pub turbulence: Option<Turbulence>,
    pub warps: Vec<Warp>,
}

/// A pigment with the transform from pattern space to world space.
#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    pub kind: PigmentKind,
    pub transform: Transform,
    /// `uv_mapping`: the pattern space is the surface's (u, v, 0), not the world. The
    /// transforms written inside the pigment (or inside a `texture { uv_mapping ... }`)
    /// move the pattern in uv space; those of the object and of an enclosing texture do
    /// not (measured: `scale 0.5` on such a sphere or its outer texture leaves u as it is).
    pub uv_mapping: bool,
}

impl Default for Pigment {
    /// POV-Ray's default pigment is black.
    fn default() -> Self {
        Pigment::solid(Colour::BLACK)
    }
}

impl Pigment {
    /// The pattern a patterned pigment reads (none for a colour or an image).
    pub fn pattern(&self) -> Option<&Pattern> {
        match &self.kind {
            PigmentKind::List { pattern, .. }
            | PigmentKind::ColourMap { pattern, .. }
            | PigmentKind::PigmentMap { pattern, .. } => Some(pattern),
            PigmentKind::Solid(_) | PigmentKind::Image(_) => None,
        }
    }

    pub fn solid(c: Colour) -> Pigment {
        Pigment {
            kind: PigmentKind::Solid(c),
            transform: Transform::IDENTITY,
            uv_mapping: false,
        }
    }

    pub fn transform_by(&mut self, t: &Transform) {
        if self.uv_mapping {
            return;
        }
        self.transform = self.transform.then(t);
        match &mut self.kind {
            PigmentKind::List { entries, .. } => {
                for e in entries {
                    e.transform_by(t);
                }
            }
            PigmentKind::PigmentMap { map, .. } => {
                for (_, e) in map {
                    e.transform_by(t);
                }
            }
            _ => {}
        }
    }

    /// Whether the pigment, or any pigment inside it, reads the surface's (u, v).
    pub fn uses_uv(&self) -> bool {
        self.uv_mapping
            || match &self.kind {
                PigmentKind::List { entries, .. } => entries.iter().any(Pigment::uses_uv),
                PigmentKind::PigmentMap { map, .. } => map.iter().any(|(_, p)| p.uses_uv()),
                _ => false,
            }
    }

    pub fn pattern_mut(&mut self) -> Option<&mut Pattern> {
        match &mut self.kind {
            PigmentKind::Solid(_) | PigmentKind::Image(_) => None,
            PigmentKind::List { pattern, .. }
            | PigmentKind::ColourMap { pattern, .. }
            | PigmentKind::PigmentMap { pattern, .. } => Some(pattern),
        }
    }
}

/// `normal { pattern amount ... }`. `amount` is POV-Ray's bump height (also `bump_size`).
#[derive(Clone, Debug, PartialEq)]
pub struct Normal {
    pub pattern: Pattern,
    pub amount: f64,
    pub transform: Transform,
    /// The finite-difference step (world units) for patterns without their own normal.
    pub accuracy: f64,
    /// `slope_map`: the pattern value becomes a height before the finite difference.
    pub slope_map: Vec<SlopeEntry>,
    /// `normal_map`: the pattern value blends these normals instead of tilting by itself.
    pub normal_map: Vec<(f64, Normal)>,
}

/// One `[value, <height, slope>]` of a slope map; `slope` is the height's derivative per
/// unit of the interval's own parameter (0 to 1 between neighbouring entries), not per
/// unit pattern value (measured: `[0 <0,1>][0.5 <1,1>][1 <0,-1>]` fits only that way).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlopeEntry {
    pub value: f64,
    pub height: f64,
    pub slope: f64,
}

impl Normal {
    pub fn new(pattern: Pattern) -> Normal {
        Normal {
            pattern,
            amount: 0.5,
            transform: Transform::IDENTITY,
            accuracy: 0.02,
            slope_map: Vec::new(),
            normal_map: Vec::new(),
        }
    }

    /// Only the normal's own transform moves: a `pigment_pattern`'s pigment is evaluated in
    /// the normal's pattern space, so moving it too would apply the transform twice
    /// (measured: `rotate z*90` on the object turns POV-Ray's grooves by 90 degrees, not 180).
    /// A normal map's entries are evaluated at the world point, so they move too (measured:
    /// `rotate z*30` after a `normal_map` turns the entries' tilts with the pattern).
    pub fn transform_by(&mut self, t: &Transform) {
        self.transform = self.transform.then(t);
        for (_, e) in &mut self.normal_map {
            e.transform_by(t);
        }
    }
}

/// `reflection { min, max falloff p fresnel exponent e metallic m }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflection {
    pub min: DVec3,
    pub max: DVec3,
    pub falloff: f64,
    pub fresnel: bool,
    pub exponent: f64,
    pub metallic: f64,
}

impl Default for Reflection {
    fn default() -> Self {
        Reflection {
            min: DVec3::ZERO,
            max: DVec3::ZERO,
            falloff: 1.0,
            fresnel: false,
            exponent: 1.0,
            metallic: 0.0,
        }
    }
}

impl Reflection {
    pub fn is_zero(&self) -> bool {
        self.min == DVec3::ZERO && self.max == DVec3::ZERO
    }
}

/// The finish with POV-Ray's defaults (ambient 0.1, diffuse 0.6, ...).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finish {
    pub ambient: DVec3,
    pub emission: DVec3,
    pub diffuse: f64,
    /// `diffuse a, b`: the share of light reaching the back side (POV-Ray 3.7 default 0).
    pub diffuse_back: f64,
    /// The diffuse value as written, which scales the light radiosity gathers: POV-Ray
    /// applies `diffuse albedo`'s brilliance adjustment to the lights only (measured:
    /// `diffuse albedo 0.6 brilliance 3` lights with 1.2 and gathers with 0.6).
    pub radiosity_diffuse: f64,
    pub brilliance: f64,
    pub phong: f64,
    pub phong_size: f64,
    pub specular: f64,
    pub roughness: f64,
    pub metallic: f64,
    pub reflection: Reflection,
    pub conserve_energy: bool,
    /// `crand`: POV-Ray darkens each light's diffuse part by `crand * u`, u uniform; penumbra
    /// subtracts its mean (see `diffuse_term`).
    pub crand: f64,
    /// `fresnel` in the finish (POV-Ray 3.7): also attenuates transmitted light by 1 - R.
    pub fresnel: bool,
    /// `caustics` written in the finish, as before POV-Ray 3.1: POV-Ray 3.7 warns and gives
    /// the object's interior caustics of a 45th of it (measured: 1 + |cos|^c, where the
    /// interior's `caustics c` gives 1 + |cos|^(45 c)); 0: none.
    pub caustics: f64,
    pub irid: Option<Irid>,
}

/// `irid { amount thickness t turbulence u }`: thin-film interference on the light that
/// reaches the surface (see appearance::finish::irid_factor).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Irid {
    pub amount: f64,
    pub thickness: f64,
    pub turbulence: f64,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            emission: DVec3::ZERO,
            diffuse: 0.6,
            diffuse_back: 0.0,
            radiosity_diffuse: 0.6,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: Reflection::default(),
            conserve_energy: false,
            crand: 0.0,
            irid: None,
            fresnel: false,
            caustics: 0.0,
        }
    }
}

/// What is inside a solid object: the index of refraction, the fade of light along
/// its path through it, and the media that fill it.
#[derive(Clone, Debug, PartialEq)]
pub struct Interior {
    pub ior: f64,
    /// Distance at which light has faded to half (POV-Ray default 0: no fade).
    pub fade_distance: f64,
    /// 0 means no fade; >= 1000 means exponential fade.
    pub fade_power: f64,
    pub fade_colour: DVec3,
    /// Several media in one interior add (measured: emission 0.5 and 0.25 emit 0.75).
    pub media: Vec<super::Media>,
    /// `caustics`: POV-Ray's fake caustics, which brighten the light shadow rays bring
    /// through the surfaces where they cross them near the normal (0: none).
    pub caustics: f64,
    /// `dispersion`: the ratio of the largest to the smallest index of refraction, spread
    /// over `dispersion_samples` wavelengths (1: none).
    pub dispersion: f64,
    /// `dispersion_samples`: wavelengths a dispersing refraction splits light into (>= 2).
    pub dispersion_samples: u32,
}

impl Interior {
    /// Whether refraction into this interior splits light into wavelengths.
    pub fn disperses(&self) -> bool {
        self.dispersion != 1.0
    }
}

impl Default for Interior {
    fn default() -> Self {
        Interior {
            ior: 1.0,
            fade_distance: 0.0,
            fade_power: 0.0,
            fade_colour: DVec3::ZERO,
            media: Vec::new(),
            caustics: 0.0,
            dispersion: 1.0,
            dispersion_samples: 7,
        }
    }
}

impl Interior {
    /// Media densities live in the object's space: they move with it.
    pub fn transform_by(&mut self, t: &Transform) {
        for m in &mut self.media {
            m.transform_by(t);
        }
    }
}
