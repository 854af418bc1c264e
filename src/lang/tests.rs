//! What cannot be a single scene file under tests/lang/ (which `tests/lang_files.rs` runs):
//! inputs that must never panic, the example-scene walks run by hand, and type checks.

use std::path::PathBuf;

use super::*;

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
fn diagnostics_can_cross_threads() {
    fn assert_send_sync<T: Send + Sync + std::error::Error>() {}
    assert_send_sync::<Diagnostic>();
}

/// An image map takes turbulence and warps like a pattern (POV-Ray's warp1.pov): the
/// transform written before a `warp` joins the warp chain instead of being dropped.
#[test]
fn image_map_keeps_its_warps() {
    use crate::appearance::pigment::evaluate_pigment;
    use crate::scene::{Colour, PigmentKind, Warp};
    use glam::DVec3;
    let dir = crate::study::TempDir::new("image-warps").unwrap();
    let mut img = image::RgbImage::new(2, 1);
    img.put_pixel(0, 0, image::Rgb([255, 0, 0]));
    img.put_pixel(1, 0, image::Rgb([0, 0, 255]));
    img.save(dir.path().join("two.png")).unwrap();
    let source = "plane { z, 0 pigment { image_map { png \"two.png\" } scale 4 \
        warp { turbulence 0 } turbulence 0.3 octaves 3 } }";
    let loaded = load_beside(dir.path(), source);
    let texture = loaded.scene.objects[0].texture.as_ref().expect("a texture");
    let pigment = &texture.pigment;
    let PigmentKind::Image(im) = &pigment.kind else {
        panic!("not an image: {pigment:?}");
    };
    assert!(matches!(
        im.warps[..],
        [Warp::Transform(_), Warp::Turbulence(_)]
    ));
    let t = im.turbulence.expect("classic turbulence kept");
    assert_eq!((t.amount, t.octaves), (DVec3::splat(0.3), 3));
    // x = 3 is 3/4 across the scaled image: the blue pixel.
    let mut plain = pigment.clone();
    if let PigmentKind::Image(im) = &mut plain.kind {
        im.turbulence = None;
    }
    let c = evaluate_pigment(&plain, DVec3::new(3.0, 0.5, 0.0));
    assert_eq!(c, Colour::rgb(0.0, 0.0, 1.0));
}

/// A 3.7 scene sees an image's linear colour whatever its assumed_gamma; an older
/// A scene read as if it were a file in `dir` (whose images it names).
fn load_beside(dir: &std::path::Path, source: &str) -> Loaded {
    let scene_path = dir.join("scene.pov").display().to_string();
    load_inner(
        &scene_path,
        source,
        &LoadOptions::default(),
        &FileSystem,
        false,
    )
    .unwrap()
}

/// The value a 1x1 grey-128 PNG shows at its centre in a scene with `header`, its image
/// block ending with `extra`.
fn grey_128(header: &str, extra: &str) -> f64 {
    use crate::appearance::pigment::evaluate_pigment;
    use glam::DVec3;
    let dir = crate::study::TempDir::new("image-gamma").unwrap();
    image::RgbImage::from_pixel(1, 1, image::Rgb([128, 128, 128]))
        .save(dir.path().join("grey.png"))
        .unwrap();
    let source = format!(
        "{header}\nplane {{ z, 0 pigment {{ image_map {{ png \"grey.png\" {extra} }} }} }}"
    );
    let loaded = load_beside(dir.path(), &source);
    let pigment = &loaded.scene.objects[0].texture.as_ref().unwrap().pigment;
    evaluate_pigment(pigment, DVec3::new(0.5, 0.5, 0.0)).rgb.x
}

fn assert_close(a: f64, b: f64) {
    assert!((a - b).abs() < 1e-6, "{a} against {b}");
}

