//! The command line: clap types turned into library calls. No rendering logic lives here.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use penumbra::lang::{LoadOptions, load_scene_with};
use penumbra::output::{BitDepth, write_image};
use penumbra::render::{Progress, RenderOptions};
use penumbra::study::reference::{ReferenceRequest, render_reference, write_reference};

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
    }
}

fn default_output(scene: &Path) -> PathBuf {
    let stem = scene.file_stem().unwrap_or_else(|| "penumbra".as_ref());
    PathBuf::from(stem).with_extension("png")
}
