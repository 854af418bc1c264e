//! Which interiors a ray is inside.

/// Nested interiors deeper than this are treated as the innermost one.
const DEPTH: usize = 8;

/// The interiors a ray is inside, innermost last, with their indices of refraction. POV-Ray
/// keeps interiors, not surfaces: a ray inside an interior that meets any part of the object
/// owning it leaves that interior, whichever way the part faces (measured: a glass box and a
/// cylinder of one object meeting face to face, or overlapping, turn a ray back by total
/// internal reflection at the box's top as if air were beyond, exactly as with a gap).
#[derive(Clone, Copy, Debug)]
pub(super) struct InteriorStack {
    ids: [u32; DEPTH],
    iors: [f64; DEPTH],
    /// Bit k: slot k is a solid (not `hollow`) object, where POV-Ray computes no fog.
    solid: u8,
    len: usize,
}

impl InteriorStack {
    pub(super) const OUTSIDE: InteriorStack = InteriorStack {
        ids: [u32::MAX; DEPTH],
        iors: [1.0; DEPTH],
        solid: 0,
        len: 0,
    };

    /// The index of refraction the ray travels in.
    pub(super) fn current(&self) -> f64 {
        if self.len == 0 {
            1.0
        } else {
            self.iors[self.len - 1]
        }
    }

    /// Whether the ray is inside no interior at all.
    pub(super) fn is_empty(&self) -> bool {
        self.len == 0
    }

    pub(super) fn contains(&self, id: u32) -> bool {
        self.ids[..self.len].contains(&id)
    }

    /// The interiors, outermost first.
    pub(super) fn ids(&self) -> &[u32] {
        &self.ids[..self.len]
    }

    pub(super) fn entered(&self, id: u32, ior: f64, hollow: bool) -> InteriorStack {
        let mut m = *self;
        let slot = m.len.min(DEPTH - 1);
        m.ids[slot] = id;
        m.iors[slot] = ior;
        m.solid = (m.solid & !(1 << slot)) | (u8::from(!hollow) << slot);
        m.len = slot + 1;
        m
    }

    /// Whether the ray travels through the atmosphere, where fog applies: inside no solid
    /// object (POV-Ray's atmosphere stops at non-hollow objects).
    pub(super) fn in_atmosphere(&self) -> bool {
        self.solid & ((1u16 << self.len) - 1) as u8 == 0
    }

    /// Without the interior `id`. Rays leave only interiors they are in; for an `id` not in
    /// the stack the innermost is dropped, a safeguard no caller relies on.
    pub(super) fn left(&self, id: u32) -> InteriorStack {
        let mut m = *self;
        match m.ids[..m.len].iter().rposition(|&i| i == id) {
            Some(k) => {
                // Every slot above k moves down one, those past the top too (the stack is
                // short: a fixed loop, where `copy_within` called memmove).
                for j in k..DEPTH - 1 {
                    m.ids[j] = m.ids[j + 1];
                    m.iors[j] = m.iors[j + 1];
                }
                let below = m.solid & ((1u8 << k) - 1);
                m.solid = below | ((m.solid >> 1) & !((1u8 << k) - 1));
                m.len -= 1;
            }
            None => m.len = m.len.saturating_sub(1),
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entering_and_leaving_nest() {
        let glass = InteriorStack::OUTSIDE.entered(1, 1.5, false);
        let water = glass.entered(2, 1.33, false);
        assert_eq!(water.current(), 1.33);
        // Leaving the outer interior first keeps the inner one.
        let w = water.left(1);
        assert!(!w.contains(1) && w.contains(2));
        assert_eq!(w.current(), 1.33);
        assert_eq!(water.left(2).current(), 1.5);
        // Leaving an interior the ray did not know it was in drops the innermost.
        assert_eq!(glass.left(7).current(), 1.0);
        assert_eq!(InteriorStack::OUTSIDE.left(3).current(), 1.0);
    }

    #[test]
    fn fog_stops_inside_solid_objects_only() {
        let outside = InteriorStack::OUTSIDE;
        assert!(outside.in_atmosphere());
        let hollow = outside.entered(1, 1.0, true);
        assert!(hollow.in_atmosphere());
        let glass = hollow.entered(2, 1.5, false);
        assert!(!glass.in_atmosphere());
        // Leaving the solid glass (the inner slot) restores the hollow one's atmosphere;
        // leaving the hollow one first keeps the glass solid, in its new slot.
        assert!(glass.left(2).in_atmosphere());
        assert!(!glass.left(1).in_atmosphere());
        assert!(glass.left(1).left(2).in_atmosphere());
    }

    #[test]
    fn too_deep_nesting_replaces_the_innermost() {
        let mut s = InteriorStack::OUTSIDE;
        for id in 0..20 {
            s = s.entered(id, 1.0 + id as f64, false);
        }
        assert_eq!(s.current(), 20.0);
        assert!(s.contains(19) && !s.contains(8));
    }
}
