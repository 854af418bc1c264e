//! Scenes read end to end: values in the resulting model, exact diagnostics, and inputs
//! that must never panic.

use std::path::PathBuf;

use glam::DVec3;

use super::*;
use crate::scene::{Colour, LightKind, PigmentKind, Shape};

fn load(src: &str) -> Loaded {
    match load_scene_source("test.pov", src, &LoadOptions::default()) {
        Ok(l) => l,
        Err(e) => panic!("unexpected error:\n{e}"),
    }
}

fn error(src: &str) -> Diagnostic {
    match load_scene_source("test.pov", src, &LoadOptions::default()) {
        Ok(_) => panic!("expected an error for:\n{src}"),
        Err(e) => e,
    }
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

#[test]
fn empty_scene_has_defaults() {
    let s = load("// nothing\n/* nested /* comment */ still */").scene;
    assert!(s.objects.is_empty());
    assert_eq!(s.version, 3.7);
    assert_eq!(s.background, Colour::BLACK);
}

#[test]
fn sphere_with_pigment_and_translate() {
    let s = load("sphere { <1,2,3>, 0.5 pigment { color rgb <1,0,0> } translate x*2 }").scene;
    let o = &s.objects[0];
    assert_eq!(
        o.shape,
        Shape::Sphere {
            center: DVec3::new(1.0, 2.0, 3.0),
            radius: 0.5
        }
    );
    assert!(close(
        o.transform.point(DVec3::ZERO),
        DVec3::new(2.0, 0.0, 0.0)
    ));
    let tex = o.texture.as_ref().expect("texture");
    assert_eq!(
        tex.pigment.kind,
        PigmentKind::Solid(Colour::rgb(1.0, 0.0, 0.0))
    );
    // The pigment was attached before the translate, so it moves with the object.
    assert!(close(
        tex.pigment.transform.point(DVec3::ZERO),
        DVec3::new(2.0, 0.0, 0.0)
    ));
}

#[test]
fn texture_after_transform_does_not_move() {
    let s = load("sphere { 0, 1 scale 2 pigment { rgb 1 } }").scene;
    let tex = s.objects[0].texture.as_ref().expect("texture");
    assert!(tex.pigment.transform.is_identity());
    assert!(close(
        s.objects[0].transform.point(DVec3::X),
        DVec3::new(2.0, 0.0, 0.0)
    ));
}

#[test]
fn expressions_follow_precedence() {
    let s = load(
        "#declare A = 1 + 2 * 3 - -4 / 2;\n\
         #declare V = <1,2,3> * 2 + 1;\n\
         #declare L = vlength(<3,4,0>);\n\
         #declare M = max(1, 5, 3) + min(2, -1) + pow(2, 10) + abs(-2) + sqrt(16);\n\
         #declare C = vcross(x, y);\n\
         #declare D = vdot(<1,2,3>, <4,5,6>) + degrees(pi) + radians(180);\n\
         sphere { V, A pigment { rgb <L, M, D> } }\n\
         sphere { C, (2 < 3) + (3 = 3) + (1 & 0) + (1 | 0) + (0 ? 5 : 7) }",
    )
    .scene;
    match &s.objects[0].shape {
        Shape::Sphere { center, radius } => {
            assert_eq!(*radius, 9.0);
            assert_eq!(*center, DVec3::new(3.0, 5.0, 7.0));
        }
        other => panic!("{other:?}"),
    }
    let PigmentKind::Solid(c) = &s.objects[0].texture.as_ref().expect("t").pigment.kind else {
        panic!()
    };
    assert_eq!(c.rgb.x, 5.0);
    assert_eq!(c.rgb.y, 5.0 - 1.0 + 1024.0 + 2.0 + 4.0);
    assert!((c.rgb.z - (32.0 + 180.0 + std::f64::consts::PI)).abs() < 1e-9);
    match &s.objects[1].shape {
        Shape::Sphere { center, radius } => {
            assert_eq!(*center, DVec3::Z);
            assert_eq!(*radius, 1.0 + 1.0 + 0.0 + 1.0 + 7.0);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn colour_forms_and_arithmetic() {
    let s = load(
        "#declare White = rgb 1;\n\
         #declare Clear = rgbf 1;\n\
         background { White * 0.3 }\n\
         plane { y, 0 pigment { color red 1 green 0.5 blue 0.2 filter 0.1 transmit 0.3 } }\n\
         plane { y, 0 pigment { rgbft <1,2,3,4,5> } }\n\
         plane { y, 0 pigment { Clear } }\n\
         plane { y, 0 pigment { color rgb 1 * 0.5 } }\n\
         plane { y, 0 pigment { color <1,0,0,0.5> } }\n\
         plane { y, 0 pigment { rgbt <1,1,1,0.25> } }",
    )
    .scene;
    assert!(close(s.background.rgb, DVec3::splat(0.3)));
    let colours: Vec<Colour> = s
        .objects
        .iter()
        .map(
            |o| match &o.texture.as_ref().expect("texture").pigment.kind {
                PigmentKind::Solid(c) => *c,
                other => panic!("{other:?}"),
            },
        )
        .collect();
    assert_eq!(
        colours[0],
        Colour {
            rgb: DVec3::new(1.0, 0.5, 0.2),
            filter: 0.1,
            transmit: 0.3
        }
    );
    assert_eq!(
        colours[1],
        Colour {
            rgb: DVec3::new(1.0, 2.0, 3.0),
            filter: 4.0,
            transmit: 5.0
        }
    );
    assert_eq!(
        colours[2],
        Colour {
            rgb: DVec3::ONE,
            filter: 1.0,
            transmit: 0.0
        }
    );
    assert_eq!(colours[3], Colour::rgb(0.5, 0.5, 0.5));
    assert_eq!(colours[4].filter, 0.5);
    assert_eq!(colours[5].transmit, 0.25);
    assert_eq!(colours[5].filter, 0.0);
}

#[test]
fn camera_look_at_and_right_from_image_size() {
    let options = LoadOptions {
        image_width: 640,
        image_height: 480,
        ..LoadOptions::default()
    };
    let l = load_scene_source(
        "cam.pov",
        "camera { location <0, 0, -5> right x*image_width/image_height look_at <0,0,0> }",
        &options,
    )
    .expect("loads");
    let c = &l.scene.camera;
    assert!(close(c.location, DVec3::new(0.0, 0.0, -5.0)));
    assert!(close(c.direction, DVec3::Z));
    assert!(close(c.right, DVec3::new(640.0 / 480.0, 0.0, 0.0)));
    assert!(close(c.up, DVec3::Y));

    let c = load("camera { location <0,0,-1> look_at <1,0,-1> angle 90 }")
        .scene
        .camera;
    // Looking along +x: the direction turns, its length set by the 90 degree angle.
    assert!(close(c.direction.normalize(), DVec3::X));
    assert!((c.direction.length() - 0.5 * 1.33).abs() < 1e-9);
    assert!(close(c.right.normalize(), DVec3::new(0.0, 0.0, -1.0)));
}

#[test]
fn lights_area_spot_and_transforms() {
    let s = load(
        "light_source { <1,2,3>, color rgb <1,0.5,0.25> translate <1,0,0> }\n\
         light_source { <0,10,0> rgb 1 spotlight point_at <0,0,0> radius 10 falloff 20 tightness 5 }\n\
         light_source { <0,10,0> 1 area_light <1,0,0>, <0,0,1>, 5, 3 adaptive 1 jitter circular orient\n\
           fade_distance 2 fade_power 2 shadowless area_illumination on }\n\
         light_source { <0,10,0> 1 parallel point_at <0,0,1> translate y }",
    )
    .scene;
    assert_eq!(s.lights.len(), 4);
    assert_eq!(s.lights[0].location, DVec3::new(2.0, 2.0, 3.0));
    assert_eq!(s.lights[0].colour, DVec3::new(1.0, 0.5, 0.25));
    assert_eq!(
        s.lights[1].kind,
        LightKind::Spot {
            point_at: DVec3::ZERO,
            radius: 10.0,
            falloff: 20.0,
            tightness: 5.0
        }
    );
    let a = s.lights[2].area.expect("area light");
    assert_eq!((a.size1, a.size2, a.adaptive), (5, 3, Some(1)));
    assert!(a.jitter && a.circular && a.orient);
    assert!(s.lights[2].shadowless && s.lights[2].area_illumination);
    assert_eq!(
        (s.lights[2].fade_distance, s.lights[2].fade_power),
        (2.0, 2.0)
    );
    assert_eq!(
        s.lights[3].kind,
        LightKind::Parallel {
            point_at: DVec3::new(0.0, 1.0, 1.0)
        }
    );
    assert_eq!(s.lights[3].location, DVec3::new(0.0, 11.0, 0.0));
}

#[test]
fn finish_values_and_albedo() {
    let s = load(
        "#declare F = finish { ambient 0.2 diffuse albedo 0.5 brilliance 3 phong albedo 1 phong_size 9\n\
           specular 0.3 roughness 0.01 metallic reflection { 0.1, 0.8 falloff 2 fresnel exponent 2 metallic 0.5 }\n\
           conserve_energy emission rgb <1,2,3> }\n\
         sphere { 0, 1 finish { F reflection_exponent 3 } }\n\
         sphere { 0, 1 finish { reflection 0.5 specular albedo 1 roughness 0.5 } }\n\
         sphere { 0, 1 finish { reflection { 0.7 fresnel } } }",
    )
    .scene;
    let f = s.objects[0].texture.as_ref().expect("t").finish;
    assert_eq!(f.ambient, DVec3::splat(0.2));
    assert_eq!(f.emission, DVec3::new(1.0, 2.0, 3.0));
    assert_eq!(f.diffuse, 0.5 * 4.0 / 2.0);
    assert_eq!(f.phong, 1.0 * 10.0 / 2.0);
    assert_eq!(f.specular, 0.3);
    assert_eq!(f.metallic, 1.0);
    assert_eq!(f.reflection.min, DVec3::splat(0.1));
    assert_eq!(f.reflection.max, DVec3::splat(0.8));
    assert_eq!(f.reflection.falloff, 2.0);
    assert!(f.reflection.fresnel);
    assert_eq!(f.reflection.metallic, 0.5);
    assert_eq!(f.reflection.exponent, 3.0);
    assert!(f.conserve_energy);
    let f = s.objects[1].texture.as_ref().expect("t").finish;
    assert_eq!(f.reflection.min, DVec3::splat(0.5));
    let e: f64 = 2.0;
    assert!((f.specular - (e + 2.0) / (4.0 * (2.0 - 2f64.powf(-e / 2.0)))).abs() < 1e-12);
    let f = s.objects[2].texture.as_ref().expect("t").finish;
    assert_eq!(f.reflection.min, DVec3::ZERO);
    assert_eq!(f.reflection.max, DVec3::splat(0.7));
}

#[test]
fn union_children_keep_no_texture_and_move_together() {
    let s = load(
        "#declare U = union { sphere { 0, 1 } sphere { x, 1 pigment { rgb 1 } } pigment { rgb <1,0,0> } }\n\
         object { U translate y no_shadow }",
    )
    .scene;
    let o = &s.objects[0];
    assert!(o.flags.no_shadow);
    let Shape::Union(children) = &o.shape else {
        panic!()
    };
    assert_eq!(children[0].texture, None);
    assert!(children[1].texture.is_some());
    assert!(close(children[0].transform.point(DVec3::ZERO), DVec3::Y));
    assert!(close(o.transform.point(DVec3::ZERO), DVec3::Y));
    assert!(close(
        o.texture
            .as_ref()
            .expect("t")
            .pigment
            .transform
            .point(DVec3::ZERO),
        DVec3::Y
    ));
}

#[test]
fn checker_defaults_and_entries() {
    let s = load(
        "plane { y, -1 pigment { checker } }\n\
         plane { <0,2,0>, 1 pigment { checker color rgb 1, pigment { rgb 0.5 } scale 2 } }",
    )
    .scene;
    let PigmentKind::List { entries, .. } = &s.objects[0].texture.as_ref().expect("t").pigment.kind
    else {
        panic!()
    };
    assert_eq!(
        entries[0].kind,
        PigmentKind::Solid(Colour::rgb(0.0, 0.0, 1.0))
    );
    assert_eq!(
        entries[1].kind,
        PigmentKind::Solid(Colour::rgb(0.0, 1.0, 0.0))
    );
    let p = &s.objects[1].texture.as_ref().expect("t").pigment;
    let PigmentKind::List { entries, .. } = &p.kind else {
        panic!()
    };
    assert_eq!(
        entries[1].kind,
        PigmentKind::Solid(Colour::rgb(0.5, 0.5, 0.5))
    );
    assert!(close(
        p.transform.point(DVec3::X),
        DVec3::new(2.0, 0.0, 0.0)
    ));
    assert_eq!(
        s.objects[1].shape,
        Shape::Plane {
            normal: DVec3::Y,
            distance: 1.0
        }
    );
}

#[test]
fn declared_textures_are_copied_then_modified() {
    let s = load(
        "#declare T = texture { pigment { rgb 1 } finish { phong 1 } }\n\
         sphere { 0, 1 texture { T finish { phong 0.5 } } }\n\
         sphere { 0, 1 texture { T } }\n\
         #declare P = pigment { rgb <0,1,0> }\n\
         box { -1, 1 pigment { P scale 3 } }",
    )
    .scene;
    assert_eq!(s.objects[0].texture.as_ref().expect("t").finish.phong, 0.5);
    assert_eq!(s.objects[1].texture.as_ref().expect("t").finish.phong, 1.0);
    let p = &s.objects[2].texture.as_ref().expect("t").pigment;
    assert_eq!(p.kind, PigmentKind::Solid(Colour::rgb(0.0, 1.0, 0.0)));
    assert!(close(
        p.transform.point(DVec3::X),
        DVec3::new(3.0, 0.0, 0.0)
    ));
}

#[test]
fn global_settings_version_and_background() {
    let s = load(
        "#version 3.6;\n\
         global_settings { assumed_gamma 1.0 max_trace_level 10 adc_bailout 0 ambient_light rgb <1,0.5,0.5> }\n\
         background { rgb <0.1, 0.2, 0.3> }",
    )
    .scene;
    assert_eq!(s.version, 3.6);
    assert!(s.legacy());
    assert_eq!(s.settings.assumed_gamma, Some(1.0));
    assert_eq!(s.settings.max_trace_level, 10);
    assert_eq!(s.settings.adc_bailout, 0.0);
    assert_eq!(s.settings.ambient_light, DVec3::new(1.0, 0.5, 0.5));
    assert_eq!(s.background.rgb, DVec3::new(0.1, 0.2, 0.3));
}

#[test]
fn flags_and_transforms() {
    let s = load(
        "sphere { 0, 1 hollow no_image no_reflection double_illuminate inverse rotate y*90 scale <1,2,3> }",
    )
    .scene;
    let o = &s.objects[0];
    assert!(o.flags.hollow && o.flags.no_image && o.flags.no_reflection);
    assert!(o.flags.double_illuminate && o.flags.inverse);
    // rotate y*90 takes +x to -z, then the scale stretches z by 3.
    assert!(close(
        o.transform.point(DVec3::X),
        DVec3::new(0.0, 0.0, -3.0)
    ));
}

#[test]
fn command_line_declares_and_flow_control() {
    let options = LoadOptions {
        declares: vec![("Quality".into(), 2.0)],
        ..LoadOptions::default()
    };
    let l = load_scene_source(
        "flow.pov",
        "#if (Quality > 1) #declare R = 2; #else #declare R = 1; #end\n\
         #declare I = 0;\n\
         #while (I < 3) sphere { <I,0,0>, R } #declare I = I + 1; #end\n\
         #for (J, 1, 2) box { -J, J } #end\n\
         #switch (I) #case (2) #declare S = 2; #break #case (3) #declare S = 3; #break #else #declare S = 0; #end\n\
         #ifdef (S) sphere { 0, S } #end #ifndef (Nope) plane { y, 0 } #end",
        &options,
    )
    .expect("loads");
    let s = l.scene;
    assert_eq!(s.objects.len(), 3 + 2 + 2);
    assert_eq!(
        s.objects[2].shape,
        Shape::Sphere {
            center: DVec3::new(2.0, 0.0, 0.0),
            radius: 2.0
        }
    );
    assert_eq!(
        s.objects[4].shape,
        Shape::Box {
            corner1: DVec3::splat(-2.0),
            corner2: DVec3::splat(2.0)
        }
    );
    assert_eq!(
        s.objects[5].shape,
        Shape::Sphere {
            center: DVec3::ZERO,
            radius: 3.0
        }
    );
}

#[test]
fn macros_at_item_level_and_in_expressions() {
    let s = load(
        "#macro Ball(P, R) sphere { P, R } #end\n\
         #macro Twice(V) (V * 2) #end\n\
         #macro Inc(N) #declare N = N + 1; #end\n\
         #macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n\
         #declare K = 1; Inc(K) Inc(K)\n\
         Ball(<1,0,0>, Twice(3))\n\
         Ball(0, K)\n\
         sphere { 0, Fact(5) }",
    )
    .scene;
    let radii: Vec<f64> = s
        .objects
        .iter()
        .map(|o| match o.shape {
            Shape::Sphere { radius, .. } => radius,
            _ => f64::NAN,
        })
        .collect();
    assert_eq!(radii, vec![6.0, 3.0, 120.0]);
}

#[test]
fn includes_are_searched_and_chained_in_errors() {
    let mut world = MemoryFiles::default();
    world.files.insert(
        PathBuf::from("inc/colours.inc"),
        "#declare Red = rgb <1,0,0>;\n#declare Bad = <1,2;\n".into(),
    );
    world.files.insert(
        PathBuf::from("inc/good.inc"),
        "#declare Red = rgb <1,0,0>;\n".into(),
    );
    let options = LoadOptions {
        include_paths: vec![PathBuf::from("inc")],
        ..LoadOptions::default()
    };
    let l = load_with_files(
        "main.pov",
        "#include \"good.inc\"\nsphere { 0, 1 pigment { Red } }",
        &options,
        &world,
    )
    .expect("loads");
    assert_eq!(
        l.scene.objects[0].texture.as_ref().expect("t").pigment.kind,
        PigmentKind::Solid(Colour::rgb(1.0, 0.0, 0.0))
    );
    let e = load_with_files("main.pov", "\n#include \"colours.inc\"\n", &options, &world)
        .expect_err("bad include");
    assert_eq!(
        e.to_string(),
        "error: expected `>` to close the vector, found `;`\n \
         --> inc/colours.inc:2:20\n  \
         |\n\
         2 | #declare Bad = <1,2;\n  \
         |                    ^\n  \
         = note: in file `inc/colours.inc` included here at main.pov:2:1"
    );
}

#[test]
fn arrays() {
    let s = load(
        "#declare A = array[3] { 1, 2, 3 };\n\
         #declare A[1] = 5;\n\
         #declare B = array[2][2] { {1, 2}, {3, 4} }\n\
         sphere { 0, A[1] + A[2] + B[1][0] }",
    )
    .scene;
    assert_eq!(
        s.objects[0].shape,
        Shape::Sphere {
            center: DVec3::ZERO,
            radius: 11.0
        }
    );
}

// ---- Golden diagnostics: exact message, line and column. ----

#[test]
fn golden_missing_close_brace() {
    let e =
        error("sphere { <0,0,0>, 1\n    pigment { rgb 1 }\n\n    camera { location <0,1,-3> }\n");
    assert_eq!(
        e.to_string(),
        "error: expected `}` to close the sphere, found `camera`\n \
         --> test.pov:4:5\n  \
         |\n\
         4 |     camera { location <0,1,-3> }\n  \
         |     ^^^^^^"
    );
}

#[test]
fn golden_unknown_identifier_with_hint() {
    let e = error("#declare Foo = 1;\nsphere { 0, Fo0 }");
    assert_eq!(e.message, "unknown identifier `Fo0`");
    assert_eq!((e.line(), e.column()), (Some(2), Some(13)));
    assert_eq!(e.hints, vec!["did you mean `Foo`?".to_string()]);
    assert!(
        e.to_string().ends_with("= help: did you mean `Foo`?"),
        "{e}"
    );
}

#[test]
fn golden_unsupported_feature() {
    let e = error("#version 3.7;\n\nlathe { 0, y, 1 }");
    assert_eq!(e.message, "unsupported: `lathe` is not supported yet");
    assert_eq!((e.line(), e.column()), (Some(3), Some(1)));
    let e = error("sphere { 0, 1 normal { crackle 0.5 } }");
    assert_eq!(e.message, "unsupported: `crackle` is not supported yet");
    assert_eq!((e.line(), e.column()), (Some(1), Some(24)));
}

#[test]
fn golden_zero_scale() {
    let e = error("box { 0, 1\n  scale <1, 0, 1>\n}");
    assert_eq!(e.message, "a scale of <1, 0, 1> has a zero component");
    assert_eq!((e.line(), e.column()), (Some(2), Some(9)));
}

#[test]
fn golden_wrong_type() {
    let e = error("sphere { 0, <1,2,3> }");
    assert_eq!(e.message, "expected a float, found a vector");
    assert_eq!((e.line(), e.column()), (Some(1), Some(13)));
    let d = e.location.as_ref().expect("location");
    assert_eq!(d.width, 7);
}

#[test]
fn golden_macro_trace() {
    let e = error("#macro M(A)\n  sphere { 0, A pigment { Nope } }\n#end\nM(1)\n");
    assert_eq!(e.message, "unknown identifier `Nope`");
    assert_eq!((e.line(), e.column()), (Some(2), Some(27)));
    assert!(
        e.to_string()
            .ends_with("= note: in macro `M` called here at test.pov:4:1"),
        "{e}"
    );
}

#[test]
fn golden_missing_end_and_bad_directive() {
    let e = error("#if (1)\nsphere { 0, 1 }\n");
    assert_eq!(e.message, "this `#if` has no `#end`");
    assert_eq!((e.line(), e.column()), (Some(1), Some(1)));
    let e = error("\n  #frobnicate 3");
    assert_eq!(e.message, "unknown directive `#frobnicate`");
    assert_eq!((e.line(), e.column()), (Some(2), Some(3)));
    let e = error("sphere { 0, 1 / 0 }");
    assert_eq!(e.message, "division by zero");
}

#[test]
fn golden_end_of_file() {
    let e = error("sphere { 0, 1");
    assert_eq!(
        e.message,
        "expected `}` to close the sphere, found end of file"
    );
    assert_eq!((e.line(), e.column()), (Some(1), Some(14)));
}

#[test]
fn nesting_and_loops_are_limited() {
    let deep = format!(
        "#declare A = {}1{};",
        "(".repeat(10_000),
        ")".repeat(10_000)
    );
    assert!(error(&deep).message.contains("nesting is too deep"));
    let e = error("#macro R() R() #end R()");
    assert!(e.message.contains("too deeply"), "{e}");
    let e = error("#while (1) #end");
    assert!(e.message.contains("too many loop iterations"), "{e}");
}

mod garbage {
    use super::*;
    use proptest::prelude::*;

    const SAMPLE: &str = "#version 3.7;\n#declare C = rgb <1,0.5,0>;\n\
        #macro M(A) sphere { 0, A pigment { C } } #end\n\
        camera { location <0,1,-3> look_at 0 angle 60 }\n\
        light_source { <1,2,3>, 1 area_light x, z, 3, 3 }\n\
        #for (I, 0, 2) M(I + 1) #end\n\
        union { box { -1, 1 } sphere { y, 0.5 finish { phong 1 } } scale 2 }\n\
        plane { y, 0 pigment { checker rgb 1, rgb 0 } }";

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn random_text_never_panics(s in "[ -~\\n]{0,200}") {
            let _ = load_scene_source("g.pov", &s, &LoadOptions::default());
        }

        #[test]
        fn token_soup_never_panics(words in proptest::collection::vec(
            prop_oneof![
                Just("sphere"), Just("{"), Just("}"), Just("<"), Just(">"), Just(","),
                Just("1"), Just("#declare"), Just("X"), Just("="), Just("#if"), Just("#end"),
                Just("#while"), Just("("), Just(")"), Just("#macro"), Just("union"),
                Just("pigment"), Just("rgb"), Just("scale"), Just("0"), Just("X()"),
                Just(";"), Just("#else"), Just("checker"), Just("."), Just("x"),
                Just("cylinder"), Just("cone"), Just("mesh"), Just("triangle"),
                Just("polygon"), Just("difference"), Just("clipped_by"), Just("bounded_by"),
                Just("disc"), Just("torus"), Just("open"), Just("blob"), Just("array"),
                Just("["), Just("]"), Just("object"), Just("seed"), Just("rand"),
            ], 0..60)) {
            let s = words.join(" ");
            let _ = load_scene_source("g.pov", &s, &LoadOptions::default());
        }

        #[test]
        fn truncated_scenes_never_panic(n in 0usize..SAMPLE.len()) {
            let _ = load_scene_source("t.pov", &SAMPLE[..n], &LoadOptions::default());
        }
    }

    #[test]
    fn sample_scene_loads() {
        let s = load(SAMPLE).scene;
        assert_eq!(s.objects.len(), 5);
        assert_eq!(s.lights.len(), 1);
    }
}

/// Reads POV-Ray's example scenes listed in /work/shared/corpus-in-scope.txt and prints the
/// first error of each; run by hand with `--ignored --nocapture` to see what is missing.
#[test]
#[ignore]
fn corpus_report() {
    let list = std::fs::read_to_string("/work/shared/corpus-in-scope.txt").unwrap_or_default();
    let (mut ok, mut total) = (0, 0);
    for line in list
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        total += 1;
        let path = PathBuf::from("/usr/share/povray-3.7/scenes").join(line.trim());
        match load_scene(&path, &LoadOptions::default()) {
            Ok(_) => ok += 1,
            Err(e) => println!(
                "{line}: {}",
                e.to_string().lines().take(2).collect::<Vec<_>>().join(" ")
            ),
        }
    }
    println!("{ok} of {total} scenes load");
}

/// Every example scene POV-Ray ships: prints the errors that are not "unsupported", which
/// point at gaps or bugs in the language itself.
#[test]
#[ignore]
fn all_scenes_report() {
    fn walk(dir: &std::path::Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "pov") {
                out.push(p);
            }
        }
    }
    let mut files = Vec::new();
    walk(
        std::path::Path::new("/usr/share/povray-3.7/scenes"),
        &mut files,
    );
    files.sort();
    let (mut ok, mut unsupported) = (0, 0);
    for f in &files {
        match load_scene(f, &LoadOptions::default()) {
            Ok(_) => ok += 1,
            Err(e) if e.message.starts_with("unsupported") => unsupported += 1,
            Err(e) => println!(
                "{}",
                e.to_string().lines().take(2).collect::<Vec<_>>().join(" ")
            ),
        }
    }
    println!(
        "{} scenes: {ok} load, {unsupported} need unsupported features",
        files.len()
    );
}

