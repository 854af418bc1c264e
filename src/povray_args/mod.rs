//! POV-Ray's command line and INI files, read the way POV-Ray 3.7 reads them: switches
//! (`+W640`, `-D`, `+KFF30`), `Key=Value` lines, `.pov` and `.ini` arguments (an INI file
//! may name a section, `file.ini[Section]`). Pure: text in, [`PovSettings`] out; files are
//! read through [`SourceFiles`]. [`job`] turns the settings into what penumbra renders.

pub mod job;
pub mod table;
#[cfg(test)]
mod tests;

use std::path::{Path, PathBuf};

use crate::lang::SourceFiles;
pub use job::{Frame, Job, Sampling, sampling_for};
use table::{OPTIONS, PovOption, Setting, find_ini, find_long, find_switch, nearest};

/// POV-Ray's own INI folder, searched last for INI files named without a folder.
pub const SYSTEM_INI_DIR: &str = "/usr/share/povray-3.7/ini";

/// A row, column or frame bound: POV-Ray takes a whole number as a pixel (from 1) or frame,
/// and a number with a decimal point between 0 and 1 as a fraction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    Pixel(i64),
    Fraction(f64),
}

/// POV-Ray's anti-aliasing settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Antialias {
    pub on: bool,
    pub threshold: f64,
    pub method: u32,
    pub depth: u32,
}

impl Default for Antialias {
    fn default() -> Self {
        Antialias {
            on: false,
            threshold: 0.3,
            method: 1,
            depth: 3,
        }
    }
}

/// The animation settings, as POV-Ray names them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Animation {
    pub clock: f64,
    pub initial_frame: i64,
    pub final_frame: i64,
    pub initial_clock: f64,
    pub final_clock: f64,
    pub subset_start: Option<Bound>,
    pub subset_end: Option<Bound>,
    pub cyclic: bool,
    pub frame_step: i64,
}

impl Default for Animation {
    fn default() -> Self {
        Animation {
            clock: 0.0,
            initial_frame: 1,
            final_frame: 1,
            initial_clock: 0.0,
            final_clock: 1.0,
            subset_start: None,
            subset_end: None,
            cyclic: false,
            frame_step: 1,
        }
    }
}

/// The window of `+SR +ER +SC +EC`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WindowBounds {
    pub start_row: Option<Bound>,
    pub end_row: Option<Bound>,
    pub start_column: Option<Bound>,
    pub end_column: Option<Bound>,
}

/// Everything a POV-Ray command line and its INI files set.
#[derive(Clone, Debug, PartialEq)]
pub struct PovSettings {
    pub input: Option<PathBuf>,
    pub output: Option<PathBuf>,
    pub output_to_file: bool,
    /// `+Fx`'s type letter, upper case (N png, E exr, ...).
    pub file_type: char,
    pub bits_per_colour: u32,
    pub width: u32,
    pub height: u32,
    pub library_paths: Vec<PathBuf>,
    pub declares: Vec<(String, f64)>,
    pub antialias: Antialias,
    pub quality: u32,
    pub threads: Option<usize>,
    pub window: WindowBounds,
    pub animation: Animation,
    pub crop: bool,
    /// `--spp N`: overrides the anti-aliasing mapping; a fractional N is an adaptive
    /// render's average.
    pub spp: Option<f64>,
    pub seed: u64,
    pub quiet: bool,
    /// `+GD` (the default): the scene's `#debug` text on stderr.
    pub debug_console: bool,
    /// `--allow-write DIR`.
    pub allow_write: Option<PathBuf>,
    /// `+C`: continue an interrupted render from its checkpoint.
    pub continue_trace: bool,
    /// `--motion-blur N`.
    pub motion_blur: u32,
    /// `--adaptive` (true) or `--uniform` (false); none: `adaptive_by_default`.
    pub adaptive: Option<bool>,
    /// One line per option accepted that does not apply.
    pub notes: Vec<String>,
}

/// 800 x 600, no anti-aliasing, quality 9, png: the installed POV-Ray's defaults.
impl Default for PovSettings {
    fn default() -> Self {
        PovSettings {
            input: None,
            output: None,
            output_to_file: true,
            file_type: 'N',
            bits_per_colour: 8,
            width: 800,
            height: 600,
            library_paths: Vec::new(),
            declares: Vec::new(),
            antialias: Antialias::default(),
            quality: 9,
            threads: None,
            window: WindowBounds::default(),
            animation: Animation::default(),
            crop: false,
            spp: None,
            seed: 0,
            quiet: false,
            debug_console: true,
            allow_write: None,
            continue_trace: false,
            motion_blur: 1,
            adaptive: None,
            notes: Vec::new(),
        }
    }
}

