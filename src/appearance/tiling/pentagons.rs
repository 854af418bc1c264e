//! `tiling 25`: Penrose's first tiling (P1) of pentagons, pentagrams ("stars"), boats (three
//! fifths of a star) and diamonds (thin rhombs), all of edge 1. Measured: a pentagon of
//! type 0 is centred on the origin with a corner at (-0.8507, 0); POV-Ray's types are the
//! three kinds of pentagon (0, 1, 2), stars 3, boats 4 and diamonds 5, bevelled over
//! 1 / 3.43009 as the rhombs are.
//!
//! The tiling is the fixed point of the substitution that scales by 1 / phi^2 (as
//! the Tilings Encyclopedia and Wikipedia draw it): a pentagon becomes six, one in its
//! middle turned half a turn and one in each corner, with diamonds across its edges where
//! its kind makes them (five, two or none: the three kinds of pentagon); a diamond becomes a
//! pentagon with a boat at its tip and a star at its other end; a star or a boat becomes
//! one star in its middle, a boat in each point and a pentagon between each two points.
//! Children reach beyond their parent (a diamond across a parent's edge belongs to one of
//! the two pentagons that share it), so the tile holding a point is found by substituting
//! every tile near the point, level by level, from one large pentagon round the origin.
//! Each of POV-Ray's 1600 values (tests/tiling_values.rs) is matched by this tiling and
//! by no other orientation of it.

use std::sync::OnceLock;

use glam::DVec2;

const PHI: f64 = 1.618_033_988_749_895;
const INV_PHI: f64 = PHI - 1.0;
const INV_PHI2: f64 = 2.0 - PHI;
const INV_SQRT5: f64 = 0.447_213_595_499_957_9;

/// The bevel width, the rhombs' (measured: every value of tiling 25 agrees to 1e-6).
const BEVEL: f64 = 1.0 / 3.43009;

/// The kinds of tile. The pentagons are told apart by the diamonds their substitution puts
/// across their edges.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Kind {
    /// Diamonds across all five edges (POV-Ray's type 0, the one at the origin).
    Pentagon5,
    /// Diamonds across the two edges at its axis corner (type 2).
    Pentagon2,
    /// No diamonds (type 1).
    Pentagon0,
    Diamond,
    Boat,
    Star,
}

impl Kind {
    fn povray_type(self) -> f64 {
        match self {
            Kind::Pentagon5 => 0.0,
            Kind::Pentagon0 => 1.0,
            Kind::Pentagon2 => 2.0,
            Kind::Star => 3.0,
            Kind::Boat => 4.0,
            Kind::Diamond => 5.0,
        }
    }

    /// The distance from the tile's centre to its axis corner per unit edge: a pentagon's
    /// circumradius, half a diamond's long diagonal, a star's tip (a boat is measured from
    /// the centre of the star it is cut from).
    fn radius(self) -> f64 {
        let pentagon = 0.5 / TURN[1].y;
        match self {
            Kind::Pentagon5 | Kind::Pentagon2 | Kind::Pentagon0 => pentagon,
            Kind::Diamond => TURN[2].y,
            Kind::Boat | Kind::Star => PHI * pentagon,
        }
    }

    fn children(self) -> &'static [Child] {
        match self {
            Kind::Pentagon5 => PENTAGON5,
            Kind::Pentagon2 => PENTAGON2,
            Kind::Pentagon0 => PENTAGON0,
            Kind::Diamond => DIAMOND,
            Kind::Boat => BOAT,
            Kind::Star => STAR,
        }
    }
}

/// Multiples of 36 degrees, as unit vectors (cos 36 = phi / 2, cos 72 = 1 / (2 phi)).
const TURN: [DVec2; 10] = {
    let (c36, s36) = (PHI / 2.0, 0.587_785_252_292_473_1);
    let (c72, s72) = (INV_PHI / 2.0, 0.951_056_516_295_153_5);
    [
        DVec2::new(1.0, 0.0),
        DVec2::new(c36, s36),
        DVec2::new(c72, s72),
        DVec2::new(-c72, s72),
        DVec2::new(-c36, s36),
        DVec2::new(-1.0, 0.0),
        DVec2::new(-c36, -s36),
        DVec2::new(-c72, -s72),
        DVec2::new(c72, -s72),
        DVec2::new(c36, -s36),
    ]
};

/// `v` turned by `k` times 36 degrees.
fn turned(v: DVec2, k: i8) -> DVec2 {
    TURN[usize::from(k.rem_euclid(10).unsigned_abs())].rotate(v)
}

