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
