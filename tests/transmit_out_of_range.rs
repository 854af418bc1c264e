//! POV-Ray takes `transmit` literally outside [0, 1]: a surface of colour c and transmit t
//! in front of a background b shows (1 - t) c + t b, so `transmit -1` subtracts what lies
//! behind and `transmit 2` amplifies it (measured with POV-Ray 3.7: 0.702, 0.102 and 0.400
//! for t = -1, 2 and 0.5 with c = 0.5, b = 0.3; textures/pigments/transmitfx.pov shows
//! both).

use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::render::RenderOptions;

fn centre(transmit: f64) -> f32 {
    let source = format!(
        "#version 3.7;\nglobal_settings {{ assumed_gamma 1 }}\n\
         camera {{ orthographic location <0, 0, -4> look_at 0 }}\n\
         plane {{ z, 2 pigment {{ rgb 0.3 }} finish {{ ambient 1 diffuse 0 }} }}\n\
         plane {{ z, 0 pigment {{ rgb 0.5 transmit {transmit} }} finish {{ ambient 1 diffuse 0 }} }}\n"
    );
    let options = LoadOptions {
        image_width: 8,
        image_height: 6,
        ..LoadOptions::default()
    };
    let scene = load_scene_source("test.pov", &source, &options)
        .unwrap_or_else(|d| panic!("{d}"))
        .scene;
    let render = RenderOptions {
        width: 8,
        height: 6,
        samples_per_pixel: 4,
        seed: 1,
        ..RenderOptions::default()
    };
    let image = penumbra::render_scene(&scene, &render, &())
        .expect("render")
        .0;
    image.pixels[3 * 8 + 4][0]
}

#[test]
fn transmit_outside_zero_to_one_is_taken_literally() {
    for (t, expected) in [(-1.0, 0.7), (2.0, 0.1), (0.5, 0.4)] {
        let got = f64::from(centre(t));
        // Uniform colours: no noise, only float rounding.
        assert!(
            (got - expected).abs() < 1e-5,
            "transmit {t}: {got}, expected {expected}"
        );
    }
}
