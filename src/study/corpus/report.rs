//! docs/corpus.md: the counts, how scenes are judged, one row per scene, and a gallery of
//! the failures (penumbra's mean of K seeds beside POV-Ray's reference, sRGB PNGs).

use super::judge::{DIST_BLOCK, DIST_Z, TestKind};
use super::{CorpusRequest, Outcome, ParseStatus, Row, scan};
use crate::output::{BitDepth, Image, write_image};
use crate::study::StudyError;
use crate::study::reference::MediaQuadrature;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// What every rewrite of the report shares.
pub struct Context<'a> {
    pub req: &'a CorpusRequest,
    pub povray_version: &'a str,
    pub start: Instant,
}

/// The folder of the gallery's PNGs: the report's path without `.md` (docs/corpus/).
pub fn gallery_dir(out: &Path) -> PathBuf {
    out.with_extension("")
}

/// penumbra (left) beside POV-Ray (right), one PNG per failing scene.
pub fn write_gallery_image(
    req: &CorpusRequest,
    scene: &str,
    penumbra: &Image,
    povray: &Image,
) -> Result<PathBuf, StudyError> {
    let dir = gallery_dir(&req.out);
    std::fs::create_dir_all(&dir).map_err(|source| StudyError::Io {
        path: dir.clone(),
        source,
    })?;
    let (w, h) = (penumbra.width, penumbra.height);
    let gap = 4;
    let both = Image::from_fn(2 * w + gap, h, |x, y| {
        if x < w {
            penumbra.get(x, y)
        } else if x >= w + gap && x - w - gap < povray.width && y < povray.height {
            povray.get(x - w - gap, y)
        } else {
            [1.0; 3]
        }
    });
    let path = dir.join(format!("{}.png", scan::flat_name(scene)));
    write_image(&path, &both, BitDepth::Eight)?;
    Ok(path)
}

/// Rewrites the report from the rows so far.
pub fn write(context: &Context, rows: &[Row], finished: bool) -> Result<(), StudyError> {
    let text = markdown(context, rows, finished);
    let out = &context.req.out;
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|source| StudyError::Io {
            path: dir.to_path_buf(),
            source,
        })?;
    }
    std::fs::write(out, text).map_err(|source| StudyError::Io {
        path: out.clone(),
        source,
    })
}

/// The written reason of a failing scene (tests/corpus/known-differences.txt).
fn known_reason(row: &Row) -> Option<&str> {
    row.known.as_deref()
}

fn fails(row: &Row) -> bool {
    matches!(&row.outcome, Outcome::Judged(j) if !j.passes())
        || matches!(row.outcome, Outcome::RenderFailed(_))
}

/// Short words for the table's result column.
pub fn result_text(row: &Row) -> String {
    match (&row.parse, &row.outcome) {
        (ParseStatus::Parsed, Outcome::NotMeasured) => "not measured yet".into(),
        (ParseStatus::Parsed, Outcome::RenderFailed(_)) => "penumbra failed".into(),
        (ParseStatus::Parsed, Outcome::ReferenceFailed(_)) => "POV-Ray failed".into(),
        (ParseStatus::Parsed, Outcome::Judged(j)) if j.passes() => "pass".into(),
        (ParseStatus::Parsed, Outcome::Judged(_)) if known_reason(row).is_some() => {
            "fail, reason known".into()
        }
        (ParseStatus::Parsed, Outcome::Judged(_)) => "**FAIL**".into(),
        _ => "does not parse".into(),
    }
}

fn parse_text(parse: &ParseStatus) -> &'static str {
    match parse {
        ParseStatus::Parsed => "yes",
        ParseStatus::Unsupported(_) => "unsupported",
        ParseStatus::Error(_) => "error",
        ParseStatus::Crash(_) => "crash",
        ParseStatus::TimedOut => "timeout",
    }
}

fn test_text(row: &Row) -> String {
    let mut kind = kind_text(row);
    if row.phase_anchor.is_some() {
        kind.push_str(", phase ensemble");
    }
    match row.media {
        MediaQuadrature::AsWritten => kind,
        MediaQuadrature::Converged => format!("{kind}, media converged"),
    }
}

fn kind_text(row: &Row) -> String {
    match &row.test {
        TestKind::Pixel => "pixel".into(),
        TestKind::Distribution(words) => {
            let mut shown: Vec<&str> = words.iter().take(3).map(String::as_str).collect();
            if words.len() > 3 {
                shown.push("...");
            }
            format!("distribution ({})", shown.join(", "))
        }
    }
}

