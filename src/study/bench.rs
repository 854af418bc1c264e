//! `penumbra bench`: how the geometry scales. Not a timed test: it prints figures and ratios.
//!
//! - Rays per second for camera rays (nearest hit) and shadow rays (any hit) on 1e3, 1e5 and
//!   1e6 random spheres filling a cube at constant density (radius 0.4 spacings), one thread, and the growth of
//!   time per ray from the smallest to the largest scene (a BVH should keep it near log n;
//!   the target is at most 3x from 1e3 to 1e6).
//! - BVH build time (parallel and sequential) and memory per object.
//! - The same kind of scene written with `#while` as a POV-Ray file, rendered by POV-Ray
//!   (`-A`, no anti-aliasing) and by penumbra (1 sample per pixel) side by side at the same
//!   size with a point light: the wall-time ratio penumbra / POV-Ray, parse included.

use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

use glam::DVec3;

use crate::geometry::{Ray, ShapeKind, Transform, World, WorldBuilder};

use super::tempdir::TempDir;

/// What to measure.
#[derive(Clone, Debug)]
pub struct BenchOptions {
    /// Sphere counts for the ray-rate table.
    pub counts: Vec<usize>,
    /// Rays of each kind traced per count.
    pub rays: usize,
    /// Sphere counts for the side-by-side run against POV-Ray (empty: skip it).
    pub povray_counts: Vec<usize>,
    pub width: u32,
    pub height: u32,
    /// The penumbra binary for the side-by-side run.
    pub penumbra: std::path::PathBuf,
}

/// A small deterministic generator (xorshift), so every run benchmarks the same scene.
struct Xorshift(u64);

impl Xorshift {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn vec3(&mut self) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next())
    }
}

/// n spheres in the cube [-1, 1]^3 with radii 0.4 times their mean spacing: a dense cloud
/// (about a quarter of the volume filled), so a ray's first hit lies a fixed number of
/// spacings in and a good BVH's cost per ray grows only like log n.
fn sphere_world(n: usize) -> (World, f64) {
    let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
    let radius = 0.4 * 2.0 / (n as f64).cbrt();
    let mut b = WorldBuilder::default();
    for _ in 0..n {
        let centre = rng.vec3() * 2.0 - DVec3::ONE;
        let item = b.primitive(
            ShapeKind::Sphere {
                center: centre,
                radius,
            },
            &Transform::IDENTITY,
            0,
            0,
        );
        b.add_top(item);
    }
    let start = Instant::now();
    let world = b.build();
    (world, start.elapsed().as_secs_f64())
}

/// One shape filling the view (about the unit cube the sphere worlds fill), for the
/// per-shape lines: a sphere to compare with, then the spline shapes.
fn shape_world(name: &str) -> World {
    use crate::geometry::{LatheData, PrismData, SorData};
    use crate::scene::{SplineKind, lathe_profile, prism_profile, sor_profile};
    let v = |p: &[(f64, f64)]| -> Vec<glam::DVec2> {
        p.iter().map(|&(x, y)| glam::DVec2::new(x, y)).collect()
    };
    let mut b = WorldBuilder::default();
    let star = v(&[
        (-0.2, -1.0),
        (0.2, -1.0),
        (0.2, 0.2),
        (1.0, -0.2),
        (1.0, 0.2),
        (0.2, 1.0),
        (-0.2, 1.0),
        (-1.0, 0.2),
        (-1.0, -0.2),
        (-0.2, 0.2),
        (-0.2, -1.0),
        (0.2, -1.0),
        (0.2, 0.2),
    ]);
    let vase = v(&[
        (0.2, -1.3),
        (0.5, -1.0),
        (0.9, -0.4),
        (0.3, 0.2),
        (0.6, 0.8),
        (1.0, 1.5),
    ]);
    let shape = match name {
        "prism" => {
            let segments = prism_profile(SplineKind::Cubic, &star).expect("a closed star");
            let data = PrismData::new(&segments.segments, -0.5, 0.5, false, false);
            b.tables.prisms.push(data);
            ShapeKind::Prism(0)
        }
        "sor" => {
            b.tables
                .sors
                .push(SorData::new(&sor_profile(&vase).expect("rising"), false));
            ShapeKind::Sor(0)
        }
        "lathe" => {
            let segments = lathe_profile(SplineKind::Cubic, &vase).expect("enough points");
            b.tables.lathes.push(LatheData::new(&segments));
            ShapeKind::Lathe(0)
        }
        other => algebraic_shape(other, &mut b.tables).unwrap_or(ShapeKind::Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
        }),
    };
    // Tilted towards the camera so that caps and sides both show.
    let tilt = Transform::rotate(DVec3::new(-60.0, 20.0, 0.0));
    let item = b.primitive(shape, &tilt, 0, 0);
    b.add_top(item);
    b.build()
}

