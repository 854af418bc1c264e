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
    /// `media max_steps [, factor]`: photons in media. penumbra keeps each photon's path
    /// through media whole (a beam), so the steps and their spacing are read and unused.
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
    /// `refraction on|off` (`None`: not written). Without it photons refract only from a
    /// light with `refraction on` (see [`ObjectPhotons::refracts`]).
    pub refraction: Option<bool>,
    /// `reflection on|off`, as `refraction`.
    pub reflection: Option<bool>,
    /// `collect off`: photons landing on it are not kept.
    pub no_collect: bool,
    /// `pass_through`: photons go through it unchanged.
    pub pass_through: bool,
}

impl ObjectPhotons {
    /// Whether photons from a light with `light`'s block refract through this object.
    pub fn refracts(&self, light: &LightPhotons) -> bool {
        turned_on(self.refraction, light.refraction)
    }

    /// Whether this object, a photon target, stops the shadow rays of a light with
    /// `light`'s block: when its own `refraction on` lets that light's photons bring the
    /// light through it (measured: a clear glass ball with `refraction on` casts a black
    /// shadow but for its caustic; a clear target box whose photons refract by the light's
    /// `refraction on` lets the light's shadow rays through as well, 88.5 against 71.9
    /// without photons in the box's mean pixel value, the photons' light added).
    pub fn stops_shadows(&self, light: &LightPhotons) -> bool {
        self.refraction == Some(true) && light.refraction != Some(false)
    }

    /// Whether photons from a light with `light`'s block reflect at this object.
    pub fn reflects(&self, light: &LightPhotons) -> bool {
        turned_on(self.reflection, light.reflection)
    }
}

/// The rule, measured with POV-Ray 3.7 (photons stored): an object's own `on` or `off`
/// decides, unless the light says `off`; where the object says nothing, the light's
/// explicit `on` turns it on, and anything else stops the photons. A bare `photons { target
/// }` mirror under a light with `photons { reflection on }`: 8,445 stored, under a light
/// without the block none shot; a mirror without a photons block inside a clear target box,
/// under a light with both on: 65,811 stored, 61,843 with the mirror's `reflection off`. A
/// clear slab without a photons block under a glass target: under a plain light the photons
/// stop on it (67,162 stored, as without the slab, and no caustic below it), under a light
/// with both on they go through (131,800 stored, the caustic under it as without it).
/// Whatever the rules, a photon whose first surface is not a target is lost (the
/// integrator's `trace_photon`).
fn turned_on(object: Option<bool>, light: Option<bool>) -> bool {
    match (object, light) {
        (_, Some(false)) => false,
        (Some(on), _) => on,
        (None, on) => on == Some(true),
    }
}

/// A light's `photons { ... }` block (`None`: not written). Lights shoot photons unless
/// told not to (measured: a light without a photons block lights a mirror's caustic like
/// one with `photons { reflection on }`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct LightPhotons {
    pub refraction: Option<bool>,
    pub reflection: Option<bool>,
    /// `area_light`: photons start all over an area light, not at its centre.
    pub area_light: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn object(target: bool, refraction: Option<bool>, reflection: Option<bool>) -> ObjectPhotons {
        ObjectPhotons {
            target,
            refraction,
            reflection,
            ..Default::default()
        }
    }

    fn light(refraction: Option<bool>, reflection: Option<bool>) -> LightPhotons {
        LightPhotons {
            refraction,
            reflection,
            ..Default::default()
        }
    }

    /// The cases measured with POV-Ray (see `turned_on`), each as it was set up.
    #[test]
    fn photons_follow_povrays_measured_rules() {
        let plain = light(None, None);
        let both_on = light(Some(true), Some(true));
        // A glass target with `refraction on` under a light without a block: refracts, and
        // its shadow is black; under a light with `refraction off` neither.
        let glass = object(true, Some(true), Some(false));
        assert!(glass.refracts(&plain) && glass.stops_shadows(&plain));
        let off = light(Some(false), Some(false));
        assert!(!glass.refracts(&off) && !glass.stops_shadows(&off));
        // A bare target mirror: no photons under a plain light, reflects under `reflection
        // on`.
        let bare = object(true, None, None);
        assert!(!bare.reflects(&plain) && !bare.refracts(&plain));
        assert!(bare.reflects(&light(None, Some(true))));
        // A bare target box under a light with both on: photons pass, its shadow stays.
        assert!(bare.refracts(&both_on) && !bare.stops_shadows(&both_on));
        // An object without a block: reflects and refracts under the light's `on` (a clear
        // slab under a glass target shows the caustic through it), stops them under a
        // plain light.
        let none = ObjectPhotons::default();
        assert!(none.reflects(&both_on) && none.refracts(&both_on));
        assert!(!none.reflects(&plain) && !none.refracts(&plain));
        // The object's own `off` wins over the light's `on`.
        assert!(!object(false, None, Some(false)).reflects(&both_on));
        assert!(!object(true, Some(false), None).refracts(&both_on));
    }
}
