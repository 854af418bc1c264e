//! Stratification pays (shared/testing-statistics.md): on a straight shadow edge with a wide
//! penumbra, Var(independent) / Var(stratified) grows with N, about like sqrt(N) in the
//! penumbra and like N where only the pixel position varies. Variances come from replicates
//! (K = 8), never from the spread of samples within one pixel.

use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::output::Image;
use penumbra::render::{LightSamples, RenderOptions};

const SCENE: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -0.01> look_at <0, 0, 0> right x*image_width/image_height angle 60 }
light_source { <0, 4, 0> color rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 65, 65 }
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-10, 1, -10>, <0, 1.01, 10> pigment { color rgb 0 } }
";

const W: usize = 64;
const H: usize = 48;
const K: u64 = 8;

fn variance_map(stratified: bool, spp: u32) -> Vec<f64> {
    let options = LoadOptions {
        image_width: W as u32,
        image_height: H as u32,
        ..LoadOptions::default()
    };
    let scene = load_scene_source("edge.pov", SCENE, &options)
        .expect("loads")
        .scene;
    let images: Vec<Image> = (0..K)
        .map(|k| {
            let o = RenderOptions {
                width: W,
                height: H,
                samples_per_pixel: spp,
                seed: 40 + k,
                stratified,
                // The sampler's own strata, one shadow ray per sample: what this test measures.
                light_samples: LightSamples::Fixed(1),
                ..RenderOptions::default()
            };
            penumbra::render_scene(&scene, &o, &()).expect("renders").0
        })
        .collect();
    (0..W * H)
        .map(|i| {
            let v: Vec<f64> = images.iter().map(|im| im.pixels[i][0] as f64).collect();
            let m = v.iter().sum::<f64>() / K as f64;
            v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (K - 1) as f64
        })
        .collect()
}

/// Mean variance over the pixels in a class.
fn mean_over(v: &[f64], class: &[bool]) -> f64 {
    let (s, n) = v
        .iter()
        .zip(class)
        .filter(|(_, c)| **c)
        .fold((0.0, 0usize), |(s, n), (x, _)| (s + x, n + 1));
    s / n.max(1) as f64
}

#[test]
fn stratified_variance_falls_faster_than_independent() {
    // Classify pixels once, from a well-converged render: penumbra pixels vary with the
    // light sample; smooth lit ones only with the pixel position.
    let options = LoadOptions {
        image_width: W as u32,
        image_height: H as u32,
        ..LoadOptions::default()
    };
    let converged = |source: &str| -> Vec<f64> {
        let scene = load_scene_source("edge.pov", source, &options)
            .expect("loads")
            .scene;
        let o = RenderOptions {
            width: W,
            height: H,
            samples_per_pixel: 1024,
            ..RenderOptions::default()
        };
        let image = penumbra::render_scene(&scene, &o, &()).expect("renders").0;
        image.pixels.iter().map(|p| p[0] as f64).collect()
    };
    let shadowed = converged(SCENE);
    let open = converged(&SCENE.replace("box {", "#declare Unused = box {"));
    // The fraction of the light each pixel sees: 0 in the umbra, 1 where fully lit.
    let seen: Vec<f64> = shadowed
        .iter()
        .zip(&open)
        .map(|(s, o)| if *o > 0.0 { s / o } else { 0.0 })
        .collect();
    let penumbra_px: Vec<bool> = seen.iter().map(|&v| v > 0.15 && v < 0.85).collect();
    let lit: Vec<bool> = seen.iter().map(|&v| v > 0.999).collect();
    assert!(penumbra_px.iter().filter(|c| **c).count() > 100);
    assert!(lit.iter().filter(|c| **c).count() > 100);

    let mut ratios = Vec::new();
    for spp in [4u32, 16, 64] {
        let ind = variance_map(false, spp);
        let strat = variance_map(true, spp);
        let r_pen = mean_over(&ind, &penumbra_px) / mean_over(&strat, &penumbra_px);
        let r_lit = mean_over(&ind, &lit) / mean_over(&strat, &lit);
        let slope_pen = mean_over(&strat, &penumbra_px);
        println!(
            "N = {spp:3}: Var ratio independent/stratified: penumbra {r_pen:6.2}, lit {r_lit:7.2}; \
             stratified penumbra variance {slope_pen:.3e}"
        );
        ratios.push((spp, r_pen, r_lit, slope_pen));
    }
    let (first, last) = (ratios[0], ratios[2]);
    // From N = 4 to N = 64 the prediction is x4 (sqrt N) in the penumbra and x16 (N) where
    // only the pixel position matters; half of each leaves room for replicate noise (K = 8).
    let pen_growth = last.1 / first.1;
    let lit_growth = last.2 / first.2;
    let slope = (last.3 / first.3).ln() / 16f64.ln();
    println!(
        "growth N=4..64: penumbra x{pen_growth:.2}, lit x{lit_growth:.2}; \
         stratified penumbra variance slope {slope:.2} (RMSE slope {:.2})",
        slope / 2.0
    );
    assert!(pen_growth > 2.0, "penumbra ratio grew only x{pen_growth}");
    assert!(lit_growth > 8.0, "lit ratio grew only x{lit_growth}");
    // And stratified noise in the penumbra falls faster than N^-1/2 (variance N^-1).
    assert!(slope < -1.2, "stratified penumbra variance slope {slope}");
}
