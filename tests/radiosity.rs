//! Radiosity against the answer known in closed form (a furnace), as POV-Ray computes it.
//!
//! A closed diffuse sphere seen from inside, white, `finish { emission E ambient 0 diffuse
//! rho }`, lit by a point light of colour I at its centre: every surface point gets E + rho I
//! directly, and each diffuse bounce multiplies by rho (brightness b: by b rho), so with
//! `recursion_limit R` every pixel is (E + rho I)(1 + b rho + ... + (b rho)^R). POV-Ray 3.7
//! renders exactly that (measured: 0.7998 for R=1, rho=0.6, E=0.2, I=0.5, exact 0.8; 1.0039
//! for R=3, rho=0.8, E=0.1, I=0.3, exact 1.0037; 1.8203 for b=2, R=2, exact 1.82). One
//! bounce has no variance (the radiance is the same in every direction); beyond it roulette
//! makes the estimate random, so the image mean must lie within 3 standard errors (from the
//! spread of the pixels, whose noise is independent) of the answer.

use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::render::RenderOptions;

struct Furnace {
    recursion_limit: u32,
    rho: f64,
    emission: f64,
    light: f64,
    brightness: f64,
}

impl Furnace {
    fn scene(&self) -> String {
        format!(
            "#version 3.7;
global_settings {{ assumed_gamma 1
  radiosity {{ recursion_limit {} brightness {} count 50 }} }}
camera {{ location <0.1, 0.05, 0> direction z up y right x }}
light_source {{ 0, rgb {} }}
sphere {{ 0, 1 pigment {{ rgb 1 }}
  finish {{ ambient 0.3 emission {} diffuse {} }} }}
",
            self.recursion_limit, self.brightness, self.light, self.emission, self.rho
        )
    }

    fn exact(&self) -> f64 {
        let direct = self.emission + self.rho * self.light;
        let k = self.brightness * self.rho;
        direct
            * (0..=self.recursion_limit)
                .map(|i| k.powi(i as i32))
                .sum::<f64>()
    }
}

fn render(source: &str, size: usize, spp: u32, threads: usize) -> Vec<f64> {
    let loaded = load_scene_source("furnace.pov", source, &LoadOptions::default())
        .unwrap_or_else(|d| panic!("{d}"));
    let options = RenderOptions {
        width: size,
        height: size,
        samples_per_pixel: spp,
        seed: 7,
        threads: Some(threads),
        ..RenderOptions::default()
    };
    let image = penumbra::render_scene(&loaded.scene, &options, &())
        .expect("render")
        .0;
    (0..size * size)
        .map(|i| f64::from(image.get(i % size, i / size)[0]))
        .collect()
}

fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

#[test]
fn a_diffuse_furnace_gives_the_sum_over_bounces() {
    let cases = [
        (1, 0.6, 0.2, 0.5, 1.0),
        (2, 0.5, 0.0, 1.0, 1.0),
        (3, 0.8, 0.1, 0.3, 1.0),
        (5, 0.7, 0.3, 0.0, 1.0),
        (8, 0.9, 0.05, 0.2, 1.0),
        (2, 0.6, 0.2, 0.5, 2.0),
        (20, 0.5, 0.4, 0.4, 1.0),
    ];
    for (recursion_limit, rho, emission, light, brightness) in cases {
        let f = Furnace {
            recursion_limit,
            rho,
            emission,
            light,
            brightness,
        };
        let (mean, se) = mean_and_error(&render(&f.scene(), 24, 32, 2));
        let want = f.exact();
        // f32 output rounds at about 1e-7 relative.
        let tolerance = 3.0 * se + 1e-6 * want;
        assert!(
            (mean - want).abs() <= tolerance,
            "R={recursion_limit} rho={rho} E={emission} I={light} b={brightness}: \
             {mean} +- {se}, exact {want}"
        );
        if recursion_limit == 1 {
            assert!(se < 1e-7, "one bounce in a furnace has no variance: {se}");
        }
    }
}

#[test]
fn a_radiosity_render_is_the_same_on_any_number_of_threads() {
    let f = Furnace {
        recursion_limit: 4,
        rho: 0.8,
        emission: 0.1,
        light: 0.3,
        brightness: 1.0,
    };
    let one = render(&f.scene(), 16, 4, 1);
    let two = render(&f.scene(), 16, 4, 2);
    assert_eq!(one, two);
}
