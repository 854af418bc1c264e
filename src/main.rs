//! The command line: clap types turned into library calls. No rendering logic lives here.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{CommandFactory, Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use penumbra::lang::{LoadOptions, load_scene_with, parse_memory_size};
use penumbra::output::BitDepth;
use penumbra::povray_args::{self, Job, PovSettings};
use penumbra::render::target::TargetError;
use penumbra::render::{AreaLightMode, LightSamples, RenderOptions, Splitting};
use penumbra::render_job::{FrameReport, JobError, JobProgress, JobSettings, run_job};
use penumbra::study::reference::{
    MediaQuadrature, ReferenceRequest, render_reference, write_reference,
};
use penumbra::study::{compare as study_compare, converge as study_converge, corpus};

#[derive(Parser)]
#[command(
    name = "penumbra",
    version,
    about = "A stochastic ray tracer for POV-Ray scenes"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Args)]
struct SceneArgs {
    /// Define a float before the scene is read, like POV-Ray's Declare=NAME=VALUE.
    #[arg(long = "declare", value_name = "NAME=VALUE", value_parser = parse_declare)]
    declares: Vec<(String, f64)>,
    /// Folders to search for #include files (after the scene's own folder).
    #[arg(short = 'L', long = "include-path", value_name = "DIR")]
    include_paths: Vec<PathBuf>,
    /// The one folder `#fopen ... write` may write in; without it, scenes cannot write.
    #[arg(long = "allow-write", value_name = "DIR")]
    allow_write: Option<PathBuf>,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene to PNG (sRGB) or OpenEXR (linear), chosen by the output's extension.
    /// POV-Ray's switches and INI files are read too (`penumbra render scene.pov +W640
    /// +A0.3`, or without `render`): see docs/cli.md.
    Render(RenderArgs),
    /// Merge shard files (renders of sample ranges, from many machines) into the image the
    /// whole render gives, byte for byte; refuses shards that do not belong together.
    Merge(MergeArgs),
    /// Parse and evaluate scenes without rendering, and summarise them.
    Check(CheckArgs),
    /// Render a converged reference with the installed POV-Ray: k times the size without
    /// anti-aliasing, k x k blocks averaged, written as linear OpenEXR (with the k/2 render
    /// beside it, whose difference bounds the reference's own error).
    Reference(ReferenceArgs),
    /// Compare an image with a reference (EXR linear, PNG decoded from sRGB): RMSE, relMSE,
    /// mean and max absolute error; with --replicates, noise sqrt(V) and bias sqrt(B) apart.
    Compare(CompareArgs),
    /// Geometry benchmark: camera and shadow rays per second on 1e3, 1e5, 1e6 spheres, BVH
    /// build time and memory per object, and the wall time against POV-Ray on a `#while`
    /// scene. Prints figures; not a timed test.
    Bench(BenchArgs),
    /// Error against time: K seeds at each sample count against a reference, optionally
    /// POV-Ray at its quality settings; writes a CSV, charts (SVG, PNG) and a summary.
    Converge(ConvergeArgs),
    /// Every example scene: parse, render with K seeds, render (or take from the cache)
    /// POV-Ray's reference, judge pixel by pixel or in distribution, write a markdown table.
    Corpus(CorpusArgs),
}

