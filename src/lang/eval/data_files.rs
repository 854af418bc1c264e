//! `#fopen`, `#read`, `#write`, `#fclose`: data files, inside a sandbox at least as tight
//! as POV-Ray's I/O restrictions. Reading finds files where includes are found (the
//! scene's folder, the include paths, POV-Ray's include folder) and in the write folder;
//! writing needs `--allow-write DIR` and stays inside DIR. A path may not climb out with
//! `..`, be absolute, follow a symbolic link out of its folder, or name anything but a
//! regular file. Written text is kept in memory and written (to a temporary name, then
//! renamed) at `#fclose` or when the scene ends, so a refused write leaves nothing behind.
//!
//! Measured with POV-Ray 3.7: `#write` puts floats as C's `%g` (0.333333, 1e+20), vectors
//! as `<1,2,3> `, strings as they are, with nothing between items; `#read` takes
//! comma-separated floats, vectors and strings, and at the end of the file closes it, so
//! `defined(F)` turns false.

use std::path::{Path, PathBuf};
use std::rc::Rc;

use super::super::diagnostics::Span;
use super::super::syntax::{Punct, Token, TokenKind};
use super::Evaluator;
use super::value::{Value, Vector};
use crate::lang::diagnostics::Diagnostic;

type R<T> = Result<T, Diagnostic>;

/// Largest data file a scene may read, and most text it may write to one file.
pub const MAX_DATA_FILE_BYTES: u64 = 64 << 20;

pub(super) enum DataFile {
    Read { tokens: Rc<[Token]>, pos: usize },
    Write { path: PathBuf, text: String },
}