/// An error, with the INI file and line it comes from when it has one.
#[derive(Clone, Debug, PartialEq)]
pub struct PovArgError {
    pub place: Option<(PathBuf, usize)>,
    pub message: String,
}

impl std::fmt::Display for PovArgError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.place {
            Some((file, line)) => write!(f, "{}:{line}: {}", file.display(), self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for PovArgError {}

/// Whether an argument looks like part of a POV-Ray invocation: a switch, a scene, an INI
/// file or a `Key=Value` setting.
pub fn looks_like_povray(arg: &str) -> bool {
    let lower = arg.to_ascii_lowercase();
    (arg.len() > 1 && (arg.starts_with('+') || arg.starts_with('-')) && !arg.starts_with("--"))
        || lower.ends_with(".pov")
        || lower.ends_with(".ini")
        || (lower.contains(".ini[") && lower.ends_with(']'))
        || arg
            .split_once('=')
            .is_some_and(|(k, _)| find_ini(k.trim()).is_some())
}

/// Reads a POV-Ray command line (without the program name).
pub fn parse_args(args: &[String], files: &dyn SourceFiles) -> Result<PovSettings, PovArgError> {
    let mut reader = Reader {
        settings: PovSettings::default(),
        files,
        depth: 0,
    };
    let mut i = 0;
    while i < args.len() {
        let arg = &args[i];
        if let Some(name) = arg.strip_prefix("--") {
            let (name, inline) = match name.split_once('=') {
                Some((n, v)) => (n, Some(v.to_string())),
                None => (name, None),
            };
            let option = find_long(name).ok_or_else(|| unknown(arg, None))?;
            let flag = matches!(
                option.setting,
                Setting::Crop | Setting::Quiet | Setting::Adaptive | Setting::Uniform
            );
            let value = if flag {
                inline.unwrap_or_default()
            } else if let Some(v) = inline {
                v
            } else {
                i += 1;
                args.get(i)
                    .cloned()
                    .ok_or_else(|| plain(format!("{arg} needs a value")))?
            };
            reader.apply(option, Form::Long, &value).map_err(plain)?;
        } else {
            reader.argument(arg, None, Path::new("."))?;
        }
        i += 1;
    }
    Ok(reader.settings)
}

/// Reads INI text as if it were a file `name` (for tests and INI text given inline).
pub fn parse_ini_text(
    name: &Path,
    text: &str,
    section: Option<&str>,
    files: &dyn SourceFiles,
) -> Result<PovSettings, PovArgError> {
    let mut reader = Reader {
        settings: PovSettings::default(),
        files,
        depth: 0,
    };
    reader.ini_text(name, text, section)?;
    Ok(reader.settings)
}

fn plain(message: String) -> PovArgError {
    PovArgError {
        place: None,
        message,
    }
}

fn unknown(arg: &str, place: Option<(PathBuf, usize)>) -> PovArgError {
    let hint = if let Some(name) = arg.strip_prefix("--") {
        nearest(name, OPTIONS.iter().filter_map(|o| o.long)).map(|n| format!("--{n}"))
    } else if let Some(rest) = arg.strip_prefix(['+', '-']) {
        let letters: String = rest
            .chars()
            .take_while(|c| c.is_ascii_alphabetic())
            .collect();
        nearest(&letters, OPTIONS.iter().filter_map(|o| o.switch)).map(|n| format!("+{n}"))
    } else {
        let key = arg.split('=').next().unwrap_or(arg).trim();
        nearest(key, OPTIONS.iter().filter_map(|o| o.ini)).map(str::to_string)
    };
    let what = if arg.starts_with(['+', '-']) {
        "switch"
    } else {
        "option"
    };
    PovArgError {
        place,
        message: match hint {
            Some(h) => format!("unknown {what} `{arg}` (nearest known: `{h}`)"),
            None => format!("unknown {what} `{arg}`"),
        },
    }
}

/// How a value arrived: a switch with its sign, an INI line, or a penumbra long option.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Form {
    Switch { on: bool },
    Ini,
    Long,
}

struct Reader<'f> {
    settings: PovSettings,
    files: &'f dyn SourceFiles,
    depth: usize,
}

/// INI files that include INI files stop at this depth (a file that includes itself).
const MAX_INI_DEPTH: usize = 16;

