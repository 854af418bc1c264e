//! The scene language builds the appearance model POV-Ray's syntax describes: layered
//! textures, texture maps, normals, pattern modifiers, finish and interior items.

use glam::DVec3;
use penumbra::appearance::{may_transmit, perturbed_normal, texture_layers};
use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::scene::Scene;

fn load(source: &str) -> Scene {
    let options = LoadOptions {
        image_width: 160,
        image_height: 120,
        ..LoadOptions::default()
    };
    match load_scene_source("test.pov", source, &options) {
        Ok(l) => l.scene,
        Err(d) => panic!("{d}"),
    }
}

#[test]
fn layered_textures_stack_top_last_written() {
    let s = load(
        "#version 3.7;\nsphere { 0, 1 texture { pigment { rgb <1,0,0> } }\n\
         texture { pigment { rgbt <0,0,1,0.5> } } }",
    );
    let t = s.objects[0].texture.as_ref().expect("texture");
    let layers: Vec<_> = texture_layers(t, DVec3::ZERO).map(|l| l.colour).collect();
    assert_eq!(layers.len(), 2);
    assert_eq!(layers[0].rgb, DVec3::new(0.0, 0.0, 1.0));
    assert_eq!(layers[0].transmit, 0.5);
    assert_eq!(layers[1].rgb, DVec3::new(1.0, 0.0, 0.0));
    assert!(may_transmit(t));
}

#[test]
fn texture_map_entries_are_texture_bodies() {
    let s = load(
        "#version 3.7;\n#declare Red = texture { pigment { rgb <1,0,0> } }\n\
         plane { y, 0 texture { gradient x texture_map { [0 Red] [1 pigment { rgb <0,0,1> } finish { ambient 0 }] } } }",
    );
    // tests/lang/textures/texture_map_entries.pov checks the entries; here, their blend.
    let t = s.objects[0].texture.as_ref().expect("texture");
    let c = texture_layers(t, DVec3::new(0.5, 0.0, 0.0))
        .next()
        .expect("a layer")
        .colour
        .rgb;
    assert!((c - DVec3::new(0.5, 0.0, 0.5)).length() < 1e-4, "{c}");
}

#[test]
fn list_patterns_take_texture_entries() {
    let s = load(
        "#version 3.7;\n#declare Red = texture { pigment { rgb <1,0,0> } finish { phong 1 } }\n\
         plane { y, 0 texture { checker texture { Red } texture { pigment { rgb <0,0,1> } } } }\n\
         plane { y, 0 texture { hexagon texture { Red } } }",
    );
    let colour = |object: usize, p: DVec3| {
        let t = s.objects[object].texture.as_ref().expect("texture");
        texture_layers(t, p).next().expect("a layer").colour.rgb
    };
    // Checker: the cube at the origin takes the first entry, its neighbour the second.
    assert_eq!(
        colour(0, DVec3::new(0.5, 0.5, 0.5)),
        DVec3::new(1.0, 0.0, 0.0)
    );
    assert_eq!(
        colour(0, DVec3::new(1.5, 0.5, 0.5)),
        DVec3::new(0.0, 0.0, 1.0)
    );
    // Hexagon with one entry: the other two take the default texture (pigment black).
    assert_eq!(colour(1, DVec3::ZERO), DVec3::new(1.0, 0.0, 0.0));
    let others = colour(1, DVec3::new(1.0, 0.0, 0.2));
    assert_eq!(others, DVec3::ZERO, "{others}");
}

#[test]
fn average_weighs_its_pigment_map_entries() {
    let s = load(
        "#version 3.7;\n\
         plane { y, 0 pigment { average pigment_map { [1 rgb <1,0,0>] [3 rgbt <0,0,1,1>] } } }\n\
         plane { y, 0 pigment { average pigment_map { [gradient x] [rgb 1] } } }",
    );
    let colour = |object: usize, p: DVec3| {
        let t = s.objects[object].texture.as_ref().expect("texture");
        texture_layers(t, p).next().expect("a layer").colour
    };
    let c = colour(0, DVec3::ZERO);
    assert_eq!(c.rgb, DVec3::new(0.25, 0.0, 0.75));
    assert_eq!(c.transmit, 0.75);
    // Without weights every entry counts once: gradient x at x = 0.5 reads grey 0.5.
    let g = colour(1, DVec3::new(0.5, 0.0, 0.0)).rgb;
    assert!((g - DVec3::splat(0.75)).length() < 1e-12, "{g}");
}

