//! What a ray that leaves the scene sees: the sky sphere's pigments over the background.
//!
//! POV-Ray layers them in two ways, chosen by `#version` (measured with uniform `rgbft`
//! layers, one pixel, background black, white and each primary):
//! - 3.7: bottom up, each layer `c (1 - f - t) + below (c f + t)`, the filter colouring
//!   what lies below.
//! - older: top down, each layer adds `c (1 - f - t)` times the plain sum `f + t` of the
//!   layers above it, so a filtering layer does not tint the layers below; the background
//!   shows through `prod(c) prod(f) + prod(t)`. Two layers of colour (.2,.4,.6) and
//!   (.5,.6,.7) with filter .5/.3 and transmit .1/.2 give (0.290, 0.380, 0.470) over black
//!   (3.7's rule: (0.299, 0.418, 0.563) less the background) and pass 0.035/0.056/0.083 of a
//!   white background. A layer filtering 0.9 over an opaque one lets 0.9 of it through, not
//!   0.9 times its colour: skysph2.pov's white clouds over a blue gradient.

use glam::DVec3;

use crate::appearance::evaluate_pigment;
use crate::scene::{Colour, SkySphere};

/// The sky's colour in the unit direction `d`.
pub fn sky_colour(sky: &SkySphere, d: DVec3, background: DVec3, legacy: bool) -> DVec3 {
    let layers = sky.pigments.iter().map(|p| evaluate_pigment(p, d));
    if legacy {
        layer_top_down(layers.rev(), sky.emission, background)
    } else {
        layers.fold(background, |below, c| {
            c.rgb * (1.0 - c.filter - c.transmit) * sky.emission
                + below * (c.rgb * c.filter + DVec3::splat(c.transmit))
        })
    }
}

/// The pre-3.7 rule, the top layer first.
fn layer_top_down(
    layers: impl Iterator<Item = Colour>,
    emission: DVec3,
    background: DVec3,
) -> DVec3 {
    let mut colour = DVec3::ZERO;
    let mut seen = 1.0;
    let (mut tint, mut filter, mut transmit) = (DVec3::ONE, 1.0, 1.0);
    for c in layers {
        colour += c.rgb * (seen * (1.0 - c.filter - c.transmit)) * emission;
        seen *= c.filter + c.transmit;
        tint *= c.rgb;
        filter *= c.filter;
        transmit *= c.transmit;
    }
    colour + background * (tint * filter + DVec3::splat(transmit))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Pigment, PigmentKind};

    fn sky(layers: &[[f64; 5]]) -> SkySphere {
        SkySphere {
            pigments: layers
                .iter()
                .map(|&[r, g, b, f, t]| Pigment {
                    kind: PigmentKind::Solid(Colour {
                        rgb: DVec3::new(r, g, b),
                        filter: f,
                        transmit: t,
                    }),
                    ..Pigment::default()
                })
                .collect(),
            emission: DVec3::ONE,
        }
    }

    fn close(a: DVec3, b: [f64; 3]) {
        assert!(
            (a - DVec3::from(b)).abs().max_element() < 1e-3,
            "{a} against {b:?}"
        );
    }

    /// POV-Ray 3.7.0.10's values (half-float EXR) for the layers in the module comment.
    #[test]
    fn layers_follow_povray_for_both_versions() {
        let two = sky(&[[0.2, 0.4, 0.6, 0.5, 0.1], [0.5, 0.6, 0.7, 0.3, 0.2]]);
        let bg = DVec3::new(0.3, 0.5, 0.7);
        close(
            sky_colour(&two, DVec3::Y, bg, false),
            [0.2991, 0.4175, 0.5630],
        );
        close(
            sky_colour(&two, DVec3::Y, bg, true),
            [0.3005, 0.4080, 0.5283],
        );
        close(
            sky_colour(&two, DVec3::Y, DVec3::ZERO, true),
            [0.2900, 0.3799, 0.4700],
        );
        close(
            sky_colour(&two, DVec3::Y, DVec3::ONE, true),
            [0.3250, 0.4360, 0.5532],
        );
        // Filter in one layer, transmit in the other: nothing of the background passes.
        let mixed = sky(&[[0.2, 0.4, 0.6, 0.5, 0.0], [0.5, 0.6, 0.7, 0.0, 0.3]]);
        close(
            sky_colour(&mixed, DVec3::Y, DVec3::ONE, true),
            [0.3799, 0.4800, 0.5801],
        );
        // skysph2.pov's layering: an opaque base, a thin and a nearly clear cloud.
        let clouds = sky(&[
            [0.2, 0.4, 0.6, 0.0, 0.0],
            [0.75, 0.75, 0.75, 0.1, 0.0],
            [0.45, 0.45, 0.45, 0.9, 0.0],
        ]);
        close(
            sky_colour(&clouds, DVec3::Y, bg, true),
            [0.6704, 0.6885, 0.7065],
        );
        close(
            sky_colour(&clouds, DVec3::Y, bg, false),
            [0.3245, 0.3306, 0.3367],
        );
    }
}