impl Reader<'_> {
    /// One argument or one word of an INI line: `place` is the INI line it comes from,
    /// `dir` the folder relative names are also looked for in.
    fn argument(
        &mut self,
        arg: &str,
        place: Option<(PathBuf, usize)>,
        dir: &Path,
    ) -> Result<(), PovArgError> {
        let at = |message: String| PovArgError {
            place: place.clone(),
            message,
        };
        if let Some(rest) = arg.strip_prefix(['+', '-']).filter(|r| !r.is_empty()) {
            let on = arg.starts_with('+');
            let (option, value) = find_switch(rest).ok_or_else(|| unknown(arg, place.clone()))?;
            return self
                .apply(option, Form::Switch { on }, value)
                .map_err(|m| at(format!("`{arg}`: {m}")));
        }
        if let Some((key, value)) = arg.split_once('=') {
            let option = find_ini(key.trim()).ok_or_else(|| unknown(arg, place.clone()))?;
            return self
                .apply(option, Form::Ini, strip_quotes(value.trim()))
                .map_err(|m| at(format!("`{}`: {m}", key.trim())));
        }
        let lower = arg.to_ascii_lowercase();
        if lower.ends_with(".pov") {
            self.settings.input = Some(PathBuf::from(arg));
            return Ok(());
        }
        // Anything else is an INI file, `.ini` assumed (POV-Ray reads `res120` as
        // res120.ini), optionally with a section: `file.ini[Section]`.
        let (file, section) = match arg.split_once('[') {
            Some((f, s)) if s.ends_with(']') => (f, Some(&s[..s.len() - 1])),
            _ => (arg, None),
        };
        let path = self.find_ini_file(file, dir).ok_or_else(|| {
            at(format!(
                "cannot find the INI file `{file}` (nor a scene: scenes end in .pov)"
            ))
        })?;
        let text = self
            .files
            .read(&path)
            .map_err(|e| at(format!("cannot read `{}`: {e}", path.display())))?;
        if self.depth >= MAX_INI_DEPTH {
            return Err(at(format!("INI files nest deeper than {MAX_INI_DEPTH}")));
        }
        self.depth += 1;
        let result = self.ini_text(&path, &text, section);
        self.depth -= 1;
        result
    }

    fn find_ini_file(&self, file: &str, dir: &Path) -> Option<PathBuf> {
        let mut names = vec![PathBuf::from(file)];
        if Path::new(file).extension().is_none() {
            names.insert(0, PathBuf::from(format!("{file}.ini")));
        }
        let mut dirs = vec![PathBuf::new(), dir.to_path_buf()];
        dirs.extend(self.settings.library_paths.iter().cloned());
        dirs.push(PathBuf::from(SYSTEM_INI_DIR));
        for d in &dirs {
            for n in &names {
                let p = if d.as_os_str().is_empty() || n.is_absolute() {
                    n.clone()
                } else {
                    d.join(n)
                };
                if self.files.exists(&p) {
                    return Some(p);
                }
            }
        }
        None
    }

    /// An INI file's lines: those before the first `[section]`, and, when `section` is
    /// given, those of that section.
    fn ini_text(
        &mut self,
        name: &Path,
        text: &str,
        section: Option<&str>,
    ) -> Result<(), PovArgError> {
        let dir = name.parent().unwrap_or(Path::new(".")).to_path_buf();
        let mut active = true;
        for (n, line) in text.lines().enumerate() {
            let line = strip_comment(line).trim();
            if line.is_empty() {
                continue;
            }
            if let Some(label) = line.strip_prefix('[') {
                let label = label.trim_end_matches(']').trim();
                active = section.is_some_and(|s| s.trim().eq_ignore_ascii_case(label));
                continue;
            }
            if !active {
                continue;
            }
            let place = Some((name.to_path_buf(), n + 1));
            if let Some((key, value)) = line.split_once('=')
                && !key.trim().starts_with(['+', '-'])
            {
                // `Key=Value`: the value is the rest of the line (it may hold spaces).
                let arg = format!("{}={}", key.trim(), value.trim());
                self.argument(&arg, place, &dir)?;
            } else {
                for word in line.split_whitespace() {
                    self.argument(word, place.clone(), &dir)?;
                }
            }
        }
        Ok(())
    }

    fn apply(&mut self, option: &PovOption, form: Form, value: &str) -> Result<(), String> {
        let s = &mut self.settings;
        let switch_on = match form {
            Form::Switch { on } => Some(on),
            _ => None,
        };
        match option.setting {
            Setting::Input => s.input = Some(PathBuf::from(need(value)?)),
            // POV-Ray's INI files leave the name empty for the default (the scene's own
            // name), as advanced/benchmark/benchmark.ini does.
            Setting::Output => s.output = (!value.is_empty()).then(|| PathBuf::from(value)),
            Setting::Width => s.width = positive(value)?,
            Setting::Height => s.height = positive(value)?,
            Setting::LibraryPath => s.library_paths.push(PathBuf::from(need(value)?)),
            Setting::Declare => s.declares.push(parse_declare(value)?),
            Setting::Antialias => {
                s.antialias.on = flag(switch_on, value, true)?;
                if switch_on.is_some() && !value.is_empty() {
                    s.antialias.threshold = number(value)?;
                }
            }
            Setting::AntialiasThreshold => s.antialias.threshold = number(value)?,
            Setting::SamplingMethod => s.antialias.method = whole(value, 1..=3)?,
            Setting::AntialiasDepth => s.antialias.depth = whole(value, 1..=9)?,
            Setting::Jitter | Setting::JitterAmount => {}
            Setting::Quality => s.quality = whole(value, 0..=11)?,
            Setting::WorkThreads => s.threads = Some(whole(value, 1..=4096)? as usize),
            Setting::OutputFile => self.output_file(switch_on.unwrap_or(true), value)?,
            Setting::OutputToFile => s.output_to_file = flag(None, value, true)?,
            Setting::OutputFileType => self.output_file(true, value)?,
            Setting::BitsPerColour => s.bits_per_colour = whole(value, 1..=16)?,
            Setting::Crop => s.crop = true,
            Setting::Frames => {
                let (a, b) = value
                    .split_once("..")
                    .ok_or_else(|| format!("expected A..B, got `{value}`"))?;
                s.animation.initial_frame = integer(a)?;
                s.animation.final_frame = integer(b)?;
            }
            Setting::Spp => s.spp = Some(samples(value)?),
            Setting::Seed => s.seed = value.trim().parse().map_err(|_| not_number(value))?,
            Setting::Quiet => s.quiet = true,
            Setting::AllowWrite => s.allow_write = Some(PathBuf::from(value.trim())),
            Setting::MotionBlur => s.motion_blur = whole(value, 1..=1024)?,
            Setting::Adaptive => s.adaptive = Some(true),
            Setting::Uniform => s.adaptive = Some(false),
            _ => self.apply_more(option, switch_on, value)?,
        }
        Ok(())
    }

    /// The window, animation and display settings.
    fn apply_more(
        &mut self,
        option: &PovOption,
        switch_on: Option<bool>,
        value: &str,
    ) -> Result<(), String> {
        let s = &mut self.settings;
        let a = &mut s.animation;
        match option.setting {
            Setting::StartRow => s.window.start_row = Some(bound(value)?),
            Setting::EndRow => s.window.end_row = Some(end_bound(value)?),
            Setting::StartColumn => s.window.start_column = Some(bound(value)?),
            Setting::EndColumn => s.window.end_column = Some(end_bound(value)?),
            Setting::Clock => a.clock = number(value)?,
            Setting::InitialFrame => a.initial_frame = integer(value)?,
            Setting::FinalFrame => a.final_frame = integer(value)?,
            Setting::InitialClock => a.initial_clock = number(value)?,
            Setting::FinalClock => a.final_clock = number(value)?,
            Setting::SubsetStartFrame => a.subset_start = Some(bound(value)?),
            Setting::SubsetEndFrame => a.subset_end = Some(bound(value)?),
            Setting::CyclicAnimation => a.cyclic = flag(switch_on, value, true)?,
            Setting::FrameStep => a.frame_step = integer(value)?.max(1),
            Setting::ContinueTrace => s.continue_trace = flag(switch_on, value, true)?,
            Setting::DebugConsole => {
                s.debug_console = flag(switch_on, value, true)?;
                if switch_on == Some(true) && !value.trim().is_empty() {
                    s.notes.push(format!(
                        "note: `+GD{}` also writes the #debug stream to a file, which penumbra \
                         does not; it is shown on the console only",
                        value.trim()
                    ));
                }
            }
            Setting::Verbose => {
                if !flag(switch_on, value, true)? {
                    s.quiet = true;
                }
            }
            Setting::Display | Setting::PauseWhenDone | Setting::NotApplicable => {
                let on = match option.setting {
                    Setting::NotApplicable => true,
                    _ => flag(switch_on, value, true)?,
                };
                if on {
                    s.notes.push(note(option, switch_on));
                }
            }
            _ => unreachable!("handled in apply"),
        }
        Ok(())
    }

    fn output_file(&mut self, on: bool, value: &str) -> Result<(), String> {
        let s = &mut self.settings;
        s.output_to_file = on;
        let mut chars = value.chars();
        if let Some(t) = chars.next() {
            let t = t.to_ascii_uppercase();
            if !"NETCPSBHJ".contains(t) {
                return Err(format!("unknown output file type `{t}`"));
            }
            s.file_type = t;
            let bits = chars.as_str();
            if !bits.is_empty() {
                s.bits_per_colour = whole(bits, 1..=16)?;
            }
            if !"NE".contains(t) {
                s.notes.push(format!(
                    "output file type `{t}`: penumbra writes png (N) or OpenEXR (E); writing png"
                ));
                s.file_type = 'N';
            }
        }
        Ok(())
    }
}

