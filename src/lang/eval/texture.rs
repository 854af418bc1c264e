//! `pigment`, `finish` and `texture` blocks. Each starts from a base (the object's current
//! one, or the default) because POV-Ray modifies in place: `pigment { scale 2 }` on an
//! object scales the pigment it already has, and a declared texture is copied, then changed.

use glam::DVec3;

use super::super::diagnostics::Diagnostic;
use super::super::diagnostics::Span;
use super::super::syntax::{Punct, Token, TokenKind};
use super::Evaluator;
use super::value::{Value, colour_of};
use crate::scene::{
    BlackHole, Colour, Crackle, Finish, Fractal, FractalColouring, FractalFormula, ImageData,
    ImageMap, Interior, MapType, MappingKind, MappingWarp, Normal, Orientation, Pattern,
    PatternKind, Pigment, PigmentKind, Reflection, RepeatWarp, SlopeEntry, Texture, TextureMap,
    Transform, Turbulence, Warp, Wave,
};

type R<T> = Result<T, Diagnostic>;

/// Pattern keywords POV-Ray has that penumbra does not model yet.
const UNSUPPORTED_PATTERNS: &[&str] = &["aoi", "facets"];

/// Pattern keywords penumbra models.
const PATTERNS: &[&str] = &[
    "object",
    "image_pattern",
    "density_file",
    "slope",
    "quilted",
    "mandel",
    "julia",
    "magnet",
    "cells",
    "crackle",
    "average",
    "checker",
    "hexagon",
    "square",
    "triangular",
    "brick",
    "gradient",
    "onion",
    "radial",
    "spiral1",
    "spiral2",
    "tiling",
    "pavement",
    "leopard",
    "marble",
    "wood",
    "agate",
    "bozo",
    "spotted",
    "granite",
    "wrinkles",
    "bumps",
    "dents",
    "ripples",
    "waves",
    "planar",
    "spherical",
    "cylindrical",
    "boxed",
    "pigment_pattern",
    "function",
];

/// What a pattern block holds while it is read: the pattern and where its modifiers go.
/// `albedo` forms of `diffuse`, `phong` and `specular`: they depend on `brilliance`,
/// `phong_size` and `roughness`, which may come later in the block, so they are resolved
/// at its end.
#[derive(Default)]
struct Albedos {
    diffuse: Option<f64>,
    phong: Option<f64>,
    specular: Option<f64>,
}

impl Albedos {
    fn resolve(&self, f: &mut Finish) {
        if let Some(k) = self.diffuse {
            f.diffuse = k * (f.brilliance + 1.0) / 2.0;
        }
        if let Some(p) = self.phong {
            f.phong = p * (f.phong_size + 1.0) / 2.0;
        }
        if let Some(s) = self.specular {
            let e = 1.0 / f.roughness;
            f.specular = s * (e + 2.0) / (4.0 * (2.0 - 2f64.powf(-e / 2.0)));
        }
    }
}

/// Reads one pattern item (after its keyword) into the pattern.
type PatternItem = fn(&mut Evaluator<'_>, &mut Pattern) -> R<()>;

fn turbulence(p: &mut Pattern) -> &mut Turbulence {
    p.turbulence.get_or_insert_with(Turbulence::default)
}

fn set_wave(p: &mut Pattern, wave: Wave) -> R<()> {
    p.wave = wave;
    Ok(())
}

/// The items every pattern takes (`warp` aside, which also moves the pattern's transform).
const PATTERN_ITEMS: &[(&str, PatternItem)] = &[
    ("frequency", |ev, p| {
        p.frequency = ev.float()?;
        Ok(())
    }),
    ("phase", |ev, p| {
        p.phase = ev.float()?;
        Ok(())
    }),
    ("ramp_wave", |_, p| set_wave(p, Wave::Ramp)),
    ("sine_wave", |_, p| set_wave(p, Wave::Sine)),
    ("triangle_wave", |_, p| set_wave(p, Wave::Triangle)),
    ("scallop_wave", |_, p| set_wave(p, Wave::Scallop)),
    ("cubic_wave", |_, p| set_wave(p, Wave::Cubic)),
    ("poly_wave", |ev, p| {
        let e = if ev.starts_float()? { ev.float()? } else { 1.0 };
        set_wave(p, Wave::Poly(e))
    }),
    ("turbulence", |ev, p| {
        let (v, s) = ev.expr()?;
        let amount = ev.to_vec3(&v, s)?;
        turbulence(p).amount = amount;
        Ok(())
    }),
    ("octaves", |ev, p| {
        let o = ev.float()?;
        turbulence(p).octaves = o.clamp(1.0, 10.0) as u32;
        Ok(())
    }),
    ("omega", |ev, p| {
        let o = ev.float()?;
        turbulence(p).omega = o;
        Ok(())
    }),
    ("lambda", |ev, p| {
        let l = ev.float()?;
        turbulence(p).lambda = l;
        Ok(())
    }),
    ("noise_generator", |ev, p| {
        p.noise_generator = ev.float()?.clamp(1.0, 3.0) as u8;
        Ok(())
    }),
    // A density_file's interpolation may come after its other modifiers (a normal's
    // amount, for instance).
    ("interpolate", |ev, p| {
        let trilinear = ev.df3_interpolation()?;
        if let PatternKind::DensityFile(grid) = &mut p.kind {
            std::sync::Arc::make_mut(grid).trilinear = trilinear;
        }
        Ok(())
    }),
    ("brick_size", |ev, p| {
        let v = ev.vector3()?;
        if let PatternKind::Brick { size, .. } = &mut p.kind {
            *size = v;
        }
        Ok(())
    }),
    ("mortar", |ev, p| {
        let m = ev.float()?;
        if let PatternKind::Brick { mortar, .. } = &mut p.kind {
            *mortar = m;
        }
        Ok(())
    }),
    ("form", |ev, p| {
        if let PatternKind::Pavement(v) = &mut p.kind {
            v.form = ev.pavement_setting("form", &[0, 1, 2, 3])?;
            return Ok(());
        }
        let v = ev.vector3()?;
        if let Some(c) = crackle(p) {
            c.form = v;
        }
        Ok(())
    }),
    ("number_of_sides", |ev, p| {
        let n = ev.pavement_setting("number_of_sides", &[3, 4, 6])?;
        if let PatternKind::Pavement(v) = &mut p.kind {
            v.sides = n;
        }
        Ok(())
    }),
    ("number_of_tiles", |ev, p| {
        let n = ev.pavement_setting("number_of_tiles", &[1, 2, 3, 4, 5, 6])?;
        if let PatternKind::Pavement(v) = &mut p.kind {
            v.tiles = n;
        }
        Ok(())
    }),
    ("pattern", |ev, p| {
        let n = ev.pavement_setting("pattern", &PAVEMENT_PATTERNS)?;
        if let PatternKind::Pavement(v) = &mut p.kind {
            v.pattern = n;
        }
        Ok(())
    }),
    ("metric", |ev, p| {
        let m = ev.float()?;
        if let Some(c) = crackle(p) {
            c.metric = m;
        }
        Ok(())
    }),
    ("offset", |ev, p| {
        let o = ev.float()?;
        if let Some(c) = crackle(p) {
            c.offset = o;
        }
        Ok(())
    }),
    ("solid", |_, p| {
        if let Some(c) = crackle(p) {
            c.solid = true;
        }
        Ok(())
    }),
    ("control0", |ev, p| {
        let c = ev.float()?;
        if let PatternKind::Quilted(q) = &mut p.kind {
            q.control0 = c;
        }
        Ok(())
    }),
    ("control1", |ev, p| {
        let c = ev.float()?;
        if let PatternKind::Quilted(q) = &mut p.kind {
            q.control1 = c;
        }
        Ok(())
    }),
    ("exponent", |ev, p| ev.fractal_exponent(p)),
    ("exterior", |ev, p| {
        if let PatternKind::Pavement(v) = &mut p.kind {
            v.exterior = ev.pavement_setting("exterior", &[0, 1, 2])?;
            return Ok(());
        }
        let (c, span) = ev.fractal_colouring("exterior")?;
        ev.fractal_of(p, "exterior", span)?.exterior = c;
        Ok(())
    }),
    ("interior", |ev, p| {
        if let PatternKind::Pavement(v) = &mut p.kind {
            v.interior = ev.pavement_setting("interior", &[0, 1, 2])?;
            return Ok(());
        }
        let (c, span) = ev.fractal_colouring("interior")?;
        ev.fractal_of(p, "interior", span)?.interior = c;
        Ok(())
    }),
    ("agate_turb", |ev, p| {
        let a = ev.float()?;
        if let PatternKind::Agate { turbulence } = &mut p.kind {
            *turbulence = a;
        }
        Ok(())
    }),
];

/// Pavement's pattern numbers: up to the 35 hexominoes.
const PAVEMENT_PATTERNS: [u8; 35] = {
    let mut all = [0; 35];
    let mut i = 0;
    while i < 35 {
        all[i] = i as u8 + 1;
        i += 1;
    }
    all
};

/// The crackle settings a modifier changes; other patterns ignore crackle's modifiers.
fn crackle(p: &mut Pattern) -> Option<&mut Crackle> {
    match &mut p.kind {
        PatternKind::Crackle(c) => Some(c),
        _ => None,
    }
}

impl Evaluator<'_> {
    /// The parameters after `mandel`, `julia` or `magnet`: `[magnet 1|2] mandel N` or
    /// `[magnet 1|2] julia <c>, N`.
    fn fractal(&mut self, word: &str) -> R<Fractal> {
        let mut form = word.to_string();
        let mut formula = FractalFormula::Power(2);
        if word == "magnet" {
            let (v, span) = self.expr()?;
            formula = match self.to_float(&v, span)? {
                1.0 => FractalFormula::Magnet1,
                2.0 => FractalFormula::Magnet2,
                _ => return Err(self.err(span, "the magnet type must be 1 or 2")),
            };
            let tok = self.next()?;
            match tok.ident() {
                Some(w @ ("mandel" | "julia")) => form = w.to_string(),
                _ => return Err(self.expected("`mandel` or `julia` after the magnet type", &tok)),
            }
        }
        let julia = if form == "julia" {
            let (v, span) = self.expr()?;
            let c = self.to_vec3(&v, span)?;
            self.eat(Punct::Comma)?;
            Some([c.x, c.y])
        } else {
            None
        };
        let (v, span) = self.expr()?;
        let n = self.to_float(&v, span)?;
        if !(0.0..=f64::from(u32::MAX)).contains(&n) {
            return Err(self.err(span, "max_iteration must be 0 or more (and below 2^32)"));
        }
        Ok(Fractal::new(formula, julia, n as u32))
    }

    /// The fractal settings a fractal modifier changes; any other pattern refuses them.
    fn fractal_of<'p>(&self, p: &'p mut Pattern, word: &str, span: Span) -> R<&'p mut Fractal> {
        match &mut p.kind {
            PatternKind::Fractal(f) => Ok(f),
            _ => Err(self.err(
                span,
                format!("`{word}` works only with mandel, julia and magnet"),
            )),
        }
    }

    /// `exponent n` (2 to 33) of mandel or julia.
    fn fractal_exponent(&mut self, p: &mut Pattern) -> R<()> {
        let (v, span) = self.expr()?;
        let n = self.to_float(&v, span)?;
        let f = self.fractal_of(p, "exponent", span)?;
        if !matches!(f.formula, FractalFormula::Power(_)) {
            return Err(self.err(
                span,
                "`exponent` works only with mandel and julia, not magnet",
            ));
        }
        if !(2.0..34.0).contains(&n) {
            return Err(self.err(span, "the fractal exponent must be from 2 to 33"));
        }
        f.formula = FractalFormula::Power(n as u32);
        Ok(())
    }

    /// `TYPE, FACTOR` after `exterior` or `interior`: type 0 to 6.
    fn fractal_colouring(&mut self, what: &str) -> R<((FractalColouring, f64), Span)> {
        let (v, span) = self.expr()?;
        let n = self.to_float(&v, span)?;
        let kind = FractalColouring::from_type(n as i64)
            .filter(|_| n.fract() == 0.0)
            .ok_or_else(|| self.err(span, format!("the {what} type must be 0 to 6")))?;
        self.eat(Punct::Comma)?;
        Ok(((kind, self.float()?), span))
    }
}