/// `#version` takes the file's values as working colours (POV-Ray 3.7.0.10, grey 128:
/// 0.2158 in 3.7 scenes; 0.5020 (`assumed_gamma 1`) and 0.2195 = 0.502^2.2
/// (`assumed_gamma 2.2`) written by 3.6 scenes, which is drums2/drums.pov's backdrop).
#[test]
fn image_values_follow_the_version_and_gamma() {
    let grey = |header: &str| grey_128(header, "");
    let linear = ((128.0 / 255.0 + 0.055) / 1.055f64).powf(2.4);
    assert_close(
        grey("#version 3.7; global_settings { assumed_gamma 1 }"),
        linear,
    );
    assert_close(
        grey("#version 3.7; global_settings { assumed_gamma 2.2 }"),
        linear.powf(1.0 / 2.2),
    );
    assert_close(
        grey("#version 3.6; global_settings { assumed_gamma 2.2 }"),
        128.0 / 255.0,
    );
    assert_close(grey("#version 3.6;"), 128.0 / 255.0);
}

/// An image block's `gamma` is the file's encoding (POV-Ray 3.7.0.10, grey 128 written
/// linear: 0.2196 with `gamma 2.2`, 0.2902 with `gamma 1.8`, 0.5020 with `gamma 1`, the
/// sRGB curve's 0.2157 with `gamma srgb`).
#[test]
fn an_image_gamma_decodes_the_file() {
    let v = 128.0 / 255.0f64;
    let header = "#version 3.7; global_settings { assumed_gamma 1 }";
    assert_close(grey_128(header, "gamma 2.2"), v.powf(2.2));
    assert_close(grey_128(header, "gamma 1.8"), v.powf(1.8));
    assert_close(grey_128(header, "gamma 1"), v);
    assert_close(grey_128(header, "gamma srgb"), grey_128(header, ""));
    // Working in gamma 2.2: decoded, then encoded for the working space.
    let header = "#version 3.7; global_settings { assumed_gamma 2.2 }";
    assert_close(grey_128(header, "gamma 1.8"), v.powf(1.8 / 2.2));
}

/// `jpeg "file"` reads a JPEG as `png` reads a PNG (decoded from sRGB); a flat grey
/// survives the compression to within a step.
#[test]
fn a_jpeg_image_map_reads_like_a_png() {
    use crate::appearance::pigment::evaluate_pigment;
    use glam::DVec3;
    let dir = crate::study::TempDir::new("image-jpeg").unwrap();
    image::RgbImage::from_pixel(8, 8, image::Rgb([128, 128, 128]))
        .save(dir.path().join("grey.jpg"))
        .unwrap();
    let source = "#version 3.7; global_settings { assumed_gamma 1 }\n\
                  plane { z, 0 pigment { image_map { jpeg \"grey.jpg\" } } }";
    let loaded = load_beside(dir.path(), source);
    let pigment = &loaded.scene.objects[0].texture.as_ref().unwrap().pigment;
    let v = evaluate_pigment(pigment, DVec3::new(0.5, 0.5, 0.0)).rgb.x;
    let linear = |c: f64| ((c / 255.0 + 0.055) / 1.055f64).powf(2.4);
    assert!(v > linear(127.0) && v < linear(129.0), "{v}");
}

/// A two-entry palette PNG (red, green) named `name` in `dir`.
fn write_palette_png(dir: &std::path::Path, name: &str) {
    let file = std::fs::File::create(dir.join(name)).unwrap();
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), 2, 1);
    encoder.set_color(png::ColorType::Indexed);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_palette(vec![255, 0, 0, 0, 255, 0]);
    encoder
        .write_header()
        .unwrap()
        .write_image_data(&[0, 1])
        .unwrap();
}

