//! `material_map { png "file" [map_type n] [once] [interpolate n] texture {...} ... }`: an
//! image whose pixels number the textures (read as POV-Ray reads them: a palette image's
//! index, an 8-bit colour image's red byte, an 8-bit grey image's value cut as a bump map's
//! height is; which texture a number picks is in `appearance::pigment::material_index`).
//! The textures become a list pattern's entries, so the texture machinery (transforms,
//! normals, finishes) treats them as it treats `checker texture {...}`.

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
    /// After `bump_map` in a normal: `{ [png] "file" [once] [map_type n] [interpolate n]
    /// [use_color | use_index] [bump_size s] }`: the image's heights, mapped as an
    /// image_map's colours are (bump_size 1 unless given).
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
        let (mut once, mut use_index, mut bilinear, mut size) = (false, false, false, 1.0);
        let mut map_type = MapType::Planar;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            match tok.ident() {
                Some("once") => once = self.next().map(|_| true)?,
                Some("use_index") => use_index = self.next().map(|_| true)?,
                Some("use_color" | "use_colour") => use_index = self.next().map(|_| false)?,
                Some("bump_size") => {
                    self.next()?;
                    size = self.float()?;
                }
                // 2 (bilinear) and 4 (normalised distance) both blend neighbours, as in
                // image maps.
                Some("interpolate") => {
                    self.next()?;
                    bilinear = self.float()? != 0.0;
                }
                Some("map_type") => {
                    self.next()?;
                    map_type = self.map_type_number(&tok)?;
                }
                _ => return Err(self.stray_in_block(&tok, "the bump_map")),
            }
        }
        let image = load_heights(&path, use_index).map_err(|e| self.err(span, e))?;
        let kind = PatternKind::BumpMap(BumpMap {
            image: Arc::new(image),
            map_type,
            once,
            bilinear,
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
            .ok_or_else(|| self.unsupported(tok, "map_type other than 0, 1, 2, 5"))
    }
}

/// A bump map's heights from the stored values: a colour's brightness, or with `use_index`
/// the palette index itself. Measured with POV-Ray 3.7 (normals recovered from three renders
/// of ramps on a plane):
/// - a palette ramp of indices 0 to 15 with grey entries, `use_index bump_size 0.004`, tilts
///   as the grey ramp 0 to 15 / 255 with bump_size 1.02, to 1e-4 in every pixel;
/// - the steps of an 8-bit grey ramp 0 to 255 are 0, 1 or 2 / 255, not 1: the brightness
///   0.297 r + 0.589 g + 0.114 b is summed in single precision and cut down to a whole
///   number of 1 / 255 (`quantised_brightness` fits all 254 pixels, the exact value 71);
/// - a 16-bit ramp is smooth (steps of 37 / 65535 measured as 0.144 / 255).
fn load_heights(path: &std::path::Path, use_index: bool) -> Result<HeightImage, String> {
    if use_index {
        let im = load_indices(path)?;
        return Ok(HeightImage {
            width: im.width,
            height: im.height,
            heights: im.index.iter().map(|&i| f32::from(i)).collect(),
        });
    }
    let img = image::open(path).map_err(|e| format!("cannot read \"{}\": {e}", path.display()))?;
    let (width, height) = (img.width() as usize, img.height() as usize);
    let sixteen = matches!(
        img,
        image::DynamicImage::ImageLuma16(_)
            | image::DynamicImage::ImageLumaA16(_)
            | image::DynamicImage::ImageRgb16(_)
            | image::DynamicImage::ImageRgba16(_)
    );
    let heights = if sixteen {
        let max = f32::from(u16::MAX);
        let rgb = img.to_rgb16();
        rgb.pixels()
            .map(|p| quantised_brightness(p.0.map(|c| f32::from(c) / max), max))
            .collect()
    } else {
        let max = f32::from(u8::MAX);
        let rgb = img.to_rgb8();
        rgb.pixels()
            .map(|p| quantised_brightness(p.0.map(|c| f32::from(c) / max), max))
            .collect()
    };
    Ok(HeightImage {
        width,
        height,
        heights,
    })
}

/// A colour's brightness as POV-Ray takes a bump map's height from it: in single precision,
/// cut down to a whole number of steps of the file's depth (`max` 255 or 65535).
fn quantised_brightness([r, g, b]: [f32; 3], max: f32) -> f32 {
    let y = 0.297_f32 * r + 0.589_f32 * g + 0.114_f32 * b;
    (y * max).floor() / max
}

/// How a PNG's pixels become numbers.
#[derive(Clone, Copy)]
enum NumberKind {
    /// The palette index as stored.
    Palette,
    /// An 8-bit colour image's red byte (measured).
    Red,
    /// An 8-bit grey image's value cut as a bump map's height is (measured with 3
    /// textures over the greys 0 to 11 and 0 to 220 by 20: 0 1 2 2 1 1 2 1 2 0 0 2 and 0 1 0
    /// 0 1 0 0 1 0 2 1 0, which the grey itself, 0 1 2 2 1 2 0 1 2 ..., misses).
    Grey,
    /// A 16-bit image's first sample (grey, or red) divided by 257, whole: measured with 16
    /// textures on the values 257 k - 1, 257 k and 257 k + 1 for k up to 15 (513 picks 1,
    /// 514 picks 2; the green and blue samples have no effect).
    Wide,
}