impl Evaluator<'_> {
    /// `#fopen Name "file" read|write|append`.
    pub(super) fn fopen(&mut self) -> R<()> {
        let id = self.raw_next();
        let Some(handle) = id.ident().map(Rc::<str>::from) else {
            return Err(self.expected("a file identifier after `#fopen`", &id));
        };
        let (v, s) = self.expr()?;
        let Value::Str(name) = v else {
            return Err(self.err(
                s,
                format!("expected a file name string, found {}", v.kind_name()),
            ));
        };
        let mode = self.raw_next();
        let file = match mode.ident() {
            Some("read") => self.open_for_reading(&name, s)?,
            Some(m @ ("write" | "append")) => self.open_for_writing(&name, s, m == "append")?,
            _ => return Err(self.expected("`read`, `write` or `append`", &mode)),
        };
        if let Some(DataFile::Write { path, text }) = self.data_files.insert(handle, file) {
            self.flush_data_file(&path, &text, s)?;
        }
        Ok(())
    }

    /// `#fclose Name`; closing a file that is not open does nothing, as in POV-Ray.
    pub(super) fn fclose(&mut self) -> R<()> {
        let id = self.raw_next();
        let Some(handle) = id.ident() else {
            return Err(self.expected("a file identifier after `#fclose`", &id));
        };
        if let Some(DataFile::Write { path, text }) = self.data_files.remove(handle) {
            self.flush_data_file(&path, &text, id.span)?;
        }
        Ok(())
    }

    /// Writes every file still open for writing; at the end of the scene.
    pub(super) fn close_data_files(&mut self, at: Span) -> R<()> {
        let open: Vec<_> = self.data_files.drain().collect();
        for (_, f) in open {
            if let DataFile::Write { path, text } = f {
                self.flush_data_file(&path, &text, at)?;
            }
        }
        Ok(())
    }

    pub(super) fn is_open_data_file(&self, name: &str) -> bool {
        self.data_files.contains_key(name)
    }

    fn open_for_reading(&mut self, name: &str, span: Span) -> R<DataFile> {
        let path = self.readable_data_file(name, span)?;
        self.inputs.file(&path);
        let text = self
            .sources
            .read(&path)
            .map_err(|e| self.err(span, format!("cannot read \"{}\": {e}", path.display())))?;
        let id = self
            .files
            .add(path.display().to_string(), Rc::from(text.as_str()));
        let tokens = super::super::parse::tokenize(id, &text)?;
        Ok(DataFile::Read {
            tokens: tokens.tokens,
            pos: 0,
        })
    }

    /// Where a file to read is: found as includes are, or in the write folder, and still
    /// inside that folder once links are followed.
    fn readable_data_file(&self, name: &str, span: Span) -> R<PathBuf> {
        let refused =
            |why: &str| self.err(span, format!("refused: the data file \"{name}\" {why}"));
        if super::directives::escapes_folder(name) {
            return Err(refused(
                "is outside the allowed folders (the scene's folder, --include-path folders, POV-Ray's include folder, the --allow-write folder)",
            ));
        }
        let mut dirs = self.include_dirs();
        dirs.extend(self.allow_write.iter().cloned());
        let Some((dir, path)) = dirs
            .into_iter()
            .map(|d| (d.clone(), d.join(name)))
            .find(|(_, p)| p.exists())
        else {
            return Err(self.err(span, format!("cannot find the data file \"{name}\"")));
        };
        inside_folder(&dir, &path).map_err(refused)?;
        let meta = std::fs::metadata(&path)
            .map_err(|e| self.err(span, format!("cannot read \"{name}\": {e}")))?;
        if !meta.is_file() {
            return Err(refused("is not a regular file"));
        }
        if meta.len() > MAX_DATA_FILE_BYTES {
            return Err(refused(&format!(
                "is larger than the limit of {} MiB",
                MAX_DATA_FILE_BYTES >> 20
            )));
        }
        Ok(path)
    }

    fn open_for_writing(&mut self, name: &str, span: Span, append: bool) -> R<DataFile> {
        let Some(dir) = self.allow_write.clone() else {
            return Err(self.err(
                span,
                format!("refused: writing \"{name}\" needs --allow-write DIR (a folder the scene may write in)"),
            ));
        };
        if super::directives::escapes_folder(name) {
            return Err(self.err(
                span,
                format!("refused: the data file \"{name}\" is outside the --allow-write folder"),
            ));
        }
        let path = dir.join(name);
        let parent = path.parent().unwrap_or(&dir).to_path_buf();
        inside_folder(&dir, &parent)
            .map_err(|why| self.err(span, format!("refused: the data file \"{name}\" {why}")))?;
        let mut text = String::new();
        if let Ok(meta) = std::fs::symlink_metadata(&path) {
            if !meta.file_type().is_file() {
                return Err(self.err(
                    span,
                    format!("refused: \"{name}\" exists and is not a regular file (a link, a folder or a device)"),
                ));
            }
            if append {
                text = self.readable_existing(&path, meta.len(), name, span)?;
            }
        }
        Ok(DataFile::Write { path, text })
    }

    fn readable_existing(&self, path: &Path, len: u64, name: &str, span: Span) -> R<String> {
        if len > MAX_DATA_FILE_BYTES {
            return Err(self.err(
                span,
                format!("refused: \"{name}\" is larger than the limit"),
            ));
        }
        std::fs::read_to_string(path)
            .map_err(|e| self.err(span, format!("cannot read \"{name}\": {e}")))
    }

    fn flush_data_file(&self, path: &Path, text: &str, span: Span) -> R<()> {
        let tmp = path.with_extension("penumbra-partial");
        let written = std::fs::write(&tmp, text).and_then(|()| std::fs::rename(&tmp, path));
        written.map_err(|e| {
            let _ = std::fs::remove_file(&tmp);
            self.err(span, format!("cannot write \"{}\": {e}", path.display()))
        })
    }

    /// `#read (Name, A, B, ...)`. As in POV-Ray, the file closes as soon as its last value
    /// is read (so `defined(Name)` is false right after), and reading a closed file is an
    /// error; identifiers past the end keep what they had.
    pub(super) fn read_directive(&mut self) -> R<()> {
        self.expect(Punct::LParen, "after `#read`")?;
        let id = self.raw_next();
        let Some(handle) = id.ident().map(Rc::<str>::from) else {
            return Err(self.expected("a file identifier", &id));
        };
        if !self.data_files.contains_key(&handle) {
            return Err(self.err(id.span, format!("`{handle}` is not an open file")));
        }
        self.eat(Punct::Comma)?;
        while !self.peek()?.is_punct(Punct::RParen) {
            let var = self.raw_next();
            let Some(name) = var.ident().map(Rc::<str>::from) else {
                return Err(self.expected("an identifier to read into", &var));
            };
            if let Some(v) = self.next_data_value(&handle, id.span)? {
                self.assign(&name, v, false);
            }
            self.eat(Punct::Comma)?;
        }
        self.expect(Punct::RParen, "to close `#read`")?;
        Ok(())
    }

    /// The next value, or `None` once the file is closed. Values are separated by commas,
    /// also from one `#read` to the next: POV-Ray reads nothing after a value that no comma
    /// follows.
    fn next_data_value(&mut self, handle: &str, span: Span) -> R<Option<Value>> {
        let (tokens, at) = match self.data_files.get(handle) {
            Some(DataFile::Read { tokens, pos }) => (tokens.clone(), *pos),
            Some(DataFile::Write { .. }) => {
                return Err(self.err(span, format!("`{handle}` is open for writing, not reading")));
            }
            None => return Ok(None),
        };
        let Some((value, mut next)) = self.data_value(&tokens, at)? else {
            self.data_files.remove(handle);
            return Ok(None);
        };
        let comma = tokens.get(next).is_some_and(|t| t.is_punct(Punct::Comma));
        if comma {
            next += 1;
        }
        if !comma || next >= tokens.len() {
            self.data_files.remove(handle);
        } else if let Some(DataFile::Read { pos, .. }) = self.data_files.get_mut(handle) {
            *pos = next;
        }
        Ok(Some(value))
    }

    /// A float (with its sign), a string or a vector at `at`; `None` at the end.
    fn data_value(&self, tokens: &[Token], mut at: usize) -> R<Option<(Value, usize)>> {
        let Some(tok) = tokens.get(at) else {
            return Ok(None);
        };
        match &tok.kind {
            TokenKind::Str(s) => Ok(Some((Value::Str(Rc::from(*s)), at + 1))),
            TokenKind::Punct(Punct::Lt) => {
                let mut c = [0.0; 5];
                let mut len = 0usize;
                at += 1;
                loop {
                    let (x, next) = self.data_number(tokens, at)?;
                    if len == 5 {
                        return Err(
                            self.err(tok.span, "a vector in a data file has at most 5 components")
                        );
                    }
                    c[len] = x;
                    len += 1;
                    at = next;
                    match tokens.get(at) {
                        Some(t) if t.is_punct(Punct::Comma) => at += 1,
                        Some(t) if t.is_punct(Punct::Gt) => break,
                        _ => {
                            return Err(self.err(
                                tok.span,
                                "this vector in the data file is not closed with `>`",
                            ));
                        }
                    }
                }
                Ok(Some((Value::Vector(Vector { c, len: len as u8 }), at + 1)))
            }
            _ => {
                let (x, next) = self.data_number(tokens, at)?;
                Ok(Some((Value::Float(x), next)))
            }
        }
    }

    fn data_number(&self, tokens: &[Token], at: usize) -> R<(f64, usize)> {
        let (sign, at) = match tokens.get(at) {
            Some(t) if t.is_punct(Punct::Minus) => (-1.0, at + 1),
            Some(t) if t.is_punct(Punct::Plus) => (1.0, at + 1),
            _ => (1.0, at),
        };
        match tokens.get(at) {
            Some(Token {
                kind: TokenKind::Number(n),
                ..
            }) => Ok((sign * n, at + 1)),
            Some(t) => Err(self.err(
                t.span,
                format!("expected a number in the data file, found {}", t.describe()),
            )),
            None => Err(self.err(Span::DETACHED, "the data file ends inside a value")),
        }
    }

    /// `#write (Name, item, ...)`.
    pub(super) fn write_directive(&mut self) -> R<()> {
        self.expect(Punct::LParen, "after `#write`")?;
        let id = self.raw_next();
        let Some(handle) = id.ident().map(Rc::<str>::from) else {
            return Err(self.expected("a file identifier", &id));
        };
        let mut out = String::new();
        // html_gen.inc writes `#write(File Header1)`: the commas are optional, as POV-Ray
        // reads them.
        self.eat(Punct::Comma)?;
        while !self.peek()?.is_punct(Punct::RParen) {
            let (v, s) = self.expr()?;
            write_value(&mut out, &v).map_err(|m| self.err(s, m))?;
            self.eat(Punct::Comma)?;
        }
        self.expect(Punct::RParen, "to close `#write`")?;
        match self.data_files.get_mut(&*handle) {
            Some(DataFile::Write { text, .. }) => {
                if (text.len() + out.len()) as u64 > MAX_DATA_FILE_BYTES {
                    return Err(
                        self.err(id.span, "refused: this data file would grow past the limit")
                    );
                }
                text.push_str(&out);
                Ok(())
            }
            Some(DataFile::Read { .. }) => Err(self.err(
                id.span,
                format!("`{handle}` is open for reading, not writing"),
            )),
            None => Err(self.err(id.span, format!("`{handle}` is not an open file"))),
        }
    }
}

