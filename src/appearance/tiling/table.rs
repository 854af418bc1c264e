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
        },
    ),
];
