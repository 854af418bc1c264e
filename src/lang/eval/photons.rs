//! The three `photons { }` blocks: in global_settings, in an object, in a light.

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use crate::scene::{LightPhotons, ObjectPhotons, PhotonSettings};

type R<T> = Result<T, Diagnostic>;

/// The most photons a scene may ask for: more would only exhaust memory in POV-Ray.
const MAX_COUNT: f64 = 1e9;

impl Evaluator<'_> {
    /// The block after `photons` in global_settings; a second block changes the first's
    /// values one by one.
    pub(super) fn photon_settings(&mut self, start: PhotonSettings) -> R<PhotonSettings> {
        self.block_items("photons", "the photons block", start, |ev, tok, p| {
            let Some(word) = tok.ident() else {
                return Err(ev.stray_in_block(tok, "the photons block"));
            };
            ev.next()?;
            ev.photon_setting(word, tok, p)
        })
    }

    fn photon_setting(&mut self, word: &str, tok: &Token, p: &mut PhotonSettings) -> R<()> {
        match word {
            "spacing" => {
                let (v, span) = self.expr()?;
                let s = self.to_float(&v, span)?;
                if !(s > 0.0 && s.is_finite()) {
                    return Err(self.err(span, "photon spacing must be greater than 0"));
                }
                p.spacing = Some(s);
            }
            "count" => {
                let (v, span) = self.expr()?;
                let c = self.to_float(&v, span)?;
                if !(1.0..=MAX_COUNT).contains(&c) {
                    return Err(self.err(span, "photon count must be between 1 and 1e9"));
                }
                p.count = Some(c as u32);
            }
            "max_trace_level" => p.max_trace_level = Some(self.float()?.clamp(1.0, 256.0) as u32),
            "adc_bailout" => p.adc_bailout = Some(self.float()?),
            "gather" => {
                let min = self.float()?.max(0.0) as u32;
                self.expect(Punct::Comma, "between gather's two counts")?;
                p.gather = (min, self.float()?.max(0.0) as u32);
            }
            "media" => {
                let steps = self.float()?.max(0.0) as u32;
                let factor = if self.eat(Punct::Comma)? {
                    self.float()?
                } else {
                    1.0
                };
                p.media = Some((steps, factor));
            }
            "jitter" => p.jitter = self.float()?,
            "autostop" => p.autostop = self.float()?,
            "radius" => p.radius = Some(self.photon_radius()?),
            "expand_thresholds" => {
                let f = self.float()?;
                self.expect(Punct::Comma, "between expand_thresholds' two values")?;
                p.expand_thresholds = (f, self.float()?.max(0.0) as u32);
            }
            // POV-Ray's map files: penumbra makes new photons for every sample.
            "save_file" | "load_file" => {
                self.expr()?;
            }
            _ => return Err(self.stray_in_block(tok, "the photons block")),
        }
        Ok(())
    }

    /// `radius [gather [, multiplier [, media gather [, media multiplier]]]]`: up to four
    /// floats, any of them left out; the first, if given, is kept.
    fn photon_radius(&mut self) -> R<f64> {
        let mut first = 0.0;
        for i in 0..4 {
            if i > 0 && !self.eat(Punct::Comma)? {
                break;
            }
            if self.starts_float()? {
                let f = self.float()?;
                if i == 0 {
                    first = f;
                }
            }
        }
        Ok(first)
    }

    /// An object's `photons { target [f] refraction on|off reflection on|off collect
    /// on|off pass_through }`, after the keyword.
    pub(super) fn object_photons(&mut self, start: ObjectPhotons) -> R<ObjectPhotons> {
        self.next()?;
        self.block_items(
            "photons",
            "the object's photons block",
            start,
            |ev, tok, p| {
                let word = tok.ident().unwrap_or("");
                match word {
                    "target" => {
                        ev.next()?;
                        if ev.starts_float()? {
                            ev.float()?;
                        }
                        p.target = true;
                    }
                    "refraction" => p.refraction = Some(ev.on_off()?),
                    "reflection" => p.reflection = Some(ev.on_off()?),
                    "collect" => p.no_collect = !ev.on_off()?,
                    "pass_through" => {
                        ev.next()?;
                        p.pass_through = ev.optional_bool()?;
                    }
                    "split_union" => {
                        ev.next()?;
                        ev.optional_bool()?;
                    }
                    _ => return Err(ev.stray_in_block(tok, "the object's photons block")),
                }
                Ok(())
            },
        )
    }

    /// A light's `photons { refraction on|off reflection on|off area_light }`, after the
    /// keyword.
    pub(super) fn light_photons(&mut self, start: LightPhotons) -> R<LightPhotons> {
        self.next()?;
        self.block_items(
            "photons",
            "the light's photons block",
            start,
            |ev, tok, p| {
                match tok.ident().unwrap_or("") {
                    "refraction" => p.refraction = Some(ev.on_off()?),
                    "reflection" => p.reflection = Some(ev.on_off()?),
                    "area_light" => {
                        ev.next()?;
                        p.area_light = ev.optional_bool()?;
                    }
                    _ => return Err(ev.stray_in_block(tok, "the light's photons block")),
                }
                Ok(())
            },
        )
    }

    /// The keyword, then `on`/`off` (or any boolean; nothing means on).
    fn on_off(&mut self) -> R<bool> {
        self.next()?;
        self.optional_bool()
    }
}