fn write_value(out: &mut String, v: &Value) -> Result<(), String> {
    match v {
        Value::Str(s) => out.push_str(s),
        Value::Float(f) => out.push_str(&format_g(*f)),
        Value::Vector(v) => {
            let parts: Vec<String> = v.c[..usize::from(v.len)]
                .iter()
                .map(|x| format_g(*x))
                .collect();
            out.push_str(&format!("<{}> ", parts.join(",")));
        }
        other => {
            return Err(format!(
                "`#write` takes floats, vectors and strings, found {}",
                other.kind_name()
            ));
        }
    }
    Ok(())
}

/// C's `%g`: six significant digits, trailing zeros dropped, an exponent below 1e-4 or from
/// 1e6 on.
fn format_g(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return if x.is_nan() {
            "nan".into()
        } else if x.is_infinite() {
            if x > 0.0 { "inf".into() } else { "-inf".into() }
        } else {
            "0".into()
        };
    }
    let exp = x.abs().log10().floor() as i32;
    let trim = |s: String| {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    };
    // Rounding to six digits can carry into the next power of ten.
    let rounded: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    let exp = if rounded.abs() >= 10f64.powi(exp + 1) {
        exp + 1
    } else {
        exp
    };
    if (-4..6).contains(&exp) {
        let decimals = (5 - exp).max(0) as usize;
        trim(format!("{x:.decimals$}"))
    } else {
        let m = format!("{:.5e}", x);
        let (mant, e) = m.split_once('e').unwrap_or((&m, "0"));
        let e: i32 = e.parse().unwrap_or(0);
        format!(
            "{}e{}{:02}",
            trim(mant.to_string()),
            if e < 0 { '-' } else { '+' },
            e.abs()
        )
    }
}

/// Whether `path` (once links are followed) is inside `dir`.
fn inside_folder(dir: &Path, path: &Path) -> Result<(), &'static str> {
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    let dir = std::fs::canonicalize(dir).map_err(|_| "is in a folder that does not exist")?;
    let real = std::fs::canonicalize(path).map_err(|_| "cannot be found")?;
    if !real.starts_with(&dir) {
        return Err("leads outside its folder (through a symbolic link)");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::format_g;

    #[test]
    fn floats_are_written_as_povray_writes_them() {
        // POV-Ray 3.7 wrote 5, 0.1, 1/3, 1e20 and -2.5 as these.
        for (x, want) in [
            (5.0, "5"),
            (0.1, "0.1"),
            (1.0 / 3.0, "0.333333"),
            (1e20, "1e+20"),
            (-2.5, "-2.5"),
        ] {
            assert_eq!(format_g(x), want);
        }
        assert_eq!(format_g(999999.5), "1e+06");
        assert_eq!(format_g(0.0001234), "0.0001234");
        assert_eq!(format_g(0.00001234), "1.234e-05");
    }
}