#[derive(clap::Args)]
struct RenderArgs {
    scene: PathBuf,
    /// Output file (.png or .exr); default: the scene's name with .png, here.
    #[arg(short, long)]
    output: Option<PathBuf>,
    #[arg(long, default_value_t = 320)]
    width: u32,
    #[arg(long, default_value_t = 240)]
    height: u32,
    /// Samples per pixel; a fractional N (e.g. 1.5) is an adaptive render's average.
    #[arg(long, default_value_t = 16.0)]
    spp: f64,
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Worker threads (default: one per core). The image does not depend on it.
    #[arg(long)]
    threads: Option<usize>,
    /// Bits per channel for PNG output.
    #[arg(long, value_enum, default_value = "8")]
    bit_depth: Depth,
    /// No progress bar and no summary line.
    #[arg(short, long)]
    quiet: bool,
    /// `pov`: POV-Ray's grid of point lights (converges to POV-Ray's image);
    /// `continuous`: the ideal emitter the grid approximates.
    #[arg(long, value_enum, default_value = "pov")]
    area_lights: AreaMode,
    /// Where a ray both reflects and refracts: trace `both` branches, or `one` chosen
    /// at random in proportion to its weight.
    #[arg(long, value_enum, default_value = "both")]
    splitting: Split,
    /// Shadow rays per area light at each shading point, or `cover`: enough that each
    /// pixel's samples together test every point of POV-Ray's light grid.
    #[arg(long, default_value = "cover")]
    light_samples: LightSamples,
    /// Spend the samples where a pilot pass finds noise (same average per pixel); the
    /// default from 2 samples per pixel on, without --motion-blur.
    #[arg(long, conflicts_with = "uniform")]
    adaptive: bool,
    /// The same samples for every pixel (the default at 1 sample per pixel or with
    /// --motion-blur).
    #[arg(long)]
    uniform: bool,
    /// Leave out features penumbra does not support (with a warning) instead of stopping.
    #[arg(long)]
    skip_unsupported: bool,
    /// Render frames A to B of an animation (`clock` from 0 at A to 1 at B, as POV-Ray's
    /// +KFIA +KFFB), named scene01.png ... like POV-Ray's.
    #[arg(long, value_name = "A..B")]
    frames: Option<String>,
    /// With --frames: render only frame N of the animation (its clock as in the whole
    /// animation, as POV-Ray's +SF N +EF N), for a farm's frames x shards grid.
    #[arg(long, value_name = "N", requires = "frames")]
    frame: Option<i64>,
    /// With --frames: each frame averages N times spread over its shutter (the frame's clock
    /// to the next frame's), the scene parsed at each.
    #[arg(long, value_name = "N", default_value_t = 1)]
    motion_blur: u32,
    /// Memory the scene's objects and values may take (e.g. 2G, 512M); default: the smaller
    /// of half the physical memory and the address-space limit.
    #[arg(long, value_name = "SIZE", value_parser = parse_memory_size)]
    max_memory: Option<u64>,
    /// Render only samples A..B of each pixel's --spp and write their sums to a shard file
    /// (.pshard), for `penumbra merge` (docs/farm.md).
    #[arg(long, value_name = "A..B", value_parser = parse_range)]
    sample_range: Option<std::ops::Range<u32>>,
    /// Continue an interrupted render from the checkpoint beside its output (the same
    /// command line otherwise); frames already written are skipped.
    #[arg(long)]
    resume: bool,
    /// Render in passes until the estimated RMSE (linear units, or `N%` of the image's
    /// mean) is below this with 95% confidence, the samples going where the noise is.
    #[arg(long, value_name = "E", value_parser = parse_target)]
    target_error: Option<(f64, bool)>,
    /// With --target-error: stop at this many samples per pixel on average.
    #[arg(long, value_name = "N", default_value_t = 4096)]
    max_spp: u32,
    /// Rewrite this PNG with the image so far while the render runs (atomically).
    #[arg(long, value_name = "FILE.png")]
    preview: Option<PathBuf>,
    /// Seconds between preview rewrites.
    #[arg(long, value_name = "SECONDS", default_value_t = 5.0)]
    preview_every: f64,
    #[command(flatten)]
    scene_args: SceneArgs,
}

#[derive(clap::Args)]
struct MergeArgs {
    /// Shard files of one render (`penumbra render --sample-range`), in any order.
    #[arg(required = true)]
    shards: Vec<PathBuf>,
    /// The merged image (.png or .exr).
    #[arg(short, long)]
    output: PathBuf,
    /// Also write each pixel's noise estimate (the variance of its mean, per channel) as
    /// a linear EXR.
    #[arg(long, value_name = "FILE.exr")]
    variance: Option<PathBuf>,
    /// Bits per channel for PNG output.
    #[arg(long, value_enum, default_value = "8")]
    bit_depth: Depth,
}

#[derive(clap::Args)]
struct CheckArgs {
    #[arg(required = true)]
    scenes: Vec<PathBuf>,
    /// Leave out features penumbra does not support (with a warning) instead of stopping.
    #[arg(long)]
    skip_unsupported: bool,
    /// Memory the scene's objects and values may take (e.g. 2G, 512M); default: the smaller
    /// of half the physical memory and the address-space limit.
    #[arg(long, value_name = "SIZE", value_parser = parse_memory_size)]
    max_memory: Option<u64>,
    #[command(flatten)]
    scene_args: SceneArgs,
}

#[derive(clap::Args)]
struct ReferenceArgs {
    scene: PathBuf,
    #[arg(short, long)]
    output: PathBuf,
    #[arg(long, default_value_t = 160)]
    width: u32,
    #[arg(long, default_value_t = 120)]
    height: u32,
    #[arg(long, default_value_t = 16)]
    supersample: u32,
    /// The `clock` value (POV-Ray's +K): one frame of an animation.
    #[arg(long)]
    clock: Option<f64>,
    /// An option for POV-Ray, given before penumbra's own (e.g. an INI file, `+SF1`).
    #[arg(long = "povray-arg", value_name = "ARG", allow_hyphen_values = true)]
    povray_args: Vec<String>,
    /// Render every media block at `method 2 intervals 10 samples 10`: the integral that
    /// penumbra estimates, where POV-Ray's default quadrature overshoots it.
    #[arg(long)]
    converged_media: bool,
    #[command(flatten)]
    scene_args: SceneArgs,
}

