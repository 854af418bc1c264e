//! Shard files: a film's exact sums, so that renders of sample ranges on many machines (or
//! an interrupted render and its continuation) merge into exactly the single render.
//!
//! The format (docs/farm.md): a text header of `key = value` lines after the line
//! `penumbra-shard 1`, ended by an empty line; then, little-endian, per pixel in row order
//! the sample count (u32), the three fixed-point sums (i64) and the three sums of squares
//! (u128); the count of non-finite samples (u64) and each one's pixel (u32 x, u32 y); and
//! last an FNV-1a 64 checksum (u64) of every byte before it, so a truncated or damaged
//! file is refused rather than merged.

use std::io::{Read, Write};
use std::ops::Range;
use std::path::Path;

use super::OutputError;
use super::atomic::write_atomically;
use super::fnv::Fnv;
use crate::render::{Film, PixelSum};

const MAGIC: &str = "penumbra-shard 1";

/// Bytes per pixel in the payload.
const PIXEL_BYTES: usize = 4 + 3 * 8 + 3 * 16;

/// Largest image a shard may describe (a sanity bound on the header before allocating).
const MAX_PIXELS: u64 = 1 << 28;

/// What a shard's samples belong to: two shards merge only when all of this but the range
/// agrees.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShardHeader {
    /// The penumbra version that rendered it (the sampler must be the same).
    pub version: String,
    /// A hash of the evaluated scene (its whole model), not of its file: an edited include
    /// file changes it too.
    pub scene_hash: u64,
    /// The scene file, for messages only.
    pub scene: String,
    pub frame: i64,
    pub width: usize,
    pub height: usize,
    pub spp: u32,
    pub seed: u64,
    /// Every other option that changes pixels, in a canonical text form.
    pub options: String,
    /// The sample indices the shard was asked for.
    pub range: Range<u32>,
    /// False for an interrupted render's checkpoint: its pixels hold a prefix of the range.
    pub complete: bool,
}

/// A shard read back: its header and film.
#[derive(Clone, Debug, PartialEq)]
pub struct Shard {
    pub header: ShardHeader,
    pub film: Film,
}

fn invalid(path: &Path, message: impl Into<String>) -> OutputError {
    OutputError::Invalid {
        path: path.to_path_buf(),
        message: message.into(),
    }
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> OutputError + '_ {
    move |source| OutputError::Io {
        path: path.to_path_buf(),
        source,
    }
}

impl ShardHeader {
    fn text(&self) -> String {
        let line = |k: &str, v: &dyn std::fmt::Display| format!("{k} = {v}\n");
        [
            format!("{MAGIC}\n"),
            line("version", &self.version),
            line("scene", &self.scene.replace('\n', " ")),
            line("scene_hash", &format!("{:016x}", self.scene_hash)),
            line("frame", &self.frame),
            line("width", &self.width),
            line("height", &self.height),
            line("spp", &self.spp),
            line("seed", &self.seed),
            line("options", &self.options.replace('\n', " ")),
            line(
                "range",
                &format!("{}..{}", self.range.start, self.range.end),
            ),
            line("complete", &self.complete),
            "\n".to_string(),
        ]
        .concat()
    }

    fn parse(path: &Path, text: &str) -> Result<ShardHeader, OutputError> {
        let mut lines = text.lines();
        if lines.next() != Some(MAGIC) {
            return Err(invalid(
                path,
                "not a penumbra shard (no `penumbra-shard 1` line)",
            ));
        }
        let fields: Vec<(&str, &str)> = lines.filter_map(|l| l.split_once(" = ")).collect();
        let get = |key: &str| {
            fields
                .iter()
                .find(|(k, _)| *k == key)
                .map(|(_, v)| *v)
                .ok_or_else(|| invalid(path, format!("the shard header has no `{key}`")))
        };
        let num = |key: &str| -> Result<u64, OutputError> {
            get(key)?
                .parse()
                .map_err(|_| invalid(path, format!("the shard's `{key}` is not a number")))
        };
        let range = get("range")?
            .split_once("..")
            .and_then(|(a, b)| Some(a.parse().ok()?..b.parse().ok()?))
            .ok_or_else(|| invalid(path, "the shard's `range` is not A..B"))?;
        Ok(ShardHeader {
            version: get("version")?.to_string(),
            scene_hash: u64::from_str_radix(get("scene_hash")?, 16)
                .map_err(|_| invalid(path, "the shard's `scene_hash` is not hexadecimal"))?,
            scene: get("scene")?.to_string(),
            frame: get("frame")?
                .parse()
                .map_err(|_| invalid(path, "the shard's `frame` is not a number"))?,
            width: num("width")? as usize,
            height: num("height")? as usize,
            spp: num("spp")? as u32,
            seed: num("seed")?,
            options: get("options")?.to_string(),
            range,
            complete: get("complete")? == "true",
        })
    }
}