/// Values checked against POV-Ray 3.7's own `#debug` output for the same expressions.
#[test]
fn builtins_match_povray() {
    let s = load(
        "#macro Check(Got, Want) #if (vlength(Got - Want) > 1e-4) #error concat(\"got \", vstr(3, Got, \",\", 0, 4)) #end #end\n\
         Check(vaxis_rotate(<1,0,0>, <0,1,0>, 90), <0,0,-1>)\n\
         Check(vrotate(<1,0,0>, <0,90,0>), <0,0,-1>)\n\
         Check(vaxis_rotate(<0,1,0>, <1,1,0>, 30), <0.0670,0.9330,0.3536>)\n\
         Check(vrotate(<0,1,0>, <30,20,10>), <0.0180,0.8826,0.4698>)\n\
         Check(<mod(-7, 3), div(-7, 2), int(-2.5)>, <-1, -3, -2>)\n\
         Check(log(100), 2)\n\
         #if (strcmp(str(3.14159, -8, 2), \"00003.14\") != 0) #error \"str\" #end\n\
         #if (strcmp(str(2, 5, -1), \"2.000000\") != 0) #error \"str 2\" #end\n\
         #if (strcmp(concat(\"a\", chr(66), substr(\"xcdx\", 2, 2)), \"aBcd\") != 0) #error \"concat\" #end\n\
         sphere { 0, 1 }",
    );
    assert_eq!(s.scene.objects.len(), 1);
    assert!(s.warnings.is_empty());
}