#[derive(clap::Args)]
struct CorpusArgs {
    /// POV-Ray's example scenes.
    #[arg(long, default_value = "/usr/share/povray-3.7/scenes")]
    scenes: PathBuf,
    /// Library includes (for the cache key and the noise scan).
    #[arg(long, default_value = "/usr/share/povray-3.7/include")]
    include_dir: Vec<PathBuf>,
    /// Measure only scenes whose path (relative to --scenes) matches this glob (or one of
    /// several, comma-separated).
    #[arg(long)]
    only: Option<String>,
    #[arg(long, default_value_t = 4)]
    seeds: u32,
    #[arg(long, default_value_t = 64)]
    spp: u32,
    #[arg(long, default_value_t = 160)]
    width: u32,
    #[arg(long, default_value_t = 120)]
    height: u32,
    #[arg(long, default_value_t = 16)]
    supersample: u32,
    /// The markdown report; failures' PNGs go beside it, in a folder of its name.
    #[arg(long, default_value = "docs/corpus.md")]
    out: PathBuf,
    /// Reference cache (default: $XDG_CACHE_HOME or ~/.cache, then penumbra/corpus).
    #[arg(long)]
    cache: Option<PathBuf>,
    /// Seconds allowed for one parse, one penumbra replicate, one POV-Ray reference.
    #[arg(long, default_value_t = 30)]
    parse_timeout: u64,
    #[arg(long, default_value_t = 300)]
    render_timeout: u64,
    #[arg(long, default_value_t = 1200)]
    reference_timeout: u64,
    /// Failures whose reason is written down, `scene | reason` per line (default:
    /// tests/corpus/known-differences.txt when it exists).
    #[arg(long)]
    known: Option<PathBuf>,
    /// Scenes judged over an ensemble of noise phases, `scene | anchor` per line (default:
    /// tests/corpus/phase-ensemble.txt when it exists).
    #[arg(long)]
    phase_ensemble: Option<PathBuf>,
    /// Measure in alphabetical order instead of cheapest first (by a 1-sample probe).
    #[arg(long)]
    by_name: bool,
}

#[derive(clap::Args)]
struct CompareArgs {
    /// The image to judge (the first replicate).
    image: PathBuf,
    /// The reference; a `penumbra reference` EXR also lends its k/2 layer to the bias.
    reference: PathBuf,
    /// More independent renders of the same scene (different seeds).
    #[arg(long, num_args = 1.., value_name = "IMAGE")]
    replicates: Vec<PathBuf>,
    /// Write the signed difference (mean of the images minus the reference) as a PNG.
    #[arg(long, value_name = "OUT.png")]
    diff: Option<PathBuf>,
    /// Colour scale of --diff: +-this maps to full red/blue (default: the 99th
    /// percentile of |difference|).
    #[arg(long, value_name = "S")]
    diff_scale: Option<f64>,
}

#[derive(clap::Args)]
struct BenchArgs {
    /// Sphere counts for the ray-rate table.
    #[arg(long, value_delimiter = ',', default_values_t = [1_000usize, 100_000, 1_000_000])]
    counts: Vec<usize>,
    /// Rays of each kind per count.
    #[arg(long, default_value_t = 200_000)]
    rays: usize,
    /// Sphere counts (N x N grids) for the whole pipeline against POV-Ray, time and peak
    /// memory; `0` skips it.
    #[arg(long, value_delimiter = ',', default_values_t = [1_000usize, 100_000, 1_000_000])]
    povray_counts: Vec<usize>,
    #[arg(long, default_value_t = 640)]
    width: u32,
    #[arg(long, default_value_t = 480)]
    height: u32,
    /// Only the parse section: the `#while` evaluation and the model's bytes per sphere
    /// against POV-Ray's parse time.
    #[arg(long)]
    parse: bool,
    /// Sphere counts (N x N grids) for `--parse`.
    #[arg(long, value_delimiter = ',', default_values_t = [10_000usize, 100_000, 1_000_000])]
    parse_counts: Vec<usize>,
    /// Runs of each for `--parse`; medians are printed.
    #[arg(long, default_value_t = 3)]
    parse_repeats: usize,
    /// Only the function line and the shape lines (rays per second against one shape).
    #[arg(long)]
    shapes: bool,
    /// Only the ray-rate table over clouds of spheres (`--counts`, `--rays`).
    #[arg(long)]
    spheres: bool,
    /// Only the whole-pipeline section (`--povray-counts`, `--width`, `--height`): the N x N
    /// spheres scene rendered by penumbra and by POV-Ray, time and peak memory of each.
    #[arg(long)]
    pipeline: bool,
    /// Only the forest section: scenes/forest.pov (a declared tree placed Trees x Trees
    /// times) at each TREESxPARTS size, rendered by penumbra and by POV-Ray, time and peak
    /// memory of each.
    #[arg(long, value_delimiter = ',', value_name = "TREESxPARTS", value_parser = parse_forest)]
    forest: Vec<(usize, usize)>,
}

/// `100x1000`: a forest of 100 x 100 trees of 1000 objects each.
fn parse_forest(s: &str) -> Result<(usize, usize), String> {
    parse_pair(s, "x", "a count")
}

