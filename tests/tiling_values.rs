//! `tiling` and `pavement` give POV-Ray's own values: each pattern, read through a pigment
//! function at 1600 points over [-5.3, 5.3]^2, printed with `#debug` by POV-Ray 3.7 and by
//! penumbra from the same scene text. POV-Ray evaluates colour maps in single precision,
//! so values agree to its rounding: the largest difference measured over all tilings was
//! 3.7e-7, and a wrong tile anywhere differs by at least a bevel step (0.01 and more). Skips
//! (saying so) where POV-Ray is not installed; CI installs it.

use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::study::TempDir;
use penumbra::study::reference::find_povray;
use std::process::Command;

/// A scene printing the pattern's value at a 40 x 40 grid of points (the steps are not
/// multiples of any tile edge, so no point falls on an edge).
fn probe_scene(pattern: &str) -> String {
    format!(
        "#version 3.7;\nglobal_settings {{ assumed_gamma 1 }}\n\
         #declare F = function {{ pigment {{ {pattern} color_map {{ [0 rgb 0][1 rgb 1] }} }} }}\n\
         #declare I = 0;\n#while (I < 40)\n  #declare J = 0;\n  #while (J < 40)\n\
         #debug concat(str(F(-5.3 + I * 0.26537, 0.3, -5.3 + J * 0.26519).red, 0, 9), \"\\n\")\n\
         #declare J = J + 1;\n  #end\n  #declare I = I + 1;\n#end\n\
         camera {{ location -5 look_at 0 }} sphere {{ 0, 1 pigment {{ rgb 1 }} }}\n"
    )
}

fn numbers(text: &str) -> Vec<f64> {
    text.lines().filter_map(|l| l.trim().parse().ok()).collect()
}

fn penumbra_values(scene: &str) -> Vec<f64> {
    let options = LoadOptions {
        image_width: 8,
        image_height: 8,
        ..LoadOptions::default()
    };
    match load_scene_source("probe.pov", scene, &options) {
        Ok(loaded) => numbers(&loaded.debug),
        Err(d) => panic!("{d}"),
    }
}

fn povray_values(scene: &str, dir: &TempDir) -> Vec<f64> {
    let path = dir.path().join("probe.pov");
    std::fs::write(&path, scene).unwrap();
    let out = Command::new("povray")
        .arg(format!("+I{}", path.display()))
        .arg(format!("+O{}", dir.path().join("probe.png").display()))
        .args(["+W8", "+H8", "-D", "-V"])
        .output()
        .expect("povray runs");
    numbers(&String::from_utf8_lossy(&out.stderr))
}

/// The largest difference between POV-Ray's and penumbra's values of each pattern.
fn worst_differences(patterns: &[String]) -> Option<Vec<(String, f64)>> {
    if find_povray().is_err() {
        eprintln!("povray is not installed: POV-Ray's tiling values not compared");
        return None;
    }
    let dir = TempDir::new("tiling-values").unwrap();
    let mut worst = Vec::new();
    for pattern in patterns {
        let scene = probe_scene(pattern);
        let theirs = povray_values(&scene, &dir);
        let ours = penumbra_values(&scene);
        assert_eq!(
            theirs.len(),
            1600,
            "{pattern}: POV-Ray printed {}",
            theirs.len()
        );
        assert_eq!(
            ours.len(),
            1600,
            "{pattern}: penumbra printed {}",
            ours.len()
        );
        let d = theirs
            .iter()
            .zip(&ours)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        worst.push((pattern.clone(), d));
    }
    Some(worst)
}

/// All 27 tilings, and the aperiodic ones (Penrose's pentagons, kites and darts, rhombs)
/// also ten times further out (up to 75 from the origin), where their construction starts
/// from a larger tile.
#[test]
fn every_tiling_gives_povrays_values() {
    let patterns: Vec<String> = (1..=27)
        .map(|n| format!("tiling {n}"))
        .chain((25..=27).map(|n| format!("tiling {n} scale 0.1")))
        .collect();
    let Some(worst) = worst_differences(&patterns) else {
        return;
    };
    for (pattern, d) in worst {
        assert!(d < 1e-5, "{pattern}: POV-Ray's value differs by {d}");
    }
}

