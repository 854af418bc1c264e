//! Which sampler dimension each random decision reads.
//!
//! The sampler's values are a pure function of (pixel, sample index, dimension, seed), and a
//! dimension's strata are permuted independently of every other dimension's. Two decisions
//! that read the same dimension would be correlated, and a decision whose dimension moved
//! with what earlier events happened to draw would lose its strata. So every decision has a
//! fixed dimension, given here and nowhere else: the camera's decisions first, then one block
//! per trace level holding every decision a surface hit at that level can make.
//!
//! A scene pays only for the decisions it can make: the per-level block holds two 2D slots
//! per light and the roulette and splitting slots always, and the optional slots (random
//! light choice, media, diffuse bounces, dispersion) only when the scene enables them, so
//! adding them does not move the dimensions (and so the image) of scenes that do not use
//! them.

/// What a sampler dimension is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Purpose {
    /// Where in the pixel the camera ray passes (2D).
    PixelPosition,
    /// Where on the lens the camera ray starts (2D).
    Lens,
    /// Where on area light `light` a shadow ray aims (2D).
    LightPosition(u32),
    /// For `area_illumination`, the point of light `light` that shades the surface (2D).
    LightShading(u32),
    /// Russian roulette on the reflected branch (1D).
    RouletteReflection,
    /// Russian roulette on the transmitted branch (1D).
    RouletteTransmission,
    /// The choice between reflection and refraction under `--splitting one` (1D).
    Splitting,
    /// Which light to sample, where lights are chosen at random (1D; optional).
    LightChoice,
    /// A distance along the ray in a participating medium (1D; optional).
    MediaDistance,
    /// A scattering direction in a medium (2D; optional).
    MediaDirection,
    /// A diffuse bounce's direction (2D; optional).
    DiffuseDirection,
    /// Russian roulette on a diffuse bounce (1D; optional).
    DiffuseRoulette,
    /// Which of a dispersing interior's wavelengths a refracted ray carries (1D; optional).
    Dispersion,
}

impl Purpose {
    /// How many consecutive dimensions it reads.
    pub fn width(self) -> u32 {
        match self {
            Purpose::PixelPosition
            | Purpose::Lens
            | Purpose::LightPosition(_)
            | Purpose::LightShading(_)
            | Purpose::MediaDirection
            | Purpose::DiffuseDirection => 2,
            Purpose::RouletteReflection
            | Purpose::RouletteTransmission
            | Purpose::Splitting
            | Purpose::LightChoice
            | Purpose::MediaDistance
            | Purpose::DiffuseRoulette
            | Purpose::Dispersion => 1,
        }
    }
}

/// The camera's decisions, read once per sample before any trace level.
const CAMERA: [Purpose; 2] = [Purpose::PixelPosition, Purpose::Lens];
/// Dimensions per light and level: its shadow-ray point, then its shading point.
const PER_LIGHT: u32 = 4;
/// Decisions every level has, after the lights' slots.
const ALWAYS: [Purpose; 3] = [
    Purpose::RouletteReflection,
    Purpose::RouletteTransmission,
    Purpose::Splitting,
];
/// Decisions a level has only where the scene enables their group, in this order.
const OPTIONAL: [(Purpose, Group); 6] = [
    (Purpose::LightChoice, Group::LightChoice),
    (Purpose::MediaDistance, Group::Media),
    (Purpose::MediaDirection, Group::Media),
    (Purpose::DiffuseDirection, Group::Diffuse),
    (Purpose::DiffuseRoulette, Group::Diffuse),
    (Purpose::Dispersion, Group::Dispersion),
];

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Group {
    LightChoice,
    Media,
    Diffuse,
    Dispersion,
}

/// Which optional decision groups a scene makes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OptionalDecisions {
    pub light_choice: bool,
    pub media: bool,
    pub diffuse: bool,
    pub dispersion: bool,
}

impl OptionalDecisions {
    fn has(self, group: Group) -> bool {
        match group {
            Group::LightChoice => self.light_choice,
            Group::Media => self.media,
            Group::Diffuse => self.diffuse,
            Group::Dispersion => self.dispersion,
        }
    }
}

/// The dimension assignment for one scene: it depends on the number of lights and the
/// optional groups only (not on objects, textures or the image).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DimensionLayout {
    lights: u32,
    optional: OptionalDecisions,
    per_level: u32,
}

impl DimensionLayout {
    pub fn new(lights: usize, optional: OptionalDecisions) -> DimensionLayout {
        let lights = lights as u32;
        let always: u32 = ALWAYS.iter().map(|p| p.width()).sum();
        let extra: u32 = OPTIONAL
            .iter()
            .filter(|(_, g)| optional.has(*g))
            .map(|(p, _)| p.width())
            .sum();
        DimensionLayout {
            lights,
            optional,
            per_level: PER_LIGHT * lights + always + extra,
        }
    }

