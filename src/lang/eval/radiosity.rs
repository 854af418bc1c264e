//! `radiosity { ... }` in global_settings, and in objects (`radiosity { importance f }`).

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use crate::scene::Radiosity;

type R<T> = Result<T, Diagnostic>;

/// POV-Ray refuses a recursion_limit outside this range (measured: 0 is a parse error).
const RECURSION_LIMITS: std::ops::RangeInclusive<f64> = 1.0..=20.0;

impl Evaluator<'_> {
    /// The block after `radiosity` in global_settings; a second block replaces the first's
    /// values one by one, as POV-Ray reads settings.
    pub(super) fn radiosity_block(&mut self, start: Radiosity) -> R<Radiosity> {
        self.block_items("radiosity", "the radiosity block", start, |ev, tok, r| {
            let Some(word) = tok.ident() else {
                return Err(ev.stray_in_block(tok, "the radiosity block"));
            };
            ev.next()?;
            ev.radiosity_item(word, tok, r)
        })
    }

    fn radiosity_item(&mut self, word: &str, tok: &Token, r: &mut Radiosity) -> R<()> {
        let c = &mut r.cache;
        match word {
            "recursion_limit" => {
                let (v, span) = self.expr()?;
                let f = self.to_float(&v, span)?;
                if !RECURSION_LIMITS.contains(&f.trunc()) {
                    return Err(self.err(span, "recursion_limit must be in the range 1 to 20"));
                }
                r.recursion_limit = f as u32;
            }
            "brightness" => r.brightness = self.float()?,
            "gray_threshold" => r.gray_threshold = self.float()?.clamp(0.0, 1.0),
            "normal" => r.normal = self.optional_bool()?,
            "media" => r.media = self.optional_bool()?,
            "count" => {
                c.count = self.float()?.max(1.0) as u32;
                if self.eat(Punct::Comma)? {
                    c.directions = self.float()?.max(0.0) as u32;
                }
            }
            "nearest_count" => {
                c.nearest_count = self.float()?.max(1.0) as u32;
                if self.eat(Punct::Comma)? {
                    c.nearest_count_min = self.float()?.max(0.0) as u32;
                }
            }
            "error_bound" => c.error_bound = self.float()?,
            "low_error_factor" => c.low_error_factor = self.float()?,
            "minimum_reuse" => c.minimum_reuse = self.float()?,
            "maximum_reuse" => c.maximum_reuse = self.float()?,
            "pretrace_start" => c.pretrace_start = self.float()?,
            "pretrace_end" => c.pretrace_end = self.float()?,
            "adc_bailout" => c.adc_bailout = self.float()?,
            "always_sample" => c.always_sample = self.optional_bool()?,
            "max_sample" => c.max_sample = self.float()?,
            "subsurface" => c.subsurface = self.optional_bool()?,
            // POV-Ray's cache files: nothing to read or write without a cache.
            "load_file" | "save_file" => {
                self.expr()?;
            }
            _ => return Err(self.stray_in_block(tok, "the radiosity block")),
        }
        Ok(())
    }

    /// `radiosity { importance f }` in an object: how many of POV-Ray's cache rays aim at
    /// it. penumbra samples every direction alike, so it is read and has no effect.
    pub(super) fn object_radiosity(&mut self) -> R<()> {
        self.next()?;
        self.block_items(
            "radiosity",
            "the object's radiosity block",
            (),
            |ev, tok, ()| {
                if tok.ident() != Some("importance") {
                    return Err(ev.stray_in_block(tok, "the object's radiosity block"));
                }
                ev.next()?;
                ev.float()?;
                Ok(())
            },
        )
    }
}
