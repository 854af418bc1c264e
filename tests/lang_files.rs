//! Runs every `.pov` file under tests/lang/ and checks the expectations written in its
//! comments (see tests/lang/README.md). Adding a case is adding a file.

#[path = "lang_files/probe.rs"]
mod probe;

use std::path::{Path, PathBuf};

use penumbra::lang::{
    Diagnostic, LoadOptions, Loaded, Severity, SourceFiles, load_reading_globals, parse_memory_size,
};

/// Reads names relative to tests/lang, so diagnostics name files the same way on every
/// machine (`diagnostics/macro_trace.pov:4:1`).
struct Rooted(PathBuf);

impl Rooted {
    fn full(&self, path: &Path) -> PathBuf {
        if path.is_relative() {
            self.0.join(path)
        } else {
            path.to_path_buf()
        }
    }
}

impl SourceFiles for Rooted {
    fn read(&self, path: &Path) -> std::io::Result<String> {
        let bytes = std::fs::read(self.full(path))?;
        Ok(String::from_utf8_lossy(&bytes).into_owned())
    }

    fn exists(&self, path: &Path) -> bool {
        self.full(path).is_file()
    }
}

/// One `// kind: text` comment, with its line in the file.
struct Expect {
    line: usize,
    kind: String,
    text: String,
}

const KINDS: &[&str] = &[
    "error", "hint", "note", "rendered", "warning", "debug", "value", "model",
];
const SETTINGS: &[&str] = &["declare", "image", "include-path", "options", "max-memory"];

fn expectations(source: &str) -> Vec<Expect> {
    let mut out = Vec::new();
    for (i, line) in source.lines().enumerate() {
        let Some(rest) = line.trim_start().strip_prefix("// ") else {
            continue;
        };
        let Some((kind, text)) = rest.split_once(':') else {
            continue;
        };
        if KINDS.contains(&kind) || SETTINGS.contains(&kind) {
            // One space after the colon belongs to the syntax; the rest is the text.
            let text = text.strip_prefix(' ').unwrap_or(text);
            out.push(Expect {
                line: i + 1,
                kind: kind.to_string(),
                text: text.to_string(),
            });
        }
    }
    out
}

fn options(expects: &[Expect]) -> Result<(LoadOptions, bool), String> {
    let mut o = LoadOptions::default();
    let mut skip = false;
    for e in expects {
        let bad = || format!("line {}: cannot read `{}: {}`", e.line, e.kind, e.text);
        match e.kind.as_str() {
            "declare" => {
                let (name, value) = e.text.split_once('=').ok_or_else(bad)?;
                let value = value.trim().parse().map_err(|_| bad())?;
                o.declares.push((name.trim().to_string(), value));
            }
            "image" => {
                let (w, h) = e.text.trim().split_once('x').ok_or_else(bad)?;
                o.image_width = w.parse().map_err(|_| bad())?;
                o.image_height = h.parse().map_err(|_| bad())?;
            }
            "include-path" => o.include_paths.push(PathBuf::from(e.text.trim())),
            "max-memory" => o.max_memory = Some(parse_memory_size(&e.text).map_err(|_| bad())?),
            "options" if e.text.trim() == "skip-unsupported" => skip = true,
            "options" => return Err(bad()),
            _ => {}
        }
    }
    Ok((o, skip))
}

/// `[FILE:]L:C message`.
fn position(text: &str) -> Option<(Option<&str>, usize, usize, &str)> {
    let (place, message) = text.split_once(' ')?;
    let mut parts: Vec<&str> = place.rsplitn(3, ':').collect();
    parts.reverse();
    let (file, line, column) = match parts.as_slice() {
        [f, l, c] if l.parse::<usize>().is_ok() => (Some(*f), *l, *c),
        [l, c] => (None, *l, *c),
        _ => return None,
    };
    Some((file, line.parse().ok()?, column.parse().ok()?, message))
}

/// Compares one diagnostic with an `error:`/`warning:` expectation and the `hint:`/`note:`
/// lines attached to it; returns the differences.
fn check_diagnostic(
    d: &Diagnostic,
    e: &Expect,
    hints: &[&Expect],
    notes: &[&Expect],
) -> Vec<String> {
    let mut out = Vec::new();
    let Some((file, line, column, message)) = position(&e.text) else {
        return vec![format!("{}: cannot read `{}: {}`", e.line, e.kind, e.text)];
    };
    let loc = d.location.as_ref();
    let actual = format!(
        "{}:{}:{} {}",
        loc.map_or("?", |l| l.file.as_str()),
        d.line().unwrap_or(0),
        d.column().unwrap_or(0),
        d.message
    );
    let same_file = file.is_none_or(|f| loc.is_some_and(|l| l.file == f));
    if d.message != message || d.line() != Some(line) || d.column() != Some(column) || !same_file {
        out.push(format!(
            "{}: expected {}: {}\n    got {actual}",
            e.line, e.kind, e.text
        ));
    }
    if !hints.is_empty() {
        let want: Vec<&str> = hints.iter().map(|h| h.text.as_str()).collect();
        if d.hints != want {
            out.push(format!(
                "{}: expected hints {want:?}\n    got {:?}",
                hints[0].line, d.hints
            ));
        }
    }
    let severity = if e.kind == "warning" {
        Severity::Warning
    } else {
        Severity::Error
    };
    if d.severity != severity {
        out.push(format!(
            "{}: expected {severity:?}, got {:?}",
            e.line, d.severity
        ));
    }
    let rendered = d.to_string();
    for n in notes {
        let line = format!("= note: {}", n.text);
        if !rendered.lines().any(|l| l.trim() == line) {
            out.push(format!(
                "{}: expected note `{}` in\n{rendered}",
                n.line, n.text
            ));
        }
    }
    out
}

