use glam::DVec3;

use crate::scene::{Colour, Pattern, Pigment, PigmentKind};

/// The pigment's colour at a world-space point.
pub fn evaluate_pigment(pigment: &Pigment, world: DVec3) -> Colour {
    match &pigment.kind {
        PigmentKind::Solid(c) => *c,
        PigmentKind::List { pattern, entries } => {
            if entries.is_empty() {
                return Colour::BLACK;
            }
            let p = pigment.transform.inverse_point(world);
            let index = list_pattern_index(*pattern, p) % entries.len();
            evaluate_pigment(&entries[index], world)
        }
    }
}

/// Which entry of a list pattern a pattern-space point selects.
pub fn list_pattern_index(pattern: Pattern, p: DVec3) -> usize {
    match pattern {
        Pattern::Checker => {
            // POV-Ray nudges by 1e-10 so that faces at integer coordinates fall consistently.
            let s = (p.x + 1e-10).floor() + (p.y + 1e-10).floor() + (p.z + 1e-10).floor();
            (s.rem_euclid(2.0)) as usize
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Transform;

    #[test]
    fn checker_alternates_on_unit_cubes() {
        let a = Colour::rgb(1.0, 0.0, 0.0);
        let b = Colour::rgb(0.0, 1.0, 0.0);
        let mut pig = Pigment {
            kind: PigmentKind::List {
                pattern: Pattern::Checker,
                entries: vec![Pigment::solid(a), Pigment::solid(b)],
            },
            transform: Transform::IDENTITY,
        };
        assert_eq!(evaluate_pigment(&pig, DVec3::new(0.5, 0.5, 0.5)), a);
        assert_eq!(evaluate_pigment(&pig, DVec3::new(1.5, 0.5, 0.5)), b);
        assert_eq!(evaluate_pigment(&pig, DVec3::new(-0.5, 0.5, 0.5)), b);
        assert_eq!(evaluate_pigment(&pig, DVec3::new(-0.5, -0.5, 0.5)), a);
        // Integer faces belong to the cube above them.
        assert_eq!(evaluate_pigment(&pig, DVec3::new(1.0, 0.0, 0.0)), b);
        pig.transform_by(&Transform::scale(DVec3::splat(2.0)).unwrap());
        assert_eq!(evaluate_pigment(&pig, DVec3::new(1.5, 0.5, 0.5)), a);
    }
}
