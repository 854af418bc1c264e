//! The command line: clap types turned into library calls. No rendering logic lives here.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use penumbra::lang::{LoadOptions, load_scene_with};
use penumbra::output::{BitDepth, write_image};
use penumbra::render::{AreaLightMode, Progress, RenderOptions, Splitting};
use penumbra::study::reference::{ReferenceRequest, render_reference, write_reference};
use penumbra::study::{compare as study_compare, converge as study_converge};

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
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene to PNG (sRGB) or OpenEXR (linear), chosen by the output's extension.
    Render {
        scene: PathBuf,
        /// Output file (.png or .exr); default: the scene's name with .png, here.
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[arg(long, default_value_t = 320)]
        width: u32,
        #[arg(long, default_value_t = 240)]
        height: u32,
        /// Samples per pixel.
        #[arg(long, default_value_t = 16)]
        spp: u32,
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
        /// Shadow rays per area light at each shading point.
        #[arg(long, default_value_t = 1)]
        light_samples: u32,
        /// Spend the samples where a pilot pass finds noise (same average per pixel).
        #[arg(long)]
        adaptive: bool,
        /// Leave out features penumbra does not support (with a warning) instead of stopping.
        #[arg(long)]
        skip_unsupported: bool,
        #[command(flatten)]
        scene_args: SceneArgs,
    },
    /// Parse and evaluate scenes without rendering, and summarise them.
    Check {
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Leave out features penumbra does not support (with a warning) instead of stopping.
        #[arg(long)]
        skip_unsupported: bool,
        #[command(flatten)]
        scene_args: SceneArgs,
    },
    /// Render a converged reference with the installed POV-Ray: k times the size without
    /// anti-aliasing, k x k blocks averaged, written as linear OpenEXR (with the k/2 render
    /// beside it, whose difference bounds the reference's own error).
    Reference {
        scene: PathBuf,
        #[arg(short, long)]
        output: PathBuf,
        #[arg(long, default_value_t = 160)]
        width: u32,
        #[arg(long, default_value_t = 120)]
        height: u32,
        #[arg(long, default_value_t = 16)]
        supersample: u32,
        #[command(flatten)]
        scene_args: SceneArgs,
    },
    /// Compare an image with a reference (EXR linear, PNG decoded from sRGB): RMSE, relMSE,
    /// mean and max absolute error; with --replicates, noise sqrt(V) and bias sqrt(B) apart.
    Compare {
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
    },
    /// Geometry benchmark: camera and shadow rays per second on 1e3, 1e5, 1e6 spheres, BVH
    /// build time and memory per object, and the wall time against POV-Ray on a `#while`
    /// scene. Prints figures; not a timed test.
    Bench {
        /// Sphere counts for the ray-rate table.
        #[arg(long, value_delimiter = ',', default_values_t = [1_000usize, 100_000, 1_000_000])]
        counts: Vec<usize>,
        /// Rays of each kind per count.
        #[arg(long, default_value_t = 200_000)]
        rays: usize,
        /// Sphere counts for the side-by-side run against POV-Ray (rounded to cubes); `0`
        /// skips it.
        #[arg(long, value_delimiter = ',', default_values_t = [1_000usize, 100_000])]
        povray_counts: Vec<usize>,
        #[arg(long, default_value_t = 320)]
        width: u32,
        #[arg(long, default_value_t = 240)]
        height: u32,
    },
    /// Error against time: K seeds at each sample count against a reference, optionally
    /// POV-Ray at its quality settings; writes a CSV, charts (SVG, PNG) and a summary.
    Converge {
        scene: PathBuf,
        /// A reference written by `penumbra reference` (fixes the image size).
        #[arg(long)]
        reference: PathBuf,
        /// Samples per pixel, comma-separated.
        #[arg(long, value_delimiter = ',', default_value = "1,4,16,64,256")]
        spp: Vec<u32>,
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
        /// No progress lines.
        #[arg(short, long)]
        quiet: bool,
        #[command(flatten)]
        scene_args: SceneArgs,
    },
}

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

fn parse_declare(s: &str) -> Result<(String, f64), String> {
    let (name, value) = s
        .split_once('=')
        .ok_or_else(|| format!("expected NAME=VALUE, got `{s}`"))?;
    let value: f64 = value
        .trim()
        .parse()
        .map_err(|_| format!("`{value}` is not a number"))?;
    let name = name.trim();
    let valid = name
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid {
        return Err(format!("`{name}` is not an identifier"));
    }
    Ok((name.to_string(), value))
}

struct Bar(ProgressBar);

impl Progress for Bar {
    fn advance(&self, done: u64, total: u64) {
        self.0.set_length(total);
        self.0.set_position(done);
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(message) => {
            eprintln!("{message}");
            ExitCode::FAILURE
        }
    }
}

fn load_options(args: &SceneArgs, width: u32, height: u32) -> LoadOptions {
    LoadOptions {
        declares: args.declares.clone(),
        include_paths: args.include_paths.clone(),
        image_width: width,
        image_height: height,
    }
}