/// Mutated copies of POV-Ray's example scenes: the reader must fail cleanly, never crash.
/// Run by hand with `--ignored`.
#[test]
#[ignore]
fn fuzz_example_scenes() {
    let list = std::fs::read_to_string("/work/shared/corpus-in-scope.txt").unwrap_or_default();
    let mut state = 0x1234_5678_u64;
    let mut rand = move |n: usize| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) as usize) % n.max(1)
    };
    let mut crashes = Vec::new();
    let mut runs = 0usize;
    for line in list
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let path = PathBuf::from("/usr/share/povray-3.7/scenes").join(line.trim());
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        for _ in 0..20 {
            let mut bytes = text.clone().into_bytes();
            for _ in 0..1 + rand(5) {
                let at = rand(bytes.len());
                match rand(3) {
                    0 => {
                        let end = (at + rand(40)).min(bytes.len());
                        bytes.drain(at..end);
                    }
                    1 => bytes.truncate(at),
                    _ => {
                        let c = b"{}<>()#,;=-+*/\"x0"[rand(17)];
                        bytes.insert(at, c);
                    }
                }
            }
            let mutated = String::from_utf8_lossy(&bytes).into_owned();
            runs += 1;
            if let Err(e) = load_inner(
                &path.display().to_string(),
                &mutated,
                &LoadOptions {
                    include_paths: path
                        .parent()
                        .map(|p| vec![p.to_path_buf()])
                        .unwrap_or_default(),
                    ..LoadOptions::default()
                },
                &FileSystem,
                runs.is_multiple_of(2),
            ) && e.message.starts_with("internal error")
            {
                crashes.push(mutated);
            }
        }
    }
    if let Some(first) = crashes.first() {
        std::fs::write("/tmp/penumbra-crash.pov", first).ok();
    }
    eprintln!(
        "fuzz: {runs} mutated scenes, {} ran without a panic",
        runs - crashes.len()
    );
    assert!(
        crashes.is_empty(),
        "{} crashes; first saved to /tmp/penumbra-crash.pov",
        crashes.len()
    );
}

