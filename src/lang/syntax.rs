//! The syntax tree of a scene file.
//!
//! POV-Ray's language is directive-driven: `#if`, `#while` and macro calls may appear
//! anywhere, even in the middle of an expression or an object, and macros expand to raw
//! text. A nested tree of statements cannot represent that faithfully, so the tree here is
//! deliberately flat: a file is a sequence of tokens, each with its span, and the evaluator
//! (`eval`) gives them structure while it reads them, exactly as POV-Ray does. Tokens are
//! shared (`Rc`) so loops and macro bodies replay them without copying, and are plain
//! `Copy` values: names and strings are interned ([`Name`]), so reading a token copies a few
//! words and never touches a reference count.

/// An interned name or string: one copy per distinct text for the life of the process
/// (bounded by the scene text read), so tokens can be `Copy` and equal names share a pointer.
pub type Name = &'static str;

use super::diagnostics::Span;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Punct {
    LBrace,
    RBrace,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Lt,
    Gt,
    Le,
    Ge,
    Eq,
    Ne,
    Comma,
    Semi,
    Plus,
    Minus,
    Star,
    Slash,
    Question,
    Colon,
    Dot,
    Bang,
    Amp,
    Pipe,
}

impl Punct {
    pub fn text(self) -> &'static str {
        match self {
            Punct::LBrace => "{",
            Punct::RBrace => "}",
            Punct::LParen => "(",
            Punct::RParen => ")",
            Punct::LBracket => "[",
            Punct::RBracket => "]",
            Punct::Lt => "<",
            Punct::Gt => ">",
            Punct::Le => "<=",
            Punct::Ge => ">=",
            Punct::Eq => "=",
            Punct::Ne => "!=",
            Punct::Comma => ",",
            Punct::Semi => ";",
            Punct::Plus => "+",
            Punct::Minus => "-",
            Punct::Star => "*",
            Punct::Slash => "/",
            Punct::Question => "?",
            Punct::Colon => ":",
            Punct::Dot => ".",
            Punct::Bang => "!",
            Punct::Amp => "&",
            Punct::Pipe => "|",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TokenKind {
    Number(f64),
    /// Keywords and user identifiers alike: which is which depends on where they appear.
    Ident(Name),
    Str(Name),
    /// `#name` (POV-Ray allows spaces after the `#`).
    Directive(Name),
    Punct(Punct),
    /// End of a file or of a macro body.
    Eof,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Token {
    pub kind: TokenKind,
    pub span: Span,
}

impl Token {
    pub fn is_punct(&self, p: Punct) -> bool {
        self.kind == TokenKind::Punct(p)
    }

    pub fn ident(&self) -> Option<Name> {
        match &self.kind {
            TokenKind::Ident(s) => Some(s),
            _ => None,
        }
    }

    pub fn is_ident(&self, name: &str) -> bool {
        self.ident() == Some(name)
    }

    /// How the token reads in an error message.
    pub fn describe(&self) -> String {
        match &self.kind {
            TokenKind::Number(n) => format!("`{n}`"),
            TokenKind::Ident(s) => format!("`{s}`"),
            TokenKind::Str(s) => format!("string \"{s}\""),
            TokenKind::Directive(s) => format!("`#{s}`"),
            TokenKind::Punct(p) => format!("`{}`", p.text()),
            TokenKind::Eof => "end of file".to_string(),
        }
    }
}

/// One source file after tokenizing.
#[derive(Clone, Debug)]
pub struct SourceTokens {
    pub tokens: std::rc::Rc<[Token]>,
    /// Where "end of file" errors point.
    pub eof: Span,
}
