//! Blend maps: where a pattern value falls among a map's entries, and how two colours mix.
//! Patterns, normals and textures all read maps this way, so the lookup lives on its own,
//! below all three (the only cycle left in appearance is the real one: a pigment pattern
//! holds a pigment).

use crate::scene::Colour;

/// Where a value falls in a blend map: one entry, or between entry i and i + 1.
pub enum Blend {
    None,
    One(usize),
    Two(usize, f64),
}

/// POV-Ray's blend-map lookup: values below the first entry take the first, above the last
/// the last; between two entries the colours mix linearly (all five channels); equal
/// values make a sharp step. A value exactly at an entry belongs to the interval below it
/// (measured: `[0 green][0.5 green][0.5 red][1 red]` is green at exactly 0.5), which
/// decides the faces of boxes and planes that lie on a stripe's edge; but a value at or
/// above the last entry takes the last, even when entries before it share its value
/// (measured: `[0 black][.5 red][1 yellow][1 black]` is black at a fractal's interior value
/// of exactly 1, as textures/patterns/fractals3.pov paints its sets).
pub fn blend_position<T>(map: &[T], v: f64, key: impl Fn(&T) -> f64) -> Blend {
    let n = map.len();
    if n == 0 {
        return Blend::None;
    }
    if v <= key(&map[0]) {
        return Blend::One(0);
    }
    if v >= key(&map[n - 1]) {
        return Blend::One(n - 1);
    }
    for i in 1..n {
        let hi = key(&map[i]);
        if v <= hi {
            let lo = key(&map[i - 1]);
            let t = if hi > lo { (v - lo) / (hi - lo) } else { 1.0 };
            return Blend::Two(i - 1, t);
        }
    }
    Blend::One(n - 1)
}

/// The colour a fraction `t` of the way from `a` to `b`, in all five channels.
pub fn mix(a: &Colour, b: &Colour, t: f64) -> Colour {
    Colour {
        rgb: a.rgb + (b.rgb - a.rgb) * t,
        filter: a.filter + (b.filter - a.filter) * t,
        transmit: a.transmit + (b.transmit - a.transmit) * t,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_fall_between_entries_or_clamp_to_the_ends() {
        let map = [0.2, 0.5, 0.5, 0.9];
        let at = |v| blend_position(&map, v, |e| *e);
        assert!(matches!(at(0.0), Blend::One(0)));
        assert!(matches!(at(1.0), Blend::One(3)));
        match at(0.35) {
            Blend::Two(0, t) => assert!((t - 0.5).abs() < 1e-12),
            _ => panic!("expected a blend of entries 0 and 1"),
        }
        // Two entries at the same value make a sharp step: at it, the pair below; just above
        // it, the next pair.
        assert!(matches!(at(0.5), Blend::Two(0, t) if t == 1.0));
        assert!(matches!(at(0.5 + 1e-12), Blend::Two(2, t) if t < 1e-9));
        // At the last value the last entry, even with an equal entry before it.
        let end = [0.0, 0.5, 1.0, 1.0];
        assert!(matches!(blend_position(&end, 1.0, |e| *e), Blend::One(3)));
        let empty: [f64; 0] = [];
        assert!(matches!(blend_position(&empty, 0.5, |e| *e), Blend::None));
    }

    #[test]
    fn mixing_is_linear_in_every_channel() {
        let a = Colour::rgb(1.0, 0.0, 0.0);
        let mut b = Colour::rgb(0.0, 1.0, 0.0);
        b.filter = 1.0;
        b.transmit = 0.5;
        let m = mix(&a, &b, 0.25);
        assert_eq!(m.rgb, glam::DVec3::new(0.75, 0.25, 0.0));
        assert_eq!((m.filter, m.transmit), (0.25, 0.125));
    }
}
