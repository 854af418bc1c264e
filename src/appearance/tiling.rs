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
use std::sync::OnceLock;

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

/// The tilings penumbra has measured, by POV-Ray's number, each with its lookup grid.
fn table(n: u8) -> Option<Indexed> {
    static GRIDS: [OnceLock<Grid>; TILINGS.len()] = [const { OnceLock::new() }; TILINGS.len()];
    let i = TILINGS.iter().position(|(k, _)| *k == n)?;
    Some(Indexed::new(&TILINGS[i].1, &GRIDS[i]))
}

/// Whether `tiling n` is modelled (the language refuses the others by name).
pub fn supported(n: u8) -> bool {
    TILINGS.iter().any(|(k, _)| *k == n) || aperiodic(n).is_some()
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
fn pavement(v: &crate::scene::Pavement) -> Option<Indexed> {
    static GRIDS: [OnceLock<Grid>; PAVEMENTS.len()] = [const { OnceLock::new() }; PAVEMENTS.len()];
    // The table is in order of its keys (a test checks): a pattern's every value looks
    // its pavement up, and a scan of 112 keys took about 300 instructions.
    let key = (v.sides, v.tiles, v.pattern);
    let i = PAVEMENTS.binary_search_by_key(&key, |(k, _)| *k).ok()?;
    Some(Indexed::new(&PAVEMENTS[i].1, &GRIDS[i]))
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
        corners::styled_rise(v, t.tiling, found.tile, found.local, plain_rise).max(BODY)
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
fn bevelled(t: Indexed, p: DVec3) -> f64 {
    locate(t, DVec2::new(p.x, p.z)).map_or(0.0, |found| {
        let rise = (1.0 - found.depth).max(BODY);
        (f64::from(found.tile.kind) + rise) / f64::from(t.tiling.types)
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

fn locate(t: Indexed, q: DVec2) -> Option<Found<'static>> {
    let (a, b) = (DVec2::from(t.tiling.a), DVec2::from(t.tiling.b));
    let det = a.perp_dot(b);
    let (u, v) = (q.perp_dot(b) / det, a.perp_dot(q) / det);
    let (cell_u, cell_v) = (u.floor(), v.floor());
    for &(k, i) in t.grid.candidates(u - cell_u, v - cell_v) {
        let (di, dj) = NEIGHBOURS[usize::from(k)];
        let local = q - a * (cell_u + f64::from(di)) - b * (cell_v + f64::from(dj));
        let tile = &t.tiling.tiles[usize::from(i)];
        if let Some(depth) = depth_in(tile, t.tiling, local) {
            return Some(Found { tile, local, depth });
        }
    }
    None
}

/// A tiling's table and its lookup grid.
#[derive(Clone, Copy)]
struct Indexed {
    tiling: &'static Tiling,
    grid: &'static Grid,
}

impl Indexed {
    fn new(tiling: &'static Tiling, grid: &'static OnceLock<Grid>) -> Self {
        let grid = grid.get_or_init(|| Grid::new(tiling));
        Self { tiling, grid }
    }
}

/// Which tile copies of the cells round a point's own can hold it, by where the point lies
/// in its cell: the cell's parallelogram cut into `GRID` x `GRID` bins, each listing the
/// (neighbour, tile) pairs whose polygon's box in cell coordinates meets the bin, in the
/// order the search of every neighbour's every tile would try them. A point is found in
/// the same tile as by that search, having tested two or three polygons instead of up to
/// 25 cells' worth (on textures/patterns/tiling a point took about 900 instructions, now
/// about 500).
struct Grid {
    /// Where each bin's candidates start in `candidates`, with the end after the last bin.
    starts: Vec<u32>,
    candidates: Vec<(u8, u8)>,
}

const GRID: usize = 16;

/// How far past a bin a polygon's box may reach and still be listed: a point's own cell
/// coordinates and its tile-local ones are rounded apart by far less.
const GRID_MARGIN: f64 = 1e-6;

impl Grid {
    fn new(t: &Tiling) -> Self {
        let boxes = cell_boxes(t);
        let mut starts = Vec::with_capacity(GRID * GRID + 1);
        let mut candidates = Vec::new();
        let bin = |i: usize| (i as f64 / GRID as f64, (i + 1) as f64 / GRID as f64);
        for i in 0..GRID {
            for j in 0..GRID {
                starts.push(candidates.len() as u32);
                let (u, v) = (bin(i), bin(j));
                let met = boxes.iter().filter(|b| b.meets(u, v));
                candidates.extend(met.map(|b| b.key));
            }
        }
        starts.push(candidates.len() as u32);
        Self { starts, candidates }
    }

    /// The candidates for a point at (`u`, `v`) in its cell, each coordinate in [0, 1].
    fn candidates(&self, u: f64, v: f64) -> &[(u8, u8)] {
        let index = |x: f64| ((x * GRID as f64) as usize).min(GRID - 1);
        let bin = index(u) * GRID + index(v);
        &self.candidates[self.starts[bin] as usize..self.starts[bin + 1] as usize]
    }
}

/// One neighbour's copy of one tile, (neighbour, tile), with the copy's box in the
/// coordinates of the point's own cell (the lattice vectors a and b as units).
struct CellBox {
    key: (u8, u8),
    lo: DVec2,
    hi: DVec2,
}

impl CellBox {
    /// Whether the box meets the bin spanning `u` and `v` (each a low and a high bound).
    fn meets(&self, u: (f64, f64), v: (f64, f64)) -> bool {
        self.lo.x <= u.1 + GRID_MARGIN
            && self.hi.x >= u.0 - GRID_MARGIN
            && self.lo.y <= v.1 + GRID_MARGIN
            && self.hi.y >= v.0 - GRID_MARGIN
    }
}

/// Every neighbour's copy of every tile, in search order.
fn cell_boxes(t: &Tiling) -> Vec<CellBox> {
    let (a, b) = (DVec2::from(t.a), DVec2::from(t.b));
    let det = a.perp_dot(b);
    let in_cell = |w: &[f64; 2]| {
        let w = DVec2::from(*w);
        DVec2::new(w.perp_dot(b) / det, a.perp_dot(w) / det)
    };
    let mut boxes = Vec::new();
    for (k, &(di, dj)) in NEIGHBOURS.iter().enumerate() {
        let offset = DVec2::new(f64::from(di), f64::from(dj));
        for (i, tile) in t.tiles.iter().enumerate() {
            let corners = tile.vertices.iter().map(in_cell);
            let lo = corners.clone().fold(DVec2::INFINITY, DVec2::min) + offset;
            let hi = corners.fold(DVec2::NEG_INFINITY, DVec2::max) + offset;
            boxes.push(CellBox {
                key: (k as u8, i as u8),
                lo,
                hi,
            });
        }
    }
    boxes
}

/// The 5 x 5 cells round a point's own, ring by ring: the cell's polygons may reach past
/// the parallelogram spanned by its lattice vectors, so a point may lie in a neighbouring
/// cell's copy of a tile. Tiles do not overlap, so the order only decides how soon the tile
/// is found (most points lie in their own cell's copy) and which of two tiles a point on
/// their shared edge takes.
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
    // Only pavements look for reflex corners; tilings' tiles are convex.
    let turn = if t.grid.is_empty() {
        0.0
    } else {
        orientation(vertices)
    };
    let mut nearest = f64::INFINITY;
    let mut before = DVec2::from(vertices[vertices.len() - 1]);
    for (i, &s) in vertices.iter().enumerate() {
        let s = DVec2::from(s);
        let e = DVec2::from(*vertices.get(i + 1).unwrap_or(&vertices[0]));
        let edge = e - s;
        let width = tile.edge_bevels.get(i).copied().unwrap_or(t.bevel);
        nearest = nearest.min(segment_distance(q, s, e) / width);
        if turn != 0.0 && (s - before).perp_dot(edge) * turn < 0.0 {
            let p = q - s;
            let corner = t
                .grid
                .iter()
                .map(|&u| DVec2::from(u).perp_dot(p).abs())
                .fold(0.0, f64::max);
            nearest = nearest.min(corner / t.bevel);
        }
        before = s;
    }
    Some(nearest)
}

/// Whether `q` lies inside the polygon (by the crossings of a ray along +x).
fn inside(vertices: &[[f64; 2]], q: DVec2) -> bool {
    let mut inside = false;
    let mut s = DVec2::from(vertices[vertices.len() - 1]);
    for &e in vertices {
        let e = DVec2::from(e);
        if (s.y > q.y) != (e.y > q.y) && q.x < s.x + (q.y - s.y) * (e.x - s.x) / (e.y - s.y) {
            inside = !inside;
        }
        s = e;
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

    /// Every periodic tiling and pavement with its lookup grid.
    fn every_table() -> Vec<(String, Indexed)> {
        let tilings = TILINGS
            .iter()
            .map(|(n, _)| (format!("tiling {n}"), table(*n).unwrap()));
        let pavements = PAVEMENTS.iter().map(|&((sides, tiles, pattern), _)| {
            let v = crate::scene::Pavement {
                sides,
                tiles,
                pattern,
                ..Default::default()
            };
            (
                format!("pavement {sides} {tiles} {pattern}"),
                pavement(&v).unwrap(),
            )
        });
        tilings.chain(pavements).collect()
    }

    #[test]
    fn every_point_lies_in_a_tile_of_every_tiling() {
        for (n, t) in every_table() {
            for i in 0..2000 {
                let x = f64::from(i % 40) * 0.731 - 17.0;
                let z = f64::from(i / 40) * 0.593 - 15.0;
                let found = locate(t, DVec2::new(x, z)).map(|f| (f.tile.kind, f.depth));
                assert!(found.is_some(), "{n} has a gap at ({x}, {z})");
                let (kind, d) = found.unwrap();
                assert!(kind < t.tiling.types && d >= 0.0, "{n} at ({x}, {z})");
            }
        }
    }

    /// The search the grid replaces: every tile of the 5 x 5 cells round the point's own.
    fn search_every_cell(t: &Tiling, q: DVec2) -> Option<Found<'_>> {
        let (a, b) = (DVec2::from(t.a), DVec2::from(t.b));
        let det = a.perp_dot(b);
        let u = (q.perp_dot(b) / det).floor();
        let v = (a.perp_dot(q) / det).floor();
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

    #[test]
    fn the_grid_finds_the_tile_every_cell_s_search_finds() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64::seed_from_u64(16);
        for (n, t) in every_table() {
            // Points anywhere, and points on the cell's lattice and its tiles' corners,
            // where a point lies on several polygons' edges and the first found decides.
            let corners = t.tiling.tiles.iter().flat_map(|tile| tile.vertices);
            let mut points: Vec<DVec2> = corners.map(|&w| DVec2::from(w)).collect();
            for _ in 0..3000 {
                let scale = [1.0, 10.0, 1e4][rng.random_range(0..3)];
                let x = rng.random_range(-scale..scale);
                points.push(DVec2::new(x, rng.random_range(-scale..scale)));
            }
            for q in points {
                let key = |f: Option<Found>| {
                    f.map(|f| (std::ptr::from_ref(f.tile), f.local.to_array(), f.depth))
                };
                let found = key(locate(t, q));
                assert_eq!(found, key(search_every_cell(t.tiling, q)), "{n} at {q}");
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
        assert!(
            PAVEMENTS.is_sorted_by_key(|(k, _)| *k),
            "looked up by halving"
        );
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
