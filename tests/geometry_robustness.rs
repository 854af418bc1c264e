//! The places where ray tracers fail (shared/testing-statistics.md, "Failure modes"), each
//! provoked on purpose: self-shadowing acne at grazing angles and extreme scales, scenes far
//! from the origin, coincident CSG faces, degenerate input, lights inside objects and lights
//! of zero area.

use glam::DVec3;
use penumbra::geometry::{Ray, Transform};
use penumbra::render::{Integrator, PixelSampler, PreparedScene, RayCounts, RenderOptions};
use penumbra::scene::*;

fn matte(c: f64) -> Option<Texture> {
    Some(Texture {
        pigment: Pigment::solid(Colour::rgb(c, c, c)),
        finish: Finish {
            ambient: DVec3::ZERO,
            diffuse: 1.0,
            ..Finish::default()
        },
        ..Texture::default()
    })
}

fn object(shape: Shape, texture: Option<Texture>) -> Object {
    let mut o = Object::new(shape);
    o.texture = texture.map(std::sync::Arc::new);
    o
}

fn radiance(scene: &PreparedScene, ray: &Ray) -> DVec3 {
    let mut sampler = PixelSampler::new(1);
    sampler.start(0, 0, 0, 0);
    Integrator::new(scene, &RenderOptions::default()).radiance(
        ray,
        &mut sampler,
        &mut RayCounts::default(),
    )
}

/// A convex object cannot shadow itself: the lit side shows exactly albedo * N.L, down to
/// grazing N.L = 1e-3, for spheres from 1e-3 to 1e5 in size and far from the origin.
#[test]
fn no_acne_at_grazing_angles_and_any_scale() {
    for scale in [1e-3, 1.0, 1e3, 1e5] {
        for offset in [0.0, 1e3 * scale] {
            let center = DVec3::new(offset, -offset * 0.5, offset * 0.25);
            let mut scene = Scene::default();
            scene.objects.push(object(
                Shape::Sphere {
                    center,
                    radius: scale,
                },
                matte(0.8),
            ));
            // The light far away along +y: N.L = cos(polar angle).
            scene
                .lights
                .push(Light::point(center + DVec3::Y * scale * 1e6, DVec3::ONE));
            let prepared = PreparedScene::new(&scene);
            for n_dot_l in [1.0f64, 0.5, 0.1, 1e-2, 1e-3] {
                for azimuth in [0.0f64, 1.0, 2.0, 4.0] {
                    let s = (1.0 - n_dot_l * n_dot_l).sqrt();
                    let normal = DVec3::new(s * azimuth.cos(), n_dot_l, s * azimuth.sin());
                    let point = center + normal * scale;
                    // Look at the point along its normal, from outside.
                    let origin = point + normal * scale * 3.0;
                    let l = radiance(&prepared, &Ray::new(origin, -normal));
                    // The light is not quite at infinity: use its true direction.
                    let to_light = (center + DVec3::Y * scale * 1e6 - point).normalize();
                    let expected = 0.8 * normal.dot(to_light);
                    assert!(
                        (l.x - expected).abs() <= 1e-6 * expected.max(1e-3),
                        "scale {scale}, offset {offset}, N.L {n_dot_l}: {} vs {expected}",
                        l.x
                    );
                }
            }
        }
    }
}

fn test_scene() -> Scene {
    let mut scene = Scene::default();
    let mut camera = CameraSpec {
        location: DVec3::new(0.0, 2.0, -5.0),
        look_at: Some(DVec3::new(0.0, 0.5, 0.0)),
        ..CameraSpec::default()
    };
    camera.right = DVec3::X * 4.0 / 3.0;
    scene.camera = camera.resolve();
    scene.objects.push(object(
        Shape::Plane {
            normal: DVec3::Y,
            distance: 0.0,
        },
        matte(0.7),
    ));
    scene.objects.push(object(
        Shape::Sphere {
            center: DVec3::new(0.0, 1.0, 0.0),
            radius: 1.0,
        },
        matte(0.9),
    ));
    let mut lit = Light::point(DVec3::new(-3.0, 5.0, -3.0), DVec3::ONE);
    lit.area = Some(AreaLight {
        axis1: DVec3::X,
        axis2: DVec3::Z,
        size1: 3,
        size2: 3,
        adaptive: None,
        jitter: false,
        circular: false,
        orient: false,
    });
    scene.lights.push(lit);
    scene
}

fn render(scene: &Scene, spp: u32) -> Vec<[f32; 3]> {
    let options = RenderOptions {
        width: 64,
        height: 48,
        samples_per_pixel: spp,
        seed: 3,
        ..RenderOptions::default()
    };
    penumbra::render_scene(scene, &options, &())
        .expect("renders")
        .0
        .pixels
}

fn translate_everything(scene: &mut Scene, by: DVec3) {
    let t = Transform::translate(by);
    for o in &mut scene.objects {
        o.transform_by(&t);
    }
    for l in &mut scene.lights {
        l.location += by;
    }
    scene.camera.location += by;
}

