//! Static facts about a scene file, read without parsing it: the files it includes, the
//! cache key of its POV-Ray reference, whether its textures use POV-Ray's noise, and the INI
//! file it comes with.

use crate::output::Fnv;
use crate::study::media_quadrature;
use crate::study::reference::MediaQuadrature;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Words that make a scene's image depend on POV-Ray's private noise tables: noise-based
/// patterns, warps and normals, and the functions.inc functions built on them.
pub const NOISE_KEYWORDS: &[&str] = &[
    "agate",
    "bozo",
    "bumps",
    "cells",
    "crackle",
    "dents",
    "facets",
    "granite",
    "marble",
    "noise_generator",
    "ripples",
    "spotted",
    "turbulence",
    "waves",
    "wood",
    "wrinkles",
    "f_agate",
    "f_bozo",
    "f_bumps",
    "f_cells",
    "f_crackle",
    "f_dents",
    "f_granite",
    "f_hetero_mf",
    "f_marble",
    "f_noise3d",
    "f_noise_generator",
    "f_ridge",
    "f_ridged_mf",
    "f_snoise3d",
    "f_spotted",
    "f_wood",
    "f_wrinkles",
];

/// The example scenes under `dir` (following symbolic links), as sorted paths relative to it
/// with `/` separators.
pub fn list_scenes(dir: &Path) -> std::io::Result<Vec<String>> {
    let mut found = Vec::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(folder) = pending.pop() {
        for entry in std::fs::read_dir(&folder)? {
            let path = entry?.path();
            if path.is_dir() {
                pending.push(path);
            } else if path.extension().is_some_and(|e| e == "pov")
                && let Ok(rel) = path.strip_prefix(dir)
            {
                found.push(rel.to_string_lossy().replace('\\', "/"));
            }
        }
    }
    found.sort();
    Ok(found)
}

/// Shell-style matching of a whole path: `*` any run of characters (`/` included), `?` one.
pub fn glob_match(pattern: &str, text: &str) -> bool {
    let (p, t): (Vec<char>, Vec<char>) = (pattern.chars().collect(), text.chars().collect());
    let (mut pi, mut ti) = (0, 0);
    let mut star: Option<(usize, usize)> = None;
    while ti < t.len() {
        if pi < p.len() && (p[pi] == '?' || p[pi] == t[ti]) {
            pi += 1;
            ti += 1;
        } else if pi < p.len() && p[pi] == '*' {
            star = Some((pi, ti));
            pi += 1;
        } else if let Some((sp, st)) = star {
            pi = sp + 1;
            ti = st + 1;
            star = Some((sp, st + 1));
        } else {
            return false;
        }
    }
    p[pi..].iter().all(|&c| c == '*')
}

/// A file the scene reads and its text.
#[derive(Debug, Clone, PartialEq)]
pub struct SourceFile {
    pub path: PathBuf,
    pub text: String,
    /// In the scene's own folder tree (its content is the scene's), not a library include.
    pub local: bool,
}

/// The scene and, recursively, every `#include "name"` whose name is a literal string,
/// found in the scene's folder or in `include_dirs`. Includes named by expressions are
/// missed (the cache key then covers only what is found).
pub fn sources(scene: &Path, include_dirs: &[PathBuf]) -> std::io::Result<Vec<SourceFile>> {
    let folder = scene.parent().unwrap_or(Path::new(".")).to_path_buf();
    let mut files = vec![SourceFile {
        path: scene.to_path_buf(),
        text: read_lossy(scene)?,
        local: true,
    }];
    let mut seen: BTreeSet<PathBuf> = BTreeSet::from([scene.to_path_buf()]);
    let mut next = 0;
    while next < files.len() {
        for name in included_names(&files[next].text) {
            let found = std::iter::once(&folder)
                .chain(include_dirs)
                .map(|dir| dir.join(&name))
                .find(|p| p.is_file());
            if let Some(path) = found
                && seen.insert(path.clone())
                && let Ok(text) = read_lossy(&path)
            {
                let local = path.parent() == Some(folder.as_path());
                files.push(SourceFile { path, text, local });
            }
        }
        next += 1;
    }
    Ok(files)
}