#[test]
fn golden_two_digit_line_and_typo_of_keyword() {
    let src = format!("{}sphree {{ 0, 1 }}\n", "\n".repeat(11));
    let e = error(&src);
    assert_eq!(
        e.to_string(),
        "error: unknown identifier `sphree`\n  \
         --> test.pov:12:1\n   \
         |\n\
         12 | sphree { 0, 1 }\n   \
         | ^^^^^^\n   \
         = help: did you mean `sphere`?"
    );
}

#[test]
fn unsupported_declarations_fail_only_when_used() {
    // Include files declare many things a scene never uses.
    let l = load(
        "#declare Marble = texture { pigment { marble color_map { [0 rgb 0] [1 rgb 1] } } }\n\
         #declare Layered = texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } }\n\
         #declare Q = quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 }\n\
         sphere { 0, 1 }",
    );
    assert_eq!(l.scene.objects.len(), 1);
    let e = error(
        "#declare Marble = texture { pigment { crackle } }\n\
         sphere { 0, 1 texture { Marble } }",
    );
    assert_eq!(e.message, "unsupported: `crackle` is not supported yet");
    assert_eq!((e.line(), e.column()), (Some(2), Some(25)));
    assert!(
        e.to_string()
            .contains("`Marble` was declared with it at test.pov:1:39"),
        "{e}"
    );
}

