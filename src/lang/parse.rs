//! Text to tokens, with nom. Whitespace and comments (`//` and nested `/* */`) vanish
//! here; every token keeps the byte range it came from.

use std::collections::HashSet;
use std::sync::{Mutex, OnceLock};

use nom::{
    IResult, Parser,
    branch::alt,
    bytes::complete::{tag, take_while},
    character::complete::{char, digit0, digit1, one_of, satisfy},
    combinator::{opt, recognize},
};

use super::diagnostics::{Diagnostic, FileId, Span};
use super::syntax::{Name, Punct, SourceTokens, Token, TokenKind};

pub fn tokenize(file: FileId, text: &str) -> Result<SourceTokens, Diagnostic> {
    let mut tokens = Vec::new();
    let mut rest = text;
    loop {
        rest = skip_trivia(file, text, rest)?;
        if rest.is_empty() {
            break;
        }
        let start = text.len() - rest.len();
        let (after, kind) = match token(rest) {
            Ok(ok) => ok,
            Err(_) => {
                let c = rest.chars().next().unwrap_or(' ');
                let span = Span::new(file, start, start + c.len_utf8());
                return Err(if c == '"' {
                    Diagnostic::error(span, "unterminated string")
                } else {
                    Diagnostic::error(span, format!("unexpected character `{c}`"))
                });
            }
        };
        let end = text.len() - after.len();
        tokens.push(Token {
            kind,
            span: Span::new(file, start, end),
        });
        rest = after;
    }
    Ok(SourceTokens {
        tokens: tokens.into(),
        eof: Span::new(file, text.len(), text.len()),
    })
}

/// Skips whitespace and comments. Block comments nest, so this is a small loop rather than
/// a nom combinator.
fn skip_trivia<'a>(file: FileId, text: &'a str, mut rest: &'a str) -> Result<&'a str, Diagnostic> {
    loop {
        let trimmed = rest.trim_start();
        if let Some(after) = trimmed.strip_prefix("//") {
            rest = after.find('\n').map_or("", |i| &after[i..]);
        } else if trimmed.starts_with("/*") {
            let open = text.len() - trimmed.len();
            let mut depth = 0usize;
            let mut i = 0;
            let bytes = trimmed.as_bytes();
            loop {
                if i + 1 >= bytes.len() {
                    return Err(Diagnostic::error(
                        Span::new(file, open, open + 2),
                        "unterminated comment",
                    ));
                }
                if bytes[i] == b'/' && bytes[i + 1] == b'*' {
                    depth += 1;
                    i += 2;
                } else if bytes[i] == b'*' && bytes[i + 1] == b'/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            rest = &trimmed[i..];
        } else {
            return Ok(trimmed);
        }
    }
}

/// The interned names, and where the keywords' copies lie: they are interned first, side
/// by side in one block, so whether a name is a keyword is whether it points into it.
struct Interner {
    names: Mutex<HashSet<Name>>,
    keywords: std::ops::Range<usize>,
}

fn interner() -> &'static Interner {
    static INTERNER: OnceLock<Interner> = OnceLock::new();
    INTERNER.get_or_init(|| {
        let keywords = super::eval::keywords::KEYWORDS;
        let block: &'static str = Box::leak(keywords.concat().into_boxed_str());
        let mut names = HashSet::new();
        let mut at = 0;
        for k in keywords {
            names.insert(&block[at..at + k.len()]);
            at += k.len();
        }
        let start = block.as_ptr() as usize;
        Interner {
            names: Mutex::new(names),
            keywords: start..start + block.len(),
        }
    })
}

/// The one copy of `text`: names and strings live as long as the process, so tokens are
/// `Copy` (see [`Name`]). What is kept is bounded by the distinct texts of the scenes read.
pub fn intern(text: &str) -> Name {
    let mut names = interner().names.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(&name) = names.get(text) {
        return name;
    }
    let name: Name = Box::leak(text.to_owned().into_boxed_str());
    names.insert(name);
    name
}

/// Whether an interned name (a token's) is a keyword: a comparison of its address, where
/// `keywords::is_keyword` hashes the text (the evaluator asks for every name it reads).
pub fn is_interned_keyword(name: Name) -> bool {
    !name.is_empty() && interner().keywords.contains(&(name.as_ptr() as usize))
}

fn token(i: &str) -> IResult<&str, TokenKind> {
    alt((number, word, directive, string, punct)).parse(i)
}