enum Modified<'a> {
    Pigment(&'a mut Pigment),
    Normal(&'a mut Normal),
    Texture(&'a mut Texture),
}

impl Evaluator<'_> {
    /// A pattern with the global `noise_generator` as its default.
    pub(super) fn new_pattern(&self, kind: PatternKind) -> Pattern {
        let mut p = Pattern::new(kind);
        p.noise_generator = self.scene.settings.noise_generator;
        p
    }

    /// `{ ... }` after `pigment`.
    pub(super) fn pigment_body(&mut self, base: Pigment) -> R<Pigment> {
        let open = self.expect(Punct::LBrace, "after `pigment`")?;
        self.enter(open.span)?;
        let r = self.pigment_items(base, Punct::RBrace);
        self.leave();
        let p = r?;
        let close = self.expect(Punct::RBrace, "to close the pigment")?;
        self.check_pavement(p.pattern(), close.span)?;
        if let PigmentKind::ColourMap { pattern, .. } = &p.kind
            && matches!(pattern.kind, PatternKind::Average)
        {
            return Err(self.err(close.span, "`average` needs a pigment_map"));
        }
        Ok(p)
    }

    /// A pigment of the pattern `w` (the next token): a list pattern with its entries, or
    /// any other with its default map (`default_colour_map`).
    fn pattern_pigment(&mut self, w: &str) -> R<Pigment> {
        self.next()?;
        let kind = self.pattern_kind(w)?;
        let pattern = self.new_pattern(kind);
        let kind = if let Some(n) = pattern.kind.list_size() {
            let entries = self.list_entries(n)?;
            self.object_pattern_end(&pattern.kind)?;
            PigmentKind::List { pattern, entries }
        } else {
            let map = default_colour_map(&pattern.kind);
            PigmentKind::ColourMap { pattern, map }
        };
        Ok(Pigment {
            kind,
            transform: Transform::IDENTITY,
            uv_mapping: false,
        })
    }

    fn pigment_items(&mut self, mut p: Pigment, close: Punct) -> R<Pigment> {
        let mut first = true;
        // Set when the block closes, so that the transforms written inside still move the
        // pattern (in uv space) while those applied later do not.
        let mut uv_mapping = false;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(close) {
                if uv_mapping {
                    p.uv_mapping = true;
                }
                settle_default_map(&mut p);
                return Ok(p);
            }
            if let Some(t) = self.transform_modifier()? {
                p.transform_by(&t);
                first = false;
                continue;
            }
            let word = tok.ident();
            match word {
                // A colour keyword can only start a colour (keywords are never declared):
                // the common `pigment { color ... }` skips the tests of patterns and names.
                Some(w) if super::keywords::is_colour_keyword(w) => {
                    let (c, _) = self.colour()?;
                    p = Pigment::solid(colour_of(c));
                }
                Some(w) if PATTERNS.contains(&w) && self.lookup(w).is_none() => {
                    p = self.pattern_pigment(w)?;
                }
                Some("color_map" | "colour_map") => {
                    self.next()?;
                    let map = self.colour_map_body()?;
                    let pattern = p
                        .pattern_mut()
                        .map(|x| x.clone())
                        .unwrap_or_else(|| Pattern::new(PatternKind::Gradient(DVec3::X)));
                    p.kind = PigmentKind::ColourMap { pattern, map };
                }
                Some(w) if w == self.pigment_map_word() => {
                    self.next()?;
                    let average = p
                        .pattern_mut()
                        .is_some_and(|x| matches!(x.kind, PatternKind::Average));
                    let mut map = self.pigment_map_body(average)?;
                    let t = p.transform;
                    for (_, e) in &mut map {
                        e.transform_by(&t);
                    }
                    let pattern = p
                        .pattern_mut()
                        .map(|x| x.clone())
                        .unwrap_or_else(|| Pattern::new(PatternKind::Gradient(DVec3::X)));
                    p.kind = PigmentKind::PigmentMap { pattern, map };
                }
                Some("image_map") => {
                    self.next()?;
                    p = Pigment {
                        kind: PigmentKind::Image(self.image_map_body()?),
                        transform: Transform::IDENTITY,
                        uv_mapping: false,
                    };
                }
                Some("uv_mapping") => {
                    self.next()?;
                    uv_mapping = true;
                    continue;
                }
                Some("quick_color" | "quick_colour") => {
                    self.next()?;
                    self.colour()?;
                }
                Some(w) if UNSUPPORTED_PATTERNS.contains(&w) && self.lookup(w).is_none() => {
                    return Err(self.unsupported(&tok, w));
                }
                Some(w) if matches!(self.lookup(w), Some(Value::Pigment(_))) && first => {
                    if let Some(Value::Pigment(named)) = self.lookup(w).cloned() {
                        p = *named;
                    }
                    self.next()?;
                }
                Some(w)
                    if self.lookup(w).is_none()
                        && self.pattern_modifier(Modified::Pigment(&mut p), w)? => {}
                // `pigment { Pigments[frame_number - 1] }`: an element of an array of
                // pigments (or of colours), as portfolio/p_skies.pov writes.
                Some(w) if first && matches!(self.lookup(w), Some(Value::Array(_))) => {
                    let (v, span) = self.expr()?;
                    p = match v {
                        Value::Pigment(named) => *named,
                        other => Pigment::solid(colour_of(self.to_colour(&other, span)?)),
                    };
                }
                _ if first || self.starts_colour(&tok)? => {
                    let (c, _) = self.colour()?;
                    p = Pigment::solid(colour_of(c));
                }
                _ => return Err(self.stray_in_block(&tok, "the pigment")),
            }
            first = false;
        }
    }

    /// The parameters that follow a pattern keyword.
    fn pattern_kind(&mut self, word: &str) -> R<PatternKind> {
        Ok(match word {
            "checker" => PatternKind::Checker,
            "hexagon" => PatternKind::Hexagon,
            "square" => PatternKind::Square,
            "triangular" => PatternKind::Triangular,
            "brick" => PatternKind::Brick {
                size: DVec3::new(8.0, 3.0, 4.5),
                mortar: 0.5,
            },
            // POV-Ray uses the direction only: `gradient <2,0,0>` repeats every unit.
            "gradient" => PatternKind::Gradient(self.vector3()?.normalize_or_zero()),
            "onion" => PatternKind::Onion,
            "radial" => PatternKind::Radial,
            "spiral1" => PatternKind::Spiral1(self.float()?),
            "tiling" => PatternKind::Tiling(self.tiling_number()?),
            "pavement" => PatternKind::Pavement(crate::scene::Pavement::default()),
            "spiral2" => PatternKind::Spiral2(self.float()?),
            "leopard" => PatternKind::Leopard,
            "marble" => PatternKind::Marble,
            "wood" => PatternKind::Wood,
            "agate" => PatternKind::Agate { turbulence: 1.0 },
            "bozo" => PatternKind::Bozo,
            "spotted" => PatternKind::Spotted,
            "granite" => PatternKind::Granite,
            "wrinkles" => PatternKind::Wrinkles,
            "bumps" => PatternKind::Bumps,
            "dents" => PatternKind::Dents,
            "ripples" => PatternKind::Ripples,
            "waves" => PatternKind::Waves,
            "planar" => PatternKind::Planar,
            "spherical" => PatternKind::Spherical,
            "cylindrical" => PatternKind::Cylindrical,
            "boxed" => PatternKind::Boxed,
            "crackle" => PatternKind::Crackle(Crackle::default()),
            "quilted" => PatternKind::Quilted(crate::scene::Quilted::default()),
            "cells" => PatternKind::Cells,
            "mandel" | "julia" | "magnet" => PatternKind::Fractal(self.fractal(word)?),
            "average" => PatternKind::Average,
            "image_pattern" => {
                let (image, use_alpha) = self.image_body("image_pattern", true)?;
                PatternKind::ImagePattern {
                    image: std::sync::Arc::new(image),
                    use_alpha,
                }
            }
            "slope" => PatternKind::Slope(self.slope()?),
            "density_file" => PatternKind::DensityFile(std::sync::Arc::new(self.density_file()?)),
            "function" => {
                let span = self.peek()?.span;
                PatternKind::Function(self.point_function(span)?)
            }
            "object" => PatternKind::Object(self.object_pattern()?),
            _ => {
                // pigment_pattern
                let pig = self.pigment_body_from_keyword()?;
                PatternKind::PigmentPattern(Box::new(pig))
            }
        })
    }

    /// `tiling n`'s number, refused by name where the tiling is not modelled.
    fn tiling_number(&mut self) -> R<u8> {
        let tok = self.peek()?;
        let (v, span) = self.expr()?;
        let n = self.to_float(&v, span)?.trunc();
        if !(1.0..=27.0).contains(&n) {
            return Err(self.err(span, format!("tiling takes a number from 1 to 27, not {n}")));
        }
        let n = n as u8;
        if !crate::appearance::tiling::supported(n) {
            return Err(self.unsupported(&tok, &format!("tiling {n}")));
        }
        Ok(n)
    }

    /// One of pavement's whole-number settings, which must be one of `allowed`.
    fn pavement_setting(&mut self, name: &str, allowed: &[u8]) -> R<u8> {
        let (v, span) = self.expr()?;
        let n = self.to_float(&v, span)?.trunc();
        if let Some(&a) = allowed.iter().find(|&&a| f64::from(a) == n) {
            return Ok(a);
        }
        let choices = match allowed {
            [first, .., last] if allowed.len() > 6 => format!("from {first} to {last}"),
            _ => {
                let all: Vec<String> = allowed.iter().map(u8::to_string).collect();
                format!("one of {}", all.join(", "))
            }
        };
        Err(self.err(span, format!("pavement's {name} is {choices}, not {n}")))
    }

    /// A pavement whose block has closed at `span`: its polyform must exist (POV-Ray refuses
    /// hexagons of 6 and patterns past the count of their polyforms).
    fn check_pavement(&self, pattern: Option<&Pattern>, span: Span) -> R<()> {
        let Some(PatternKind::Pavement(v)) = pattern.map(|p| &p.kind) else {
            return Ok(());
        };
        let count = crate::appearance::tiling::pavement_count(v.sides, v.tiles);
        if v.pattern > count {
            return Err(self.err(
                span,
                format!(
                    "pavement has {count} patterns of {} polygons of {} sides, not {}",
                    v.tiles, v.sides, v.pattern
                ),
            ));
        }
        Ok(())
    }

    /// `slope { <d> [, lo, hi] [altitude <a> [, lo, hi]] }` (the braces may be left out,
    /// as in POV-Ray's older `slope <d>`).
    fn slope(&mut self) -> R<crate::scene::Slope> {
        let braced = self.peek()?.is_punct(Punct::LBrace);
        if braced {
            let open = self.next()?;
            self.enter(open.span)?;
        }
        let r = self.slope_body();
        if braced {
            self.leave();
        }
        let slope = r?;
        if braced {
            self.expect(Punct::RBrace, "to close the slope")?;
        }
        Ok(slope)
    }

    fn slope_body(&mut self) -> R<crate::scene::Slope> {
        let tok = self.peek()?;
        if tok.is_ident("point_at") {
            return Err(self.unsupported(&tok, "slope { point_at ... }"));
        }
        let d = self.vector3()?;
        if d.length() == 0.0 || !d.is_finite() {
            return Err(self.err(tok.span, "the slope direction must be a non-zero vector"));
        }
        let range = self.slope_range()?;
        let altitude = if self.eat_ident("altitude")? {
            let at = self.peek()?;
            let a = self.vector3()?;
            if !a.is_finite() {
                return Err(self.err(at.span, "the altitude direction must be finite"));
            }
            let range = self.slope_range()?;
            Some((a.normalize_or_zero(), a.length(), range))
        } else {
            None
        };
        Ok(crate::scene::Slope {
            direction: d.normalize(),
            range,
            altitude,
            weight: d.length(),
        })
    }

    /// `, lo, hi` after a slope or altitude vector; (0, 1) without.
    fn slope_range(&mut self) -> R<(f64, f64)> {
        if !self.eat(Punct::Comma)? {
            return Ok((0.0, 1.0));
        }
        let lo = self.float()?;
        self.expect(Punct::Comma, "between the low and high slope values")?;
        Ok((lo, self.float()?))
    }

    /// `df3 "file" [interpolate k]` after `density_file`.
    fn density_file(&mut self) -> R<crate::scene::VoxelGrid> {
        let tok = self.next()?;
        if !tok.is_ident("df3") {
            return Err(self.expected("`df3` after `density_file`", &tok));
        }
        let (v, span) = self.expr()?;
        let Value::Str(name) = v else {
            return Err(self.err(span, "expected the df3 file name as a string"));
        };
        let Some(path) = self.resolve_include(&name) else {
            return Err(self.err(span, format!("cannot find the density file \"{name}\"")));
        };
        let bytes = std::fs::read(&path)
            .map_err(|e| self.err(span, format!("cannot read \"{name}\": {e}")))?;
        let mut grid = read_df3(&bytes).map_err(|e| self.err(span, format!("\"{name}\": {e}")))?;
        if self.eat_ident("interpolate")? {
            grid.trilinear = self.df3_interpolation()?;
        }
        Ok(grid)
    }

    /// The number after `interpolate` of a density_file: 1 is trilinear, 0 the nearest
    /// voxel; 2 (tricubic) is refused.
    fn df3_interpolation(&mut self) -> R<bool> {
        let tok = self.peek()?;
        let k = self.float()?;
        if k == 2.0 {
            return Err(self.unsupported(&tok, "tricubic df3 interpolation"));
        }
        Ok(k == 1.0)
    }

    fn pigment_body_from_keyword(&mut self) -> R<Pigment> {
        self.pigment_body(Pigment::default())
    }

    /// Up to `n` entries of a list pattern, with POV-Ray's defaults for missing ones.
    fn list_entries(&mut self, n: usize) -> R<Vec<Pigment>> {
        let first = self.peek()?;
        let pigments = first.is_ident(self.pigment_word())
            || matches!(
                first.ident().and_then(|w| self.lookup(w)),
                Some(Value::Pigment(_))
            );
        let mut entries = Vec::new();
        while entries.len() < n {
            match self.list_entry()? {
                Some(e) => entries.push(e),
                None => break,
            }
            self.eat(Punct::Comma)?;
        }
        // POV-Ray's defaults for missing entries (measured): a list of pigments gets the
        // default pigment (black); a list of colours checker's blue, green, hexagon's blue,
        // green, red, square's red, green, blue, yellow and triangular's red, green, blue,
        // yellow, cyan, magenta.
        let (r, g, b) = (
            Colour::rgb(1.0, 0.0, 0.0),
            Colour::rgb(0.0, 1.0, 0.0),
            Colour::rgb(0.0, 0.0, 1.0),
        );
        let (yellow, magenta, cyan) = (
            Colour::rgb(1.0, 1.0, 0.0),
            Colour::rgb(1.0, 0.0, 1.0),
            Colour::rgb(0.0, 1.0, 1.0),
        );
        let black = [Colour::BLACK; 6];
        let defaults: &[Colour] = match n {
            _ if pigments => &black[..n.min(6)],
            3 => &[b, g, r],
            4 => &[r, g, b, yellow],
            6 => &[r, g, b, yellow, cyan, magenta],
            _ => &[b, g],
        };
        for d in defaults.iter().skip(entries.len()) {
            entries.push(Pigment::solid(*d));
        }
        Ok(entries)
    }

    /// A pattern modifier (frequency, wave, turbulence, warp, brick size ...) applied to
    /// the pattern being read; false when the word is none.
    fn pattern_modifier(&mut self, target: Modified<'_>, word: &str) -> R<bool> {
        let item = PATTERN_ITEMS.iter().find(|(name, _)| *name == word);
        if item.is_none() && word != "warp" {
            return Ok(false);
        }
        let tok = self.next()?;
        let mut image = None;
        let (pattern, transform) = match target {
            Modified::Pigment(p) => {
                let t = &mut p.transform;
                match &mut p.kind {
                    PigmentKind::Solid(_) => (None, t),
                    PigmentKind::Image(im) => {
                        image = Some(im);
                        (None, t)
                    }
                    PigmentKind::List { pattern, .. }
                    | PigmentKind::ColourMap { pattern, .. }
                    | PigmentKind::PigmentMap { pattern, .. } => (Some(pattern), t),
                }
            }
            Modified::Normal(n) => (Some(&mut n.pattern), &mut n.transform),
            Modified::Texture(t) => match &mut t.map {
                Some(m) => (Some(&mut m.pattern), &mut m.transform),
                None => {
                    return Err(self.err(tok.span, format!("`{word}` needs a pattern before it")));
                }
            },
        };
        // Without a pattern (a plain colour) the item is read and has no effect; an image
        // keeps the turbulence and warps it gets.
        let mut scratch = Pattern::new(PatternKind::Bozo);
        if let Some(im) = &mut image {
            scratch.turbulence = im.turbulence.take();
            scratch.warps = std::mem::take(&mut im.warps);
        }
        let pattern = pattern.unwrap_or(&mut scratch);
        let read = if let Some((_, read)) = item {
            read(self, pattern)
        } else {
            self.warp_into(pattern, transform)
        };
        if let Some(im) = image {
            im.turbulence = scratch.turbulence;
            im.warps = scratch.warps;
        }
        read.map(|()| true)
    }

    /// `warp { turbulence ... }`: transforms written before it are warped with the
    /// pattern, so they move into the warp chain.
    fn warp_into(&mut self, pattern: &mut Pattern, transform: &mut Transform) -> R<()> {
        if let Some(w) = self.warp_block()? {
            if !transform.is_identity() {
                pattern.warps.push(Warp::Transform(*transform));
                *transform = Transform::IDENTITY;
            }
            pattern.warps.push(w);
        }
        Ok(())
    }

    /// `warp { ... }`: the turbulence warp or one of the geometric warps (appearance::warps).
    fn warp_block(&mut self) -> R<Option<Warp>> {
        let open = self.expect(Punct::LBrace, "after `warp`")?;
        self.enter(open.span)?;
        let r = self.warp_body();
        self.leave();
        let w = r?;
        self.expect(Punct::RBrace, "to close the warp")?;
        Ok(w)
    }

    fn warp_body(&mut self) -> R<Option<Warp>> {
        let tok = self.peek()?;
        Ok(match tok.ident() {
            Some("repeat") => {
                self.next()?;
                Some(self.repeat_warp(&tok)?)
            }
            Some("black_hole") => {
                self.next()?;
                Some(Warp::BlackHole(self.black_hole_warp()?))
            }
            Some("planar") => {
                self.next()?;
                let (mut normal, mut distance) = (DVec3::Z, 0.0);
                if !self.peek()?.is_punct(Punct::RBrace) {
                    normal = self.vector3()?;
                    self.expect(Punct::Comma, "after the planar warp's normal")?;
                    distance = self.float()?;
                }
                Some(Warp::Planar {
                    orient: Orientation::new(normal),
                    distance,
                })
            }
            Some(w @ ("cylindrical" | "spherical" | "toroidal" | "cubic")) => {
                let kind = match w {
                    "cylindrical" => MappingKind::Cylindrical,
                    "spherical" => MappingKind::Spherical,
                    "toroidal" => MappingKind::Toroidal { major_radius: 1.0 },
                    _ => MappingKind::Cubic,
                };
                self.next()?;
                Some(Warp::Mapping(self.mapping_warp(kind)?))
            }
            _ => self.turbulence_warp()?,
        })
    }

    /// `repeat <w> [offset <v>] [flip <v>]`: w must lie along one axis, as POV-Ray demands.
    fn repeat_warp(&mut self, tok: &Token) -> R<Warp> {
        let dir = self.vector3()?;
        let axes: Vec<usize> = (0..3).filter(|&i| dir[i] != 0.0).collect();
        let [axis] = axes[..] else {
            return Err(self.err(tok.span, "a repeat warp repeats along exactly one axis"));
        };
        let mut r = RepeatWarp {
            axis,
            width: dir[axis],
            offset: DVec3::ZERO,
            flip: DVec3::ZERO,
        };
        loop {
            let t = self.peek()?;
            match t.ident() {
                Some("offset") => {
                    self.next()?;
                    r.offset = self.vector3()?;
                }
                Some("flip") => {
                    self.next()?;
                    let f = self.vector3()?;
                    r.flip = DVec3::select(f.cmpne(DVec3::ZERO), DVec3::ONE, DVec3::ZERO);
                }
                _ => return Ok(Warp::Repeat(r)),
            }
        }
    }

    /// `black_hole <c>, r` and its modifiers (defaults: falloff 2, strength 1).
    fn black_hole_warp(&mut self) -> R<BlackHole> {
        let centre = self.vector3()?;
        self.expect(Punct::Comma, "after the black hole's centre")?;
        let tok = self.peek()?;
        let radius = self.float()?;
        if radius <= 0.0 || radius.is_nan() {
            return Err(self.err(tok.span, "a black hole's radius must be positive"));
        }
        let mut b = BlackHole {
            centre,
            radius,
            falloff: 2.0,
            strength: 1.0,
            inverse: false,
            repeat: DVec3::ZERO,
            jitter: DVec3::ZERO,
        };
        loop {
            let t = self.peek()?;
            match t.ident() {
                Some("falloff") => {
                    self.next()?;
                    b.falloff = self.float()?;
                }
                Some("strength") => {
                    self.next()?;
                    b.strength = self.float()?;
                }
                Some("inverse") => {
                    self.next()?;
                    b.inverse = true;
                }
                Some("repeat") => {
                    self.next()?;
                    b.repeat = self.vector3()?.max(DVec3::ZERO);
                }
                Some("turbulence") => {
                    self.next()?;
                    b.jitter = self.vector3()?;
                }
                _ => return Ok(b),
            }
        }
    }

    /// `cylindrical`, `spherical`, `toroidal`: `orientation <v>`, `dist_exp f` and (toroidal)
    /// `major_radius f`; `cubic` takes none, as in POV-Ray.
    fn mapping_warp(&mut self, mut kind: MappingKind) -> R<MappingWarp> {
        let mut m = MappingWarp {
            kind,
            dist_exp: 0.0,
            orient: Orientation::new(DVec3::Z),
        };
        if kind == MappingKind::Cubic {
            return Ok(m);
        }
        loop {
            let t = self.peek()?;
            match t.ident() {
                Some("orientation") => {
                    self.next()?;
                    m.orient = Orientation::new(self.vector3()?);
                }
                Some("dist_exp") => {
                    self.next()?;
                    m.dist_exp = self.float()?;
                }
                Some("major_radius") if matches!(kind, MappingKind::Toroidal { .. }) => {
                    self.next()?;
                    kind = MappingKind::Toroidal {
                        major_radius: self.float()?,
                    };
                    m.kind = kind;
                }
                _ => return Ok(m),
            }
        }
    }

    /// `turbulence v octaves n omega w lambda l` inside a warp.
    fn turbulence_warp(&mut self) -> R<Option<Warp>> {
        let (mut t, mut any) = (Turbulence::default(), false);
        loop {
            let tok = self.peek()?;
            match tok.ident() {
                Some("turbulence") => {
                    self.next()?;
                    let (v, s) = self.expr()?;
                    t.amount = self.to_vec3(&v, s)?;
                    any = true;
                }
                Some("octaves") => {
                    self.next()?;
                    t.octaves = self.float()?.clamp(1.0, 10.0) as u32;
                }
                Some("omega") => {
                    self.next()?;
                    t.omega = self.float()?;
                }
                Some("lambda") => {
                    self.next()?;
                    t.lambda = self.float()?;
                }
                _ if tok.is_punct(Punct::RBrace) => {
                    return Ok(any.then_some(Warp::Turbulence(t)));
                }
                _ => return Err(self.stray_in_block(&tok, "the warp")),
            }
        }
    }

    /// `{ [v colour] ... }` after `color_map`; entries sorted by value as POV-Ray keeps them.
    pub(super) fn colour_map_body(&mut self) -> R<Vec<(f64, Colour)>> {
        self.read_map_entries(
            "color_map",
            "colour map",
            Self::declared_colour_map_entries,
            |ev, map| {
                let v = ev.float()?;
                ev.eat(Punct::Comma)?;
                // The old form `[a, b colour c colour d]`: a second value before the colours.
                if ev.starts_float()? {
                    let v2 = ev.float()?;
                    let (c1, _) = ev.colour()?;
                    ev.eat(Punct::Comma)?;
                    let (c2, _) = ev.colour()?;
                    map.push((v, colour_of(c1)));
                    map.push((v2, colour_of(c2)));
                } else {
                    let (c, _) = ev.colour()?;
                    map.push((v, colour_of(c)));
                }
                Ok(())
            },
        )
    }

    /// `color_map { Declared }`: a map declared earlier (kept as a pigment) starts the map.
    fn declared_colour_map_entries(&mut self) -> R<Vec<(f64, Colour)>> {
        if let Some(Value::Pigment(named)) =
            self.peek()?.ident().and_then(|w| self.lookup(w)).cloned()
            && let PigmentKind::ColourMap { map, .. } = named.kind
        {
            self.next()?;
            return Ok(map);
        }
        Ok(Vec::new())
    }

    /// `{ [entry] ... }` after a map keyword, the same for every kind of map: `entry` reads
    /// what is inside one `[ ]` into the map, which `start` begins.
    fn read_map_entries<T>(
        &mut self,
        keyword: &str,
        what: &str,
        start: fn(&mut Self) -> R<Vec<T>>,
        mut entry: impl FnMut(&mut Self, &mut Vec<T>) -> R<()>,
    ) -> R<Vec<T>> {
        let open = self.expect(Punct::LBrace, &format!("after `{keyword}`"))?;
        self.enter(open.span)?;
        let r = (|| -> R<Vec<T>> {
            let mut map = start(self)?;
            while self.eat(Punct::LBracket)? {
                entry(self, &mut map)?;
                self.expect(Punct::RBracket, &format!("to close the {what} entry"))?;
            }
            Ok(map)
        })();
        self.leave();
        let map = r?;
        self.expect(Punct::RBrace, &format!("to close the {what}"))?;
        Ok(map)
    }

    /// What a pigment block calls its sub-pigments: `density` inside a density.
    fn pigment_word(&self) -> &'static str {
        if self.reading_density {
            "density"
        } else {
            "pigment"
        }
    }

    fn pigment_map_word(&self) -> &'static str {
        if self.reading_density {
            "density_map"
        } else {
            "pigment_map"
        }
    }

    /// `{ [v pigment {...}] ... }` after `pigment_map`.
    /// `{ [v pigment] ... }` after `pigment_map`; under `average` the weight v may be left
    /// out (it is then 1, as POV-Ray's).
    fn pigment_map_body(&mut self, average: bool) -> R<Vec<(f64, Pigment)>> {
        self.read_map_entries(
            "pigment_map",
            "pigment map",
            |_| Ok(Vec::new()),
            |ev, map| {
                let v = ev.map_weight(average)?;
                ev.eat(Punct::Comma)?;
                // Entries are pigment bodies: `[0.5 checker rgb 1, rgb 0]`, `[1 Named]`.
                let p = if ev.peek()?.is_ident(ev.pigment_word()) {
                    ev.list_entry()?.unwrap_or_default()
                } else {
                    ev.pigment_items(Pigment::default(), Punct::RBracket)?
                };
                map.push((v, p));
                Ok(())
            },
        )
    }

    /// `{ [v texture {...}] ... }` after `texture_map` (v optional under `average`).
    fn texture_map_body(&mut self, average: bool) -> R<Vec<(f64, Texture)>> {
        self.read_map_entries(
            "texture_map",
            "texture map",
            |_| Ok(Vec::new()),
            |ev, map| {
                let v = ev.map_weight(average)?;
                ev.eat(Punct::Comma)?;
                // Entries are texture bodies: `[0.5 T_Named]`, `[1 pigment {...} finish {...}]`.
                let t = if ev.peek()?.is_ident("texture") {
                    ev.next()?;
                    ev.texture_body(ev.default_texture.clone())?
                } else {
                    ev.texture_items(ev.default_texture.clone(), Punct::RBracket)?
                };
                map.push((v, t));
                Ok(())
            },
        )
    }

    /// A map entry's value; under `average` it is a weight that may be left out (1, as
    /// POV-Ray's).
    fn map_weight(&mut self, average: bool) -> R<f64> {
        if average && !self.starts_float()? {
            Ok(1.0)
        } else {
            self.float()
        }
    }

    /// `{ ... }` after `normal`.
    pub(super) fn normal_body(&mut self, base: Option<Normal>) -> R<Option<Normal>> {
        let open = self.expect(Punct::LBrace, "after `normal`")?;
        self.enter(open.span)?;
        let r = self.normal_items(base, Punct::RBrace);
        self.leave();
        let n = r?;
        let close = self.expect(Punct::RBrace, "to close the normal")?;
        self.check_pavement(n.as_ref().map(|n| &n.pattern), close.span)?;
        Ok(n)
    }

    /// An array element that must be a normal (one needing an unsupported feature reports
    /// that feature here, where it is used).
    fn normal_element(&mut self) -> R<Option<Normal>> {
        match self.expr()? {
            (Value::Normal(named), _) => Ok(*named),
            (Value::Unsupported(d), s) => Err(self.err(s, d.message.clone())),
            (other, s) => {
                Err(self.err(s, format!("expected a normal, found {}", other.kind_name())))
            }
        }
    }

    fn normal_items(&mut self, mut n: Option<Normal>, close: Punct) -> R<Option<Normal>> {
        loop {
            let tok = self.peek()?;
            if tok.is_punct(close) {
                return Ok(n);
            }
            if let Some(t) = self.transform_modifier()? {
                if let Some(n) = &mut n {
                    n.transform_by(&t);
                }
                continue;
            }
            let Some(word) = tok.ident() else {
                return Err(self.stray_in_block(&tok, "the normal"));
            };
            if let Some(Value::Normal(named)) = self.lookup(word) {
                // `normal { Named ... }`: the declared normal, modified by what follows.
                n = (**named).clone();
                self.next()?;
                continue;
            }
            if matches!(self.lookup(word), Some(Value::Array(_))) {
                // `normal { Normals[i] ... }`
                n = self.normal_element()?;
                continue;
            }
            match word {
                w if PATTERNS.contains(&w) && self.lookup(w).is_none() => {
                    self.next()?;
                    let kind = self.pattern_kind(w)?;
                    let mut normal = Normal::new(self.new_pattern(kind));
                    // The amount follows the pattern, after a comma when the pattern took a
                    // vector or a number.
                    self.eat(Punct::Comma)?;
                    if self.starts_float()? {
                        normal.amount = self.float()?;
                    }
                    if let Some(count) = normal.pattern.kind.list_size() {
                        normal.normal_map = self.normal_list_entries(count)?;
                        self.object_pattern_end(&normal.pattern.kind)?;
                    }
                    n = Some(normal);
                }
                "bump_map" => {
                    self.next()?;
                    n = Some(self.bump_map_body()?);
                }
                "bump_size" => {
                    self.next()?;
                    let a = self.float()?;
                    if let Some(n) = &mut n {
                        n.amount = a;
                    }
                }
                "accuracy" => {
                    self.next()?;
                    let a = self.float()?;
                    if let Some(n) = &mut n {
                        n.accuracy = a;
                    }
                }
                "slope_map" => {
                    self.next()?;
                    let map = self.slope_map_body()?;
                    match &mut n {
                        Some(n) => n.slope_map = map,
                        None => {
                            return Err(self.err(tok.span, "`slope_map` needs a pattern before it"));
                        }
                    }
                }
                "normal_map" => {
                    self.next()?;
                    let average = n
                        .as_ref()
                        .is_some_and(|n| matches!(n.pattern.kind, PatternKind::Average));
                    let map = self.normal_map_body(average)?;
                    match &mut n {
                        Some(n) => n.normal_map = map,
                        None => {
                            return Err(
                                self.err(tok.span, "`normal_map` needs a pattern before it")
                            );
                        }
                    }
                }
                w if UNSUPPORTED_PATTERNS.contains(&w) => {
                    return Err(self.unsupported(&tok, w));
                }
                w => {
                    if let Some(normal) = &mut n
                        && self.pattern_modifier(Modified::Normal(normal), w)?
                    {
                        continue;
                    }
                    return Err(self.stray_in_block(&tok, "the normal"));
                }
            }
        }
    }

    /// `checker normal {A} normal {B}`: a list pattern's normals, as a normal map at the
    /// pattern's values 0, 1, 2 (which the list patterns give exactly), so each cell takes
    /// its own entry whole. No entries: the pattern tilts by itself.
    fn normal_list_entries(&mut self, count: usize) -> R<Vec<(f64, Normal)>> {
        let mut entries = Vec::new();
        while entries.len() < count && self.peek()?.is_ident("normal") {
            let kw = self.next()?;
            // POV-Ray refuses an empty entry too ("No normal type").
            let n = self.normal_body(None)?.ok_or_else(|| {
                self.err(
                    kw.span,
                    "a list pattern's normal entry needs a pattern (POV-Ray: \"No normal type\")",
                )
            })?;
            entries.push((entries.len() as f64, n));
            self.eat(Punct::Comma)?;
        }
        Ok(entries)
    }

    /// `{ [v, <height, slope>] ... }` after `slope_map`, sorted as written.
    fn slope_map_body(&mut self) -> R<Vec<SlopeEntry>> {
        self.read_map_entries(
            "slope_map",
            "slope map",
            |_| Ok(Vec::new()),
            |ev, map| {
                let value = ev.map_value()?;
                ev.eat(Punct::Comma)?;
                let v = ev.vector3()?;
                map.push(SlopeEntry {
                    value,
                    height: v.x,
                    slope: v.y,
                });
                Ok(())
            },
        )
    }

    /// `{ [v normal body] ... }` after `normal_map`: entries are bare normal bodies
    /// (`[0.5 bumps 0.3 scale 2]`); POV-Ray rejects a `normal {...}` wrapper there.
    fn normal_map_body(&mut self, average: bool) -> R<Vec<(f64, Normal)>> {
        self.read_map_entries(
            "normal_map",
            "normal map",
            |_| Ok(Vec::new()),
            |ev, map| {
                let v = ev.map_weight(average)?;
                ev.eat(Punct::Comma)?;
                let n = ev.normal_items(None, Punct::RBracket)?;
                // An entry without a pattern leaves the normal as it is.
                let n = n.unwrap_or_else(|| Normal {
                    amount: 0.0,
                    ..Normal::new(Pattern::new(PatternKind::Bozo))
                });
                map.push((v, n));
                Ok(())
            },
        )
    }

    /// One entry of a pattern list: `pigment {...}` or a colour; `None` when neither follows.
    fn list_entry(&mut self) -> R<Option<Pigment>> {
        let tok = self.peek()?;
        if tok.is_ident(self.pigment_word()) {
            self.next()?;
            return Ok(Some(self.pigment_body(Pigment::default())?));
        }
        if let Some(Value::Pigment(p)) = tok.ident().and_then(|w| self.lookup(w)).cloned() {
            self.next()?;
            return Ok(Some(*p));
        }
        if self.starts_colour(&tok)? {
            let (c, _) = self.colour()?;
            return Ok(Some(Pigment::solid(colour_of(c))));
        }
        Ok(None)
    }

    /// Whether the token can begin a colour (keyword, vector, number or colour identifier).
    fn starts_colour(&mut self, tok: &super::super::syntax::Token) -> R<bool> {
        Ok(match &tok.kind {
            TokenKind::Ident(w) => {
                super::keywords::is_colour_keyword(w)
                    || matches!(
                        self.lookup(w),
                        Some(Value::Colour(_) | Value::Vector(_) | Value::Float(_))
                    )
            }
            TokenKind::Number(_) => true,
            TokenKind::Punct(p) => matches!(p, Punct::Lt | Punct::LParen | Punct::Minus),
            _ => false,
        })
    }

    /// `{ ... }` after `finish`.
    pub(super) fn finish_body(&mut self, base: Finish) -> R<Finish> {
        let open = self.expect(Punct::LBrace, "after `finish`")?;
        self.enter(open.span)?;
        let r = self.finish_items(base);
        self.leave();
        let f = r?;
        self.expect(Punct::RBrace, "to close the finish")?;
        Ok(f)
    }

    fn finish_items(&mut self, mut f: Finish) -> R<Finish> {
        let mut albedo = Albedos::default();
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            let Some(word) = tok.ident() else {
                return Err(self.stray_in_block(&tok, "the finish"));
            };
            if let Some(Value::Finish(named)) = self.lookup(word).cloned() {
                self.next()?;
                f = *named;
                continue;
            }
            // `finish { Finishes[frame_number - 1] }` (portfolio/f_finish.pov).
            if matches!(self.lookup(word), Some(Value::Array(_))) {
                let (v, span) = self.expr()?;
                let Value::Finish(named) = v else {
                    return Err(
                        self.err(span, format!("expected a finish, found {}", v.kind_name()))
                    );
                };
                f = *named;
                continue;
            }
            self.next()?;
            match word {
                "ambient" => f.ambient = self.colour_or_float()?,
                "emission" => f.emission = self.colour_or_float()?,
                "diffuse" => {
                    self.albedo_or_value(&mut f.diffuse, &mut albedo.diffuse)?;
                    f.radiosity_diffuse = albedo.diffuse.unwrap_or(f.diffuse);
                    if self.eat(Punct::Comma)? {
                        f.diffuse_back = self.float()?;
                    }
                }
                "brilliance" => f.brilliance = self.float()?,
                "phong" => self.albedo_or_value(&mut f.phong, &mut albedo.phong)?,
                "phong_size" => f.phong_size = self.float()?,
                "specular" => self.albedo_or_value(&mut f.specular, &mut albedo.specular)?,
                "roughness" => f.roughness = self.positive_float("roughness")?,
                "metallic" => {
                    f.metallic = if self.starts_float()? {
                        self.float()?
                    } else {
                        1.0
                    };
                }
                "reflection" => {
                    if self.peek()?.is_punct(Punct::LBrace) {
                        f.reflection = self.reflection_block(f.reflection)?;
                    } else {
                        let c = self.colour_or_float()?;
                        f.reflection.min = c;
                        f.reflection.max = c;
                    }
                }
                "reflection_exponent" => {
                    f.reflection.exponent = self.positive_float("reflection_exponent")?;
                }
                "conserve_energy" => f.conserve_energy = self.optional_bool()?,
                "crand" => f.crand = self.float()?,
                "fresnel" => f.fresnel = self.optional_bool()?,
                "caustics" => {
                    self.warn(
                        tok.span,
                        "`caustics` belongs in the interior (as POV-Ray 3.7 says)",
                    );
                    f.caustics = self.float()?;
                }
                "irid" => f.irid = Some(self.irid_block()?),
                "ior" | "subsurface" | "fade_distance" | "fade_power" | "refraction" => {
                    return Err(self.unsupported(&tok, word));
                }
                _ => return Err(self.stray_in_block(&tok, "the finish")),
            }
        }
        albedo.resolve(&mut f);
        Ok(f)
    }

    /// `irid { amount [thickness t] [turbulence u] }` (POV-Ray's defaults: thickness 0,
    /// turbulence 0).
    fn irid_block(&mut self) -> R<crate::scene::Irid> {
        let open = self.expect(Punct::LBrace, "after `irid`")?;
        self.enter(open.span)?;
        let r = (|| -> R<crate::scene::Irid> {
            let mut irid = crate::scene::Irid {
                amount: self.float()?,
                thickness: 0.0,
                turbulence: 0.0,
            };
            loop {
                let tok = self.peek()?;
                match tok.ident() {
                    Some("thickness") => {
                        self.next()?;
                        irid.thickness = self.float()?;
                    }
                    Some("turbulence") => {
                        self.next()?;
                        // A vector is accepted; its x is the amount, as in POV-Ray.
                        let (v, span) = self.expr()?;
                        irid.turbulence = self.to_vec3(&v, span)?.x;
                    }
                    _ if tok.is_punct(Punct::RBrace) => return Ok(irid),
                    _ => return Err(self.stray_in_block(&tok, "the irid block")),
                }
            }
        })();
        self.leave();
        let irid = r?;
        self.expect(Punct::RBrace, "to close the irid block")?;
        Ok(irid)
    }

    /// `phong [albedo] v` (and `diffuse`, `specular`): a plain value is set now; an albedo
    /// is kept for the end of the block, and the last of the two written wins.
    fn albedo_or_value(&mut self, value: &mut f64, albedo: &mut Option<f64>) -> R<()> {
        let is_albedo = self.eat_ident("albedo")?;
        let v = self.float()?;
        if is_albedo {
            *albedo = Some(v);
        } else {
            *albedo = None;
            *value = v;
        }
        Ok(())
    }

    /// A float that must be greater than zero (it is divided by or raised to).
    fn positive_float(&mut self, what: &str) -> R<f64> {
        let (v, s) = self.expr()?;
        let x = self.to_float(&v, s)?;
        if x <= 0.0 {
            return Err(self.err(s, format!("{what} must be greater than zero")));
        }
        Ok(x)
    }

    /// A float (all of r, g, b) or a colour (its r, g, b).
    fn colour_or_float(&mut self) -> R<DVec3> {
        let (c, _) = self.colour()?;
        Ok(DVec3::new(c[0], c[1], c[2]))
    }

    fn reflection_block(&mut self, base: Reflection) -> R<Reflection> {
        let open = self.expect(Punct::LBrace, "after `reflection`")?;
        self.enter(open.span)?;
        let r = (|| -> R<Reflection> {
            let mut r = base;
            let first = self.colour_or_float()?;
            let mut single = true;
            // The comma is optional, as in POV-Ray (measured: `{ 0.3 0.8 }` renders as
            // `{ 0.3, 0.8 }`).
            let tok = self.peek()?;
            let item = matches!(
                tok.ident(),
                Some("falloff" | "fresnel" | "exponent" | "metallic")
            );
            if self.eat(Punct::Comma)? || !(item || tok.is_punct(Punct::RBrace)) {
                r.min = first;
                r.max = self.colour_or_float()?;
                single = false;
            } else {
                r.min = first;
                r.max = first;
            }
            loop {
                let tok = self.peek()?;
                if tok.is_punct(Punct::RBrace) {
                    break;
                }
                match tok.ident() {
                    Some("falloff") => {
                        self.next()?;
                        r.falloff = self.float()?;
                    }
                    Some("fresnel") => {
                        self.next()?;
                        r.fresnel = self.optional_bool()?;
                    }
                    Some("exponent") => {
                        self.next()?;
                        r.exponent = self.float()?;
                    }
                    Some("metallic") => {
                        self.next()?;
                        r.metallic = if self.starts_float()? {
                            self.float()?
                        } else {
                            1.0
                        };
                    }
                    _ => return Err(self.stray_in_block(&tok, "the reflection block")),
                }
            }
            // With `fresnel` a single value is the maximum and the minimum is zero.
            if single && r.fresnel {
                r.min = DVec3::ZERO;
            }
            Ok(r)
        })();
        self.leave();
        let r = r?;
        self.expect(Punct::RBrace, "to close the reflection block")?;
        Ok(r)
    }

    /// `{ ... }` after `texture`.
    pub(super) fn texture_body(&mut self, base: Texture) -> R<Texture> {
        let open = self.expect(Punct::LBrace, "after `texture`")?;
        self.enter(open.span)?;
        let r = self.texture_items(base, Punct::RBrace);
        self.leave();
        let t = r?;
        let close = self.expect(Punct::RBrace, "to close the texture")?;
        self.check_pavement(t.map.as_ref().map(|m| &m.pattern), close.span)?;
        Ok(t)
    }

    fn texture_items(&mut self, mut t: Texture, close: Punct) -> R<Texture> {
        let mut uv_mapping = false;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(close) {
                if uv_mapping {
                    mark_uv_mapped(&mut t);
                }
                return Ok(t);
            }
            if let Some(tr) = self.transform_modifier()? {
                t.transform_by(&tr);
                continue;
            }
            let Some(word) = tok.ident() else {
                return Err(self.stray_in_block(&tok, "the texture"));
            };
            match word {
                "pigment" => {
                    self.next()?;
                    t.pigment = self.pigment_body(t.pigment)?;
                }
                "finish" => {
                    self.next()?;
                    t.finish = self.finish_body(t.finish)?;
                }
                "normal" => {
                    self.next()?;
                    t.normal = self.normal_body(t.normal.take())?;
                }
                "texture_map" => {
                    self.next()?;
                    let average = t
                        .map
                        .as_ref()
                        .is_some_and(|m| matches!(m.pattern.kind, PatternKind::Average));
                    let mut entries = self.texture_map_body(average)?;
                    let Some(map) = &mut t.map else {
                        return Err(self.err(tok.span, "`texture_map` needs a pattern before it"));
                    };
                    transform_late_entries(&mut entries, &map.transform);
                    map.entries = entries;
                }
                w if PATTERNS.contains(&w) && self.lookup(w).is_none() => {
                    self.texture_pattern(&mut t, &tok, w)?;
                }
                "tiles" => {
                    self.next()?;
                    t.map = Some(Box::new(self.tiles_body()?));
                }
                "uv_mapping" => {
                    self.next()?;
                    uv_mapping = true;
                }
                "texture" if t.map.as_ref().is_some_and(|m| m.entries.is_empty()) => {
                    self.texture_list_entries(&mut t, &tok)?;
                }
                "material_map" => {
                    self.next()?;
                    t.map = Some(Box::new(self.material_map_body()?));
                }
                "image_map" => {
                    return Err(self.unsupported(&tok, word));
                }
                w if t.map.is_some()
                    && self.lookup(w).is_none()
                    && self.pattern_modifier(Modified::Texture(&mut t), w)? => {}
                _ => match self.lookup(word).cloned() {
                    Some(Value::Texture(named)) => {
                        self.next()?;
                        t = *named;
                    }
                    // An element of an array of textures: `texture { T[i][j] }`.
                    Some(Value::Array(_)) => {
                        let (v, span) = self.expr()?;
                        match v {
                            Value::Texture(named) => t = *named,
                            other => {
                                return Err(self.err(
                                    span,
                                    format!("expected a texture, found {}", other.kind_name()),
                                ));
                            }
                        }
                    }
                    _ if UNSUPPORTED_PATTERNS.contains(&word) => {
                        return Err(self.unsupported(&tok, word));
                    }
                    _ => return Err(self.stray_in_block(&tok, "the texture")),
                },
            }
        }
    }
}