/// `hint:` and `note:` lines belong to the `error:` or `warning:` above them, or to the
/// error if none is above.
fn attached(expects: &[Expect], owner: usize, first: usize) -> (Vec<&Expect>, Vec<&Expect>) {
    let mut hints = Vec::new();
    let mut notes = Vec::new();
    let mut current = None;
    for (i, e) in expects.iter().enumerate() {
        match e.kind.as_str() {
            "error" | "warning" => current = Some(i),
            "hint" if current.unwrap_or(first) == owner => hints.push(e),
            "note" if current.unwrap_or(first) == owner => notes.push(e),
            _ => {}
        }
    }
    (hints, notes)
}

fn check_error(d: &Diagnostic, expects: &[Expect]) -> Vec<String> {
    let Some(owner) = expects.iter().position(|e| e.kind == "error") else {
        return vec![format!("unexpected error:\n{d}")];
    };
    let (hints, notes) = attached(expects, owner, owner);
    let mut out = check_diagnostic(d, &expects[owner], &hints, &notes);
    let rendered: Vec<&Expect> = expects.iter().filter(|e| e.kind == "rendered").collect();
    if !rendered.is_empty() {
        let want: Vec<&str> = rendered.iter().map(|e| e.text.as_str()).collect();
        let text = d.to_string();
        if text.lines().collect::<Vec<_>>() != want {
            out.push(format!(
                "{}: expected the error to render as\n{}\n    got\n{text}",
                rendered[0].line,
                want.join("\n")
            ));
        }
    }
    for e in expects
        .iter()
        .filter(|e| matches!(e.kind.as_str(), "warning" | "debug" | "value" | "model"))
    {
        out.push(format!(
            "{}: `{}:` cannot be checked in a file that fails to load",
            e.line, e.kind
        ));
    }
    out
}

fn check_warnings(loaded: &Loaded, expects: &[Expect]) -> Vec<String> {
    let mut out = Vec::new();
    let first = expects
        .iter()
        .position(|e| e.kind == "warning")
        .unwrap_or(0);
    let wanted: Vec<usize> = (0..expects.len())
        .filter(|&i| expects[i].kind == "warning")
        .collect();
    for (n, w) in loaded.warnings.iter().enumerate() {
        match wanted.get(n) {
            Some(&i) => {
                let (hints, notes) = attached(expects, i, first);
                out.extend(check_diagnostic(w, &expects[i], &hints, &notes));
            }
            None => out.push(format!("unexpected warning:\n{w}")),
        }
    }
    for &i in wanted.iter().skip(loaded.warnings.len()) {
        out.push(format!(
            "{}: expected warning: {}, but there was none",
            expects[i].line, expects[i].text
        ));
    }
    out
}

fn check_debug(loaded: &Loaded, expects: &[Expect]) -> Vec<String> {
    let want: Vec<&Expect> = expects.iter().filter(|e| e.kind == "debug").collect();
    let got: Vec<&str> = loaded.debug.lines().collect();
    let want_text: Vec<&str> = want.iter().map(|e| e.text.as_str()).collect();
    match want.first() {
        Some(first) if got != want_text => vec![format!(
            "{}: expected #debug output\n{}\n    got\n{}",
            first.line,
            want_text.join("\n"),
            got.join("\n")
        )],
        _ => Vec::new(),
    }
}

/// `EXPECTED [within TOLERANCE]`.
fn tolerance(text: &str) -> (&str, Option<f64>) {
    match text.rsplit_once(" within ") {
        Some((v, t)) => match t.trim().parse() {
            Ok(t) => (v.trim(), Some(t)),
            Err(_) => (text.trim(), None),
        },
        None => (text.trim(), None),
    }
}

fn check_values(values: &[(&Expect, &str, Option<String>)]) -> Vec<String> {
    let mut out = Vec::new();
    for (e, name, got) in values {
        let (_, want) = e.text.split_once('=').unwrap_or_default();
        let (want, tol) = tolerance(want);
        let ok = match (probe::parse(want), got) {
            (Ok(w), Some(g)) => probe::parse(g).is_ok_and(|g| probe::matches(&w, &g, tol)),
            _ => false,
        };
        if !ok {
            let got = got.as_deref().unwrap_or("undefined");
            out.push(format!(
                "{}: expected {name} = {want}\n    got {got}",
                e.line
            ));
        }
    }
    out
}

