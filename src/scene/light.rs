use glam::DVec3;

/// The kinds of light POV-Ray has; each differs in where light comes from and how it
/// falls off across directions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    Point,
    Spot {
        point_at: DVec3,
        /// Degrees.
        radius: f64,
        /// Degrees.
        falloff: f64,
        tightness: f64,
    },
    /// Shines along `point_at - location` everywhere.
    Parallel {
        point_at: DVec3,
    },
    /// Parallel light confined to a cylinder around the axis through `location` and
    /// `point_at`; `radius` and `falloff` are distances from the axis.
    Cylinder {
        point_at: DVec3,
        radius: f64,
        falloff: f64,
        tightness: f64,
    },
}

/// `area_light <axis1>, <axis2>, size1, size2 ...`: a grid of point lights POV-Ray uses
/// for soft shadows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight {
    pub axis1: DVec3,
    pub axis2: DVec3,
    pub size1: u32,
    pub size2: u32,
    pub adaptive: Option<u32>,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    pub location: DVec3,
    pub colour: DVec3,
    pub area: Option<AreaLight>,
    pub area_illumination: bool,
    pub shadowless: bool,
    pub fade_distance: f64,
    pub fade_power: f64,
    /// `looks_like { object }`: already placed at the light; it is seen but does not
    /// shadow its own light.
    pub looks_like: Option<Box<super::Object>>,
    /// `media_attenuation on`: the light dims through fog on its way (and through media).
    pub media_attenuation: bool,
    /// `media_interaction off`: scattering media do not see the light.
    pub media_interaction: bool,
    /// The `light_group` the light belongs to (`None`: a global light).
    pub group: Option<u32>,
    /// `photons { }`: whether its photons reflect and refract.
    pub photons: super::LightPhotons,
    /// `projected_through { object }`: the light reaches only points whose ray towards it
    /// meets the object, as if it shone from there (render::integrator::direct).
    pub projected_through: Option<super::ObjectPattern>,
}

impl Light {
    pub fn point(location: DVec3, colour: DVec3) -> Light {
        Light {
            kind: LightKind::Point,
            location,
            colour,
            area: None,
            area_illumination: false,
            shadowless: false,
            fade_distance: 0.0,
            fade_power: 0.0,
            looks_like: None,
            media_attenuation: false,
            media_interaction: true,
            group: None,
            photons: super::LightPhotons::default(),
            projected_through: None,
        }
    }
}
