//! `height_field { [png | pgm | ppm] "file" [smooth] [water_level w] [hierarchy b] }`: the
//! heights read from an image. How POV-Ray 3.7 turns pixels into heights (measured with
//! flat height fields of one colour, seen from above through a `gradient y` pigment and
//! written as 16-bit files without gamma):
//! - grey and grey+alpha: v / 255 (8-bit), v / 65535 (16-bit);
//! - palette: the index as the high byte, index * 256 / 65535;
//! - 8-bit colour: red as the high byte and green as the low one, (256 r + g) / 65535;
//! - 16-bit colour: the grey 0.297 r + 0.589 g + 0.114 b, over 65535.
//!
//! The image's top row lies at z = 1 and its left column at x = 0 (measured).

use std::path::Path;

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::{Punct, Token, TokenKind};
use super::Evaluator;
use super::value::{ObjectValue, Value};
use crate::scene::{HeightField, Object, Shape};

type R<T> = Result<T, Diagnostic>;

/// Pixels as heights, row 0 at the top of the image.
struct Heights {
    width: usize,
    height: usize,
    values: Vec<f32>,
}

const IMAGE_TYPES: &[&str] = &[
    "png", "pgm", "ppm", "tga", "gif", "iff", "jpeg", "tiff", "sys", "exr", "hdr", "bmp", "pot",
];

impl Evaluator<'_> {
    /// The height field's own items, up to its object modifiers; `None` when
    /// `--skip-unsupported` leaves it out.
    pub(super) fn height_field_items(&mut self, kw: &Token) -> R<Option<ObjectValue>> {
        let tok = self.peek()?;
        if tok.is_ident("function") {
            self.next()?;
            let mut hf = self.function_heights(tok.span)?;
            self.count_objects(1, hf.heights.len() * 4, kw.span)?;
            self.height_field_options(&mut hf)?;
            return Ok(Some(ObjectValue {
                object: Some(Object::new(Shape::HeightField(Box::new(hf)))),
                ..ObjectValue::default()
            }));
        }
        let mut kind = None;
        if let Some(w) = tok.ident().filter(|w| IMAGE_TYPES.contains(w)) {
            self.next()?;
            kind = Some((w, tok));
        }
        let (v, span) = self.expr()?;
        let Value::Str(name) = v else {
            return Err(self.err(
                span,
                "expected the height field's image file name as a string",
            ));
        };
        let ext = Path::new(&*name)
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        let at = kind.as_ref().map(|k| k.1);
        let format = match (kind, ext.as_deref()) {
            (Some((w, _)), _) => w,
            (None, Some("png")) => "png",
            (None, Some("pgm")) => "pgm",
            (None, Some("ppm")) => "ppm",
            (None, Some("jpg" | "jpeg")) => "jpeg",
            (None, _) => "other",
        };
        if !matches!(format, "png" | "pgm" | "ppm" | "jpeg") {
            let what = format!("{format} images in a height_field");
            let at = at.unwrap_or(Token {
                kind: TokenKind::Str(""),
                span,
            });
            return Err(self.unsupported(&at, &what));
        }
        let Some(path) = self.resolve_include(&name) else {
            return Err(self.err(
                span,
                format!("cannot find the height field image \"{name}\""),
            ));
        };
        let image = load_heights(&path, format).map_err(|e| self.err(span, e))?;
        if image.width < 2 || image.height < 2 {
            return Err(self.err(
                span,
                format!(
                    "a height field image needs at least 2 x 2 pixels, \"{name}\" has {} x {}",
                    image.width, image.height
                ),
            ));
        }
        self.count_objects(1, image.values.len() * 4, kw.span)?;
        let mut hf = from_image(image);
        self.height_field_options(&mut hf)?;
        Ok(Some(ObjectValue {
            object: Some(Object::new(Shape::HeightField(Box::new(hf)))),
            ..ObjectValue::default()
        }))
    }

    /// `W, H { body }` after `function`: the function sampled on a W x H grid. Measured
    /// with POV-Ray's `trace`: point (i, j) of the grid reads f(i / (W - 1), 1 - j / (H - 1),
    /// 0) (the function's y runs down the rows, as an image's do), and the value wraps as a
    /// function pattern's does (-0.5 and 1.5 give 0.5, 1 stays 1).
    fn function_heights(&mut self, span: Span) -> R<HeightField> {
        let (w, ws) = self.expr()?;
        let w = self.to_float(&w, ws)?;
        self.eat(Punct::Comma)?;
        let (h, hs) = self.expr()?;
        let h = self.to_float(&h, hs)?;
        if !(2.0..=MAX_FUNCTION_GRID).contains(&w) || !(2.0..=MAX_FUNCTION_GRID).contains(&h) {
            return Err(self.err(
                ws.join(hs),
                format!("a function height field needs 2 to {MAX_FUNCTION_GRID} points each way, found {w} x {h}"),
            ));
        }
        let body = self.function_after_keyword(span)?.body;
        if let crate::function::Body::Spline(_) | crate::function::Body::Transform(_) = body {
            return Err(self.err(span, "a spline or transform function gives a vector; a height field needs a float or pigment function"));
        }
        let (columns, rows) = (w as usize, h as usize);
        let heights = HeightField::sample(columns, rows, |i, j| {
            let x = i as f64 / (columns - 1) as f64;
            let y = 1.0 - j as f64 / (rows - 1) as f64;
            let p = glam::DVec3::new(x, y, 0.0);
            let v = match &body {
                crate::function::Body::Float(f) => f.at(p),
                // A pigment gives its grey (measured: pure red, green and blue read 0.297,
                // 0.589 and 0.114; filter and transmit change nothing).
                crate::function::Body::Pigment(pig) => {
                    let c = crate::appearance::evaluate_pigment(pig, p).rgb;
                    0.297 * c.x + 0.589 * c.y + 0.114 * c.z
                }
                crate::function::Body::Spline(_) | crate::function::Body::Transform(_) => {
                    unreachable!("refused above")
                }
            };
            if (0.0..=1.0).contains(&v) {
                v
            } else if v.is_finite() {
                v - v.floor()
            } else {
                0.0
            }
        });
        Ok(HeightField {
            columns,
            rows,
            heights: std::sync::Arc::new(heights),
            smooth: false,
            water_level: 0.0,
        })
    }

    /// `smooth`, `water_level w`, `hierarchy [b]`, and the image options POV-Ray accepts
    /// that change nothing here (`gamma`, `premultiplied`).
    fn height_field_options(&mut self, hf: &mut HeightField) -> R<()> {
        loop {
            let tok = self.peek()?;
            match tok.ident() {
                Some("smooth") => {
                    self.next()?;
                    hf.smooth = true;
                }
                Some("water_level") => {
                    self.next()?;
                    hf.water_level = self.float()?;
                }
                Some("hierarchy" | "premultiplied") => {
                    self.next()?;
                    self.optional_bool()?;
                }
                Some("gamma") => {
                    self.next()?;
                    self.float()?;
                }
                _ => return Ok(()),
            }
        }
    }
}

