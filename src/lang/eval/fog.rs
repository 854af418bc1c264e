//! `fog { }`: POV-Ray's FOG_ITEMS, with its defaults (docs: fog_type 1, turb_depth 0.5,
//! octaves 6, omega 0.5, lambda 2, up y).

use super::super::diagnostics::Diagnostic;
use super::Evaluator;
use super::value::{Value, colour_of};
use crate::scene::{Fog, FogKind, FogTurbulence, Turbulence};

type R<T> = Result<T, Diagnostic>;

/// What the block has read so far: ground-fog and turbulence settings only take effect
/// with `fog_type 2` and `turbulence`, but may come in any order.
struct Draft {
    fog: Fog,
    ground: bool,
    offset: f64,
    alt: f64,
    turbulence: Option<Turbulence>,
    settings: Turbulence,
    depth: f64,
}

impl From<Fog> for Draft {
    /// A draft that starts from a fog (a declared one, or the defaults).
    fn from(mut fog: Fog) -> Draft {
        // Back to the fog's own up: the end of the block turns it by all the transforms.
        fog.up = fog
            .transform
            .inverse_vector(fog.up)
            .normalize_or(glam::DVec3::Y);
        let (ground, offset, alt) = match fog.kind {
            FogKind::Constant => (false, 0.0, 0.0),
            FogKind::Ground { offset, alt } => (true, offset, alt),
        };
        let turb = fog.turbulence;
        Draft {
            ground,
            offset,
            alt,
            turbulence: turb.map(|t| t.turbulence),
            settings: turb.map_or_else(Turbulence::default, |t| t.turbulence),
            depth: turb.map_or(0.5, |t| t.depth),
            fog,
        }
    }
}

impl Evaluator<'_> {
    pub(super) fn fog(&mut self) -> R<Fog> {
        self.next()?;
        let draft = Draft::from(Fog::default());
        let d = self.block_items("fog", "the fog", draft, |ev, tok, d| {
            let Some(word) = tok.ident() else {
                return Err(ev.stray_in_block(tok, "the fog"));
            };
            if ev.fog_item(d, word)? {
                return Ok(());
            }
            if let Some(t) = ev.transform_modifier()? {
                d.fog.transform = d.fog.transform.then(&t);
                return Ok(());
            }
            Err(ev.stray_in_block(tok, "the fog"))
        })?;
        let mut fog = d.fog;
        fog.up = fog.transform.vector(fog.up).normalize_or(glam::DVec3::Y);
        fog.kind = if d.ground {
            FogKind::Ground {
                offset: d.offset,
                alt: d.alt,
            }
        } else {
            FogKind::Constant
        };
        fog.turbulence = d.turbulence.map(|amount| FogTurbulence {
            turbulence: Turbulence {
                amount: amount.amount,
                ..d.settings
            },
            depth: d.depth,
        });
        Ok(fog)
    }

    /// One fog item; false if `word` is none (a transform, or a stray word).
    fn fog_item(&mut self, d: &mut Draft, word: &str) -> R<bool> {
        match word {
            "color" | "colour" | "rgb" | "rgbf" | "rgbt" | "rgbft" | "srgb" | "srgbf" | "srgbt"
            | "srgbft" => {
                let (c, _) = self.colour()?;
                d.fog.colour = colour_of(c);
                return Ok(true);
            }
            // A colour identifier or expression without the keyword, as POV-Ray reads it
            // (`fog { distance 200 Wheat * .5 }`, lights/circular.pov).
            _ if matches!(self.lookup(word), Some(Value::Colour(_))) => {
                let (v, span) = self.expr()?;
                d.fog.colour = colour_of(self.to_colour(&v, span)?);
                return Ok(true);
            }
            _ if matches!(self.lookup(word), Some(Value::Fog(_))) => {
                if let Some(Value::Fog(named)) = self.lookup(word).cloned() {
                    *d = Draft::from(*named);
                }
                self.next()?;
                return Ok(true);
            }
            "fog_type" | "distance" | "turbulence" | "turb_depth" | "octaves" | "omega"
            | "lambda" | "fog_offset" | "fog_alt" | "up" => {}
            _ => return Ok(false),
        }
        let tok = self.next()?;
        match word {
            "fog_type" => {
                let kind = self.float()?;
                if kind != 1.0 && kind != 2.0 {
                    return Err(self
                        .err(tok.span, format!("fog_type must be 1 or 2, found {kind}"))
                        .with_hint("1 is constant fog, 2 ground fog"));
                }
                d.ground = kind == 2.0;
            }
            "distance" => d.fog.distance = self.float()?,
            "turbulence" => {
                let (v, span) = self.expr()?;
                let amount = self.to_vec3(&v, span)?;
                d.turbulence = Some(Turbulence {
                    amount,
                    ..Turbulence::default()
                });
            }
            "turb_depth" => d.depth = self.float()?,
            "octaves" => d.settings.octaves = self.float()?.clamp(1.0, 10.0) as u32,
            "omega" => d.settings.omega = self.float()?,
            "lambda" => d.settings.lambda = self.float()?,
            "fog_offset" => d.offset = self.float()?,
            "fog_alt" => d.alt = self.float()?,
            _ => d.fog.up = self.vector3()?.normalize_or(glam::DVec3::Y),
        }
        Ok(true)
    }
}
