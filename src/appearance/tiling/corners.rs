//! pavement's corner styles: `exterior` (convex corners of 60 and 90 degrees), `form`
//! (120-degree corners of triangles and hexagons, the bend of an L of squares) and
//! `interior` (corners of 180 degrees and more). Measured on all 112 pavements from POV-Ray's
//! printed values (docs/appearance.md), never from its code.
//!
//! Each basic polygon (a square, triangle or hexagon of side 1) is split into corner zones,
//! the points nearer one of its vertices than the others. A style changes the value only in
//! the zones of the vertices it applies to, which is decided by how many of the basic
//! polygons round the vertex belong to the tile: one square is a 90-degree corner, three a
//! 270-degree one; one triangle 60 degrees, two 120 and so on.

use super::{Tile, Tiling, inside};
use crate::scene::Pavement;
use glam::DVec2;

const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// Which basic polygon a pavement is made of.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Grid {
    Squares,
    Triangles,
    Hexagons,
}

/// The vertex of the basic polygon nearest the point, with the tile's polygons round it.
struct Corner {
    vertex: DVec2,
    /// How many basic polygons round the vertex lie in the tile.
    around: usize,
    /// The unit bisector from the vertex into the tile.
    bisector: DVec2,
}

/// Whether a pavement's styles leave every value as the default corners give it (form 3
/// of triangles and hexagons is form 0: POV-Ray takes their form modulo 3).
pub(super) fn plain(v: &Pavement) -> bool {
    let form = if v.sides == 4 { v.form } else { v.form % 3 };
    v.interior == 0 && v.exterior == 0 && form == 0
}

/// The rise (0 in a tile's body, 1 at its edge) at `q`, a point inside `tile` in the cell's
/// coordinates, whose default rise is `plain_rise`.
pub(super) fn styled_rise(v: &Pavement, t: &Tiling, tile: &Tile, q: DVec2, plain_rise: f64) -> f64 {
    let rise = match grid(v) {
        Grid::Squares => square_rise(v, tile, q, plain_rise),
        grid => polygon_rise(v, t, grid, tile, q, plain_rise),
    };
    rise.min(1.0)
}

fn grid(v: &Pavement) -> Grid {
    match v.sides {
        4 => Grid::Squares,
        6 => Grid::Hexagons,
        _ => Grid::Triangles,
    }
}

/// The norm a style number picks: 0 the largest coordinate, 1 their sum, 2 Euclidean.
fn norm(style: u8, a: f64, b: f64) -> f64 {
    match style {
        1 => a + b,
        2 => a.hypot(b),
        _ => a.max(b),
    }
}

/// Squares (side 1, bevel 1/2). In a bend (a square whose only two neighbours in the tile
/// meet at a missing square) `form` 0 to 2 draws a quarter ring round the inner corner V:
/// r = norm(P - V), distance min(r, 1 - r). Elsewhere, in the quarter at a convex corner
/// the distance is 1/2 - norm(offset from the square's centre) by `exterior`, and at a
/// reflex corner norm(P - V) by `interior`.
fn square_rise(v: &Pavement, tile: &Tile, q: DVec2, plain_rise: f64) -> f64 {
    let cell = q.floor();
    let centre = cell + DVec2::splat(0.5);
    let holds = |dx: f64, dz: f64| inside(tile.vertices, centre + DVec2::new(dx, dz));
    if v.form < 3
        && let Some(corner) = bend(&holds)
    {
        let p = (q - (centre + corner * 0.5)).abs();
        let r = norm(v.form, p.x, p.y);
        return 1.0 - 2.0 * r.min(1.0 - r);
    }
    let toward = DVec2::new((q.x - centre.x).signum(), (q.y - centre.y).signum());
    let p = (q - (centre + toward * 0.5)).abs();
    match (holds(toward.x, 0.0), holds(0.0, toward.y)) {
        (false, false) => 2.0 * norm(v.exterior, 0.5 - p.x, 0.5 - p.y),
        (true, true) if !holds(toward.x, toward.y) => 1.0 - 2.0 * norm(v.interior, p.x, p.y),
        _ => plain_rise,
    }
}

/// When the square is a bend, the direction (±1, ±1) from its centre to its inner corner.
fn bend(holds: &impl Fn(f64, f64) -> bool) -> Option<DVec2> {
    let only = |plus: bool, minus: bool| match (plus, minus) {
        (true, false) => Some(1.0),
        (false, true) => Some(-1.0),
        _ => None,
    };
    let dx = only(holds(1.0, 0.0), holds(-1.0, 0.0))?;
    let dz = only(holds(0.0, 1.0), holds(0.0, -1.0))?;
    (!holds(dx, dz)).then_some(DVec2::new(dx, dz))
}