#[derive(clap::Args)]
struct ConvergeArgs {
    scene: PathBuf,
    /// A reference written by `penumbra reference` (fixes the image size).
    #[arg(long)]
    reference: PathBuf,
    /// Samples per pixel, comma-separated (fractional counts, adaptive only, are averages).
    #[arg(long, value_delimiter = ',', default_value = "1,4,16,64,256")]
    spp: Vec<f64>,
    /// Replicates (seeds) per sample count, at least 2.
    #[arg(long, default_value_t = 4)]
    seeds: u32,
    /// Also time POV-Ray at -A, +A0.3, +AM2 +R3 and +AM2 +R4.
    #[arg(long)]
    povray: bool,
    #[arg(long, default_value = "converge")]
    output_dir: PathBuf,
    /// Threads for penumbra and POV-Ray (default: one per core).
    #[arg(long)]
    threads: Option<usize>,
    /// Independent samples instead of stratified ones (the N^-1/2 baseline).
    #[arg(long)]
    independent: bool,
    /// Target errors for the time-to-reach table, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "0.01,0.005")]
    targets: Vec<f64>,
    /// Shadow rays per area light at each shading point, or `cover` (as for render).
    #[arg(long, default_value = "cover")]
    light_samples: LightSamples,
    /// Per-pixel adaptive sample counts (render's default from 2 spp on; off here unless
    /// given, so that both can be measured).
    #[arg(long)]
    adaptive: bool,
    /// No progress lines.
    #[arg(short, long)]
    quiet: bool,
    #[command(flatten)]
    scene_args: SceneArgs,
}

// The command line's spellings of library enums (the library, in src/render and src/output,
// does not depend on clap). Each maps to its library enum in one `From` impl, the three side
// by side below: a variant added here does not compile until it is mapped, and one added to
// the library is added in this one place.

#[derive(Clone, Copy, ValueEnum)]
enum AreaMode {
    Pov,
    Continuous,
}

#[derive(Clone, Copy, ValueEnum)]
enum Split {
    Both,
    One,
}

#[derive(Clone, Copy, ValueEnum)]
enum Depth {
    #[value(name = "8")]
    Eight,
    #[value(name = "16")]
    Sixteen,
}

impl From<AreaMode> for AreaLightMode {
    fn from(mode: AreaMode) -> Self {
        match mode {
            AreaMode::Pov => AreaLightMode::Pov,
            AreaMode::Continuous => AreaLightMode::Continuous,
        }
    }
}

impl From<Split> for Splitting {
    fn from(split: Split) -> Self {
        match split {
            Split::Both => Splitting::Both,
            Split::One => Splitting::One,
        }
    }
}

impl From<Depth> for BitDepth {
    fn from(depth: Depth) -> Self {
        match depth {
            Depth::Eight => BitDepth::Eight,
            Depth::Sixteen => BitDepth::Sixteen,
        }
    }
}

fn parse_declare(s: &str) -> Result<(String, f64), String> {
    povray_args::parse_declare(s)
}

fn main() -> ExitCode {
    if let Some(missing) = missing_cpu_feature() {
        eprintln!(
            "error: this penumbra was built for x86-64-v2 processors (.cargo/config.toml), and \
             this processor lacks {missing}; rebuild with RUSTFLAGS=\"-C target-cpu=x86-64\""
        );
        return ExitCode::FAILURE;
    }
    run_main()
}

/// The instruction set the build assumes (.cargo/config.toml) that this processor lacks,
/// checked before any code that may use it runs.
fn missing_cpu_feature() -> Option<&'static str> {
    #[cfg(target_arch = "x86_64")]
    {
        if !std::arch::is_x86_feature_detected!("sse4.2") {
            return Some("SSE4.2");
        }
        if !std::arch::is_x86_feature_detected!("popcnt") {
            return Some("POPCNT");
        }
    }
    None
}

#[inline(never)]
fn run_main() -> ExitCode {
    // A reader that stops early (`penumbra compare ... | head`) closes the pipe: end quietly,
    // as other command-line tools do, instead of panicking in `println!`.
    // SAFETY: sets a signal's disposition to the default before any thread starts.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let argv: Vec<String> = std::env::args_os()
        .skip(1)
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    let result = match povray_invocation(&argv) {
        Some(args) => povray(args),
        None => run(Cli::parse()),
    };
    match result {
        Ok(code) => code,
        Err(message) => {
            eprintln!("{message}");
            ExitCode::FAILURE
        }
    }
}

/// The arguments to read as POV-Ray's when the command line is a POV-Ray invocation: its
/// first argument is no subcommand and looks like POV-Ray's (`+W640`, `-D`, `scene.pov`,
/// `render.ini`, `Width=640`), or it is `render` followed by a `+` switch, an INI file or
/// a `Key=Value` setting.
fn povray_invocation(argv: &[String]) -> Option<&[String]> {
    let first = argv.first()?;
    let subcommands: Vec<String> = Cli::command()
        .get_subcommands()
        .map(|c| c.get_name().to_string())
        .chain(["help".to_string()])
        .collect();
    if first == "render" {
        let rest = &argv[1..];
        let povray_style = |a: &String| {
            a.starts_with('+')
                || (povray_args::looks_like_povray(a)
                    && !a.starts_with('-')
                    && !a.ends_with(".pov"))
        };
        return rest.iter().any(povray_style).then_some(rest);
    }
    let own =
        subcommands.contains(first) || first.starts_with("--") || first == "-h" || first == "-V";
    (!own && povray_args::looks_like_povray(first)).then_some(argv)
}

