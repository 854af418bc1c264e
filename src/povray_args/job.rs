//! From POV-Ray's settings to what penumbra renders: the sample count the anti-aliasing
//! options stand for, the pixel window, and the frames with their clocks and file names.

use std::path::{Path, PathBuf};

use super::{Antialias, Bound, PovSettings};
use crate::lang::AnimationClock;
use crate::render::{PixelWindow, adaptive_by_default, spp_in_range};

/// Samples per pixel and whether a pilot pass spreads them where the noise is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sampling {
    /// Each pixel's count (uniform), or the largest whole count an adaptive render's
    /// budget rounds up to.
    pub spp: u32,
    /// An adaptive render's fractional average (`--spp 1.5`), else none.
    pub average: Option<f64>,
    pub adaptive: bool,
}

impl Sampling {
    /// `--spp N`: N samples per pixel, adaptive by default from 2 on; a fractional N is an
    /// average, which only adaptive sampling can spend.
    fn of(spp: f64) -> Sampling {
        let whole = spp.ceil() as u32;
        Sampling {
            spp: whole,
            average: (spp.fract() != 0.0).then_some(spp),
            adaptive: adaptive_by_default(whole),
        }
    }
}

/// The sampling penumbra uses for POV-Ray's anti-aliasing options, chosen so that its RMSE
/// against a converged reference is at most POV-Ray's with the same options (measured on
/// scenes/ in docs/cli.md). POV-Ray without anti-aliasing shoots one ray per pixel centre;
/// with it, up to depth^2 rays (method 1) or (2^depth + 1)^2 (method 2) where neighbours
/// differ by more than the threshold. penumbra takes that many samples everywhere, with
/// adaptive sampling, at least 16, and twice as many per halving of the threshold below 0.3.
pub fn sampling_for(aa: &Antialias) -> Sampling {
    if !aa.on {
        return Sampling::of(16.0);
    }
    let depth = aa.depth.clamp(1, 6);
    let rays = if aa.method >= 2 {
        let side = (1u32 << depth) + 1;
        side * side
    } else {
        depth * depth
    };
    let mut spp = (4 * rays).max(16);
    let mut t = aa.threshold.max(0.0);
    while t < 0.3 && spp < 4096 {
        spp *= 2;
        t *= 2.0;
        if t == 0.0 {
            break;
        }
    }
    Sampling {
        spp: spp.min(4096),
        average: None,
        adaptive: true,
    }
}

/// One frame to render.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub number: i64,
    pub clock: AnimationClock,
    pub output: PathBuf,
}

/// A render job read from POV-Ray's options.
#[derive(Clone, Debug, PartialEq)]
pub struct Job {
    pub scene: PathBuf,
    pub width: u32,
    pub height: u32,
    pub sampling: Sampling,
    pub quality: u32,
    pub threads: Option<usize>,
    pub seed: u64,
    pub sixteen_bits: bool,
    pub write: bool,
    pub window: Option<PixelWindow>,
    pub crop: bool,
    pub frames: Vec<Frame>,
    pub declares: Vec<(String, f64)>,
    pub library_paths: Vec<PathBuf>,
    pub quiet: bool,
    /// The scene's `#debug` text on stderr (POV-Ray's `+GD`, the default).
    pub debug_console: bool,
    pub allow_write: Option<PathBuf>,
    /// `+C`: continue from the checkpoint.
    pub resume: bool,
    pub notes: Vec<String>,
    /// penumbra's `--motion-blur N`: times per frame spread over its shutter (1: none).
    pub motion_blur: u32,
}

/// The job the settings describe; errors are the user's (no scene, an empty window).
pub fn job(settings: &PovSettings) -> Result<Job, String> {
    let scene = settings
        .input
        .clone()
        .ok_or("no scene: give a .pov file or +Iscene.pov")?;
    let window = pixel_window(settings)?;
    let frames = frames(settings, &scene)?;
    let mut sampling = match settings.spp {
        Some(spp) if !spp_in_range(spp) => {
            return Err(format!("--spp {spp} is outside 1..=1048576"));
        }
        Some(spp) => Sampling::of(spp),
        None => sampling_for(&settings.antialias),
    };
    // Each time of a motion-blurred frame is its own render, whose pilot would spread its
    // samples its own way: the times' shares of each pixel would differ.
    sampling.adaptive = settings
        .adaptive
        .unwrap_or(sampling.adaptive && settings.motion_blur <= 1);
    if let (Some(average), false) = (sampling.average, sampling.adaptive) {
        return Err(format!(
            "--spp {average} is an average, which needs adaptive sampling (uniform renders and motion blur take whole samples per pixel)"
        ));
    }
    Ok(Job {
        scene,
        width: settings.width,
        height: settings.height,
        sampling,
        quality: settings.quality,
        threads: settings.threads,
        seed: settings.seed,
        sixteen_bits: settings.bits_per_colour > 8,
        write: settings.output_to_file,
        window,
        crop: settings.crop,
        frames,
        declares: settings.declares.clone(),
        library_paths: settings.library_paths.clone(),
        quiet: settings.quiet,
        debug_console: settings.debug_console,
        allow_write: settings.allow_write.clone(),
        resume: settings.continue_trace,
        notes: settings.notes.clone(),
        motion_blur: settings.motion_blur,
    })
}

