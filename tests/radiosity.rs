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
//!
//! The back side of `diffuse front, back` (POV-Ray 3.7's backside illumination) has known
//! answers too: a light behind a surface shines through the second value, and radiosity
//! gathers the hemisphere behind through it (a furnace inside an emitting one).

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

/// A plane seen from the front under a parallel light: the diffuse term is pigment x value
/// x cos^brilliance, with the second value for a light behind (measured with POV-Ray 3.7,
/// `diffuse 0.6, 0.3` under a point light: 0.5996 in front, 0.2998 behind, 0.2139 at 45
/// degrees, 0.1087 with brilliance 3; double_illuminate lights from behind through the
/// first value, 0.5996; transmit 0.5 halves the back as the front).
#[test]
fn a_light_behind_shines_through_the_back_value() {
    let scene = |light: &str, finish: &str, object: &str| {
        format!(
            "#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ orthographic location <0, 0, -5> look_at 0 right x*2 up y*2 }}
light_source {{ {light} rgb 1 parallel point_at 0 }}
plane {{ z, 0 finish {{ ambient 0 {finish} }} {object} }}
"
        )
    };
    let cos45 = std::f64::consts::FRAC_1_SQRT_2;
    let white = "pigment { rgb 1 }";
    let cases = [
        ("<0, 0, -3>", "diffuse 0.6, 0.3", white, 0.6),
        ("<0, 0, 3>", "diffuse 0.6, 0.3", white, 0.3),
        ("<3, 0, 3>", "diffuse 0.6, 0.3", white, 0.3 * cos45),
        (
            "<3, 0, 3>",
            "diffuse 0.6, 0.3 brilliance 3",
            white,
            0.3 * cos45.powi(3),
        ),
        (
            "<0, 0, 3>",
            "diffuse 0.6, 0.3",
            "pigment { rgb 1 } double_illuminate",
            0.6,
        ),
        ("<0, 0, 3>", "diffuse 0.6", white, 0.0),
        (
            "<0, 0, 3>",
            "diffuse 0.6, 0.3",
            "pigment { rgbt <1, 1, 1, 0.5> }",
            0.15,
        ),
    ];
    for (light, finish, object, want) in cases {
        for v in render(&scene(light, finish, object), 8, 1, 1) {
            assert!(
                (v - want).abs() < 1e-6,
                "{light} {finish} {object}: {v}, want {want}"
            );
        }
    }
}

/// A furnace inside a furnace: the camera inside a sphere of `diffuse a, b` and emission E
/// within a larger sphere of emission F (diffuse 0). Radiosity gathers the inner wall over
/// the front hemisphere and the outer one over the back, so with recursion_limit R the
/// inner wall is L_R, with L_0 = E and L_k = E + a L_(k-1) + b F (POV-Ray 3.7: 0.75 for
/// a = 0.5, b = 0.3, E = 0.2, F = 1.5, R = 1, exact 0.75; 1.02539 for R = 2, exact
/// 1.025). penumbra draws the side in proportion to a and b, so the mean is random beyond
/// the first bounce: within 3 standard errors.
#[test]
fn radiosity_gathers_behind_through_the_back_value() {
    for (r, a, b, e, f) in [
        (1, 0.5, 0.3, 0.2, 1.5),
        (2, 0.5, 0.3, 0.2, 1.5),
        (3, 0.7, 0.1, 0.1, 2.0),
        (2, 0.0, 0.8, 0.3, 0.5),
    ] {
        let source = format!(
            "#version 3.7;
global_settings {{ assumed_gamma 1 radiosity {{ recursion_limit {r} }} }}
camera {{ location <0.1, 0.05, 0> direction z up y right x }}
sphere {{ 0, 1 pigment {{ rgb 1 }} finish {{ ambient 0 emission {e} diffuse {a}, {b} }} }}
sphere {{ 0, 2 pigment {{ rgb 1 }} finish {{ ambient 0 emission {f} diffuse 0 }} }}
"
        );
        let want = (0..r).fold(e, |l, _| e + a * l + b * f);
        let (mean, se) = mean_and_error(&render(&source, 16, 16, 2));
        assert!(
            (mean - want).abs() <= 3.0 * se + 1e-6 * want,
            "R={r} a={a} b={b} E={e} F={f}: {mean} +- {se}, exact {want}"
        );
    }
}