#[test]
fn default_texture_applies_to_new_textures() {
    let s = load(
        "#default { finish { ambient 0 diffuse 0.8 } }\n\
         sphere { 0, 1 }\n\
         sphere { 0, 1 pigment { rgb 1 } }",
    )
    .scene;
    for o in &s.objects {
        let f = o.texture.as_ref().expect("texture").finish;
        assert_eq!((f.ambient, f.diffuse), (DVec3::ZERO, 0.8));
    }
}

#[test]
fn declarations_without_semicolons_finish_before_the_next_directive() {
    let s = load(
        "#declare I = 0\n\
         #while (I < 3)\n\
           sphere { <I, 0, 0>, 1 }\n\
           #declare I = I + 1\n\
         #end\n\
         #declare C = rgb <1, 0, 0>\n\
         #declare D = C\n\
         #declare A = array[2]\n\
         #declare A[0] = 5\n\
         sphere { 0, A[0] pigment { D } }",
    )
    .scene;
    assert_eq!(s.objects.len(), 4);
    assert_eq!(
        s.objects[3].texture.as_ref().expect("t").pigment.kind,
        PigmentKind::Solid(Colour::rgb(1.0, 0.0, 0.0))
    );
}

#[test]
fn diagnostics_can_cross_threads() {
    fn assert_send_sync<T: Send + Sync + std::error::Error>() {}
    assert_send_sync::<Diagnostic>();
}

