//! `tiling N` and `pavement`: POV-Ray's periodic tilings of the x-z plane, each tile
//! bevelled. Pavements are tilings of one type whose tile is a polyform.
//!
//! Every tiling is one table: two lattice vectors and the polygons of one cell, each with
//! its tile type. The value inside a tile of type t (of n types) is
//! `(t + max(0, 1 - d / bevel)) / n`, d being the distance to the tile's boundary: the
//! tile's body takes t/n and its edge (t+1)/n, which is how POV-Ray's documentation tells
//! users to caulk tiles. Tables and the bevel rule were measured from POV-Ray's renders of
//! each tiling seen from above (the bevel is the smallest tile's inradius, so the smallest
//! tile rises to its edge from a single centre point); no code of POV-Ray's was read.

use glam::{DVec2, DVec3};

mod corners;
mod pavements;
mod penrose;
mod pentagons;
mod table;
use pavements::PAVEMENTS;
use table::TILINGS;

/// One polygon of a tiling's cell (vertices in order, x then z). `edge_bevels`, when not
/// empty, gives each edge (vertex k to k + 1) its own bevel width: tiling 22's dodecagons
/// bevel three of their edges wider than the others (measured).
struct Tile {
    kind: u8,
    vertices: &'static [[f64; 2]],
    edge_bevels: &'static [f64],
}

/// A tiling: the cell's lattice vectors, its tiles, the number of tile types and the
/// bevel width.
/// `grid` holds the directions of the basic grid's lines for pavements: at a reflex corner
/// of a polyform, POV-Ray's distance is the largest of the distances to the grid lines
/// through the corner (squares round a square's reflex corner, hexagons round a triangle's
/// or a hexagon's), not the distance to the corner itself (measured on all 112 pavements).
/// Tilings' tiles are convex and leave it empty.
struct Tiling {
    a: [f64; 2],
    b: [f64; 2],
    tiles: &'static [Tile],
    types: u8,
    bevel: f64,
    grid: &'static [[f64; 2]],
}

/// The tilings penumbra has measured, by POV-Ray's number.
fn table(n: u8) -> Option<&'static Tiling> {
    TILINGS.iter().find(|(k, _)| *k == n).map(|(_, t)| t)
}

/// Whether `tiling n` is modelled (the language refuses the others by name).
pub fn supported(n: u8) -> bool {
    table(n).is_some() || aperiodic(n).is_some()
}

/// The aperiodic tilings: Penrose's first (src/appearance/tiling/pentagons.rs), and his
/// kites and darts and rhombs (src/appearance/tiling/penrose.rs).
enum Aperiodic {
    Pentagons,
    Halves(penrose::Penrose),
}

fn aperiodic(n: u8) -> Option<Aperiodic> {
    match n {
        25 => Some(Aperiodic::Pentagons),
        26 => Some(Aperiodic::Halves(penrose::Penrose::KitesAndDarts)),
        27 => Some(Aperiodic::Halves(penrose::Penrose::Rhombs)),
        _ => None,
    }
}

/// The pavement measured for a choice of polyform, if penumbra has it.
fn pavement(v: &crate::scene::Pavement) -> Option<&'static Tiling> {
    PAVEMENTS
        .iter()
        .find(|(k, _)| *k == (v.sides, v.tiles, v.pattern))
        .map(|(_, t)| t)
}

/// How many arrangements POV-Ray has of `tiles` basic polygons of `sides` sides (POV-Ray's
/// documentation: the polyforms that pave the plane; none of 6 hexagons).
pub fn pavement_count(sides: u8, tiles: u8) -> u8 {
    let counts: &[u8] = match sides {
        3 => &[1, 1, 1, 3, 4, 12],
        4 => &[1, 1, 2, 5, 12, 35],
        6 => &[1, 1, 3, 7, 22],
        _ => &[],
    };
    counts
        .get(usize::from(tiles).wrapping_sub(1))
        .copied()
        .unwrap_or(0)
}

/// The pattern value of a pavement at a point (its y is ignored).
pub fn pavement_value(v: &crate::scene::Pavement, p: DVec3) -> f64 {
    let Some(t) = pavement(v) else {
        return 0.0;
    };
    if corners::plain(v) {
        return bevelled(t, p);
    }
    locate(t, DVec2::new(p.x, p.z)).map_or(0.0, |found| {
        let plain_rise = 1.0 - found.depth;
        corners::styled_rise(v, t, found.tile, found.local, plain_rise).max(BODY)
    })
}