/// One child of a substitution: its kind, its centre (`at` times the parent's axis turned
/// by `at_turn` steps of 36 degrees, from the parent's centre) and its axis's turn from the
/// parent's. Its size is the parent's edge over phi^2.
struct Child {
    kind: Kind,
    at: f64,
    at_turn: i8,
    turn: i8,
}

const fn child(kind: Kind, at: f64, at_turn: i8, turn: i8) -> Child {
    Child {
        kind,
        at,
        at_turn,
        turn,
    }
}

/// A pentagon's corner children sit at its corners (centre 1 / phi of the way out), its
/// middle child half a turn round; diamonds straddle edges (centre on the edge's midpoint,
/// phi / 2 of the way out) with their tips pointing in.
const PENTAGON5: &[Child] = &[
    child(Kind::Pentagon5, 0.0, 0, 5),
    child(Kind::Pentagon2, INV_PHI, 0, 0),
    child(Kind::Pentagon2, INV_PHI, 2, 2),
    child(Kind::Pentagon2, INV_PHI, 4, 4),
    child(Kind::Pentagon2, INV_PHI, -4, -4),
    child(Kind::Pentagon2, INV_PHI, -2, -2),
    child(Kind::Diamond, PHI / 2.0, 1, 6),
    child(Kind::Diamond, PHI / 2.0, 3, 8),
    child(Kind::Diamond, PHI / 2.0, 5, 0),
    child(Kind::Diamond, PHI / 2.0, -3, 2),
    child(Kind::Diamond, PHI / 2.0, -1, 4),
];

const PENTAGON2: &[Child] = &[
    child(Kind::Pentagon5, 0.0, 0, 5),
    child(Kind::Pentagon2, INV_PHI, 0, 0),
    child(Kind::Pentagon2, INV_PHI, 2, 2),
    child(Kind::Pentagon0, INV_PHI, 4, 2),
    child(Kind::Pentagon0, INV_PHI, -4, -2),
    child(Kind::Pentagon2, INV_PHI, -2, -2),
    child(Kind::Diamond, PHI / 2.0, 1, 6),
    child(Kind::Diamond, PHI / 2.0, -1, 4),
];

const PENTAGON0: &[Child] = &[
    child(Kind::Pentagon5, 0.0, 0, 5),
    child(Kind::Pentagon2, INV_PHI, 0, 0),
    child(Kind::Pentagon0, INV_PHI, 2, 0),
    child(Kind::Pentagon0, INV_PHI, 4, -4),
    child(Kind::Pentagon0, INV_PHI, -4, 4),
    child(Kind::Pentagon0, INV_PHI, -2, 0),
];

/// A diamond: a pentagon near its middle, a boat at its tip, a star at its other end.
const DIAMOND: &[Child] = &[
    child(Kind::Pentagon0, INV_PHI2 * INV_PHI * INV_SQRT5, 0, 5),
    child(Kind::Boat, INV_SQRT5, 0, 0),
    child(Kind::Star, INV_SQRT5, 5, 5),
];

/// A boat: a star in the middle, boats in its three points, pentagons between them.
const BOAT: &[Child] = &[
    child(Kind::Star, 0.0, 0, 5),
    child(Kind::Boat, INV_PHI, 0, 0),
    child(Kind::Boat, INV_PHI, 2, 2),
    child(Kind::Boat, INV_PHI, -2, -2),
    child(Kind::Pentagon0, INV_PHI2, 0, 5),
    child(Kind::Pentagon0, INV_PHI2, 2, 7),
    child(Kind::Pentagon0, INV_PHI2, -2, 3),
];

/// A star: the boat's children and two more points.
const STAR: &[Child] = &[
    child(Kind::Star, 0.0, 0, 5),
    child(Kind::Boat, INV_PHI, 0, 0),
    child(Kind::Boat, INV_PHI, 2, 2),
    child(Kind::Boat, INV_PHI, 4, 4),
    child(Kind::Boat, INV_PHI, -4, -4),
    child(Kind::Boat, INV_PHI, -2, -2),
    child(Kind::Pentagon0, INV_PHI2, 0, 5),
    child(Kind::Pentagon0, INV_PHI2, 2, 7),
    child(Kind::Pentagon0, INV_PHI2, 4, 9),
    child(Kind::Pentagon0, INV_PHI2, -4, 1),
    child(Kind::Pentagon0, INV_PHI2, -2, 3),
];