impl Evaluator<'_> {
    /// A pattern keyword `w` in a texture: the pattern of a texture map to come (or of a
    /// list of textures); the object pattern's entries come inside its braces.
    fn texture_pattern(
        &mut self,
        t: &mut Texture,
        tok: &super::super::syntax::Token,
        w: &str,
    ) -> R<()> {
        self.next()?;
        let kind = self.pattern_kind(w)?;
        let object = matches!(kind, PatternKind::Object(_));
        t.map = Some(Box::new(TextureMap {
            pattern: self.new_pattern(kind),
            transform: Transform::IDENTITY,
            entries: Vec::new(),
            uv_mapping: false,
        }));
        if object {
            self.texture_list_entries(t, tok)?;
            self.expect(Punct::RBrace, "to close the object pattern")?;
        }
        Ok(())
    }

    /// `object { Obj` (or an object block) of an object pattern, whose entries and closing
    /// brace follow ([`Evaluator::object_pattern_end`]); the object is built for inside
    /// tests here, once.
    fn object_pattern(&mut self) -> R<crate::scene::ObjectPattern> {
        self.expect(Punct::LBrace, "after `object`")?;
        let value = match self.named_object()? {
            Some(o) => o,
            None if super::objects::is_object_keyword(self.peek()?.ident().unwrap_or("")) => {
                self.object()?
            }
            None => {
                let tok = self.peek()?;
                return Err(self.expected("an object for the object pattern", &tok));
            }
        };
        Ok(built_for_tests(value.object))
    }

    /// The closing brace of an object pattern, after its entries.
    fn object_pattern_end(&mut self, kind: &PatternKind) -> R<()> {
        if matches!(kind, PatternKind::Object(_)) {
            self.expect(Punct::RBrace, "to close the object pattern")?;
        }
        Ok(())
    }

    /// `texture { checker texture {A} texture {B} }`: the entries of a list pattern, one
    /// texture per index (the pattern's value), as a texture map with entries at 0, 1, ...
    fn texture_list_entries(
        &mut self,
        t: &mut Texture,
        tok: &super::super::syntax::Token,
    ) -> R<()> {
        let Some(map) = &mut t.map else {
            return Err(self.stray_in_block(tok, "the texture"));
        };
        let Some(n) = map.pattern.kind.list_size() else {
            return Err(self.err(
                tok.span,
                "texture entries follow only checker, hexagon or brick; use a texture_map",
            ));
        };
        let mut entries = Vec::with_capacity(n);
        while entries.len() < n && self.peek()?.is_ident("texture") {
            self.next()?;
            let entry = self.texture_body(self.default_texture.clone())?;
            entries.push((entries.len() as f64, entry));
            self.eat(Punct::Comma)?;
        }
        // Entries left out take the default texture, as POV-Ray's do.
        while entries.len() < n {
            entries.push((entries.len() as f64, self.default_texture.clone()));
        }
        if let Some(map) = &mut t.map {
            transform_late_entries(&mut entries, &map.transform);
            map.entries = entries;
        }
        Ok(())
    }
}