fn read_lossy(path: &Path) -> std::io::Result<String> {
    Ok(String::from_utf8_lossy(&std::fs::read(path)?).into_owned())
}

/// The literal names of `#include "..."` directives outside comments.
pub fn included_names(text: &str) -> Vec<String> {
    let code = strip_comments(text);
    let mut names = Vec::new();
    let mut rest = code.as_str();
    while let Some(at) = rest.find("#include") {
        rest = rest[at + "#include".len()..].trim_start();
        if let Some(body) = rest.strip_prefix('"')
            && let Some(end) = body.find('"')
        {
            names.push(body[..end].to_string());
        }
    }
    names
}

/// The text with `//` and (nested) `/* */` comments replaced by spaces; strings kept.
pub fn strip_comments(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let (mut i, mut depth, mut in_string) = (0, 0usize, false);
    while i < bytes.len() {
        let two = &bytes[i..(i + 2).min(bytes.len())];
        if depth == 0 && !in_string && two == b"//" {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
        } else if !in_string && two == b"/*" {
            depth += 1;
            i += 2;
        } else if depth > 0 && two == b"*/" {
            depth -= 1;
            i += 2;
        } else if depth > 0 {
            i += 1;
        } else {
            if bytes[i] == b'"' {
                in_string = !in_string;
            }
            if bytes[i] == b'\n' {
                in_string = false;
            }
            out.push(bytes[i] as char);
            i += 1;
        }
    }
    out
}

/// Identifier-like words of code (comments already stripped).
fn words(code: &str) -> impl Iterator<Item = &str> {
    code.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| !w.is_empty())
}

/// Which noise keywords or noise-using identifiers the scene uses, sorted; empty when its
/// image does not depend on POV-Ray's noise. An identifier is noise-using when its
/// `#declare`, `#local` or `#macro` body (up to the next such directive) in any source names
/// a noise keyword or another noise-using identifier. Every word of the scene and of its
/// local includes counts as used (conservative: a declared but unused noisy texture counts).
pub fn noise_words(files: &[SourceFile]) -> Vec<String> {
    let keywords: BTreeSet<&str> = NOISE_KEYWORDS.iter().copied().collect();
    let codes: Vec<String> = files.iter().map(|f| strip_comments(&f.text)).collect();
    let mut chunks: Vec<(String, BTreeSet<String>)> = Vec::new();
    for code in &codes {
        // Other directives (#if, #end, ...) continue the body of the declaration before them.
        let mut current: Option<usize> = None;
        for piece in code.split('#').skip(1) {
            let mut ws = words(piece);
            let first = ws.next();
            if matches!(first, Some("declare" | "local" | "macro"))
                && let Some(name) = ws.next()
            {
                chunks.push((name.to_string(), ws.map(str::to_string).collect()));
                current = Some(chunks.len() - 1);
            } else if let Some(i) = current {
                chunks[i].1.extend(words(piece).map(str::to_string));
            }
        }
    }
    let mut noisy: BTreeSet<String> = keywords.iter().map(|k| k.to_string()).collect();
    loop {
        let before = noisy.len();
        for (name, body) in &chunks {
            if !noisy.contains(name) && body.iter().any(|w| noisy.contains(w)) {
                noisy.insert(name.clone());
            }
        }
        if noisy.len() == before {
            break;
        }
    }
    let mut used = BTreeSet::new();
    for (file, code) in files.iter().zip(&codes) {
        if file.local {
            used.extend(
                words(code)
                    .filter(|w| noisy.contains(*w))
                    .map(str::to_string),
            );
        }
    }
    used.into_iter().collect()
}

/// The INI file POV-Ray reads with the scene: `<stem>.ini` beside it, or an INI there whose
/// `Input_File_Name` names it.
pub fn ini_for(scene: &Path) -> Option<PathBuf> {
    let folder = scene.parent()?;
    let own = scene.with_extension("ini");
    if own.is_file() {
        return Some(own);
    }
    let name = scene.file_name()?.to_string_lossy().to_lowercase();
    let mut inis: Vec<PathBuf> = std::fs::read_dir(folder)
        .ok()?
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("ini")))
        .collect();
    inis.sort();
    inis.into_iter().find(|ini| {
        ini_value(&read_lossy(ini).unwrap_or_default(), "Input_File_Name")
            .is_some_and(|v| v.to_lowercase() == name)
    })
}