/// How far a tile's children reach beyond it, per edge of the tile: half the long diagonal
/// of a diamond one level down (the furthest any child reaches).
const CHILD_REACH: f64 = TURN[2].y / (PHI * PHI);

/// A tile: its kind, centre and axis (from the centre to the axis corner).
#[derive(Clone, Copy, Debug)]
struct Tile {
    kind: Kind,
    centre: DVec2,
    axis: DVec2,
}

impl Tile {
    fn child(&self, c: &Child) -> Tile {
        let scale = c.kind.radius() / (self.kind.radius() * PHI * PHI);
        Tile {
            kind: c.kind,
            centre: self.centre + turned(self.axis, c.at_turn) * c.at,
            axis: turned(self.axis, c.turn) * scale,
        }
    }

    /// The corners, counter-clockwise; returns how many.
    fn corners(&self, out: &mut [DVec2; 10]) -> usize {
        let (c, a) = (self.centre, self.axis);
        match self.kind {
            Kind::Pentagon5 | Kind::Pentagon2 | Kind::Pentagon0 => {
                for (k, o) in (0..5).zip(out.iter_mut()) {
                    *o = c + turned(a, 2 * k);
                }
                5
            }
            Kind::Diamond => {
                // Half the short diagonal over half the long one: tan 18 degrees.
                let side = a.perp() * (TURN[1].y / (1.0 + TURN[1].x));
                out[..4].copy_from_slice(&[c + a, c + side, c - a, c - side]);
                4
            }
            Kind::Star | Kind::Boat => {
                let steps: &[i8] = if self.kind == Kind::Star {
                    &[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]
                } else {
                    &[0, 1, 2, 3, 7, 8, 9]
                };
                for (&k, o) in steps.iter().zip(out.iter_mut()) {
                    // Tips at even steps, the inner pentagon's corners (1 / phi^2 as far
                    // out) at odd ones.
                    let r = if k % 2 == 0 { 1.0 } else { INV_PHI2 };
                    *o = c + turned(a, k) * r;
                }
                steps.len()
            }
        }
    }

    /// How far outside the tile's edges' lines `p` is at most (negative inside a convex
    /// tile).
    fn outside(&self, p: DVec2) -> f64 {
        let mut corners = [DVec2::ZERO; 10];
        let n = self.corners(&mut corners);
        (0..n)
            .map(|i| -inward_distance(corners[i], corners[(i + 1) % n], p))
            .fold(f64::NEG_INFINITY, f64::max)
    }

    fn holds(&self, p: DVec2) -> bool {
        let mut corners = [DVec2::ZERO; 10];
        let n = self.corners(&mut corners);
        polygon_holds(&corners[..n], p)
    }

    /// How deep `p` lies in the tile. A pentagon's or a diamond's depth is the distance to
    /// its boundary; a star's or a boat's is POV-Ray's: the largest, over the convex pieces
    /// of the tile bounded by its own edges' lines, of the distance to the piece's boundary
    /// (matched at every one of the 1600 points; the distance to the boundary misses by up
    /// to 0.028).
    fn depth(&self, p: DVec2) -> f64 {
        let mut corners = [DVec2::ZERO; 10];
        let n = self.corners(&mut corners);
        let corners = &corners[..n];
        let inward = |i: usize| inward_distance(corners[i], corners[(i + 1) % n], p);
        let pieces = match self.kind {
            Kind::Star => star_pieces(),
            Kind::Boat => boat_pieces(),
            _ => return (0..n).map(inward).fold(f64::INFINITY, f64::min),
        };
        pieces
            .iter()
            .map(|&piece| {
                (0..n)
                    .filter(|i| piece & (1 << i) != 0)
                    .map(inward)
                    .fold(f64::INFINITY, f64::min)
            })
            .filter(|&d| d >= 0.0)
            .fold(0.0, f64::max)
    }
}

/// The signed distance from the line through `a` and `b` (a counter-clockwise polygon's
/// edge), positive inside.
fn inward_distance(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    (b - a).perp_dot(p - a) / (b - a).length()
}

/// Even-odd rule, for the concave stars and boats as for the rest.
fn polygon_holds(corners: &[DVec2], p: DVec2) -> bool {
    let n = corners.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (corners[i], corners[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if x > p.x {
                inside = !inside;
            }
        }
    }
    inside
}

fn star_pieces() -> &'static [u16] {
    static PIECES: OnceLock<Vec<u16>> = OnceLock::new();
    PIECES.get_or_init(|| convex_pieces(Kind::Star))
}

