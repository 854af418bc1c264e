//! The pavements, one table each (a tiling of one type), measured from POV-Ray 3.7's
//! renders seen from above, keyed by (number_of_sides, number_of_tiles, pattern).

use super::{Tile, Tiling};

pub(super) const PAVEMENTS: &[((u8, u8, u8), Tiling)] = &[(
    (4, 1, 1),
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
)];