fn note(option: &PovOption, switch_on: Option<bool>) -> String {
    let name = match (switch_on, option.switch, option.ini) {
        (Some(_), Some(s), _) => format!("+{s}"),
        (_, _, Some(k)) => k.to_string(),
        (_, Some(s), None) => format!("+{s}"),
        _ => "option".to_string(),
    };
    format!(
        "note: `{name}` ({}) does not apply to penumbra; ignored",
        option.povray
    )
}

/// The text before a `;` comment (POV-Ray's INI comments; `//` too).
fn strip_comment(line: &str) -> &str {
    let end = [line.find(';'), line.find("//")]
        .into_iter()
        .flatten()
        .min()
        .unwrap_or(line.len());
    &line[..end]
}

fn strip_quotes(value: &str) -> &str {
    value
        .strip_prefix('"')
        .and_then(|v| v.strip_suffix('"'))
        .unwrap_or(value)
}

fn need(value: &str) -> Result<&str, String> {
    if value.is_empty() {
        Err("needs a value".into())
    } else {
        Ok(value)
    }
}

fn not_number(value: &str) -> String {
    format!("`{value}` is not a number")
}

fn number(value: &str) -> Result<f64, String> {
    value.trim().parse().map_err(|_| not_number(value))
}

fn integer(value: &str) -> Result<i64, String> {
    let x = number(value)?;
    if x.fract() != 0.0 {
        return Err(format!("`{value}` is not a whole number"));
    }
    Ok(x as i64)
}

