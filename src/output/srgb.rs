//! The sRGB transfer curve (IEC 61966-2-1), which POV-Ray 3.7 applies to PNG output by
//! default. Computed in `f64` so that encoding and decoding round-trip 16-bit codes exactly.

/// Linear value to sRGB-encoded value, both nominally in [0, 1]; no clamping.
pub fn encode(linear: f64) -> f64 {
    if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    }
}

/// sRGB-encoded value to linear value; no clamping.
pub fn decode(encoded: f64) -> f64 {
    if encoded <= 0.040_45 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// Quantises a linear value to an integer code in 0..=max_code, rounding to nearest after
/// clamping to [0, 1]. NaN becomes 0 and +inf becomes max_code, so a broken pixel is visible
/// but cannot abort writing the rest of the image.
pub fn quantize(linear: f32, max_code: u32) -> u32 {
    let v = if linear.is_nan() {
        0.0
    } else {
        f64::from(linear).clamp(0.0, 1.0)
    };
    (encode(v) * f64::from(max_code)).round() as u32
}

/// [`quantize`] to 8 bits without a power per value: the code is the number of the 255
/// code thresholds (the least `f32` that reaches each code, found once by bisection over
/// `quantize` itself) at or below the value. Same codes, as `quantize` rises with its
/// input; the power was a tenth of a one-sample 640x480 render's instructions.
pub fn quantize8(linear: f32) -> u8 {
    if linear.is_nan() {
        return 0;
    }
    let thresholds = THRESHOLDS8.get_or_init(thresholds8);
    thresholds.partition_point(|&t| t <= linear) as u8
}

static THRESHOLDS8: std::sync::OnceLock<[f32; 255]> = std::sync::OnceLock::new();

/// For codes 1 to 255, the least non-negative `f32` that `quantize` maps to that code or
/// above (non-negative floats order as their bit patterns).
fn thresholds8() -> [f32; 255] {
    std::array::from_fn(|i| {
        let code = i as u32 + 1;
        let (mut low, mut high) = (0u32, 1.0f32.to_bits());
        while low < high {
            let mid = low + (high - low) / 2;
            if quantize(f32::from_bits(mid), 255) >= code {
                high = mid;
            } else {
                low = mid + 1;
            }
        }
        f32::from_bits(low)
    })
}

/// The linear value an integer code stands for.
pub fn dequantize(code: u32, max_code: u32) -> f32 {
    decode(f64::from(code) / f64::from(max_code)) as f32
}
