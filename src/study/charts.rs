//! Charts of accuracy against speed, and signed difference images, drawn with plotters.
//!
//! Every chart is written twice from one drawing function: SVG for the docs (small, sharp)
//! and PNG for viewers without SVG. Text in the PNG needs a font; one is compiled in (from
//! `epaint_default_fonts`) so that charts look the same on every machine and never depend
//! on the fonts a system happens to have installed.

use super::StudyError;
use crate::output::Image;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;
use std::path::Path;
use std::sync::OnceLock;

const FONT: &str = "sans-serif";
const CHART_SIZE: (u32, u32) = (900, 620);

/// Registers the compiled-in font once; plotters' text layout (for SVG too) needs it.
fn font() -> Result<(), StudyError> {
    static REGISTERED: OnceLock<Result<(), String>> = OnceLock::new();
    REGISTERED
        .get_or_init(|| {
            plotters::style::register_font(
                FONT,
                FontStyle::Normal,
                epaint_default_fonts::UBUNTU_LIGHT,
            )
            .map_err(|_| "the compiled-in chart font is not a valid TrueType font".to_string())
        })
        .clone()
        .map_err(StudyError::Chart)
}

fn chart_error<E: std::fmt::Debug>(path: &Path) -> impl Fn(E) -> StudyError + '_ {
    move |e| StudyError::Chart(format!("{}: {e:?}", path.display()))
}

/// One method's measured points (x, median error, lowest, highest), joined by a line.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    pub label: String,
    pub points: Vec<BandPoint>,
    /// Index into the palette, so the same quantity keeps its colour across charts.
    pub colour: usize,
    /// Draw the line thinner and without markers: a component, not a method.
    pub secondary: bool,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandPoint {
    pub x: f64,
    pub y: f64,
    pub low: f64,
    pub high: f64,
}

/// Single measurements drawn as labelled markers (POV-Ray's quality settings).
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    pub label: String,
    pub x: f64,
    pub y: f64,
}

/// Everything on one log-log error chart.
#[derive(Debug, Clone, PartialEq)]
pub struct ErrorChart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub curves: Vec<Curve>,
    pub markers: Vec<Marker>,
    /// Dashed horizontal floors: (label, value). Non-positive values are not drawn.
    pub floors: Vec<(String, f64)>,
    /// Reference slopes drawn through the first point of the first curve.
    pub slopes: Vec<f64>,
    /// Dotted horizontal target errors.
    pub targets: Vec<f64>,
}

const PALETTE: [RGBColor; 6] = [
    RGBColor(0x1f, 0x77, 0xb4),
    RGBColor(0xd6, 0x27, 0x28),
    RGBColor(0x2c, 0xa0, 0x2c),
    RGBColor(0x94, 0x67, 0xbd),
    RGBColor(0xff, 0x7f, 0x0e),
    RGBColor(0x8c, 0x56, 0x4b),
];

fn colour(index: usize) -> RGBColor {
    PALETTE[index % PALETTE.len()]
}

/// Writes `chart` as `stem.svg` and `stem.png`.
pub fn write_error_chart(stem: &Path, chart: &ErrorChart) -> Result<(), StudyError> {
    font()?;
    let svg = stem.with_extension("svg");
    {
        let root = SVGBackend::new(&svg, CHART_SIZE).into_drawing_area();
        draw_error_chart(&root, chart).map_err(chart_error(&svg))?;
        root.present().map_err(chart_error(&svg))?;
    }
    let png = stem.with_extension("png");
    let mut buffer = vec![0u8; (CHART_SIZE.0 * CHART_SIZE.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, CHART_SIZE).into_drawing_area();
        draw_error_chart(&root, chart).map_err(chart_error(&png))?;
        root.present().map_err(chart_error(&png))?;
    }
    save_rgb_png(&png, &buffer, CHART_SIZE)
}

