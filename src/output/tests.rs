use super::*;
use crate::study::TempDir;
use std::path::PathBuf;

/// A fresh directory per test under the system temp dir, removed on drop, so tests can run
/// in parallel without sharing files.
struct Scratch(TempDir);

impl Scratch {
    fn new(tag: &str) -> Scratch {
        Scratch(TempDir::new(&format!("output-test-{tag}")).expect("create scratch dir"))
    }
    fn path(&self, name: &str) -> PathBuf {
        self.0.path().join(name)
    }
    fn entries(&self) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(self.0.path())
            .expect("read scratch dir")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }
}

fn gradient(width: usize, height: usize) -> Image {
    Image::from_fn(width, height, |x, y| {
        [
            x as f32 / (width - 1) as f32,
            y as f32 / (height - 1) as f32,
            0.25 + 0.001 * (x * y) as f32,
        ]
    })
}

#[test]
fn srgb_curve_round_trips_and_matches_known_points() {
    assert_eq!(srgb::encode(0.0), 0.0);
    assert!((srgb::encode(1.0) - 1.0).abs() < 1e-12);
    // Mid grey 0.5 encodes to about 0.7354 (code 188 in 8 bits).
    assert!((srgb::encode(0.5) - 0.735_356_6).abs() < 1e-6);
    assert_eq!(srgb::quantize(0.5, 255), 188);
    for code in 0..=65535u32 {
        let linear = srgb::dequantize(code, 65535);
        assert_eq!(srgb::quantize(linear, 65535), code, "code {code}");
    }
}

#[test]
fn quantize_clamps_and_handles_non_finite() {
    assert_eq!(srgb::quantize(-1.0, 255), 0);
    assert_eq!(srgb::quantize(7.0, 255), 255);
    assert_eq!(srgb::quantize(f32::NAN, 255), 0);
    assert_eq!(srgb::quantize(f32::INFINITY, 255), 255);
    assert_eq!(srgb::quantize(f32::NEG_INFINITY, 255), 0);
}

/// The table's 8-bit codes are `quantize`'s: around every code's value and every switch
/// between two codes (8 floats either side of each), at a million values spread over
/// [-0.1, 1.2], and at the special values.
#[test]
fn quantize8_gives_quantizes_codes() {
    let same = |v: f32| assert_eq!(u32::from(srgb::quantize8(v)), srgb::quantize(v, 255), "{v}");
    let around = |v: f32| {
        let bits = v.to_bits();
        (bits.saturating_sub(8)..=bits + 8).for_each(|b| same(f32::from_bits(b)));
    };
    for code in 0..=255u32 {
        around(srgb::dequantize(code, 255));
        around(srgb::decode((f64::from(code) + 0.5) / 255.0) as f32);
    }
    let mut state = 7u64;
    for _ in 0..1_000_000 {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1);
        same(-0.1 + 1.3 * (state >> 40) as f32 / (1u64 << 24) as f32);
    }
    for v in [
        0.0,
        -0.0,
        1.0,
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MIN_POSITIVE,
    ] {
        same(v);
    }
}

#[test]
fn png_8_and_16_bit_round_trip_within_quantisation() {
    let scratch = Scratch::new("png");
    let image = gradient(17, 9);
    for (depth, name, max) in [
        (BitDepth::Eight, "a.png", 255.0),
        (BitDepth::Sixteen, "b.png", 65535.0),
    ] {
        let path = scratch.path(name);
        write_image(&path, &image, depth).expect("write png");
        let back = read_image(&path).expect("read png");
        assert!(back.same_size(&image));
        for (a, b) in image.pixels.iter().zip(&back.pixels) {
            for c in 0..3 {
                let error = srgb::encode(f64::from(a[c])) - srgb::encode(f64::from(b[c]));
                assert!(error.abs() <= 0.5 / max + 1e-9, "{a:?} vs {b:?}");
            }
        }
    }
    assert_eq!(scratch.entries(), vec!["a.png", "b.png"]);
}

#[test]
fn png_values_are_clamped() {
    let scratch = Scratch::new("clamp");
    let image = Image::from_pixels(2, 1, vec![[-0.5, 2.0, f32::NAN], [0.0, 1.0, 0.5]])
        .expect("size matches");
    let path = scratch.path("c.png");
    write_png(&path, &image, BitDepth::Eight).expect("write");
    let back = read_png(&path).expect("read");
    assert_eq!(back.get(0, 0), [0.0, 1.0, 0.0]);
    assert_eq!(back.get(1, 0)[1], 1.0);
}

#[test]
fn exr_round_trips_exactly_with_layers_and_attributes() {
    let scratch = Scratch::new("exr");
    let image = gradient(13, 7).map(|v| v * 3.0 - 0.5);
    let half = gradient(13, 7).map(|v| v * 0.5);
    let path = scratch.path("r.exr");
    write_exr(
        &path,
        &image,
        &[("half", &half)],
        &[("povray_seconds", "12.5"), ("scene", "spheres.pov")],
    )
    .expect("write exr");
    let back = read_exr(&path).expect("read exr");
    assert_eq!(back.image, image);
    assert!(!back.half_float);
    assert_eq!(back.layers.len(), 1);
    assert_eq!(back.layer("half"), Some(&half));
    assert_eq!(back.attribute("povray_seconds"), Some("12.5"));
    assert_eq!(back.attribute("scene"), Some("spheres.pov"));
    assert_eq!(read_image(&path).expect("read rgb"), image);
    assert_eq!(scratch.entries(), vec!["r.exr"]);
}