/// `transmit` and `filter` of palette entries, in the order written (POV-Ray 3.7.0.10 on
/// this palette in front of blue: `transmit all 0.3 transmit 1, 0.5` shows 0.3 and 0.5;
/// the other order 0.3 and 0.3; `filter 1, 0.5` filters only the green entry).
#[test]
fn palette_entries_take_filter_and_transmit_in_order() {
    use crate::appearance::pigment::evaluate_pigment;
    use glam::DVec3;
    let dir = crate::study::TempDir::new("palette-edits").unwrap();
    write_palette_png(dir.path(), "pal.png");
    let pixels = |items: &str| {
        let source =
            format!("plane {{ z, 0 pigment {{ image_map {{ png \"pal.png\" {items} }} }} }}");
        let loaded = load_beside(dir.path(), &source);
        let pigment = &loaded.scene.objects[0].texture.as_ref().unwrap().pigment;
        [0.25, 0.75].map(|x| {
            let c = evaluate_pigment(pigment, DVec3::new(x, 0.5, 0.0));
            (c.filter, c.transmit)
        })
    };
    assert_eq!(pixels("transmit 1, 0.5"), [(0.0, 0.0), (0.0, 0.5)]);
    assert_eq!(
        pixels("transmit all 0.3 transmit 1, 0.5"),
        [(0.0, 0.3), (0.0, 0.5)]
    );
    assert_eq!(
        pixels("transmit 1, 0.5 transmit all 0.3"),
        [(0.0, 0.3), (0.0, 0.3)]
    );
    assert_eq!(pixels("filter 1 0.5"), [(0.0, 0.0), (0.5, 0.0)]);
}

/// An entry of a colour image, or past the palette's end, is a positioned error (POV-Ray
/// refuses both too).
#[test]
fn palette_entries_out_of_place_are_positioned_errors() {
    let dir = crate::study::TempDir::new("palette-errors").unwrap();
    write_palette_png(dir.path(), "pal.png");
    image::RgbImage::new(2, 1)
        .save(dir.path().join("rgb.png"))
        .unwrap();
    let scene_path = dir.path().join("scene.pov").display().to_string();
    for (file, message) in [
        ("rgb.png", "needs a palette image"),
        (
            "pal.png",
            "palette entry 2 is out of range: the palette has 2 entries",
        ),
    ] {
        let source = format!(
            "plane {{ z, 0 pigment {{\n  image_map {{ png \"{file}\" transmit 2, 0.5 }} }} }}"
        );
        let Err(e) = load_inner(
            &scene_path,
            &source,
            &LoadOptions::default(),
            &FileSystem,
            false,
        ) else {
            panic!("{file}: accepted");
        };
        assert!(e.message.contains(message), "{file}: {}", e.message);
        assert_eq!((e.line(), e.column()), (Some(2), Some(38)), "{file}");
    }
}

/// `uv_mapping` among an object's modifiers maps the textures that follow as `texture {
/// uv_mapping ... }` does (POV-Ray 3.7.0.10 renders the three the same, pixel for pixel),
/// and after a texture it is refused, as POV-Ray refuses it.
#[test]
fn object_uv_mapping_is_the_texture_s() {
    let texture = |source: &str| {
        let loaded = load_scene_source("uv.pov", source, &LoadOptions::default()).unwrap();
        loaded.scene.objects[0].texture.clone()
    };
    let inner =
        texture("sphere { 0, 1 texture { uv_mapping pigment { gradient x } } rotate y*30 }");
    assert!(inner.as_ref().unwrap().pigment.uv_mapping);
    for outer in [
        "sphere { 0, 1 uv_mapping texture { pigment { gradient x } } rotate y*30 }",
        "sphere { 0, 1 uv_mapping pigment { gradient x } rotate y*30 }",
    ] {
        assert_eq!(texture(outer), inner, "{outer}");
    }
    let Err(e) = load_scene_source(
        "uv.pov",
        "sphere { 0, 1 pigment { gradient x } uv_mapping }",
        &LoadOptions::default(),
    ) else {
        panic!("accepted");
    };
    assert!(
        e.message.contains("before the object's texture"),
        "{}",
        e.message
    );
    assert_eq!(e.column(), Some(38));
}
