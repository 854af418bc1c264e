//! `rainbow { }`: POV-Ray's RAINBOW_ITEMS (docs: arc_angle and falloff_angle, jitter 0,
//! up y); what they do is in render::rainbow.

use super::super::diagnostics::Diagnostic;
use super::Evaluator;
use crate::scene::Rainbow;

type R<T> = Result<T, Diagnostic>;

/// What the block has read: the arc's two angles may come in either order.
#[derive(Default)]
struct Draft {
    rainbow: Rainbow,
    arc: Option<f64>,
    falloff: Option<f64>,
}

impl Evaluator<'_> {
    pub(super) fn rainbow(&mut self) -> R<Rainbow> {
        self.next()?;
        let d = self.block_items("rainbow", "the rainbow", Draft::default(), |ev, tok, d| {
            let Some(word) = tok.ident() else {
                return Err(ev.stray_in_block(tok, "the rainbow"));
            };
            let r = &mut d.rainbow;
            match word {
                "direction" | "up" => {
                    ev.next()?;
                    let v = ev.vector3()?.normalize_or_zero();
                    if v == glam::DVec3::ZERO {
                        return Err(ev.err(tok.span, format!("the rainbow's `{word}` is zero")));
                    }
                    *(if word == "up" {
                        &mut r.up
                    } else {
                        &mut r.direction
                    }) = v;
                }
                "angle" | "width" | "distance" | "jitter" => {
                    ev.next()?;
                    let v = ev.float()?;
                    *(match word {
                        "angle" => &mut r.angle,
                        "width" => &mut r.width,
                        "distance" => &mut r.distance,
                        _ => &mut r.jitter,
                    }) = v;
                }
                "arc_angle" => d.arc = Some(ev.next().and_then(|_| ev.float())?),
                "falloff_angle" => d.falloff = Some(ev.next().and_then(|_| ev.float())?),
                "color_map" | "colour_map" => {
                    ev.next()?;
                    r.colour_map = ev.colour_map_body()?;
                }
                _ => return Err(ev.stray_in_block(tok, "the rainbow")),
            }
            Ok(())
        })?;
        let mut rainbow = d.rainbow;
        // Only a given arc_angle cuts the ring; without a falloff_angle its edge is sharp
        // (measured).
        rainbow.arc = d.arc.map(|a| (a, d.falloff.unwrap_or(a)));
        Ok(rainbow)
    }
}