/// The pattern value of `tiling n` at a point (its y is ignored).
pub fn tiling_value(n: u8, p: DVec3) -> f64 {
    let flat = DVec2::new(p.x, p.z);
    match aperiodic(n) {
        Some(Aperiodic::Pentagons) => return pentagons::pentagons_value(flat),
        Some(Aperiodic::Halves(tiling)) => return penrose::penrose_value(tiling, flat),
        None => {}
    }
    table(n).map_or(0.0, |t| bevelled(t, p))
}

/// A tiling's value: the tile's type, raised by the bevel near its edge.
fn bevelled(t: &Tiling, p: DVec3) -> f64 {
    locate(t, DVec2::new(p.x, p.z)).map_or(0.0, |found| {
        let rise = (1.0 - found.depth).max(BODY);
        (f64::from(found.tile.kind) + rise) / f64::from(t.types)
    })
}

/// How far above t/n a tile's flat body reads. POV-Ray's bodies read a hair above it
/// (measured through `frequency` and `phase` into a colour map ramp 1e-11 wide: tiling 7's
/// octagons 1e-12 above 1/2, tiling 9's hexagons 1.4e-8 above 2/3), so a colour map entry
/// placed exactly at t/n, as POV-Ray's documentation and textures/patterns/tiling.pov place
/// them, colours the body with the type's own entry rather than the caulk below it.
const BODY: f64 = 1e-10;

/// The tile holding a point, the point in the coordinates of the tile's cell, and how deep
/// it lies in the tile: its distance to the tile's boundary in bevel widths.
struct Found<'a> {
    tile: &'a Tile,
    local: DVec2,
    depth: f64,
}

fn locate(t: &Tiling, q: DVec2) -> Option<Found<'_>> {
    let (a, b) = (DVec2::from(t.a), DVec2::from(t.b));
    let det = a.perp_dot(b);
    let u = (q.perp_dot(b) / det).floor();
    let v = (a.perp_dot(q) / det).floor();
    // The cell's polygons may reach past the parallelogram spanned by a and b, so the
    // point is looked for in the neighbouring cells' copies too, nearest cells first.
    for (di, dj) in NEIGHBOURS {
        let local = q - a * (u + f64::from(di)) - b * (v + f64::from(dj));
        for tile in t.tiles {
            if let Some(depth) = depth_in(tile, t, local) {
                return Some(Found { tile, local, depth });
            }
        }
    }
    None
}

/// The 5 x 5 cells round a point's own, ring by ring: tiles do not overlap, so the order
/// only decides how soon the tile is found (most points lie in their own cell's copy).
const NEIGHBOURS: [(i8, i8); 25] = [
    (0, 0),
    (-1, 0),
    (1, 0),
    (0, -1),
    (0, 1),
    (-1, -1),
    (-1, 1),
    (1, -1),
    (1, 1),
    (-2, 0),
    (2, 0),
    (0, -2),
    (0, 2),
    (-2, -1),
    (-2, 1),
    (2, -1),
    (2, 1),
    (-1, -2),
    (1, -2),
    (-1, 2),
    (1, 2),
    (-2, -2),
    (-2, 2),
    (2, -2),
    (2, 2),
];

/// When `q` lies inside the tile, its distance to the tile's boundary in bevel widths (each
/// edge's own width where the tile has them).
fn depth_in(tile: &Tile, t: &Tiling, q: DVec2) -> Option<f64> {
    let vertices = tile.vertices;
    if !inside(vertices, q) {
        return None;
    }
    let mut nearest = f64::INFINITY;
    let n = vertices.len();
    // Only pavements look for reflex corners; tilings' tiles are convex.
    let turn = if t.grid.is_empty() {
        0.0
    } else {
        orientation(vertices)
    };
    for i in 0..n {
        let s = DVec2::from(vertices[i]);
        let e = DVec2::from(vertices[(i + 1) % n]);
        let edge = e - s;
        let width = tile.edge_bevels.get(i).copied().unwrap_or(t.bevel);
        nearest = nearest.min(segment_distance(q, s, e) / width);
        let before = s - DVec2::from(vertices[(i + n - 1) % n]);
        if before.perp_dot(edge) * turn < 0.0 {
            let p = q - s;
            let corner = t
                .grid
                .iter()
                .map(|&u| DVec2::from(u).perp_dot(p).abs())
                .fold(0.0, f64::max);
            nearest = nearest.min(corner / t.bevel);
        }
    }
    Some(nearest)
}