/// An image's `map_type` number: the three POV-Ray types penumbra maps.
pub(super) fn map_type_of(n: f64) -> Option<MapType> {
    match n as i64 {
        0 => Some(MapType::Planar),
        1 => Some(MapType::Spherical),
        2 => Some(MapType::Cylindrical),
        5 => Some(MapType::Torus),
        _ => None,
    }
}

/// Entries read after transforms of their texture get those transforms too: POV-Ray
/// transforms a texture map's entries with the whole texture whatever the order
/// (measured: `texture { gradient y scale 4 texture_map { [0 T] [1 T] } }` with T a
/// `gradient x` repeats T every 4 units, as with the scale after the map).
fn transform_late_entries(entries: &mut [(f64, Texture)], since_pattern: &Transform) {
    if *since_pattern != Transform::IDENTITY {
        for (_, e) in entries {
            e.transform_by(since_pattern);
        }
    }
}

/// An object built on its own, for inside and ray tests (the object pattern, a light's
/// `projected_through`); none gives an empty world.
pub(super) fn built_for_tests(object: Option<crate::scene::Object>) -> crate::scene::ObjectPattern {
    let scene = crate::scene::Scene {
        objects: object.into_iter().collect(),
        ..crate::scene::Scene::default()
    };
    let world = crate::render::prepared::PreparedScene::new(&scene).world;
    crate::scene::ObjectPattern(std::sync::Arc::new(world))
}

