//! The adaptive pilot on the pixels' corners, and the control variate it gives.
//!
//! From [`CORNERS_FROM_SPP`] samples per pixel on, in a scene whose samples vary only with
//! their position in the pixel (no hidden noise, no lens, no mesh camera, no area light),
//! the adaptive pilot traces one ray near every corner of the pixel grid instead of one
//! through a random point of every pixel, and none of its values goes into a pixel's mean:
//! - a straight edge that crosses a pixel puts its corners on both sides, so the range of
//!   a pixel's four corners finds the pixels an edge crosses; the pilot's neighbours in a
//!   3 x 3 block (point samples anywhere in their pixels) found a band two pixels wide on
//!   the average, half of whose samples fell where no edge was. Where a texture changes
//!   several times a pixel, four corners can agree by chance: there a pixel takes the
//!   change of its neighbours ([`upper_median`]);
//! - the corners' bilinear surface g is known over the whole pixel (its mean is the
//!   corners' mean), so each sample f(x) becomes f(x) - g(x) + mean(g): the same
//!   expectation whatever g is (x is uniform over the pixel and independent of the
//!   corners), and where g follows the image (shading, colour ramps, an edge's two sides)
//!   less variance.
//!
//! Tried first in a simulation (a 5120x3840 one-sample render of scenes/checker.pov and
//! scenes/pattern_gradient.pov read as 320x240 pixels of 16 x 16 points, each pixel's
//! samples stratified), RMSE at 3 / 4 / 6 / 8 samples per pixel, the neighbours' pilot
//! against the corners': checker 0.0091 / 0.0073 / 0.0051 / 0.0042 against 0.0088 /
//! 0.0057 / 0.0040 / 0.0030, pattern_gradient 0.0144 / 0.0115 / 0.0084 / 0.0068 against
//! 0.0142 / 0.0100 / 0.0069 / 0.0053. Not kept from it: subdividing an edge pixel on
//! further corners with one sample a cell (the corners' rays go into no mean: worse at
//! equal rays on both scenes within a pixel's budget), and taking a smooth pixel's one
//! sample only with probability q (its correction weighed 1/q; mixed, worse where the
//! corners miss a detail). Measured in the renderer: [`CORNERS_FROM_SPP`].

use glam::DVec3;

use super::film::Film;
use super::{AdaptivePixel, PilotSample, PixelWork};

/// The least average (samples per pixel) at which an adaptive render takes its pilot at
/// the corners (module docs): the corner pass's sample per pixel goes into no mean, so at
/// a small budget it costs more than it saves. Measured at 640x480 against POV-Ray, RMSE of
/// the corners against the pixels' pilot, at 3 / 4 / 6 / 8 spp: checker +9 / -9 / -15 /
/// -13%, pattern_gradient +12 / -3 / -12 / -19%, shape_quadrics +6 / -7 / -10 / -13%,
/// reflection +8 / -6 / -12 / -14%, csg_operations +15 / +1 / -5 / +1%, glass +19 / +7 /
/// +5 / +6% (its far checks, many to a pixel, are most of its error: there every pixel
/// needs samples, and the pixels' pilot keeps its own). Measured again with the bend and
/// the pixels' pilot counted in its pixel's share (twenty-third session), at 3 / 4 / 6 spp:
/// checker +6 / -10 / -15%, pattern_gradient +11 / -7 / -18%, shape_quadrics +2 / -12 /
/// -18%, reflection -1 / -14 / -20%, csg_operations +13 / 0 / -6%, glass +18 / +5 / 0%.
pub(super) const CORNERS_FROM_SPP: f64 = 4.0;

