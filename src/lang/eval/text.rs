//! `text { ttf "font.ttf" "string" thickness, offset }`: a union of glyph prisms, one per
//! character with an outline, each stood up so its face is at z = 0 and its back at
//! z = thickness (see `scene::text` for where the glyphs go).

use glam::{DAffine3, DMat3, DVec2, DVec3};

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::{ObjectValue, Value};
use crate::scene::text::Font;
use crate::scene::{Glyph, Object, Shape, Transform};

type R<T> = Result<T, Diagnostic>;

impl Evaluator<'_> {
    /// The text object's items up to its modifiers.
    pub(super) fn text_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let tok = self.next()?;
        let (font_name, font_span) = match tok.ident() {
            Some("ttf") => self.string_item("the font file's name")?,
            Some("internal") => self.internal_font()?,
            _ => return Err(self.expected("`ttf` and the font file's name", &tok)),
        };
        self.eat(Punct::Comma)?;
        let (text, _) = self.string_item("the text as a string")?;
        self.eat(Punct::Comma)?;
        let thickness = self.float()?;
        self.eat(Punct::Comma)?;
        let (v, s) = self.expr()?;
        let offset = self.to_vec3(&v, s)?;
        let (path, mut font) = self.font(&font_name, font_span)?;
        let glyphs = font.layout(&text, DVec2::new(offset.x, offset.y));
        self.fonts.insert(path, font);
        self.count_objects(glyphs.len() as u64, super::budget::OBJECT_BYTES, kw.span)?;
        // Prism space (u, h, v) to text space: u is x, -v is y, the sweep h is z.
        let stand_up = DMat3::from_cols(DVec3::X, DVec3::Z, -DVec3::Y);
        let children = glyphs
            .into_iter()
            .map(|g| {
                let mut o = Object::new(Shape::Glyph(Glyph {
                    segments: g.segments,
                    depth: thickness,
                }));
                let place = DAffine3::from_mat3_translation(stand_up, g.at.extend(0.0));
                if let Some(t) = Transform::from_affine(place) {
                    o.transform_by(&t);
                }
                o
            })
            .collect();
        Ok(ObjectValue {
            object: Some(Object::new(Shape::Union(children))),
            lights: Vec::new(),
        })
    }

    /// `internal n`: POV-Ray's built-in fonts are the four it installs beside its include
    /// files, found the same way here (measured: each renders a text pixel for pixel as
    /// the file does; 0 and numbers past 3 are povlogo.ttf).
    fn internal_font(&mut self) -> R<(std::rc::Rc<str>, Span)> {
        let (v, span) = self.expr()?;
        let n = self.to_float(&v, span)?;
        let name = match n as i64 {
            1 => "timrom.ttf",
            2 => "cyrvetic.ttf",
            3 => "crystal.ttf",
            _ => "povlogo.ttf",
        };
        Ok((name.into(), span))
    }

    fn string_item(&mut self, what: &str) -> R<(std::rc::Rc<str>, Span)> {
        let (v, span) = self.expr()?;
        match v {
            Value::Str(s) => Ok((s, span)),
            other => Err(self.err(
                span,
                format!("expected {what}, found {}", other.kind_name()),
            )),
        }
    }

    /// The font and its path, taken from the cache (the caller puts it back) or read.
    /// Found like an include file, then with `.ttf` added, as POV-Ray does
    /// (`ttf "cyrvetic"`).
    fn font(&mut self, name: &str, span: Span) -> R<(std::path::PathBuf, Font)> {
        let path = self
            .resolve_include(name)
            .or_else(|| self.resolve_include(&format!("{name}.ttf")));
        let Some(path) = path else {
            return Err(self.err(span, format!("cannot find the font \"{name}\"")));
        };
        if let Some(font) = self.fonts.remove(&path) {
            return Ok((path, font));
        }
        let bytes = std::fs::read(&path)
            .map_err(|e| self.err(span, format!("cannot read the font \"{name}\": {e}")))?;
        let font = Font::new(bytes).map_err(|e| self.err(span, format!("\"{name}\" {e}")))?;
        Ok((path, font))
    }
}