fn number(i: &str) -> IResult<&str, TokenKind> {
    let mantissa = alt((
        recognize((digit1, opt((char('.'), digit0)))),
        recognize((char('.'), digit1)),
    ));
    let exponent = (one_of("eE"), opt(one_of("+-")), digit1);
    let (rest, text) = recognize((mantissa, opt(exponent))).parse(i)?;
    // The text is digits, a dot and an exponent only, so this cannot fail; a huge literal
    // becomes infinity, which the evaluator treats like any other float.
    let value = text.parse::<f64>().unwrap_or(f64::INFINITY);
    Ok((rest, TokenKind::Number(value)))
}

fn ident_text(i: &str) -> IResult<&str, &str> {
    recognize((
        satisfy(|c| c.is_ascii_alphabetic() || c == '_'),
        take_while(|c: char| c.is_ascii_alphanumeric() || c == '_'),
    ))
    .parse(i)
}

fn word(i: &str) -> IResult<&str, TokenKind> {
    let (rest, text) = ident_text(i)?;
    Ok((rest, TokenKind::Ident(intern(text))))
}

fn directive(i: &str) -> IResult<&str, TokenKind> {
    let (rest, (_, _, name)) = (
        char('#'),
        take_while(|c: char| c == ' ' || c == '\t'),
        opt(ident_text),
    )
        .parse(i)?;
    // A lone `#` (seen in POV-Ray's own examples) is an empty directive that does nothing.
    Ok((rest, TokenKind::Directive(intern(name.unwrap_or("")))))
}

fn string(i: &str) -> IResult<&str, TokenKind> {
    let (mut rest, _) = char('"').parse(i)?;
    let mut out = String::new();
    loop {
        let (after, chunk) =
            take_while(|c: char| c != '"' && c != '\\' && c != '\n').parse(rest)?;
        out.push_str(chunk);
        rest = after;
        if let Ok((after, _)) = char::<&str, nom::error::Error<&str>>('"').parse(rest) {
            return Ok((after, TokenKind::Str(intern(&out))));
        }
        let (after, _) = char('\\').parse(rest)?;
        let (mut after, c) = satisfy(|c| c != '\n').parse(after)?;
        out.push(match c {
            'n' => '\n',
            't' => '\t',
            'r' => '\r',
            // `\u` and four hex digits: a Unicode character, as POV-Ray reads it.
            'u' => match after.get(..4).and_then(|h| u32::from_str_radix(h, 16).ok()) {
                Some(code) => {
                    after = &after[4..];
                    char::from_u32(code).unwrap_or(char::REPLACEMENT_CHARACTER)
                }
                None => 'u',
            },
            other => other,
        });
        rest = after;
    }
}

fn punct(i: &str) -> IResult<&str, TokenKind> {
    let (rest, p) = alt((
        tag("<=").map(|_| Punct::Le),
        tag(">=").map(|_| Punct::Ge),
        tag("!=").map(|_| Punct::Ne),
        single_punct,
    ))
    .parse(i)?;
    Ok((rest, TokenKind::Punct(p)))
}

fn single_punct(i: &str) -> IResult<&str, Punct> {
    let (rest, c) = one_of("{}()[]<>=,;+-*/?:.!&|").parse(i)?;
    let p = match c {
        '{' => Punct::LBrace,
        '}' => Punct::RBrace,
        '(' => Punct::LParen,
        ')' => Punct::RParen,
        '[' => Punct::LBracket,
        ']' => Punct::RBracket,
        '<' => Punct::Lt,
        '>' => Punct::Gt,
        '=' => Punct::Eq,
        ',' => Punct::Comma,
        ';' => Punct::Semi,
        '+' => Punct::Plus,
        '-' => Punct::Minus,
        '*' => Punct::Star,
        '/' => Punct::Slash,
        '?' => Punct::Question,
        ':' => Punct::Colon,
        '.' => Punct::Dot,
        '!' => Punct::Bang,
        '&' => Punct::Amp,
        _ => Punct::Pipe,
    };
    Ok((rest, p))
}

#[cfg(test)]
mod keyword_tests {
    use super::*;

    /// The address test agrees with the text's: every keyword interned is one, and names
    /// near them (prefixes, suffixes, other cases) are not.
    #[test]
    fn interned_keywords_are_known_by_address() {
        for &k in super::super::eval::keywords::KEYWORDS {
            assert!(is_interned_keyword(intern(k)), "{k}");
            for other in [
                format!("{k}_"),
                format!("My{k}"),
                k.to_uppercase(),
                k[1..].to_string(),
            ] {
                let keyword = super::super::eval::keywords::is_keyword(&other);
                assert_eq!(is_interned_keyword(intern(&other)), keyword, "{other}");
            }
        }
        assert!(!is_interned_keyword(intern("")));
    }
}