/// `texture { uv_mapping ... }`: the texture's pigments (and its texture map's pattern)
/// read the surface's (u, v) from here on.
pub(super) fn mark_uv_mapped(t: &mut Texture) {
    t.pigment.uv_mapping = true;
    if let Some(m) = &mut t.map {
        m.uv_mapping = true;
        for (_, e) in &mut m.entries {
            mark_uv_mapped(e);
        }
    }
}

impl Evaluator<'_> {
    /// Interior items penumbra's appearance model owns (the fade of light inside).
    pub(super) fn interior_fade_item(&mut self, word: &str, interior: &mut Interior) -> R<()> {
        match word {
            "fade_distance" => interior.fade_distance = self.float()?,
            "fade_power" => interior.fade_power = self.float()?,
            _ => interior.fade_colour = self.colour_or_float()?,
        }
        Ok(())
    }

    /// `caustics`, `dispersion` or `dispersion_samples` in an interior, after the keyword.
    pub(super) fn interior_light_item(&mut self, word: &str, interior: &mut Interior) -> R<()> {
        match word {
            "caustics" => interior.caustics = self.float()?,
            "dispersion" => interior.dispersion = self.positive_float("dispersion")?,
            _ => {
                let (v, s) = self.expr()?;
                let n = self.to_float(&v, s)?;
                // POV-Ray refuses fewer than two ("Dispersion samples minimum is 2").
                if n < 2.0 || !n.is_finite() {
                    return Err(self.err(s, "dispersion_samples must be at least 2"));
                }
                interior.dispersion_samples = n.min(f64::from(u16::MAX)) as u32;
            }
        }
        Ok(())
    }

    /// `tiles { texture {A}... tile2 texture {B}... }`: POV-Ray's older form of a checker of
    /// textures; several textures in a group layer as they do on an object.
    fn tiles_body(&mut self) -> R<TextureMap> {
        let open = self.expect(Punct::LBrace, "after `tiles`")?;
        self.enter(open.span)?;
        let r = (|| -> R<TextureMap> {
            let first = self.tile_textures()?;
            let tok = self.next()?;
            if !tok.is_ident("tile2") {
                return Err(self.expected("`tile2` and the second tile's texture", &tok));
            }
            let second = self.tile_textures()?;
            Ok(TextureMap {
                pattern: self.new_pattern(PatternKind::Checker),
                transform: Transform::IDENTITY,
                // Measured: the first tile lies where checker puts its second entry.
                entries: vec![(0.0, second), (1.0, first)],
                uv_mapping: false,
            })
        })();
        self.leave();
        let map = r?;
        self.expect(Punct::RBrace, "to close the tiles")?;
        Ok(map)
    }

    /// One tile's textures: at least one `texture { }`, later ones layered on top.
    fn tile_textures(&mut self) -> R<Texture> {
        let mut group: Option<Texture> = None;
        while self.peek()?.is_ident("texture") {
            self.next()?;
            let top = self.texture_body(self.default_texture.clone())?;
            group = Some(Self::layer_texture(group, top));
        }
        match group {
            Some(t) => Ok(t),
            None => {
                let tok = self.peek()?;
                Err(self.expected("a `texture` for the tile", &tok))
            }
        }
    }

    /// A second `texture` on an object goes on top of the ones before it.
    pub(super) fn layer_texture(below: Option<Texture>, mut top: Texture) -> Texture {
        if let Some(mut b) = below {
            let rest = std::mem::take(&mut b.below);
            top.below.push(b);
            top.below.extend(rest);
        }
        top
    }
}

