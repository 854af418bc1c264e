//! The scene language: POV-Ray 3.7 scene files to the [`crate::scene`] model.
//!
//! Stages: [`parse`] turns text into tokens (nom), [`syntax`] defines them with their spans,
//! `eval` runs directives and macros while reading objects, textures and settings into a
//! [`Scene`](crate::scene::Scene), and [`diagnostics`] prints errors with file, line,
//! column and a caret. All file access goes through [`SourceFiles`], so tests can use files held
//! in memory.

pub mod diagnostics;
mod eval;
pub mod parse;
pub mod syntax;

#[cfg(test)]
mod tests;

use std::collections::HashMap;
use std::path::{Path, PathBuf};

pub use diagnostics::{Diagnostic, Severity, Span};
pub use eval::budget::{default_memory_budget, parse_memory_size};
pub use eval::builtins_markdown;

/// Settings from the command line that the scene can see.
#[derive(Clone, Debug)]
pub struct LoadOptions {
    /// `--declare NAME=VALUE`, defined before the scene is read.
    pub declares: Vec<(String, f64)>,
    pub include_paths: Vec<PathBuf>,
    /// For the `image_width` / `image_height` identifiers.
    pub image_width: u32,
    pub image_height: u32,
    /// For the animation identifiers (`clock`, `frame_number`, ...).
    pub clock: AnimationClock,
    /// Bytes the scene's objects and values may take (`--max-memory`); `None`: the default,
    /// [`default_memory_budget`].
    pub max_memory: Option<u64>,
    /// `--allow-write DIR`: the folder `#fopen ... write` may write in; `None`: writing is
    /// refused.
    pub allow_write: Option<PathBuf>,
}

/// What the animation identifiers read: `clock`, `clock_delta`, `clock_on`,
/// `frame_number`, `initial_frame`, `final_frame`, `initial_clock`, `final_clock`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnimationClock {
    pub clock: f64,
    pub clock_delta: f64,
    /// True while rendering an animation (more than one frame).
    pub clock_on: bool,
    pub frame_number: i64,
    pub initial_frame: i64,
    pub final_frame: i64,
    pub initial_clock: f64,
    pub final_clock: f64,
}

/// A still: what POV-Ray 3.7 gives without animation options (clock 0, frames 1 to 1, clock
/// from 0 to 1, frame_number 0).
impl Default for AnimationClock {
    fn default() -> Self {
        AnimationClock {
            clock: 0.0,
            clock_delta: 0.0,
            clock_on: false,
            frame_number: 0,
            initial_frame: 1,
            final_frame: 1,
            initial_clock: 0.0,
            final_clock: 1.0,
        }
    }
}

/// 800 x 600 is what the installed POV-Ray 3.7 renders without `+W`/`+H`.
impl Default for LoadOptions {
    fn default() -> Self {
        LoadOptions {
            declares: Vec::new(),
            include_paths: Vec::new(),
            image_width: 800,
            image_height: 600,
            clock: AnimationClock::default(),
            max_memory: None,
            allow_write: None,
        }
    }
}

/// A scene that was read, with the warnings met on the way.
#[derive(Clone, Debug)]
pub struct Loaded {
    pub scene: crate::scene::Scene,
    pub warnings: Vec<Diagnostic>,
    /// Text from `#debug`, which POV-Ray prints on its debug stream; `check` prints it.
    pub debug: String,
    /// A hash of what the scene was made from (its text, the files it read, the options it
    /// saw): equal for equal scenes, cheap to compute (`eval::inputs`).
    pub inputs_hash: u64,
}

/// Where include files come from. One place decides what can be read, and tests substitute
/// files held in memory.
pub trait SourceFiles {
    fn read(&self, path: &Path) -> std::io::Result<String>;
    fn exists(&self, path: &Path) -> bool;
}

/// The real file system.
pub struct FileSystem;

impl SourceFiles for FileSystem {
    fn read(&self, path: &Path) -> std::io::Result<String> {
        let bytes = std::fs::read(path)?;
        // Scene files are often Latin-1; keep going rather than refusing them.
        Ok(String::from_utf8_lossy(&bytes).into_owned())
    }

    fn exists(&self, path: &Path) -> bool {
        path.is_file()
    }
}

/// Files held in memory, looked up by path; for tests.
#[derive(Default, Clone, Debug)]
pub struct MemoryFiles {
    pub files: HashMap<PathBuf, String>,
}

impl SourceFiles for MemoryFiles {
    fn read(&self, path: &Path) -> std::io::Result<String> {
        self.files
            .get(path)
            .cloned()
            .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::NotFound, "no such file"))
    }

    fn exists(&self, path: &Path) -> bool {
        self.files.contains_key(path)
    }
}

