//! POV-Ray's media quadrature raised until it converges, for references.
//!
//! POV-Ray sums a fixed set of samples per interval along a ray in media; at its default
//! (`method 3`, one interval, a few samples) the sum overshoots the integral by 2-25% where
//! the media glows (docs/differences.md, "Media: the integral"). penumbra estimates the
//! integral itself, so it converges to what POV-Ray renders at high quadrature, not to what it
//! renders as written. A reference of a media scene is therefore rendered from a copy whose
//! every `media { }` block ends in `method 2 intervals 10 samples 10`, within 0.02% of the
//! integral on a test slab (scripts/media_quadrature.py). POV-Ray takes the last value of a
//! repeated media setting, so appending the settings overrides the scene's without having to
//! parse its expressions.

/// Appended inside every media block.
pub const CONVERGED_SETTINGS: &str = " method 2 intervals 10 samples 10 ";

/// Whether the scene text has a `media { }` block outside comments and strings. Bytes, not
/// text: scenes are often Latin-1, and their strings must reach POV-Ray unchanged.
pub fn has_media(text: &[u8]) -> bool {
    !media_block_ends(text).is_empty()
}

/// The scene text with `CONVERGED_SETTINGS` before the closing brace of every media block.
pub fn converged(text: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(text.len() + 64);
    let mut last = 0;
    for end in media_block_ends(text) {
        out.extend_from_slice(&text[last..end]);
        out.extend_from_slice(CONVERGED_SETTINGS.as_bytes());
        last = end;
    }
    out.extend_from_slice(&text[last..]);
    out
}

/// Byte offsets of the closing braces of the media blocks, in order.
fn media_block_ends(text: &[u8]) -> Vec<usize> {
    let tokens = tokens(text);
    let mut ends = Vec::new();
    let mut open: Vec<bool> = Vec::new(); // per open brace: does it open a media block?
    for (i, token) in tokens.iter().enumerate() {
        match token.text {
            b"{" => open.push(i > 0 && tokens[i - 1].text == b"media"),
            // The guard pops the brace whether or not it closes a media block.
            b"}" if open.pop() == Some(true) => ends.push(token.start),
            _ => {}
        }
    }
    ends
}

struct Token<'a> {
    text: &'a [u8],
    start: usize,
}

/// Words and braces, with comments and strings skipped (other punctuation is dropped: only
/// `media` directly before `{` matters).
fn tokens(text: &[u8]) -> Vec<Token<'_>> {
    let find =
        |haystack: &[u8], needle: &[u8]| haystack.windows(needle.len()).position(|w| w == needle);
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < text.len() {
        let rest = &text[i..];
        if rest.starts_with(b"//") {
            i += find(rest, b"\n").unwrap_or(rest.len());
        } else if rest.starts_with(b"/*") {
            i += find(&rest[2..], b"*/").map_or(rest.len(), |n| n + 4);
        } else if rest[0] == b'"' {
            i += 1 + find(&rest[1..], b"\"").map_or(rest.len() - 1, |n| n + 1);
        } else if rest[0] == b'{' || rest[0] == b'}' {
            tokens.push(Token {
                text: &rest[..1],
                start: i,
            });
            i += 1;
        } else if rest[0].is_ascii_alphanumeric() || rest[0] == b'_' {
            let len = rest
                .iter()
                .take_while(|b| b.is_ascii_alphanumeric() || **b == b'_')
                .count();
            tokens.push(Token {
                text: &rest[..len],
                start: i,
            });
            i += len;
        } else {
            i += 1;
        }
    }
    tokens
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_media_block_ends_in_the_converged_settings() {
        let text = "#declare M = media { method 3 samples 5 density { spherical } }\n\
                    box { 0, 1 interior { media { M } } hollow }";
        let out = String::from_utf8(converged(text.as_bytes())).expect("ascii");
        assert_eq!(out.matches(CONVERGED_SETTINGS).count(), 2);
        // Inside the media braces, after the nested density block, not after `density`'s.
        assert!(out.contains(&format!("density {{ spherical }} {CONVERGED_SETTINGS}}}")));
        assert!(out.contains(&format!("media {{ M {CONVERGED_SETTINGS}}}")));
    }

    #[test]
    fn comments_strings_and_longer_names_are_not_media_blocks() {
        for text in [
            "// media { }\nsphere { 0, 1 }",
            "/* media { } */ sphere { 0, 1 }",
            "#debug \"media { }\" sphere { 0, 1 }",
            "global_settings { no_media { } media_attenuation { } }",
            "sphere { 0, 1 } // media",
        ] {
            assert!(!has_media(text.as_bytes()), "{text}");
            assert_eq!(converged(text.as_bytes()), text.as_bytes());
        }
        assert!(has_media(b"interior { media\n{\n emission 1 } }"));
        // Latin-1 bytes pass through unchanged.
        let latin =
            b"// caf\xe9\ntext { ttf \"a.ttf\" \"\xe9\" 1, 0 } box { 0, 1 interior { media { } } }";
        let out = converged(latin);
        assert!(out.starts_with(&latin[..40]));
        assert_eq!(out.len(), latin.len() + CONVERGED_SETTINGS.len());
    }

    #[test]
    fn unbalanced_text_is_left_as_it_is() {
        // POV-Ray reports the error itself; the rewrite must not panic or invent a brace.
        let text = b"interior { media { emission 1 ";
        assert_eq!(converged(text), text);
        assert_eq!(converged(b"} } media"), b"} } media");
    }
}
