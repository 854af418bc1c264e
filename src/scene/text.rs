//! The `text` object's glyphs: each character's TrueType outline as exact curves (lines,
//! quadratic and cubic Béziers in the power basis a prism's profile takes), placed along +x
//! as POV-Ray 3.7 places them. The placement rules were measured with povray 3.7.0.10
//! (`trace` across the glyphs; docs/language.md has the figures):
//! - the first glyph's left side bearing is dropped, so the text starts at x = 0;
//! - each glyph's outline moves by its hmtx left side bearing minus its glyf `xMin`;
//! - the pen advances by the hmtx advance, plus the `kern` table's value for the pair,
//!   plus the offset's x and y (its z is ignored);
//! - the `kern` pairs are searched one by one: POV-Ray's fonts have unsorted pair lists,
//!   where a binary search (ttf-parser's) misses pairs povray applies.

use std::collections::HashMap;
use std::sync::Arc;

use glam::DVec2;
use ttf_parser::{Face, GlyphId, OutlineBuilder, PlatformId};

use super::Segment;

/// A font file's bytes with the outlines already converted, per glyph id.
pub struct Font {
    data: Vec<u8>,
    outlines: HashMap<u16, Option<Arc<[Segment]>>>,
}

/// A glyph of a laid-out string: its curves (see [`Font::layout`]) and where its origin
/// goes, in em units.
#[derive(Clone, Debug)]
pub struct PlacedGlyph {
    pub segments: Arc<[Segment]>,
    pub at: DVec2,
}

impl Font {
    /// The error says why the bytes are not a font penumbra can read.
    pub fn new(data: Vec<u8>) -> Result<Font, String> {
        let face = Face::parse(&data, 0).map_err(|e| format!("is not a TrueType font ({e})"))?;
        if face.tables().glyf.is_none() && face.tables().cff.is_none() {
            return Err("has no glyph outlines (no glyf or CFF table)".to_string());
        }
        Ok(Font {
            data,
            outlines: HashMap::new(),
        })
    }

    /// The glyphs of `text` with outlines, in order; a glyph's curves are in em units with
    /// the font's x along u and its y along -v, which the text object's turn stands up.
    /// Characters without a glyph take glyph 0 (the font's "missing" box), as in POV-Ray.
    pub fn layout(&mut self, text: &str, offset: DVec2) -> Vec<PlacedGlyph> {
        let Font { data, outlines } = self;
        let Ok(face) = Face::parse(data, 0) else {
            return Vec::new();
        };
        let em = f64::from(face.units_per_em().max(1));
        let ids: Vec<GlyphId> = text.chars().map(|c| glyph_for(&face, c)).collect();
        let lsb = |g: GlyphId| f64::from(face.glyph_hor_side_bearing(g).unwrap_or(0));
        let mut pen = DVec2::new(-ids.first().map_or(0.0, |&g| lsb(g)) / em, 0.0);
        let mut out = Vec::new();
        for (i, &g) in ids.iter().enumerate() {
            let segments = outlines.entry(g.0).or_insert_with(|| outline(&face, g, em));
            if let Some(segments) = segments {
                let x_min = face
                    .glyph_bounding_box(g)
                    .map_or(lsb(g), |b| f64::from(b.x_min));
                out.push(PlacedGlyph {
                    segments: Arc::clone(segments),
                    at: pen + DVec2::new((lsb(g) - x_min) / em, 0.0),
                });
            }
            let kern = ids.get(i + 1).map_or(0.0, |&next| kerning(&face, g, next));
            let advance = f64::from(face.glyph_hor_advance(g).unwrap_or(0));
            pen += DVec2::new((advance + kern) / em, 0.0) + offset;
        }
        out
    }
}

/// POV-Ray's choice of character map: a Unicode one, else the Macintosh Roman one for
/// ASCII (povlogo.ttf has only that and a symbol map), else the symbol map's private-use
/// codes; glyph 0 when none has the character.
fn glyph_for(face: &Face<'_>, c: char) -> GlyphId {
    if let Some(g) = face.glyph_index(c) {
        return g;
    }
    let code = u32::from(c);
    let tables = face.tables().cmap.into_iter().flat_map(|m| m.subtables);
    let found = tables.filter_map(|t| match (t.platform_id, t.encoding_id) {
        (PlatformId::Macintosh, 0) if code < 128 => t.glyph_index(code),
        (PlatformId::Windows, 0) if code < 256 => t.glyph_index(0xF000 + code),
        _ => None,
    });
    found.into_iter().find(|g| g.0 != 0).unwrap_or(GlyphId(0))
}