/// The value of `key=value` in INI text (case-insensitive key, `;` comments skipped).
pub fn ini_value(text: &str, key: &str) -> Option<String> {
    text.lines()
        .map(|l| l.split(';').next().unwrap_or("").trim())
        .filter_map(|l| l.split_once('='))
        .find(|(k, _)| k.trim().eq_ignore_ascii_case(key))
        .map(|(_, v)| v.trim().trim_matches('"').to_string())
}

/// POV-Ray's options for a scene with an INI: the INI itself and its first frame.
pub fn ini_args(ini: &Path) -> Vec<String> {
    let mut args = vec![ini.display().to_string()];
    args.extend(first_frame_args(ini));
    args
}

/// When the INI animates, the switches that render only its first frame (`+SF +EF`, so the
/// clock stays the animation's initial clock).
/// The frames may be given as keys (`Final_Frame=20`) or as switches on a line
/// (`+kff20`, as animations/splinefollow's INI does).
pub fn first_frame_args(ini: &Path) -> Vec<String> {
    let text = read_lossy(ini).unwrap_or_default();
    if ini_value(&text, "Final_Frame")
        .or_else(|| ini_switch(&text, "KFF"))
        .is_none()
    {
        return Vec::new();
    }
    let first = ini_value(&text, "Initial_Frame")
        .or_else(|| ini_switch(&text, "KFI"))
        .and_then(|v| v.parse::<i64>().ok())
        .unwrap_or(1);
    vec![format!("+SF{first}"), format!("+EF{first}")]
}

/// The value of a switch (`+KFF20`, `-kff20`: `20`) written in an INI's lines.
fn ini_switch(text: &str, name: &str) -> Option<String> {
    text.lines()
        .map(|l| l.split(';').next().unwrap_or(""))
        .flat_map(str::split_whitespace)
        .filter_map(|w| w.strip_prefix('+').or_else(|| w.strip_prefix('-')))
        .find(|w| {
            w.len() > name.len()
                && w.get(..name.len())
                    .is_some_and(|p| p.eq_ignore_ascii_case(name))
        })
        .map(|w| w[name.len()..].to_string())
}

/// What a cached reference depends on.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceKey<'a> {
    pub files: &'a [SourceFile],
    pub width: u32,
    pub height: u32,
    pub supersample: u32,
    pub povray_version: &'a str,
    pub extra_args: &'a [String],
    pub media: MediaQuadrature,
}

impl ReferenceKey<'_> {
    /// The cache file's name: the scene's path with `/` as `_`, then the hash.
    pub fn file_name(&self, scene: &str) -> String {
        let mut h = Fnv::default();
        h.write_field(b"penumbra corpus reference v1");
        h.write_field(self.povray_version.as_bytes());
        h.write_field(format!("{}x{} k={}", self.width, self.height, self.supersample).as_bytes());
        // As-written keys are those of before the option existed, so their caches stay valid.
        if self.media == MediaQuadrature::Converged {
            h.write_field(media_quadrature::CONVERGED_SETTINGS.as_bytes());
        }
        for arg in self.extra_args {
            h.write_field(arg.as_bytes());
            if let Ok(text) = std::fs::read(arg) {
                h.write_field(&text);
            }
        }
        for file in self.files {
            h.write_field(file.path.to_string_lossy().as_bytes());
            h.write_field(file.text.as_bytes());
        }
        format!("{}-{:016x}.exr", flat_name(scene), h.finish())
    }
}

/// A scene's relative path as one file name: `textures/patterns/bozo.pov` becomes
/// `textures_patterns_bozo`.
pub fn flat_name(scene: &str) -> String {
    scene.trim_end_matches(".pov").replace('/', "_")
}