/// All 112 of POV-Ray's pavements (the polyforms of 1 to 6 triangles and squares and of 1
/// to 5 hexagons), each followed by `styles`.
fn every_pavement(styles: &str) -> Vec<String> {
    let counts: [(u8, &[u8]); 3] = [
        (3, &[1, 1, 1, 3, 4, 12]),
        (4, &[1, 1, 2, 5, 12, 35]),
        (6, &[1, 1, 3, 7, 22]),
    ];
    let mut patterns = Vec::new();
    for (sides, per_size) in counts {
        for (tiles, &count) in (1..).zip(per_size) {
            for pattern in 1..=count {
                patterns.push(format!(
                    "pavement number_of_sides {sides} number_of_tiles {tiles} pattern {pattern} \
                     {styles}"
                ));
            }
        }
    }
    assert_eq!(patterns.len(), 112);
    patterns
}

/// The 112 pavements with the default corners.
#[test]
fn every_pavement_gives_povrays_values() {
    let Some(worst) = worst_differences(&every_pavement("")) else {
        return;
    };
    for (pattern, d) in worst {
        assert!(d < 1e-5, "{pattern}: POV-Ray's value differs by {d}");
    }
}

/// The corner styles, each where it applies (exterior at 60 and 90-degree corners, form at
/// the bends of squares and 120-degree corners, interior at reflex and straight ones) and in
/// combination. `PENUMBRA_PAVEMENT_STYLES=all` runs ten combinations on all 112 pavements
/// instead (about 15 minutes; the result is recorded in docs/appearance.md).
#[test]
fn pavement_corner_styles_give_povrays_values() {
    let sample = [
        "4 5 3 exterior 1",
        "4 5 3 exterior 2",
        "4 6 20 interior 1",
        "4 6 20 interior 2",
        "4 3 2 form 1",
        "4 4 5 form 2",
        "4 5 3 form 3 interior 2 exterior 1",
        "3 6 7 exterior 1 interior 2",
        "3 6 7 exterior 2 form 1",
        "3 5 4 form 2 interior 1",
        "3 4 2 form 3 interior 1 exterior 2",
        "6 4 7 form 1 interior 2",
        "6 5 13 form 2 interior 1",
        "6 3 2 form 3 exterior 2 interior 2",
    ];
    let patterns: Vec<String> = if std::env::var("PENUMBRA_PAVEMENT_STYLES").as_deref() == Ok("all")
    {
        STYLE_SWEEP.iter().flat_map(|s| every_pavement(s)).collect()
    } else {
        sample
            .iter()
            .map(|s| {
                let mut w = s.splitn(4, ' ');
                let (sides, tiles, pattern) = (w.next(), w.next(), w.next());
                format!(
                    "pavement number_of_sides {} number_of_tiles {} pattern {} {}",
                    sides.unwrap(),
                    tiles.unwrap(),
                    pattern.unwrap(),
                    w.next().unwrap()
                )
            })
            .collect()
    };
    let Some(worst) = worst_differences(&patterns) else {
        return;
    };
    let largest = worst.iter().map(|(_, d)| *d).fold(0.0, f64::max);
    eprintln!(
        "{} pavements with corner styles: largest difference {largest:e}",
        worst.len()
    );
    for (pattern, d) in worst {
        assert!(d < 1e-5, "{pattern}: POV-Ray's value differs by {d}");
    }
}

/// The combinations the full sweep runs.
const STYLE_SWEEP: [&str; 10] = [
    "exterior 1",
    "exterior 2",
    "interior 1",
    "interior 2",
    "form 1",
    "form 2",
    "form 3 interior 2 exterior 1",
    "form 1 interior 1 exterior 2",
    "form 2 interior 2 exterior 2",
    "form 3 interior 1 exterior 2",
];
