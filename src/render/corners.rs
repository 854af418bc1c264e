//! The adaptive pilot on the pixels' corners, and the control variate it gives.
//!
//! From [`CORNERS_FROM_SPP`] samples per pixel on, in a scene whose samples vary only with
//! their position in the pixel (no hidden noise, no lens, no mesh camera, no area light),
//! the adaptive pilot traces one ray near corners of the pixel grid instead of one through
//! a random point of every pixel, and none of its values goes into a pixel's mean. It
//! traces every other corner across and down first, then the rest only where those change
//! ([`refinement`]); a corner left out takes its traced neighbours' mean. Against every
//! corner traced (a sample per pixel), at 640x480, 2 seeds, RMSE at 4 / 6 / 8 / 16 spp:
//! checker -9 / -1 / +1 / -3%, pattern_gradient -4 / 0 / 0 / 0%, shape_quadrics -12 / -2
//! / -2 / 0%, reflection -12 / -5 / -3 / 0%, csg_operations -4 / 0 / -1 / -9%, glass +1 / +3
//! / +3 / -9%; the coarse corners alone (a quarter of a sample per pixel) lost on four of
//! the six scenes (checker at 8 spp +56%, glass +55%). From there on:
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
/// the corners (module docs): the corner passes' rays go into no mean, so at a small
/// budget they cost more than they save. Measured at 640x480 against POV-Ray, RMSE of
/// the corners against the pixels' pilot, at 3 / 4 / 6 / 8 spp: checker +9 / -9 / -15 /
/// -13%, pattern_gradient +12 / -3 / -12 / -19%, shape_quadrics +6 / -7 / -10 / -13%,
/// reflection +8 / -6 / -12 / -14%, csg_operations +15 / +1 / -5 / +1%, glass +19 / +7 /
/// +5 / +6% (its far checks, many to a pixel, are most of its error: there every pixel
/// needs samples, and the pixels' pilot keeps its own). Measured again with the bend and
/// the pixels' pilot counted in its pixel's share (twenty-third session), at 3 / 4 / 6 spp:
/// checker +6 / -10 / -15%, pattern_gradient +11 / -7 / -18%, shape_quadrics +2 / -12 /
/// -18%, reflection -1 / -14 / -20%, csg_operations +13 / 0 / -6%, glass +18 / +5 / 0%.
/// With the corners traced only where a coarse pass finds change ([`refinement`]: 0.37 to
/// 0.97 samples per pixel on these scenes instead of 1), at 2 / 2.5 / 3 spp: checker -4 /
/// -14 / -14%, pattern_gradient +20 / +4 / -3%, shape_quadrics -14 / -20 / -22%, reflection
/// -16 / -23 / -24%, csg_operations +19 / +7 / 0%, glass +23 / +12 / +6%.
pub(super) const CORNERS_FROM_SPP: f64 = 3.0;

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
///
/// Corners the pilot did not trace ([`refinement`]) take the mean of the two traced
/// corners beside them, or of the four around them, and their cost.
pub(super) fn corner_pixels(
    corners: &Film,
    work: &mut [PixelWork],
) -> (Vec<AdaptivePixel>, Control) {
    let (cw, ch) = (corners.width, corners.height);
    let mut values = means(corners);
    fill_untraced(corners, &mut values, work);
    let work = &*work;
    let (w, h) = (cw - 1, ch - 1);
    let bend = bends(&values, &whole_line(cw), &whole_line(ch));
    let own: Vec<f64> = (0..w * h)
        .map(|i| cell_change(&values, &bend, cell_corners(i, w)))
        .collect();
    let pixels = super::per_neighbourhood(w, h, |i, near| {
        let c = cell_corners(i, w);
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

/// The four corners of cell i of a grid w cells wide (w + 1 corners).
fn cell_corners(i: usize, w: usize) -> [usize; 4] {
    let (x, y, cw) = (i % w, i / w, w + 1);
    [
        y * cw + x,
        y * cw + x + 1,
        (y + 1) * cw + x,
        (y + 1) * cw + x + 1,
    ]
}

/// A cell's change: its corners' range, or the most they bend where that is less.
fn cell_change(values: &[[f32; 3]], bend: &[f64], corners: [usize; 4]) -> f64 {
    let most = corners.iter().map(|&k| bend[k]).fold(0.0, f64::max);
    super::neighbour_change(values, &corners).min(most)
}

/// The corners' values in single precision (0 where none was traced).
fn means(corners: &Film) -> Vec<[f32; 3]> {
    corners
        .pixels
        .iter()
        .map(|p| p.mean().map(|v| v as f32))
        .collect()
}

/// Whether each corner of a cw x ch grid is in the pilot's first pass: every other one
/// across and down, and the last column and row, so that every corner left out lies
/// midway between two traced ones, or amid four.
pub(super) fn coarse(cw: usize, ch: usize) -> Vec<bool> {
    (0..cw * ch)
        .map(|k| on_coarse_line(k % cw, cw) && on_coarse_line(k / cw, ch))
        .collect()
}

/// Whether position i along an axis n corners long is a [`coarse`] one.
fn on_coarse_line(i: usize, n: usize) -> bool {
    i.is_multiple_of(2) || i + 1 == n
}

/// Every position along an axis n corners long.
fn whole_line(n: usize) -> Vec<usize> {
    (0..n).collect()
}

/// The positions of the [`coarse`] corners along an axis n corners long.
fn coarse_line(n: usize) -> Vec<usize> {
    (0..n).filter(|&i| on_coarse_line(i, n)).collect()
}

/// The change above which a block of 2 x 2 pixels takes the rest of its corners, at an
/// average of `average` samples per pixel: [`REFINE`] / average^2.
pub(super) fn refine_threshold(average: f64) -> f64 {
    REFINE / (average * average)
}

/// A block's change (its coarse corners' range, or their bend on the coarse grid where
/// that is less) times the average squared above which the block's other corners are
/// traced. The more samples a pixel takes, the less of its error a corner's guess may be:
/// measured at 640x480, 2 seeds, RMSE at 3 / 4 / 8 spp with a threshold of k / spp against
/// k / spp^2 (and against every corner traced, the pixels' pilot at 3 spp): k / spp with
/// k = 0.006 / 0.012 / 0.024 left glass at 8 spp 0.00402 / 0.00426 / 0.00427 (every corner:
/// 0.00407) and pattern_gradient at 3 spp 0.00721 / 0.00692 / 0.00636 (0.00656); 0.072 /
/// spp^2 gives 0.00419 and 0.00636, and checker 0.00293 / 0.00228 / 0.00168 (0.00340 /
/// 0.00250 / 0.00167).
const REFINE: f64 = 0.072;

/// The corners the pilot's second pass traces: those not yet traced of every block of 2 x 2
/// pixels whose change exceeds `threshold` ([`REFINE`]), or whose neighbours mostly change
/// twice as much as it does (the [`change`] rule; a texture finer than a block can leave
/// its four corners alike). A straight edge through a block parts its corners, so only
/// detail within the block goes unseen; its guessed corners stand in the control variate,
/// which keeps each sample's expectation whatever they are.
pub(super) fn refinement(first: &Film, threshold: f64) -> Vec<bool> {
    let (cw, ch) = (first.width, first.height);
    let values = means(first);
    let (xs, ys) = (coarse_line(cw), coarse_line(ch));
    let (bw, bh) = (xs.len() - 1, ys.len() - 1);
    // The coarse corners' values, as a grid of their own whose cells are the blocks.
    let coarse_values: Vec<[f32; 3]> = (0..xs.len() * ys.len())
        .map(|k| values[ys[k / xs.len()] * cw + xs[k % xs.len()]])
        .collect();
    let bend = bends(&coarse_values, &xs, &ys);
    let own: Vec<f64> = (0..bw * bh)
        .map(|b| cell_change(&coarse_values, &bend, cell_corners(b, bw)))
        .collect();
    let mut rest = vec![false; cw * ch];
    for b in 0..bw * bh {
        let (bx, by) = (b % bw, b / bw);
        let (near, n) = super::neighbours(bw, bh, bx, by);
        if change(&own, b, &near[..n]) <= threshold {
            continue;
        }
        for y in ys[by]..=ys[by + 1] {
            for x in xs[bx]..=xs[bx + 1] {
                rest[y * cw + x] = first.pixels[y * cw + x].count == 0;
            }
        }
    }
    rest
}

/// Gives each corner no pass traced the mean of the traced corners beside it (along its
/// row first, then down its column: a corner amid four takes their mean) and the cost of
/// one of them.
fn fill_untraced(corners: &Film, values: &mut [[f32; 3]], work: &mut [PixelWork]) {
    let (cw, ch) = (corners.width, corners.height);
    let mean = |a: [f32; 3], b: [f32; 3]| std::array::from_fn(|c| 0.5 * (a[c] + b[c]));
    let untraced = |k: usize| corners.pixels[k].count == 0;
    for y in coarse_line(ch) {
        for k in (1..cw - 1)
            .step_by(2)
            .map(|x| y * cw + x)
            .filter(|&k| untraced(k))
        {
            values[k] = mean(values[k - 1], values[k + 1]);
            work[k].rays = work[k - 1].rays;
        }
    }
    for y in (1..ch - 1).step_by(2) {
        for k in (y * cw..(y + 1) * cw).filter(|&k| untraced(k)) {
            values[k] = mean(values[k - cw], values[k + cw]);
            work[k].rays = work[k - cw].rays;
        }
    }
}

/// How far each corner's value bends from the straight line through its neighbours across
/// and down the grid (the larger second difference, averaged over the channels), the
/// corners at positions `xs` across and `ys` down (a coarse grid's last step may be half
/// the others: the line is drawn through the true positions, so a ramp bends nowhere). On
/// the grid's border, the bend at the next corner in; a grid under three corners wide or
/// high bends without limit that way.
fn bends(values: &[[f32; 3]], xs: &[usize], ys: &[usize]) -> Vec<f64> {
    let (cw, ch) = (xs.len(), ys.len());
    // The outer two points' weights, twice the line's at the middle one (1 and 1 on even
    // steps, so that the difference is the plain second difference there).
    let weights = |p: &[usize], m: usize| -> [f32; 2] {
        let (h1, h2) = ((p[m] - p[m - 1]) as f32, (p[m + 1] - p[m]) as f32);
        [2.0 * h2 / (h1 + h2), 2.0 * h1 / (h1 + h2)]
    };
    let second = |a: usize, k: usize, b: usize, [wa, wb]: [f32; 2]| -> f64 {
        (0..3)
            .map(|c| f64::from((values[a][c] * wa - 2.0 * values[k][c] + values[b][c] * wb).abs()))
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
                second(i - 1, i, i + 1, weights(xs, m))
            });
            let down = middle(y, ch).map_or(f64::INFINITY, |m| {
                let i = m * cw + x;
                second(i - cw, i, i + cw, weights(ys, m))
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
    use super::super::film::PixelSum;
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
        let mut work = vec![PixelWork::default(); cw * ch];
        let edge = film(&|x, _| if x >= 4 { 1.0 } else { 0.0 });
        let (pixels, _) = corner_pixels(&edge, &mut work);
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
        let (pixels, _) = corner_pixels(&texture, &mut work);
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

    /// [`corner_film`] with only the [`coarse`] corners traced.
    fn coarse_film(cw: usize, ch: usize, value: &dyn Fn(usize, usize) -> f64) -> Film {
        let mut film = corner_film(cw, ch, value);
        for (p, traced) in film.pixels.iter_mut().zip(coarse(cw, ch)) {
            if !traced {
                *p = PixelSum::default();
            }
        }
        film
    }

    /// On a ramp the coarse corners ask for no more (at a threshold of 1e-6, what 270 spp
    /// would take), and the corners left out take the ramp's values, across both an even
    /// and an odd number of pixels (the last column and row are traced whatever their
    /// parity), so the pixels show no change.
    #[test]
    fn a_coarse_ramp_is_filled_exactly() {
        for (cw, ch) in [(9, 6), (8, 7)] {
            let value = |x: usize, y: usize| 0.25 * x as f64 + 0.125 * y as f64;
            let film = coarse_film(cw, ch, &value);
            let traced = film.pixels.iter().filter(|p| p.count > 0).count();
            assert_eq!(traced, coarse(cw, ch).iter().filter(|&&t| t).count());
            assert!(traced < cw * ch / 2, "{traced} of {}", cw * ch);
            // Above the single-precision roundings of a third's weights (2/3, 4/3).
            let rest = refinement(&film, 1e-6);
            assert!(
                rest.iter().all(|&r| !r),
                "a ramp refines none ({cw} x {ch})"
            );
            let mut work = vec![PixelWork::default(); cw * ch];
            let (pixels, control) = corner_pixels(&film, &mut work);
            for (k, v) in control.values.iter().enumerate() {
                let expect = value(k % cw, k / cw) as f32;
                assert!((v[0] - expect).abs() < 1e-6, "corner {k}: {v:?}, {expect}");
            }
            assert!(pixels.iter().all(|p| p.change == 0.0));
        }
    }

    /// A step between corner columns 4 and 6 (x = 5 and up are 1): the blocks of 2 x 2
    /// pixels it crosses take their other corners, column 5 and the odd rows of columns 4
    /// and 6, and no other block does, at any threshold below the step's change of 1.
    #[test]
    fn a_step_refines_the_blocks_it_crosses() {
        let (cw, ch) = (11, 7);
        let film = coarse_film(cw, ch, &|x, _| if x >= 5 { 1.0 } else { 0.0 });
        for threshold in [0.0, 0.5, 0.99] {
            let rest = refinement(&film, threshold);
            for (k, &r) in rest.iter().enumerate() {
                let (x, y) = (k % cw, k / cw);
                let expect = x == 5 || (x == 4 || x == 6) && y % 2 == 1;
                assert_eq!(r, expect, "corner ({x}, {y}) at {threshold}");
            }
        }
        assert!(refinement(&film, 1.0).iter().all(|&r| !r));
    }

    /// Shading that changes linearly across the pixels (their corners on a ramp) asks for
    /// no samples beyond the floor, where the control variate takes it whole, on the
    /// image's border too; on a curve the change is the bend, less than the range.
    #[test]
    fn a_ramp_of_corners_asks_for_no_samples() {
        let (cw, ch) = (9, 6);
        let mut work = vec![PixelWork::default(); cw * ch];
        let w = cw - 1;
        let ramp = corner_film(cw, ch, &|x, y| 0.25 * x as f64 + 0.125 * y as f64);
        let (pixels, _) = corner_pixels(&ramp, &mut work);
        assert_eq!(pixels.len(), w * (ch - 1));
        for (i, p) in pixels.iter().enumerate() {
            assert_eq!(p.change, 0.0, "pixel {i}");
        }
        let curve = corner_film(cw, ch, &|x, _| 0.01 * (x * x) as f64);
        let (pixels, _) = corner_pixels(&curve, &mut work);
        // Pixel (3, 2): corners at x = 3 and 4, range 0.07, bend 0.02.
        assert!((pixels[2 * w + 3].change - 0.02).abs() < 1e-6);
    }
}
