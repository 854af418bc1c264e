//! Shared objects: `object { Name transforms }` of a declared object of many parts places
//! one prototype instead of copying it (issue 16's forest). The forest's image against
//! POV-Ray is in tests/povray_convergence.rs (scenes/forest.pov); here, what is shared and
//! what is copied, and the forest's memory.

use std::path::PathBuf;
use std::sync::Arc;

use penumbra::lang::{LoadOptions, load_scene, load_scene_source};
use penumbra::render::prepared::PreparedScene;
use penumbra::scene::{Object, Scene, Shape};

fn load(source: &str) -> Scene {
    match load_scene_source("test.pov", source, &LoadOptions::default()) {
        Ok(loaded) => loaded.scene,
        Err(d) => panic!("{d}"),
    }
}

/// A tree of `parts` spheres, declared, and then `placements`.
fn scene(parts: usize, placements: &str) -> String {
    format!(
        "#declare Tree = union {{\n\
           #declare I = 0;\n\
           #while (I < {parts}) sphere {{ <I, 0, 0>, 0.4 }} #declare I = I + 1; #end\n\
           pigment {{ checker color rgb 1 color rgb 0 scale 0.3 }}\n\
         }}\n\
         {placements}\n"
    )
}

fn shared(o: &Object) -> Option<&Arc<Object>> {
    match &o.shape {
        Shape::Instance(s) => Some(s),
        _ => None,
    }
}

#[test]
fn placements_that_only_move_a_large_object_share_it() {
    let s = load(&scene(
        40,
        "object { Tree translate x } object { Tree rotate y * 30 scale 2 }",
    ));
    let (a, b) = (shared(&s.objects[0]), shared(&s.objects[1]));
    assert!(a.is_some_and(|a| b.is_some_and(|b| Arc::ptr_eq(a, b))));
    let prepared = PreparedScene::new(&s);
    assert_eq!(prepared.world.instance_count(), 2);
    // One prototype of 40 spheres, no copies in the world itself.
    assert_eq!(prepared.world.primitive_count(), 0);
}

#[test]
fn small_objects_and_placements_with_modifiers_are_copies() {
    // Below the size that pays for sharing.
    let s = load(&scene(8, "object { Tree translate x }"));
    assert!(matches!(s.objects[0].shape, Shape::Union(_)));
    // A texture of the placement's own: its own copy, textured.
    let s = load(&scene(40, "object { Tree translate x pigment { rgb 1 } }"));
    assert!(matches!(s.objects[0].shape, Shape::Union(_)));
    assert!(s.objects[0].texture.is_some());
    // Flags too.
    let s = load(&scene(40, "object { Tree no_shadow }"));
    assert!(s.objects[0].flags.no_shadow && matches!(s.objects[0].shape, Shape::Union(_)));
}

#[test]
fn a_placement_that_inherits_looks_is_built_as_a_copy() {
    // The union's texture reaches the tree's parts only in this placement: the prepared
    // scene copies it rather than sharing the prototype's materials.
    let s = load(&scene(
        40,
        "union { object { Tree } sphere { -x, 1 } pigment { rgb <1, 0, 0> } }\n\
         object { Tree translate 5 * y }",
    ));
    let prepared = PreparedScene::new(&s);
    assert_eq!(prepared.world.instance_count(), 1);
    assert_eq!(prepared.world.primitive_count(), 41);
}

/// 10^4 trees of 10^3 parts: 10^7 objects as POV-Ray reads the scene (where it takes about
/// 6 GB, docs/large-scenes.md); shared, the whole prepared scene stays small.
#[test]
fn a_forest_of_ten_million_parts_fits_in_a_few_megabytes() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/forest.pov");
    let options = LoadOptions {
        declares: vec![("Trees".into(), 100.0), ("Parts".into(), 1000.0)],
        ..LoadOptions::default()
    };
    let scene = load_scene(&path, &options).expect("the forest loads").scene;
    assert_eq!(scene.objects.len(), 100 * 100 + 1);
    let prepared = PreparedScene::new(&scene);
    assert_eq!(prepared.world.instance_count(), 100 * 100);
    let bytes = prepared.world.memory_bytes();
    // A placement costs its instance, its bounds in the BVH and one moved leaf texture:
    // well under 1 KB each, against about 10^3 x 100 bytes copied.
    assert!(bytes < 10 << 20, "{bytes} bytes");
    // Each tree has two materials of its own (bark, leaves), nothing per part.
    assert!(
        prepared.materials.len() <= 2 * 100 * 100 + 4,
        "{}",
        prepared.materials.len()
    );
}

