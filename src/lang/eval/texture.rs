//! `pigment`, `finish` and `texture` blocks. Each starts from a base (the object's current
//! one, or the default) because POV-Ray modifies in place: `pigment { scale 2 }` on an
//! object scales the pigment it already has, and a declared texture is copied, then changed.

use glam::DVec3;

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, TokenKind};
use super::Evaluator;
use super::value::{Value, colour_of};
use crate::scene::{Colour, Finish, Pattern, Pigment, PigmentKind, Reflection, Texture};

type R<T> = Result<T, Diagnostic>;

/// Pattern keywords POV-Ray has that penumbra does not model yet.
const UNSUPPORTED_PATTERNS: &[&str] = &[
    "agate",
    "aoi",
    "average",
    "boxed",
    "bozo",
    "brick",
    "bumps",
    "cells",
    "crackle",
    "cylindrical",
    "density_file",
    "dents",
    "facets",
    "function",
    "gradient",
    "granite",
    "hexagon",
    "image_map",
    "image_pattern",
    "julia",
    "leopard",
    "magnet",
    "mandel",
    "marble",
    "onion",
    "pavement",
    "pigment_pattern",
    "planar",
    "quilted",
    "radial",
    "ripples",
    "slope",
    "spherical",
    "spiral1",
    "spiral2",
    "spotted",
    "square",
    "tiling",
    "triangular",
    "waves",
    "wood",
    "wrinkles",
    "color_map",
    "colour_map",
    "pigment_map",
    "turbulence",
    "warp",
    "frequency",
    "phase",
    "octaves",
    "omega",
    "lambda",
    "ramp_wave",
    "sine_wave",
    "triangle_wave",
    "scallop_wave",
    "cubic_wave",
    "poly_wave",
    "uv_mapping",
    "object",
];

