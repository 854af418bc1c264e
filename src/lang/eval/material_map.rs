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
use crate::scene::{
    BumpMap, HeightImage, IndexImage, MapType, MaterialImage, Normal, PatternKind, TextureMap,
};

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

    /// `[png] "file"` at the start of a material_map or bump_map: the file found through
    /// the include path, and where its name was written.
    fn png_file(&mut self, what: &str) -> R<(std::path::PathBuf, Span)> {
        let tok = self.peek()?;
        match tok.ident() {
            Some("png") => {
                self.next()?;
            }
            Some(w @ ("gif" | "tga" | "iff" | "ppm" | "pgm" | "jpeg" | "tiff" | "sys")) => {
                let w = w.to_string();
                return Err(self.unsupported(&tok, &format!("{w} images in a {what}")));
            }
            _ => {}
        }
        let (v, span) = self.expr()?;
        let Value::Str(name) = v else {
            return Err(self.err(
                span,
                format!("expected the {what}'s image file name as a string"),
            ));
        };
        match self.resolve_include(&name) {
            Some(path) => Ok((path, span)),
            None => Err(self.err(span, format!("cannot find the {what} image \"{name}\""))),
        }
    }

    fn material_map_items(&mut self, at: Span) -> R<TextureMap> {
        let (path, span) = self.png_file("material_map")?;
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
                    map_type = self.map_type_number(&tok)?;
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

impl Evaluator<'_> {
    /// After `bump_map` in a normal: `{ [png] "file" [once] [map_type 0] [interpolate 0]
    /// [use_color] [bump_size s] }`, the x-y plane's heights (bump_size 1 unless given).
    /// Other map types, interpolation and use_index are refused: not yet measured.
    pub(super) fn bump_map_body(&mut self) -> R<Normal> {
        let open = self.expect(Punct::LBrace, "after `bump_map`")?;
        self.enter(open.span)?;
        let r = self.bump_map_items();
        self.leave();
        let n = r?;
        self.expect(Punct::RBrace, "to close the bump_map")?;
        Ok(n)
    }

    fn bump_map_items(&mut self) -> R<Normal> {
        let (path, span) = self.png_file("bump_map")?;
        let (mut once, mut use_index, mut size) = (false, false, 1.0);
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            match tok.ident() {
                Some("once") => once = self.next().map(|_| true)?,
                // Heights from palette indices do not match POV-Ray's yet (index / 255
                // tilts far more than its render): refused until measured.
                Some("use_index") => {
                    return Err(self.unsupported(&tok, "use_index in a bump_map"));
                }
                Some("use_color" | "use_colour") => use_index = self.next().map(|_| false)?,
                Some("bump_size") => {
                    self.next()?;
                    size = self.float()?;
                }
                Some(w @ ("map_type" | "interpolate")) => {
                    let w = w.to_string();
                    self.next()?;
                    if self.float()? != 0.0 {
                        return Err(self.unsupported(&tok, &format!("{w} in a bump_map")));
                    }
                }
                _ => return Err(self.stray_in_block(&tok, "the bump_map")),
            }
        }
        let image = load_heights(&path, use_index).map_err(|e| self.err(span, e))?;
        let kind = PatternKind::BumpMap(BumpMap {
            image: Arc::new(image),
            once,
        });
        let mut normal = Normal::new(self.new_pattern(kind));
        normal.amount = size;
        Ok(normal)
    }
}

impl Evaluator<'_> {
    /// `map_type n` after the keyword `tok`.
    fn map_type_number(&mut self, tok: &super::super::syntax::Token) -> R<MapType> {
        let n = self.float()?;
        super::texture::map_type_of(n)
            .ok_or_else(|| self.unsupported(tok, "map_type other than 0, 1, 2"))
    }
}

/// A bump map's heights (`use_index`: palette indices / 255, not yet reachable), else grey / max or a
/// colour's brightness (0.297 r + 0.589 g + 0.114 b), from the stored values.
fn load_heights(path: &std::path::Path, use_index: bool) -> Result<HeightImage, String> {
    if use_index {
        let im = load_indices(path)?;
        return Ok(HeightImage {
            width: im.width,
            height: im.height,
            heights: im.index.iter().map(|&i| f32::from(i) / 255.0).collect(),
        });
    }
    let img = image::open(path).map_err(|e| format!("cannot read \"{}\": {e}", path.display()))?;
    let (width, height) = (img.width() as usize, img.height() as usize);
    let heights = match img {
        image::DynamicImage::ImageLuma8(g) => g.pixels().map(|p| f32::from(p[0]) / 255.0).collect(),
        image::DynamicImage::ImageLuma16(g) => {
            g.pixels().map(|p| f32::from(p[0]) / 65535.0).collect()
        }
        other => other
            .to_rgb8()
            .pixels()
            .map(|p| {
                (0.297 * f32::from(p[0]) + 0.589 * f32::from(p[1]) + 0.114 * f32::from(p[2]))
                    / 255.0
            })
            .collect(),
    };
    Ok(HeightImage {
        width,
        height,
        heights,
    })
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