#[test]
fn warning_and_error_directives() {
    let l = load("#warning \"careful\"\nsphere { 0, 1 }");
    assert_eq!(l.warnings.len(), 1);
    assert_eq!(l.warnings[0].severity, Severity::Warning);
    assert!(
        l.warnings[0]
            .to_string()
            .starts_with("warning: careful\n --> test.pov:1:1")
    );
    let e = error("#declare N = 3;\n#if (N > 2) #error concat(\"too many: \", str(N, 0, 0)) #end");
    assert_eq!(e.message, "#error: too many: 3");
    assert_eq!((e.line(), e.column()), (Some(2), Some(13)));
}

fn load_skipping(src: &str) -> Loaded {
    match load_inner(
        "test.pov",
        src,
        &LoadOptions::default(),
        &MemoryFiles::default(),
        true,
    ) {
        Ok(l) => l,
        Err(e) => panic!("unexpected error:\n{e}"),
    }
}

#[test]
fn all_model_shapes_read() {
    let s = load(
        "cylinder { 0, y, 1 open }
         cone { 0, 1, y*2, 0.5 }
         disc { x, y*2, 1, 0.5 }
         torus { 2, 0.5 sturm }
         quadric { <1,1,1>, 0, 0, -1 }
         triangle { 0, x, y }
         smooth_triangle { 0, z, x, z, y, z }
         mesh { triangle { 0, x, y } triangle { 0, x, 2*x } inside_vector z }
         polygon { 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,0> }",
    )
    .scene;
    let shapes: Vec<&Shape> = s.objects.iter().map(|o| &o.shape).collect();
    assert_eq!(
        shapes[0],
        &Shape::Cylinder {
            base: DVec3::ZERO,
            cap: DVec3::Y,
            radius: 1.0,
            open: true
        }
    );
    assert_eq!(
        shapes[1],
        &Shape::Cone {
            base: DVec3::ZERO,
            base_radius: 1.0,
            cap: DVec3::new(0.0, 2.0, 0.0),
            cap_radius: 0.5,
            open: false
        }
    );
    assert_eq!(
        shapes[2],
        &Shape::Disc {
            center: DVec3::X,
            normal: DVec3::Y,
            radius: 1.0,
            hole_radius: 0.5
        }
    );
    assert_eq!(
        shapes[3],
        &Shape::Torus {
            major: 2.0,
            minor: 0.5
        }
    );
    assert_eq!(
        shapes[4],
        &Shape::Quadric {
            coefficients: [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]
        }
    );
    assert!(matches!(shapes[5], Shape::Triangle { corners } if corners[1] == DVec3::X));
    assert!(matches!(shapes[6], Shape::SmoothTriangle { normals, .. } if normals[2] == DVec3::Z));
    match shapes[7] {
        // The degenerate triangle is dropped silently, as POV-Ray does in meshes.
        Shape::Mesh(m) => {
            assert_eq!(m.triangles.len(), 1);
            assert_eq!(m.inside_vector, Some(DVec3::Z));
        }
        other => panic!("expected a mesh, got {other:?}"),
    }
    match shapes[8] {
        Shape::Polygon { points } => {
            assert_eq!(points.len(), 5);
            assert_eq!(points[2], DVec3::new(1.0, 1.0, 0.0));
        }
        other => panic!("expected a polygon, got {other:?}"),
    }
}