/// The summed horizontal `kern` values for a pair, each table searched in full.
fn kerning(face: &Face<'_>, left: GlyphId, right: GlyphId) -> f64 {
    let Some(kern) = face.tables().kern else {
        return 0.0;
    };
    let mut sum = 0.0;
    for table in kern.subtables {
        if !table.horizontal || table.has_cross_stream || table.variable {
            continue;
        }
        let value = match table.format {
            ttf_parser::kern::Format::Format0(pairs) => pairs
                .pairs
                .into_iter()
                .find(|p| p.left() == left && p.right() == right)
                .map(|p| p.value),
            _ => table.glyphs_kerning(left, right),
        };
        sum += f64::from(value.unwrap_or(0));
    }
    sum
}

/// A glyph's closed curves; `None` for a glyph with no outline (a space).
fn outline(face: &Face<'_>, g: GlyphId, em: f64) -> Option<Arc<[Segment]>> {
    let mut curves = Curves {
        scale: 1.0 / em,
        ..Curves::default()
    };
    face.outline_glyph(g, &mut curves)?;
    curves.close();
    (!curves.segments.is_empty()).then(|| curves.segments.into())
}

/// Collects outline segments, closing each contour with a line when it does not end where
/// it began.
#[derive(Default)]
struct Curves {
    scale: f64,
    start: DVec2,
    last: DVec2,
    segments: Vec<Segment>,
}

impl Curves {
    /// Font units to a prism's (u, v): x along u, y along -v.
    fn point(&self, x: f32, y: f32) -> DVec2 {
        DVec2::new(f64::from(x), -f64::from(y)) * self.scale
    }

    fn push(&mut self, segment: Segment, to: DVec2) {
        if to != self.last || segment[1] != DVec2::ZERO || segment[2] != DVec2::ZERO {
            self.segments.push(segment);
        }
        self.last = to;
    }
}

impl OutlineBuilder for Curves {
    fn move_to(&mut self, x: f32, y: f32) {
        self.close();
        self.start = self.point(x, y);
        self.last = self.start;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let (a, b) = (self.last, self.point(x, y));
        if a != b {
            self.push([a, b - a, DVec2::ZERO, DVec2::ZERO], b);
        }
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (a, b, c) = (self.last, self.point(x1, y1), self.point(x, y));
        self.push([a, (b - a) * 2.0, a - b * 2.0 + c, DVec2::ZERO], c);
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let a = self.last;
        let (b, c, d) = (self.point(x1, y1), self.point(x2, y2), self.point(x, y));
        let segment = [
            a,
            (b - a) * 3.0,
            (a - b * 2.0 + c) * 3.0,
            -a + b * 3.0 - c * 3.0 + d,
        ];
        self.push(segment, d);
    }