    /// The first dimension `purpose` reads at trace `level` (1 for the camera ray's hit;
    /// the camera's own purposes ignore the level).
    pub fn dimension(&self, level: u32, purpose: Purpose) -> u32 {
        let camera: u32 = CAMERA.iter().map(|p| p.width()).sum();
        match purpose {
            Purpose::PixelPosition => 0,
            Purpose::Lens => Purpose::PixelPosition.width(),
            _ => camera + (level.max(1) - 1) * self.per_level + self.in_level(purpose),
        }
    }

    /// Dimensions a trace level takes.
    pub fn per_level(&self) -> u32 {
        self.per_level
    }

    /// Every purpose a level of this layout can read, for tests and for documentation.
    pub fn level_purposes(&self) -> Vec<Purpose> {
        let lights =
            (0..self.lights).flat_map(|i| [Purpose::LightPosition(i), Purpose::LightShading(i)]);
        let optional = OPTIONAL
            .iter()
            .filter(|(_, g)| self.optional.has(*g))
            .map(|(p, _)| *p);
        lights.chain(ALWAYS).chain(optional).collect()
    }

    fn in_level(&self, purpose: Purpose) -> u32 {
        let lights = PER_LIGHT * self.lights;
        match purpose {
            Purpose::LightPosition(i) => {
                debug_assert!(i < self.lights);
                PER_LIGHT * i
            }
            Purpose::LightShading(i) => {
                debug_assert!(i < self.lights);
                PER_LIGHT * i + Purpose::LightPosition(i).width()
            }
            _ => lights + self.after_lights(purpose),
        }
    }

    /// Offset of a fixed or optional purpose after the lights' slots.
    fn after_lights(&self, purpose: Purpose) -> u32 {
        let mut offset = 0;
        for p in ALWAYS {
            if p == purpose {
                return offset;
            }
            offset += p.width();
        }
        for (p, group) in OPTIONAL {
            if !self.optional.has(group) {
                continue;
            }
            if p == purpose {
                return offset;
            }
            offset += p.width();
        }
        debug_assert!(false, "{purpose:?} is not in this layout");
        offset
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all_optional() -> Vec<OptionalDecisions> {
        let mut out = Vec::new();
        for bits in 0..16 {
            out.push(OptionalDecisions {
                light_choice: bits & 1 != 0,
                media: bits & 2 != 0,
                diffuse: bits & 4 != 0,
                dispersion: bits & 8 != 0,
            });
        }
        out
    }

    #[test]
    fn no_two_decisions_share_a_dimension() {
        let max_trace_level = 64;
        for lights in [0, 1, 2, 5, 17] {
            for optional in all_optional() {
                let layout = DimensionLayout::new(lights, optional);
                let mut owner = std::collections::HashMap::new();
                let mut claim = |d: u32, what: (u32, Purpose)| {
                    if let Some(other) = owner.insert(d, what) {
                        panic!(
                            "dimension {d}: {other:?} and {what:?} ({lights} lights, {optional:?})"
                        );
                    }
                };
                for p in CAMERA {
                    for k in 0..p.width() {
                        claim(layout.dimension(1, p) + k, (0, p));
                    }
                }
                for level in 1..=max_trace_level {
                    let purposes = layout.level_purposes();
                    let width: u32 = purposes.iter().map(|p| p.width()).sum();
                    assert_eq!(width, layout.per_level());
                    for p in purposes {
                        for k in 0..p.width() {
                            claim(layout.dimension(level, p) + k, (level, p));
                        }
                    }
                }
                // Dense: nothing skipped, so nothing a scene pays for goes unused.
                let camera: u32 = CAMERA.iter().map(|p| p.width()).sum();
                assert_eq!(
                    owner.len() as u32,
                    camera + max_trace_level * layout.per_level()
                );
            }
        }
    }

    #[test]
    fn optional_groups_do_not_move_the_fixed_slots_of_level_one() {
        let plain = DimensionLayout::new(3, OptionalDecisions::default());
        for optional in all_optional() {
            let layout = DimensionLayout::new(3, optional);
            for p in plain.level_purposes() {
                assert_eq!(plain.dimension(1, p), layout.dimension(1, p), "{p:?}");
            }
        }
    }

    #[test]
    fn the_layout_is_the_one_the_renderer_has_always_used() {
        // Pixel 0-1, lens 2-3, then per level 4 per light and three 1D slots: the images
        // rendered before this table existed stay bit-identical.
        let layout = DimensionLayout::new(2, OptionalDecisions::default());
        assert_eq!(layout.per_level(), 11);
        assert_eq!(layout.dimension(1, Purpose::LightPosition(0)), 4);
        assert_eq!(layout.dimension(1, Purpose::LightShading(1)), 4 + 6);
        assert_eq!(layout.dimension(2, Purpose::RouletteReflection), 4 + 11 + 8);
        assert_eq!(
            layout.dimension(2, Purpose::RouletteTransmission),
            4 + 11 + 9
        );
        assert_eq!(layout.dimension(3, Purpose::Splitting), 4 + 22 + 10);
    }
}
