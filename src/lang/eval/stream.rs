//! The token stream: a stack of frames (files, macro bodies) and the state of open
//! `#if`/`#while`/`#for` blocks. Directives and macro calls are run here, as they are met.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::rc::Rc;

use super::super::diagnostics::{Diagnostic, FileId, Span, TracePoint};
use super::super::parse::{intern, tokenize};
use super::super::syntax::{Name, Token, TokenKind};
use super::Evaluator;
use super::value::{MacroDef, Value};

/// One scope of identifiers. Names are hashed on every use, so the hash is a cheap one
/// (FxHash's multiply-rotate) rather than SipHash: scene files are not hostile to it in a
/// way that matters, as a scope holds at most what the scene itself declares.
pub(super) type Scope = HashMap<Key, Value, BuildHasherDefault<NameHasher>>;

/// A scope's name: interned, so that a lookup by a token's name (the same interned copy)
/// is settled by comparing addresses, not text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) struct Key(NameRef<'static>);

impl Key {
    /// The key of a token's name (or of any text that lives as long).
    pub(super) fn new(name: Name) -> Key {
        Key(NameRef(name))
    }

    /// The key of any text: its interned copy.
    pub(super) fn of(name: &str) -> Key {
        Key(NameRef(intern(name)))
    }

    pub(super) fn text(&self) -> &'static str {
        self.0.0
    }
}

impl<'a> std::borrow::Borrow<NameRef<'a>> for Key {
    fn borrow(&self) -> &NameRef<'a> {
        &self.0
    }
}

/// A name to look up: equal to a key of the same text, at once when it is the key's own
/// interned copy.
#[derive(Clone, Copy, Debug)]
pub(super) struct NameRef<'a>(pub &'a str);

impl PartialEq for NameRef<'_> {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self.0, other.0) || self.0 == other.0
    }
}

impl Eq for NameRef<'_> {}

impl std::hash::Hash for NameRef<'_> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.hash(state);
    }
}

/// FxHash: a word at a time, rotate, xor, multiply.
#[derive(Default, Clone, Copy)]
pub(super) struct NameHasher(u64);

impl NameHasher {
    const K: u64 = 0xf135_7aea_2e62_a9c5;

    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(Self::K);
    }
}