/// How far (in pixels, each way) a corner's ray may fall from the corner: exact corners
/// alias with a texture whose period is near a pixel, where whole regions of corners agree
/// (scenes/glass.pov's far checks: RMSE at 4 / 8 spp 0.0068 / 0.0053 with exact corners,
/// 0.0055 / 0.0040 with a quarter pixel, 0.0057 / 0.0041 with a half), at some cost where
/// edges are few and long (scenes/checker.pov 0.0023 / 0.0015 exact, 0.0025 / 0.0017 a
/// quarter, 0.0032 / 0.0024 a half: the further the points stray, the wider the band of
/// pixels an edge shows in).
pub(super) const CORNER_JITTER: f64 = 0.25;

/// The pilot's corners, for the control variate of each pixel's samples.
pub(super) struct Control {
    /// The corner grid's width: the image's plus one.
    width: usize,
    /// The corners' values, row by row (finite: the film keeps none that is not).
    values: Vec<[f32; 3]>,
}

impl Control {
    /// A sample `l` of pixel (x, y) at `(u, v)` in the pixel (v down), less the corners'
    /// bilinear surface there, plus the surface's mean over the pixel.
    pub(super) fn apply(&self, (x, y): (usize, usize), (u, v): (f64, f64), l: DVec3) -> DVec3 {
        let at = |dx: usize, dy: usize| {
            DVec3::from_array(self.values[(y + dy) * self.width + x + dx].map(f64::from))
        };
        let (c00, c10, c01, c11) = (at(0, 0), at(1, 0), at(0, 1), at(1, 1));
        let g = (c00 * (1.0 - u) + c10 * u) * (1.0 - v) + (c01 * (1.0 - u) + c11 * u) * v;
        l - g + (c00 + c10 + c01 + c11) * 0.25
    }
}

/// The pixels' decisions from the corner pass (`corners`, (w + 1) x (h + 1), and what each
/// corner's ray cost): the change is the range of a pixel's four corners, or the most they
/// bend ([`bends`]) where that is less ([`change`]), the cost their mean. The control
/// variate takes away what changes linearly across the pixel, so only the bend is left
/// there: with the range alone, smooth shading's pixels took samples they did not need
/// (RMSE at 640x480 and 4 / 6 / 8 / 16 spp with the bend: pattern_gradient 0.00535 /
/// 0.00352 / 0.00275 / 0.00169 -> 0.00482 / 0.00317 / 0.00247 / 0.00156, reflection
/// 0.00061 / 0.00044 / 0.00038 / 0.00031 -> 0.00057 / 0.00041 / 0.00036 / 0.00030,
/// shape_quadrics 0.00071 / 0.00053 / 0.00048 / 0.00042 -> 0.00066 / 0.00051 / 0.00047 /
/// 0.00041, checker 1% lower at 4 and 6, glass and csg_operations within 1%). A scene
/// with area lights keeps the pixels' pilot, so no pixel is near a penumbra: each takes
/// one shadow ray per light per sample, all its samples from its point 0 (no pilot sample
/// is a pixel's).
pub(super) fn corner_pixels(corners: &Film, work: &[PixelWork]) -> (Vec<AdaptivePixel>, Control) {
    let (cw, ch) = (corners.width, corners.height);
    let values: Vec<[f32; 3]> = corners
        .pixels
        .iter()
        .map(|p| p.mean().map(|v| v as f32))
        .collect();
    let (w, h) = (cw - 1, ch - 1);
    let corners_of = |i: usize| -> [usize; 4] {
        let (x, y) = (i % w, i / w);
        [
            y * cw + x,
            y * cw + x + 1,
            (y + 1) * cw + x,
            (y + 1) * cw + x + 1,
        ]
    };
    let bend = bends(&values, cw, ch);
    let own: Vec<f64> = (0..w * h)
        .map(|i| {
            let c = corners_of(i);
            let range = super::neighbour_change(&values, &c);
            range.min(c.iter().map(|&k| bend[k]).fold(0.0, f64::max))
        })
        .collect();
    let pixels = super::per_neighbourhood(w, h, |i, near| {
        let c = corners_of(i);
        AdaptivePixel {
            change: change(&own, i, near),
            cost: super::neighbour_cost(work, &c),
            one_ray: true,
            pilot: PilotSample::LeftOut,
        }
    });
    let control = Control { width: cw, values };
    (pixels, control)
}

