//! `crackle`: a Voronoi pattern over one random point per unit cube. Measured with POV-Ray
//! 3.7 (`#debug` of `function { pattern { crackle ... } }` at 4000 random points): the value
//! is form . (d1, d2, d3), the distances to the three nearest points, clamped to [0, 1]
//! (default form <-1, 1, 0>: d2 - d1, to 1e-7); `metric m` measures them as
//! (|dx|^m + |dy|^m + |dz|^m)^(1/m); `offset o` turns each into sqrt(d^2 + o^2) (to 1e-7);
//! `solid` gives each cell one value, whatever the form, distributed as POV-Ray's noise
//! (quantiles 1/10/50/90/99% 0.225/0.343/0.506/0.667/0.784 against bozo's
//! 0.224/0.341/0.507/0.667/0.786). The points' distribution matches one uniform point per
//! cube (d1, d2, d3 medians 0.520, 0.721, 0.848 against 0.525, 0.721, 0.848 simulated);
//! the points themselves are penumbra's own hash, so crackle agrees with POV-Ray in
//! distribution, as the noise patterns do.

use std::cell::RefCell;

use glam::DVec3;

use super::noise::{lattice_hash, noise_with};
use crate::scene::Crackle;

const POINT_SEED: u32 = 0xc7ac_41e0;

/// The random point of the cube with corner `cell`.
fn cell_point(cell: [i64; 3]) -> DVec3 {
    let h = lattice_hash(cell[0], cell[1], cell[2], POINT_SEED);
    let a = super::noise::hash(h ^ 0x68bc_21eb);
    let b = super::noise::hash(a ^ 0x02e5_be93);
    let unit = |x: u32| f64::from(x) / (f64::from(u32::MAX) + 1.0);
    DVec3::new(
        cell[0] as f64 + unit(h),
        cell[1] as f64 + unit(a),
        cell[2] as f64 + unit(b),
    )
}

fn distance(d: DVec3, metric: f64) -> f64 {
    if metric == 2.0 {
        return d.length();
    }
    let a = d.abs();
    (a.x.powf(metric) + a.y.powf(metric) + a.z.powf(metric)).powf(1.0 / metric)
}

/// The random points of the 27 cubes around one cube, in the order the search visits them.
struct Neighbourhood {
    /// The cube's corner, when `points` holds its neighbourhood.
    cell: Option<[i64; 3]>,
    points: [DVec3; 27],
}

thread_local! {
    /// The neighbourhood of the last cube searched, per thread: successive evaluations (a
    /// normal's four samples, neighbouring shading points) mostly fall in one cube, and
    /// hashing its 27 points was most of an evaluation's work. POV-Ray keeps such a cache.
    static NEIGHBOURHOOD: RefCell<Neighbourhood> = const {
        RefCell::new(Neighbourhood {
            cell: None,
            points: [DVec3::ZERO; 27],
        })
    };
}

/// The three nearest distances among the 27 cubes around `p`, and the nearest point.
fn nearest_three(p: DVec3, metric: f64) -> ([f64; 3], DVec3) {
    let base = p.floor();
    let cell = [base.x as i64, base.y as i64, base.z as i64];
    NEIGHBOURHOOD.with_borrow_mut(|near| {
        if near.cell != Some(cell) {
            near.points = std::array::from_fn(|n| {
                let (i, j, k) = (n as i64 / 9 - 1, n as i64 / 3 % 3 - 1, n as i64 % 3 - 1);
                cell_point([cell[0] + i, cell[1] + j, cell[2] + k])
            });
            near.cell = Some(cell);
        }
        let mut d = [f64::INFINITY; 3];
        let mut nearest = p;
        for &q in &near.points {
            let r = distance(p - q, metric);
            if r < d[0] {
                nearest = q;
                d = [r, d[0], d[1]];
            } else if r < d[1] {
                d = [d[0], r, d[1]];
            } else if r < d[2] {
                d[2] = r;
            }
        }
        (d, nearest)
    })
}