/// Reads a scene file and everything it includes.
pub fn load_scene(path: &Path, options: &LoadOptions) -> Result<Loaded, Diagnostic> {
    load_scene_with(path, options, false)
}

/// Like [`load_scene`]; with `skip_unsupported`, features penumbra lacks become warnings
/// and are left out of the scene instead of stopping it (`--skip-unsupported`). A separate
/// entry point rather than a `LoadOptions` field, so code that builds `LoadOptions` by hand
/// keeps compiling.
pub fn load_scene_with(
    path: &Path,
    options: &LoadOptions,
    skip_unsupported: bool,
) -> Result<Loaded, Diagnostic> {
    let source = FileSystem.read(path).map_err(|e| {
        Diagnostic::error(
            Span::DETACHED,
            format!("cannot read \"{}\": {e}", path.display()),
        )
    })?;
    load_inner(
        &path.display().to_string(),
        &source,
        options,
        &FileSystem,
        skip_unsupported,
    )
}

/// Reads a scene held in memory; includes are still searched on disk.
pub fn load_scene_source(
    name: &str,
    source: &str,
    options: &LoadOptions,
) -> Result<Loaded, Diagnostic> {
    load_with_files(name, source, options, &FileSystem)
}

/// Stack for the evaluator's thread: deeply nested scenes recurse, and the nesting limit
/// (`eval::MAX_DEPTH`) is set so this is always enough, even in debug builds.
const EVAL_STACK_BYTES: usize = 256 << 20;

/// Reads a scene with includes resolved through `files`.
pub fn load_with_files(
    name: &str,
    source: &str,
    options: &LoadOptions,
    files: &(dyn SourceFiles + Sync),
) -> Result<Loaded, Diagnostic> {
    load_inner(name, source, options, files, false)
}

/// [`load_with_files`] with the choice of skipping unsupported features.
pub fn load_inner(
    name: &str,
    source: &str,
    options: &LoadOptions,
    files: &(dyn SourceFiles + Sync),
    skip_unsupported: bool,
) -> Result<Loaded, Diagnostic> {
    load_reading_globals(name, source, options, files, skip_unsupported, &[]).map(|(l, _)| l)
}

/// [`load_inner`] that also returns the values the global identifiers `globals` have once
/// the scene is read, printed as [`print_value`] does (`None` for an undefined one); for
/// tests that check what a scene computed.
pub fn load_reading_globals(
    name: &str,
    source: &str,
    options: &LoadOptions,
    files: &(dyn SourceFiles + Sync),
    skip_unsupported: bool,
    globals: &[String],
) -> Result<(Loaded, Vec<Option<String>>), Diagnostic> {
    let run = || evaluate(name, source, options, files, skip_unsupported, globals);
    std::thread::scope(|s| {
        let handle = std::thread::Builder::new()
            .name("penumbra-lang".into())
            .stack_size(EVAL_STACK_BYTES)
            .spawn_scoped(s, run);
        match handle {
            Ok(h) => h.join().unwrap_or_else(|_| {
                Err(Diagnostic::error(
                    Span::DETACHED,
                    "internal error: the scene reader crashed",
                ))
            }),
            // No thread (resource limits): read on this one.
            Err(_) => run(),
        }
    })
}

fn evaluate(
    name: &str,
    source: &str,
    options: &LoadOptions,
    files: &dyn SourceFiles,
    skip_unsupported: bool,
    globals: &[String],
) -> Result<(Loaded, Vec<Option<String>>), Diagnostic> {
    let mut ev = eval::Evaluator::new(
        files,
        options.include_paths.clone(),
        options.image_width,
        options.image_height,
    );
    ev.skip_unsupported = skip_unsupported;
    ev.clock = options.clock;
    ev.allow_write = options.allow_write.clone();
    ev.set_memory_budget(options.max_memory.unwrap_or_else(default_memory_budget));
    for (name, value) in &options.declares {
        ev.declare_global(name, eval::value::Value::Float(*value));
    }
    ev.run(name, source)?;
    let values = globals
        .iter()
        .map(|g| ev.global(g).map(print_value))
        .collect();
    let scene = std::mem::take(&mut ev.scene);
    let loaded = Loaded {
        scene,
        warnings: std::mem::take(&mut ev.warnings),
        debug: std::mem::take(&mut ev.debug_output),
        inputs_hash: ev.inputs.hash(source, options, skip_unsupported, files),
    };
    Ok((loaded, values))
}