/// `+SR +ER +SC +EC` as pixel ranges (POV-Ray counts pixels from 1, ends inclusive; a
/// fraction f starts at pixel floor(f n) and ends at ceil(f n)); `None` for the whole image.
fn pixel_window(s: &PovSettings) -> Result<Option<PixelWindow>, String> {
    let w = s.window;
    if w == Default::default() {
        return Ok(None);
    }
    let start = |b: Option<Bound>, n: u32| match b {
        None => 0,
        Some(Bound::Pixel(p)) => (p - 1).clamp(0, i64::from(n)) as usize,
        Some(Bound::Fraction(f)) => (f * f64::from(n)).floor() as usize,
    };
    let end = |b: Option<Bound>, n: u32| match b {
        None => n as usize,
        Some(Bound::Pixel(p)) => p.clamp(0, i64::from(n)) as usize,
        Some(Bound::Fraction(f)) => ((f * f64::from(n)).ceil() as usize).min(n as usize),
    };
    let x = start(w.start_column, s.width)..end(w.end_column, s.width);
    let y = start(w.start_row, s.height)..end(w.end_row, s.height);
    if x.is_empty() || y.is_empty() {
        return Err(format!(
            "the window (columns {}..{}, rows {}..{}) holds no pixels",
            x.start, x.end, y.start, y.end
        ));
    }
    Ok(Some(PixelWindow { x, y }))
}

/// The frames to render with their clocks and file names, as POV-Ray computes them: an
/// animation when the final frame is after the initial one; clock_delta is the clock range
/// over the frame count less one (or over the count, cyclic); `+SF +EF` pick a subset.
fn frames(s: &PovSettings, scene: &Path) -> Result<Vec<Frame>, String> {
    let a = s.animation;
    let extension = if s.file_type == 'E' { "exr" } else { "png" };
    if a.final_frame <= a.initial_frame {
        let clock = AnimationClock {
            clock: a.clock,
            ..AnimationClock::default()
        };
        let output = output_name(s, scene, extension, None);
        return Ok(vec![Frame {
            number: 0,
            clock,
            output,
        }]);
    }
    let span = a.final_frame - a.initial_frame;
    let steps = if a.cyclic { span + 1 } else { span };
    let delta = (a.final_clock - a.initial_clock) / steps as f64;
    let frame_of = |b: Option<Bound>, default: i64| match b {
        None => default,
        Some(Bound::Pixel(n)) => n,
        Some(Bound::Fraction(f)) => a.initial_frame + (f * span as f64).round() as i64,
    };
    let first = frame_of(a.subset_start, a.initial_frame).max(a.initial_frame);
    let last = frame_of(a.subset_end, a.final_frame).min(a.final_frame);
    if first > last {
        return Err(format!("the frame subset {first}..{last} is empty"));
    }
    let digits = a.final_frame.to_string().len();
    Ok((first..=last)
        .step_by(a.frame_step.max(1) as usize)
        .map(|number| Frame {
            number,
            clock: AnimationClock {
                clock: a.initial_clock + (number - a.initial_frame) as f64 * delta,
                clock_delta: delta,
                clock_on: true,
                frame_number: number,
                initial_frame: a.initial_frame,
                final_frame: a.final_frame,
                initial_clock: a.initial_clock,
                final_clock: a.final_clock,
            },
            output: output_name(s, scene, extension, Some((number, digits))),
        })
        .collect())
}

/// POV-Ray's output name: `+O` (a folder when it ends in `/` or is one), else the scene's
/// name in the current folder, the type's extension added when there is none; a frame's
/// number, zero-padded to the final frame's digits, goes before the extension.
fn output_name(
    s: &PovSettings,
    scene: &Path,
    extension: &str,
    frame: Option<(i64, usize)>,
) -> PathBuf {
    let stem = scene.file_stem().unwrap_or("penumbra".as_ref());
    let mut path = match &s.output {
        Some(o) if o.to_string_lossy().ends_with(['/', '\\']) || o.is_dir() => {
            o.join(stem).with_extension(extension)
        }
        Some(o) if o.extension().is_none() => o.with_extension(extension),
        Some(o) => o.clone(),
        None => PathBuf::from(stem).with_extension(extension),
    };
    if let Some((number, digits)) = frame {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().into_owned())
            .unwrap_or_default();
        let stem = path
            .file_stem()
            .map(|e| e.to_string_lossy().into_owned())
            .unwrap_or_default();
        path.set_file_name(format!("{stem}{number:0digits$}.{ext}"));
    }
    path
}