/// Triangles and hexagons (side 1 on the triangle grid, bevel W = sqrt(3)/6): a style
/// raises the value near its corner, taking the larger of its own and the default's.
fn polygon_rise(
    v: &Pavement,
    t: &Tiling,
    grid: Grid,
    tile: &Tile,
    q: DVec2,
    plain_rise: f64,
) -> f64 {
    let c = corner(grid, tile, q);
    let w = t.bevel;
    let p = q - c.vertex;
    let along = p.dot(c.bisector);
    let angle = c.around * if grid == Grid::Triangles { 60 } else { 120 };
    let extra = match (angle, v.exterior, v.form % 3, v.interior) {
        (60, 1, _, _) => 2.0 - along / w,
        (60, 2, _, _) => (p - c.bisector * 2.0 * w).length() / w,
        (120, _, 1, _) => 2.0 - 4.0 * along,
        (120, _, 2, _) => 1.0 - (SQRT_3 / 2.0 - (p - c.bisector).length()) / w,
        (180..=300, _, _, 1) => {
            let reach = t.grid.iter().map(|&u| DVec2::from(u).dot(p).abs());
            1.0 - 3.0 * reach.fold(0.0, f64::max)
        }
        (180..=300, _, _, 2) => 1.0 - 3.0 * p.length(),
        _ => 0.0,
    };
    plain_rise.max(extra)
}

/// The grid point (i, j) of the triangle grid at i (1, 0) + j (1/2, sqrt(3)/2).
fn grid_point(i: f64, j: f64) -> DVec2 {
    DVec2::new(i + j / 2.0, j * SQRT_3 / 2.0)
}

/// The corner of the basic triangle or hexagon holding `q` nearest to it.
fn corner(grid: Grid, tile: &Tile, q: DVec2) -> Corner {
    let j = q.y * 2.0 / SQRT_3;
    let i = q.x - j / 2.0;
    let (i0, j0) = (i.floor(), j.floor());
    let up = (i - i0) + (j - j0) < 1.0;
    let triangle = if up {
        [(i0, j0), (i0 + 1.0, j0), (i0, j0 + 1.0)]
    } else {
        [(i0 + 1.0, j0), (i0 + 1.0, j0 + 1.0), (i0, j0 + 1.0)]
    };
    // A hexagon's centre is a grid point of the residue (i - j) mod 3 that its vertices
    // never take; the other two points of the triangle are its corners.
    let centre_residue = (grid == Grid::Hexagons).then(|| hexagon_centre_residue(tile));
    let is_centre = |(a, b): (f64, f64)| Some(residue(a, b)) == centre_residue;
    let vertex = triangle
        .iter()
        .filter(|&&g| !is_centre(g))
        .map(|&(a, b)| grid_point(a, b))
        .min_by(|x, y| x.distance(q).total_cmp(&y.distance(q)))
        .expect("a triangle has a corner");
    // The centres of the basic polygons round the vertex: six triangles, or the three
    // hexagons among the six grid points next to it.
    let (start, distance) = match grid {
        Grid::Triangles => (30.0, 1.0 / SQRT_3),
        _ => (0.0, 1.0),
    };
    let held = (0..6)
        .map(|k| ring(vertex, start + 60.0 * f64::from(k), distance))
        .filter(|&c| grid == Grid::Triangles || is_centre(skew(c)))
        .filter(|&c| inside(tile.vertices, c));
    let (around, sum) = held.fold((0, DVec2::ZERO), |(n, s), c| (n + 1, s + (c - vertex)));
    Corner {
        vertex,
        around,
        bisector: sum.normalize_or_zero(),
    }
}

/// The point at `distance` from `from` in the direction `degrees` from +x.
fn ring(from: DVec2, degrees: f64, distance: f64) -> DVec2 {
    let (s, c) = degrees.to_radians().sin_cos();
    from + DVec2::new(c, s) * distance
}

/// The (rounded) triangle-grid coordinates of a grid point.
fn skew(p: DVec2) -> (f64, f64) {
    let j = (p.y * 2.0 / SQRT_3).round();
    ((p.x - j / 2.0).round(), j)
}

fn residue(i: f64, j: f64) -> i64 {
    ((i - j) as i64).rem_euclid(3)
}

/// The residue of the tile's hexagons' centres: the one its first two corners leave.
fn hexagon_centre_residue(tile: &Tile) -> i64 {
    let (a, b) = (tile.vertices[0], tile.vertices[1]);
    let (ra, rb) = (skew(DVec2::from(a)), skew(DVec2::from(b)));
    (3 - residue(ra.0, ra.1) - residue(rb.0, rb.1)).rem_euclid(3)
}
