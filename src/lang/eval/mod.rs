//! The evaluator: reads tokens, runs directives and macros as it meets them, and builds the
//! scene model.
//!
//! POV-Ray's language has no separate preprocessor: `#if`, `#while` and macro calls work on
//! the token stream wherever they appear. So the evaluator is one recursive-descent reader
//! over a stack of token *frames* (the scene file, included files, macro bodies). Asking for
//! the next token ([`Evaluator::peek`]) transparently runs any directive or macro call in the
//! way; everything above that level (expressions, objects, textures) just reads tokens.
//!
//! Files: `stream` (frames, scopes, limits), `directives` (`#declare`, flow control, macros,
//! includes), `expr` (expressions), `functions` (the table of built-in functions), `items` (camera, lights, global
//! settings), `objects` (shapes, CSG, modifiers), `texture` (pigment, finish, texture).

mod blob;
pub mod budget;
mod compiled;
mod data_files;
mod directives;
mod expr;
mod fog;
mod functions;
pub use functions::builtins_markdown;
mod height_field;
mod inputs;
mod isosurface;
mod items;
pub(super) mod keywords;
mod material_map;
mod media;
mod mesh_camera;
mod meshes;
mod objects;
mod path_splines;
mod photons;
mod placement;
mod poly;
mod radiosity;
mod rainbow;
mod stream;
mod sweeps;
mod text;
mod texture;
mod user_functions;
pub mod value;

use std::path::PathBuf;
use std::rc::Rc;

use crate::scene::Scene;

use super::SourceFiles;
use super::diagnostics::{Diagnostic, Files, Span};
use super::syntax::{Punct, Token, TokenKind};
use stream::{Cond, Frame, Key, NameRef, Scope};
use value::Value;

/// Deeper nesting than this (blocks, parentheses, macro calls, includes) is reported rather
/// than risking the stack.
pub const MAX_DEPTH: usize = 256;
/// Total loop iterations in a scene, so an endless `#while` ends with an error.
#[cfg(not(test))]
pub const MAX_LOOP_ITERATIONS: u64 = 10_000_000;
/// Smaller under test so the endless-loop test is quick.
#[cfg(test)]
pub const MAX_LOOP_ITERATIONS: u64 = 100_000;

pub struct Evaluator<'w> {
    sources: &'w dyn SourceFiles,
    pub files: Files,
    frames: Vec<Frame>,
    conds: Vec<Cond>,
    scopes: Vec<Scope>,
    /// The names (by interned address) some scope may bind to a macro or an unsupported
    /// value, which the token stream must act on where they appear; other names pass
    /// unlooked-up (a scene that declares one macro no longer looks up every name it reads).
    special_names:
        std::collections::HashSet<usize, std::hash::BuildHasherDefault<stream::NameHasher>>,
    pub scene: Scene,
    pub warnings: Vec<Diagnostic>,
    depth: usize,
    loop_iterations: u64,
    include_paths: Vec<PathBuf>,
    image_width: u32,
    image_height: u32,
    rng_states: Vec<u64>,
    /// Inside `<...>` a `>` closes the vector instead of comparing.
    in_vector: bool,
    /// How many grouping parentheses the expression being read is inside: POV-Ray reads
    /// `<` as less-than only there (`poly { 4 <...> }` is an order and a vector).
    grouping: u32,
    /// What new textures start from; `#default` changes it.
    default_texture: crate::scene::Texture,
    /// The default texture, shared, once `#default` made it differ from the built-in one.
    changed_default: Option<std::sync::Arc<crate::scene::Texture>>,
    /// Inside a `density { }`, where `density` and `density_map` stand for `pigment` and
    /// `pigment_map`.
    reading_density: bool,
    /// The texture an object got last: the next object with an equal one shares it.
    last_texture: Option<std::sync::Arc<crate::scene::Texture>>,
    /// The last texture a `pigment` made on an object without one: the default texture
    /// with that pigment. An object with an equal pigment shares it without a copy or a
    /// comparison of the whole texture (a loop of a million such objects spent a tenth of
    /// its time there). Forgotten whenever the default texture changes.
    default_with_pigment: Option<std::sync::Arc<crate::scene::Texture>>,
    /// `--skip-unsupported`: unsupported features become warnings and are left out.
    pub skip_unsupported: bool,
    /// What `#debug` printed, in order.
    pub debug_output: String,
    /// The animation identifiers' values.
    pub clock: crate::lang::AnimationClock,
    /// What the scene's objects and values take, against the memory budget.
    budget: budget::Budget,
    /// Files opened with `#fopen`, by identifier.
    data_files: std::collections::HashMap<Rc<str>, data_files::DataFile>,
    /// `--allow-write DIR`: the one folder `#fopen ... write` may write in.
    pub allow_write: Option<PathBuf>,
    /// The fonts `text` objects read, by path: read and converted once per scene.
    fonts: std::collections::HashMap<PathBuf, crate::scene::text::Font>,
    /// Objects built for `trace`, `inside` and the extents.
    placements: placement::Placements,
    /// How many `light_group`s have been read: the next one's id.
    light_groups: u32,
    /// Whether the `#version 3.8` warning was given (include files switch versions back and
    /// forth; once is enough).
    warned_version_3_8: bool,
    /// What the scene was made from (its files and whether it read the clock).
    pub inputs: inputs::Inputs,
    /// Expressions of loop and macro bodies, compiled where they were first read.
    programs: compiled::Programs,
}