fn save_rgb_png(path: &Path, buffer: &[u8], (w, h): (u32, u32)) -> Result<(), StudyError> {
    image::save_buffer_with_format(
        path,
        buffer,
        w,
        h,
        image::ExtendedColorType::Rgb8,
        image::ImageFormat::Png,
    )
    .map_err(|e| StudyError::Chart(format!("{}: {e}", path.display())))
}

/// Axis range covering `values` with a margin of a fifth of a decade each side.
fn log_range(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return None;
    }
    let margin = 10f64.powf(0.2);
    Some((lo / margin, hi * margin))
}

type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// The log-log axes both charts are drawn on.
type LogChart<'a, DB> = ChartContext<'a, DB, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

fn draw_error_chart<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    chart: &ErrorChart,
) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let Some(((x0, x1), (y0, y1))) = axis_ranges(chart) else {
        // Nothing measurable: an empty chart with its title still says so.
        root.titled(&format!("{} (no data)", chart.title), (FONT, 22))?;
        return Ok(());
    };
    let mut ctx = ChartBuilder::on(root)
        .caption(&chart.title, (FONT, 22))
        .margin(14)
        .x_label_area_size(46)
        .y_label_area_size(72)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?;
    ctx.configure_mesh()
        .x_desc(chart.x_label.as_str())
        .y_desc(chart.y_label.as_str())
        .label_style((FONT, 15))
        .axis_desc_style((FONT, 17))
        .x_label_formatter(&|v| format_number(*v))
        .y_label_formatter(&|v| format_number(*v))
        .light_line_style(RGBColor(0xee, 0xee, 0xee))
        .draw()?;
    draw_targets(&mut ctx, &chart.targets, (x0, x1))?;
    draw_floors(&mut ctx, &chart.floors, (x0, x1))?;
    draw_slopes(&mut ctx, chart, x1)?;
    for curve in &chart.curves {
        draw_curve(&mut ctx, curve)?;
    }
    draw_markers(&mut ctx, &chart.markers)?;
    ctx.configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .label_font((FONT, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// The x and y ranges covering every point, marker, floor and target; `None` without data.
fn axis_ranges(chart: &ErrorChart) -> Option<((f64, f64), (f64, f64))> {
    let xs = chart
        .curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.x))
        .chain(chart.markers.iter().map(|m| m.x));
    let ys = chart
        .curves
        .iter()
        .flat_map(|c| c.points.iter().flat_map(|p| [p.y, p.low, p.high]))
        .chain(chart.markers.iter().map(|m| m.y))
        .chain(chart.floors.iter().map(|f| f.1))
        .chain(chart.targets.iter().copied());
    Some((log_range(xs)?, log_range(ys)?))
}

/// Dotted grey lines across the chart at the target errors.
fn draw_targets<DB: DrawingBackend>(
    ctx: &mut LogChart<'_, DB>,
    targets: &[f64],
    (x0, x1): (f64, f64),
) -> DrawResult<DB> {
    let grey = RGBColor(0x99, 0x99, 0x99);
    for &target in targets {
        ctx.draw_series(DashedLineSeries::new(
            [(x0, target), (x1, target)],
            2,
            5,
            grey.stroke_width(1),
        ))?
        .label(format!("target {}", format_number(target)))
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], grey));
    }
    Ok(())
}

/// Dashed floors; one that is zero (or not finite) only appears in the legend.
fn draw_floors<DB: DrawingBackend>(
    ctx: &mut LogChart<'_, DB>,
    floors: &[(String, f64)],
    (x0, x1): (f64, f64),
) -> DrawResult<DB> {
    for (index, (label, value)) in floors.iter().enumerate() {
        let c = colour(3 + index);
        if *value <= 0.0 || !value.is_finite() {
            // Nothing to draw on a log axis, but the legend still says it was measured.
            ctx.draw_series(std::iter::empty::<PathElement<(f64, f64)>>())?
                .label(format!("{label} = 0 (not drawn)"))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                });
            continue;
        }
        ctx.draw_series(DashedLineSeries::new(
            [(x0, *value), (x1, *value)],
            10,
            6,
            c.stroke_width(2),
        ))?
        .label(format!("{label} = {}", format_number(*value)))
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    Ok(())
}

