//! `ripples` and `waves` normals where a scene scales the pattern up and its frequency by as
//! much (`translate -0.5 scale 100000 frequency 100000`, as textures/finishes/var_refl.pov
//! does for straight waves): each wave's phase is then 10^5 times a wave source's distance
//! from the pattern's origin, so POV-Ray's sources must be known to 1e-8 for the waves to
//! line up. POV-Ray renders a mirror under the normal, seen from straight above, reflecting
//! a sky whose red is the reflected ray's x and green its z; its 16-bit PNG gives the normal
//! at every pixel centre, which penumbra's must match. Skips (saying so) where POV-Ray is
//! not installed; CI installs it.

use glam::DVec3;
use penumbra::appearance::perturbed_normal;
use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::scene::Texture;
use penumbra::study::TempDir;
use penumbra::study::reference::find_povray;
use std::process::Command;

const SIZE: u32 = 48;
const EXTENT: f64 = 4.0;

fn scene(normal: &str) -> String {
    format!(
        "#version 3.7;\nglobal_settings {{ assumed_gamma 1 }}\n\
         camera {{ orthographic location <0, 10, 0> look_at 0 right x*{EXTENT} up z*{EXTENT} sky z }}\n\
         sky_sphere {{ pigment {{ average pigment_map {{\n\
           [1 function {{ x * 0.5 + 0.5 }} color_map {{ [0 rgb 0] [1 rgb <2, 0, 0>] }}]\n\
           [1 function {{ z * 0.5 + 0.5 }} color_map {{ [0 rgb 0] [1 rgb <0, 2, 0>] }}] }} }} }}\n\
         plane {{ y, 0 texture {{ pigment {{ rgb 0 }} normal {{ {normal} }}\n\
           finish {{ ambient 0 diffuse 0 reflection 1 }} }} }}\n"
    )
}

fn srgb_to_linear(v: f64) -> f64 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// POV-Ray's normals, row by row from the top: the reflected ray of a view straight down is
/// 2 n_y (n_x, ., n_z), read from the red and green channels.
fn povray_normals(normal: &str, dir: &TempDir) -> Vec<DVec3> {
    let pov = dir.path().join("waves.pov");
    let png = dir.path().join("waves.png");
    std::fs::write(&pov, scene(normal)).unwrap();
    let out = Command::new("povray")
        .arg(format!("+I{}", pov.display()))
        .arg(format!("+O{}", png.display()))
        .args([
            &format!("+W{SIZE}"),
            &format!("+H{SIZE}"),
            "-D",
            "-V",
            "+FN16",
        ])
        .output()
        .expect("povray runs");
    assert!(png.exists(), "{}", String::from_utf8_lossy(&out.stderr));
    let img = image::open(&png).expect("a PNG").to_rgb16();
    img.pixels()
        .map(|p| {
            let channel = |c: u16| srgb_to_linear(f64::from(c) / 65535.0) * 2.0 - 1.0;
            let (rx, rz) = (channel(p[0]), channel(p[1]));
            // r = 2 n_y (n_x, n_z): n_y^2 = (1 + sqrt(1 - |r|^2)) / 2 for a tilt under 45 degrees.
            let ny = ((1.0 + (1.0 - rx * rx - rz * rz).sqrt()) / 2.0).sqrt();
            DVec3::new(rx / (2.0 * ny), ny, rz / (2.0 * ny))
        })
        .collect()
}

fn texture(normal: &str) -> Texture {
    let source =
        format!("#version 3.7;\nplane {{ y, 0 pigment {{ rgb 1 }} normal {{ {normal} }} }}\n");
    let loaded = load_scene_source("waves.pov", &source, &LoadOptions::default())
        .unwrap_or_else(|d| panic!("{d}"));
    std::sync::Arc::unwrap_or_clone(loaded.scene.objects[0].texture.clone().expect("texture"))
}

/// penumbra's normals at POV-Ray's pixel centres (the image's x runs along -x: the camera
/// looks down with z up).
fn penumbra_normals(normal: &str) -> Vec<DVec3> {
    let t = texture(normal);
    let step = EXTENT / f64::from(SIZE);
    let mut v = Vec::new();
    for j in 0..SIZE {
        for i in 0..SIZE {
            let x = EXTENT / 2.0 - (f64::from(i) + 0.5) * step;
            let z = EXTENT / 2.0 - (f64::from(j) + 0.5) * step;
            v.push(perturbed_normal(&t, DVec3::new(x, 0.0, z), DVec3::Y));
        }
    }
    v
}

/// The largest difference in the normal over the image: 16-bit output resolves it to 3e-5,
/// the sources' nine digits put a phase error of at most 2 pi 10^5 1e-9 (4e-4 rad, times the
/// amount in the normal); a wave out of phase moves it by up to twice its amount (0.05),
/// and the five-digit sources of before moved it by 0.02.
#[test]
fn scaled_waves_keep_povrays_phases() {
    if find_povray().is_err() {
        eprintln!("povray is not installed: the waves' phases are not compared");
        return;
    }
    let dir = TempDir::new("wave-phases").unwrap();
    for kind in ["ripples", "waves"] {
        for scale in ["1", "100000"] {
            let normal = format!("{kind} 0.05 translate -0.5 scale {scale} frequency {scale}");
            let theirs = povray_normals(&normal, &dir);
            let ours = penumbra_normals(&normal);
            assert_eq!(theirs.len(), ours.len());
            let worst = theirs
                .iter()
                .zip(&ours)
                .map(|(a, b)| (*a - *b).abs().max_element())
                .fold(0.0, f64::max);
            eprintln!("{normal}: largest difference {worst:.2e}");
            assert!(worst < 1e-3, "{normal}: the normal differs by {worst}");
        }
    }
}
