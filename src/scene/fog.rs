//! `fog { }`: POV-Ray's distance fog, which tints what a ray sees by how far it travelled
//! through the atmosphere (no light interaction; that is media's job).

use glam::DVec3;

use super::{Colour, Transform, Turbulence};

/// How the fog's density varies in space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FogKind {
    /// `fog_type 1`: density 1 everywhere.
    Constant,
    /// `fog_type 2`: density 1 up to `offset` along `up`, then 1 / (1 + (h - offset) /
    /// alt)^2 above (a quarter at offset + alt).
    Ground { offset: f64, alt: f64 },
}

/// `turbulence` in a fog: not a change of the density, but of the attenuation, read at one
/// point along the ray (`turb_depth` of the way to the hit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogTurbulence {
    /// The turbulence settings; `amount` scales the point (a frequency, not a strength).
    pub turbulence: Turbulence,
    pub depth: f64,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Fog {
    pub kind: FogKind,
    /// The depth at which exp(-1) of what lies behind still shows.
    pub distance: f64,
    /// rgb: the fog's own colour; filter: how much of what is seen through it is tinted by
    /// that colour; transmit: the least that always shows through.
    pub colour: Colour,
    /// The ground fog's up direction in world space (unit): the fog's transforms turn it,
    /// but do not move the heights (measured: `translate` and `scale <1, 2, 1>` leave a
    /// ground fog as it is, `rotate 90*z` turns it).
    pub up: DVec3,
    pub turbulence: Option<FogTurbulence>,
    /// Where the turbulence is read: world points go through the inverse.
    pub transform: Transform,
}

impl Default for Fog {
    /// POV-Ray's defaults; a distance of 0 means no fog.
    fn default() -> Self {
        Fog {
            kind: FogKind::Constant,
            distance: 0.0,
            colour: Colour::BLACK,
            up: DVec3::Y,
            turbulence: None,
            transform: Transform::IDENTITY,
        }
    }
}