impl Evaluator<'_> {
    /// `{ png "file" ... }` after `image_map`; the file is found like an include file.
    fn image_map_body(&mut self) -> R<ImageMap> {
        self.image_body("image_map", false).map(|(im, _)| im)
    }

    /// The image file at the start of an image block (`png "file"`), loaded as an image
    /// map with default settings.
    fn image_file(&mut self, data: bool) -> R<(ImageMap, ImageSource)> {
        let tok = self.peek()?;
        match tok.ident() {
            // The decoder reads the file's own header, whichever of the two it is.
            Some("png" | "jpeg") => {
                self.next()?;
            }
            Some(
                w
                @ ("gif" | "tga" | "iff" | "ppm" | "pgm" | "tiff" | "sys" | "hdr" | "exr" | "bmp"),
            ) => {
                let w = w.to_string();
                return Err(self.unsupported(&tok, &format!("{w} images")));
            }
            _ => {}
        }
        let (v, span) = self.expr()?;
        let Value::Str(name) = v else {
            return Err(self.err(span, "expected the image file name as a string"));
        };
        let Some(path) = self.resolve_include(&name) else {
            return Err(self.err(span, format!("cannot find the image \"{name}\"")));
        };
        let working = if data || self.scene.legacy() {
            ImageGamma::Raw
        } else {
            ImageGamma::Working {
                file: None,
                gamma: self.scene.settings.assumed_gamma.unwrap_or(1.0),
            }
        };
        let image = load_png(&path, working).map_err(|e| self.err(span, e))?;
        let source = ImageSource {
            path,
            working,
            span,
        };
        let map = ImageMap {
            image: std::sync::Arc::new(image),
            map_type: MapType::Planar,
            interpolate: crate::scene::Interpolate::Nearest,
            once: false,
            filter_all: 0.0,
            transmit_all: 0.0,
            turbulence: None,
            warps: Vec::new(),
        };
        Ok((map, source))
    }

    /// `gamma g` or `gamma srgb` in an image block: the file's own encoding, which POV-Ray
    /// decodes (measured on grey 128 in a 3.7 scene: 0.2196 = 0.502^2.2 with `gamma 2.2`,
    /// 0.502 with `gamma 1`, 0.2157 with `gamma srgb` as without one). The image is read
    /// again with it; values read as data (`image_pattern`, old scenes) keep theirs.
    fn image_gamma(&mut self, source: &ImageSource, im: &mut ImageMap) -> R<()> {
        self.next()?;
        let file = if self.eat_ident("srgb")? {
            None
        } else {
            let (v, s) = self.expr()?;
            Some(self.to_float(&v, s)?)
        };
        if let ImageGamma::Working { gamma, .. } = source.working {
            let working = ImageGamma::Working { file, gamma };
            let image = load_png(&source.path, working).map_err(|e| self.err(source.span, e))?;
            im.image = std::sync::Arc::new(image);
        }
        Ok(())
    }

    /// After `filter` or `transmit` in an image block: `all v` or `N[,] v`.
    fn palette_edit(&mut self, filter: bool) -> R<PaletteEdit> {
        let entry = if self.eat_ident("all")? {
            None
        } else {
            let at = self.peek()?.span;
            let n = self.float()?;
            self.eat(Punct::Comma)?;
            Some((n, at))
        };
        let value = self.float()?;
        Ok(PaletteEdit {
            filter,
            entry,
            value,
        })
    }

    /// The image block's `filter` and `transmit` items, in the order written. Measured on a
    /// two-entry palette: `N, v` sets entry N, `all v` sets every entry (a later `all`
    /// overrides an entry set before it); an entry past the palette's end, or any entry of
    /// a colour image, is an error. Without entries, `all` adds to every pixel.
    fn apply_palette_edits(
        &mut self,
        source: &ImageSource,
        im: &mut ImageMap,
        edits: &[PaletteEdit],
    ) -> R<()> {
        let Some((_, first)) = edits.iter().find_map(|e| e.entry) else {
            for e in edits {
                *(if e.filter {
                    &mut im.filter_all
                } else {
                    &mut im.transmit_all
                }) = e.value;
            }
            return Ok(());
        };
        let indices = super::material_map::load_indices(&source.path)
            .map_err(|e| self.err(source.span, e))?;
        if indices.palette == 0 {
            return Err(self.err(
                first,
                "filter or transmit of one palette entry needs a palette image",
            ));
        }
        let data = std::sync::Arc::make_mut(&mut im.image);
        for e in edits {
            let target = match e.entry {
                None => None,
                Some((n, span)) if !(0.0..indices.palette as f64).contains(&n) => {
                    return Err(self.err(
                        span,
                        format!(
                            "palette entry {n} is out of range: the palette has {} entries",
                            indices.palette
                        ),
                    ));
                }
                Some((n, _)) => Some(n as u8),
            };
            for (c, &i) in data.pixels.iter_mut().zip(&indices.index) {
                if target.is_none_or(|t| t == i) {
                    *(if e.filter {
                        &mut c.filter
                    } else {
                        &mut c.transmit
                    }) = e.value;
                }
            }
        }
        Ok(())
    }

    /// `{ png "file" ... }` after `image_map`, or (`data`) after `image_pattern`, whose
    /// values POV-Ray reads as they are in the file, without gamma (measured: grey 128
    /// gives 0.502 in a 3.7 scene), and which may say `use_alpha` (the flag returned).
    fn image_body(&mut self, keyword: &str, data: bool) -> R<(ImageMap, bool)> {
        let open = self.expect(Punct::LBrace, &format!("after `{keyword}`"))?;
        self.enter(open.span)?;
        let mut use_alpha = false;
        let r = (|| -> R<ImageMap> {
            let (mut im, source) = self.image_file(data)?;
            let mut edits = Vec::new();
            loop {
                let tok = self.peek()?;
                if tok.is_punct(Punct::RBrace) {
                    self.apply_palette_edits(&source, &mut im, &edits)?;
                    return Ok(im);
                }
                match tok.ident() {
                    Some("map_type") => {
                        self.next()?;
                        let (m, s) = self.expr()?;
                        im.map_type = map_type_of(self.to_float(&m, s)?).ok_or_else(|| {
                            self.unsupported(&tok, "map_type other than 0, 1, 2, 5")
                        })?;
                    }
                    Some("interpolate") => {
                        self.next()?;
                        // 4 weighs the neighbours by inverse squared distance; any other
                        // number that is not 0 reads as 2, bilinear.
                        let n = self.float()?;
                        im.interpolate = match n {
                            0.0 => crate::scene::Interpolate::Nearest,
                            4.0 => crate::scene::Interpolate::InverseSquare,
                            _ => crate::scene::Interpolate::Bilinear,
                        };
                    }
                    Some("once") => {
                        self.next()?;
                        im.once = true;
                    }
                    Some(w @ ("filter" | "transmit")) => {
                        let filter = w == "filter";
                        self.next()?;
                        edits.push(self.palette_edit(filter)?);
                    }
                    Some("gamma") => self.image_gamma(&source, &mut im)?,
                    Some("use_alpha") if data => {
                        self.next()?;
                        use_alpha = true;
                    }
                    Some("use_colour" | "use_color" | "use_index") if data => {
                        self.next()?;
                        use_alpha = false;
                    }
                    _ => return Err(self.stray_in_block(&tok, "the image map")),
                }
            }
        })();
        self.leave();
        let im = r?;
        self.expect(Punct::RBrace, "to close the image map")?;
        Ok((im, use_alpha))
    }
}

