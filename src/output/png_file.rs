use super::atomic::write_atomically;
use super::{BitDepth, Image, OutputError, srgb};
use image::codecs::png::PngEncoder;
use image::{DynamicImage, ExtendedColorType, ImageEncoder, ImageFormat};
use std::io::{BufReader, BufWriter, Write};
use std::path::Path;

fn io_error(path: &Path, source: std::io::Error) -> OutputError {
    OutputError::Io {
        path: path.to_path_buf(),
        source,
    }
}

fn png_error(path: &Path, error: impl std::fmt::Display) -> OutputError {
    OutputError::Png {
        path: path.to_path_buf(),
        message: error.to_string(),
    }
}

/// Writes an sRGB-encoded PNG, as POV-Ray 3.7 does by default, so that penumbra's and
/// POV-Ray's pictures look the same side by side. Values are clamped to [0, 1] and rounded
/// to the nearest code; this loses information, so never measure on PNGs.
pub fn write_png(path: &Path, image: &Image, bit_depth: BitDepth) -> Result<(), OutputError> {
    let (width, height) = checked_size(path, image)?;
    let (bytes, colour_type) = match bit_depth {
        BitDepth::Eight => {
            let bytes: Vec<u8> = image
                .pixels
                .iter()
                .flatten()
                .map(|&v| srgb::quantize8(v))
                .collect();
            (bytes, ExtendedColorType::Rgb8)
        }
        BitDepth::Sixteen => {
            // The encoder takes native-endian 16-bit samples and swaps them itself.
            let bytes: Vec<u8> = image
                .pixels
                .iter()
                .flatten()
                .flat_map(|&v| (srgb::quantize(v, 65535) as u16).to_ne_bytes())
                .collect();
            (bytes, ExtendedColorType::Rgb16)
        }
    };
    write_atomically(path, |temp| {
        let file = std::fs::File::create(temp).map_err(|e| io_error(path, e))?;
        let mut writer = BufWriter::new(file);
        PngEncoder::new(&mut writer)
            .write_image(&bytes, width, height, colour_type)
            .map_err(|e| png_error(path, e))?;
        writer.flush().map_err(|e| io_error(path, e))?;
        let file = writer
            .into_inner()
            .map_err(|e| io_error(path, e.into_error()))?;
        file.sync_all().map_err(|e| io_error(path, e))
    })
}

/// Reads a PNG of any bit depth and decodes it from sRGB to linear. Alpha is dropped;
/// grey images become equal RGB.
pub fn read_png(path: &Path) -> Result<Image, OutputError> {
    let file = std::fs::File::open(path).map_err(|e| io_error(path, e))?;
    let decoded =
        image::load(BufReader::new(file), ImageFormat::Png).map_err(|e| png_error(path, e))?;
    let (width, height) = (decoded.width() as usize, decoded.height() as usize);
    let pixels: Vec<[f32; 3]> = match decoded {
        DynamicImage::ImageLuma8(_)
        | DynamicImage::ImageLumaA8(_)
        | DynamicImage::ImageRgb8(_)
        | DynamicImage::ImageRgba8(_) => {
            // One table lookup per code keeps decoding exact and cheap.
            let table: Vec<f32> = (0..=255u32).map(|c| srgb::dequantize(c, 255)).collect();
            decoded
                .into_rgb8()
                .pixels()
                .map(|p| p.0.map(|c| table[usize::from(c)]))
                .collect()
        }
        other => other
            .into_rgb16()
            .pixels()
            .map(|p| p.0.map(|c| srgb::dequantize(u32::from(c), 65535)))
            .collect(),
    };
    Image::from_pixels(width, height, pixels)
        .ok_or_else(|| png_error(path, "decoded pixel count does not match the size"))
}

fn checked_size(path: &Path, image: &Image) -> Result<(u32, u32), OutputError> {
    let invalid = |message: &str| OutputError::Invalid {
        path: path.to_path_buf(),
        message: message.to_string(),
    };
    if image.width == 0 || image.height == 0 {
        return Err(invalid("cannot write an empty image"));
    }
    if image.pixels.len() != image.width * image.height {
        return Err(invalid("pixel count does not match width x height"));
    }
    let width = u32::try_from(image.width).map_err(|_| invalid("image too wide"))?;
    let height = u32::try_from(image.height).map_err(|_| invalid("image too tall"))?;
    Ok((width, height))
}

pub(super) fn validate(path: &Path, image: &Image) -> Result<(), OutputError> {
    checked_size(path, image).map(|_| ())
}
