//! `material_map { png "file" [map_type n] [once] [interpolate n] texture {...} ... }`: an
//! image whose pixels number the textures (read as POV-Ray reads them: a palette image's
//! index, an 8-bit colour image's red byte; a grey image is refused, its conversion not yet
//! measured; which texture a number picks is in `appearance::pigment::material_index`). The textures become a list pattern's entries, so the texture machinery
//! (transforms, normals, finishes) treats them as it treats `checker texture {...}`.

use std::sync::Arc;

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::Punct;
use super::Evaluator;
use super::value::Value;
use crate::geometry::Transform;
use crate::scene::{IndexImage, MapType, MaterialImage, PatternKind, TextureMap};

type R<T> = Result<T, Diagnostic>;

impl Evaluator<'_> {
    /// After `material_map`: the braced body, as a texture map.
    pub(super) fn material_map_body(&mut self) -> R<TextureMap> {
        let open = self.expect(Punct::LBrace, "after `material_map`")?;
        self.enter(open.span)?;
        let r = self.material_map_items(open.span);
        self.leave();
        let map = r?;
        self.expect(Punct::RBrace, "to close the material_map")?;
        Ok(map)
    }

    fn material_map_items(&mut self, at: Span) -> R<TextureMap> {
        let tok = self.peek()?;
        match tok.ident() {
            Some("png") => {
                self.next()?;
            }
            Some(w @ ("gif" | "tga" | "iff" | "ppm" | "pgm" | "jpeg" | "tiff" | "sys")) => {
                let w = w.to_string();
                return Err(self.unsupported(&tok, &format!("{w} images in a material_map")));
            }
            _ => {}
        }
        let (v, span) = self.expr()?;
        let Value::Str(name) = v else {
            return Err(self.err(
                span,
                "expected the material_map's image file name as a string",
            ));
        };
        let Some(path) = self.resolve_include(&name) else {
            return Err(self.err(
                span,
                format!("cannot find the material_map image \"{name}\""),
            ));
        };
        let image = load_indices(&path).map_err(|e| self.err(span, e))?;
        let mut map_type = MapType::Planar;
        let mut once = false;
        let mut entries = Vec::new();
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            match tok.ident() {
                Some("map_type") => {
                    self.next()?;
                    map_type = match self.float()? as i64 {
                        0 => MapType::Planar,
                        1 => MapType::Spherical,
                        2 => MapType::Cylindrical,
                        _ => return Err(self.unsupported(&tok, "map_type other than 0, 1, 2")),
                    };
                }
                Some("once") => {
                    self.next()?;
                    once = true;
                }
                // Numbers do not blend: POV-Ray's interpolation has nothing to mix here.
                Some("interpolate") => {
                    self.next()?;
                    self.float()?;
                }
                Some("texture") => {
                    self.next()?;
                    let t = self.texture_body(self.default_texture.clone())?;
                    entries.push((entries.len() as f64, t));
                }
                _ => return Err(self.stray_in_block(&tok, "the material_map")),
            }
        }
        if entries.is_empty() {
            return Err(self.err(at, "a material_map needs at least one texture"));
        }
        let kind = PatternKind::MaterialMap(MaterialImage {
            image: Arc::new(image),
            map_type,
            once,
            count: entries.len(),
        });
        Ok(TextureMap {
            pattern: self.new_pattern(kind),
            transform: Transform::IDENTITY,
            entries,
            uv_mapping: false,
        })
    }
}

/// A PNG's pixels as numbers: palette indices as stored, or the red byte of 8-bit colour.
fn load_indices(path: &std::path::Path) -> Result<IndexImage, String> {
    let cannot = |e: String| format!("cannot read \"{}\": {e}", path.display());
    let file = std::fs::File::open(path).map_err(|e| cannot(e.to_string()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| cannot(e.to_string()))?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| cannot("too large".into()))?;
    let mut buf = vec![0u8; size];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| cannot(e.to_string()))?;
    let (w, h) = (info.width as usize, info.height as usize);
    let bits = info.bit_depth as usize;
    let channels = info.color_type.samples();
    let palette = match (info.color_type, bits) {
        (png::ColorType::Indexed, _) => true,
        (png::ColorType::Rgb | png::ColorType::Rgba, 8) => false,
        _ => {
            return Err(cannot(
                "a material_map reads palette or 8-bit colour PNGs only".into(),
            ));
        }
    };
    let index_at = |row: &[u8], x: usize| -> u8 {
        if !palette {
            return row[x * channels];
        }
        let per = 8 / bits;
        let shift = 8 - bits * (x % per + 1);
        ((u16::from(row[x / per]) >> shift) & ((1u16 << bits) - 1)) as u8
    };
    let mut index = Vec::with_capacity(w * h);
    for y in 0..h {
        let row = &buf[y * info.line_size..(y + 1) * info.line_size];
        index.extend((0..w).map(|x| index_at(row, x)));
    }
    Ok(IndexImage {
        width: w,
        height: h,
        index,
    })
}