/// Writes a shard atomically (a reader never sees half a file).
pub fn write_shard(path: &Path, header: &ShardHeader, film: &Film) -> Result<(), OutputError> {
    if (film.width, film.height) != (header.width, header.height) {
        return Err(invalid(path, "the film and the header differ in size"));
    }
    let mut bytes = header.text().into_bytes();
    bytes.reserve(film.pixels.len() * PIXEL_BYTES + 16 + film.non_finite.len() * 8);
    for p in &film.pixels {
        bytes.extend_from_slice(&p.count.to_le_bytes());
        p.rgb
            .iter()
            .for_each(|s| bytes.extend_from_slice(&s.to_le_bytes()));
        p.squares
            .iter()
            .for_each(|s| bytes.extend_from_slice(&s.to_le_bytes()));
    }
    bytes.extend_from_slice(&(film.non_finite.len() as u64).to_le_bytes());
    for (x, y) in &film.non_finite {
        bytes.extend_from_slice(&x.to_le_bytes());
        bytes.extend_from_slice(&y.to_le_bytes());
    }
    let mut hash = Fnv::default();
    hash.write(&bytes);
    bytes.extend_from_slice(&hash.finish().to_le_bytes());
    write_atomically(path, |temp| {
        let mut file = std::fs::File::create(temp).map_err(io(path))?;
        file.write_all(&bytes).map_err(io(path))?;
        file.sync_all().map_err(io(path))
    })
}

/// Reads a shard, checking its structure and checksum.
pub fn read_shard(path: &Path) -> Result<Shard, OutputError> {
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|mut f| f.read_to_end(&mut bytes))
        .map_err(io(path))?;
    let damaged = || {
        invalid(
            path,
            "the shard is truncated or damaged (checksum mismatch)",
        )
    };
    if bytes.len() < 8 {
        return Err(damaged());
    }
    let (body, sum) = bytes.split_at(bytes.len() - 8);
    let mut hash = Fnv::default();
    hash.write(body);
    if hash.finish().to_le_bytes() != sum {
        return Err(damaged());
    }
    let end = body
        .windows(2)
        .position(|w| w == b"\n\n")
        .ok_or_else(|| invalid(path, "the shard has no header"))?;
    let text = std::str::from_utf8(&body[..end + 1])
        .map_err(|_| invalid(path, "the shard header is not text"))?;
    let header = ShardHeader::parse(path, text)?;
    let pixels = header.width as u64 * header.height as u64;
    if pixels == 0 || pixels > MAX_PIXELS {
        return Err(invalid(
            path,
            format!("the shard's size {pixels} pixels is out of range"),
        ));
    }
    let film = read_film(path, &header, &body[end + 2..])?;
    Ok(Shard { header, film })
}

