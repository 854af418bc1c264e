use super::atomic::write_atomically;
use super::png_file::validate;
use super::{Image, OutputError};
use exr::prelude::{
    AnyChannel, AnyChannels, AttributeValue, Encoding, FlatSamples, Layer, LayerAttributes,
    LineOrder, ReadChannels, ReadLayers, SmallVec, Text, WritableImage,
};
use std::path::Path;

/// Everything penumbra keeps in an EXR: the main RGB image, extra RGB layers stored as
/// `<layer>.R`, `<layer>.G`, `<layer>.B` (the OpenEXR naming convention, so other tools show
/// them as layers), and string attributes in the header.
#[derive(Debug, Clone, PartialEq)]
pub struct ExrFile {
    /// The unprefixed R, G, B channels.
    pub image: Image,
    /// Complete extra RGB layers, sorted by name. Incomplete ones are ignored.
    pub layers: Vec<(String, Image)>,
    /// Every string attribute of the header, sorted by name (including ones other software
    /// wrote, such as POV-Ray's `software` and `comments`).
    pub attributes: Vec<(String, String)>,
    /// Whether the main image was stored as 16-bit half floats (POV-Ray's choice), which
    /// limits its precision to about 5e-4 relative.
    pub half_float: bool,
}

impl ExrFile {
    pub fn layer(&self, name: &str) -> Option<&Image> {
        self.layers.iter().find(|(n, _)| n == name).map(|(_, i)| i)
    }

    pub fn attribute(&self, name: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }
}

/// Header attributes that describe the file's structure; letting a caller set them would
/// corrupt the file, so they are refused.
const RESERVED_ATTRIBUTES: &[&str] = &[
    "channels",
    "compression",
    "dataWindow",
    "displayWindow",
    "lineOrder",
    "pixelAspectRatio",
    "screenWindowCenter",
    "screenWindowWidth",
    "tiles",
    "name",
    "type",
    "version",
    "chunkCount",
    "maxSamplesPerPixel",
];

fn exr_error(path: &Path, error: impl std::fmt::Display) -> OutputError {
    OutputError::Exr {
        path: path.to_path_buf(),
        message: error.to_string(),
    }
}

fn invalid(path: &Path, message: String) -> OutputError {
    OutputError::Invalid {
        path: path.to_path_buf(),
        message,
    }
}

/// Writes linear 32-bit float RGB, plus `layers` (each the same size as `image`) and string
/// `attributes`. Layer names must be non-empty and free of `.`; attribute names and values
/// must be printable Latin-1 text that EXR can store, and not a structural header name.
pub fn write_exr(
    path: &Path,
    image: &Image,
    layers: &[(&str, &Image)],
    attributes: &[(&str, &str)],
) -> Result<(), OutputError> {
    validate(path, image)?;
    let mut channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    push_rgb(&mut channels, "", image);
    for (i, (name, layer)) in layers.iter().enumerate() {
        if name.is_empty() || name.contains('.') || Text::new_or_none(name).is_none() {
            return Err(invalid(
                path,
                format!("layer name {name:?} must be non-empty ASCII without '.'"),
            ));
        }
        if layers[..i].iter().any(|(other, _)| other == name) {
            return Err(invalid(path, format!("layer {name:?} given twice")));
        }
        if !layer.same_size(image) {
            return Err(invalid(
                path,
                format!(
                    "layer {name:?} is {}x{}, the image is {}x{}",
                    layer.width, layer.height, image.width, image.height
                ),
            ));
        }
        validate(path, layer)?;
        push_rgb(&mut channels, &format!("{name}."), layer);
    }

    let mut layer_attributes = LayerAttributes::default();
    for (name, value) in attributes {
        if RESERVED_ATTRIBUTES.contains(name) {
            return Err(invalid(
                path,
                format!("attribute {name:?} is reserved by OpenEXR"),
            ));
        }
        let (Some(key), Some(text)) = (Text::new_or_none(name), Text::new_or_none(value)) else {
            return Err(invalid(
                path,
                format!("attribute {name:?} = {value:?} cannot be stored as EXR text"),
            ));
        };
        if name.is_empty() || layer_attributes.other.contains_key(&key) {
            return Err(invalid(
                path,
                format!("attribute name {name:?} is empty or repeated"),
            ));
        }
        layer_attributes
            .other
            .insert(key, AttributeValue::Text(text));
    }

    let layer = Layer::new(
        (image.width, image.height),
        layer_attributes,
        DETERMINISTIC_LOSSLESS,
        AnyChannels::sort(channels),
    );
    let exr_image = exr::prelude::Image::from_layer(layer);
    write_atomically(path, |temp| {
        exr_image
            .write()
            .to_file(temp)
            .map_err(|e| exr_error(path, e))
    })
}