impl<'w> Evaluator<'w> {
    pub fn new(
        sources: &'w dyn SourceFiles,
        include_paths: Vec<PathBuf>,
        image_width: u32,
        image_height: u32,
    ) -> Evaluator<'w> {
        Evaluator {
            sources,
            files: Files::default(),
            frames: Vec::new(),
            conds: Vec::new(),
            scopes: vec![Scope::default()],
            special_names: Default::default(),
            scene: Scene::default(),
            warnings: Vec::new(),
            depth: 0,
            loop_iterations: 0,
            include_paths,
            image_width,
            image_height,
            rng_states: Vec::new(),
            in_vector: false,
            grouping: 0,
            default_texture: crate::scene::Texture::default(),
            changed_default: None,
            reading_density: false,
            last_texture: None,
            default_with_pigment: None,
            skip_unsupported: false,
            debug_output: String::new(),
            clock: crate::lang::AnimationClock::default(),
            budget: budget::Budget::new(budget::default_memory_budget()),
            data_files: std::collections::HashMap::new(),
            allow_write: None,
            fonts: std::collections::HashMap::new(),
            placements: placement::Placements::default(),
            light_groups: 0,
            warned_version_3_8: false,
            inputs: inputs::Inputs::default(),
            programs: compiled::Programs::default(),
        }
    }

    pub fn declare_global(&mut self, name: &str, value: Value) {
        if value.needs_check_in_stream() {
            self.mark_special(name);
        }
        self.scopes[0].insert(Key::of(name), value);
    }

    /// A global identifier's value after the scene was read; for tests that check values.
    pub(crate) fn global(&self, name: &str) -> Option<&Value> {
        self.scopes[0].get(&NameRef(name))
    }

    /// Reads the whole scene from `name`/`source` and returns the finished scene.
    pub fn run(&mut self, name: &str, source: &str) -> Result<(), Diagnostic> {
        let result = self.run_inner(name, source);
        result.map_err(|d| self.files.resolve(d))
    }

    fn run_inner(&mut self, name: &str, source: &str) -> Result<(), Diagnostic> {
        self.push_file(name.to_string(), Rc::from(source), None)?;
        loop {
            let tok = self.peek()?;
            if tok.kind == TokenKind::Eof {
                return self.close_data_files(tok.span);
            }
            self.item()?;
        }
    }

    /// Builds an error carrying the chain of macro calls and includes in force.
    fn err(&self, span: Span, message: impl Into<String>) -> Diagnostic {
        let mut d = Diagnostic::error(span, message);
        d.trace = self.trace();
        d
    }

    fn warn(&mut self, span: Span, message: impl Into<String>) {
        let d = Diagnostic::warning(span, message);
        let d = self.files.resolve(d);
        self.warnings.push(d);
    }

    fn expected(&self, what: &str, found: &Token) -> Diagnostic {
        self.err(
            found.span,
            format!("expected {what}, found {}", found.describe()),
        )
    }

    /// Consumes the punctuation or reports what was there instead.
    fn expect(&mut self, p: Punct, context: &str) -> Result<Token, Diagnostic> {
        let tok = self.peek()?;
        if tok.is_punct(p) {
            self.advance();
            Ok(tok)
        } else {
            let what = if context.is_empty() {
                format!("`{}`", p.text())
            } else {
                format!("`{}` {context}", p.text())
            };
            Err(self.expected(&what, &tok))
        }
    }

    /// [`Evaluator::expect`] with the context written only when it is needed.
    fn expect_lazy(
        &mut self,
        p: Punct,
        context: impl FnOnce() -> String,
    ) -> Result<Token, Diagnostic> {
        let tok = self.peek()?;
        if tok.is_punct(p) {
            self.advance();
            Ok(tok)
        } else {
            self.expect(p, &context())
        }
    }

    fn eat(&mut self, p: Punct) -> Result<bool, Diagnostic> {
        if self.peek()?.is_punct(p) {
            self.advance();
            Ok(true)
        } else {
            Ok(false)
        }
    }

    fn eat_ident(&mut self, name: &str) -> Result<bool, Diagnostic> {
        if self.peek()?.is_ident(name) {
            self.advance();
            Ok(true)
        } else {
            Ok(false)
        }
    }

    /// Guards recursion: every nested block, parenthesis and call goes through here.
    fn enter(&mut self, span: Span) -> Result<(), Diagnostic> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(self.err(
                span,
                format!("nesting is too deep (more than {MAX_DEPTH} levels)"),
            ));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    /// Marks a name the token stream must look up wherever it appears.
    fn mark_special(&mut self, name: &str) {
        let name = super::parse::intern(name);
        self.special_names.insert(name.as_ptr() as usize);
    }

    /// Whether a token's (interned) name may be bound to a macro or an unsupported value.
    fn may_be_special(&self, name: crate::lang::syntax::Name) -> bool {
        !self.special_names.is_empty() && self.special_names.contains(&(name.as_ptr() as usize))
    }

    fn lookup(&self, name: &str) -> Option<&Value> {
        self.scopes.iter().rev().find_map(|s| s.get(&NameRef(name)))
    }

    /// The unknown-identifier error with the nearest declared name as a hint.
    fn unknown_identifier(&self, tok: &Token, name: &str) -> Diagnostic {
        let mut d = self.err(tok.span, format!("unknown identifier `{name}`"));
        let names = self.scopes.iter().flat_map(|s| s.keys().map(Key::text));
        if let Some(best) = super::diagnostics::nearest(name, names) {
            d = d.with_hint(format!("did you mean `{best}`?"));
        } else if let Some(best) =
            super::diagnostics::nearest(name, keywords::KEYWORDS.iter().copied())
        {
            d = d.with_hint(format!("did you mean `{best}`?"));
        }
        d
    }

    /// A texture for an object: the last one handed out when equal (objects made by a loop
    /// share one), else a new shared one.
    fn share_texture(
        &mut self,
        texture: crate::scene::Texture,
    ) -> std::sync::Arc<crate::scene::Texture> {
        if let Some(last) = &self.last_texture
            && **last == texture
        {
            return last.clone();
        }
        // Charged when it is known: an error here would change nothing.
        let size = std::mem::size_of::<crate::scene::Texture>() as u64;
        self.budget.used = self.budget.used.saturating_add(size);
        let shared = std::sync::Arc::new(texture);
        self.last_texture = Some(shared.clone());
        shared
    }

    /// Sets the memory budget (bytes) the scene's objects and values may take.
    pub fn set_memory_budget(&mut self, bytes: u64) {
        self.budget.limit = bytes;
    }

    /// Counts `n` shapes (or mesh triangles) made of `bytes_each`, against the memory
    /// budget, so a loop cannot fill memory with objects unnoticed.
    fn count_objects(&mut self, n: u64, bytes_each: usize, span: Span) -> Result<(), Diagnostic> {
        let bytes = n.saturating_mul(bytes_each as u64);
        self.charge(bytes, budget::Growth::Objects(n), span)
    }

    /// An unsupported feature at `tok`: an error, or with `--skip-unsupported` a warning,
    /// and the feature (the keyword, then its `{ ... }` block or its value) is skipped.
    fn unsupported_or_skip(&mut self, tok: &Token, name: &str) -> Result<(), Diagnostic> {
        if !self.skip_unsupported {
            return Err(self.unsupported(tok, name));
        }
        self.warn(
            tok.span,
            format!("unsupported: `{name}` is not supported yet; it is left out"),
        );
        self.next()?;
        self.skip_feature_body()
    }

    /// Skips to the `}` that closes the block being read, and past it.
    /// Reads tokens as written (no directives, no macros, no identifier checks): the block
    /// is being dropped, and an identifier in it may itself be an unsupported value.
    fn skip_rest_of_block(&mut self) -> Result<(), Diagnostic> {
        let mut depth = 1usize;
        while depth > 0 {
            let t = if self.raw_peek(0).is_some() {
                self.raw_next()
            } else {
                self.next()?
            };
            match &t.kind {
                TokenKind::Eof => return Err(self.expected("`}`", &t)),
                TokenKind::Punct(Punct::LBrace) => depth += 1,
                TokenKind::Punct(Punct::RBrace) => depth -= 1,
                _ => {}
            }
        }
        Ok(())
    }

    /// After an unsupported keyword: a balanced `{ ... }` block, or an expression value.
    fn skip_feature_body(&mut self) -> Result<(), Diagnostic> {
        let tok = self.peek()?;
        if tok.is_punct(Punct::LBrace) {
            self.next()?;
            return self.skip_rest_of_block();
        }
        let starts_value = match &tok.kind {
            TokenKind::Number(_) | TokenKind::Str(_) => true,
            TokenKind::Punct(p) => matches!(p, Punct::Lt | Punct::Minus | Punct::LParen),
            TokenKind::Ident(w) => {
                self.lookup(w).is_some()
                    || keywords::is_function(w)
                    || keywords::is_colour_keyword(w)
                    || matches!(
                        &**w,
                        "x" | "y" | "z" | "pi" | "on" | "off" | "true" | "false"
                    )
            }
            _ => false,
        };
        if starts_value {
            self.expr()?;
        }
        Ok(())
    }

    fn unsupported(&self, tok: &Token, name: &str) -> Diagnostic {
        self.err(
            tok.span,
            format!("unsupported: `{name}` is not supported yet"),
        )
    }
}