/// How far each corner's value bends from the straight line through its neighbours across
/// and down the grid (the larger second difference, averaged over the channels). On the
/// grid's border, the bend at the next corner in; a grid under three corners wide or high
/// bends without limit that way.
fn bends(values: &[[f32; 3]], cw: usize, ch: usize) -> Vec<f64> {
    let second = |a: usize, k: usize, b: usize| -> f64 {
        (0..3)
            .map(|c| f64::from((values[a][c] - 2.0 * values[k][c] + values[b][c]).abs()))
            .sum::<f64>()
            / 3.0
    };
    // The nearest point along an axis n corners long with neighbours both ways.
    let middle = |at: usize, n: usize| (n >= 3).then(|| at.clamp(1, n - 2));
    (0..cw * ch)
        .map(|k| {
            let (x, y) = (k % cw, k / cw);
            let across = middle(x, cw).map_or(f64::INFINITY, |m| {
                let i = y * cw + m;
                second(i - 1, i, i + 1)
            });
            let down = middle(y, ch).map_or(f64::INFINITY, |m| {
                let i = m * cw + x;
                second(i - cw, i, i + cw)
            });
            across.max(down)
        })
        .collect()
}

/// The upper median of a few values (the larger middle one of an even count; 0 of none),
/// sorting them in place: an edge crosses at most three of a pixel's eight neighbours, so
/// this is 0 beside an edge and high only among many, where a texture has several changes
/// to a pixel.
fn upper_median(values: &mut [f64]) -> f64 {
    values.sort_unstable_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(0.0)
}