fn boat_pieces() -> &'static [u16] {
    static PIECES: OnceLock<Vec<u16>> = OnceLock::new();
    PIECES.get_or_init(|| convex_pieces(Kind::Boat))
}

/// The largest convex pieces of a tile bounded by its edges' lines, as sets of edges (bit
/// i: the edge from corner i): every set whose half-planes meet in a region inside the
/// tile, keeping only those with no such subset.
fn convex_pieces(kind: Kind) -> Vec<u16> {
    let tile = Tile {
        kind,
        centre: DVec2::ZERO,
        axis: DVec2::X,
    };
    let mut corners = [DVec2::ZERO; 10];
    let n = tile.corners(&mut corners);
    let corners = &corners[..n];
    let valid: Vec<u16> = (1u16..1 << n)
        .filter(|&set| piece_inside(corners, set))
        .collect();
    valid
        .iter()
        .copied()
        .filter(|&set| !valid.iter().any(|&s| s != set && s & set == s))
        .collect()
}

/// Whether the edges in `set` bound a region of positive area inside the tile: the region
/// is cut from a large square, and points along its boundary, pulled in a hair, must all lie
/// in the tile.
fn piece_inside(corners: &[DVec2], set: u16) -> bool {
    let n = corners.len();
    let mut region: Vec<DVec2> = [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)]
        .iter()
        .map(|&(x, y)| DVec2::new(x, y))
        .collect();
    for i in (0..n).filter(|i| set & (1 << i) != 0) {
        region = clip(&region, corners[i], corners[(i + 1) % n]);
    }
    let m = region.len();
    let area: f64 = (0..m)
        .map(|i| region[i].perp_dot(region[(i + 1) % m]))
        .sum();
    if m < 3 || area < 1e-9 {
        return false;
    }
    let middle = region.iter().copied().sum::<DVec2>() / m as f64;
    (0..m).all(|i| {
        (0..32).all(|k| {
            let q = region[i].lerp(region[(i + 1) % m], f64::from(k) / 32.0);
            polygon_holds(corners, q.lerp(middle, 1e-6))
        })
    })
}

/// The part of a convex polygon on the inner side of the line from `a` to `b`.
fn clip(polygon: &[DVec2], a: DVec2, b: DVec2) -> Vec<DVec2> {
    let m = polygon.len();
    let mut out = Vec::with_capacity(m + 1);
    for i in 0..m {
        let (p, q) = (polygon[i], polygon[(i + 1) % m]);
        let (sp, sq) = (inward_distance(a, b, p), inward_distance(a, b, q));
        if sp >= 0.0 {
            out.push(p);
        }
        if (sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0) {
            out.push(p.lerp(q, sp / (sp - sq)));
        }
    }
    out
}

/// Tiles kept at one level: those that may hold the point or have children that may.
/// At most 6 over 2000 points out to 10^4 (tests below); the room is four times that.
struct Near {
    tiles: [Tile; 24],
    len: usize,
}

impl Near {
    fn new() -> Near {
        let none = Tile {
            kind: Kind::Pentagon5,
            centre: DVec2::ZERO,
            axis: DVec2::X,
        };
        Near {
            tiles: [none; 24],
            len: 0,
        }
    }

    fn push(&mut self, t: Tile) {
        if self.len < self.tiles.len() {
            self.tiles[self.len] = t;
            self.len += 1;
        }
    }

    fn as_slice(&self) -> &[Tile] {
        &self.tiles[..self.len]
    }
}

/// The number of substitutions from the first pentagon for a point at distance `r`: its
/// edge phi^(2 levels) is at least ten times r, so that the children the first pentagon's
/// missing neighbours would have given never reach the point.
fn levels_for(r: f64) -> i32 {
    let mut levels = 2;
    while PHI.powi(2 * levels) < 10.0 * (r + 2.0) {
        levels += 1;
    }
    levels
}

