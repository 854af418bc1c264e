//! The failures whose reason is written down (tests/corpus/known-differences.txt): a missing
//! feature, or a measured POV-Ray behaviour penumbra does not copy. One list, read by the
//! sweep, so the report says which failures are explained and flags an entry whose scene
//! passes again.

/// One `scene | reason` line.
#[derive(Debug, Clone, PartialEq)]
pub struct Known {
    /// Path relative to the scenes folder, as in the report.
    pub scene: String,
    pub reason: String,
}

/// Reads `scene | reason` lines; `#` starts a comment line, blank lines are skipped.
pub fn parse_known(text: &str) -> Result<Vec<Known>, String> {
    let mut known = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let Some((scene, reason)) = line.split_once('|') else {
            return Err(format!("line {}: expected `scene | reason`", i + 1));
        };
        let (scene, reason) = (scene.trim(), reason.trim());
        if scene.is_empty() || reason.is_empty() {
            return Err(format!("line {}: empty scene or reason", i + 1));
        }
        if known.iter().any(|k: &Known| k.scene == scene) {
            return Err(format!("line {}: {scene} is listed twice", i + 1));
        }
        known.push(Known {
            scene: scene.to_string(),
            reason: reason.to_string(),
        });
    }
    Ok(known)
}

/// The written reason for a scene, if any.
pub fn reason<'a>(known: &'a [Known], scene: &str) -> Option<&'a str> {
    known
        .iter()
        .find(|k| k.scene == scene)
        .map(|k| k.reason.as_str())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_comments_and_errors_with_their_line() {
        let k = parse_known("# note\n\na/b.pov | noise phase\n c.pov|x \n").unwrap();
        assert_eq!(k.len(), 2);
        assert_eq!(reason(&k, "a/b.pov"), Some("noise phase"));
        assert_eq!(reason(&k, "c.pov"), Some("x"));
        assert_eq!(reason(&k, "d.pov"), None);
        assert_eq!(
            parse_known("ok.pov | a\nno bar\n").unwrap_err(),
            "line 2: expected `scene | reason`"
        );
        assert!(
            parse_known("a.pov |\n")
                .unwrap_err()
                .starts_with("line 1: empty")
        );
        assert!(
            parse_known("a.pov | x\na.pov | y\n")
                .unwrap_err()
                .contains("twice")
        );
    }
}