pub fn crackle_value(c: &Crackle, p: DVec3, generator: u8) -> f64 {
    let (d, nearest) = nearest_three(p, c.metric);
    if c.solid {
        return noise_with(nearest, generator);
    }
    let d = if c.offset == 0.0 {
        d
    } else {
        d.map(|r| r.hypot(c.offset))
    };
    (c.form.x * d[0] + c.form.y * d[1] + c.form.z * d[2]).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn crackle() -> Crackle {
        Crackle::default()
    }

    /// Points spread over many cubes, from a fixed sequence.
    fn points(n: usize) -> impl Iterator<Item = DVec3> {
        (0..n).map(|i| {
            let f = |k: u32| f64::from(super::super::noise::hash(i as u32 * 3 + k)) / 2f64.powi(32);
            DVec3::new(f(0), f(1), f(2)) * 40.0 - 20.0
        })
    }

    /// The kept neighbourhood gives what searching the 27 cubes afresh gives, bit for
    /// bit, whether successive points share a cube or go back to the one before, in two
    /// threads at once.
    #[test]
    fn kept_neighbourhoods_give_the_fresh_search() {
        let fresh = |p: DVec3| {
            let base = p.floor();
            let mut all = Vec::new();
            for i in -1..=1 {
                for j in -1..=1 {
                    for k in -1..=1 {
                        let cell = [base.x as i64 + i, base.y as i64 + j, base.z as i64 + k];
                        all.push(distance(p - cell_point(cell), 2.0));
                    }
                }
            }
            all.sort_by(f64::total_cmp);
            [all[0], all[1], all[2]]
        };
        let check = |scale: f64| {
            let (mut shared, mut previous) = (0, DVec3::ZERO);
            for p in points(3000).map(|p| p * scale) {
                // A point, one beside it (mostly in its cube), then back to the cube before.
                let near = p + DVec3::splat(0.01);
                shared += usize::from(near.floor() == p.floor());
                for q in [p, near, previous] {
                    assert_eq!(nearest_three(q, 2.0).0, fresh(q), "{q}");
                }
                previous = p;
            }
            assert!(shared > 2_800, "{shared}");
        };
        std::thread::scope(|s| {
            s.spawn(|| check(1.0));
            s.spawn(|| check(-0.3));
        });
    }

    #[test]
    fn forms_combine_the_three_distances() {
        let single = |form| Crackle { form, ..crackle() };
        for p in points(500) {
            let d1 = crackle_value(&single(DVec3::X), p, 2);
            let d2 = crackle_value(&single(DVec3::Y), p, 2);
            let d3 = crackle_value(&single(DVec3::Z), p, 2);
            assert!(d1 <= d2 && d2 <= d3, "{p}: {d1} {d2} {d3}");
            if d2 < 1.0 {
                assert!((crackle_value(&crackle(), p, 2) - (d2 - d1)).abs() < 1e-12);
            }
            let off = Crackle {
                offset: 0.5,
                ..single(DVec3::X)
            };
            assert!((crackle_value(&off, p, 2) - d1.hypot(0.5).min(1.0)).abs() < 1e-12);
        }
    }

    #[test]
    fn distances_follow_povray_s_distribution() {
        // POV-Ray's medians of d1, d2, d3 over 4000 points: 0.520, 0.721, 0.848 (SE about
        // 0.006); the metric 1 and 3 means 0.732 and 0.465 (SE 0.004).
        let median = |form: DVec3, metric: f64| {
            let c = Crackle {
                form,
                metric,
                ..crackle()
            };
            let mut v: Vec<f64> = points(4000).map(|p| crackle_value(&c, p, 2)).collect();
            v.sort_by(f64::total_cmp);
            (v[2000], v.iter().sum::<f64>() / v.len() as f64)
        };
        let within = |a: f64, b: f64, tol: f64| assert!((a - b).abs() < tol, "{a} against {b}");
        within(median(DVec3::X, 2.0).0, 0.520, 0.024);
        within(median(DVec3::Y, 2.0).0, 0.721, 0.024);
        within(median(DVec3::Z, 2.0).0, 0.848, 0.024);
        within(median(DVec3::X, 1.0).1, 0.732, 0.016);
        within(median(DVec3::X, 3.0).1, 0.465, 0.016);
    }

    #[test]
    fn solid_is_one_value_per_cell() {
        let solid = Crackle {
            solid: true,
            ..crackle()
        };
        let (_, q) = nearest_three(DVec3::new(3.3, -1.2, 7.9), 2.0);
        // Points close to a cell's own point are in its cell.
        let a = crackle_value(&solid, q + DVec3::splat(1e-3), 2);
        let b = crackle_value(&solid, q - DVec3::splat(1e-3), 2);
        assert_eq!(a, b);
        assert_eq!(a, noise_with(q, 2));
    }
}