/// The payload after the header.
fn read_film(path: &Path, header: &ShardHeader, data: &[u8]) -> Result<Film, OutputError> {
    let mut film = Film::new(header.width, header.height);
    let need = film.pixels.len() * PIXEL_BYTES + 8;
    if data.len() < need {
        return Err(invalid(path, "the shard's pixels are cut short"));
    }
    let mut at = 0;
    let mut take = |n: usize| {
        let s = &data[at..at + n];
        at += n;
        s
    };
    for p in &mut film.pixels {
        *p = PixelSum {
            count: u32::from_le_bytes(take(4).try_into().expect("4 bytes")),
            rgb: std::array::from_fn(|_| i64::from_le_bytes(take(8).try_into().expect("8"))),
            squares: std::array::from_fn(|_| {
                u128::from_le_bytes(take(16).try_into().expect("16 bytes"))
            }),
        };
    }
    let count = u64::from_le_bytes(take(8).try_into().expect("8 bytes"));
    if data.len() - need != count as usize * 8 {
        return Err(invalid(
            path,
            "the shard's list of non-finite samples is damaged",
        ));
    }
    for _ in 0..count {
        let x = u32::from_le_bytes(take(4).try_into().expect("4 bytes"));
        let y = u32::from_le_bytes(take(4).try_into().expect("4 bytes"));
        film.non_finite.push((x, y));
    }
    Ok(film)
}

/// Merges shards that belong together: the same header but for the range, complete, and
/// ranges that cover 0..spp exactly once. The error names the shard that does not fit.
pub fn merge_shards(shards: &[(std::path::PathBuf, Shard)]) -> Result<Film, String> {
    let Some((first_path, first)) = shards.first() else {
        return Err("no shards to merge".into());
    };
    let name = |p: &Path| p.display().to_string();
    for (path, s) in shards {
        if !s.header.complete {
            return Err(format!(
                "{} is an interrupted render's checkpoint ({} of its samples); resume it with --resume first",
                name(path),
                s.film.samples()
            ));
        }
        if let Some(what) = mismatch(&first.header, &s.header) {
            return Err(format!(
                "{} and {} are not shards of one render: {what}",
                name(first_path),
                name(path)
            ));
        }
    }
    let mut order: Vec<&(std::path::PathBuf, Shard)> = shards.iter().collect();
    order.sort_by_key(|(_, s)| (s.header.range.start, s.header.range.end));
    let mut next = 0;
    let mut last: Option<&(std::path::PathBuf, Shard)> = None;
    for shard in &order {
        let (path, s) = shard;
        let r = &s.header.range;
        if let Some((last_path, l)) = last.filter(|_| r.start < next) {
            return Err(format!(
                "{} (samples {}..{}) overlaps {} (samples {}..{})",
                name(path),
                r.start,
                r.end,
                name(last_path),
                l.header.range.start,
                l.header.range.end
            ));
        }
        if r.start > next {
            return Err(format!("samples {next}..{} are missing", r.start));
        }
        next = r.end;
        last = Some(shard);
    }
    if next != first.header.spp {
        return Err(format!("samples {next}..{} are missing", first.header.spp));
    }
    let mut film = Film::new(first.header.width, first.header.height);
    for (_, s) in order {
        film.merge(&s.film);
    }
    Ok(film)
}

/// What differs between two shards' headers, other than their ranges.
fn mismatch(a: &ShardHeader, b: &ShardHeader) -> Option<String> {
    let differs = |what: &str, x: &dyn std::fmt::Display, y: &dyn std::fmt::Display| {
        Some(format!("{what} {x} against {y}"))
    };
    if a.scene_hash != b.scene_hash {
        return Some(format!(
            "they come from different scenes (scene hash {:016x} against {:016x})",
            a.scene_hash, b.scene_hash
        ));
    }
    if a.version != b.version {
        return differs("penumbra version", &a.version, &b.version);
    }
    if (a.width, a.height) != (b.width, b.height) {
        return differs(
            "size",
            &format!("{}x{}", a.width, a.height),
            &format!("{}x{}", b.width, b.height),
        );
    }
    if a.spp != b.spp {
        return differs("samples per pixel", &a.spp, &b.spp);
    }
    if a.seed != b.seed {
        return differs("seed", &a.seed, &b.seed);
    }
    if a.frame != b.frame {
        return differs("frame", &a.frame, &b.frame);
    }
    if a.options != b.options {
        return differs("options", &a.options, &b.options);
    }
    None
}