#[test]
fn csg_kinds_flags_and_clipping() {
    let s = load(
        "#declare B = box { -1, 1 }
         difference { object { B } sphere { 0, 1.2 } inverse no_image }
         intersection { sphere { 0, 1 } sphere { x, 1 } clipped_by { plane { y, 0 } } translate y }
         merge { sphere { 0, 1 } sphere { x, 1 } hollow no_reflection double_illuminate }
         sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }",
    )
    .scene;
    assert!(matches!(&s.objects[0].shape, Shape::Difference(c) if c.len() == 2));
    assert!(s.objects[0].flags.inverse && s.objects[0].flags.no_image);
    let clip = &s.objects[1].clipped_by;
    assert_eq!(clip.len(), 1);
    // The later translate moves the clipping plane too.
    assert!(close(clip[0].transform.point(DVec3::ZERO), DVec3::Y));
    assert!(matches!(&s.objects[2].shape, Shape::Merge(c) if c.len() == 2));
    let f = s.objects[2].flags;
    assert!(f.hollow && f.no_reflection && f.double_illuminate && !f.no_shadow);
    assert!(matches!(
        &s.objects[3].clipped_by[0].shape,
        Shape::Box { .. }
    ));
}

#[test]
fn degenerate_shapes_as_povray_treats_them() {
    let l = load("triangle { 0, x, 2*x } union { triangle { 0, y, 2*y } sphere { 0, 1 } }");
    assert_eq!(l.scene.objects.len(), 1);
    assert_eq!(l.warnings.len(), 2);
    assert_eq!(l.warnings[0].message, "degenerate triangle; it is left out");
    let e = error("sphere { 0, 1 }\n  cylinder { y, y, 1 }");
    assert_eq!(
        e.message,
        "degenerate cylinder: the base point equals the cap point"
    );
    assert_eq!(
        e.location.as_ref().map(|l| (l.line, l.column)),
        Some((2, 3))
    );
    let e = error("polygon { 2, 0, x }");
    assert!(e.message.contains("at least three points"), "{}", e.message);
    let e = error("mesh { triangle { 0, x, 2*x } }");
    assert!(e.message.contains("no (non-degenerate) triangles"));
    let l = load("difference { sphere { 0, 1 } }");
    assert!(l.warnings[0].message.contains("at least 2 objects"));
}

#[test]
fn skip_unsupported_leaves_features_out() {
    let src = "blob { threshold 0.5 sphere { 0, 1, 1 } }
               fog { distance 3 color rgb 1 }
               #declare T = text { ttf \"a.ttf\" \"x\" 1, 0 }
               object { T translate x }
               union { sphere { 0, 1 } lathe { linear_spline 2, <0,0>, <1,1> } }
               sphere { 0, 1 photons { target } }";
    let e = error(src);
    assert!(e.message.starts_with("unsupported: `blob`"));
    let l = load_skipping(src);
    assert_eq!(l.scene.objects.len(), 2);
    assert!(
        l.warnings
            .iter()
            .all(|w| w.message.contains("not supported")),
        "{:?}",
        l.warnings
    );
    assert_eq!(l.warnings.len(), 5);
}

#[test]
fn matrix_and_inverse_transform() {
    let s = load(
        "#declare T = transform { translate <1,2,3> scale 2 }
         sphere { 0, 1 transform { T inverse } }
         sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 4,5,6> }",
    )
    .scene;
    assert!(close(
        s.objects[0].transform.point(DVec3::new(2.0, 4.0, 6.0)),
        DVec3::ZERO
    ));
    assert!(close(
        s.objects[1].transform.point(DVec3::ZERO),
        DVec3::new(4.0, 5.0, 6.0)
    ));
}

/// Expected values printed by POV-Ray 3.7.0.10 with `#debug str(rand(S), 0, 10)`.
#[test]
fn rand_matches_povray() {
    let cases: [(&str, [f64; 3]); 5] = [
        ("0", [0.0000028743, 0.4665636845, 0.2490702288]),
        ("12345", [0.4665636845, 0.2490702288, 0.9658760421]),
        ("-7", [0.0460728682, 0.3226610886, 0.3312883220]),
        ("2.7", [0.8439828762, 0.5076787119, 0.0827222022]),
        ("4000000000", [0.5000028744, 0.9665636846, 0.7490702290]),
    ];
    for (seed, expected) in cases {
        let src = format!(
            "#declare S = seed({seed});
             #declare A = rand(S); #declare B = rand(S); #declare C = rand(S);
             sphere {{ <A, B, C>, 1 }}"
        );
        let s = load(&src).scene;
        let Shape::Sphere { center, .. } = s.objects[0].shape else {
            panic!("expected a sphere");
        };
        for (got, want) in center.to_array().into_iter().zip(expected) {
            assert!((got - want).abs() < 6e-11, "seed {seed}: {got} vs {want}");
        }
    }
}