/// A pixel's change: its corners' range `own[i]`, or where more than half its neighbours
/// change over twice as much, their [`upper_median`]. The test first: in smooth shading
/// every pixel's range is small and about its neighbours', and sorting every pixel's eight
/// took 1.6% of a 6 spp render's instructions.
fn change(own: &[f64], i: usize, near: &[usize]) -> f64 {
    let above = near.iter().filter(|&&j| own[j] > 2.0 * own[i]).count();
    if above < near.len().div_ceil(2) {
        return own[i];
    }
    let mut values = [0.0; 8];
    for (slot, &j) in values.iter_mut().zip(near) {
        *slot = own[j];
    }
    upper_median(&mut values[..near.len()])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The control variate keeps each sample's expectation: over the pixel, the mean of
    /// f - g + mean(g) is the mean of f, for any corners. A 64 x 64 grid of points (the
    /// midpoints of its cells, where the bilinear surface's mean over them is exact) in a
    /// pixel whose corners differ; and it removes a linear ramp whole.
    #[test]
    fn the_control_variate_keeps_the_mean_and_removes_a_ramp() {
        let control = Control {
            width: 3,
            values: vec![
                [0.0, 1.0, 0.5],
                [0.2, 0.0, 0.5],
                [9.0, 9.0, 9.0],
                [0.7, 0.3, 0.5],
                [0.9, 0.1, 0.0],
                [9.0, 9.0, 9.0],
            ],
        };
        let f = |u: f64, v: f64| DVec3::new(u * u, (u * 7.0).sin() * v, 1.0 - v);
        let n = 64;
        let (mut plain, mut controlled) = (DVec3::ZERO, DVec3::ZERO);
        for i in 0..n {
            for j in 0..n {
                let (u, v) = ((i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / n as f64);
                plain += f(u, v);
                controlled += control.apply((0, 0), (u, v), f(u, v));
            }
        }
        let diff = (plain - controlled).abs().max_element() / (n * n) as f64;
        assert!(diff < 1e-12, "means differ by {diff}");
        // The corners of pixel 0 on the ramp 0.2 u + 0.7 v: every sample becomes its mean.
        let ramp = |u: f64, v: f64| DVec3::splat(0.2 * u + 0.7 * v);
        let ramp_control = Control {
            width: 2,
            values: vec![[0.0; 3], [0.2; 3], [0.7; 3], [0.9; 3]],
        };
        for (u, v) in [(0.1, 0.9), (0.5, 0.5), (0.99, 0.01)] {
            let got = ramp_control.apply((0, 0), (u, v), ramp(u, v));
            assert!(
                (got - DVec3::splat(0.45)).abs().max_element() < 1e-6,
                "{got}"
            );
        }
    }

    /// A vertical edge at x = 3.3 on an 8 x 4 image: only the pixels the edge crosses
    /// (column 3) show a change; their neighbours, whose 3 x 3 blocks straddle it, do not.
    /// A band of columns 4 to 7 holding a change every pixel (a texture finer than the
    /// pixels, whose four corners can agree by chance) gives its pixels the change of their
    /// neighbours where their own corners agree.
    #[test]
    fn the_corners_find_the_pixels_an_edge_crosses() {
        let (cw, ch) = (9, 5);
        let film = |value: &dyn Fn(usize, usize) -> f64| corner_film(cw, ch, value);
        let work = vec![PixelWork::default(); cw * ch];
        let edge = film(&|x, _| if x >= 4 { 1.0 } else { 0.0 });
        let (pixels, _) = corner_pixels(&edge, &work);
        for (i, p) in pixels.iter().enumerate() {
            let expect = if i % 8 == 3 { 1.0 } else { 0.0 };
            assert_eq!(p.change, expect, "pixel {i}");
            assert!(p.one_ray && !p.keeps_pilot());
        }
        // Corner columns 5 to 8 alternate, but the four corners of pixel (6, 1) agree.
        let texture = film(&|x, y| match (x, y) {
            (6 | 7, 1 | 2) => 1.0,
            (x, y) if x >= 5 => ((x + y) % 2) as f64,
            _ => 0.0,
        });
        let (pixels, _) = corner_pixels(&texture, &work);
        assert_eq!(pixels[8 + 6].change, 1.0, "agreeing corners among changes");
        assert_eq!(pixels[8 + 2].change, 0.0);
    }

    /// A corner film cw x ch whose corner (x, y) holds `value(x, y)` in every channel.
    fn corner_film(cw: usize, ch: usize, value: &dyn Fn(usize, usize) -> f64) -> Film {
        let mut corners = Film::new(cw, ch);
        for y in 0..ch {
            for x in 0..cw {
                let v = value(x, y);
                corners.pixels[y * cw + x].add([v, v, v]);
            }
        }
        corners
    }

    /// Shading that changes linearly across the pixels (their corners on a ramp) asks for
    /// no samples beyond the floor, where the control variate takes it whole, on the
    /// image's border too; on a curve the change is the bend, less than the range.
    #[test]
    fn a_ramp_of_corners_asks_for_no_samples() {
        let (cw, ch) = (9, 6);
        let work = vec![PixelWork::default(); cw * ch];
        let w = cw - 1;
        let ramp = corner_film(cw, ch, &|x, y| 0.25 * x as f64 + 0.125 * y as f64);
        let (pixels, _) = corner_pixels(&ramp, &work);
        assert_eq!(pixels.len(), w * (ch - 1));
        for (i, p) in pixels.iter().enumerate() {
            assert_eq!(p.change, 0.0, "pixel {i}");
        }
        let curve = corner_film(cw, ch, &|x, _| 0.01 * (x * x) as f64);
        let (pixels, _) = corner_pixels(&curve, &work);
        // Pixel (3, 2): corners at x = 3 and 4, range 0.07, bend 0.02.
        assert!((pixels[2 * w + 3].change - 0.02).abs() < 1e-6);
    }
}