/// Reference slopes from the first point of the first curve to the right edge.
fn draw_slopes<DB: DrawingBackend>(
    ctx: &mut LogChart<'_, DB>,
    chart: &ErrorChart,
    x1: f64,
) -> DrawResult<DB> {
    let Some(first) = chart.curves.first().and_then(|c| c.points.first()) else {
        return Ok(());
    };
    for &slope in &chart.slopes {
        let line = [
            (first.x, first.y),
            (x1, first.y * (x1 / first.x).powf(slope)),
        ];
        let c = RGBColor(0x55, 0x55, 0x55);
        ctx.draw_series(DashedLineSeries::new(line, 3, 3, c.stroke_width(1)))?
            .label(format!("slope {slope}"))
            .legend(move |(x, y)| PathElement::new(vec![(x, y + 4), (x + 20, y - 4)], c));
    }
    Ok(())
}

/// One curve: its line, dots at the measurements (primary curves only), and the spread
/// over seeds.
fn draw_curve<DB: DrawingBackend>(ctx: &mut LogChart<'_, DB>, curve: &Curve) -> DrawResult<DB> {
    let c = colour(curve.colour);
    let width = if curve.secondary { 1 } else { 2 };
    // Zeros (a bias estimate clamped at 0) have no place on a log axis.
    let points: Vec<(f64, f64)> = curve
        .points
        .iter()
        .filter(|p| p.y > 0.0)
        .map(|p| (p.x, p.y))
        .collect();
    ctx.draw_series(LineSeries::new(points.clone(), c.stroke_width(width)))?
        .label(curve.label.as_str())
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(width)));
    if !curve.secondary {
        ctx.draw_series(
            points
                .iter()
                .map(|&(x, y)| Circle::new((x, y), 3, c.filled())),
        )?;
    }
    // The spread over seeds: a vertical bar from the lowest to the highest replicate.
    ctx.draw_series(
        curve
            .points
            .iter()
            .filter(|p| p.high > p.low && p.low > 0.0)
            .map(|p| PathElement::new(vec![(p.x, p.low), (p.x, p.high)], c.mix(0.6))),
    )?;
    Ok(())
}

/// POV-Ray's settings as labelled crosses.
fn draw_markers<DB: DrawingBackend>(
    ctx: &mut LogChart<'_, DB>,
    markers: &[Marker],
) -> DrawResult<DB> {
    if markers.is_empty() {
        return Ok(());
    }
    let pov = colour(1);
    ctx.draw_series(
        markers
            .iter()
            .map(|m| Cross::new((m.x, m.y), 6, pov.stroke_width(2))),
    )?
    .label("POV-Ray (quality settings)")
    .legend(move |(x, y)| Cross::new((x + 10, y), 6, pov.stroke_width(2)));
    // Labels sit beside their cross, not on it, so the sign of "-A" stays readable.
    ctx.draw_series(markers.iter().map(|m| {
        EmptyElement::at((m.x, m.y))
            + Text::new(m.label.clone(), (9, -4), (FONT, 13).into_font().color(&pov))
    }))?;
    Ok(())
}

