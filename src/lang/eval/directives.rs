//! Directives: `#declare`/`#local`, `#version`, flow control (`#if`, `#while`, `#for`,
//! `#switch`), macros and `#include`. They run while the token stream is read, so they may
//! appear anywhere.

use std::path::PathBuf;
use std::rc::Rc;

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::{Punct, Token, TokenKind};
use super::Evaluator;
use super::stream::{Cond, Key, NameRef, Scope, SkipStop};
use super::value::{ArrayValue, MacroDef, Value};

type R<T> = Result<T, Diagnostic>;

/// Elements in one array, so a typo in a size cannot exhaust memory.
/// `#debug` text kept; more is dropped.
const MAX_DEBUG_BYTES: usize = 1 << 20;
const MAX_ARRAY_ELEMENTS: usize = 1_000_000;

impl Evaluator<'_> {
    pub(super) fn directive(&mut self, name: &'static str, span: Span) -> R<()> {
        let tok = Token {
            kind: TokenKind::Directive(name),
            span,
        };
        self.enter(span)?;
        let r = self.directive_inner(name, &tok);
        self.leave();
        r
    }

    fn directive_inner(&mut self, name: &str, tok: &Token) -> R<()> {
        let span = tok.span;
        match name {
            "" => Ok(()),
            "declare" | "local" => self.declare(name == "local", span),
            "version" => self.version_directive(),
            "if" => {
                let c = self.condition()?;
                self.branch(c, span)
            }
            "ifdef" | "ifndef" => self.ifdef(name, span),
            "else" | "elseif" => self.else_while_running(name, span),
            "end" => self.end(span),
            "while" => self.while_directive(span),
            "for" => self.for_loop(span),
            "switch" => self.switch(span),
            "case" | "range" => {
                // Reached while running a matched case: POV-Ray falls through.
                self.case_test(name == "range")?;
                Ok(())
            }
            "break" => self.break_block(span),
            "macro" => self.define_macro(span),
            "include" => self.include(span),
            "debug" | "warning" | "error" => self.message_directive(name, span),
            "undef" => self.undef(),
            "default" => self.default_directive(),
            "fopen" => self.fopen(),
            "fclose" => self.fclose(),
            "read" => self.read_directive(),
            "write" => self.write_directive(),
            "render" | "statistics" => {
                Err(self.err(span, format!("unsupported: `#{name}` is not supported yet")))
            }
            other => Err(self.err(span, format!("unknown directive `#{other}`"))),
        }
    }

    /// `#version 3.7;`: a number as written is read raw, so the directive takes effect before
    /// the next token is read.
    fn version_directive(&mut self) -> R<()> {
        let at = self.raw_peek(0).map(|t| t.span);
        let v = match self.raw_peek(0).map(|t| t.kind) {
            Some(TokenKind::Number(n)) => {
                self.raw_next();
                n
            }
            _ => self.float()?,
        };
        self.eat_declare_semicolon();
        if v >= 3.8 && self.scene.version < 3.8 {
            self.version_3_8(at);
        }
        self.scene.version = v;
        Ok(())
    }

    /// `#version 3.8` or later. POV-Ray 3.7 refuses such scenes ("Your scene file requires
    /// POV-Ray version 3.8", a fatal parse error, measured with 3.7.0.10). POV-Ray 3.8
    /// changes one default: when the directive is the scene's first statement, the default
    /// ambient is 0 instead of 0.1 (POV-Ray pull request 305). penumbra does that and
    /// otherwise reads the scene as 3.7, with a warning that POV-Ray 3.7 cannot render it.
    fn version_3_8(&mut self, at: Option<Span>) {
        let first = self.scene.objects.is_empty()
            && self.scene.lights.is_empty()
            && self.changed_default.is_none();
        if first {
            self.default_with_pigment = None;
            self.default_texture.finish.ambient = glam::DVec3::ZERO;
            self.changed_default = Some(std::sync::Arc::new(self.default_texture.clone()));
        }
        if !self.warned_version_3_8 {
            self.warned_version_3_8 = true;
            let span = at.unwrap_or(Span::DETACHED);
            let ambient = if first {
                "0 (as POV-Ray 3.8 does)"
            } else {
                "unchanged (not the first statement)"
            };
            self.warn(
                span,
                format!(
                    "POV-Ray 3.7 refuses `#version 3.8`; penumbra reads the scene as 3.7, default ambient {ambient}"
                ),
            );
        }
    }

    /// `#ifdef (Name)` and `#ifndef (Name)`: the name is read raw, as it may be undeclared.
    fn ifdef(&mut self, name: &str, span: Span) -> R<()> {
        self.expect_lazy(Punct::LParen, || format!("after `#{name}`"))?;
        let id = self.raw_next();
        let value = match id.ident() {
            Some(n) => self.lookup(n).cloned(),
            None => return Err(self.expected("an identifier", &id)),
        };
        // `#ifdef (A[3])` asks whether that element is set (html_gen.inc does).
        let defined = match value {
            Some(v @ Value::Array(_)) if self.peek()?.is_punct(Punct::LBracket) => {
                self.array_element(&v)?.0.is_some()
            }
            v => v.is_some(),
        };
        while !self.peek()?.is_punct(Punct::RParen) {
            let t = self.next()?;
            if t.kind == TokenKind::Eof {
                return Err(self.expected("`)`", &t));
            }
        }
        self.expect_lazy(Punct::RParen, || format!("to close `#{name}(`"))?;
        self.branch(defined == (name == "ifdef"), span)
    }

    /// `#while (c)`: remembers where it starts, so `#end` can come back to test again.
    fn while_directive(&mut self, span: Span) -> R<()> {
        let at = self.frame_pos().saturating_sub(1);
        self.count_iteration(span)?;
        // The condition is read again at every `#end`: worth compiling.
        let outer = std::mem::replace(&mut self.programs.in_loop_condition, true);
        let holds = self.condition();
        self.programs.in_loop_condition = outer;
        if holds? {
            self.conds.push(Cond::While { span, at });
        } else {
            self.skip_to_end(span)?;
        }
        Ok(())
    }

    /// `#debug`, `#warning` and `#error` with their string.
    fn message_directive(&mut self, name: &str, span: Span) -> R<()> {
        let (v, s) = self.expr()?;
        let text = match v {
            Value::Str(t) => t,
            other => {
                return Err(self.err(s, format!("expected a string, found {}", other.kind_name())));
            }
        };
        match name {
            "error" => Err(self.err(span, format!("#error: {}", text.trim_end()))),
            "warning" => {
                self.warn(span, text.trim_end().to_string());
                Ok(())
            }
            _ => {
                // A loop printing forever must not fill memory.
                if self.debug_output.len() < MAX_DEBUG_BYTES {
                    self.debug_output.push_str(&text);
                }
                Ok(())
            }
        }
    }

    fn undef(&mut self) -> R<()> {
        let id = self.raw_next();
        let Some(n) = id.ident() else {
            return Err(self.expected("an identifier", &id));
        };
        if let Some(scope) = self
            .scopes
            .iter_mut()
            .rev()
            .find(|s| s.contains_key(&NameRef(n)))
        {
            scope.remove(&NameRef(n));
        }
        Ok(())
    }

    /// `(expression)` after `#if`, `#while`, `#elseif`: any float, nonzero is true.
    fn condition(&mut self) -> R<bool> {
        let v = self.directive_float()?;
        Ok(v.abs() > 1e-10)
    }

    /// A parenthesised float that ends at its `)`: reading one token further would run the
    /// directive that follows before this one has taken effect.
    fn directive_float(&mut self) -> R<f64> {
        if !self.peek()?.is_punct(Punct::LParen) {
            return self.float();
        }
        self.next()?;
        let saved = std::mem::replace(&mut self.in_vector, false);
        self.grouping += 1;
        let r = self.float();
        self.grouping -= 1;
        self.in_vector = saved;
        let v = r?;
        self.expect(Punct::RParen, "to close the condition")?;
        Ok(v)
    }

    /// Consumes a `;` that ends a `#declare`, without reading past it: the next token may be
    /// a directive that must wait until this declaration is done.
    fn eat_declare_semicolon(&mut self) {
        loop {
            let Some(frame) = self.frames.last() else {
                return;
            };
            let done = frame.pos >= frame.end;
            if done && self.frames.len() > 1 && self.conds.len() <= frame.cond_base {
                self.pop_frame();
                continue;
            }
            break;
        }
        if self.raw_peek(0).is_some_and(|t| t.is_punct(Punct::Semi)) {
            self.raw_next();
        }
    }

    fn branch(&mut self, cond: bool, span: Span) -> R<()> {
        if cond {
            self.conds.push(Cond::If { span });
            return Ok(());
        }
        loop {
            match self.skip_branch(span)? {
                SkipStop::Else => {
                    self.conds.push(Cond::If { span });
                    return Ok(());
                }
                SkipStop::ElseIf if self.condition()? => {
                    self.conds.push(Cond::If { span });
                    return Ok(());
                }
                SkipStop::End => return Ok(()),
                _ => {}
            }
        }
    }

    /// Skips tokens to this block's own `#end`, consuming it.
    fn skip_to_end(&mut self, span: Span) -> R<()> {
        while self.skip_branch(span)? != SkipStop::End {}
        Ok(())
    }

    fn else_while_running(&mut self, name: &str, span: Span) -> R<()> {
        let base = self.frame_cond_base();
        match self.conds.last() {
            Some(Cond::If { .. }) if self.conds.len() > base => {
                // The branch just run was the taken one: skip the rest.
                if let Some(cond) = self.conds.pop() {
                    self.skip_to_end(cond.span())?;
                }
                Ok(())
            }
            Some(Cond::Switch { .. }) if self.conds.len() > base && name == "else" => Ok(()),
            _ => Err(self.err(span, format!("`#{name}` without an open `#if`"))),
        }
    }

    fn end(&mut self, span: Span) -> R<()> {
        if self.conds.len() <= self.frame_cond_base() {
            return Err(self.err(span, "`#end` without an open block"));
        }
        let Some(cond) = self.conds.pop() else {
            return Ok(());
        };
        match cond {
            Cond::If { .. } | Cond::Switch { .. } => Ok(()),
            Cond::While { at, .. } => {
                self.set_frame_pos(at);
                Ok(())
            }
            Cond::For {
                span: for_span,
                var,
                end,
                step,
                body,
            } => {
                self.count_iteration(for_span)?;
                let current = match self.lookup(&var) {
                    Some(Value::Float(f)) => *f,
                    _ => {
                        return Err(self.err(
                            for_span,
                            format!("the loop variable `{var}` is no longer a float"),
                        ));
                    }
                };
                let next = current + step;
                if (step > 0.0 && next <= end + 1e-10) || (step < 0.0 && next >= end - 1e-10) {
                    self.assign(&var, Value::Float(next), false);
                    self.conds.push(Cond::For {
                        span: for_span,
                        var,
                        end,
                        step,
                        body,
                    });
                    self.set_frame_pos(body);
                }
                Ok(())
            }
        }
    }

    fn for_loop(&mut self, span: Span) -> R<()> {
        self.expect(Punct::LParen, "after `#for`")?;
        let id = self.raw_next();
        let Some(var) = id.ident().map(Rc::<str>::from) else {
            return Err(self.expected("a loop variable name", &id));
        };
        self.expect(Punct::Comma, "after the loop variable")?;
        let start = self.float()?;
        self.expect(Punct::Comma, "after the start value")?;
        let end = self.float()?;
        let step = if self.eat(Punct::Comma)? {
            self.float()?
        } else {
            1.0
        };
        self.expect(Punct::RParen, "to close `#for (`")?;
        if step == 0.0 {
            return Err(self.err(span, "the `#for` step is zero"));
        }
        let body = self.frame_pos();
        let runs = if step > 0.0 {
            start <= end + 1e-10
        } else {
            start >= end - 1e-10
        };
        if runs {
            self.assign(&var, Value::Float(start), false);
            self.conds.push(Cond::For {
                span,
                var,
                end,
                step,
                body,
            });
        } else {
            self.skip_to_end(span)?;
        }
        Ok(())
    }

    fn switch(&mut self, span: Span) -> R<()> {
        let value = self.directive_float()?;
        self.conds.push(Cond::Switch {
            span,
            value,
            matched: false,
        });
        // Find the first clause that matches.
        loop {
            match self.skip_branch(span)? {
                SkipStop::Case | SkipStop::Range => {
                    let range = self.last_skip_was_range();
                    if self.case_test(range)? {
                        return Ok(());
                    }
                }
                SkipStop::Else => return Ok(()),
                SkipStop::End => {
                    self.conds.pop();
                    return Ok(());
                }
                _ => {}
            }
        }
    }

    /// Whether the directive just consumed by a skip was `#range` (else `#case`).
    fn last_skip_was_range(&self) -> bool {
        let pos = self.frame_pos();
        self.frames
            .last()
            .and_then(|f| f.tokens.get(pos.wrapping_sub(1)))
            .is_some_and(|t| t.kind == TokenKind::Directive("range"))
    }

    /// `#case (v)` or `#range (a, b)` against the innermost `#switch` value.
    fn case_test(&mut self, range: bool) -> R<bool> {
        let value = match self.conds.last() {
            Some(Cond::Switch { value, .. }) => *value,
            _ => {
                let tok = self.peek()?;
                return Err(self.err(tok.span, "`#case` or `#range` outside `#switch`"));
            }
        };
        let hit = if range {
            self.expect(Punct::LParen, "after `#range`")?;
            let lo = self.float()?;
            self.expect(Punct::Comma, "in `#range (low, high)`")?;
            let hi = self.float()?;
            self.expect(Punct::RParen, "to close `#range (`")?;
            value >= lo && value <= hi
        } else {
            let c = self.directive_float()?;
            (c - value).abs() < 1e-10
        };
        if hit && let Some(Cond::Switch { matched, .. }) = self.conds.last_mut() {
            *matched = true;
        }
        Ok(hit)
    }

    /// `#break`: leaves the innermost `#switch`, `#while` or `#for`, skipping what is left
    /// of every block inside it.
    fn break_block(&mut self, span: Span) -> R<()> {
        let base = self.frame_cond_base();
        loop {
            if self.conds.len() <= base {
                return Err(self.err(span, "`#break` outside `#switch`, `#while` or `#for`"));
            }
            let Some(cond) = self.conds.pop() else {
                return Ok(());
            };
            self.skip_to_end(cond.span())?;
            if !matches!(cond, Cond::If { .. }) {
                return Ok(());
            }
        }
    }

    /// `#default { texture/pigment/finish {...} }`: the texture new textures start from.
    pub(super) fn default_directive(&mut self) -> R<()> {
        self.default_with_pigment = None;
        let open = self.expect(Punct::LBrace, "after `#default`")?;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            match tok.ident() {
                Some("texture") => {
                    self.next()?;
                    self.default_texture = self.texture_body(self.default_texture.clone())?;
                }
                Some("pigment") => {
                    self.next()?;
                    self.default_texture.pigment =
                        self.pigment_body(self.default_texture.pigment.clone())?;
                }
                Some("finish") => {
                    self.next()?;
                    self.default_texture.finish = self.finish_body(self.default_texture.finish)?;
                }
                Some("normal") => {
                    self.next()?;
                    let base = self.default_texture.normal.take();
                    self.default_texture.normal = self.normal_body(base)?;
                }
                Some(w @ ("interior" | "media")) => {
                    let w = w.to_string();
                    return Err(self.unsupported(&tok, &w));
                }
                _ => return Err(self.stray_in_block(&tok, "`#default`")),
            }
            self.changed_default = (self.default_texture != crate::scene::Texture::default())
                .then(|| std::sync::Arc::new(self.default_texture.clone()));
        }
        let _ = open;
        // Not `expect`: reading past the `}` would run the next directive too early.
        let close = self.raw_next();
        if !close.is_punct(Punct::RBrace) {
            return Err(self.expected("`}` to close `#default`", &close));
        }
        Ok(())
    }

    fn declare(&mut self, local: bool, span: Span) -> R<()> {
        let mut id = self.raw_next();
        // `#declare deprecated [once] "message" Name = ...`: the message is for users of
        // the identifier; penumbra does not print it.
        if id.is_ident("deprecated") {
            id = self.raw_next();
            if id.is_ident("once") {
                id = self.raw_next();
            }
            if matches!(id.kind, TokenKind::Str(_)) {
                id = self.raw_next();
            }
        }
        let Some(name) = id.ident() else {
            return Err(self.expected("an identifier to declare", &id));
        };
        if super::keywords::is_keyword(name) {
            return Err(self.err(
                id.span,
                format!("`{name}` is a POV-Ray keyword and cannot be declared"),
            ));
        }
        // `#declare A[i][j] = value`: assignment into an existing array.
        if self.peek()?.is_punct(Punct::LBracket) {
            return self.declare_element(name, &id, span);
        }
        self.expect_lazy(Punct::Eq, || format!("after `{name}`"))?;
        // A `#local` belongs to the scope it is written in, not to a macro the value calls:
        // that macro's scope is still open while its last tokens are read (`#local M =
        // Matrix_Trans(...)` in transforms.inc's Spline_Trans).
        let scope = self.scopes.len() - 1;
        let value = self.declared_value_tolerant()?;
        // Assign before looking for the optional `;`: looking past the end of a macro body
        // closes the macro's scope, and a parameter passed by reference must be written
        // while that scope still exists (e.g. `#declare Stuff = object { Stuff ... } #end`).
        if local {
            self.assign_at(name, value, scope);
        } else {
            self.assign(name, value, false);
        }
        self.eat_declare_semicolon();
        Ok(())
    }

    /// The value of a declaration; if it needs an unsupported feature, the declaration is
    /// skipped and the identifier remembers the error for when it is used.
    fn declared_value_tolerant(&mut self) -> R<Value> {
        let frames = self.frames.len();
        let pos = self.frame_pos();
        let (conds, depth, in_vector) = (self.conds.len(), self.depth, self.in_vector);
        match self.declared_value() {
            Ok(v) => Ok(v),
            Err(e) if e.message.starts_with("unsupported:") && self.frames.len() >= frames => {
                while self.frames.len() > frames {
                    self.pop_frame();
                }
                self.conds.truncate(conds);
                self.depth = depth;
                self.in_vector = in_vector;
                self.set_frame_pos(pos);
                self.skip_declaration_raw();
                Ok(Value::Unsupported(Rc::new(e)))
            }
            Err(e) => Err(e),
        }
    }

    /// Skips the right-hand side of a declaration as written: a balanced `{ }` block, or
    /// tokens up to a `;`, the next directive or the keyword of the next statement (so a
    /// macro call's value, `M(1)`, does not swallow the object written after it).
    fn skip_declaration_raw(&mut self) {
        let mut depth = 0usize;
        let mut first = true;
        while let Some(tok) = self.raw_peek(0).cloned() {
            if depth == 0 && !first && tok.ident().is_some_and(super::items::starts_statement) {
                return;
            }
            first = false;
            match &tok.kind {
                TokenKind::Punct(Punct::LBrace | Punct::LParen | Punct::LBracket) => depth += 1,
                TokenKind::Punct(Punct::RBrace | Punct::RParen | Punct::RBracket) => {
                    if depth == 0 {
                        return;
                    }
                    depth -= 1;
                    if depth == 0 && tok.is_punct(Punct::RBrace) {
                        self.raw_next();
                        // Layered textures: `texture {...} texture {...}`.
                        let more = self.raw_peek(0).is_some_and(|t| t.is_ident("texture"))
                            && self.raw_peek(1).is_some_and(|t| t.is_punct(Punct::LBrace));
                        if !more {
                            return;
                        }
                        continue;
                    }
                }
                TokenKind::Punct(Punct::Semi) if depth == 0 => return,
                TokenKind::Directive(_) if depth == 0 => return,
                _ => {}
            }
            self.raw_next();
        }
    }

    fn declare_element(&mut self, name: &str, id: &Token, _span: Span) -> R<()> {
        let Some(Value::Array(a)) = self.lookup(name).cloned() else {
            return Err(self.err(id.span, format!("`{name}` is not an array")));
        };
        let mut idx = Vec::new();
        let mut span = id.span;
        while self.eat(Punct::LBracket)? {
            let (v, s) = self.expr()?;
            let i = self.to_float(&v, s)?;
            let close = self.expect(Punct::RBracket, "to close the index")?;
            span = span.join(close.span);
            idx.push((i, s));
        }
        let flat = self.flat_index(&a.borrow().dims, &idx, span)?;
        self.expect(Punct::Eq, "after the array element")?;
        let value = self.declared_value_tolerant()?;
        self.eat_declare_semicolon();
        if let Some(slot) = a.borrow_mut().items.get_mut(flat) {
            *slot = Some(value);
        }
        Ok(())
    }

    /// `array[n][m] { ... }` after `#declare X =`.
    pub(super) fn array_value(&mut self) -> R<Value> {
        let kw = self.next()?;
        let mut dims = Vec::new();
        // Raw look-ahead: `#declare A = array[3]` may be followed directly by a directive
        // that uses `A`, which must not run before `A` exists.
        while self
            .raw_peek(0)
            .is_some_and(|t| t.is_punct(Punct::LBracket))
        {
            self.next()?;
            let (v, s) = self.expr()?;
            let n = self.to_float(&v, s)?;
            if !(1.0..=MAX_ARRAY_ELEMENTS as f64).contains(&n) {
                return Err(self.err(
                    s,
                    format!("an array size must be between 1 and {MAX_ARRAY_ELEMENTS}"),
                ));
            }
            dims.push(n as usize);
            self.expect(Punct::RBracket, "to close the array size")?;
        }
        if dims.is_empty() {
            let tok = self.peek()?;
            return Err(self.expected("`[` with the array size", &tok));
        }
        let total = dims
            .iter()
            .try_fold(1usize, |acc, &d| acc.checked_mul(d))
            .unwrap_or(usize::MAX);
        if total > MAX_ARRAY_ELEMENTS {
            return Err(self.err(kw.span, "this array is too large"));
        }
        let bytes = total.saturating_mul(std::mem::size_of::<Option<Value>>());
        self.charge(
            bytes as u64,
            super::budget::Growth::ArrayElements(total),
            kw.span,
        )?;
        let mut items = vec![None; total];
        if self.raw_peek(0).is_some_and(|t| t.is_punct(Punct::LBrace)) {
            let mut flat = Vec::new();
            self.array_initializer(&mut flat, dims.len())?;
            if flat.len() != total {
                return Err(self.err(
                    kw.span,
                    format!(
                        "the array has {total} elements but {} values were given",
                        flat.len()
                    ),
                ));
            }
            for (slot, v) in items.iter_mut().zip(flat) {
                *slot = Some(v);
            }
        }
        Ok(Value::Array(Rc::new(std::cell::RefCell::new(ArrayValue {
            dims,
            items,
        }))))
    }

    fn array_initializer(&mut self, out: &mut Vec<Value>, levels: usize) -> R<()> {
        let open = self.expect(Punct::LBrace, "to start the array values")?;
        self.enter(open.span)?;
        let r = (|| -> R<()> {
            loop {
                // Before peeking: a peek at such a name raises its error.
                if levels == 1
                    && let Some(v) = self.unsupported_element()
                {
                    out.push(v);
                } else if self.peek()?.is_punct(Punct::RBrace) {
                    break;
                } else if levels > 1 {
                    self.array_initializer(out, levels - 1)?;
                } else {
                    out.push(self.declared_value()?);
                }
                // Commas between values are optional in POV-Ray.
                self.eat(Punct::Comma)?;
            }
            Ok(())
        })();
        self.leave();
        r?;
        self.expect(Punct::RBrace, "to close the array values")?;
        Ok(())
    }

    /// An array element that is only the name of a declaration needing an unsupported
    /// feature: kept as it is, so that the error comes where the element is used, as for
    /// the name itself (portfolio/allnormals.pov lists `facets` among thirty normals and
    /// renders one per frame).
    fn unsupported_element(&mut self) -> Option<Value> {
        let name = self.raw_peek(0)?.ident()?;
        let value @ Value::Unsupported(_) = self.lookup(name)?.clone() else {
            return None;
        };
        let after = self.raw_peek(1)?;
        if !(after.is_punct(Punct::Comma) || after.is_punct(Punct::RBrace)) {
            return None;
        }
        self.raw_next();
        Some(value)
    }

    fn define_macro(&mut self, span: Span) -> R<()> {
        let id = self.raw_next();
        let Some(name) = id.ident() else {
            return Err(self.expected("a macro name", &id));
        };
        let open = self.raw_next();
        if !open.is_punct(Punct::LParen) {
            return Err(self.expected(&format!("`(` after `#macro {name}`"), &open));
        }
        let mut params = Vec::new();
        loop {
            let t = self.raw_next();
            if t.is_punct(Punct::RParen) {
                break;
            }
            let optional = t.is_ident("optional");
            let t = if optional { self.raw_next() } else { t };
            let Some(p) = t.ident() else {
                return Err(self.expected("a parameter name or `)`", &t));
            };
            params.push((p, optional));
            let sep = self.raw_next();
            if sep.is_punct(Punct::RParen) {
                break;
            }
            if !sep.is_punct(Punct::Comma) {
                return Err(self.expected("`,` or `)` in the parameter list", &sep));
            }
        }
        let start = self.frame_pos();
        self.skip_to_end(span)?;
        let end = self.frame_pos().saturating_sub(1);
        let Some((tokens, file)) = self.frame_tokens() else {
            return Ok(());
        };
        let def = MacroDef {
            name,
            params,
            tokens,
            start,
            end,
            file,
        };
        self.mark_special(name);
        self.scopes[0].insert(Key::new(name), Value::Macro(Rc::new(def)));
        Ok(())
    }

    pub(super) fn call_macro(&mut self, name: &str, span: Span) -> R<()> {
        let Some(Value::Macro(def)) = self.lookup(name).cloned() else {
            return Ok(());
        };
        self.expect(Punct::LParen, &format!("after the macro name `{name}`"))?;
        let mut locals = Scope::default();
        let mut by_ref = Vec::new();
        let mut i = 0;
        let saved = std::mem::replace(&mut self.in_vector, false);
        let r = (|| -> R<()> {
            while !self.peek()?.is_punct(Punct::RParen) {
                let Some((param, _)) = def.params.get(i).cloned() else {
                    let tok = self.peek()?;
                    return Err(self.err(
                        tok.span,
                        format!(
                            "macro `{name}` takes {} arguments, found more",
                            def.params.len()
                        ),
                    ));
                };
                // A bare identifier is passed by reference.
                let by_name = match (self.raw_peek(0), self.raw_peek(1)) {
                    (Some(a), Some(b))
                        if (b.is_punct(Punct::Comma) || b.is_punct(Punct::RParen))
                            && a.ident().is_some_and(|n| {
                                !super::keywords::is_keyword(n) && self.lookup(n).is_some()
                            }) =>
                    {
                        a.ident()
                    }
                    _ => None,
                };
                // A function passed by name is passed itself: an expression would call it.
                let value = match by_name.and_then(|n| self.lookup(n)) {
                    Some(f @ Value::Function(_)) => {
                        let f = f.clone();
                        self.next()?;
                        f
                    }
                    _ => self.declared_value()?,
                };
                if let Some(caller) = by_name {
                    by_ref.push((param, caller));
                }
                locals.insert(Key::new(param), value);
                i += 1;
                // POV-Ray's commas between arguments are optional (incdemo/shapes.pov
                // passes an object and then `-y` without one).
                self.eat(Punct::Comma)?;
            }
            Ok(())
        })();
        self.in_vector = saved;
        r?;
        let close = self.expect(Punct::RParen, &format!("to close the call of `{name}`"))?;
        if let Some((missing, _)) = def.params.iter().skip(i).find(|(_, optional)| !optional) {
            return Err(self.err(
                span.join(close.span),
                format!(
                    "macro `{name}` takes {} arguments, found {i} (`{missing}` is missing)",
                    def.params.len()
                ),
            ));
        }
        self.push_macro(def, span, locals, by_ref)
    }

    fn include(&mut self, span: Span) -> R<()> {
        // A plain string is taken as is, so the directive after it waits for the include.
        let (v, s) = match self.raw_peek(0).map(|t| (t.kind, t.span)) {
            Some((TokenKind::Str(name), s)) => {
                self.raw_next();
                (Value::Str(Rc::from(name)), s)
            }
            _ => self.expr()?,
        };
        let Value::Str(name) = v else {
            return Err(self.err(
                s,
                format!("expected a file name string, found {}", v.kind_name()),
            ));
        };
        if escapes_folder(&name) {
            return Err(self.err(
                s,
                format!(
                    "refused: the include file \"{name}\" is outside the allowed folders \
                     (the scene's folder, --include-path folders, POV-Ray's include folder)"
                ),
            ));
        }
        let Some(path) = self.resolve_include(&name) else {
            return Err(self.err(s, format!("cannot find the include file \"{name}\"")));
        };
        let text = self
            .sources
            .read(&path)
            .map_err(|e| self.err(s, format!("cannot read \"{}\": {e}", path.display())))?;
        self.push_file(
            path.display().to_string(),
            Rc::from(text.as_str()),
            Some(span),
        )
    }

    /// The including file's folder, then each include path, then POV-Ray's own includes.
    /// Names that could leave those folders find nothing (see [`escapes_folder`]).
    pub(super) fn resolve_include(&self, name: &str) -> Option<PathBuf> {
        if escapes_folder(name) {
            return None;
        }
        self.include_dirs()
            .into_iter()
            .map(|d| d.join(name))
            .find(|p| self.sources.exists(p))
            .inspect(|p| self.inputs.file(p))
    }

    /// The folders includes (and data files) are looked up in, in order.
    pub(super) fn include_dirs(&self) -> Vec<PathBuf> {
        let mut dirs = Vec::new();
        if let Some(file) = self.current_file().and_then(|f| self.files.name(f)) {
            dirs.push(
                std::path::Path::new(file)
                    .parent()
                    .map(|p| p.to_path_buf())
                    .unwrap_or_default(),
            );
        }
        dirs.extend(self.include_paths.iter().cloned());
        dirs.push(PathBuf::from("/usr/share/povray-3.7/include"));
        dirs
    }
}

/// Whether an include name could reach outside the folder it is looked up in: absolute
/// paths, and `..` that climbs above the start. Scenes must not read arbitrary files.
pub(super) fn escapes_folder(name: &str) -> bool {
    let path = std::path::Path::new(name);
    let mut depth = 0i64;
    for c in path.components() {
        match c {
            std::path::Component::Normal(_) => depth += 1,
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir => {
                depth -= 1;
                if depth < 0 {
                    return true;
                }
            }
            std::path::Component::RootDir | std::path::Component::Prefix(_) => return true,
        }
    }
    false
}