fn run(cli: Cli) -> Result<ExitCode, String> {
    match cli.command {
        Command::Render {
            scene,
            output,
            width,
            height,
            spp,
            seed,
            threads,
            bit_depth,
            quiet,
            area_lights,
            splitting,
            light_samples,
            adaptive,
            skip_unsupported,
            scene_args,
        } => {
            let output = output.unwrap_or_else(|| default_output(&scene));
            let loaded = load_scene_with(
                &scene,
                &load_options(&scene_args, width, height),
                skip_unsupported,
            )
            .map_err(|d| d.to_string())?;
            for w in &loaded.warnings {
                eprintln!("{w}");
            }
            let options = RenderOptions {
                width: width as usize,
                height: height as usize,
                samples_per_pixel: spp,
                seed,
                threads,
                area_lights: match area_lights {
                    AreaMode::Pov => AreaLightMode::Pov,
                    AreaMode::Continuous => AreaLightMode::Continuous,
                },
                splitting: match splitting {
                    Split::Both => Splitting::Both,
                    Split::One => Splitting::One,
                },
                light_samples,
                adaptive,
                ..RenderOptions::default()
            };
            let show = !quiet && std::io::stderr().is_terminal();
            let bar = ProgressBar::with_draw_target(
                Some(1),
                if show {
                    ProgressDrawTarget::stderr()
                } else {
                    ProgressDrawTarget::hidden()
                },
            );
            if let Ok(style) =
                ProgressStyle::with_template("{bar:40} {percent:>3}%  eta {eta}  {msg}")
            {
                bar.set_style(style);
            }
            let (image, stats) = penumbra::render_scene(&loaded.scene, &options, &Bar(bar.clone()))
                .map_err(|e| e.to_string())?;
            bar.finish_and_clear();
            let depth = match bit_depth {
                Depth::Eight => BitDepth::Eight,
                Depth::Sixteen => BitDepth::Sixteen,
            };
            write_image(&output, &image, depth).map_err(|e| e.to_string())?;
            if !quiet {
                eprintln!(
                    "{}: {:.2} s, {} samples, {:.2} M rays/s ({} rays)",
                    output.display(),
                    stats.wall.as_secs_f64(),
                    stats.samples,
                    stats.rays_per_second() / 1e6,
                    stats.rays.total()
                );
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Check {
            scenes,
            skip_unsupported,
            scene_args,
        } => {
            let mut failed = false;
            for path in &scenes {
                let options = load_options(&scene_args, 320, 240);
                match load_scene_with(path, &options, skip_unsupported) {
                    Ok(loaded) => {
                        eprint!("{}", loaded.debug);
                        for w in &loaded.warnings {
                            eprintln!("{w}");
                        }
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
            Ok(if failed {
                ExitCode::FAILURE
            } else {
                ExitCode::SUCCESS
            })
        }
        Command::Reference {
            scene,
            output,
            width,
            height,
            supersample,
            scene_args,
        } => {
            let request = ReferenceRequest {
                scene,
                width,
                height,
                supersample,
                declares: scene_args.declares,
                include_paths: scene_args.include_paths,
            };
            let reference = render_reference(&request).map_err(|e| e.to_string())?;
            write_reference(&output, &reference).map_err(|e| e.to_string())?;
            eprintln!(
                "{}: POV-Ray took {:.2} s",
                output.display(),
                reference.povray_seconds
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Compare {
            image,
            reference,
            replicates,
            diff,
            diff_scale,
        } => {
            let target =
                study_compare::read_target(&reference).map_err(|e| format!("reference: {e}"))?;
            let mut images = Vec::new();
            for path in std::iter::once(&image).chain(&replicates) {
                let target = study_compare::read_target(path).map_err(|e| format!("image: {e}"))?;
                images.push(target.image);
            }
            let comparison =
                study_compare::compare_to(&images, &target).map_err(|e| e.to_string())?;
            print!("{comparison}");
            if let Some(path) = diff {
                let scale = study_compare::write_diff(&path, &images, &target.image, diff_scale)
                    .map_err(|e| e.to_string())?;
                println!("{}: signed difference, scale +-{scale:.5}", path.display());
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            counts,
            rays,
            povray_counts,
            width,
            height,
        } => {
            let options = penumbra::study::bench::BenchOptions {
                counts,
                rays,
                povray_counts: povray_counts.into_iter().filter(|&n| n > 0).collect(),
                width,
                height,
                penumbra: std::env::current_exe().map_err(|e| e.to_string())?,
            };
            penumbra::study::bench::run(&options, |line| println!("{line}"));
            Ok(ExitCode::SUCCESS)
        }
        Command::Converge {
            scene,
            reference,
            spp,
            seeds,
            povray,
            output_dir,
            threads,
            independent,
            targets,
            quiet,
            scene_args,
        } => {
            let request = study_converge::ConvergeRequest {
                scene,
                declares: scene_args.declares,
                include_paths: scene_args.include_paths,
                reference,
                spp,
                seeds,
                povray,
                output_dir: output_dir.clone(),
                threads,
                stratified: !independent,
                targets,
            };
            let log = StderrLog { quiet };
            let report = study_converge::converge(&request, &log).map_err(|e| e.to_string())?;
            print!("{}", study_converge::summary_markdown(&report));
            println!(
                "wrote {}/converge.csv, error_vs_time.svg/.png, error_vs_spp.svg/.png, summary.md",
                output_dir.display()
            );
            Ok(ExitCode::SUCCESS)
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

fn default_output(scene: &Path) -> PathBuf {
    let stem = scene.file_stem().unwrap_or_else(|| "penumbra".as_ref());
    PathBuf::from(stem).with_extension("png")
}