/// What a file's values mean in the scene's working colour space. POV-Ray 3.7 decodes an
/// image (PNG without gAMA: sRGB) and re-encodes it with `assumed_gamma`, so a 3.7 scene
/// sees the same linear colour whatever its gamma; older `#version`s take the file's values
/// as working colours unchanged (measured: grey 128 gives 0.2158 in 3.7 scenes, 0.5020 in a
/// 3.6 scene with `assumed_gamma 1`, 0.2195 = 0.502^2.2 with `assumed_gamma 2.2`).
#[derive(Clone, Copy, Debug, PartialEq)]
enum ImageGamma {
    Raw,
    /// `file`: the power the file's values are decoded with (`None`: the sRGB curve);
    /// `gamma`: the working gamma (1 is linear).
    Working {
        file: Option<f64>,
        gamma: f64,
    },
}

/// Where an image block's pixels came from, to read them again with another gamma.
/// One `filter` or `transmit` item of an image block: `all` (no entry) or a palette entry,
/// with where its number was written.
struct PaletteEdit {
    filter: bool,
    entry: Option<(f64, crate::lang::Span)>,
    value: f64,
}

struct ImageSource {
    path: std::path::PathBuf,
    working: ImageGamma,
    span: crate::lang::Span,
}

impl ImageGamma {
    fn convert(self, c: f32) -> f64 {
        let c = c as f64;
        match self {
            ImageGamma::Raw => c,
            ImageGamma::Working { file, gamma: g } => {
                let linear = match file {
                    Some(power) => c.max(0.0).powf(power),
                    None if c <= 0.04045 => c / 12.92,
                    None => ((c + 0.055) / 1.055).powf(2.4),
                };
                if (g - 1.0).abs() > 1e-9 && g > 0.0 {
                    linear.powf(1.0 / g)
                } else {
                    linear
                }
            }
        }
    }
}