#[test]
fn exr_rejects_bad_layers_and_attributes_without_leaving_files() {
    let scratch = Scratch::new("exrbad");
    let image = gradient(4, 4);
    let small = gradient(2, 2);
    let path = scratch.path("bad.exr");
    assert!(write_exr(&path, &image, &[("x", &small)], &[]).is_err());
    assert!(write_exr(&path, &image, &[("a.b", &image)], &[]).is_err());
    assert!(write_exr(&path, &image, &[("", &image)], &[]).is_err());
    assert!(write_exr(&path, &image, &[("x", &image), ("x", &image)], &[]).is_err());
    assert!(write_exr(&path, &image, &[], &[("channels", "x")]).is_err());
    assert!(write_exr(&path, &image, &[], &[("t", "\u{1F600}")]).is_err());
    assert!(scratch.entries().is_empty());
}

#[test]
fn failed_writes_leave_nothing_and_name_the_path() {
    let scratch = Scratch::new("fail");
    let image = gradient(4, 4);
    let missing_dir = scratch.path("no/such/dir");
    for name in ["x.png", "x.exr"] {
        let path = missing_dir.join(name);
        let error = write_image(&path, &image, BitDepth::Eight).expect_err("must fail");
        assert!(
            error.to_string().contains(&*path.to_string_lossy()),
            "{error}"
        );
        assert!(!path.exists());
    }
    assert!(scratch.entries().is_empty());

    let error = write_image(&scratch.path("x.tiff"), &image, BitDepth::Eight).expect_err("tiff");
    assert!(matches!(error, OutputError::UnsupportedFormat { .. }));
    assert!(error.to_string().contains("x.tiff"));

    let empty = Image::new(0, 0);
    assert!(write_image(&scratch.path("e.png"), &empty, BitDepth::Eight).is_err());
    assert!(write_image(&scratch.path("e.exr"), &empty, BitDepth::Eight).is_err());
    let inconsistent = Image {
        width: 3,
        height: 3,
        pixels: vec![[0.0; 3]; 2],
    };
    assert!(write_image(&scratch.path("i.png"), &inconsistent, BitDepth::Eight).is_err());
    assert!(scratch.entries().is_empty());
}

#[test]
fn overwriting_replaces_the_whole_file() {
    let scratch = Scratch::new("over");
    let path = scratch.path("o.exr");
    write_image(&path, &gradient(8, 8), BitDepth::Eight).expect("first");
    let second = Image::filled(3, 2, [0.1, 0.2, 0.3]);
    write_image(&path, &second, BitDepth::Eight).expect("second");
    assert_eq!(read_image(&path).expect("read"), second);
    assert_eq!(scratch.entries(), vec!["o.exr"]);
}

#[test]
fn reading_garbage_is_an_error_with_the_path() {
    let scratch = Scratch::new("garbage");
    for name in ["g.png", "g.exr"] {
        let path = scratch.path(name);
        std::fs::write(&path, b"not an image").expect("write garbage");
        let error = read_image(&path).expect_err("garbage");
        assert!(error.to_string().contains(name), "{error}");
    }
    assert!(read_image(&scratch.path("missing.exr")).is_err());
}

#[test]
fn downsample_is_an_exact_box_filter() {
    let image = Image::from_fn(4, 2, |x, y| [x as f32, y as f32, 1.0]);
    let small = image.downsample(2).expect("divisible");
    assert_eq!(small.width, 2);
    assert_eq!(small.height, 1);
    assert_eq!(small.get(0, 0), [0.5, 0.5, 1.0]);
    assert_eq!(small.get(1, 0), [2.5, 0.5, 1.0]);
    assert!(image.downsample(3).is_none());
    assert!(image.downsample(0).is_none());
}

#[test]
fn from_pixels_checks_the_count_and_non_finite_finds_nan() {
    assert!(Image::from_pixels(2, 2, vec![[0.0; 3]; 3]).is_none());
    let mut image = Image::new(3, 2);
    image.set(2, 1, [0.0, f32::NAN, f32::INFINITY]);
    assert_eq!(image.non_finite(), vec![(2, 1, 1), (2, 1, 2)]);
}

#[test]
fn a_failed_rename_removes_the_temporary() {
    // The destination is a non-empty directory, so the final rename fails after the
    // temporary file was written completely.
    let scratch = Scratch::new("rename");
    let blocker = scratch.path("x.exr");
    std::fs::create_dir(&blocker).expect("dir");
    std::fs::write(blocker.join("keep"), b"").expect("file");
    let error = write_image(&blocker, &gradient(4, 4), BitDepth::Eight).expect_err("rename");
    assert!(matches!(error, OutputError::Io { .. }), "{error}");
    assert!(error.to_string().contains("x.exr"));
    assert_eq!(scratch.entries(), vec!["x.exr"]);
    assert!(blocker.join("keep").exists());
}

#[test]
fn the_same_pixels_give_the_same_exr_bytes() {
    // 1000x800 is 208 tiles, compressed in parallel: before the chunks were written in
    // order, two writes of this image differed in most runs.
    let scratch = Scratch::new("exr-bytes");
    let image = gradient(1000, 800).map(|v| (v * 37.0).sin());
    let bytes = |name: &str| {
        let path = scratch.path(name);
        write_exr(&path, &image, &[], &[]).expect("write exr");
        std::fs::read(&path).expect("read back")
    };
    let first = bytes("a.exr");
    for k in 0..8 {
        assert!(bytes(&format!("{k}.exr")) == first, "write {k} differs");
    }
}
