//! The tilings, one table each, measured from POV-Ray 3.7's renders of each tiling seen
//! from above (pattern values read along lines to find edges, vertices, tile types and
//! bevel widths; every table reproduces POV-Ray's values to 16-bit rounding at every pixel
//! of two 200 x 200 renders, one near the origin and one over [-5.3, 5.3]^2). Edges are 1
//! long unless a comment says otherwise.

use super::{Tile, Tiling};

const SQRT_3: f64 = 1.732_050_807_568_877_2;
const SQRT_2: f64 = std::f64::consts::SQRT_2;

pub(super) const TILINGS: &[(u8, Tiling)] = &[
    // tiling 1: unit squares, one type
    (
        1,
        Tiling {
            a: [1.0, 0.0],
            b: [0.0, 1.0],
            tiles: &[Tile {
                kind: 0,
                vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
                edge_bevels: &[],
            }],
            types: 1,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 2: regular hexagons, side 1, vertices at (c+-1, z); origin is a vertex
    (
        2,
        Tiling {
            a: [3.0 / 2.0, SQRT_3 / 2.0],
            b: [0.0, SQRT_3],
            tiles: &[Tile {
                kind: 0,
                vertices: &[
                    [1.0, 0.0],
                    [3.0 / 2.0, SQRT_3 / 2.0],
                    [1.0, SQRT_3],
                    [0.0, SQRT_3],
                    [-1.0 / 2.0, SQRT_3 / 2.0],
                    [0.0, 0.0],
                ],
                edge_bevels: &[],
            }],
            types: 1,
            bevel: SQRT_3 / 2.0,
            grid: &[],
        },
    ),
    // tiling 3: equilateral triangles side 1; type 0 = up (base on z=0), type 1 = down (apex
    // at origin)
    (
        3,
        Tiling {
            a: [1.0, 0.0],
            b: [1.0 / 2.0, SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 0,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0 / 2.0, SQRT_3 / 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 0.0],
                        [1.0 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 2,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 4
    (
        4,
        Tiling {
            a: [1.0, 0.0],
            b: [1.0 / 2.0, SQRT_3 / 2.0],
            tiles: &[Tile {
                kind: 0,
                vertices: &[
                    [0.0, 0.0],
                    [1.0, 0.0],
                    [3.0 / 2.0, SQRT_3 / 2.0],
                    [1.0 / 2.0, SQRT_3 / 2.0],
                ],
                edge_bevels: &[],
            }],
            types: 1,
            bevel: SQRT_3 / 4.0,
            grid: &[],
        },
    ),
    // tiling 5: three 60-degree rhombi (side 1) meeting at the origin, forming a hexagon
    (
        5,
        Tiling {
            a: [3.0 / 2.0, SQRT_3 / 2.0],
            b: [0.0, SQRT_3],
            tiles: &[
                Tile {
                    kind: 0,
                    vertices: &[
                        [0.0, 0.0],
                        [1.0, 0.0],
                        [3.0 / 2.0, SQRT_3 / 2.0],
                        [1.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 0.0],
                        [1.0 / 2.0, SQRT_3 / 2.0],
                        [0.0, SQRT_3],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[
                        [-1.0, 0.0],
                        [0.0, 0.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-3.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_3 / 4.0,
            grid: &[],
        },
    ),
    // tiling 6: 1x2 rectangles in a diagonal staircase: vertical (type 1) and horizontal (type
    // 0), both stepping by (1,1); repeat 4x4 in x,z
    (
        6,
        Tiling {
            a: [1.0, 1.0],
            b: [4.0, 0.0],
            tiles: &[
                Tile {
                    kind: 1,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[0.0, -1.0], [2.0, -1.0], [2.0, 0.0], [0.0, 0.0]],
                    edge_bevels: &[],
                },
            ],
            types: 2,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 7: octagon (type 1) centred at the origin, side 1; diamond square (type 0) at the
    // cell corner
    (
        7,
        Tiling {
            a: [1.0 + SQRT_2, 0.0],
            b: [0.0, 1.0 + SQRT_2],
            tiles: &[
                Tile {
                    kind: 1,
                    vertices: &[
                        [1.0 / 2.0 + SQRT_2 / 2.0, 1.0 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0 + SQRT_2 / 2.0],
                        [-1.0 / 2.0, 1.0 / 2.0 + SQRT_2 / 2.0],
                        [-1.0 / 2.0 - SQRT_2 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0 - SQRT_2 / 2.0, -1.0 / 2.0],
                        [-1.0 / 2.0, -1.0 / 2.0 - SQRT_2 / 2.0],
                        [1.0 / 2.0, -1.0 / 2.0 - SQRT_2 / 2.0],
                        [1.0 / 2.0 + SQRT_2 / 2.0, -1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [1.0 / 2.0 + SQRT_2 / 2.0, 1.0 / 2.0],
                        [1.0 / 2.0 + SQRT_2, 1.0 / 2.0 + SQRT_2 / 2.0],
                        [1.0 / 2.0 + SQRT_2 / 2.0, 1.0 / 2.0 + SQRT_2],
                        [1.0 / 2.0, 1.0 / 2.0 + SQRT_2 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 2,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 8: elongated triangular: rows of unit squares (type 2) alternating with rows of
    // triangles, up-pointing triangles type 0, down-pointing type 1; each square row shifted
    // by 1/2
    (
        8,
        Tiling {
            a: [1.0, 0.0],
            b: [1.0 / 2.0, 1.0 + SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[0.0, 1.0], [1.0, 1.0], [1.0 / 2.0, 1.0 + SQRT_3 / 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [1.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                        [1.0, 1.0],
                        [3.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 9: trihexagonal (kagome), side 1: flat-top hexagon (type 2), up triangle (type
    // 0), down triangle (type 1); origin is a hexagon vertex
    (
        9,
        Tiling {
            a: [2.0, 0.0],
            b: [1.0, SQRT_3],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[
                        [1.0, 0.0],
                        [3.0 / 2.0, SQRT_3 / 2.0],
                        [1.0, SQRT_3],
                        [0.0, SQRT_3],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [0.0, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[-1.0, 0.0], [0.0, 0.0], [-1.0 / 2.0, SQRT_3 / 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[0.0, 0.0], [1.0 / 2.0, -SQRT_3 / 2.0], [1.0, 0.0]],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 10: unit squares in rows offset by 1/2 (running bond); one type
    (
        10,
        Tiling {
            a: [1.0, 0.0],
            b: [1.0 / 2.0, 1.0],
            tiles: &[Tile {
                kind: 0,
                vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
                edge_bevels: &[],
            }],
            types: 1,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 11: Tiling 11: unit squares (type 0), horizontal 2x1 rectangles (type 1),
    // vertical 1x2 rectangles (type 2); period 3 in x and z; W = 1/2 (inradius of every tile)
    (
        11,
        Tiling {
            a: [3.0, 0.0],
            b: [0.0, 3.0],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[0.0, 2.0], [2.0, 2.0], [2.0, 3.0], [0.0, 3.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[1.0, 0.0], [3.0, 0.0], [3.0, 1.0], [1.0, 1.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[[2.0, 1.0], [3.0, 1.0], [3.0, 3.0], [2.0, 3.0]],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 12: Tiling 12: unit squares (type 0), horizontal 2x1 rectangles (type 1, in 4x2
    // blocks of four), vertical 1x2 rectangles (type 2, in 2x4 blocks of four); squares repeat
    // every 3 in x and z but the full pattern has lattice (6,0),(3,3) (NOT the 3x3 the wiki
    // scale suggests); W = 1/2
    (
        12,
        Tiling {
            a: [6.0, 0.0],
            b: [3.0, 3.0],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[1.0, 0.0], [3.0, 0.0], [3.0, 1.0], [1.0, 1.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[[2.0, 1.0], [3.0, 1.0], [3.0, 3.0], [2.0, 3.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[3.0, 0.0], [5.0, 0.0], [5.0, 1.0], [3.0, 1.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[[3.0, 1.0], [4.0, 1.0], [4.0, 3.0], [3.0, 3.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[4.0, 1.0], [5.0, 1.0], [5.0, 2.0], [4.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[4.0, 2.0], [6.0, 2.0], [6.0, 3.0], [4.0, 3.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[[5.0, 0.0], [6.0, 0.0], [6.0, 2.0], [5.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[6.0, 2.0], [8.0, 2.0], [8.0, 3.0], [6.0, 3.0]],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 13: Tiling 13. Measured period 2*sqrt(2) in x and z (NOT 1+sqrt(3) as the wiki
    // scale suggests). Squares (type 0, side sqrt(2)) centred at (P/2,P/2)+lattice; the gap
    // between two squares holds a hexagon with 90-degree apexes at the lattice points, split
    // along its long axis into two trapezoids (long base P=2*sqrt(2), height a=1/sqrt(2), legs
    // 1 at 45 degrees): horizontal ones type 1, vertical ones type 2.  W = a/2 = trapezoid
    // inradius (= smallest). tilemodel.py helper only: grow each polygon by 1e-9 about its
    // vertex centroid so that pixel centres lying exactly on an edge are never a gap (first
    // match in tilemodel's loop order wins)
    (
        13,
        Tiling {
            a: [2.0 * SQRT_2, 0.0],
            b: [0.0, 2.0 * SQRT_2],
            tiles: &[
                Tile {
                    kind: 0,
                    vertices: &[
                        [SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [3.0 * SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [3.0 * SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                        [SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 0.0],
                        [2.0 * SQRT_2, 0.0],
                        [3.0 * SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [SQRT_2 / 2.0, SQRT_2 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_2 / 2.0, -SQRT_2 / 2.0],
                        [3.0 * SQRT_2 / 2.0, -SQRT_2 / 2.0],
                        [2.0 * SQRT_2, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                        [0.0, 2.0 * SQRT_2],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[
                        [0.0, 0.0],
                        [0.0, 2.0 * SQRT_2],
                        [-SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                        [-SQRT_2 / 2.0, SQRT_2 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_2 / 4.0,
            grid: &[],
        },
    ),
    // tiling 14: Tiling 14 (same geometry as 13, 5 types). Measured period 2*sqrt(2) in x and
    // z (NOT 1+sqrt(3) as the wiki scale suggests). Squares (side sqrt(2)) centred at
    // (P/2,P/2)+lattice; the gap between two squares holds a hexagon with 90-degree apexes at
    // the lattice points, split along its long axis into two trapezoids (long base
    // P=2*sqrt(2), height a=1/sqrt(2), legs 1 at 45 degrees): types: square 4; trapezoids
    // above a horizontal split line 2, below it 3; right of a vertical split line 1, left of
    // it 0.  W = a/2 = trapezoid inradius (= smallest). tilemodel.py helper only: grow each
    // polygon by 1e-9 about its vertex centroid so that pixel centres lying exactly on an edge
    // are never a gap (first match in tilemodel's loop order wins)
    (
        14,
        Tiling {
            a: [2.0 * SQRT_2, 0.0],
            b: [0.0, 2.0 * SQRT_2],
            tiles: &[
                Tile {
                    kind: 4,
                    vertices: &[
                        [SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [3.0 * SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [3.0 * SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                        [SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[
                        [0.0, 0.0],
                        [2.0 * SQRT_2, 0.0],
                        [3.0 * SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [SQRT_2 / 2.0, SQRT_2 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 3,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_2 / 2.0, -SQRT_2 / 2.0],
                        [3.0 * SQRT_2 / 2.0, -SQRT_2 / 2.0],
                        [2.0 * SQRT_2, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_2 / 2.0, SQRT_2 / 2.0],
                        [SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                        [0.0, 2.0 * SQRT_2],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [0.0, 0.0],
                        [0.0, 2.0 * SQRT_2],
                        [-SQRT_2 / 2.0, 3.0 * SQRT_2 / 2.0],
                        [-SQRT_2 / 2.0, SQRT_2 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 5,
            bevel: SQRT_2 / 4.0,
            grid: &[],
        },
    ),
    // tiling 15: Tiling 15: Pythagorean tiling, unit squares (type 0) and 2x2 squares (type
    // 1); lattice (2,1),(-1,2) (period 5 along x and z); W = 1/2 = the small square's inradius
    // (big squares have a flat centre)
    (
        15,
        Tiling {
            a: [2.0, 1.0],
            b: [-1.0, 2.0],
            tiles: &[
                Tile {
                    kind: 0,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[0.0, 1.0], [2.0, 1.0], [2.0, 3.0], [0.0, 3.0]],
                    edge_bevels: &[],
                },
            ],
            types: 2,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 16: Tiling 16: rhombitrihexagonal tiling 3.4.6.4, side 1, flat-topped hexagons
    // (type 2) centred at (-1,0)+lattice (so the origin is a hexagon vertex), squares type 0,
    // triangles type 1. Primitive lattice (one hexagon per cell); s = 1+sqrt(3) = distance
    // between hexagon centres. Rectangular repeat sqrt(3)+3 in x (as the wiki scale says) but
    // 1+sqrt(3) in z (the wiki's 2*(1+sqrt(3)) is twice the true period).  W = sqrt(3)/6 =
    // triangle inradius.
    (
        16,
        Tiling {
            a: [0.0, 1.0 + SQRT_3],
            b: [3.0 / 2.0 + SQRT_3 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[
                        [0.0, 0.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-3.0 / 2.0, SQRT_3 / 2.0],
                        [-2.0, 0.0],
                        [-3.0 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 / 2.0, -SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_3 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0 + SQRT_3 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                        [-3.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                        [-3.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 / 2.0 + SQRT_3 / 2.0, -1.0 / 2.0 - SQRT_3 / 2.0],
                        [SQRT_3 / 2.0, -1.0 / 2.0],
                        [0.0, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_3 / 2.0, -1.0 / 2.0],
                        [SQRT_3 / 2.0, 1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0 + SQRT_3 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 17: Tiling 17: same geometry as tiling 16 (rhombitrihexagonal 3.4.6.4, side 1,
    // flat-topped hexagons centred at (-1,0)+lattice), 6 types: hexagon 5; squares by
    // orientation: axis-aligned 0, square on the hexagon's 30-degree edge 1, on its -30-degree
    // edge 2; triangle with its vertical edge on the left (pointing +x) 3, with its vertical
    // edge on the right (pointing -x) 4. Primitive lattice; W = sqrt(3)/6 = triangle inradius.
    (
        17,
        Tiling {
            a: [0.0, 1.0 + SQRT_3],
            b: [3.0 / 2.0 + SQRT_3 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 5,
                    vertices: &[
                        [0.0, 0.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-3.0 / 2.0, SQRT_3 / 2.0],
                        [-2.0, 0.0],
                        [-3.0 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 / 2.0, -SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_3 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0 + SQRT_3 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                        [-3.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                        [-3.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[
                        [-1.0 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 / 2.0 + SQRT_3 / 2.0, -1.0 / 2.0 - SQRT_3 / 2.0],
                        [SQRT_3 / 2.0, -1.0 / 2.0],
                        [0.0, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 4,
                    vertices: &[
                        [0.0, 0.0],
                        [SQRT_3 / 2.0, -1.0 / 2.0],
                        [SQRT_3 / 2.0, 1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 3,
                    vertices: &[
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0 + SQRT_3 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 / 2.0, 1.0 + SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 6,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 18: Tiling 18: basket weave of 2x1 rectangles in 2x2 pairs; horizontal rectangles
    // type 0, vertical ones type 1; period 4 in x and z; W = 1/2
    (
        18,
        Tiling {
            a: [4.0, 0.0],
            b: [0.0, 4.0],
            tiles: &[
                Tile {
                    kind: 1,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[1.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[0.0, 2.0], [2.0, 2.0], [2.0, 3.0], [0.0, 3.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[0.0, 3.0], [2.0, 3.0], [2.0, 4.0], [0.0, 4.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[2.0, 0.0], [4.0, 0.0], [4.0, 1.0], [2.0, 1.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[2.0, 1.0], [4.0, 1.0], [4.0, 2.0], [2.0, 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[2.0, 2.0], [3.0, 2.0], [3.0, 4.0], [2.0, 4.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[3.0, 2.0], [4.0, 2.0], [4.0, 4.0], [3.0, 4.0]],
                    edge_bevels: &[],
                },
            ],
            types: 2,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 19: snub hexagonal tiling 3.3.3.3.6, side 1; hexagons (type 2) centred at (-1,0)
    // + lattice, up-pointing triangles type 0, down-pointing type 1
    (
        19,
        Tiling {
            a: [2.0, SQRT_3],
            b: [-1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[
                        [0.0, 0.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-3.0 / 2.0, SQRT_3 / 2.0],
                        [-2.0, 0.0],
                        [-3.0 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 / 2.0, -SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 2.0 * SQRT_3],
                        [1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                        [1.0, 2.0 * SQRT_3],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0, SQRT_3],
                        [0.0, SQRT_3],
                        [-1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[-1.0, SQRT_3], [-1.0 / 2.0, SQRT_3 / 2.0], [0.0, SQRT_3]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                        [1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                        [0.0, 2.0 * SQRT_3],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [-1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                        [0.0, SQRT_3],
                        [1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-3.0 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [-1.0, SQRT_3],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [1.0 / 2.0, SQRT_3 / 2.0],
                        [0.0, SQRT_3],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [-1.0, 2.0 * SQRT_3],
                        [-1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                        [0.0, 2.0 * SQRT_3],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 20: snub hexagonal tiling 3.3.3.3.6, side 1; mirror image of tiling 19; hexagons
    // (type 2) centred at (1/2,-sqrt(3)/2) + lattice, up-pointing triangles type 0, down-
    // pointing type 1
    (
        20,
        Tiling {
            a: [5.0 / 2.0, SQRT_3 / 2.0],
            b: [-2.0, SQRT_3],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[
                        [2.0, SQRT_3],
                        [3.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                        [1.0 / 2.0, 3.0 * SQRT_3 / 2.0],
                        [0.0, SQRT_3],
                        [1.0 / 2.0, SQRT_3 / 2.0],
                        [3.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [1.0 / 2.0, SQRT_3 / 2.0],
                        [0.0, SQRT_3],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [-1.0 / 2.0, SQRT_3 / 2.0],
                        [0.0, 0.0],
                        [1.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [1.0 / 2.0, SQRT_3 / 2.0],
                        [1.0, 0.0],
                        [3.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[-1.0, 0.0], [0.0, 0.0], [-1.0 / 2.0, SQRT_3 / 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [3.0 / 2.0, SQRT_3 / 2.0],
                        [2.0, 0.0],
                        [5.0 / 2.0, SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[0.0, 0.0], [1.0, 0.0], [1.0 / 2.0, SQRT_3 / 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[1.0, 0.0], [2.0, 0.0], [3.0 / 2.0, SQRT_3 / 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[[1.0, 0.0], [3.0 / 2.0, -SQRT_3 / 2.0], [2.0, 0.0]],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 21: snub square tiling 3.3.4.3.4, side 1, square period 1+sqrt(3) (lattice is
    // centred: A, B below). Triangles typed by apex direction: 0 apex +x, 1 apex -z, 2 apex
    // -x, 3 apex +z. Squares: 4 = centred at (p/4,p/4)+lattice, 5 = centred at
    // (p/4,-p/4)+lattice, p=1+sqrt(3). Mirror symmetric in x=0 and z=0; origin = midpoint of
    // the edge shared by triangles 0 and 2.
    (
        21,
        Tiling {
            a: [1.0 / 2.0 + SQRT_3 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
            b: [1.0 / 2.0 + SQRT_3 / 2.0, -1.0 / 2.0 - SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 4,
                    vertices: &[
                        [0.0, 1.0 / 2.0],
                        [SQRT_3 / 2.0, 0.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 5,
                    vertices: &[
                        [SQRT_3 / 2.0, 0.0],
                        [0.0, -1.0 / 2.0],
                        [1.0 / 2.0, -1.0 / 2.0 - SQRT_3 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[[0.0, -1.0 / 2.0], [SQRT_3 / 2.0, 0.0], [0.0, 1.0 / 2.0]],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[
                        [1.0 + SQRT_3, 1.0 / 2.0],
                        [1.0 + SQRT_3 / 2.0, 0.0],
                        [1.0 + SQRT_3, -1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [SQRT_3 / 2.0, 0.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 + SQRT_3 / 2.0, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 3,
                    vertices: &[
                        [1.0 + SQRT_3 / 2.0, 0.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [SQRT_3 / 2.0, 0.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 6,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 22: truncated hexagonal tiling 3.12.12, side 1. Dodecagons (type 2) centred at
    // (0,-(1+sqrt(3))/2) + lattice, with vertical edges at x = centre +- (2+sqrt(3))/2. Up-
    // pointing triangles type 0, down-pointing type 1. The origin lies inside a dodecagon, 1/2
    // below its top edge (= base of an up triangle). QUIRK (measured): three edges of the
    // dodecagon have bevel width 1/3 instead of sqrt(3)/6: its two vertical edges (shared with
    // dodecagons) and its bottom edge (shared with a down triangle). EDGE_W[(tile index, edge
    // k)] = width, edge k = vertex k -> k+1; used by /tmp/m/w19/tilemodel_ew.py value = (t +
    // max(0, 1 - min_k d_k/W_k))/N.  The triangles' sides of those edges use W = sqrt(3)/6.
    (
        22,
        Tiling {
            a: [2.0 + SQRT_3, 0.0],
            b: [1.0 + SQRT_3 / 2.0, 3.0 / 2.0 + SQRT_3],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[
                        [1.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, 0.0],
                        [-1.0 - SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 - SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, -1.0 - SQRT_3],
                        [-1.0 / 2.0, -3.0 / 2.0 - SQRT_3],
                        [1.0 / 2.0, -3.0 / 2.0 - SQRT_3],
                        [1.0 / 2.0 + SQRT_3 / 2.0, -1.0 - SQRT_3],
                        [1.0 + SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[
                        SQRT_3 / 6.0,
                        SQRT_3 / 6.0,
                        SQRT_3 / 6.0,
                        SQRT_3 / 6.0,
                        SQRT_3 / 6.0,
                        1.0 / 3.0,
                        SQRT_3 / 6.0,
                        SQRT_3 / 6.0,
                        1.0 / 3.0,
                        SQRT_3 / 6.0,
                        SQRT_3 / 6.0,
                        1.0 / 3.0,
                    ],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [-1.0 / 2.0, 1.0 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                        [0.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [0.0, 3.0 / 2.0 + SQRT_3 / 2.0],
                        [1.0 / 2.0, 3.0 / 2.0 + SQRT_3],
                        [-1.0 / 2.0, 3.0 / 2.0 + SQRT_3],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: SQRT_3 / 6.0,
            grid: &[],
        },
    ),
    // tiling 23: truncated trihexagonal tiling 4.6.12, side 1. Dodecagon (type 2) centred at
    // (0,-(1+sqrt(3))/2) + lattice, vertical edges at centre +- (2+sqrt(3))/2; hexagons type
    // 0; squares type 1.
    (
        23,
        Tiling {
            a: [3.0 + SQRT_3, 0.0],
            b: [3.0 / 2.0 + SQRT_3 / 2.0, 3.0 / 2.0 + 3.0 * SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 2,
                    vertices: &[
                        [1.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, 0.0],
                        [-1.0 - SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 - SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, -1.0 - SQRT_3],
                        [-1.0 / 2.0, -3.0 / 2.0 - SQRT_3],
                        [1.0 / 2.0, -3.0 / 2.0 - SQRT_3],
                        [1.0 / 2.0 + SQRT_3 / 2.0, -1.0 - SQRT_3],
                        [1.0 + SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0 + SQRT_3],
                        [-1.0 / 2.0, 1.0 / 2.0 + SQRT_3],
                        [-1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 / 2.0, 1.0 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [5.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                        [2.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [1.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                        [1.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [2.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [2.0 + SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                        [2.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 + SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [1.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [-1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 - SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, 0.0],
                        [-1.0 / 2.0, 1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 3,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
    // tiling 24: truncated trihexagonal tiling 4.6.12, same geometry as tiling 23. Dodecagon
    // type 4, hexagons type 0, squares by orientation: axis-aligned type 1, edge normal at 60
    // deg type 2, edge normal at 120 deg type 3.
    (
        24,
        Tiling {
            a: [3.0 + SQRT_3, 0.0],
            b: [3.0 / 2.0 + SQRT_3 / 2.0, 3.0 / 2.0 + 3.0 * SQRT_3 / 2.0],
            tiles: &[
                Tile {
                    kind: 4,
                    vertices: &[
                        [1.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0, 1.0 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, 0.0],
                        [-1.0 - SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [-1.0 - SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, -1.0 - SQRT_3],
                        [-1.0 / 2.0, -3.0 / 2.0 - SQRT_3],
                        [1.0 / 2.0, -3.0 / 2.0 - SQRT_3],
                        [1.0 / 2.0 + SQRT_3 / 2.0, -1.0 - SQRT_3],
                        [1.0 + SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0 + SQRT_3],
                        [-1.0 / 2.0, 1.0 / 2.0 + SQRT_3],
                        [-1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 / 2.0, 1.0 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 0,
                    vertices: &[
                        [5.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                        [2.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [1.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                        [1.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [2.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 1,
                    vertices: &[
                        [2.0 + SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                        [2.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 + SQRT_3 / 2.0, -SQRT_3 / 2.0],
                        [1.0 + SQRT_3 / 2.0, -1.0 - SQRT_3 / 2.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 2,
                    vertices: &[
                        [1.0 + SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [1.0 / 2.0, 1.0 / 2.0],
                        [1.0 / 2.0 + SQRT_3 / 2.0, 0.0],
                    ],
                    edge_bevels: &[],
                },
                Tile {
                    kind: 3,
                    vertices: &[
                        [-1.0, 1.0 / 2.0 + SQRT_3 / 2.0],
                        [-1.0 - SQRT_3 / 2.0, SQRT_3 / 2.0],
                        [-1.0 / 2.0 - SQRT_3 / 2.0, 0.0],
                        [-1.0 / 2.0, 1.0 / 2.0],
                    ],
                    edge_bevels: &[],
                },
            ],
            types: 5,
            bevel: 1.0 / 2.0,
            grid: &[],
        },
    ),
];
