//! `media { }` and its `density { }` blocks (POV-Ray's MEDIA_ITEMS and DENSITY_ITEMS).

use glam::DVec3;

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::Value;
use crate::scene::{Media, Phase, Pigment, Scattering};

type R<T> = Result<T, Diagnostic>;

impl Evaluator<'_> {
    /// `media { ... }`, from the keyword.
    pub(super) fn media(&mut self) -> R<Media> {
        self.next()?;
        self.block_items("media", "the media", Media::default(), |ev, tok, m| {
            if let Some(t) = ev.transform_modifier()? {
                m.transform_by(&t);
                return Ok(());
            }
            let Some(word) = tok.ident() else {
                return Err(ev.stray_in_block(tok, "the media"));
            };
            if let Some(Value::Media(named)) = ev.lookup(word) {
                *m = (**named).clone();
                ev.next()?;
                return Ok(());
            }
            if !ev.media_item(m, word, tok)? {
                return Err(ev.stray_in_block(tok, "the media"));
            }
            Ok(())
        })
    }

    /// One media item; false if `word` is none.
    fn media_item(&mut self, m: &mut Media, word: &str, tok: &Token) -> R<bool> {
        match word {
            "absorption" | "emission" => {
                self.next()?;
                let (c, _) = self.colour()?;
                let c = DVec3::new(c[0], c[1], c[2]);
                if word == "absorption" {
                    m.absorption = c;
                } else {
                    m.emission = c;
                }
            }
            "scattering" => {
                self.next()?;
                m.scattering = Some(self.scattering()?);
            }
            "density" => {
                self.next()?;
                let d =
                    self.density_body(Pigment::solid(crate::scene::Colour::rgb(1.0, 1.0, 1.0)))?;
                m.densities.push(d);
            }
            "method" | "intervals" | "samples" | "confidence" | "variance" | "ratio" | "jitter"
            | "aa_level" | "aa_threshold" => {
                self.next()?;
                self.media_sampling_item(m, word, tok)?;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    fn media_sampling_item(&mut self, m: &mut Media, word: &str, tok: &Token) -> R<()> {
        let s = &mut m.sampling;
        let v = self.float()?;
        let count = |v: f64| v.clamp(1.0, 10_000.0) as u32;
        match word {
            "method" => {
                if ![1.0, 2.0, 3.0].contains(&v) {
                    return Err(self
                        .err(
                            tok.span,
                            format!("media method must be 1, 2 or 3, found {v}"),
                        )
                        .with_hint("3, adaptive sampling, is POV-Ray 3.7's default"));
                }
                s.method = v as u32;
            }
            "intervals" => s.intervals = count(v),
            "samples" => {
                let min = count(v);
                let max = if self.peek()?.is_punct(Punct::Comma) {
                    self.next()?;
                    count(self.float()?)
                } else {
                    min
                };
                s.samples = (min, max.max(min));
            }
            "confidence" => s.confidence = v,
            "variance" => s.variance = v,
            "ratio" => s.ratio = v,
            "jitter" => s.jitter = v,
            "aa_level" => s.aa_level = count(v),
            _ => s.aa_threshold = v,
        }
        Ok(())
    }

    /// `{ type, colour [eccentricity g] [extinction e] }` after `scattering`.
    fn scattering(&mut self) -> R<Scattering> {
        let open = self.expect(Punct::LBrace, "after `scattering`")?;
        self.enter(open.span)?;
        let r = self.scattering_items();
        self.leave();
        let s = r?;
        self.expect(Punct::RBrace, "to close the scattering")?;
        Ok(s)
    }

    fn scattering_items(&mut self) -> R<Scattering> {
        let kind_tok = self.peek()?;
        let kind = self.float()?;
        self.eat(Punct::Comma)?;
        let (c, _) = self.colour()?;
        let mut s = Scattering {
            phase: Phase::Isotropic,
            colour: DVec3::new(c[0], c[1], c[2]),
            extinction: 1.0,
        };
        let mut eccentricity = 0.0;
        loop {
            let tok = self.peek()?;
            match tok.ident() {
                Some("eccentricity") => {
                    if kind != 5.0 {
                        return Err(self
                            .err(tok.span, "`eccentricity` is only for scattering type 5")
                            .with_hint("type 5 is Henyey-Greenstein; POV-Ray rejects it too"));
                    }
                    self.next()?;
                    eccentricity = self.float()?;
                }
                Some("extinction") => {
                    self.next()?;
                    s.extinction = self.float()?;
                }
                _ if tok.is_punct(Punct::RBrace) => break,
                _ => return Err(self.stray_in_block(&tok, "the scattering")),
            }
        }
        s.phase = match kind as i64 {
            1 => Phase::Isotropic,
            2 => Phase::MieHazy,
            3 => Phase::MieMurky,
            4 => Phase::Rayleigh,
            5 => Phase::HenyeyGreenstein(eccentricity.clamp(-0.999, 0.999)),
            _ => {
                return Err(self
                    .err(
                        kind_tok.span,
                        format!("scattering type must be 1 to 5, found {kind}"),
                    )
                    .with_hint(
                        "1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein",
                    ));
            }
        };
        Ok(s)
    }

    /// `{ ... }` after `density`: a pigment whose colour scales the media, written with
    /// `density_map` where a pigment has `pigment_map`.
    pub(super) fn density_body(&mut self, base: Pigment) -> R<Pigment> {
        let was = std::mem::replace(&mut self.reading_density, true);
        let r = self.pigment_body(base);
        self.reading_density = was;
        r
    }
}