/// Most grid points a function height field may ask for along each side.
const MAX_FUNCTION_GRID: f64 = 8192.0;

/// The grid with its first row at z = 0: the image's bottom row.
fn from_image(image: Heights) -> HeightField {
    let (w, h) = (image.width, image.height);
    let heights = HeightField::sample(w, h, |i, j| image.values[(h - 1 - j) * w + i] as f64);
    HeightField {
        columns: w,
        rows: h,
        heights: std::sync::Arc::new(heights),
        smooth: false,
        water_level: 0.0,
    }
}

fn load_heights(path: &Path, format: &str) -> Result<Heights, String> {
    let bytes =
        std::fs::read(path).map_err(|e| format!("cannot read \"{}\": {e}", path.display()))?;
    let r = match format {
        "png" => png_heights(&bytes),
        "jpeg" => jpeg_heights(&bytes),
        _ => netpbm_heights(&bytes),
    };
    r.map_err(|e| format!("cannot read \"{}\": {e}", path.display()))
}

/// A JPEG's 8-bit samples: grey as v / 255, colour as the PNG rule for 8-bit colour
/// ((256 r + g) / 65535, which for grey content is the same v / 255; examples'
/// slopemt_dat_37.jpg is such a colour-coded grey image).
fn jpeg_heights(bytes: &[u8]) -> Result<Heights, String> {
    let image = image::load_from_memory_with_format(bytes, image::ImageFormat::Jpeg)
        .map_err(|e| e.to_string())?;
    let (w, h) = (image.width() as usize, image.height() as usize);
    let values = match image {
        image::DynamicImage::ImageLuma8(g) => g.pixels().map(|p| f32::from(p[0]) / 255.0).collect(),
        other => other
            .to_rgb8()
            .pixels()
            .map(|p| ((256.0 * f64::from(p[0]) + f64::from(p[1])) / 65535.0) as f32)
            .collect(),
    };
    Ok(Heights {
        width: w,
        height: h,
        values,
    })
}