/// A PNG's pixels as numbers: palette indices as stored, the red byte of 8-bit colour, an
/// 8-bit grey's cut brightness, or a 16-bit image's first sample over 257.
pub(super) fn load_indices(path: &std::path::Path) -> Result<IndexImage, String> {
    let cannot = |e: String| format!("cannot read \"{}\": {e}", path.display());
    let file = std::fs::File::open(path).map_err(|e| cannot(e.to_string()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| cannot(e.to_string()))?;
    let entries = reader.info().palette.as_ref().map_or(0, |p| p.len() / 3);
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
    let kind = match (info.color_type, bits) {
        (png::ColorType::Indexed, _) => NumberKind::Palette,
        (png::ColorType::Rgb | png::ColorType::Rgba, 8) => NumberKind::Red,
        (png::ColorType::Grayscale | png::ColorType::GrayscaleAlpha, 8) => NumberKind::Grey,
        (_, 16) => NumberKind::Wide,
        _ => {
            return Err(cannot(
                "numbers (material_map, use_index) are read from palette, grey or colour PNGs \
                 of 8 or 16 bits only"
                    .into(),
            ));
        }
    };
    let index_at = |row: &[u8], x: usize| -> u8 {
        match kind {
            NumberKind::Red => row[x * channels],
            NumberKind::Wide => {
                let at = 2 * x * channels;
                (u16::from_be_bytes([row[at], row[at + 1]]) / 257) as u8
            }
            NumberKind::Grey => {
                let g = f32::from(row[x * channels]) / 255.0;
                (quantised_brightness([g; 3], 255.0) * 255.0) as u8
            }
            NumberKind::Palette => {
                let per = 8 / bits;
                let shift = 8 - bits * (x % per + 1);
                ((u16::from(row[x / per]) >> shift) & ((1u16 << bits) - 1)) as u8
            }
        }
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
        palette: entries,
    })
}

#[cfg(test)]
mod tests {
    use super::quantised_brightness;

    /// The heights POV-Ray 3.7 gives the grey values 0 to 15 of an 8-bit bump map, in
    /// steps of 1 / 255, recovered from renders of a ramp through three lights.
    const MEASURED: [u8; 16] = [0, 1, 2, 2, 4, 4, 5, 7, 8, 9, 9, 11, 11, 13, 14, 15];

    #[test]
    fn grey_heights_are_cut_as_povray_cuts_them() {
        for (k, &expected) in MEASURED.iter().enumerate() {
            let g = k as f32 / 255.0;
            let h = quantised_brightness([g; 3], 255.0) * 255.0;
            assert_eq!(h, f32::from(expected), "grey {k}");
        }
    }

    /// POV-Ray 3.7's textures for the greys 0 to 11 of an 8-bit material_map with three
    /// textures (read from its render).
    #[test]
    fn grey_numbers_pick_textures_as_povray_does() {
        let dir = crate::study::TempDir::new("grey-material").unwrap();
        let path = dir.path().join("g.png");
        image::GrayImage::from_fn(12, 1, |x, _| image::Luma([x as u8]))
            .save(&path)
            .unwrap();
        let numbers = super::load_indices(&path).unwrap().index;
        let picked: Vec<usize> = numbers
            .iter()
            .map(|&n| match usize::from(n) {
                n if n < 3 => n,
                3 => 2,
                n => n % 3,
            })
            .collect();
        assert_eq!(picked, [0, 1, 2, 2, 1, 1, 2, 1, 2, 0, 0, 2]);
    }

    /// POV-Ray 3.7's textures (of 16) for the 16-bit greys 257 k - 1, 257 k, 257 k + 1,
    /// k = 0 to 15, and the same values in a colour image's red sample.
    #[test]
    fn sixteen_bit_numbers_pick_textures_as_povray_does() {
        let values: Vec<u16> = (0..16u16)
            .flat_map(|k| [(257 * k).saturating_sub(1), 257 * k, 257 * k + 1])
            .collect();
        let measured: Vec<u8> = vec![
            0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 5, 5, 5, 6, 6, 6, 7, 7, 7, 8, 8, 8, 9,
            9, 9, 10, 10, 10, 11, 11, 11, 12, 12, 12, 13, 13, 13, 14, 14, 14, 15, 15,
        ];
        let dir = crate::study::TempDir::new("wide-material").unwrap();
        let grey = dir.path().join("g.png");
        image::ImageBuffer::<image::Luma<u16>, _>::from_fn(48, 1, |x, _| {
            image::Luma([values[x as usize]])
        })
        .save(&grey)
        .unwrap();
        let red = dir.path().join("r.png");
        image::ImageBuffer::<image::Rgb<u16>, _>::from_fn(48, 1, |x, _| {
            image::Rgb([values[x as usize], 9999, 40000])
        })
        .save(&red)
        .unwrap();
        for path in [grey, red] {
            assert_eq!(super::load_indices(&path).unwrap().index, measured);
        }
    }

    #[test]
    fn sixteen_bit_heights_keep_their_depth() {
        let g = 1037.0 / 65535.0;
        let h = quantised_brightness([g; 3], 65535.0) * 65535.0;
        assert!((1036.0..=1037.0).contains(&h), "{h}");
    }
}
