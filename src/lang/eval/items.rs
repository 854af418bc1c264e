//! Top-level items (camera, lights, background, global settings, objects) and the values a
//! `#declare` can hold.

use glam::DVec3;

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token, TokenKind};
use super::Evaluator;
use super::value::{ObjectValue, Value, transform_light};
use crate::scene::{AreaLight, CameraSpec, Light, LightKind, Projection};

type R<T> = Result<T, Diagnostic>;

/// Features POV-Ray has at the top level that penumbra does not model yet.
const UNSUPPORTED_ITEMS: &[&str] = &["photons"];

impl Evaluator<'_> {
    pub(super) fn item(&mut self) -> R<()> {
        let tok = self.peek()?;
        let Some(word) = tok.ident() else {
            return Err(self.expected("an object, a camera, a light or a directive", &tok));
        };
        match word {
            "camera" => {
                let spec = self.camera_block()?;
                self.scene.camera = spec.resolve();
            }
            "background" => {
                let open = self.block_start("background")?;
                let (c, _) = self.colour()?;
                self.scene.background = super::value::colour_of(c);
                self.block_end(open, "the background")?;
            }
            "global_settings" => self.global_settings()?,
            "sky_sphere" => {
                let sky = self.sky_sphere()?;
                self.scene.sky_sphere = Some(sky);
            }
            "fog" => {
                let fog = self.fog()?;
                self.scene.fogs.push(fog);
            }
            "rainbow" => {
                let rainbow = self.rainbow()?;
                self.scene.rainbows.push(rainbow);
            }
            "media" => {
                let media = self.media()?;
                self.scene.media.push(media);
            }
            // POV-Ray still reads the old form of `#default` without the `#`.
            "default" => {
                self.next()?;
                self.default_directive()?;
            }
            "light_source" => {
                let light = self.light_source()?;
                self.scene.lights.push(light);
            }
            _ if super::objects::is_object_keyword(word) => {
                let o = self.object()?;
                self.add_object(o, tok.span)?;
            }
            _ if UNSUPPORTED_ITEMS.contains(&word) => {
                let word = word.to_string();
                self.unsupported_or_skip(&tok, &word)?;
            }
            _ if super::objects::is_known_unsupported_shape(word)
                && self.lookup(word).is_none() =>
            {
                let word = word.to_string();
                self.unsupported_or_skip(&tok, &word)?;
            }
            _ => {
                if let Some(o) = self.named_object()? {
                    return self.add_object(o, tok.span);
                }
                if let Some(v) = self.lookup(word) {
                    let hint = format!("`{word}` is {}", v.kind_name());
                    return Err(self
                        .err(
                            tok.span,
                            format!("expected an object, a camera, a light or a directive, found `{word}`"),
                        )
                        .with_hint(hint));
                }
                if super::keywords::is_keyword(word) {
                    if super::objects::is_known_unsupported_shape(word) {
                        return Err(self.unsupported(&tok, word));
                    }
                    return Err(self.expected("an object, a camera, a light or a directive", &tok));
                }
                return Err(self.unknown_identifier(&tok, word));
            }
        }
        Ok(())
    }

    pub(super) fn add_object(&mut self, o: ObjectValue, span: crate::lang::Span) -> R<()> {
        if let Some(mut object) = o.object {
            // Only a changed default needs writing down: `None` already means the built-in
            // default texture to the renderer.
            if object.texture.is_none()
                && let Some(shared) = &self.changed_default
            {
                object.texture = Some(shared.clone());
            }
            let objects = &mut self.scene.objects;
            if objects.len() == objects.capacity() {
                // The list doubles: its new capacity is charged (its slack included).
                let more = objects.capacity().max(64);
                let bytes = (more * std::mem::size_of::<crate::scene::Object>()) as u64;
                self.charge(bytes, super::budget::Growth::Objects(0), span)?;
                self.scene.objects.reserve_exact(more);
            }
            self.scene.objects.push(object);
        }
        self.scene.lights.extend(o.lights);
        Ok(())
    }

    /// What may follow `#declare Name =`.
    pub(super) fn declared_value(&mut self) -> R<Value> {
        let tok = self.peek()?;
        let Some(word) = tok.ident() else {
            return Ok(self.expr()?.0);
        };
        if self.lookup(word).is_some() {
            return Ok(self.expr()?.0);
        }
        Ok(match word {
            _ if super::objects::is_object_keyword(word) => {
                let mut value = self.object()?;
                // Placed many times, a large object is shared rather than copied.
                value.object = value.object.map(crate::scene::Object::shared_if_large);
                Value::Object(Box::new(value))
            }
            "light_source" => Value::Object(Box::new(ObjectValue {
                object: None,
                lights: vec![self.light_source()?],
            })),
            "camera" => Value::Camera(Box::new(self.camera_block()?)),
            "sky_sphere" => Value::SkySphere(Box::new(self.sky_sphere()?)),
            "fog" => Value::Fog(Box::new(self.fog()?)),
            "media" => Value::Media(Box::new(self.media()?)),
            "density" => {
                self.next()?;
                let white = crate::scene::Pigment::solid(crate::scene::Colour::rgb(1.0, 1.0, 1.0));
                Value::Pigment(Box::new(self.density_body(white)?))
            }
            "pigment" => {
                self.next()?;
                Value::Pigment(Box::new(
                    self.pigment_body(self.default_texture.pigment.clone())?,
                ))
            }
            "finish" => {
                self.next()?;
                Value::Finish(Box::new(self.finish_body(self.default_texture.finish)?))
            }
            "color_map" | "colour_map" => {
                self.next()?;
                Value::Pigment(Box::new(self.declared_colour_map()?))
            }
            "texture" => {
                self.next()?;
                let t = self.texture_body(self.default_texture.clone())?;
                let t = self.more_layers(t)?;
                Value::Texture(Box::new(t))
            }
            "interior" => {
                self.next()?;
                Value::Interior(Box::new(
                    self.interior_body(crate::scene::Interior::default())?,
                ))
            }
            "normal" => {
                self.next()?;
                Value::Normal(Box::new(self.normal_body(None)?))
            }
            "material" => {
                self.next()?;
                let mut holder = crate::scene::Object::new(crate::scene::Shape::Union(Vec::new()));
                self.material_body(&mut holder)?;
                Value::Material(Box::new((
                    holder.texture.map(std::sync::Arc::unwrap_or_clone),
                    holder.interior.map(|i| *i),
                )))
            }
            "transform" => {
                self.next()?;
                Value::Transform(Box::new(self.transform_block()?))
            }
            "array" => self.array_value()?,
            "function" => Value::Function(std::rc::Rc::new(self.function_value()?)),
            "spline" => Value::Spline(std::rc::Rc::new(self.spline_value()?)),
            _ if super::keywords::is_keyword(word)
                && !super::keywords::is_expression_keyword(word) =>
            {
                return Err(self.unsupported(&tok, word));
            }
            _ => self.expr()?.0,
        })
    }

    /// `keyword {`: consumes both and returns the brace token for error messages.
    pub(super) fn block_start(&mut self, keyword: &str) -> R<Token> {
        self.next()?;
        let open = self.expect_lazy(Punct::LBrace, || format!("after `{keyword}`"))?;
        self.enter(open.span)?;
        Ok(open)
    }

    /// The closing brace of a block opened with [`Evaluator::block_start`].
    pub(super) fn block_end(&mut self, _open: Token, what: &str) -> R<()> {
        self.leave();
        self.expect_lazy(Punct::RBrace, || format!("to close {what}"))?;
        Ok(())
    }

    /// `{ items }` after `keyword`, for blocks that are a list of items: one place for the
    /// nesting guard, the stop at `}` and the error when it is missing. `item` reads one
    /// item, starting at the token given, into `state`.
    pub(super) fn block_items<T>(
        &mut self,
        keyword: &str,
        what: &str,
        mut state: T,
        mut item: impl FnMut(&mut Self, &Token, &mut T) -> R<()>,
    ) -> R<T> {
        let open = self.expect(Punct::LBrace, &format!("after `{keyword}`"))?;
        self.enter(open.span)?;
        let r = (|| -> R<()> {
            loop {
                let tok = self.peek()?;
                if tok.is_punct(Punct::RBrace) {
                    return Ok(());
                }
                item(self, &tok, &mut state)?;
            }
        })();
        self.leave();
        r?;
        self.expect(Punct::RBrace, &format!("to close {what}"))?;
        Ok(state)
    }

    /// The error for a token that does not belong in a block: unsupported feature, unknown
    /// name, or a missing `}`.
    pub(super) fn stray_in_block(&self, tok: &Token, what: &str) -> Diagnostic {
        if let TokenKind::Ident(word) = &tok.kind
            && self.lookup(word).is_none()
        {
            if !super::keywords::is_keyword(word) {
                return self.unknown_identifier(tok, word);
            }
            if !TOP_LEVEL_ONLY.contains(&&**word) && !super::objects::is_object_keyword(word) {
                return self.unsupported(tok, word);
            }
        }
        self.expected(&format!("`}}` to close {what}"), tok)
    }

    fn sky_sphere(&mut self) -> R<crate::scene::SkySphere> {
        let sky = crate::scene::SkySphere {
            pigments: Vec::new(),
            emission: DVec3::ONE,
        };
        self.next()?;
        self.block_items("sky_sphere", "the sky_sphere", sky, |ev, tok, sky| {
            match tok.ident() {
                Some("pigment") => {
                    ev.next()?;
                    let p = ev.pigment_body(crate::scene::Pigment::default())?;
                    sky.pigments.push(p);
                }
                Some("emission") => {
                    ev.next()?;
                    let (c, _) = ev.colour()?;
                    sky.emission = DVec3::new(c[0], c[1], c[2]);
                }
                Some(word) if matches!(ev.lookup(word), Some(Value::SkySphere(_))) => {
                    if let Some(Value::SkySphere(named)) = ev.lookup(word).cloned() {
                        *sky = *named;
                    }
                    ev.next()?;
                }
                _ => {
                    if let Some(t) = ev.transform_modifier()? {
                        for p in &mut sky.pigments {
                            p.transform_by(&t);
                        }
                        return Ok(());
                    }
                    return Err(ev.stray_in_block(tok, "the sky_sphere"));
                }
            }
            Ok(())
        })
    }

    fn camera_block(&mut self) -> R<CameraSpec> {
        self.next()?;
        self.block_items(
            "camera",
            "the camera",
            CameraSpec::default(),
            |ev, tok, spec| {
                let Some(word) = tok.ident() else {
                    return Err(ev.stray_in_block(tok, "the camera"));
                };
                if let Some(projection) = projection_keyword(word) {
                    ev.next()?;
                    spec.projection = projection;
                    return Ok(());
                }
                match word {
                    "cylinder" => {
                        let tok = ev.next()?;
                        let kind = ev.float()?;
                        if ![1.0, 2.0, 3.0, 4.0].contains(&kind) {
                            return Err(ev.err(
                                tok.span,
                                format!("cylinder camera type {kind} is not 1, 2, 3 or 4"),
                            ));
                        }
                        spec.projection = Projection::Cylinder(kind as u8);
                    }
                    "location" | "look_at" | "right" | "up" | "direction" | "sky" => {
                        let word = word.to_string();
                        ev.next()?;
                        let v = ev.vector3()?;
                        match word.as_str() {
                            "location" => spec.location = v,
                            "look_at" => spec.look_at = Some(v),
                            "right" => {
                                spec.right = v;
                                spec.up_or_right_given = true;
                            }
                            "up" => {
                                spec.up = v;
                                spec.up_or_right_given = true;
                            }
                            "direction" => spec.direction = v,
                            _ => spec.sky = v,
                        }
                    }
                    "angle" => {
                        ev.next()?;
                        spec.angle = Some(ev.float()?);
                        // `angle h, v` (spherical).
                        if ev.eat(Punct::Comma)? {
                            spec.vertical_angle = Some(ev.float()?);
                        }
                    }
                    "aperture" | "focal_point" | "blur_samples" | "confidence" | "variance" => {
                        ev.next()?;
                        ev.focal_blur_setting(word, spec)?;
                    }
                    "normal" => {
                        ev.next()?;
                        spec.normal = ev.normal_body(spec.normal.take())?;
                    }
                    "mesh_camera" => {
                        let rig = ev.mesh_camera_block(tok)?;
                        spec.mesh = Some(super::mesh_camera::shared(rig));
                        spec.projection = Projection::Mesh;
                    }
                    _ => {
                        if let Some(Value::Camera(c)) = ev.lookup(word).cloned() {
                            ev.next()?;
                            *spec = *c;
                            return Ok(());
                        }
                        if let Some(t) = ev.transform_modifier()? {
                            spec.transform = spec.transform.then(&t);
                            return Ok(());
                        }
                        return Err(ev.stray_in_block(tok, "the camera"));
                    }
                }
                Ok(())
            },
        )
    }

    /// A focal blur keyword's value (the keyword read). `confidence` and `variance` set
    /// POV-Ray's rule for stopping a pixel's lens samples early (src/render/camera.rs).
    fn focal_blur_setting(&mut self, word: &str, spec: &mut CameraSpec) -> R<()> {
        match word {
            "aperture" => spec.aperture = self.float()?.max(0.0),
            "focal_point" => spec.focal_point = self.vector3()?,
            "blur_samples" => {
                spec.blur_samples = self.float()?.max(0.0) as u32;
                // POV-Ray 3.7 also takes `blur_samples min, max`.
                if self.eat(Punct::Comma)? {
                    spec.blur_samples = self.float()?.max(0.0) as u32;
                    spec.blur_minimum = true;
                }
            }
            "confidence" => spec.blur_confidence = self.float()?,
            _ => spec.blur_variance = self.float()?.max(0.0),
        }
        Ok(())
    }

    pub(super) fn light_source(&mut self) -> R<Light> {
        let open = self.block_start("light_source")?;
        let mut d = LightDraft::new(self.light_start()?);
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            let Some(word) = tok.ident() else {
                return Err(self.stray_in_block(&tok, "the light_source"));
            };
            let word = word.to_string();
            let known = self.area_light_item(&mut d.area, &word)?
                || self.light_kind_item(&mut d, &word)?
                || self.light_item(&mut d.light, &word)?;
            if known {
                continue;
            }
            let Some(t) = self.transform_modifier()? else {
                return Err(self.stray_in_block(&tok, "the light_source"));
            };
            d.transform(&t);
        }
        let light = d.finish();
        self.block_end(open, "the light_source")?;
        Ok(light)
    }

    /// `Name` (a declared light) or `location, colour`: what a light block starts with.
    fn light_start(&mut self) -> R<Light> {
        let mut light = Light::point(DVec3::ZERO, DVec3::ONE);
        let first = self.peek()?;
        if let Some(Value::Object(o)) = first.ident().and_then(|w| self.lookup(w)).cloned() {
            if let Some(l) = o.lights.first() {
                self.next()?;
                light = l.clone();
            }
        } else {
            light.location = self.vector3()?;
            self.eat(Punct::Comma)?;
            let (c, _) = self.colour()?;
            light.colour = DVec3::new(c[0], c[1], c[2]);
        }
        Ok(light)
    }

    /// `area_light` and the items that shape it; false for other words.
    fn area_light_item(&mut self, area: &mut (bool, AreaLight), word: &str) -> R<bool> {
        let (has_area, pending) = area;
        match word {
            "area_light" => {
                self.next()?;
                let axis1 = self.vector3()?;
                self.eat(Punct::Comma)?;
                let axis2 = self.vector3()?;
                self.eat(Punct::Comma)?;
                let size1 = self.count()?;
                self.eat(Punct::Comma)?;
                let size2 = self.count()?;
                pending.axis1 = axis1;
                pending.axis2 = axis2;
                pending.size1 = size1;
                pending.size2 = size2;
                *has_area = true;
            }
            "adaptive" => {
                self.next()?;
                let k = self.float()?;
                pending.adaptive = Some(k.max(0.0) as u32);
            }
            // Without an `area_light` these do nothing, as in POV-Ray; they are kept
            // in case the `area_light` comes later in the block.
            "jitter" => {
                self.next()?;
                pending.jitter = true;
            }
            "circular" => {
                self.next()?;
                pending.circular = true;
            }
            "orient" => {
                self.next()?;
                pending.orient = true;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `spotlight`, `parallel`, `cylinder` and their cone; false for other words.
    fn light_kind_item(&mut self, d: &mut LightDraft, word: &str) -> R<bool> {
        match word {
            "spotlight" => {
                self.next()?;
                d.spot = true;
            }
            "parallel" => {
                self.next()?;
                d.parallel = true;
            }
            "cylinder" => {
                self.next()?;
                d.cylinder = true;
            }
            "point_at" => {
                self.next()?;
                d.point_at = self.vector3()?;
            }
            "radius" => {
                self.next()?;
                d.radius = self.float()?;
            }
            "falloff" => {
                self.next()?;
                d.falloff = self.float()?;
            }
            "tightness" => {
                self.next()?;
                d.tightness = self.float()?;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// Colour, fading, shadows and `looks_like`; false for other words.
    fn light_item(&mut self, light: &mut Light, word: &str) -> R<bool> {
        match word {
            "color" | "colour" | "rgb" | "rgbf" | "rgbt" | "rgbft" | "srgb" => {
                let (c, _) = self.colour()?;
                light.colour = DVec3::new(c[0], c[1], c[2]);
            }
            "shadowless" => {
                self.next()?;
                light.shadowless = true;
            }
            "area_illumination" => {
                self.next()?;
                light.area_illumination = self.optional_bool()?;
            }
            "media_attenuation" => {
                self.next()?;
                light.media_attenuation = self.optional_bool()?;
            }
            "media_interaction" => {
                self.next()?;
                light.media_interaction = self.optional_bool()?;
            }
            "fade_distance" => {
                self.next()?;
                light.fade_distance = self.float()?;
            }
            "fade_power" => {
                self.next()?;
                light.fade_power = self.float()?;
            }
            "looks_like" => {
                let open = self.block_start("looks_like")?;
                let value = match self.named_object()? {
                    Some(o) => o,
                    None => self.object()?,
                };
                self.block_end(open, "looks_like")?;
                if let Some(mut object) = value.object {
                    // The object is modelled at the origin and travels with the light;
                    // it must not shadow the light it surrounds.
                    object.transform_by(&crate::scene::Transform::translate(light.location));
                    object.flags.no_shadow = true;
                    light.looks_like = Some(Box::new(object));
                }
            }
            "photons" => light.photons = self.light_photons(light.photons)?,
            "projected_through" => {
                let open = self.block_start("projected_through")?;
                let value = match self.named_object()? {
                    Some(o) => o,
                    None => self.object()?,
                };
                self.block_end(open, "projected_through")?;
                light.projected_through = value
                    .object
                    .map(|object| super::texture::built_for_tests(Some(object)));
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// A positive whole number (grid sizes).
    fn count(&mut self) -> R<u32> {
        let (v, s) = self.expr()?;
        let f = self.to_float(&v, s)?;
        if !(1.0..=1e6).contains(&f) {
            return Err(self.err(s, format!("expected a count of at least 1, found {f}")));
        }
        Ok(f as u32)
    }

    /// A keyword like `hollow` that may be followed by a boolean.
    pub(super) fn optional_bool(&mut self) -> R<bool> {
        if self.starts_float()? {
            let f = self.float()?;
            return Ok(f.abs() > 1e-10);
        }
        Ok(true)
    }

    /// Whether the next token begins a float expression (for optional arguments).
    pub(super) fn starts_float(&mut self) -> R<bool> {
        let tok = self.peek()?;
        Ok(match &tok.kind {
            TokenKind::Number(_) => true,
            TokenKind::Punct(p) => {
                matches!(p, Punct::Minus | Punct::Plus | Punct::LParen | Punct::Bang)
            }
            TokenKind::Ident(w) => {
                matches!(&**w, "true" | "false" | "on" | "off" | "yes" | "no" | "pi")
                    || super::keywords::is_function(w)
                    || matches!(self.lookup(w), Some(Value::Float(_)))
            }
            _ => false,
        })
    }

    fn global_settings(&mut self) -> R<()> {
        self.next()?;
        self.block_items("global_settings", "global_settings", (), |ev, tok, ()| {
            let Some(word) = tok.ident() else {
                return Err(ev.stray_in_block(tok, "global_settings"));
            };
            let word = word.to_string();
            ev.next()?;
            match word.as_str() {
                "assumed_gamma" => ev.scene.settings.assumed_gamma = Some(ev.float()?),
                "max_trace_level" => {
                    let f = ev.float()?;
                    ev.scene.settings.max_trace_level = f.clamp(1.0, 256.0) as u32;
                }
                "adc_bailout" => ev.scene.settings.adc_bailout = ev.float()?,
                "photons" => {
                    let start = ev.scene.settings.photons.unwrap_or_default();
                    ev.scene.settings.photons = Some(ev.photon_settings(start)?);
                }
                "radiosity" => {
                    let start = ev.scene.settings.radiosity.unwrap_or_default();
                    ev.scene.settings.radiosity = Some(ev.radiosity_block(start)?);
                }
                "ambient_light" => {
                    let (c, _) = ev.colour()?;
                    ev.scene.settings.ambient_light = DVec3::new(c[0], c[1], c[2]);
                }
                "noise_generator" => {
                    let g = ev.float()?;
                    ev.scene.settings.noise_generator = g.clamp(1.0, 3.0) as u8;
                }
                "max_intersections" | "number_of_waves" => {
                    ev.float()?;
                }
                // The output file's format (grey 16-bit, for height fields); the image
                // rendered is the same.
                "hf_gray_16" => {
                    ev.optional_bool()?;
                }
                "charset" => {
                    ev.next()?;
                }
                "irid_wavelength" => {
                    let (c, _) = ev.colour()?;
                    ev.scene.settings.irid_wavelength = super::value::colour_of(c).rgb;
                }
                _ if ev.skip_unsupported
                    && super::keywords::is_keyword(&word)
                    && ev.lookup(&word).is_none() =>
                {
                    ev.warn(
                        tok.span,
                        format!("unsupported: `{word}` is not supported yet; it is left out"),
                    );
                    ev.skip_feature_body()?;
                }
                _ => return Err(ev.stray_in_block(tok, "global_settings")),
            }
            Ok(())
        })
    }
}

/// A light while its block is read: the kind and the area light are only settled at the
/// end, since `spotlight`, `radius` or `area_light` may come in any order.
struct LightDraft {
    light: Light,
    /// Whether there is an area light, and its settings so far.
    area: (bool, AreaLight),
    spot: bool,
    parallel: bool,
    cylinder: bool,
    point_at: DVec3,
    radius: f64,
    falloff: f64,
    tightness: f64,
}

impl LightDraft {
    fn new(light: Light) -> LightDraft {
        let has_area = light.area.is_some();
        let pending = light.area.unwrap_or(AreaLight {
            axis1: DVec3::ZERO,
            axis2: DVec3::ZERO,
            size1: 1,
            size2: 1,
            adaptive: None,
            jitter: false,
            circular: false,
            orient: false,
        });
        let (point_at, radius, falloff, tightness) = match light.kind {
            LightKind::Point => (DVec3::Z, 30.0, 45.0, 0.0),
            LightKind::Spot {
                point_at,
                radius,
                falloff,
                tightness,
            }
            | LightKind::Cylinder {
                point_at,
                radius,
                falloff,
                tightness,
            } => (point_at, radius, falloff, tightness),
            LightKind::Parallel { point_at } => (point_at, 30.0, 45.0, 0.0),
        };
        LightDraft {
            spot: matches!(light.kind, LightKind::Spot { .. }),
            parallel: matches!(light.kind, LightKind::Parallel { .. }),
            cylinder: matches!(light.kind, LightKind::Cylinder { .. }),
            light,
            area: (has_area, pending),
            point_at,
            radius,
            falloff,
            tightness,
        }
    }

    /// Writes the kind and area light read so far into the light.
    fn settle(&mut self) {
        self.light.kind = kind_of(
            self.spot,
            self.parallel,
            self.cylinder,
            self.point_at,
            self.radius,
            self.falloff,
            self.tightness,
        );
        let (has_area, pending) = self.area;
        self.light.area = has_area.then_some(pending);
    }

    /// Transforms the light, keeping the spotlight target in its kind while doing so.
    fn transform(&mut self, t: &crate::scene::Transform) {
        self.settle();
        transform_light(&mut self.light, t);
        if let Some(a) = self.light.area {
            self.area.1 = a;
        }
        self.point_at = match self.light.kind {
            LightKind::Spot { point_at, .. }
            | LightKind::Cylinder { point_at, .. }
            | LightKind::Parallel { point_at } => point_at,
            LightKind::Point => t.point(self.point_at),
        };
    }

    fn finish(mut self) -> Light {
        self.settle();
        self.light
    }
}

fn kind_of(
    spot: bool,
    parallel: bool,
    cylinder: bool,
    point_at: DVec3,
    radius: f64,
    falloff: f64,
    tightness: f64,
) -> LightKind {
    if cylinder {
        LightKind::Cylinder {
            point_at,
            radius,
            falloff,
            tightness,
        }
    } else if parallel {
        LightKind::Parallel { point_at }
    } else if spot {
        LightKind::Spot {
            point_at,
            radius,
            falloff,
            tightness,
        }
    } else {
        LightKind::Point
    }
}

/// Items that are only valid at the top of a file: inside a block they mean a `}` is missing.
const TOP_LEVEL_ONLY: &[&str] = &["camera", "global_settings", "background", "light_source"];

/// Whether a word begins a scene statement (an object, a light, the camera ...), which no
/// value's expression can continue with.
pub fn starts_statement(word: &str) -> bool {
    TOP_LEVEL_ONLY.contains(&word)
        || matches!(word, "sky_sphere" | "fog" | "rainbow" | "media")
        || super::objects::is_object_keyword(word)
        || super::objects::is_known_unsupported_shape(word)
}

/// The projection a camera keyword names (`cylinder` takes a number and is read apart).
fn projection_keyword(word: &str) -> Option<Projection> {
    Some(match word {
        "perspective" => Projection::Perspective,
        "orthographic" => Projection::Orthographic,
        "fisheye" => Projection::Fisheye,
        "ultra_wide_angle" => Projection::UltraWideAngle,
        "panoramic" => Projection::Panoramic,
        "omnimax" => Projection::Omnimax,
        "spherical" => Projection::Spherical,
        _ => return None,
    })
}