/// The poly and julia_fractal lines' shapes: the sextic rounded cube x^6 + y^6 + z^6 +
/// 6 x^2 y^2 z^2 = 1 of scenes/shape_poly.pov, and the quaternion sqr julia of
/// scenes/shape_julia.pov (8 iterations, precision 20).
fn algebraic_shape(name: &str, tables: &mut crate::geometry::ShapeTables) -> Option<ShapeKind> {
    use crate::geometry::{JuliaData, PolyData, poly_term_count};
    use crate::scene::JuliaFractal;
    match name {
        "poly" => {
            let mut c = vec![0.0; poly_term_count(6)];
            // x^6, x^2 y^2 z^2, y^6, z^6 and the constant, in poly's order.
            for (i, v) in [(0, 1.0), (23, 6.0), (56, 1.0), (77, 1.0), (83, -1.0)] {
                c[i] = v;
            }
            tables.polys.push(PolyData::new(6, &c));
            Some(ShapeKind::Poly(0))
        }
        "julia" => {
            tables.julias.push(JuliaData::new(&JuliaFractal {
                c: [-0.083, 0.0, -0.83, -0.025],
                max_iteration: 8,
                ..JuliaFractal::default()
            }));
            Some(ShapeKind::Julia(0))
        }
        _ => None,
    }
}

struct RayFigures {
    camera_rate: f64,
    shadow_rate: f64,
    hit_fraction: f64,
}

/// Camera rays from a pinhole in front of the cube, then shadow rays from their hits to a
/// point light, all on the current thread.
fn trace(world: &World, rays: usize) -> RayFigures {
    let eye = DVec3::new(0.0, 0.0, -4.0);
    let light = DVec3::new(3.0, 5.0, -4.0);
    let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
    let dirs: Vec<DVec3> = (0..rays)
        .map(|_| {
            let s = rng.next() * 2.0 - 1.0;
            let t = rng.next() * 2.0 - 1.0;
            (DVec3::new(s * 1.2, t * 1.2, 3.0) - DVec3::ZERO).normalize()
        })
        .collect();
    let start = Instant::now();
    let mut points = Vec::with_capacity(rays);
    for &d in &dirs {
        let ray = Ray::new(eye, d);
        if let Some(hit) = world.intersect(&ray, f64::INFINITY, 0) {
            points.push(ray.at(hit.t * (1.0 - 1e-9)));
        }
    }
    let camera = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let mut blocked = 0usize;
    // Shadow rays: as many as camera rays (hits reused round-robin).
    for i in 0..rays {
        let Some(&p) = points.get(i % points.len().max(1)) else {
            break;
        };
        let to = light - p;
        let dist = to.length();
        if world.occluded(&Ray::new(p, to / dist), dist) {
            blocked += 1;
        }
    }
    let shadow = start.elapsed().as_secs_f64();
    std::hint::black_box(blocked);
    RayFigures {
        camera_rate: rays as f64 / camera,
        shadow_rate: if points.is_empty() {
            0.0
        } else {
            rays as f64 / shadow
        },
        hit_fraction: points.len() as f64 / rays as f64,
    }
}

/// The POV-Ray scene: a side^3 grid of spheres, jittered by POV-Ray-independent arithmetic
/// (no `rand`, so both renderers read exactly the same geometry).
fn while_scene(side: usize) -> String {
    let r = 0.35 / side as f64;
    format!(
        "// {n} spheres made with #while, for penumbra bench.\n\
         #version 3.7;\n\
         global_settings {{ assumed_gamma 1.0 }}\n\
         camera {{ location <0, 0, -4> look_at <0, 0, 0> right x*image_width/image_height angle 50 }}\n\
         light_source {{ <3, 5, -4> color rgb 1 }}\n\
         #declare S = {side};\n\
         #declare I = 0;\n\
         #while (I < S)\n\
           #declare J = 0;\n\
           #while (J < S)\n\
             #declare K = 0;\n\
             #while (K < S)\n\
               sphere {{ <(I + 0.5) / S * 2 - 1 + 0.3 / S * sin(7 * J + K),\n\
                         (J + 0.5) / S * 2 - 1 + 0.3 / S * sin(5 * K + I),\n\
                         (K + 0.5) / S * 2 - 1>, {r}\n\
                 pigment {{ color rgb <0.9, 0.5, 0.3> }} }}\n\
               #declare K = K + 1;\n\
             #end\n\
             #declare J = J + 1;\n\
           #end\n\
           #declare I = I + 1;\n\
         #end\n",
        n = side * side * side,
    )
}

fn wall_time(cmd: &mut Command) -> Result<f64, String> {
    let start = Instant::now();
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {:?}: {e}", cmd.get_program()))?;
    let elapsed = start.elapsed().as_secs_f64();
    if !out.status.success() {
        return Err(format!(
            "{:?} failed: {}",
            cmd.get_program(),
            String::from_utf8_lossy(&out.stderr)
                .lines()
                .last()
                .unwrap_or("")
        ));
    }
    Ok(elapsed)
}