fn whole(value: &str, range: std::ops::RangeInclusive<u32>) -> Result<u32, String> {
    let x = integer(value)?;
    if x < i64::from(*range.start()) || x > i64::from(*range.end()) {
        return Err(format!(
            "{x} is outside {}..={}",
            range.start(),
            range.end()
        ));
    }
    Ok(x as u32)
}

/// Samples per pixel: whole, or an adaptive render's fractional average, from 1 to 2^20.
fn samples(value: &str) -> Result<f64, String> {
    let x = number(value)?;
    if !crate::render::spp_in_range(x) {
        return Err(format!("{x} is outside 1..=1048576"));
    }
    Ok(x)
}

fn positive(value: &str) -> Result<u32, String> {
    whole(value, 1..=1 << 16)
}

/// A boolean: a switch's sign (a value after it, as in `+A0.3`, is not a boolean), or an
/// INI value (On/Off, True/False, Yes/No, 1/0). An empty INI value is `default`.
fn flag(switch_on: Option<bool>, value: &str, default: bool) -> Result<bool, String> {
    if let Some(on) = switch_on {
        return Ok(on);
    }
    match value.trim().to_ascii_lowercase().as_str() {
        "" => Ok(default),
        "on" | "true" | "yes" | "1" => Ok(true),
        "off" | "false" | "no" | "0" => Ok(false),
        _ => Err(format!("`{value}` is not On or Off")),
    }
}

fn bound(value: &str) -> Result<Bound, String> {
    let x = number(value)?;
    if value.contains('.') && (0.0..=1.0).contains(&x) {
        Ok(Bound::Fraction(x))
    } else {
        integer(value).map(Bound::Pixel)
    }
}

/// An end row or column: as [`bound`], but POV-Ray reads a plain 1 there as the fraction
/// 1.0, the whole image (measured: `+EC1` and `End_Row=1`, as advanced/benchmark's INI
/// writes them, render every column and row; `+EC2` ends at column 2, `+SC1` starts at 1).
fn end_bound(value: &str) -> Result<Bound, String> {
    match bound(value)? {
        Bound::Pixel(1) => Ok(Bound::Fraction(1.0)),
        b => Ok(b),
    }
}

/// `NAME=VALUE` with NAME an identifier and VALUE a float.
pub fn parse_declare(s: &str) -> Result<(String, f64), String> {
    let (name, value) = s
        .split_once('=')
        .ok_or_else(|| format!("expected NAME=VALUE, got `{s}`"))?;
    let value = number(value)?;
    let name = name.trim();
    let valid = name
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid {
        return Err(format!("`{name}` is not an identifier"));
    }
    Ok((name.to_string(), value))
}
