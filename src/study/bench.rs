//! `penumbra bench`: how the geometry scales. Not a timed test: it prints figures and ratios.
//!
//! - Rays per second for camera rays (nearest hit) and shadow rays (any hit) on 1e3, 1e5 and
//!   1e6 random spheres filling a cube at constant density (radius 0.4 spacings), one thread, and the growth of
//!   time per ray from the smallest to the largest scene (a BVH should keep it near log n;
//!   the target is at most 3x from 1e3 to 1e6).
//! - BVH build time (parallel and sequential) and memory per object.
//! - The whole pipeline against POV-Ray on a `#while` scene of spheres, time and peak
//!   memory of both processes side by side (`pipeline_bench`).

use std::fmt::Write as _;
use std::time::Instant;

use glam::DVec3;

use crate::geometry::{Ray, ShapeKind, Transform, World, WorldBuilder};

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
        "isosurface" => {
            b.tables.isosurfaces.push(bumpy_isosurface());
            ShapeKind::Isosurface(0)
        }
        "blob" => {
            b.tables.blobs.push(three_blob());
            ShapeKind::Blob(0)
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

/// Three spheres of radius 1 melting together (objects/blob.pov's blob, threshold 0.6).
fn three_blob() -> crate::geometry::BlobData {
    use crate::geometry::{BlobData, BlobPart, OWN_TEXTURE};
    use glam::DAffine3;
    let part = |x: f64, y: f64| BlobPart {
        to_local: DAffine3::from_translation(-DVec3::new(x, y, 0.0)),
        strength: 1.0,
        length: 0.0,
        material: OWN_TEXTURE,
    };
    BlobData::new(
        0.6,
        vec![
            part(0.75, 0.0),
            part(-0.375, 0.649_52),
            part(-0.375, -0.649_52),
        ],
    )
}

/// A unit sphere's distance with bumps of 0.1 (max_gradient 2), in a sphere of 1.2: a
/// typical scene isosurface.
fn bumpy_isosurface() -> crate::geometry::IsoData {
    use crate::function::{Expr, Internal, Math1, Math2, compile};
    let arg = |i| Box::new(Expr::Arg(i));
    let sin8 = |i| {
        let scaled = Expr::Math2(Math2::Mul, Box::new(Expr::Const(8.0)), arg(i));
        Box::new(Expr::Math1(Math1::Sin, Box::new(scaled)))
    };
    let bumps = Expr::Math2(
        Math2::Mul,
        Box::new(Expr::Const(0.1)),
        Box::new(Expr::Math2(Math2::Mul, sin8(0), sin8(1))),
    );
    let sphere = Expr::Internal(
        Internal::Sphere,
        vec![Expr::Arg(0), Expr::Arg(1), Expr::Arg(2), Expr::Const(1.0)],
    );
    let f = Expr::Math2(Math2::Add, Box::new(sphere), Box::new(bumps));
    crate::geometry::IsoData {
        function: std::sync::Arc::new(compile(&f, 3).expect("a small function")),
        container: crate::geometry::Container::Sphere {
            center: DVec3::ZERO,
            radius: 1.2,
        },
        threshold: 0.0,
        accuracy: 0.001,
        max_gradient: 2.0,
        open: false,
        steepest: Default::default(),
        origin: "bench".into(),
    }
}

/// Evaluations per second of x*x + y*y + z*z - (x*y + y*z)*0.5 (ten operations) on one
/// thread, in five runs of `PENUMBRA_FUNCTION_EVALS` (default 4M): the best and the median.
/// The best is the run the rest of the machine disturbed least (these machines are shared).
fn function_rate() -> (f64, f64) {
    use crate::function::{Expr, Math2, compile};
    let op = |f, a, b| Box::new(Expr::Math2(f, a, b));
    let arg = |i| Box::new(Expr::Arg(i));
    let sq = |i| op(Math2::Mul, arg(i), arg(i));
    let squares = op(Math2::Add, op(Math2::Add, sq(0), sq(1)), sq(2));
    let cross = op(
        Math2::Add,
        op(Math2::Mul, arg(0), arg(1)),
        op(Math2::Mul, arg(1), arg(2)),
    );
    let f = Expr::Math2(
        Math2::Sub,
        squares,
        op(Math2::Mul, cross, Box::new(Expr::Const(0.5))),
    );
    let program = compile(&f, 3).expect("a small function");
    let n: u32 = std::env::var("PENUMBRA_FUNCTION_EVALS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(4_000_000);
    let mut rates: Vec<f64> = (0..5)
        .map(|_| {
            let start = Instant::now();
            let mut sum = 0.0;
            for i in 0..n {
                let t = f64::from(i) * 1e-6;
                sum += program.eval(&[t, 1.0 - t, 0.5 * t]);
            }
            std::hint::black_box(sum);
            f64::from(n) / start.elapsed().as_secs_f64()
        })
        .collect();
    rates.sort_by(f64::total_cmp);
    (rates[4], rates[2])
}

/// "Penumbra" in timrom.ttf (when installed), about three units wide: each glyph a prism in
/// the BVH, or (`carved`) the glyphs cut out of a box, where CSG asks every glyph and only
/// each prism's own bounds test stops a ray early.
fn text_world(carved: bool) -> Option<World> {
    use crate::geometry::{CsgOp, PrismData};
    use glam::{DAffine3, DMat3, DVec2};
    let data = std::fs::read("/usr/share/povray-3.7/include/timrom.ttf").ok()?;
    let glyphs = crate::scene::text::Font::new(data)
        .ok()?
        .layout("Penumbra", DVec2::ZERO);
    let fit = Transform::translate(DVec3::new(-2.0, -0.3, 0.0))
        .then(&Transform::scale(DVec3::splat(0.75))?)
        .then(&Transform::rotate(DVec3::new(-20.0, 20.0, 0.0)));
    let stand_up = DMat3::from_cols(DVec3::X, DVec3::Z, -DVec3::Y);
    let mut b = WorldBuilder::default();
    let mut items = Vec::new();
    for g in glyphs {
        let data = PrismData::new(&g.segments, 0.0, 0.3, false, false);
        b.tables.prisms.push(data);
        let at = DAffine3::from_mat3_translation(stand_up, g.at.extend(0.0));
        let place = Transform::from_affine(at)?.then(&fit);
        let kind = ShapeKind::Prism((b.tables.prisms.len() - 1) as u32);
        items.push(b.primitive(kind, &place, 0, 0));
    }
    if carved {
        let slab = ShapeKind::Box {
            min: DVec3::new(-0.2, -0.4, 0.15),
            max: DVec3::new(4.2, 1.0, 0.8),
        };
        items.insert(0, b.primitive(slab, &fit, 0, 0));
        let item = b.csg(CsgOp::Difference, items, false);
        b.add_top(item);
    } else {
        for item in items {
            b.add_top(item);
        }
    }
    Some(b.build())
}

/// The bench lines of the text worlds: rays per second, or why there are none.
fn text_lines(rays: usize) -> Vec<String> {
    let mut out = Vec::new();
    for (name, carved) in [("text", false), ("text csg", true)] {
        let Some(world) = text_world(carved) else {
            out.push(format!("{name:>9} skipped: timrom.ttf is not installed"));
            continue;
        };
        let figures = trace(&world, rays, RayOrder::Random);
        out.push(format!(
            "{name:>9} {:>12.0} {:>12.0} {:>8.1}%   (\"Penumbra\" in timrom.ttf{})",
            figures.camera_rate,
            figures.shadow_rate,
            100.0 * figures.hit_fraction,
            if carved { ", carved out of a box" } else { "" },
        ));
    }
    out
}

/// A closed sphere of radius 1 as an indexed mesh of about `2 n^2` triangles (n bands of
/// latitude, 2n of longitude): the mesh2 line's shape, and the large mesh whose memory per
/// triangle the bench reports.
fn mesh_world(n: usize) -> (World, usize) {
    use crate::geometry::MeshData;
    let mut m = MeshData::default();
    let columns = 2 * n;
    for j in 0..=n {
        let theta = std::f64::consts::PI * j as f64 / n as f64;
        for i in 0..columns {
            let phi = std::f64::consts::TAU * i as f64 / columns as f64;
            let p = DVec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            );
            m.vertices.push(p.as_vec3().to_array());
        }
    }
    let at = |i: usize, j: usize| (j * columns + i % columns) as u32;
    for j in 0..n {
        for i in 0..columns {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if j > 0 {
                m.faces.push([a, b, c]);
            }
            if j + 1 < n {
                m.faces.push([a, c, d]);
            }
        }
    }
    m.finish();
    let triangles = m.faces.len();
    let mut b = WorldBuilder::default();
    b.tables.meshes.push(m);
    let item = b.primitive(ShapeKind::Mesh(0), &Transform::IDENTITY, 0, 0);
    b.add_top(item);
    (b.build(), triangles)
}

/// A height field of `n x n` points of rolling hills over [-1, 1] in x and z, tilted
/// towards the camera.
fn height_field_world(n: usize) -> (World, usize) {
    let heights: Vec<f32> = (0..n * n)
        .map(|k| {
            let (x, z) = ((k % n) as f64 / n as f64, (k / n) as f64 / n as f64);
            (0.5 + 0.25 * (13.0 * x).sin() * (11.0 * z).cos() + 0.2 * (31.0 * x * z).sin()) as f32
        })
        .collect();
    let hf = crate::geometry::HeightFieldData::new(n, n, std::sync::Arc::new(heights), true, 0.0)
        .expect("a full grid");
    let mut b = WorldBuilder::default();
    b.tables.height_fields.push(hf);
    let place = Transform::translate(DVec3::new(-0.5, -0.5, -0.5))
        .then(&Transform::scale(DVec3::new(2.0, 1.0, 2.0)).expect("non-zero"))
        .then(&Transform::rotate(DVec3::new(-50.0, 0.0, 0.0)));
    let item = b.primitive(ShapeKind::HeightField(0), &place, 0, 0);
    b.add_top(item);
    (b.build(), 2 * (n - 1) * (n - 1))
}

/// The mesh2 and height field lines: rays per second on one large shape of each, and
/// bytes of geometry per triangle.
fn triangle_lines(options: &BenchOptions, line: &mut impl FnMut(String)) {
    let shapes = [
        ("mesh2", mesh_world(700)),
        ("hfield", height_field_world(512)),
    ];
    for (name, (world, triangles)) in shapes {
        let figures = trace(&world, options.rays, RayOrder::Random);
        line(format!(
            "{name:>9} {:>12.0} {:>12.0} {:>8.1}%   ({triangles} triangles, {:.1} bytes per triangle)",
            figures.camera_rate,
            figures.shadow_rate,
            100.0 * figures.hit_fraction,
            world.memory_bytes() as f64 / triangles as f64,
        ));
    }
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

/// The order rays are traced in: as a camera traces them, or scattered.
#[derive(Clone, Copy, PartialEq)]
enum RayOrder {
    /// A square image's pixels tile by tile (16 x 16), one jittered ray each: the order
    /// penumbra's render traces camera rays in, where neighbouring rays meet the same
    /// nodes and objects and find them in the cache.
    Tiles,
    /// Every ray in a random direction: no ray shares the previous one's path, as for the
    /// scattered rays of diffuse bounces (the cache helps least).
    Random,
}

/// Half the width of the camera's view square at distance 3, where the clouds' front face
/// spans [-1, 1]^2: about a third of the camera rays miss the cloud at the root.
const VIEW: f64 = 1.2;
/// A view within the front face: every camera ray meets the cloud, as where objects fill the
/// image.
const INTO_CLOUD: f64 = 0.7;

/// Directions from the pinhole through the view square [-view, view]^2 at distance 3.
fn ray_directions(rays: usize, order: RayOrder, view: f64) -> Vec<DVec3> {
    const TILE: usize = 16;
    let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
    let through = |s: f64, t: f64| DVec3::new(s * view, t * view, 3.0).normalize();
    if order == RayOrder::Random {
        return (0..rays)
            .map(|_| through(rng.next() * 2.0 - 1.0, rng.next() * 2.0 - 1.0))
            .collect();
    }
    let side = ((rays as f64).sqrt().ceil() as usize).max(1);
    let tiles = side.div_ceil(TILE);
    let mut dirs = Vec::with_capacity(side * side);
    for tile in 0..tiles * tiles {
        let (tx, ty) = (tile % tiles * TILE, tile / tiles * TILE);
        for y in ty..(ty + TILE).min(side) {
            for x in tx..(tx + TILE).min(side) {
                let s = (x as f64 + rng.next()) / side as f64 * 2.0 - 1.0;
                let t = (y as f64 + rng.next()) / side as f64 * 2.0 - 1.0;
                dirs.push(through(s, t));
            }
        }
    }
    dirs.truncate(rays);
    dirs
}

/// Camera rays from a pinhole in front of the cube, then shadow rays from their hits to a
/// point light (in the same order), all on the current thread.
fn trace(world: &World, rays: usize, order: RayOrder) -> RayFigures {
    trace_view(world, rays, order, VIEW)
}

fn trace_view(world: &World, rays: usize, order: RayOrder, view: f64) -> RayFigures {
    let eye = DVec3::new(0.0, 0.0, -4.0);
    let light = DVec3::new(3.0, 5.0, -4.0);
    let dirs = ray_directions(rays, order, view);
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

/// The ray-rate table: camera and shadow rays per second through clouds of `counts`
/// spheres, in tile order and at random, with the tree's build time, bytes and depth.
pub fn sphere_table(counts: &[usize], rays: usize, line: &mut impl FnMut(String)) {
    line(
        "camera and shadow rays per second: rays in tile order as a render traces them, and \
         rays in random directions (no coherence: every ray's nodes are new to the cache)"
            .to_string(),
    );
    line(format!(
        "{:>9} {:>12} {:>12} {:>12} {:>12} {:>9} {:>12} {:>12} {:>10} {:>9}",
        "spheres",
        "camera/s",
        "shadow/s",
        "random/s",
        "r.shadow/s",
        "hit",
        "build (s)",
        "seq. (s)",
        "bytes/obj",
        "depth"
    ));
    let mut per_ray = Vec::new();
    for &n in counts {
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
        let figures = trace(&world, rays, RayOrder::Tiles);
        let random = trace(&world, rays, RayOrder::Random);
        let bytes = world.memory_bytes() as f64 / n as f64;
        per_ray.push((n, 1.0 / random.camera_rate, 1.0 / random.shadow_rate));
        line(format!(
            "{n:>9} {:>12.0} {:>12.0} {:>12.0} {:>12.0} {:>8.1}% {build:>12.4} {:>12.4} {bytes:>10.1} {:>9}",
            figures.camera_rate,
            figures.shadow_rate,
            random.camera_rate,
            random.shadow_rate,
            100.0 * random.hit_fraction,
            seq.0,
            world.bvh_depth(),
        ));
        line(format!(
            "          (BVH alone over {n} boxes: sequential {:.4} s, parallel {:.4} s, speed-up {:.2}x)",
            seq.0,
            seq.1,
            seq.0 / seq.1
        ));
        let (tiles, random) = (
            trace_view(&world, rays, RayOrder::Tiles, INTO_CLOUD),
            trace_view(&world, rays, RayOrder::Random, INTO_CLOUD),
        );
        line(format!(
            "          (every camera ray into the cloud, {:.0}% hit: camera {:.0}, shadow {:.0}; random {:.0}, {:.0} per second)",
            100.0 * random.hit_fraction,
            tiles.camera_rate,
            tiles.shadow_rate,
            random.camera_rate,
            random.shadow_rate
        ));
    }
    if let (Some(first), Some(last)) = (per_ray.first(), per_ray.last())
        && last.0 > first.0
    {
        line(format!(
            "time per random ray, {} -> {} spheres: camera x{:.2}, shadow x{:.2} (target: at most x3)",
            first.0,
            last.0,
            last.1 / first.1,
            last.2 / first.2
        ));
    }
}

/// The function line and a line per shape, beside one sphere.
pub fn shape_lines(rays: usize, line: &mut impl FnMut(String)) {
    let (best, median) = function_rate();
    line(format!(
        "function: {:.1} M evaluations/s (best of 5; median {:.1}) of a ten-operation function (x*x + y*y + z*z - (x*y + y*z)*0.5), one thread",
        best * 1e-6,
        median * 1e-6
    ));
    line(
        "one shape, rays/s (camera, shadow) and the camera rays' hit fraction; cubic spline \
         prism and lathe; isosurface: bumpy sphere, max_gradient 2; blob: three spheres; \
         sextic poly; quaternion julia"
            .to_string(),
    );
    for name in [
        "sphere",
        "prism",
        "sor",
        "lathe",
        "isosurface",
        "blob",
        "poly",
        "julia",
    ] {
        let figures = trace(&shape_world(name), rays, RayOrder::Random);
        line(format!(
            "{name:>10} {:>12.0} {:>12.0} {:>8.1}%",
            figures.camera_rate,
            figures.shadow_rate,
            100.0 * figures.hit_fraction,
        ));
    }
}

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
    sphere_table(&options.counts, options.rays, &mut line);
    shape_lines(options.rays, &mut line);
    text_lines(options.rays).into_iter().for_each(&mut line);
    triangle_lines(options, &mut line);
    if !options.povray_counts.is_empty() {
        super::pipeline_bench::run(
            &options.povray_counts,
            &options.penumbra,
            (options.width, options.height),
            &mut line,
        );
    }
    let _ = writeln!(report);
    report
}