fn side_by_side(side: usize, options: &BenchOptions, dir: &Path) -> Result<(f64, f64), String> {
    let scene = dir.join(format!("spheres_{side}.pov"));
    std::fs::write(&scene, while_scene(side)).map_err(|e| e.to_string())?;
    let (w, h) = (options.width.to_string(), options.height.to_string());
    let pov = wall_time(
        Command::new("povray")
            .arg(format!("+I{}", scene.display()))
            .arg(format!("+O{}", dir.join("pov.png").display()))
            .args([format!("+W{w}"), format!("+H{h}"), "-A".into(), "-D".into()])
            .args(["-V", "-GA"]),
    )?;
    let ours = wall_time(
        Command::new(&options.penumbra)
            .arg("render")
            .arg(&scene)
            .arg("-o")
            .arg(dir.join("penumbra.png"))
            .args(["--width", &w, "--height", &h, "--spp", "1", "-q"]),
    )?;
    Ok((ours, pov))
}

/// Runs the benchmark and returns its report as text.
pub fn run(options: &BenchOptions, mut log: impl FnMut(&str)) -> String {
    let mut report = String::new();
    let mut line = |s: String| {
        log(&s);
        report.push_str(&s);
        report.push('\n');
    };
    let threads = rayon::current_num_threads();
    line(format!(
        "penumbra bench: {} rays of each kind per scene on one thread; BVH built on {threads} threads",
        options.rays
    ));
    line(format!(
        "{:>9} {:>12} {:>12} {:>9} {:>12} {:>12} {:>10} {:>9}",
        "spheres", "camera/s", "shadow/s", "hit", "build (s)", "seq. (s)", "bytes/obj", "depth"
    ));
    let mut per_ray = Vec::new();
    for &n in &options.counts {
        let (world, build) = sphere_world(n);
        let seq = {
            let mut rng = Xorshift(1);
            let bounds: Vec<crate::geometry::Aabb> = (0..n)
                .map(|_| {
                    let c = rng.vec3();
                    crate::geometry::Aabb::new(c, c + DVec3::splat(0.01))
                })
                .collect();
            let start = Instant::now();
            std::hint::black_box(crate::geometry::Bvh::build_sequential(&bounds));
            let seq = start.elapsed().as_secs_f64();
            let start = Instant::now();
            std::hint::black_box(crate::geometry::Bvh::build(&bounds));
            (seq, start.elapsed().as_secs_f64())
        };
        let figures = trace(&world, options.rays);
        let bytes = world.memory_bytes() as f64 / n as f64;
        per_ray.push((n, 1.0 / figures.camera_rate, 1.0 / figures.shadow_rate));
        line(format!(
            "{n:>9} {:>12.0} {:>12.0} {:>8.1}% {build:>12.4} {:>12.4} {bytes:>10.1} {:>9}",
            figures.camera_rate,
            figures.shadow_rate,
            100.0 * figures.hit_fraction,
            seq.0,
            world.bvh_depth(),
        ));
        line(format!(
            "          (BVH alone over {n} boxes: sequential {:.4} s, parallel {:.4} s, speed-up {:.2}x)",
            seq.0,
            seq.1,
            seq.0 / seq.1
        ));
    }
    if let (Some(first), Some(last)) = (per_ray.first(), per_ray.last())
        && last.0 > first.0
    {
        line(format!(
            "time per ray, {} -> {} spheres: camera x{:.2}, shadow x{:.2} (target: at most x3)",
            first.0,
            last.0,
            last.1 / first.1,
            last.2 / first.2
        ));
    }
    for name in ["sphere", "prism", "sor", "lathe", "poly", "julia"] {
        let figures = trace(&shape_world(name), options.rays);
        line(format!(
            "{name:>9} {:>12.0} {:>12.0} {:>8.1}%   (one shape; cubic spline prism and lathe, sextic poly, quaternion julia)",
            figures.camera_rate,
            figures.shadow_rate,
            100.0 * figures.hit_fraction,
        ));
    }
    if options.povray_counts.is_empty() {
        return report;
    }
    let dir = match TempDir::new("bench") {
        Ok(d) => d,
        Err(e) => {
            line(format!("side by side skipped: no temp dir ({e})"));
            return report;
        }
    };
    line(format!(
        "side by side, {}x{}, point light, parse included, all cores: penumbra 1 spp vs povray -A",
        options.width, options.height
    ));
    for &n in &options.povray_counts {
        let side = (n as f64).cbrt().round().max(1.0) as usize;
        match side_by_side(side, options, dir.path()) {
            Ok((ours, pov)) => line(format!(
                "{:>9} spheres (#while): penumbra {ours:.2} s, POV-Ray {pov:.2} s, ratio {:.2}",
                side * side * side,
                ours / pov
            )),
            Err(e) => line(format!("{:>9} spheres: skipped: {e}", side * side * side)),
        }
    }
    let _ = writeln!(report);
    report
}