/// The same scene moved 1e3 to 1e6 away from the origin renders the same image.
#[test]
fn far_from_the_origin_the_image_is_unchanged() {
    let base = render(&test_scene(), 4);
    for distance in [1e3, 1e6] {
        let mut moved = test_scene();
        translate_everything(
            &mut moved,
            DVec3::new(distance, -distance * 0.3, distance * 0.7),
        );
        let image = render(&moved, 4);
        let differing = base
            .iter()
            .zip(&image)
            .filter(|(a, b)| (a[0] - b[0]).abs() > 1e-3)
            .count();
        // Only the odd pixel whose sample lands within rounding of an edge may differ.
        assert!(
            differing <= base.len() / 500,
            "{distance}: {differing} of {} pixels differ",
            base.len()
        );
    }
}

/// Zero radius, a light on a surface, degenerate triangles: every sample stays finite.
#[test]
fn degenerate_input_gives_finite_samples() {
    let mut scene = test_scene();
    scene.objects.push(object(
        Shape::Sphere {
            center: DVec3::new(1.5, 0.5, -1.0),
            radius: 0.0,
        },
        matte(0.5),
    ));
    scene.objects.push(object(
        Shape::Triangle(Box::new([DVec3::ZERO, DVec3::X, DVec3::X * 2.0])),
        matte(0.5),
    ));
    scene.objects.push(object(
        Shape::Cylinder(Box::new(penumbra::scene::Cylinder {
            base: DVec3::ONE,
            cap: DVec3::ONE,
            radius: 1.0,
            open: false,
        })),
        matte(0.5),
    ));
    // A light exactly on the floor.
    scene
        .lights
        .push(Light::point(DVec3::new(1.0, 0.0, 1.0), DVec3::splat(0.5)));
    let options = RenderOptions {
        width: 32,
        height: 24,
        samples_per_pixel: 4,
        ..RenderOptions::default()
    };
    let (film, _) = penumbra::render_film(&scene, &options, &()).expect("renders");
    assert!(
        film.non_finite.is_empty(),
        "{:?}",
        &film.non_finite[..5.min(film.non_finite.len())]
    );
    assert!(film.means().iter().flatten().all(|v| v.is_finite()));
}

/// A light inside a closed opaque object changes nothing outside it.
#[test]
fn a_light_inside_an_opaque_object_is_invisible_outside() {
    let base = render(&test_scene(), 4);
    let mut scene = test_scene();
    scene
        .lights
        .push(Light::point(DVec3::new(0.0, 1.0, 0.0), DVec3::splat(3.0)));
    assert_eq!(render(&scene, 4), base);
}

/// An area light shrunk towards zero size gives the point light's image.
#[test]
fn a_zero_area_light_equals_the_point_light() {
    let mut point = test_scene();
    point.lights[0].area = None;
    let reference = render(&point, 4);
    let mut tiny = test_scene();
    if let Some(area) = &mut tiny.lights[0].area {
        area.axis1 *= 1e-9;
        area.axis2 *= 1e-9;
    }
    let image = render(&tiny, 4);
    let max = reference
        .iter()
        .zip(&image)
        .map(|(a, b)| (a[0] - b[0]).abs())
        .fold(0.0f32, f32::max);
    assert!(max < 1e-6, "max difference {max}");
}

/// CSG with coincident faces: no speckle (pixels far from their 3x3 median).
#[test]
fn coincident_csg_faces_do_not_speckle() {
    let mut scene = test_scene();
    // A point light: shadow noise from an area light at one sample would look like speckle.
    scene.lights[0].area = None;
    scene.objects.truncate(1);
    let outer = object(
        Shape::Box {
            corner1: DVec3::new(-1.0, 0.0, -1.0),
            corner2: DVec3::new(1.0, 1.0, 1.0),
        },
        matte(0.9),
    );
    let cutter = object(
        Shape::Box {
            corner1: DVec3::new(-0.5, 0.5, -1.0),
            corner2: DVec3::new(0.5, 1.0, 0.5),
        },
        matte(0.2),
    );
    scene
        .objects
        .push(object(Shape::Difference(vec![outer, cutter]), None));
    let (w, h) = (64usize, 48usize);
    // Enough samples that edges are smooth, so only real speckle stands out.
    let image = render(&scene, 64);
    let mut speckles = 0;
    for y in 1..h - 1 {
        for x in 1..w - 1 {
            let mut around: Vec<f32> = (0..9)
                .map(|k| image[(y + k / 3 - 1) * w + x + k % 3 - 1][0])
                .collect();
            around.sort_by(f32::total_cmp);
            if (image[y * w + x][0] - around[4]).abs() > 0.2 {
                speckles += 1;
            }
        }
    }
    // Edges of the shapes can differ from their median; isolated speckles would be many.
    assert!(speckles <= 2, "{speckles} speckled pixels");
}