    fn close(&mut self) {
        let (a, b) = (self.last, self.start);
        if a != b {
            self.push([a, b - a, DVec2::ZERO, DVec2::ZERO], b);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FONTS: &str = "/usr/share/povray-3.7/include";

    fn font(name: &str) -> Option<Font> {
        let data = std::fs::read(std::path::Path::new(FONTS).join(name)).ok()?;
        Some(Font::new(data).expect("a TrueType font"))
    }

    /// Every contour closes: the segments' ends chain back to each contour's start, so the
    /// even-odd parity is that of closed curves.
    #[test]
    fn outlines_are_closed_chains() {
        let Some(mut f) = font("timrom.ttf") else {
            return;
        };
        for g in f.layout("AB&@gQ%8", DVec2::ZERO) {
            let ends: Vec<(DVec2, DVec2)> = g
                .segments
                .iter()
                .map(|s| (s[0], crate::scene::spline::evaluate(s, 1.0)))
                .collect();
            for (a, b) in &ends {
                let followers = ends.iter().filter(|(c, _)| (*c - *b).length() < 1e-12);
                let leaders = ends.iter().filter(|(_, d)| (*d - *a).length() < 1e-12);
                assert!(followers.count() >= 1 && leaders.count() >= 1);
            }
        }
    }

    /// The figures measured with povray (docs/language.md): "AV" and "To" kern, "AA" does
    /// not, and the text starts where the first glyph's side bearing is dropped.
    #[test]
    fn placement_matches_povray() {
        let Some(mut f) = font("timrom.ttf") else {
            return;
        };
        let at = |f: &mut Font, s: &str| -> Vec<f64> {
            f.layout(s, DVec2::ZERO).iter().map(|g| g.at.x).collect()
        };
        let near = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9);
        assert!(near(&at(&mut f, "AV"), &[-0.006, 0.557]));
        assert!(near(&at(&mut f, "VA"), &[0.0, 0.574]));
        assert!(near(&at(&mut f, "AA"), &[-0.006, 0.744]));
        assert!(near(&at(&mut f, "To"), &[-0.010, 0.538]));
        // '*' has a side bearing of 70 and an xMin of 66.
        assert!(near(&at(&mut f, "A*"), &[-0.006, 0.748]));
        let spaced = f.layout("A A", DVec2::new(0.1, 0.2));
        assert_eq!(spaced.len(), 2);
        assert!((spaced[1].at - DVec2::new(-0.006 + 1.004 + 0.2, 0.4)).length() < 1e-9);
    }

    /// The crossings of the line at height y (z = 0.5) with the text's sides, left to right.
    fn crossings(f: &mut Font, text: &str, y: f64) -> Vec<f64> {
        use crate::geometry::{PrismData, Ray};
        let mut xs = Vec::new();
        for g in f.layout(text, DVec2::ZERO) {
            let prism = PrismData::new(&g.segments, 0.0, 1.0, false, false);
            // Text space (x, y, z) is prism space (x - at.x, z, at.y - y).
            let o = glam::DVec3::new(-g.at.x - 1.0, 0.5, g.at.y - y);
            prism.each_hit(&Ray::new(o, glam::DVec3::X), |t| xs.push(t - 1.0));
        }
        xs.sort_by(f64::total_cmp);
        xs
    }

    /// POV-Ray's `trace` across the glyphs (povray 3.7.0.10, timrom.ttf, thickness 1):
    /// every wall where povray finds it, to its printing precision and trace's step.
    #[test]
    fn walls_where_povray_traces_them() {
        let Some(mut f) = font("timrom.ttf") else {
            return;
        };
        let cases: [(&str, f64, &[f64]); 4] = [
            (
                "AV",
                0.3,
                &[
                    0.179907, 0.232078, 0.433569, 0.541413, 0.779753, 0.888354, 1.023019,
                ],
            ),
            (
                "VA",
                0.3,
                &[
                    0.222749, 0.331350, 0.466023, 0.513975, 0.759903, 0.812074, 1.013573,
                ],
            ),
            (
                "To",
                0.2,
                &[0.232005, 0.336005, 0.571064, 0.667508, 0.918992, 1.009040],
            ),
            (
                "T o",
                0.2,
                &[0.232005, 0.336005, 0.867065, 0.963509, 1.214992, 1.305039],
            ),
        ];
        for (text, y, want) in cases {
            let got = crossings(&mut f, text, y);
            assert!(got.len() >= want.len(), "{text}: {got:?}");
            for (g, w) in got.iter().zip(want) {
                assert!((g - w).abs() < 2e-5, "{text}: {got:?} against {want:?}");
            }
        }
        assert!((crossings(&mut f, "*", 0.6)[0] - 0.012229).abs() < 2e-5);
        let mut crystal = font("crystal.ttf").expect("installed beside timrom");
        assert!((crossings(&mut crystal, "A", 0.3)[0] - 0.072430).abs() < 2e-5);
        let mut logo = font("povlogo.ttf").expect("installed beside timrom");
        assert!((crossings(&mut logo, "P", 0.5)[0] - 0.096875).abs() < 2e-5);
    }

    #[test]
    fn the_logo_font_maps_through_its_macintosh_table() {
        let Some(mut f) = font("povlogo.ttf") else {
            return;
        };
        let glyphs = f.layout("PP", DVec2::ZERO);
        assert_eq!(glyphs.len(), 2);
        assert!((glyphs[1].at.x - (361.0 - 1.0) / 512.0).abs() < 1e-12);
    }

    #[test]
    fn text_is_not_a_font() {
        assert!(Font::new(b"#declare X = 1;".to_vec()).is_err());
    }
}