/// RLE on 64x64 tiles (the crate's fast lossless choice) with the chunks written in
/// increasing order: with the crate's default, unspecified order, chunks land in the order
/// the compression threads finish them, so the same pixels gave different bytes from run
/// to run, and farms compare files by their hash.
const DETERMINISTIC_LOSSLESS: Encoding = Encoding {
    line_order: LineOrder::Increasing,
    ..Encoding::FAST_LOSSLESS
};

fn push_rgb(channels: &mut SmallVec<[AnyChannel<FlatSamples>; 4]>, prefix: &str, image: &Image) {
    for (c, letter) in ["R", "G", "B"].iter().enumerate() {
        let samples: Vec<f32> = image.pixels.iter().map(|p| p[c]).collect();
        channels.push(AnyChannel::new(
            format!("{prefix}{letter}").as_str(),
            FlatSamples::F32(samples),
        ));
    }
}

/// Reads the first layer (part) of an EXR written by penumbra or by POV-Ray. Half and
/// 32-bit samples are converted to `f32`; values are taken as linear, as EXR intends.
pub fn read_exr(path: &Path) -> Result<ExrFile, OutputError> {
    let file = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_file(path)
        .map_err(|e| exr_error(path, e))?;
    let layer = &file.layer_data;
    let (width, height) = (layer.size.x(), layer.size.y());

    // Group channels by layer prefix: "" for the main image.
    struct Group<'a> {
        name: String,
        rgb: [Option<&'a FlatSamples>; 3],
    }
    let mut groups: Vec<Group> = Vec::new();
    for channel in &layer.channel_data.list {
        let full = channel.name.to_string();
        let (prefix, letter) = full.rsplit_once('.').unwrap_or(("", full.as_str()));
        let Some(c) = ["R", "G", "B"].iter().position(|l| *l == letter) else {
            continue;
        };
        let index = match groups.iter().position(|g| g.name == prefix) {
            Some(i) => i,
            None => {
                groups.push(Group {
                    name: prefix.to_string(),
                    rgb: [None; 3],
                });
                groups.len() - 1
            }
        };
        groups[index].rgb[c] = Some(&channel.sample_data);
    }

    let to_image = |rgb: [&FlatSamples; 3]| -> Result<Image, OutputError> {
        let values: Vec<Vec<f32>> = rgb.iter().map(|s| samples_to_f32(s)).collect();
        if values.iter().any(|v| v.len() != width * height) {
            return Err(exr_error(
                path,
                "channel length does not match the data window",
            ));
        }
        let pixels = (0..width * height)
            .map(|i| [values[0][i], values[1][i], values[2][i]])
            .collect();
        Image::from_pixels(width, height, pixels)
            .ok_or_else(|| exr_error(path, "pixel count does not match the data window"))
    };

    let mut image = None;
    let mut half_float = false;
    let mut layers = Vec::new();
    for group in &groups {
        let [Some(r), Some(g), Some(b)] = group.rgb else {
            continue;
        };
        if group.name.is_empty() {
            half_float = [r, g, b].iter().any(|s| matches!(s, FlatSamples::F16(_)));
            image = Some(to_image([r, g, b])?);
        } else {
            layers.push((group.name.clone(), to_image([r, g, b])?));
        }
    }
    let image = image.ok_or_else(|| exr_error(path, "no R, G and B channels"))?;
    layers.sort_by(|a, b| a.0.cmp(&b.0));

    let mut attributes: Vec<(String, String)> = Vec::new();
    let known_text = [
        ("software", &layer.attributes.software_name),
        ("comments", &layer.attributes.comments),
        ("owner", &layer.attributes.owner),
        ("capDate", &layer.attributes.capture_date),
    ];
    for (name, value) in known_text {
        if let Some(text) = value {
            attributes.push((name.to_string(), text.to_string()));
        }
    }
    for (name, value) in layer
        .attributes
        .other
        .iter()
        .chain(file.attributes.other.iter())
    {
        if let AttributeValue::Text(text) = value {
            attributes.push((name.to_string(), text.to_string()));
        }
    }
    attributes.sort();

    Ok(ExrFile {
        image,
        layers,
        attributes,
        half_float,
    })
}

fn samples_to_f32(samples: &FlatSamples) -> Vec<f32> {
    match samples {
        FlatSamples::F16(v) => v.iter().map(|h| h.to_f32()).collect(),
        FlatSamples::F32(v) => v.clone(),
        FlatSamples::U32(v) => v.iter().map(|&u| u as f32).collect(),
    }
}