/// The tile (edge 1) holding `p`, substituting `levels` times from one pentagon, and the
/// most tiles kept at one level.
fn locate_from(p: DVec2, levels: i32) -> (Option<Tile>, usize) {
    let edge = PHI.powi(2 * levels);
    // The middle child turns half a turn each level; the last one's corner is at -x.
    let axis = if levels % 2 == 0 { -DVec2::X } else { DVec2::X };
    let mut near = Near::new();
    near.push(Tile {
        kind: Kind::Pentagon5,
        centre: DVec2::ZERO,
        axis: axis * Kind::Pentagon5.radius() * edge,
    });
    let mut edge = edge;
    let mut most = 1;
    for _ in 0..levels {
        edge /= PHI * PHI;
        // Keep a child if it, or a descendant, may hold p: its circumcircle comes within
        // the reach of all its descendants (CHILD_REACH summed over the levels below).
        let reach = CHILD_REACH * PHI * edge * 1.02;
        let mut next = Near::new();
        for parent in near.as_slice() {
            for c in parent.kind.children() {
                let t = parent.child(c);
                if p.distance(t.centre) <= t.axis.length() + reach {
                    next.push(t);
                }
            }
        }
        near = next;
        most = most.max(near.len);
    }
    let tiles = near.as_slice();
    let found = tiles.iter().copied().find(|t| t.holds(p)).or_else(|| {
        // On an edge, where rounding may put p outside both tiles: the one it is least
        // outside of.
        tiles
            .iter()
            .copied()
            .max_by(|a, b| a.outside(p).total_cmp(&b.outside(p)).reverse())
    });
    (found, most)
}

fn locate(p: DVec2) -> Option<Tile> {
    locate_from(p, levels_for(p.length())).0
}

/// The value of tiling 25 at `(x, z)`.
pub(super) fn pentagons_value(p: DVec2) -> f64 {
    let Some(tile) = locate(p) else {
        return 1.0;
    };
    let rise = (1.0 - tile.depth(p) / BEVEL).max(super::BODY);
    (tile.kind.povray_type() + rise) / 6.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(n: usize, r: f64) -> impl Iterator<Item = DVec2> {
        // A Weyl sequence over the disc's bounding square.
        (0..n).map(move |i| {
            let u = (i as f64 * 0.754_877_666_246_692_7).fract();
            let v = (i as f64 * 0.569_840_290_998_053_3).fract();
            DVec2::new(u * 2.0 - 1.0, v * 2.0 - 1.0) * r
        })
    }

    /// The substitution tiles the plane: every point lies in exactly one tile of the last
    /// level, and starting two or four levels higher finds the same tile.
    #[test]
    fn the_tiles_cover_the_plane_once_whatever_the_start() {
        for p in points(3000, 300.0) {
            let levels = levels_for(p.length());
            let t = locate_from(p, levels).0.expect("a tile holds every point");
            for more in [2, 4] {
                let u = locate_from(p, levels + more)
                    .0
                    .expect("a tile holds every point");
                assert_eq!(t.kind, u.kind, "{p}");
                assert!(t.centre.distance(u.centre) < 1e-6, "{p}");
            }
        }
    }

    /// Edge 1 everywhere, and the near tiles stay well within their room.
    #[test]
    fn tiles_have_unit_edges_and_few_are_kept() {
        let mut most = 0;
        for p in points(2000, 1e4) {
            most = most.max(locate_from(p, levels_for(p.length())).1);
        }
        assert!(most <= 12, "{most} tiles kept at one level");
        for p in points(500, 50.0) {
            let t = locate(p).unwrap();
            let mut corners = [DVec2::ZERO; 10];
            let n = t.corners(&mut corners);
            let shortest = (0..n)
                .map(|i| corners[i].distance(corners[(i + 1) % n]))
                .fold(f64::INFINITY, f64::min);
            // A boat's base is longer; every other edge has length 1.
            assert!((shortest - 1.0).abs() < 1e-9, "{shortest} {:?}", t.kind);
        }
    }

    /// The origin's pentagon: type 0, its corner at (-0.8507, 0) and its flat side at
    /// x = 0.688 (measured).
    #[test]
    fn a_type_0_pentagon_is_centred_on_the_origin() {
        assert!(pentagons_value(DVec2::new(0.0, 0.0)) < 1.0 / 6.0);
        assert!(pentagons_value(DVec2::new(-0.84, 0.0)) < 1.0 / 6.0 + 1e-9);
        assert!(pentagons_value(DVec2::new(-0.86, 0.0)) > 1.0 / 6.0);
        assert!(pentagons_value(DVec2::new(0.68, 0.0)) < 1.0 / 6.0 + 1e-9);
        assert!(pentagons_value(DVec2::new(0.70, 0.0)) > 1.0 / 6.0);
    }

    /// A star is bounded by its ten edges' lines in 40 largest convex pieces, a boat in 7.
    #[test]
    fn concave_tiles_split_into_convex_pieces() {
        assert!(!star_pieces().is_empty());
        assert!(!boat_pieces().is_empty());
        for &piece in star_pieces().iter().chain(boat_pieces()) {
            assert!(piece.count_ones() >= 3);
        }
    }
}