/// Whether `q` lies inside the polygon (by the crossings of a ray along +x).
fn inside(vertices: &[[f64; 2]], q: DVec2) -> bool {
    let n = vertices.len();
    let mut inside = false;
    for i in 0..n {
        let s = DVec2::from(vertices[i]);
        let e = DVec2::from(vertices[(i + 1) % n]);
        if (s.y > q.y) != (e.y > q.y) && q.x < s.x + (q.y - s.y) * (e.x - s.x) / (e.y - s.y) {
            inside = !inside;
        }
    }
    inside
}

/// The distance from `q` to the segment from `s` to `e`.
fn segment_distance(q: DVec2, s: DVec2, e: DVec2) -> f64 {
    let edge = e - s;
    let along = ((q - s).dot(edge) / edge.length_squared()).clamp(0.0, 1.0);
    (s + edge * along).distance(q)
}

/// The sign of a polygon's turning: +1 counter-clockwise in (x, z), -1 clockwise.
fn orientation(vertices: &[[f64; 2]]) -> f64 {
    let n = vertices.len();
    let twice_area: f64 = (0..n)
        .map(|i| DVec2::from(vertices[i]).perp_dot(DVec2::from(vertices[(i + 1) % n])))
        .sum();
    twice_area.signum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(n: u8, x: f64, z: f64) -> f64 {
        tiling_value(n, DVec3::new(x, 7.0, z))
    }

    #[test]
    fn every_point_lies_in_a_tile_of_every_tiling() {
        let all = TILINGS.iter().map(|(n, t)| (format!("tiling {n}"), t));
        let pavements = PAVEMENTS
            .iter()
            .map(|(k, t)| (format!("pavement {k:?}"), t));
        for (n, t) in all.chain(pavements) {
            for i in 0..2000 {
                let x = f64::from(i % 40) * 0.731 - 17.0;
                let z = f64::from(i / 40) * 0.593 - 15.0;
                let found = locate(t, DVec2::new(x, z)).map(|f| (f.tile.kind, f.depth));
                assert!(found.is_some(), "tiling {n} has a gap at ({x}, {z})");
                let (kind, d) = found.unwrap();
                assert!(kind < t.types && d >= 0.0, "tiling {n} at ({x}, {z})");
            }
        }
    }

    #[test]
    fn every_polyform_pov_ray_counts_has_a_table() {
        for sides in [3, 4, 6] {
            for tiles in 1..=6 {
                for pattern in 1..=pavement_count(sides, tiles) {
                    let v = crate::scene::Pavement {
                        sides,
                        tiles,
                        pattern,
                        ..Default::default()
                    };
                    assert!(pavement(&v).is_some(), "{sides} {tiles} {pattern}");
                }
            }
        }
        assert_eq!(PAVEMENTS.len(), 112);
    }

    #[test]
    fn square_tiles_rise_from_their_centres_to_their_edges() {
        assert!(at(1, 0.5, 0.5).abs() < 1e-9);
        assert!((at(1, 0.75, 0.5) - 0.5).abs() < 1e-12);
        assert!((at(1, 0.99, 0.4) - 0.98).abs() < 1e-9);
    }

    #[test]
    fn octagons_keep_a_flat_body_inside_the_bevel() {
        // The bevel is the small square's inradius (0.5): the octagon (type 1 of 2) is flat
        // at 0.5 more than 0.5 from its edge, which lies 1.207 from its centre.
        assert!((at(7, 0.0, 0.0) - 0.5).abs() < 1e-9);
        assert_eq!(at(7, 0.6, 0.0), at(7, 0.0, 0.0));
        // A hair above 1/2, so that a colour map entry at 1/2 colours it.
        assert!(at(7, 0.0, 0.0) > 0.5);
        let edge = (1.0 + std::f64::consts::SQRT_2) / 2.0;
        assert!((at(7, edge - 0.25, 0.0) - 0.75).abs() < 1e-9);
        // The square's centre reads 0, its type's lowest value.
        assert!(at(7, edge, edge).abs() < 1e-9);
    }
}