#[test]
fn array_dimensions() {
    let s = load(
        "#declare A = array[3][4];
         #declare B = array[2] { 5, 6 }
         sphere { <dimensions(A), dimension_size(A, 2), dimension_size(B, 1)>, B[1] }",
    )
    .scene;
    assert_eq!(
        s.objects[0].shape,
        Shape::Sphere {
            center: DVec3::new(2.0, 4.0, 2.0),
            radius: 6.0
        }
    );
    let e = error("#declare A = array[3];\n#declare N = dimension_size(A, 2);");
    assert_eq!(
        e.message,
        "this array has 1 dimensions, asked for dimension 2"
    );
    assert_eq!((e.line(), e.column()), (Some(2), Some(32)));
}

/// The standard include files the issue lists must read without error (declarations that
/// need unsupported features only fail when used).
#[test]
fn standard_includes_read() {
    let dir = std::path::Path::new("/usr/share/povray-3.7/include");
    if !dir.is_dir() {
        return;
    }
    for name in [
        "colors",
        "textures",
        "shapes",
        "shapes2",
        "metals",
        "golds",
        "glass",
        "woods",
        "stones",
        "finish",
        "skies",
        "stdinc",
        "consts",
        "math",
        "transforms",
        "functions",
        "strings",
        "rand",
    ] {
        // shapes2.inc uses shapes.inc's objects without including it; POV-Ray fails too.
        let src = format!(
            "#include \"colors.inc\"\n#include \"shapes.inc\"\n#include \"{name}.inc\"\nsphere {{ 0, 1 }}"
        );
        if let Err(e) = load_scene_source("inc.pov", &src, &LoadOptions::default()) {
            panic!("{name}.inc:\n{e}");
        }
    }
}

fn golden(src: &str, message: &str, line: usize, column: usize) {
    let e = error(src);
    assert_eq!(e.message, message, "for:\n{src}");
    assert_eq!(
        (e.line(), e.column()),
        (Some(line), Some(column)),
        "for:\n{src}"
    );
}

#[test]
fn golden_shapes_and_limits() {
    golden(
        "#version 3.7;\ncone { <0,1,0>, 1, <0,1,0>, 0 }",
        "degenerate cone: the base point equals the cap point",
        2,
        1,
    );
    golden(
        "polygon {\n  2, <0,0>, <1,0>\n}",
        "a polygon needs at least three points, found 2",
        2,
        3,
    );
    golden(
        "mesh { triangle { 0, x, 2*x } }",
        "this mesh has no (non-degenerate) triangles",
        1,
        1,
    );
    golden(
        "#include \"/etc/passwd\"",
        "refused: the include file \"/etc/passwd\" is outside the allowed folders \
         (the scene's folder, --include-path folders, POV-Ray's include folder)",
        1,
        10,
    );
    golden(
        "sphere { 0, 1 }\n#fopen F \"out.txt\" write",
        "unsupported: `#fopen` is refused: a scene may not open, read or write files",
        2,
        1,
    );
    golden(
        "#declare A = array[2];\n#declare B = A[5];",
        "index 5 is outside the array (size 2)",
        2,
        16,
    );
    golden(
        "#macro R(N) R(N+1) #end\nR(0)",
        "macro calls are nested too deeply (more than 256 levels)",
        1,
        13,
    );
    golden(
        "#declare S = seed(1);\n#declare V = rand(S + 3);",
        "`rand` needs a stream made by `seed`",
        2,
        19,
    );
    golden(
        "difference {\n  sphere { 0, 1 }\n  isosurface { function { x } }\n}",
        "unsupported: `isosurface` is not supported yet",
        3,
        3,
    );
}

#[test]
fn materials_and_empty_csg() {
    let s = load(
        "#declare M = material { texture { pigment { rgb 1 } } interior { ior 1.5 } }
         #declare A = array[1] { M }
         sphere { 0, 1 material { A[0] } }
         union { }
         union { #for (I, 1, 0) sphere { 0, 1 } #end pigment { rgb 1 } }",
    )
    .scene;
    assert_eq!(s.objects.len(), 1);
    assert_eq!(s.objects[0].interior.map(|i| i.ior), Some(1.5));
    assert!(s.objects[0].texture.is_some());
}

#[test]
fn uv_mapping_keeps_only_the_transforms_written_inside() {
    // Measured with povray on a sphere: u doubles for A and B, is unchanged for C and D.
    let u_scale = |src: &str| {
        let s = load(src).scene;
        let pig = &s.objects[0].texture.as_ref().unwrap().pigment;
        assert!(pig.uv_mapping, "{src}");
        pig.transform.inverse_point(DVec3::new(0.25, 0.0, 0.0)).x / 0.25
    };
    let a = u_scale("sphere { 0, 1 texture { uv_mapping pigment { gradient x } scale 0.5 } }");
    let b = u_scale("sphere { 0, 1 pigment { uv_mapping gradient x scale 0.5 } }");
    let c = u_scale("sphere { 0, 1 texture { pigment { uv_mapping gradient x } scale 0.5 } }");
    let d = u_scale("sphere { 0, 1 pigment { uv_mapping gradient x } scale 0.5 rotate y*30 }");
    assert!(
        (a - 2.0).abs() < 1e-12 && (b - 2.0).abs() < 1e-12,
        "{a} {b}"
    );
    assert!(
        (c - 1.0).abs() < 1e-12 && (d - 1.0).abs() < 1e-12,
        "{c} {d}"
    );
}

#[test]
fn global_noise_generator_is_the_patterns_default() {
    let s = load(
        "global_settings { noise_generator 3 }
         plane { z, 0 pigment { bozo } }
         plane { z, 0 pigment { bozo noise_generator 1 } }",
    )
    .scene;
    let generator = |i: usize| match &s.objects[i].texture.as_ref().unwrap().pigment.kind {
        PigmentKind::ColourMap { pattern, .. } => pattern.noise_generator,
        _ => panic!("pattern"),
    };
    assert_eq!((generator(0), generator(1)), (3, 1));
}