/// Short labels for log axes: 0.005, 0.5, 12, 3e-4.
fn format_number(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if !(1e-3..1e5).contains(&a) {
        return format!("{v:.0e}");
    }
    let digits = (2 - a.log10().floor() as i32).max(0) as usize;
    let s = format!("{v:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The colour of a signed difference d on a scale of +-`scale`: blue below zero, white at
/// zero, red above; values beyond the scale saturate.
pub fn diverging(d: f64, scale: f64) -> [u8; 3] {
    let t = if scale > 0.0 && d.is_finite() {
        (d / scale).clamp(-1.0, 1.0)
    } else if d.is_nan() {
        // NaN shows as black so it cannot pass for a small difference.
        return [0, 0, 0];
    } else {
        d.signum()
    };
    let fade = |full: f64| (255.0 * (1.0 - t.abs()) + full * t.abs()).round() as u8;
    if t >= 0.0 {
        [fade(178.0), fade(24.0), fade(43.0)]
    } else {
        [fade(33.0), fade(102.0), fade(172.0)]
    }
}

/// Writes the signed difference `a - b` (mean of the three channels) as a PNG, enlarged to
/// be readable, with a colour bar from -`scale` to +`scale` beneath it.
pub fn write_difference_png(
    path: &Path,
    a: &Image,
    b: &Image,
    scale: f64,
) -> Result<(), StudyError> {
    font()?;
    if !a.same_size(b) || a.is_empty() {
        return Err(StudyError::SizeMismatch {
            what: "difference image".into(),
            expected: (b.width, b.height),
            found: (a.width, a.height),
        });
    }
    let zoom = (480 / a.width).clamp(1, 8) as u32;
    let (iw, ih) = (a.width as u32 * zoom, a.height as u32 * zoom);
    let bar_height = 64;
    let size = (iw.max(320), ih + bar_height);
    let mut buffer = vec![255u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, size).into_drawing_area();
        draw_colour_bar(&root, (ih as i32, size.0 as i32), scale).map_err(chart_error(path))?;
        root.present().map_err(chart_error(path))?;
    }
    for y in 0..ih {
        for x in 0..iw {
            let (px, py) = ((x / zoom) as usize, (y / zoom) as usize);
            let (p, q) = (a.get(px, py), b.get(px, py));
            let d = (0..3)
                .map(|c| f64::from(p[c]) - f64::from(q[c]))
                .sum::<f64>()
                / 3.0;
            let i = ((y * size.0 + x) * 3) as usize;
            buffer[i..i + 3].copy_from_slice(&diverging(d, scale));
        }
    }
    save_rgb_png(path, &buffer, size)
}

fn draw_colour_bar<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    (top, width): (i32, i32),
    scale: f64,
) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let (left, right) = (20, width - 20);
    let bar_top = top + 8;
    for x in left..right {
        let d = scale * (2.0 * f64::from(x - left) / f64::from(right - left - 1) - 1.0);
        let [r, g, b] = diverging(d, scale);
        root.draw(&PathElement::new(
            vec![(x, bar_top), (x, bar_top + 16)],
            RGBColor(r, g, b),
        ))?;
    }
    let style = (FONT, 14).into_font().color(&BLACK);
    let labels = [
        (left, format!("-{}", format_number(scale))),
        ((left + right) / 2 - 4, "0".to_string()),
        (right - 44, format!("+{}", format_number(scale))),
    ];
    for (x, text) in labels {
        root.draw(&Text::new(text, (x, bar_top + 22), style.clone()))?;
    }
    root.draw(&Text::new(
        "first - second (mean of R, G, B; linear)",
        (left + 60, bar_top + 40),
        style,
    ))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diverging_scale_is_signed_and_saturates() {
        assert_eq!(diverging(0.0, 1.0), [255, 255, 255]);
        assert_eq!(diverging(1.0, 1.0), [178, 24, 43]);
        assert_eq!(diverging(5.0, 1.0), [178, 24, 43]);
        assert_eq!(diverging(-1.0, 1.0), [33, 102, 172]);
        assert_eq!(diverging(f64::NAN, 1.0), [0, 0, 0]);
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(format_number(0.005), "0.005");
        assert_eq!(format_number(0.01), "0.01");
        assert_eq!(format_number(12.0), "12");
        assert_eq!(format_number(1.5), "1.5");
        assert_eq!(format_number(0.0001), "1e-4");
    }
}