/// Reads a PNG into working colours (see ImageGamma); alpha becomes transmit.
fn load_png(path: &std::path::Path, working: ImageGamma) -> Result<ImageData, String> {
    let img = image::open(path).map_err(|e| format!("cannot read \"{}\": {e}", path.display()))?;
    let rgba = img.to_rgba32f();
    let (w, h) = (rgba.width() as usize, rgba.height() as usize);
    let decode = |c: f32| working.convert(c);
    let pixels = rgba
        .pixels()
        .map(|p| Colour {
            rgb: DVec3::new(decode(p[0]), decode(p[1]), decode(p[2])),
            filter: 0.0,
            transmit: 1.0 - p[3] as f64,
        })
        .collect();
    Ok(ImageData {
        width: w,
        height: h,
        pixels,
    })
}

impl Evaluator<'_> {
    /// `#declare M = color_map { ... }`: kept as a gradient pigment with that map, since the
    /// value types have no colour map of their own; `color_map { M }` takes the map back.
    pub(super) fn declared_colour_map(&mut self) -> R<Pigment> {
        let map = self.colour_map_body()?;
        Ok(Pigment {
            kind: PigmentKind::ColourMap {
                pattern: Pattern::new(PatternKind::Gradient(DVec3::X)),
                map,
            },
            transform: Transform::IDENTITY,
            uv_mapping: false,
        })
    }
}

impl Evaluator<'_> {
    /// `#declare T = texture {A} texture {B}`: a layered texture, B on top. Looks ahead
    /// without running directives, since the declaration is not finished.
    pub(super) fn more_layers(&mut self, mut t: Texture) -> R<Texture> {
        while self.raw_peek(0).is_some_and(|tok| tok.is_ident("texture")) {
            self.raw_next();
            let top = self.texture_body(self.default_texture.clone())?;
            t = Self::layer_texture(Some(t), top);
        }
        Ok(t)
    }
}

/// A df3 file: three big-endian 16-bit sizes, then the voxels, 8, 16 or 32 bits each
/// (big-endian; the width follows from the file's length).
fn read_df3(bytes: &[u8]) -> Result<crate::scene::VoxelGrid, String> {
    if bytes.len() < 6 {
        return Err("too short for a df3 header".into());
    }
    let dim = |k: usize| usize::from(u16::from_be_bytes([bytes[2 * k], bytes[2 * k + 1]]));
    let size = [dim(0), dim(1), dim(2)];
    let count = size[0] * size[1] * size[2];
    let body = &bytes[6..];
    if count == 0 || !body.len().is_multiple_of(count) {
        return Err(format!(
            "{} bytes of voxels do not fit a {}x{}x{} grid",
            body.len(),
            size[0],
            size[1],
            size[2]
        ));
    }
    let values = match body.len() / count {
        1 => body.iter().map(|&b| f32::from(b) / 255.0).collect(),
        2 => body
            .chunks_exact(2)
            .map(|c| f32::from(u16::from_be_bytes([c[0], c[1]])) / 65535.0)
            .collect(),
        4 => body
            .chunks_exact(4)
            .map(|c| {
                (f64::from(u32::from_be_bytes([c[0], c[1], c[2], c[3]])) / 4_294_967_295.0) as f32
            })
            .collect(),
        w => return Err(format!("{w} bytes per voxel; df3 has 1, 2 or 4")),
    };
    Ok(crate::scene::VoxelGrid {
        size,
        values,
        trilinear: false,
    })
}

/// `exponent` comes after the pattern's default map was chosen: mandel's own map belongs to
/// exponent 2 only (measured: `mandel 50 exponent 3` renders as with black to white, and
/// `exponent 3 exponent 2` with mandel's map), so mandel's map is taken back at the end of
/// the pigment when the exponent is not 2 (a map written out equal to it is as unlikely as
/// it would be harmless).
fn settle_default_map(p: &mut Pigment) {
    if let PigmentKind::ColourMap { pattern, map } = &mut p.kind
        && matches!(pattern.kind, PatternKind::Fractal(_))
    {
        let mandel = default_colour_map(&PatternKind::Fractal(Fractal::new(
            FractalFormula::Power(2),
            None,
            1,
        )));
        if *map == mandel {
            *map = default_colour_map(&pattern.kind);
        }
    }
}

/// The colour map of a pattern written without one. POV-Ray gives wood its own: light
/// brown below 0.6, dark brown above, a hard step (measured: the default and this map
/// written out render identically, colours to the half-float precision of the probe;
/// portfolio/p_woods.pov); the others measured so far get black to white (agate, bozo and
/// marble have maps of their own too, not yet reproduced).
fn default_colour_map(kind: &PatternKind) -> Vec<(f64, Colour)> {
    match kind {
        PatternKind::Wood => {
            let light = Colour::rgb(0.666, 0.312, 0.2);
            let dark = Colour::rgb(0.4, 0.1333, 0.066);
            vec![(0.0, light), (0.6, light), (0.6, dark), (1.0, dark)]
        }
        // Measured on `mandel 50 exterior 2, 0.37` (continuous values) against the exact
        // value at 40000 points: black up to 0.001, then cyan, yellow at 0.012, magenta at
        // 0.015 and cyan from 0.1 on, linear between (residual 8e-6). julia and magnet
        // keep black to white (measured: identical to that map written out).
        PatternKind::Fractal(Fractal {
            formula: FractalFormula::Power(2),
            julia: None,
            ..
        }) => {
            let cyan = Colour::rgb(0.0, 1.0, 1.0);
            vec![
                (0.001, Colour::BLACK),
                (0.001, cyan),
                (0.012, Colour::rgb(1.0, 1.0, 0.0)),
                (0.015, Colour::rgb(1.0, 0.0, 1.0)),
                (0.1, cyan),
            ]
        }
        _ => vec![(0.0, Colour::BLACK), (1.0, Colour::rgb(1.0, 1.0, 1.0))],
    }
}