fn detail_text(row: &Row) -> String {
    let text = match (&row.parse, &row.outcome) {
        (ParseStatus::Unsupported(m) | ParseStatus::Error(m) | ParseStatus::Crash(m), _) => {
            m.clone()
        }
        (ParseStatus::TimedOut, _) => "parse timed out".into(),
        (_, Outcome::RenderFailed(m) | Outcome::ReferenceFailed(m)) => m.clone(),
        (_, Outcome::Judged(j)) => {
            let p = &j.pixel;
            let d = &j.distribution;
            let ensemble = j.ensemble.as_ref().map_or(String::new(), |e| {
                format!(
                    "phase ensemble of {}: blocks failed {}/{}, worst {:.2}; ",
                    super::ensemble::PHASES,
                    e.failures.len(),
                    e.tested,
                    e.worst_ratio
                )
            });
            ensemble
                + &format!(
                    "sqrt(B) {:.4}, tiles failed {}/{}, non-finite {}; distribution blocks failed {}/{}, worst {:.2}",
                    p.sqrt_b,
                    p.tiles.failed(),
                    p.tiles.tested,
                    p.non_finite_count,
                    d.failures.len(),
                    d.tested,
                    d.worst_ratio
                )
        }
        _ => String::new(),
    };
    let mut text = text.replace('|', "\\|").replace('\n', " ");
    if text.len() > 160 {
        let mut cut = 157;
        while !text.is_char_boundary(cut) {
            cut -= 1;
        }
        text.truncate(cut);
        text.push_str("...");
    }
    if row.ini.is_some() {
        text.push_str(" (POV-Ray with its INI)");
    }
    match known_reason(row) {
        Some(reason) if fails(row) => format!("{}; {text}", reason.replace('|', "\\|")),
        Some(_) if matches!(row.outcome, Outcome::Judged(_)) => {
            format!("{text} (passes: its entry in known-differences.txt can go)")
        }
        _ => text,
    }
}

fn seconds(value: Option<f64>) -> String {
    value.map_or_else(String::new, |s| format!("{s:.1}"))
}

/// The counts at the top of the report.
fn counts(rows: &[Row]) -> String {
    let count = |f: &dyn Fn(&Row) -> bool| rows.iter().filter(|r| f(r)).count();
    let judged = |r: &Row, pass: bool, pixel: bool| match &r.outcome {
        Outcome::Judged(j) => j.passes() == pass && (j.kind == TestKind::Pixel) == pixel,
        _ => false,
    };
    let lines = [
        ("scenes", rows.len()),
        ("parse", count(&|r| r.parse == ParseStatus::Parsed)),
        (
            "render (penumbra's K seeds)",
            count(&|r| matches!(r.outcome, Outcome::Judged(_) | Outcome::ReferenceFailed(_))),
        ),
        ("pass, pixel test", count(&|r| judged(r, true, true))),
        (
            "pass, distribution test",
            count(&|r| judged(r, true, false)),
        ),
        ("fail, pixel test", count(&|r| judged(r, false, true))),
        (
            "fail, distribution test",
            count(&|r| judged(r, false, false)),
        ),
        (
            "fail, with the reason written down",
            count(&|r| fails(r) && known_reason(r).is_some()),
        ),
        (
            "fail, unexplained",
            count(&|r| fails(r) && known_reason(r).is_none()),
        ),
        (
            "penumbra failed to render",
            count(&|r| matches!(r.outcome, Outcome::RenderFailed(_))),
        ),
        (
            "POV-Ray failed or timed out",
            count(&|r| matches!(r.outcome, Outcome::ReferenceFailed(_))),
        ),
        (
            "parse, not measured yet",
            count(&|r| r.parse == ParseStatus::Parsed && r.outcome == Outcome::NotMeasured),
        ),
    ];
    let mut s = String::from("| | scenes |\n| --- | ---: |\n");
    for (name, n) in lines {
        let _ = writeln!(s, "| {name} | {n} |");
    }
    s
}