#[test]
fn average_without_a_pigment_map_is_an_error() {
    let options = LoadOptions::default();
    let source = "#version 3.7;\nplane { y, 0 pigment { average } }";
    let error = load_scene_source("test.pov", source, &options).expect_err("refused");
    assert!(
        error.to_string().contains("`average` needs a pigment_map"),
        "{error}"
    );
}

/// tests/lang/textures/normal_amounts.pov checks the amounts the normals read.
#[test]
fn a_gradient_normal_tilts_the_normal() {
    let s =
        load("#version 3.7;\nplane { -z, 0 pigment { rgb 1 } normal { gradient x, 1 scale 2 } }");
    // POV-Ray: amount 1 on a unit slope gives N.L = 0.9912 facing the light.
    let t = s.objects[0].texture.as_ref().expect("t");
    let n = perturbed_normal(t, DVec3::new(0.3, 0.2, 0.0), -DVec3::Z);
    assert!((n.dot(-DVec3::Z) - 0.9912).abs() < 2e-4, "{n}");
}

/// tests/lang/textures/slope_and_normal_maps.pov checks the maps as read.
#[test]
fn a_normal_map_mixes_to_a_unit_normal() {
    let s = load(
        "#version 3.7;\nplane { -z, 0 normal { gradient x normal_map { [0 gradient y, -10] [1 gradient x, -2.5 scale 2] } rotate z*30 } }",
    );
    let t1 = s.objects[0].texture.as_ref().expect("t");
    // The mixed normal is renormalised and still faces the viewer.
    let n = perturbed_normal(t1, DVec3::new(0.3, 0.2, 0.0), -DVec3::Z);
    assert!((n.length() - 1.0).abs() < 1e-9 && n.z < 0.0, "{n}");
}

/// The errors for bad input are files in tests/lang/diagnostics/.
#[test]
fn degenerate_patterns_give_finite_colours() {
    // Degenerate but valid: a zero gradient and a brick of zero size give finite colours.
    let s = load(
        "sphere { 0, 1 pigment { gradient 0 } }\nsphere { 0, 1 pigment { brick brick_size 0 } }",
    );
    for o in &s.objects {
        let t = o.texture.as_ref().expect("t");
        let mut c = texture_layers(t, DVec3::new(0.3, 0.4, 0.5));
        assert!(c.all(|l| l.colour.rgb.is_finite()));
    }
}

#[test]
fn a_transform_before_the_texture_map_moves_its_entries_too() {
    // POV-Ray transforms the entries with the texture whatever the order (measured: the
    // entry's gradient x repeats every 4 units in both textures).
    let s = load(
        "#version 3.7;\n#declare T = texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }\n\
         plane { z, 0 texture { gradient y scale 4 texture_map { [0 T] [1 T] } } }\n\
         plane { z, 0 texture { gradient y texture_map { [0 T] [1 T] } scale 4 } }",
    );
    let grey = |object: usize, x: f64| {
        let t = s.objects[object].texture.as_ref().expect("texture");
        let mut layers = texture_layers(t, DVec3::new(x, 0.3, 0.0));
        layers.next().expect("a layer").colour.rgb.x
    };
    for x in [0.5, 1.0, 2.0, 3.0] {
        assert!((grey(0, x) - x / 4.0).abs() < 1e-9, "{x}: {}", grey(0, x));
        assert!((grey(0, x) - grey(1, x)).abs() < 1e-12);
    }
}

#[test]
fn slope_reads_the_normal_and_the_altitude() {
    use penumbra::geometry::TexturePoint;
    let s = load(
        "#version 3.7;\nsphere { 0, 1 pigment { slope { y*3 altitude y, -1, 1 } color_map { [0 rgb 0] [1 rgb 1] } } }",
    );
    let t = s.objects[0].texture.as_ref().expect("texture");
    let at = |n: DVec3, y: f64| {
        let p = TexturePoint {
            world: DVec3::new(0.0, y, 0.0),
            uv: glam::DVec2::ZERO,
            normal: n,
        };
        texture_layers(t, p).next().expect("a layer").colour.rgb.x
    };
    // POV-Ray: (3 (0.5 + asin(n.y) / pi) + (y + 1) / 2) / 4.
    let n = DVec3::new(0.6, 0.8, 0.0);
    let expected = (3.0 * (0.5 + 0.8f64.asin() / std::f64::consts::PI) + 0.75) / 4.0;
    assert!((at(n, 0.5) - expected).abs() < 1e-9, "{}", at(n, 0.5));
    assert!((at(DVec3::Y, 0.0) - (3.0 + 0.5) / 4.0).abs() < 1e-9);
}
