//! Diagnostics: one error type for the whole language, printed like rustc so a user sees
//! the file, line, column and the offending text at once.
//!
//! Spans stay small and copyable (a file id and a byte range) while the scene is read; line
//! and column are worked out only when a diagnostic leaves the language module, because most
//! spans are never printed.

use std::fmt;

/// Which source file a span points into; an index into the loader's file table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct FileId(pub u32);

/// A byte range in one source file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Span {
    pub file: FileId,
    pub start: u32,
    pub end: u32,
}

impl Span {
    /// For values the evaluator makes up (built-in identifiers, `--declare` values): they
    /// have no text to point at.
    pub const DETACHED: Span = Span {
        file: FileId(u32::MAX),
        start: 0,
        end: 0,
    };

    pub fn new(file: FileId, start: usize, end: usize) -> Span {
        Span {
            file,
            start: start.min(u32::MAX as usize) as u32,
            end: end.min(u32::MAX as usize) as u32,
        }
    }

    pub fn is_detached(&self) -> bool {
        self.file == Span::DETACHED.file
    }

    /// The smallest span covering both, when they are in the same file.
    pub fn join(self, other: Span) -> Span {
        if self.file != other.file {
            return self;
        }
        Span {
            file: self.file,
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    Error,
    Warning,
}

/// Where a span lands once its file is known: what the printed form needs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    pub file: String,
    /// 1-based.
    pub line: usize,
    /// 1-based, in characters.
    pub column: usize,
    pub line_text: String,
    /// Characters to underline (at least 1).
    pub width: usize,
}

/// A step of the chain that led to an error: "in macro `Foo`", "in file included here".
#[derive(Clone, Debug, PartialEq)]
pub struct TracePoint {
    pub message: String,
    pub span: Span,
    pub location: Option<Location>,
}

/// An error or warning with its position, hints and the include/macro chain. Boxed, so
/// that the evaluator's `Result<_, Diagnostic>`, returned by every token read and every
/// expression, is no larger than its value: errors are rare, results are not.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic(Box<DiagnosticData>);

/// What a [`Diagnostic`] holds (read and written through it).
#[derive(Clone, Debug, PartialEq)]
pub struct DiagnosticData {
    pub severity: Severity,
    pub message: String,
    pub span: Span,
    pub hints: Vec<String>,
    pub trace: Vec<TracePoint>,
    /// Filled in by [`Files::resolve`] before the diagnostic is handed out.
    pub location: Option<Box<Location>>,
}

impl std::ops::Deref for Diagnostic {
    type Target = DiagnosticData;
    fn deref(&self) -> &DiagnosticData {
        &self.0
    }
}

impl std::ops::DerefMut for Diagnostic {
    fn deref_mut(&mut self) -> &mut DiagnosticData {
        &mut self.0
    }
}

impl Diagnostic {
    pub fn error(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic(Box::new(DiagnosticData {
            severity: Severity::Error,
            message: message.into(),
            span,
            hints: Vec::new(),
            trace: Vec::new(),
            location: None,
        }))
    }

    pub fn warning(span: Span, message: impl Into<String>) -> Diagnostic {
        let mut d = Diagnostic::error(span, message);
        d.severity = Severity::Warning;
        d
    }

    pub fn with_hint(mut self, hint: impl Into<String>) -> Diagnostic {
        self.hints.push(hint.into());
        self
    }

    pub fn line(&self) -> Option<usize> {
        self.location.as_ref().map(|l| l.line)
    }

    pub fn column(&self) -> Option<usize> {
        self.location.as_ref().map(|l| l.column)
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let label = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        writeln!(f, "{label}: {}", self.message)?;
        let width = self
            .location
            .as_ref()
            .map_or(1, |l| l.line.to_string().len());
        let pad = " ".repeat(width);
        if let Some(loc) = &self.location {
            writeln!(f, "{pad}--> {}:{}:{}", loc.file, loc.line, loc.column)?;
            writeln!(f, "{pad} |")?;
            writeln!(f, "{} | {}", loc.line, loc.line_text)?;
            // Copy tabs from the source line so the carets line up in any tab width.
            let lead: String = loc
                .line_text
                .chars()
                .take(loc.column.saturating_sub(1))
                .map(|c| if c == '\t' { '\t' } else { ' ' })
                .collect();
            write!(f, "{pad} | {lead}{}", "^".repeat(loc.width.max(1)))?;
        }
        for hint in &self.hints {
            write!(f, "\n{pad} = help: {hint}")?;
        }
        for point in &self.trace {
            write!(f, "\n{pad} = note: {}", point.message)?;
            if let Some(loc) = &point.location {
                write!(f, " at {}:{}:{}", loc.file, loc.line, loc.column)?;
            }
        }
        Ok(())
    }
}

impl std::error::Error for Diagnostic {}

/// The source files read so far, so spans can be turned into lines and columns.
#[derive(Default, Debug)]
pub struct Files {
    files: Vec<(String, std::rc::Rc<str>)>,
}

impl Files {
    pub fn add(&mut self, name: String, text: std::rc::Rc<str>) -> FileId {
        self.files.push((name, text));
        FileId((self.files.len() - 1) as u32)
    }

    pub fn name(&self, id: FileId) -> Option<&str> {
        self.files.get(id.0 as usize).map(|(n, _)| n.as_str())
    }

    pub fn text(&self, id: FileId) -> Option<&std::rc::Rc<str>> {
        self.files.get(id.0 as usize).map(|(_, t)| t)
    }

    pub fn locate(&self, span: Span) -> Option<Location> {
        let (name, text) = self.files.get(span.file.0 as usize)?;
        let start = floor_char_boundary(text, span.start as usize);
        let end = floor_char_boundary(text, (span.end as usize).max(start));
        let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
        let line = text[..start].matches('\n').count() + 1;
        let column = text[line_start..start].chars().count() + 1;
        let width = text[start..end.min(line_end).max(start)].chars().count();
        Some(Location {
            file: name.clone(),
            line,
            column,
            line_text: text[line_start..line_end]
                .trim_end_matches('\r')
                .to_string(),
            width: width.max(1),
        })
    }

    /// Attaches line/column information so the diagnostic prints without the file table.
    pub fn resolve(&self, mut diag: Diagnostic) -> Diagnostic {
        diag.location = self.locate(diag.span).map(Box::new);
        for point in &mut diag.trace {
            point.location = self.locate(point.span);
        }
        diag
    }
}

fn floor_char_boundary(text: &str, mut i: usize) -> usize {
    i = i.min(text.len());
    while i > 0 && !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// Levenshtein distance, for "did you mean" hints.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != *cb);
            cur[j + 1] = (prev[j] + cost).min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// The closest candidate, if it is close enough to be a plausible typo.
pub fn nearest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (name.chars().count() / 3).max(1);
    let mut best: Option<(usize, &str)> = None;
    for c in candidates {
        if c == name {
            continue;
        }
        let d = edit_distance(&name.to_lowercase(), &c.to_lowercase()).min(edit_distance(name, c));
        if d <= limit && best.is_none_or(|(bd, bc)| d < bd || (d == bd && c < bc)) {
            best = Some((d, c));
        }
    }
    best.map(|(_, c)| c)
}
