//! Image files: PNG for people (sRGB, like POV-Ray's default output) and OpenEXR for
//! measurement (linear float, with extra named layers and string attributes so one file can
//! hold a reference and its half-resolution companion).
//!
//! Every write is atomic: the file is written beside its destination under a temporary name
//! and renamed into place, so an interrupted or failed run never leaves a truncated image
//! that a later comparison could mistake for a real one.

mod atomic;
mod error;
mod exr_file;
mod fnv;
mod image;
mod png_file;
mod shard;
pub mod srgb;

pub use self::error::OutputError;
pub use self::exr_file::{ExrFile, read_exr, write_exr};
pub use self::fnv::Fnv;
pub use self::image::Image;
pub use self::png_file::{read_png, write_png};
pub use self::shard::{Shard, ShardHeader, merge_shards, read_shard, write_shard};

use std::path::Path;

/// Bits per channel of an integer (PNG) file. EXR is always 32-bit float.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BitDepth {
    #[default]
    Eight,
    Sixteen,
}

/// The file formats this module can write, chosen from the file name's extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileFormat {
    Png,
    Exr,
}

impl FileFormat {
    /// Case-insensitive, so `Render.PNG` works as users expect.
    pub fn from_path(path: &Path) -> Result<FileFormat, OutputError> {
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase());
        match extension.as_deref() {
            Some("png") => Ok(FileFormat::Png),
            Some("exr") => Ok(FileFormat::Exr),
            _ => Err(OutputError::UnsupportedFormat {
                path: path.to_path_buf(),
            }),
        }
    }
}

/// Writes `image` as PNG or EXR according to the extension. `bit_depth` only matters for PNG.
pub fn write_image(path: &Path, image: &Image, bit_depth: BitDepth) -> Result<(), OutputError> {
    match FileFormat::from_path(path)? {
        FileFormat::Png => write_png(path, image, bit_depth),
        FileFormat::Exr => write_exr(path, image, &[], &[]),
    }
}

/// Reads a PNG (decoded from sRGB to linear) or the RGB channels of an EXR (already linear).
pub fn read_image(path: &Path) -> Result<Image, OutputError> {
    match FileFormat::from_path(path)? {
        FileFormat::Png => read_png(path),
        FileFormat::Exr => read_exr(path).map(|file| file.image),
    }
}

#[cfg(test)]
mod tests;