/// A POV-Ray command line: its switches and INI files read into a job, and the job run.
fn povray(args: &[String]) -> Result<ExitCode, String> {
    let settings = povray_args::parse_args(args, &penumbra::lang::FileSystem).map_err(text)?;
    let job = povray_args::job::job(&settings).map_err(text)?;
    if !job.quiet {
        print_warnings(&job.notes);
    }
    let settings = JobSettings {
        allow_write: job.allow_write.clone(),
        resume: job.resume,
        ..JobSettings::default()
    };
    catch_interrupts();
    render_job(&job, &settings, "+C")
}

fn run(cli: Cli) -> Result<ExitCode, String> {
    match cli.command {
        Command::Render(args) => render(args),
        Command::Merge(args) => merge(args),
        Command::Check(args) => Ok(check(args)),
        Command::Reference(args) => reference(args),
        Command::Compare(args) => compare(args),
        Command::Bench(args) => bench(args),
        Command::Converge(args) => converge(args),
        Command::Corpus(args) => corpus(args),
    }
}

fn render(args: RenderArgs) -> Result<ExitCode, String> {
    let job = args.job()?;
    catch_interrupts();
    if args.preview_every.is_nan() || args.preview_every < 0.0 {
        return Err("--preview-every must be a number of seconds, 0 or more".into());
    }
    let settings = JobSettings {
        base: args.render_options(),
        skip_unsupported: args.skip_unsupported,
        max_memory: args.max_memory,
        allow_write: args.scene_args.allow_write.clone(),
        shards: args.sample_range.is_some(),
        resume: args.resume,
        preview: args
            .preview
            .clone()
            .map(|p| (p, std::time::Duration::from_secs_f64(args.preview_every))),
    };
    render_job(&job, &settings, "--resume")
}