impl Evaluator<'_> {
    /// `{ ... }` after `pigment`.
    pub(super) fn pigment_body(&mut self, base: Pigment) -> R<Pigment> {
        let open = self.expect(Punct::LBrace, "after `pigment`")?;
        self.enter(open.span)?;
        let r = self.pigment_items(base);
        self.leave();
        let p = r?;
        self.expect(Punct::RBrace, "to close the pigment")?;
        Ok(p)
    }

    fn pigment_items(&mut self, mut p: Pigment) -> R<Pigment> {
        let mut first = true;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                return Ok(p);
            }
            if let Some(t) = self.transform_modifier()? {
                p.transform_by(&t);
                first = false;
                continue;
            }
            let word = tok.ident().map(str::to_string);
            match word.as_deref() {
                Some("checker") => {
                    self.next()?;
                    let mut entries = Vec::new();
                    while entries.len() < 2 {
                        match self.list_entry()? {
                            Some(e) => entries.push(e),
                            None => break,
                        }
                        self.eat(Punct::Comma)?;
                    }
                    // POV-Ray's defaults for a checker without entries: blue, then green.
                    let defaults = [Colour::rgb(0.0, 0.0, 1.0), Colour::rgb(0.0, 1.0, 0.0)];
                    for d in defaults.iter().skip(entries.len()) {
                        entries.push(Pigment::solid(*d));
                    }
                    p = Pigment {
                        kind: PigmentKind::List {
                            pattern: Pattern::Checker,
                            entries,
                        },
                        transform: crate::scene::Transform::IDENTITY,
                    };
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
                _ if first || self.starts_colour(&tok)? => {
                    let (c, _) = self.colour()?;
                    p = Pigment::solid(colour_of(c));
                }
                _ => return Err(self.stray_in_block(&tok, "the pigment")),
            }
            first = false;
        }
    }

    /// One entry of a pattern list: `pigment {...}` or a colour; `None` when neither follows.
    fn list_entry(&mut self) -> R<Option<Pigment>> {
        let tok = self.peek()?;
        if tok.is_ident("pigment") {
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
        // `albedo` forms depend on brilliance, phong_size and roughness, which may come
        // later in the block, so they are resolved at the end.
        let mut diffuse_albedo = None;
        let mut phong_albedo = None;
        let mut specular_albedo = None;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            let Some(word) = tok.ident().map(str::to_string) else {
                return Err(self.stray_in_block(&tok, "the finish"));
            };
            if let Some(Value::Finish(named)) = self.lookup(&word).cloned() {
                self.next()?;
                f = *named;
                continue;
            }
            self.next()?;
            match word.as_str() {
                "ambient" => f.ambient = self.colour_or_float()?,
                "emission" => f.emission = self.colour_or_float()?,
                "diffuse" => {
                    let albedo = self.eat_ident("albedo")?;
                    let d = self.float()?;
                    if albedo {
                        diffuse_albedo = Some(d);
                    } else {
                        diffuse_albedo = None;
                        f.diffuse = d;
                    }
                    if self.peek()?.is_punct(Punct::Comma) {
                        let comma = self.next()?;
                        return Err(self.err(
                            comma.span,
                            "unsupported: a backside `diffuse` value is not supported yet",
                        ));
                    }
                }
                "brilliance" => f.brilliance = self.float()?,
                "phong" => {
                    let albedo = self.eat_ident("albedo")?;
                    let v = self.float()?;
                    if albedo {
                        phong_albedo = Some(v);
                    } else {
                        phong_albedo = None;
                        f.phong = v;
                    }
                }
                "phong_size" => f.phong_size = self.float()?,
                "specular" => {
                    let albedo = self.eat_ident("albedo")?;
                    let v = self.float()?;
                    if albedo {
                        specular_albedo = Some(v);
                    } else {
                        specular_albedo = None;
                        f.specular = v;
                    }
                }
                "roughness" => {
                    let (v, s) = self.expr()?;
                    let r = self.to_float(&v, s)?;
                    if r <= 0.0 {
                        return Err(self.err(s, "roughness must be greater than zero"));
                    }
                    f.roughness = r;
                }
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
                    let (v, s) = self.expr()?;
                    let e = self.to_float(&v, s)?;
                    if e <= 0.0 {
                        return Err(self.err(s, "reflection_exponent must be greater than zero"));
                    }
                    f.reflection.exponent = e;
                }
                "conserve_energy" => f.conserve_energy = self.optional_bool()?,
                "crand" | "irid" | "ior" | "subsurface" | "caustics" | "fade_distance"
                | "fade_power" | "refraction" | "fresnel" => {
                    return Err(self.unsupported(&tok, &word));
                }
                _ => return Err(self.stray_in_block(&tok, "the finish")),
            }
        }
        if let Some(k) = diffuse_albedo {
            f.diffuse = k * (f.brilliance + 1.0) / 2.0;
        }
        if let Some(p) = phong_albedo {
            f.phong = p * (f.phong_size + 1.0) / 2.0;
        }
        if let Some(s) = specular_albedo {
            let e = 1.0 / f.roughness;
            f.specular = s * (e + 2.0) / (4.0 * (2.0 - 2f64.powf(-e / 2.0)));
        }
        Ok(f)
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
            if self.eat(Punct::Comma)? {
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
        let r = self.texture_items(base);
        self.leave();
        let t = r?;
        self.expect(Punct::RBrace, "to close the texture")?;
        Ok(t)
    }

    fn texture_items(&mut self, mut t: Texture) -> R<Texture> {
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                return Ok(t);
            }
            if let Some(tr) = self.transform_modifier()? {
                t.transform_by(&tr);
                continue;
            }
            let Some(word) = tok.ident().map(str::to_string) else {
                return Err(self.stray_in_block(&tok, "the texture"));
            };
            match word.as_str() {
                "pigment" => {
                    self.next()?;
                    t.pigment = self.pigment_body(t.pigment)?;
                }
                "finish" => {
                    self.next()?;
                    t.finish = self.finish_body(t.finish)?;
                }
                "normal" | "material_map" | "texture_map" | "image_map" | "uv_mapping" => {
                    return Err(self.unsupported(&tok, &word));
                }
                _ => match self.lookup(&word).cloned() {
                    Some(Value::Texture(named)) => {
                        self.next()?;
                        t = *named;
                    }
                    _ if UNSUPPORTED_PATTERNS.contains(&word.as_str()) => {
                        return Err(self.unsupported(&tok, &word));
                    }
                    _ => return Err(self.stray_in_block(&tok, "the texture")),
                },
            }
        }
    }
}