impl Hasher for NameHasher {
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for c in &mut chunks {
            let mut w = [0u8; 8];
            w.copy_from_slice(c);
            self.add(u64::from_le_bytes(w));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            // Byte by byte: a copy of a variable length would call memcpy.
            self.add(rest.iter().rev().fold(0, |w, &b| w << 8 | u64::from(b)));
        }
    }

    fn write_u8(&mut self, i: u8) {
        self.add(u64::from(i));
    }

    fn write_u32(&mut self, i: u32) {
        self.add(u64::from(i));
    }

    fn write_usize(&mut self, i: usize) {
        self.add(i as u64);
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

pub(super) enum FrameKind {
    Root,
    Include {
        at: Span,
        name: String,
    },
    Macro {
        def: Rc<MacroDef>,
        call: Span,
        /// Parameter name and the caller's identifier it was passed as: POV-Ray passes
        /// identifiers by reference, so assignments to the parameter are copied back.
        by_ref: Vec<(Name, Name)>,
    },
}

pub(super) struct Frame {
    pub file: FileId,
    pub tokens: Rc<[Token]>,
    pub pos: usize,
    pub end: usize,
    pub eof: Span,
    pub kind: FrameKind,
    /// Length of the block stack when the frame started: blocks opened inside a file or a
    /// macro must close inside it.
    pub cond_base: usize,
}

/// An open `#if`, `#while`, `#for` or `#switch` block.
pub(super) enum Cond {
    If {
        span: Span,
    },
    /// `at` is the index of the `#while` token, re-read at `#end` to test again.
    While {
        span: Span,
        at: usize,
    },
    For {
        span: Span,
        var: Rc<str>,
        end: f64,
        step: f64,
        body: usize,
    },
    Switch {
        span: Span,
        value: f64,
        matched: bool,
    },
}

impl Cond {
    pub fn span(&self) -> Span {
        match self {
            Cond::If { span }
            | Cond::While { span, .. }
            | Cond::For { span, .. }
            | Cond::Switch { span, .. } => *span,
        }
    }
}

/// Where a skip of a false branch stopped.
#[derive(Debug, PartialEq, Eq)]
pub(super) enum SkipStop {
    Else,
    ElseIf,
    End,
    Case,
    Range,
    Break,
}

impl Evaluator<'_> {
    pub(super) fn push_file(
        &mut self,
        name: String,
        text: Rc<str>,
        include_at: Option<Span>,
    ) -> Result<(), Diagnostic> {
        if self.frames.len() >= super::MAX_DEPTH {
            let span = include_at.unwrap_or(Span::DETACHED);
            return Err(self.err(span, "includes are nested too deeply"));
        }
        let id = self.files.add(name.clone(), text.clone());
        let tokens = tokenize(id, &text).map_err(|mut d| {
            d.trace = self.trace();
            if let Some(at) = include_at {
                d.trace.insert(
                    0,
                    TracePoint {
                        message: format!("in file `{name}` included here"),
                        span: at,
                        location: None,
                    },
                );
            }
            d
        })?;
        let kind = match include_at {
            None => FrameKind::Root,
            Some(at) => {
                self.scopes.push(Scope::default());
                FrameKind::Include { at, name }
            }
        };
        self.frames.push(Frame {
            file: id,
            end: tokens.tokens.len(),
            tokens: tokens.tokens,
            pos: 0,
            eof: tokens.eof,
            kind,
            cond_base: self.conds.len(),
        });
        Ok(())
    }

    pub(super) fn push_macro(
        &mut self,
        def: Rc<MacroDef>,
        call: Span,
        locals: Scope,
        by_ref: Vec<(Name, Name)>,
    ) -> Result<(), Diagnostic> {
        if self.frames.len() >= super::MAX_DEPTH {
            return Err(self.err(
                call,
                format!(
                    "macro calls are nested too deeply (more than {} levels)",
                    super::MAX_DEPTH
                ),
            ));
        }
        for (key, value) in &locals {
            if value.needs_check_in_stream() {
                self.mark_special(key.text());
            }
        }
        self.scopes.push(locals);
        let eof = def.tokens.get(def.end).map_or(Span::DETACHED, |t| t.span);
        self.frames.push(Frame {
            file: def.file,
            tokens: def.tokens.clone(),
            pos: def.start,
            end: def.end,
            eof,
            kind: FrameKind::Macro { def, call, by_ref },
            cond_base: self.conds.len(),
        });
        Ok(())
    }

    /// The include and macro chain, innermost first.
    pub(super) fn trace(&self) -> Vec<TracePoint> {
        let mut out = Vec::new();
        for frame in self.frames.iter().rev() {
            match &frame.kind {
                FrameKind::Root => {}
                FrameKind::Include { at, name } => out.push(TracePoint {
                    message: format!("in file `{name}` included here"),
                    span: *at,
                    location: None,
                }),
                FrameKind::Macro { def, call, .. } => out.push(TracePoint {
                    message: format!("in macro `{}` called here", def.name),
                    span: *call,
                    location: None,
                }),
            }
        }
        out
    }

    /// The next token, after running any directives and macro calls in front of it.
    #[inline]
    pub(super) fn peek(&mut self) -> Result<Token, Diagnostic> {
        // Most tokens are plain: answer those here, inline in the caller, and leave
        // directives, macro calls and frame ends to `peek_slow`.
        if let Some(frame) = self.frames.last()
            && let Some(tok) = frame.tokens.get(frame.pos)
            && frame.pos < frame.end
        {
            match tok.kind {
                TokenKind::Directive(_) => {}
                TokenKind::Ident(name) if self.may_be_special(name) => {}
                _ => return Ok(*tok),
            }
        }
        self.peek_slow()
    }

    #[inline(never)]
    fn peek_slow(&mut self) -> Result<Token, Diagnostic> {
        loop {
            let Some(frame) = self.frames.last() else {
                return Ok(Token {
                    kind: TokenKind::Eof,
                    span: Span::DETACHED,
                });
            };
            if frame.pos >= frame.end {
                if let Some(cond) = self.conds.get(frame.cond_base) {
                    let what = match cond {
                        Cond::If { .. } => "#if",
                        Cond::While { .. } => "#while",
                        Cond::For { .. } => "#for",
                        Cond::Switch { .. } => "#switch",
                    };
                    return Err(self.err(cond.span(), format!("this `{what}` has no `#end`")));
                }
                if self.frames.len() == 1 {
                    return Ok(Token {
                        kind: TokenKind::Eof,
                        span: frame.eof,
                    });
                }
                self.pop_frame();
                continue;
            }
            let tok = frame.tokens[frame.pos];
            match &tok.kind {
                TokenKind::Directive(name) => {
                    self.advance();
                    self.directive(name, tok.span)?;
                }
                // Most names are keywords or plain values: only look them up when some
                // scope may hold a macro or an unsupported value.
                TokenKind::Ident(name) if !self.may_be_special(name) => return Ok(tok),
                TokenKind::Ident(name) => match self.lookup(name) {
                    Some(Value::Macro(_)) => {
                        self.advance();
                        self.call_macro(name, tok.span)?;
                    }
                    Some(Value::Unsupported(original)) => {
                        let mut d = self.err(tok.span, original.message.clone());
                        d.trace.insert(
                            0,
                            TracePoint {
                                message: format!("`{name}` was declared with it"),
                                span: original.span,
                                location: None,
                            },
                        );
                        return Err(d);
                    }
                    _ => return Ok(tok),
                },
                _ => return Ok(tok),
            }
        }
    }

    /// Like [`Evaluator::peek`], for the look-ahead after a complete operand ("is an
    /// operator next?"). A directive or macro call there ends the expression unrun, so that
    /// in `#declare I = I + 1` followed by `#end`, the loop's `#end` runs after the
    /// assignment rather than in the middle of it. Macro bodies that end are still left
    /// transparently.
    pub(super) fn peek_operator(&mut self) -> Result<Token, Diagnostic> {
        while let Some(frame) = self.frames.last() {
            if frame.pos < frame.end {
                // Neither a directive nor a name (a macro call, say) can continue an
                // expression, so neither is run here; any other token is what `peek`
                // would return. The exception is what follows the branch of an `#if`
                // just taken (its `#else`, `#elseif` or `#end`), which only skips: POV-Ray
                // reads through it, so a macro whose value comes from inside an `#if`
                // (arrays.inc's Rand_Array_Item) continues the caller's expression.
                let Some(&tok) = frame.tokens.get(frame.pos) else {
                    break;
                };
                let if_open = self.conds.len() > frame.cond_base
                    && matches!(self.conds.last(), Some(Cond::If { .. }));
                match tok.kind {
                    TokenKind::Directive(name)
                        if if_open && matches!(name, "else" | "elseif" | "end") =>
                    {
                        self.advance();
                        self.directive(name, tok.span)?;
                        continue;
                    }
                    _ => return Ok(tok),
                }
            }
            if self.frames.len() == 1 || self.conds.len() > frame.cond_base {
                break;
            }
            self.pop_frame();
        }
        self.peek()
    }

    /// Consumes an operator found by [`Evaluator::peek_operator`].
    pub(super) fn eat_operator(
        &mut self,
        p: crate::lang::syntax::Punct,
    ) -> Result<bool, Diagnostic> {
        if self.peek_operator()?.is_punct(p) {
            self.advance();
            Ok(true)
        } else {
            Ok(false)
        }
    }

    pub(super) fn next(&mut self) -> Result<Token, Diagnostic> {
        let tok = self.peek()?;
        if tok.kind != TokenKind::Eof {
            self.advance();
        }
        Ok(tok)
    }

    pub(super) fn advance(&mut self) {
        if let Some(f) = self.frames.last_mut() {
            f.pos += 1;
        }
    }

    /// The next token of the current frame as written: no directives, no macro expansion.
    /// For names that follow `#declare`, `#ifdef` and the like.
    pub(super) fn raw_next(&mut self) -> Token {
        let Some(frame) = self.frames.last_mut() else {
            return Token {
                kind: TokenKind::Eof,
                span: Span::DETACHED,
            };
        };
        if frame.pos >= frame.end {
            return Token {
                kind: TokenKind::Eof,
                span: frame.eof,
            };
        }
        frame.pos += 1;
        frame.tokens[frame.pos - 1]
    }

    pub(super) fn raw_peek(&self, ahead: usize) -> Option<&Token> {
        let frame = self.frames.last()?;
        if frame.pos + ahead >= frame.end {
            return None;
        }
        frame.tokens.get(frame.pos + ahead)
    }

    pub(super) fn pop_frame(&mut self) {
        let Some(frame) = self.frames.pop() else {
            return;
        };
        match frame.kind {
            FrameKind::Root => {}
            FrameKind::Include { .. } => {
                self.scopes.pop();
            }
            FrameKind::Macro { by_ref, .. } => {
                let locals = self.scopes.pop().unwrap_or_default();
                for (param, caller) in by_ref {
                    if let Some(v) = locals.get(&NameRef(param)) {
                        self.assign(caller, v.clone(), false);
                    }
                }
            }
        }
    }

    /// `#declare` assigns to the innermost scope that already has the name, else the
    /// global one; `#local` always assigns to the innermost scope.
    pub(super) fn assign(&mut self, name: &str, value: Value, local: bool) {
        let last = self.scopes.len() - 1;
        let index = if local {
            last
        } else {
            (1..self.scopes.len())
                .rev()
                .find(|&i| self.scopes[i].contains_key(&NameRef(name)))
                .unwrap_or(0)
        };
        self.assign_at(name, value, index);
    }

    /// Into scope `index` (for `#local`, the one the directive was written in), or the
    /// innermost if that has closed meanwhile. A name already there keeps its key: a loop's
    /// `#declare I = I + 1` allocates nothing.
    pub(super) fn assign_at(&mut self, name: &str, value: Value, index: usize) {
        if value.needs_check_in_stream() {
            self.mark_special(name);
        }
        let index = index.min(self.scopes.len() - 1);
        match self.scopes[index].get_mut(&NameRef(name)) {
            Some(slot) => *slot = value,
            None => {
                self.scopes[index].insert(Key::of(name), value);
            }
        }
    }

    /// Skips a false branch: tokens up to the `#else`/`#elseif`/`#end` (or `#case`...) that
    /// belongs to this block, consuming that directive.
    pub(super) fn skip_branch(&mut self, start: Span) -> Result<SkipStop, Diagnostic> {
        let mut depth = 0usize;
        loop {
            let tok = self.raw_next();
            match &tok.kind {
                TokenKind::Eof => {
                    return Err(self.err(start, "this block has no `#end`"));
                }
                TokenKind::Directive(d) => match &**d {
                    "if" | "ifdef" | "ifndef" | "while" | "for" | "macro" | "switch" => depth += 1,
                    "end" if depth == 0 => return Ok(SkipStop::End),
                    "end" => depth -= 1,
                    "else" if depth == 0 => return Ok(SkipStop::Else),
                    "elseif" if depth == 0 => return Ok(SkipStop::ElseIf),
                    "case" if depth == 0 => return Ok(SkipStop::Case),
                    "range" if depth == 0 => return Ok(SkipStop::Range),
                    "break" if depth == 0 => return Ok(SkipStop::Break),
                    _ => {}
                },
                _ => {}
            }
        }
    }

    pub(super) fn count_iteration(&mut self, span: Span) -> Result<(), Diagnostic> {
        self.loop_iterations += 1;
        if self.loop_iterations > super::MAX_LOOP_ITERATIONS {
            return Err(self.err(
                span,
                format!(
                    "too many loop iterations (more than {}); is this loop endless?",
                    super::MAX_LOOP_ITERATIONS
                ),
            ));
        }
        Ok(())
    }

    pub(super) fn current_file(&self) -> Option<FileId> {
        self.frames.last().map(|f| f.file)
    }

    pub(super) fn frame_pos(&self) -> usize {
        self.frames.last().map_or(0, |f| f.pos)
    }

    pub(super) fn set_frame_pos(&mut self, pos: usize) {
        if let Some(f) = self.frames.last_mut() {
            f.pos = pos;
        }
    }

    pub(super) fn frame_cond_base(&self) -> usize {
        self.frames.last().map_or(0, |f| f.cond_base)
    }

    pub(super) fn frame_tokens(&self) -> Option<(Rc<[Token]>, FileId)> {
        self.frames.last().map(|f| (f.tokens.clone(), f.file))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scope found by a token's (interned) name and by any other copy of the same text:
    /// the address is a shortcut, never the test.
    #[test]
    fn a_scope_finds_a_name_by_address_and_by_text() {
        let mut scope = Scope::default();
        scope.insert(Key::of("Radius"), Value::Float(2.0));
        let interned = intern("Radius");
        let copy = String::from("Radius");
        assert!(!std::ptr::eq(interned, copy.as_str()));
        for name in [interned, copy.as_str()] {
            assert!(
                matches!(scope.get(&NameRef(name)), Some(Value::Float(2.0))),
                "{name}"
            );
        }
        assert!(!scope.contains_key(&NameRef("Radiu")));
        assert!(!scope.contains_key(&NameRef("radius")));
    }
}