fn check_model(root: &probe::Node, e: &Expect) -> Result<(), String> {
    let text = e.text.trim();
    if let Some((path, rest)) = text
        .split_once(" maps ")
        .or_else(|| text.split_once(" unmaps "))
    {
        let forward = text.contains(" maps ");
        let (from, to) = rest
            .split_once(" to ")
            .ok_or("write `PATH maps <p> to <q>`")?;
        let (to, tol) = tolerance(to);
        let point = |s: &str| probe::parse(s).ok().and_then(|n| probe::vector(&n));
        let (p, q) = (
            point(from).ok_or("bad point")?,
            point(to).ok_or("bad point")?,
        );
        let t = probe::follow(root, path)?;
        let affine = probe::follow(&t, if forward { "forward" } else { "inverse" })?;
        let got = probe::apply(&affine, p).ok_or_else(|| format!("{path} is not a transform"))?;
        let ok = (0..3).all(|i| {
            probe::matches(
                &probe::Node::Atom(q[i].to_string()),
                &probe::Node::Atom(got[i].to_string()),
                tol,
            )
        });
        return if ok {
            Ok(())
        } else {
            Err(format!("got <{}, {}, {}>", got[0], got[1], got[2]))
        };
    }
    let (path, want) = text
        .split_once(" = ")
        .ok_or("write `PATH = VALUE` or `PATH maps <p> to <q>`")?;
    let (want, tol) = tolerance(want);
    let want = probe::parse(want)?;
    let got = probe::follow(root, path.trim())?;
    if probe::matches(&want, &got, tol) {
        Ok(())
    } else {
        Err(format!("got {got}"))
    }
}

fn check_loaded(loaded: &Loaded, expects: &[Expect], values: Vec<Option<String>>) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(e) = expects.iter().find(|e| e.kind == "error") {
        out.push(format!(
            "{}: expected error: {}, but the file loaded",
            e.line, e.text
        ));
    }
    out.extend(check_warnings(loaded, expects));
    out.extend(check_debug(loaded, expects));
    let named: Vec<(&Expect, &str, Option<String>)> = expects
        .iter()
        .filter(|e| e.kind == "value")
        .zip(values)
        .map(|(e, v)| (e, e.text.split_once('=').map_or("", |(n, _)| n.trim()), v))
        .collect();
    out.extend(check_values(&named));
    let models: Vec<&Expect> = expects.iter().filter(|e| e.kind == "model").collect();
    if !models.is_empty() {
        match probe::parse(&format!("{:?}", loaded.scene)) {
            Ok(root) => {
                for e in models {
                    if let Err(why) = check_model(&root, e) {
                        out.push(format!("{}: expected model: {}\n    {why}", e.line, e.text));
                    }
                }
            }
            Err(why) => out.push(format!("cannot read the scene's Debug form: {why}")),
        }
    }
    out
}

fn run_file(root: &Path, name: &str) -> Vec<String> {
    let source = match std::fs::read_to_string(root.join(name)) {
        Ok(s) => s,
        Err(e) => return vec![format!("cannot read: {e}")],
    };
    let expects = expectations(&source);
    if !expects.iter().any(|e| KINDS.contains(&e.kind.as_str())) {
        return vec!["the file expects nothing (add `// error:`, `// value:` ...)".into()];
    }
    if expects.iter().filter(|e| e.kind == "error").count() > 1 {
        return vec!["more than one `// error:`".into()];
    }
    let (options, skip) = match options(&expects) {
        Ok(o) => o,
        Err(e) => return vec![e],
    };
    let globals: Vec<String> = expects
        .iter()
        .filter(|e| e.kind == "value")
        .map(|e| {
            e.text
                .split_once('=')
                .map_or("", |(n, _)| n.trim())
                .to_string()
        })
        .collect();
    let files = Rooted(root.to_path_buf());
    match load_reading_globals(name, &source, &options, &files, skip, &globals) {
        Err(d) => check_error(&d, &expects),
        Ok((loaded, values)) => check_loaded(&loaded, &expects, values),
    }
}

fn walk(root: &Path, dir: &Path, out: &mut Vec<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            walk(root, &path, out);
        } else if path.extension().is_some_and(|x| x == "pov") {
            let rel = path.strip_prefix(root).unwrap_or(&path);
            let parts: Vec<String> = rel
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            out.push(parts.join("/"));
        }
    }
}

#[test]
fn lang_files() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/lang");
    let mut names = Vec::new();
    walk(&root, &root, &mut names);
    names.sort();
    assert!(!names.is_empty(), "no .pov files under {}", root.display());
    let mut failures = Vec::new();
    for name in &names {
        for f in run_file(&root, name) {
            // Failures that start with the expectation's line read `file:line: ...`.
            let sep = if f.starts_with(|c: char| c.is_ascii_digit()) {
                ":"
            } else {
                ": "
            };
            failures.push(format!("tests/lang/{name}{sep}{f}"));
        }
    }
    println!("{} scene files checked", names.len());
    assert!(
        failures.is_empty(),
        "{} of the checks in {} files failed:\n\n{}",
        failures.len(),
        names.len(),
        failures.join("\n\n")
    );
}