fn method(context: &Context) -> String {
    let req = context.req;
    format!(
        "## How a scene is judged

penumbra renders each scene {seeds} times (seeds 100..) at {w}x{h}, {spp} samples per pixel;
POV-Ray renders it {k} and {k2} times larger without anti-aliasing, averaged over k x k
blocks (`penumbra reference`). Animated scenes are compared at clock 0; a scene whose folder
holds its INI file is rendered by both with it (its first frame only). A scene with media
(\"media converged\") is rendered by POV-Ray with every media block ending in `method 2
intervals 10 samples 10` (`penumbra reference --converged-media`): POV-Ray's default
quadrature overshoots the integral by 2-25% where media glows, and penumbra estimates the
integral itself (docs/differences.md, \"Media: the integral\").

- **pixel test** (docs: shared testing-statistics.md): sqrt(B) on 4x4 block means <= 0.005,
  no failing 8x8 tile (z* = 4.78, delta = 0.004 + 0.02 |r|), every value finite.
- **distribution test**, for scenes whose textures use POV-Ray's noise (a static scan of the
  scene, its local includes, and the library declarations it names, for {keywords}): penumbra's
  noise matches POV-Ray's only in distribution, so per channel and {b}x{b} block, the mean and
  the 10/50/90% quantiles of the mean of the {seeds} seeds are compared with the reference's.
  A block fails when |d| > 0.005 + 0.02 |S(r)| (+ 1.28 times the RMS per-pixel noise of the
  mean, for quantiles, which noise biases outward) + {z} SE, with SE^2 the sum of: the replicates'
  variance of the statistic / K (sampling); the variance of the
  difference over the block's 16 sub-blocks / 4 (the texture: the scene's layout cancels in a
  sub-block's difference, the noise's phase does not; 4, not 16, allows for noise correlated
  over neighbouring sub-blocks; 1 for the quantiles, which a few sub-blocks may set); and (S(r_k) - S(r_k/2))^2 (the
  reference's own error). z = {z}: Sidak, alpha = 1e-3 over 144 tests. The same terms summed
  over all blocks give a pooled test per channel and statistic, which sees a change of the
  whole image (a gain, an offset) about sqrt(12) times smaller than one block does. It catches a wrong
  colour, brightness, missing object or camera over a block, not detail inside a busy block.
  The derivation is in src/study/corpus/judge.rs.
- **phase ensemble**, for the noise scenes listed in tests/corpus/phase-ensemble.txt, whose
  noise is larger than the blocks (a cloud sky spanning the image), so that one phase decides
  every block and POV-Ray's own image moves by more than the distribution test allows when
  the noise is shifted: {phases} copies, the noise shifted by `translate <7k, 3k, 5k>` after
  the listed anchor, are rendered by both (penumbra one seed at {phase_spp} spp, POV-Ray at
  k = {phase_k}); per channel and block, and pooled, the block mean averaged over the phases
  must agree within 0.005 + 0.02 |r| + t SE, SE^2 = the two ensembles' variances / {phases}
  (plus the references' own error), t Student's at Welch's degrees of freedom for alpha =
  1e-3 (Sidak) over the tests; and the pooled image's spread over the phases must agree
  (ln of the variance ratio within z sqrt(4 / (N - 1)), each variance floored by the mean
  test's squared tolerance). Where the noise does not reach, the phases do not spread and
  the test is as sharp as the pixel test. It decides instead of the distribution test
  (src/study/corpus/ensemble.rs).

Both statistics are computed for every scene; the test named in the table decides.

",
        seeds = req.seeds,
        w = req.width,
        h = req.height,
        spp = req.spp,
        k = req.supersample,
        k2 = req.supersample / 2,
        b = DIST_BLOCK,
        z = DIST_Z,
        keywords = scan::NOISE_KEYWORDS[..16].join(", "),
        phases = super::ensemble::PHASES,
        phase_spp = (req.spp / 4).max(1),
        phase_k = super::ensemble::PHASE_SUPERSAMPLE,
    )
}

/// The whole report.
pub fn markdown(context: &Context, rows: &[Row], finished: bool) -> String {
    let req = context.req;
    let measured = rows
        .iter()
        .filter(|r| r.outcome != Outcome::NotMeasured)
        .count();
    let mut s = String::from("# POV-Ray's example scenes: penumbra against POV-Ray\n\n");
    let _ = writeln!(
        s,
        "Generated by `tests/corpus/compare-all.sh` (`penumbra corpus`) from {}; POV-Ray: {}. \
         Sweep {}: {:.0} s of wall time, {measured} scenes measured{}.\n",
        req.scenes_dir.display(),
        context.povray_version,
        if finished {
            "finished"
        } else {
            "interrupted or still running"
        },
        context.start.elapsed().as_secs_f64(),
        req.only
            .as_deref()
            .map_or_else(String::new, |g| format!(" (only `{g}`)")),
    );
    s.push_str(&counts(rows));
    s.push('\n');
    s.push_str(&method(context));
    s.push_str("## Every scene\n\n");
    s.push_str("| scene | parses | test | result | detail | penumbra s | POV-Ray s |\n");
    s.push_str("| --- | --- | --- | --- | --- | ---: | ---: |\n");
    for row in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {}{} |",
            row.scene,
            parse_text(&row.parse),
            test_text(row),
            result_text(row),
            detail_text(row),
            seconds(row.penumbra_seconds),
            seconds(row.povray_seconds),
            if row.cached { " (cached)" } else { "" }
        );
    }
    s.push_str(&gallery(req, rows));
    s
}

fn gallery(req: &CorpusRequest, rows: &[Row]) -> String {
    let dir_name = gallery_dir(&req.out)
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut s = String::from(
        "\n## Failures\n\npenumbra's mean of the seeds (left) beside POV-Ray's reference (right).\n",
    );
    for row in rows {
        if let Outcome::Judged(j) = &row.outcome
            && !j.passes()
        {
            let _ = write!(
                s,
                "\n### {}\n\n{}{}\n\n![{}]({}/{}.png)\n",
                row.scene,
                known_reason(row).map_or_else(String::new, |r| format!("Reason: {r}\n\n")),
                j.summary().replace('|', "\\|"),
                row.scene,
                dir_name,
                scan::flat_name(&row.scene)
            );
        }
    }
    s
}
