//! These tests run the installed POV-Ray; each one prints a message and returns early when
//! `povray` is not on PATH, so the suite still passes on machines without it.

use super::*;
use crate::study::tempdir::TempDir;

fn povray_or_skip() -> bool {
    match find_povray() {
        Ok(_) => true,
        Err(e) => {
            println!("skipping: {e}");
            false
        }
    }
}

/// A background of the declared shade and a sphere in a flat, unlit colour from an include
/// file in a separate folder: exercises Declare=, +L and the box filter at once.
fn write_scene(dir: &Path) -> (PathBuf, PathBuf) {
    let scene_dir = dir.join("scene");
    let include_dir = dir.join("include");
    std::fs::create_dir_all(&scene_dir).expect("scene dir");
    std::fs::create_dir_all(&include_dir).expect("include dir");
    std::fs::write(
        include_dir.join("flat.inc"),
        "#declare Flat = finish { ambient 1 diffuse 0 };\n",
    )
    .expect("include");
    let scene = scene_dir.join("sphere.pov");
    std::fs::write(
        &scene,
        "#version 3.7;\n\
         global_settings { assumed_gamma 1.0 }\n\
         #include \"flat.inc\"\n\
         camera { location <0, 0, -4> look_at 0 right x*4/3 up y }\n\
         background { rgb <Shade, 0.5, 0.125> }\n\
         sphere { 0, 1 pigment { rgb <0.123456, 0.75, 0.5> } finish { Flat } }\n",
    )
    .expect("scene");
    (scene, include_dir)
}

#[test]
fn constant_colours_come_back_exactly_and_edges_average() {
    if !povray_or_skip() {
        return;
    }
    let dir = TempDir::new("reference-test").expect("temp dir");
    let (scene, include_dir) = write_scene(dir.path());
    let mut req = ReferenceRequest::new(&scene, 16, 12, 2);
    req.declares.push(("Shade".to_string(), 0.25));
    req.include_paths.push(include_dir);
    let reference = render_reference(&req).expect("povray renders");
    assert_eq!((reference.full.width, reference.full.height), (16, 12));
    assert_eq!((reference.half.width, reference.half.height), (16, 12));
    assert!(reference.povray_seconds > 0.0);

    // Corners see only the background; 0.25, 0.5 and 0.125 are exact in half float.
    assert_eq!(reference.full.get(0, 0), [0.25, 0.5, 0.125]);
    assert_eq!(reference.half.get(15, 11), [0.25, 0.5, 0.125]);
    // The centre sees only the sphere: linear (not sRGB-encoded) half floats.
    let centre = reference.full.get(8, 6);
    assert!((centre[0] - 0.123456).abs() < 1e-4, "{centre:?}");
    assert_eq!(&centre[1..], &[0.75, 0.5]);
    // Somewhere along the silhouette a pixel mixes both colours.
    let mixed = reference
        .full
        .pixels
        .iter()
        .any(|p| p[1] > 0.5 && p[1] < 0.75);
    assert!(mixed);
    // Every value lies between the two colours, as an average of them must.
    for p in &reference.full.pixels {
        assert!((0.12..=0.251).contains(&p[0]) && (0.5..=0.75).contains(&p[1]));
    }

    // And it survives a round trip through a reference file.
    let file = dir.path().join("ref.exr");
    write_reference(&file, &reference).expect("write");
    assert_eq!(read_reference(&file).expect("read"), reference);
}

#[test]
fn povray_errors_carry_its_message() {
    if !povray_or_skip() {
        return;
    }
    let dir = TempDir::new("reference-test").expect("temp dir");
    let scene = dir.path().join("broken.pov");
    std::fs::write(
        &scene,
        "#version 3.7;\nsphere { 0, 1 pigment { rgb Undeclared } }\n",
    )
    .expect("scene");
    let error = render_reference(&ReferenceRequest::new(&scene, 4, 3, 2)).expect_err("fails");
    let message = error.to_string();
    assert!(
        matches!(error, StudyError::PovrayFailed { .. }),
        "{message}"
    );
    assert!(message.contains("Undeclared"), "{message}");
}

#[test]
fn bad_requests_are_refused_before_running_povray() {
    let dir = TempDir::new("reference-test").expect("temp dir");
    let scene = dir.path().join("s.pov");
    std::fs::write(&scene, "").expect("scene");
    let cases = [
        ReferenceRequest::new(&scene, 0, 3, 2),
        ReferenceRequest::new(&scene, 4, 3, 3),
        ReferenceRequest::new(&scene, 4, 3, 0),
        ReferenceRequest::new(&scene, 4, 3, 128),
        ReferenceRequest::new(&scene, u32::MAX, 3, 2),
        ReferenceRequest {
            declares: vec![("9lives".to_string(), 1.0)],
            ..ReferenceRequest::new(&scene, 4, 3, 2)
        },
        ReferenceRequest {
            declares: vec![("X".to_string(), f64::NAN)],
            ..ReferenceRequest::new(&scene, 4, 3, 2)
        },
    ];
    for req in &cases {
        let error = render_reference(req).expect_err("invalid");
        assert!(matches!(error, StudyError::InvalidRequest(_)), "{error}");
    }
    if povray_or_skip() {
        let missing = ReferenceRequest::new(dir.path().join("missing.pov"), 4, 3, 2);
        let error = render_reference(&missing).expect_err("missing scene");
        assert!(error.to_string().contains("missing.pov"), "{error}");
    }
}

#[test]
fn a_missing_executable_is_not_found() {
    let dir = TempDir::new("reference-test").expect("temp dir");
    assert_eq!(find_in_path("povray", dir.path().as_os_str()), None);
    assert_eq!(find_in_path("povray", OsStr::new("")), None);
    let fake = dir.path().join("povray");
    std::fs::write(&fake, "").expect("fake");
    // Not executable yet, so still not found.
    assert_eq!(find_in_path("povray", dir.path().as_os_str()), None);
    assert!(StudyError::PovrayNotFound.to_string().contains("PATH"));
}

#[test]
fn reading_a_plain_exr_as_a_reference_explains_what_is_missing() {
    let dir = TempDir::new("reference-test").expect("temp dir");
    let path = dir.path().join("plain.exr");
    crate::output::write_exr(&path, &Image::new(2, 2), &[], &[]).expect("write");
    let error = read_reference(&path).expect_err("not a reference");
    assert!(error.to_string().contains("half"), "{error}");
}

#[test]
fn povray_statistics_times_are_summed() {
    let text = "Parser Time\n  Parse Time:       0 hours  0 minutes  0 seconds (0.012 seconds)\n\
              using 1 thread(s) with 0.011 CPU-seconds total\n\
              Bounding Time:    0 hours  0 minutes  0 seconds (0.003 seconds)\n\
              Photon Time:      No photons\n\
              Trace Time:       0 hours  0 minutes  1 seconds (1.250 seconds)\n\
              using 2 thread(s) with 2.400 CPU-seconds total\n";
    let total = reported_seconds(text).expect("times");
    assert!((total - 1.265).abs() < 1e-12, "{total}");
    assert_eq!(reported_seconds("no statistics here"), None);
}
