//! The scene language builds the appearance model POV-Ray's syntax describes: layered
//! textures, texture maps, normals, pattern modifiers, finish and interior items.

use glam::DVec3;
use penumbra::appearance::{may_transmit, perturbed_normal, texture_layers};
use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::scene::{PatternKind, PigmentKind, Scene, Warp, Wave};

fn load(source: &str) -> Scene {
    let options = LoadOptions {
        declares: Vec::new(),
        include_paths: Vec::new(),
        image_width: 160,
        image_height: 120,
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
    let layers: Vec<_> = texture_layers(t, DVec3::ZERO)
        .iter()
        .map(|l| l.colour)
        .collect();
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
    let t = s.objects[0].texture.as_ref().expect("texture");
    let map = t.map.as_ref().expect("a texture map");
    assert_eq!(map.entries.len(), 2);
    assert_eq!(map.entries[1].1.finish.ambient, DVec3::ZERO);
    let c = texture_layers(t, DVec3::new(0.5, 0.0, 0.0));
    let c = c.iter().next().expect("a layer").colour.rgb;
    assert!((c - DVec3::new(0.5, 0.0, 0.5)).length() < 1e-4, "{c}");
}

#[test]
fn normals_parse_with_amounts_and_tilt_the_normal() {
    let s = load(
        "#version 3.7;\nplane { -z, 0 pigment { rgb 1 } normal { gradient x, 1 scale 2 } }\n\
         sphere { 0, 1 normal { bumps 0.4 scale 0.1 } }\n\
         sphere { 0, 1 texture { normal { spiral1 5, 1.6 } } }",
    );
    let n0 = s.objects[0]
        .texture
        .as_ref()
        .expect("t")
        .normal
        .as_ref()
        .expect("normal");
    assert_eq!(n0.amount, 1.0);
    let n1 = s.objects[1]
        .texture
        .as_ref()
        .expect("t")
        .normal
        .as_ref()
        .expect("normal");
    assert_eq!(n1.amount, 0.4);
    let n2 = s.objects[2]
        .texture
        .as_ref()
        .expect("t")
        .normal
        .as_ref()
        .expect("normal");
    assert_eq!(n2.pattern.kind, PatternKind::Spiral1(5.0));
    assert_eq!(n2.amount, 1.6);
    // POV-Ray: amount 1 on a unit slope gives N.L = 0.9912 facing the light.
    let t = s.objects[0].texture.as_ref().expect("t");
    let n = perturbed_normal(t, DVec3::new(0.3, 0.2, 0.0), -DVec3::Z);
    assert!((n.dot(-DVec3::Z) - 0.9912).abs() < 2e-4, "{n}");
}

#[test]
fn slope_and_normal_maps_parse_and_transform_their_entries() {
    let s = load(
        "#version 3.7;\nplane { -z, 0 normal { gradient x, 1 slope_map { [0 <0, 0>] [0.5, <1, -2>] [1 0.5] } } }\n\
         plane { -z, 0 normal { gradient x normal_map { [0 gradient y, -10] [1 gradient x, -2.5 scale 2] } rotate z*30 } }",
    );
    let n0 = s.objects[0]
        .texture
        .as_ref()
        .expect("t")
        .normal
        .as_ref()
        .expect("normal");
    let heights: Vec<_> = n0
        .slope_map
        .iter()
        .map(|e| (e.value, e.height, e.slope))
        .collect();
    assert_eq!(
        heights,
        [(0.0, 0.0, 0.0), (0.5, 1.0, -2.0), (1.0, 0.5, 0.5)]
    );
    let t1 = s.objects[1].texture.as_ref().expect("t");
    let n1 = t1.normal.as_ref().expect("normal");
    assert_eq!(n1.normal_map.len(), 2);
    // The rotation written after the map turns the entries too (measured with povray).
    let p = DVec3::new(1.0, 0.0, 0.0);
    let turned = n1.normal_map[0].1.transform.inverse_point(p);
    assert!(
        (turned - n1.transform.inverse_point(p)).length() < 1e-12,
        "{turned}"
    );
    // The mixed normal is renormalised and still faces the viewer.
    let n = perturbed_normal(t1, DVec3::new(0.3, 0.2, 0.0), -DVec3::Z);
    assert!((n.length() - 1.0).abs() < 1e-9 && n.z < 0.0, "{n}");
}

#[test]
fn pattern_modifiers_and_warp_order() {
    let s = load(
        "#version 3.7;\nsphere { 0, 1 pigment { bozo scale 2 warp { turbulence 0.5 octaves 3 } \
         rotate y*10 frequency 3 phase 0.1 sine_wave color_map { [0 rgb 0] [1 rgb 1] } } }",
    );
    let p = &s.objects[0].texture.as_ref().expect("t").pigment;
    let PigmentKind::ColourMap { pattern, map } = &p.kind else {
        panic!("{:?}", p.kind)
    };
    assert_eq!(map.len(), 2);
    assert_eq!(
        (pattern.frequency, pattern.phase, pattern.wave),
        (3.0, 0.1, Wave::Sine)
    );
    // The scale before the warp moved into the chain; the rotate after it stays outside.
    assert_eq!(pattern.warps.len(), 2);
    assert!(matches!(pattern.warps[0], Warp::Transform(_)));
    let Warp::Turbulence(t) = pattern.warps[1] else {
        panic!()
    };
    assert_eq!((t.amount, t.octaves), (DVec3::splat(0.5), 3));
    assert!(!p.transform.is_identity());
}

#[test]
fn finish_and_interior_items() {
    let s = load(
        "#version 3.7;\nsphere { 0, 1 finish { diffuse 0.6, 0.2 crand 0.1 fresnel conserve_energy } \
         interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color rgb <1,0.5,0> } }",
    );
    let o = &s.objects[0];
    let f = o.texture.as_ref().expect("t").finish;
    assert_eq!((f.diffuse, f.diffuse_back, f.crand), (0.6, 0.2, 0.1));
    assert!(f.fresnel && f.conserve_energy);
    let i = o.interior.expect("interior");
    assert_eq!((i.ior, i.fade_distance, i.fade_power), (1.5, 2.0, 1001.0));
    assert_eq!(i.fade_colour, DVec3::new(1.0, 0.5, 0.0));
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let options = LoadOptions {
        declares: Vec::new(),
        include_paths: Vec::new(),
        image_width: 16,
        image_height: 16,
    };
    for src in [
        "sphere { 0, 1 pigment { gradient x color_map { [0 rgb 0] [1 } } }",
        "sphere { 0, 1 pigment { image_map { png \"missing.png\" } } }",
        "sphere { 0, 1 texture { texture_map { [0 pigment { rgb 1 }] } } }",
        "sphere { 0, 1 pigment { bozo warp { repeat x } } }",
    ] {
        assert!(
            load_scene_source("bad.pov", src, &options).is_err(),
            "{src}"
        );
    }
    // Degenerate but valid: a zero gradient and a brick of zero size give finite colours.
    let s = load(
        "sphere { 0, 1 pigment { gradient 0 } }\nsphere { 0, 1 pigment { brick brick_size 0 } }",
    );
    for o in &s.objects {
        let t = o.texture.as_ref().expect("t");
        let c = texture_layers(t, DVec3::new(0.3, 0.4, 0.5));
        assert!(c.iter().all(|l| l.colour.rgb.is_finite()));
    }
}

#[test]
fn declared_colour_maps_are_reused() {
    let s = load(
        "#version 3.7;\n#declare M = color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] }\n\
         plane { y, 0 pigment { gradient x color_map { M } } }",
    );
    let p = &s.objects[0].texture.as_ref().expect("t").pigment;
    let PigmentKind::ColourMap { map, .. } = &p.kind else {
        panic!("{:?}", p.kind)
    };
    assert_eq!(map.len(), 2);
    assert_eq!(map[1].1.rgb, DVec3::new(0.0, 0.0, 1.0));
}