/// A value as tests write it: floats as Rust prints them, vectors `<1, 2, 3>`, colours
/// `rgbft <r, g, b, f, t>`, strings in quotes; other kinds by their name (`a texture`).
fn print_value(value: &eval::value::Value) -> String {
    use eval::value::Value;
    let list = |c: &[f64]| {
        let parts: Vec<String> = c.iter().map(|x| x.to_string()).collect();
        format!("<{}>", parts.join(", "))
    };
    match value {
        Value::Float(x) => x.to_string(),
        Value::Vector(v) => list(&v.c[..usize::from(v.len)]),
        Value::Colour(c) => format!("rgbft {}", list(c)),
        Value::Str(s) => format!("{:?}", &**s),
        other => other.kind_name().to_string(),
    }
}

/// What `penumbra check` prints for a scene that was read: counts of objects, lights,
/// the shapes and features used, and warnings.
pub fn check_summary(loaded: &Loaded) -> String {
    use std::collections::BTreeMap;
    use std::fmt::Write;

    fn visit(o: &crate::scene::Object, features: &mut BTreeMap<&'static str, usize>) {
        let name = match &o.shape {
            crate::scene::Shape::Sphere { .. } => "sphere",
            crate::scene::Shape::Plane { .. } => "plane",
            crate::scene::Shape::Box { .. } => "box",
            crate::scene::Shape::Cylinder(_) => "cylinder",
            crate::scene::Shape::Cone(_) => "cone",
            crate::scene::Shape::Disc(_) => "disc",
            crate::scene::Shape::Torus { .. } => "torus",
            crate::scene::Shape::Quadric(_) => "quadric",
            crate::scene::Shape::Quartic { .. } => "quartic",
            crate::scene::Shape::Poly { .. } => "poly",
            crate::scene::Shape::Julia(_) => "julia_fractal",
            crate::scene::Shape::Superellipsoid { .. } => "superellipsoid",
            crate::scene::Shape::Blob(_) => "blob",
            crate::scene::Shape::Isosurface(_) => "isosurface",
            crate::scene::Shape::Triangle(_) => "triangle",
            crate::scene::Shape::SmoothTriangle(_) => "smooth_triangle",
            crate::scene::Shape::Mesh(_) => "mesh",
            crate::scene::Shape::HeightField(_) => "height_field",
            crate::scene::Shape::BicubicPatch(_) => "bicubic_patch",
            crate::scene::Shape::Polygon { .. } => "polygon",
            crate::scene::Shape::Prism(_) => "prism",
            crate::scene::Shape::Sor(_) => "sor",
            crate::scene::Shape::Lathe(_) => "lathe",
            crate::scene::Shape::Glyph(_) => "text glyph",
            crate::scene::Shape::Union(_) => "union",
            crate::scene::Shape::Merge(_) => "merge",
            crate::scene::Shape::Intersection(_) => "intersection",
            crate::scene::Shape::Difference(_) => "difference",
            crate::scene::Shape::Instance(_) => "shared object",
        };
        *features.entry(name).or_default() += 1;
        if !o.clipped_by().is_empty() {
            *features.entry("clipped_by").or_default() += 1;
        }
        if o.interior.is_some() {
            *features.entry("interior").or_default() += 1;
        }
        for child in o.shape.children().unwrap_or(&[]) {
            visit(child, features);
        }
        if let crate::scene::Shape::Instance(shared) = &o.shape {
            visit(shared, features);
        }
        for clip in o.clipped_by() {
            visit(clip, features);
        }
    }

    let scene = &loaded.scene;
    let mut features = BTreeMap::new();
    for o in &scene.objects {
        visit(o, &mut features);
    }
    for l in &scene.lights {
        let kind = match l.kind {
            crate::scene::LightKind::Point => "point light",
            crate::scene::LightKind::Spot { .. } => "spotlight",
            crate::scene::LightKind::Parallel { .. } => "parallel light",
            crate::scene::LightKind::Cylinder { .. } => "cylinder light",
        };
        *features.entry(kind).or_default() += 1;
        if l.area.is_some() {
            *features.entry("area_light").or_default() += 1;
        }
    }
    let mut out = format!(
        "{} objects, {} lights, version {}, {} warnings",
        scene.objects.len(),
        scene.lights.len(),
        scene.version,
        loaded.warnings.len()
    );
    if !features.is_empty() {
        out.push_str("; uses");
        for (i, (name, n)) in features.iter().enumerate() {
            let sep = if i == 0 { " " } else { ", " };
            let _ = write!(out, "{sep}{name} x{n}");
        }
    }
    out
}