/// A mesh of `n` x `n` quads (2 n^2 triangles), declared, with `placements` after it.
fn mesh_scene(n: usize, placements: &str) -> String {
    format!(
        "#version 3.7;\n\
         global_settings {{ assumed_gamma 1 }}\n\
         camera {{ location <0, 3, -6> look_at <0, 0.5, 0> }}\n\
         light_source {{ <-4, 8, -6> color rgb 1 }}\n\
         plane {{ y, -0.5 pigment {{ checker color rgb 0.8 color rgb 0.3 }} }}\n\
         #declare N = {n};\n\
         #declare Hill = mesh {{\n\
           #declare I = 0;\n\
           #while (I < N)\n\
             #declare J = 0;\n\
             #while (J < N)\n\
               #declare A = <I / N - 0.5, 0.3 * sin(I / 2) * cos(J / 3), J / N - 0.5>;\n\
               #declare B = <(I + 1) / N - 0.5, 0.3 * sin((I + 1) / 2) * cos(J / 3), J / N - 0.5>;\n\
               #declare C = <I / N - 0.5, 0.3 * sin(I / 2) * cos((J + 1) / 3), (J + 1) / N - 0.5>;\n\
               #declare D = <(I + 1) / N - 0.5, 0.3 * sin((I + 1) / 2) * cos((J + 1) / 3), (J + 1) / N - 0.5>;\n\
               triangle {{ A, B, D }} triangle {{ A, D, C }}\n\
               #declare J = J + 1;\n\
             #end\n\
             #declare I = I + 1;\n\
           #end\n\
           texture {{ pigment {{ gradient y color_map {{ [0 rgb <0.1, 0.4, 0.1>] [1 rgb <0.9, 0.8, 0.5>] }} scale 0.4 }} }}\n\
         }}\n\
         {placements}\n"
    )
}

/// Placements of a declared mesh share it, and show what copies of it show: the same
/// scene rendered with every placement made a copy (`no_reflection`, which changes nothing
/// in a scene without reflection, is a modifier, so each placement copies the mesh) gives
/// the same image, to rounding in the geometry.
#[test]
fn placed_meshes_are_shared_and_render_as_copies_do() {
    let placements = |extra: &str| {
        (0..6)
            .map(|k| {
                format!(
                    "object {{ Hill {extra} scale <1.5, 1 + {k} * 0.2, 1> rotate y * {} translate <{} - 2.5, 0, {}> }}\n",
                    k * 35,
                    k,
                    (k % 2) as f64 * 1.5
                )
            })
            .collect::<String>()
    };
    let shared_scene = load(&mesh_scene(12, &placements("")));
    let copied_scene = load(&mesh_scene(12, &placements("no_reflection")));
    let shared_world = PreparedScene::new(&shared_scene).world;
    let copied_world = PreparedScene::new(&copied_scene).world;
    assert_eq!(
        (
            shared_world.instance_count(),
            shared_world.primitive_count()
        ),
        (6, 1)
    );
    assert_eq!(
        (
            copied_world.instance_count(),
            copied_world.primitive_count()
        ),
        (0, 7)
    );
    let options = penumbra::render::RenderOptions {
        width: 96,
        height: 72,
        samples_per_pixel: 4,
        seed: 7,
        ..penumbra::render::RenderOptions::default()
    };
    let render = |s: &Scene| penumbra::render_scene(s, &options, &()).expect("render").0;
    let (a, b) = (render(&shared_scene), render(&copied_scene));
    let differing = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .filter(|(p, q)| p.iter().zip(q.iter()).any(|(x, y)| (x - y).abs() > 1e-6))
        .count();
    // A sample may fall the other way at a silhouette when the rounding differs; a wrong
    // placement, normal or texture would change hundreds of pixels.
    assert!(differing <= 3, "{differing} pixels differ");
    let lit = a
        .pixels
        .iter()
        .filter(|p| p.iter().any(|&c| c > 0.05))
        .count();
    assert!(lit > 3000, "{lit} lit pixels: the test would see nothing");
}
