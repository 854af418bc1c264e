//! `rainbow { }`: a fog-like ring of colour around the direction of a far light, seen by
//! every ray whose direction makes the right angle with it.

use glam::DVec3;

use super::Colour;

/// A rainbow, with POV-Ray's defaults where the block says nothing.
#[derive(Clone, Debug, PartialEq)]
pub struct Rainbow {
    /// The direction the (virtual) light travels, unit length.
    pub direction: DVec3,
    /// The ring's middle and width, as angles from `direction` in degrees.
    pub angle: f64,
    pub width: f64,
    /// As a fog's: the depth at which exp(-1) of what lies behind still shows.
    pub distance: f64,
    /// The most the colour-map index moves at random.
    pub jitter: f64,
    /// Where the arc's middle lies, around `direction` (unit).
    pub up: DVec3,
    /// `arc_angle` and `falloff_angle` in degrees: only a given arc_angle cuts the ring.
    pub arc: Option<(f64, f64)>,
    /// Indexed from 0 (the inner edge) to 1 (the outer).
    pub colour_map: Vec<(f64, Colour)>,
}

impl Default for Rainbow {
    fn default() -> Self {
        Rainbow {
            direction: DVec3::Z,
            angle: 0.0,
            width: 0.0,
            distance: 0.0,
            jitter: 0.0,
            up: DVec3::Y,
            arc: None,
            colour_map: Vec::new(),
        }
    }
}
