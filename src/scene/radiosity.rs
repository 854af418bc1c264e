//! `global_settings { radiosity { ... } }`: POV-Ray's diffuse interreflection.
//!
//! POV-Ray estimates it with an irradiance cache; most of the block tunes that cache
//! (how many rays per sample, how far a sample is reused, the pretrace). penumbra samples
//! the same integral per path without a cache, so it reads those settings and keeps them
//! (they say how biased POV-Ray's image is) but the image depends only on the settings that
//! change the integral: `recursion_limit`, `brightness`, `gray_threshold`, `normal` and
//! `media`. Measured with POV-Ray 3.7 (docs/differences.md, "Radiosity").

/// The radiosity block, with POV-Ray 3.7's defaults.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Radiosity {
    /// Diffuse bounces gathered: 1 to 20 (POV-Ray refuses others); the light a surface gets
    /// directly is bounce 0.
    pub recursion_limit: u32,
    /// Scales the gathered light at every bounce.
    pub brightness: f64,
    /// How far the gathered light is turned to grey (0: not at all, 1: fully).
    pub gray_threshold: f64,
    /// `normal on`: gather around the perturbed normal instead of the surface's own.
    pub normal: bool,
    /// `media on`: radiosity rays see the media they cross.
    pub media: bool,
    /// The irradiance cache's settings: read, kept, without effect on penumbra's image.
    pub cache: RadiosityCache,
}

/// The settings of POV-Ray's irradiance cache, which decide its bias and its speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadiosityCache {
    pub count: u32,
    /// `count N, M`: the size of the direction table sampled from (0: POV-Ray's default).
    pub directions: u32,
    pub error_bound: f64,
    pub low_error_factor: f64,
    pub minimum_reuse: f64,
    pub maximum_reuse: f64,
    pub nearest_count: u32,
    /// `nearest_count N, M`: the count below which POV-Ray takes a new sample in the final
    /// pass (0: N).
    pub nearest_count_min: u32,
    pub pretrace_start: f64,
    pub pretrace_end: f64,
    pub adc_bailout: f64,
    pub always_sample: bool,
    /// The brightest a single radiosity sample may be (negative: no limit).
    pub max_sample: f64,
    pub subsurface: bool,
}

impl Default for RadiosityCache {
    fn default() -> Self {
        RadiosityCache {
            count: 35,
            directions: 0,
            error_bound: 1.8,
            low_error_factor: 0.5,
            minimum_reuse: 0.015,
            maximum_reuse: 0.2,
            nearest_count: 5,
            nearest_count_min: 0,
            pretrace_start: 0.08,
            pretrace_end: 0.04,
            adc_bailout: 0.01,
            always_sample: false,
            max_sample: -1.0,
            subsurface: false,
        }
    }
}

impl Default for Radiosity {
    fn default() -> Self {
        Radiosity {
            recursion_limit: 2,
            brightness: 1.0,
            gray_threshold: 0.0,
            normal: false,
            media: false,
            cache: RadiosityCache::default(),
        }
    }
}

/// POV-Ray's grey of a colour, which `gray_threshold` blends towards (measured: gathered
/// light of <0.5, 0.25, 0.1> turns into 0.3068 at gray_threshold 1).
pub const GREY_WEIGHTS: [f64; 3] = [0.297, 0.589, 0.114];
