//! `photons { }` in global_settings, objects and lights: POV-Ray's caustics.
//!
//! POV-Ray shoots photons from the lights at the objects marked `target`, follows them
//! through the targets' mirror reflections and refractions and stores them where they land,
//! then estimates the light they bring from the photons near each shaded point. Its image
//! depends on how many photons it shoots and how far it gathers them (the map's bias);
//! penumbra shoots a new set of photons for every sample index and gathers them over a
//! radius that shrinks from one set to the next, so that the average converges to the
//! caustic itself (src/render/photons.rs). The settings below that tune POV-Ray's map are
//! read and kept; those that change the light (which objects and lights take part, the
//! trace depth) are applied.

/// `global_settings { photons { ... } }`, with POV-Ray 3.7's defaults where they change
/// the image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonSettings {
    /// `spacing`: the distance between neighbouring photons at the targets.
    pub spacing: Option<f64>,
    /// `count`: the number of photons to shoot (instead of `spacing`).
    pub count: Option<u32>,
    /// `max_trace_level`: how many surfaces a photon may cross (`None`: the scene's).
    pub max_trace_level: Option<u32>,
    /// `adc_bailout` of the photons' own tree (`None`: the scene's).
    pub adc_bailout: Option<f64>,
    /// `media max_steps [, factor]`: photons stored in media. Read; penumbra stores
    /// surface photons only.
    pub media: Option<(u32, f64)>,
    /// `gather min, max`, `radius`, `jitter`, `autostop`, `expand_thresholds`: the map's
    /// own tuning, read and kept.
    pub gather: (u32, u32),
    pub radius: Option<f64>,
    pub jitter: f64,
    pub autostop: f64,
    pub expand_thresholds: (f64, u32),
}

impl Default for PhotonSettings {
    fn default() -> Self {
        PhotonSettings {
            spacing: None,
            count: None,
            max_trace_level: None,
            adc_bailout: None,
            media: None,
            gather: (20, 100),
            radius: None,
            jitter: 0.4,
            autostop: 0.0,
            expand_thresholds: (0.2, 40),
        }
    }
}

/// An object's `photons { ... }` block (inherited by a CSG's children).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ObjectPhotons {
    /// `target [spacing multiplier]`: photons are shot at it.
    pub target: bool,
    /// `refraction on`: photons refract through it. Off unless turned on (measured: a
    /// glass target without it gets no photons, and its shadow stays filtered).
    pub refraction: bool,
    /// `reflection on`: photons reflect at it. Off unless turned on (measured: a mirror
    /// `photons { target }` without it gets no photons: photon time 0.000 s, the floor
    /// lit by the light alone).
    pub reflection: bool,
    /// `collect off`: photons landing on it are not kept.
    pub no_collect: bool,
    /// `pass_through`: photons go through it unchanged.
    pub pass_through: bool,
}

/// A light's `photons { ... }` block. Lights shoot photons unless told not to (measured:
/// a light without a photons block lights a mirror's caustic like one with
/// `photons { reflection on }`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct LightPhotons {
    pub no_refraction: bool,
    pub no_reflection: bool,
    /// `area_light`: photons start all over an area light, not at its centre.
    pub area_light: bool,
}