fn png_heights(bytes: &[u8]) -> Result<Heights, String> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    // Palette indices and 16-bit samples as stored; only sub-byte depths are widened.
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let size = reader
        .output_buffer_size()
        .ok_or("the image is too large")?;
    let mut buf = vec![0u8; size];
    let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let (w, h) = (info.width as usize, info.height as usize);
    let bits = info.bit_depth as usize;
    let channels = info.color_type.samples();
    let sample = |row: &[u8], i: usize| -> u32 {
        match bits {
            16 => u16::from_be_bytes([row[2 * i], row[2 * i + 1]]) as u32,
            8 => row[i] as u32,
            _ => {
                let per = 8 / bits;
                let byte = row[i / per];
                let shift = 8 - bits * (i % per + 1);
                ((byte >> shift) as u32) & ((1 << bits) - 1)
            }
        }
    };
    let max = ((1u32 << bits) - 1) as f64;
    let mut values = Vec::with_capacity(w * h);
    for y in 0..h {
        let row = &buf[y * info.line_size..(y + 1) * info.line_size];
        for x in 0..w {
            let s = |c: usize| sample(row, x * channels + c) as f64;
            let v = match (info.color_type, bits) {
                (png::ColorType::Indexed, _) => s(0) * 256.0 / 65535.0,
                (png::ColorType::Grayscale | png::ColorType::GrayscaleAlpha, _) => s(0) / max,
                (_, 16) => (0.297 * s(0) + 0.589 * s(1) + 0.114 * s(2)) / 65535.0,
                _ => (256.0 * s(0) + s(1)) / 65535.0,
            };
            values.push(v as f32);
        }
    }
    Ok(Heights {
        width: w,
        height: h,
        values,
    })
}

/// Binary and plain PGM and PPM (P2, P3, P5, P6): grey over the file's maximum, colour as
/// in PNG files (red high byte, green low byte).
fn netpbm_heights(bytes: &[u8]) -> Result<Heights, String> {
    let mut pos = 0;
    let mut field = || -> Result<String, String> {
        loop {
            while pos < bytes.len() && bytes[pos].is_ascii_whitespace() {
                pos += 1;
            }
            if pos < bytes.len() && bytes[pos] == b'#' {
                while pos < bytes.len() && bytes[pos] != b'\n' {
                    pos += 1;
                }
                continue;
            }
            break;
        }
        let start = pos;
        while pos < bytes.len() && !bytes[pos].is_ascii_whitespace() {
            pos += 1;
        }
        if start == pos {
            return Err("the file ends early".into());
        }
        Ok(String::from_utf8_lossy(&bytes[start..pos]).into_owned())
    };
    let magic = field()?;
    let number = |s: String| s.parse::<usize>().map_err(|_| format!("bad number `{s}`"));
    let w = number(field()?)?;
    let h = number(field()?)?;
    let maxval = number(field()?)?.max(1);
    let channels = match magic.as_str() {
        "P2" | "P5" => 1,
        "P3" | "P6" => 3,
        m => return Err(format!("not a PGM or PPM file (`{m}`)")),
    };
    let n = w
        .checked_mul(h)
        .and_then(|p| p.checked_mul(channels))
        .ok_or("the image is too large")?;
    let mut samples = Vec::with_capacity(n.min(1 << 26));
    if magic == "P2" || magic == "P3" {
        for _ in 0..n {
            samples.push(number(field()?)? as f64);
        }
    } else {
        let data = &bytes[(pos + 1).min(bytes.len())..];
        let wide = maxval > 255;
        let need = n * if wide { 2 } else { 1 };
        if data.len() < need {
            return Err("the file ends early".into());
        }
        for i in 0..n {
            samples.push(if wide {
                u16::from_be_bytes([data[2 * i], data[2 * i + 1]]) as f64
            } else {
                data[i] as f64
            });
        }
    }
    let values = samples
        .chunks(channels)
        .map(|c| {
            if channels == 1 {
                (c[0] / maxval as f64) as f32
            } else {
                ((256.0 * c[0] + c[1]) / 65535.0) as f32
            }
        })
        .collect();
    Ok(Heights {
        width: w,
        height: h,
        values,
    })
}