/// Merges shards into the image (and the variance, if asked).
fn merge(args: MergeArgs) -> Result<ExitCode, String> {
    let mut shards = Vec::new();
    for path in &args.shards {
        shards.push((
            path.clone(),
            penumbra::output::read_shard(path).map_err(text)?,
        ));
    }
    let film = penumbra::output::merge_shards(&shards)?;
    let depth = match args.bit_depth {
        Depth::Eight => penumbra::output::BitDepth::Eight,
        Depth::Sixteen => penumbra::output::BitDepth::Sixteen,
    };
    penumbra::output::write_image(&args.output, &penumbra::film_image(&film), depth)
        .map_err(text)?;
    if let Some(path) = &args.variance {
        let variance = penumbra::output::Image {
            width: film.width,
            height: film.height,
            pixels: film
                .pixels
                .iter()
                .map(|p| p.variance_of_mean().map(|v| v as f32))
                .collect(),
        };
        penumbra::output::write_exr(
            path,
            &variance,
            &[],
            &[("penumbra", "variance of each pixel's mean")],
        )
        .map_err(text)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// `A..B` (or `AxB`, as `between` says) of two numbers (`what` names one in the error).
fn parse_pair<T: std::str::FromStr>(s: &str, between: &str, what: &str) -> Result<(T, T), String> {
    let (a, b) = s
        .split_once(between)
        .ok_or_else(|| format!("expected A{between}B, got `{s}`"))?;
    let n = |x: &str| {
        x.trim()
            .parse::<T>()
            .map_err(|_| format!("`{x}` is not {what}"))
    };
    Ok((n(a)?, n(b)?))
}

/// `A..B`: a half-open range of sample indices.
fn parse_range(s: &str) -> Result<std::ops::Range<u32>, String> {
    let (a, b) = parse_pair::<u32>(s, "..", "a sample index")?;
    if a >= b {
        return Err(format!("the range {a}..{b} is empty"));
    }
    Ok(a..b)
}

/// `0.005` (linear units) or `2%` (relative to the image's mean).
fn parse_target(s: &str) -> Result<(f64, bool), String> {
    let (number, relative) = match s.strip_suffix('%') {
        Some(n) => (n, true),
        None => (s, false),
    };
    let v: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not an error (a number, or N%)"))?;
    if !(v > 0.0 && v.is_finite()) {
        return Err(format!("the target error must be above 0, got `{s}`"));
    }
    Ok(if relative {
        (v / 100.0, true)
    } else {
        (v, false)
    })
}

/// Runs a job with a progress bar over frames and samples, and a summary line per frame.
/// `resume` is the option that continues it, in the command line's own style.
fn render_job(job: &Job, settings: &JobSettings, resume: &str) -> Result<ExitCode, String> {
    let bar = progress_bar(!job.quiet && std::io::stderr().is_terminal());
    let progress = Bar {
        bar: bar.clone(),
        debug: job.debug_console,
    };
    let reports = run_job(job, settings, &progress);
    bar.finish_and_clear();
    let reports = match reports {
        Ok(r) => r,
        Err(e @ JobError::Interrupted { .. }) => {
            eprintln!("{e}");
            eprintln!("to continue: {} {resume}", command_line());
            return Ok(ExitCode::from(130));
        }
        Err(JobError::Failed(m)) => return Err(m),
    };
    for r in reports {
        if !job.quiet {
            eprintln!(
                "{}: {}x{}, {}, {:.2} s, {} samples, {:.2} M rays/s ({} rays: {} camera, {} shadow, {} secondary)",
                r.output.display(),
                r.width,
                r.height,
                sampling_summary(job, settings, &r),
                r.stats.wall.as_secs_f64(),
                r.stats.samples,
                r.stats.rays_per_second() / 1e6,
                r.stats.rays.total(),
                r.stats.rays.camera,
                r.stats.rays.shadow,
                r.stats.rays.secondary
            );
        }
        for note in &r.stats.notes {
            eprintln!("warning: {note}");
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// How the frame was sampled, for its summary line.
fn sampling_summary(job: &Job, settings: &JobSettings, r: &FrameReport) -> String {
    if let Some(t) = &settings.base.target_error {
        let pixels = (r.width * r.height).max(1) as f64;
        let goal = if t.relative {
            format!("{}%", t.value * 100.0)
        } else {
            t.value.to_string()
        };
        return format!(
            "target error {goal}: {:.1} spp on average",
            r.stats.samples as f64 / pixels
        );
    }
    let adaptive = if job.sampling.adaptive {
        " adaptive"
    } else {
        ""
    };
    let spp = job
        .sampling
        .average
        .map_or(job.sampling.spp.to_string(), |a| a.to_string());
    format!("{spp} spp{adaptive}")
}

impl RenderArgs {
    fn render_options(&self) -> RenderOptions {
        RenderOptions {
            area_lights: self.area_lights.into(),
            splitting: self.splitting.into(),
            light_samples: self.light_samples,
            sample_range: self.sample_range.clone(),
            passes: self.preview.is_some(),
            target_error: self.target_error.map(|(value, relative)| TargetError {
                value,
                relative,
                max_spp: self.max_spp,
            }),
            ..RenderOptions::default()
        }
    }

    /// penumbra's own options as the job POV-Ray's would make.
    fn job(&self) -> Result<Job, String> {
        let exr = self
            .output
            .as_ref()
            .and_then(|o| o.extension())
            .is_some_and(|e| e.eq_ignore_ascii_case("exr"));
        let shard = self.sample_range.is_some();
        let output = self.output.clone().unwrap_or_else(|| {
            default_output(&self.scene).with_extension(if shard { "pshard" } else { "png" })
        });
        let is_shard = output
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("pshard"));
        if shard != is_shard {
            return Err(if shard {
                "--sample-range writes a shard: give an output ending in .pshard, and merge the shards into an image with `penumbra merge`".into()
            } else {
                "a .pshard output needs --sample-range A..B".into()
            });
        }
        let mut settings = PovSettings {
            input: Some(self.scene.clone()),
            output: Some(output),
            file_type: if exr { 'E' } else { 'N' },
            bits_per_colour: match self.bit_depth {
                Depth::Eight => 8,
                Depth::Sixteen => 16,
            },
            width: self.width,
            height: self.height,
            library_paths: self.scene_args.include_paths.clone(),
            declares: self.scene_args.declares.clone(),
            threads: self.threads,
            spp: Some(self.spp),
            seed: self.seed,
            quiet: self.quiet,
            motion_blur: self.motion_blur.max(1),
            ..PovSettings::default()
        };
        if let Some(frames) = &self.frames {
            let (a, b) = parse_pair::<i64>(frames, "..", "a frame number")
                .map_err(|e| format!("--frames: {e}"))?;
            settings.animation.initial_frame = a;
            settings.animation.final_frame = b;
            if let Some(n) = self.frame {
                let (a, b) = (
                    settings.animation.initial_frame,
                    settings.animation.final_frame,
                );
                if !(a..=b).contains(&n) {
                    return Err(format!("--frame {n} is not one of the frames {a}..{b}"));
                }
                settings.animation.subset_start = Some(povray_args::Bound::Pixel(n));
                settings.animation.subset_end = Some(povray_args::Bound::Pixel(n));
            }
        }
        settings.adaptive = match (self.adaptive, self.uniform) {
            (true, _) => Some(true),
            (_, true) => Some(false),
            _ => None,
        };
        povray_args::job::job(&settings)
    }
}

/// Loads every scene (at the default render size), printing its summary or its diagnostic;
/// fails if any scene did.
fn check(args: CheckArgs) -> ExitCode {
    let mut failed = false;
    for path in &args.scenes {
        let options = load_options(&args.scene_args, 320, 240, args.max_memory);
        match load_scene_with(path, &options, args.skip_unsupported) {
            Ok(loaded) => {
                eprint!("{}", loaded.debug);
                print_warnings(&loaded.warnings);
                println!(
                    "{}: {}",
                    path.display(),
                    penumbra::lang::check_summary(&loaded)
                );
            }
            Err(d) => {
                eprintln!("{d}");
                failed = true;
            }
        }
    }
    if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

fn reference(args: ReferenceArgs) -> Result<ExitCode, String> {
    let request = ReferenceRequest {
        scene: args.scene,
        width: args.width,
        height: args.height,
        supersample: args.supersample,
        declares: args.scene_args.declares,
        include_paths: args.scene_args.include_paths,
        clock: args.clock,
        extra_args: args.povray_args,
        media: if args.converged_media {
            MediaQuadrature::Converged
        } else {
            MediaQuadrature::AsWritten
        },
    };
    let reference = render_reference(&request).map_err(text)?;
    write_reference(&args.output, &reference).map_err(text)?;
    eprintln!(
        "{}: POV-Ray took {:.2} s",
        args.output.display(),
        reference.povray_seconds
    );
    Ok(ExitCode::SUCCESS)
}

fn compare(args: CompareArgs) -> Result<ExitCode, String> {
    let target =
        study_compare::read_target(&args.reference).map_err(|e| format!("reference: {e}"))?;
    let mut images = Vec::new();
    for path in std::iter::once(&args.image).chain(&args.replicates) {
        let target = study_compare::read_target(path).map_err(|e| format!("image: {e}"))?;
        images.push(target.image);
    }
    let comparison = study_compare::compare_to(&images, &target).map_err(text)?;
    print!("{comparison}");
    if let Some(path) = args.diff {
        let scale = study_compare::write_diff(&path, &images, &target.image, args.diff_scale)
            .map_err(text)?;
        println!("{}: signed difference, scale +-{scale:.5}", path.display());
    }
    Ok(ExitCode::SUCCESS)
}

fn bench(args: BenchArgs) -> Result<ExitCode, String> {
    if args.parse {
        penumbra::study::parse_bench::run(&args.parse_counts, args.parse_repeats, |line| {
            println!("{line}");
        });
        return Ok(ExitCode::SUCCESS);
    }
    if args.spheres {
        penumbra::study::bench::sphere_table(&args.counts, args.rays, &mut |line| {
            println!("{line}");
        });
        return Ok(ExitCode::SUCCESS);
    }
    if args.shapes {
        penumbra::study::bench::shape_lines(args.rays, &mut |line| println!("{line}"));
        return Ok(ExitCode::SUCCESS);
    }
    if !args.forest.is_empty() {
        let exe = std::env::current_exe().map_err(text)?;
        let size = (args.width, args.height);
        penumbra::study::pipeline_bench::forest(&args.forest, &exe, size, |line| {
            println!("{line}");
        });
        return Ok(ExitCode::SUCCESS);
    }
    if args.pipeline {
        let exe = std::env::current_exe().map_err(text)?;
        let counts: Vec<usize> = args.povray_counts.into_iter().filter(|&n| n > 0).collect();
        let size = (args.width, args.height);
        penumbra::study::pipeline_bench::run(&counts, &exe, size, |line| println!("{line}"));
        return Ok(ExitCode::SUCCESS);
    }
    let options = penumbra::study::bench::BenchOptions {
        counts: args.counts,
        rays: args.rays,
        povray_counts: args.povray_counts.into_iter().filter(|&n| n > 0).collect(),
        width: args.width,
        height: args.height,
        penumbra: std::env::current_exe().map_err(text)?,
    };
    penumbra::study::bench::run(&options, |line| println!("{line}"));
    Ok(ExitCode::SUCCESS)
}

fn converge(args: ConvergeArgs) -> Result<ExitCode, String> {
    let output_dir = args.output_dir.clone();
    let log = StderrLog { quiet: args.quiet };
    let report = study_converge::converge(&args.request(), &log).map_err(text)?;
    print!("{}", study_converge::summary_markdown(&report));
    println!(
        "wrote {}/converge.csv, error_vs_time.svg/.png, error_vs_spp.svg/.png, summary.md",
        output_dir.display()
    );
    Ok(ExitCode::SUCCESS)
}

impl ConvergeArgs {
    fn request(self) -> study_converge::ConvergeRequest {
        study_converge::ConvergeRequest {
            scene: self.scene,
            declares: self.scene_args.declares,
            include_paths: self.scene_args.include_paths,
            reference: self.reference,
            spp: self.spp,
            seeds: self.seeds,
            povray: self.povray,
            output_dir: self.output_dir,
            threads: self.threads,
            stratified: !self.independent,
            targets: self.targets,
            light_samples: self.light_samples,
            adaptive: self.adaptive,
        }
    }
}

fn corpus(args: CorpusArgs) -> Result<ExitCode, String> {
    let cache = match args.cache {
        Some(dir) => dir,
        None => std::env::var_os("XDG_CACHE_HOME")
            .map(PathBuf::from)
            .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
            .ok_or("no --cache, and neither XDG_CACHE_HOME nor HOME is set")?
            .join("penumbra/corpus"),
    };
    let request = corpus::CorpusRequest {
        scenes_dir: args.scenes,
        include_dirs: args.include_dir,
        only: args.only,
        seeds: args.seeds,
        spp: args.spp,
        width: args.width,
        height: args.height,
        supersample: args.supersample,
        out: args.out,
        cache,
        penumbra: std::env::current_exe().map_err(text)?,
        timeouts: corpus::Timeouts {
            parse: args.parse_timeout,
            render: args.render_timeout,
            reference: args.reference_timeout,
        },
        cheap_first: !args.by_name,
        known: read_list(args.known.as_deref(), "tests/corpus/known-differences.txt")?,
        phase_ensemble: read_list(
            args.phase_ensemble.as_deref(),
            "tests/corpus/phase-ensemble.txt",
        )?,
    };
    let rows = corpus::run(&request, &StderrLog { quiet: false }).map_err(text)?;
    let passed = rows
        .iter()
        .filter(|r| matches!(&r.outcome, corpus::Outcome::Judged(j) if j.passes()))
        .count();
    println!(
        "{}: {passed} of {} scenes pass; references cached in {}",
        request.out.display(),
        rows.len(),
        request.cache.display()
    );
    Ok(ExitCode::SUCCESS)
}

// What the subcommands share.

/// Errors reach the user as their message.
fn text(error: impl std::fmt::Display) -> String {
    error.to_string()
}

/// A `scene | text` list of the corpus: the given file, or the default one if it exists.
fn read_list(path: Option<&Path>, default: &str) -> Result<Vec<corpus::known::Known>, String> {
    let default = Path::new(default);
    let path = match path {
        Some(p) => p,
        None if default.exists() => default,
        None => return Ok(Vec::new()),
    };
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    corpus::known::parse_known(&text).map_err(|e| format!("{}: {e}", path.display()))
}

fn load_options(args: &SceneArgs, width: u32, height: u32, max_memory: Option<u64>) -> LoadOptions {
    LoadOptions {
        max_memory,
        declares: args.declares.clone(),
        include_paths: args.include_paths.clone(),
        image_width: width,
        image_height: height,
        allow_write: args.allow_write.clone(),
        ..LoadOptions::default()
    }
}

fn print_warnings(warnings: &[impl std::fmt::Display]) {
    for w in warnings {
        eprintln!("{w}");
    }
}

/// A render's progress bar on stderr; hidden (but still counting) when `show` is false.
fn progress_bar(show: bool) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(
        Some(1),
        if show {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        },
    );
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {percent:>3}%  eta {eta}  {msg}") {
        bar.set_style(style);
    }
    bar
}

/// The render's progress bar, and whether the scene's `#debug` text is shown (`-GD`).
struct Bar {
    bar: ProgressBar,
    debug: bool,
}

impl JobProgress for Bar {
    fn frame(&self, index: usize, count: usize, output: &Path) {
        if count > 1 {
            self.bar
                .set_message(format!("frame {}/{count} {}", index + 1, output.display()));
        }
        self.bar.set_position(0);
    }

    fn samples(&self, done: u64, total: u64) {
        self.bar.set_length(total);
        self.bar.set_position(done);
    }

    fn cancelled(&self) -> bool {
        CANCELLED.load(std::sync::atomic::Ordering::Relaxed)
    }

    fn warnings(&self, warnings: &[penumbra::lang::Diagnostic]) {
        self.bar.suspend(|| print_warnings(warnings));
    }

    fn debug(&self, text: &str) {
        if self.debug {
            self.bar.suspend(|| eprint!("{text}"));
        }
    }
}

/// Progress lines on stderr, one per replicate, so a long study shows where it is.
struct StderrLog {
    quiet: bool,
}

impl study_converge::Log for StderrLog {
    fn line(&self, text: &str) {
        if !self.quiet {
            eprintln!("{text}");
        }
    }
}

/// Set by Ctrl-C or SIGTERM: renders stop at the next sample and save a checkpoint.
static CANCELLED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// The first signal asks the render to stop and save its samples; a second ends the
/// process at once.
fn catch_interrupts() {
    let _ = ctrlc::set_handler(|| {
        if CANCELLED.swap(true, std::sync::atomic::Ordering::Relaxed) {
            std::process::exit(130);
        }
    });
}

/// This process's command line, quoted where a shell needs it, without a --resume.
fn command_line() -> String {
    std::env::args()
        .filter(|a| a != "--resume" && a != "+C")
        .map(|a| {
            if a.is_empty() || a.contains(|c: char| c.is_whitespace() || "'\"$`\\*?".contains(c)) {
                format!("'{}'", a.replace('\'', "'\\''"))
            } else {
                a
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

fn default_output(scene: &Path) -> PathBuf {
    let stem = scene.file_stem().unwrap_or_else(|| "penumbra".as_ref());
    PathBuf::from(stem).with_extension("png")
}
