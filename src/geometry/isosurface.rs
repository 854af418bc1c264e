//! POV-Ray's isosurface: where a function equals the threshold, inside a container box or
//! sphere. Inside is where the function is below the threshold. Roots are found as POV-Ray
//! finds them, by subdividing the ray within the container and skipping any interval
//! where a function whose gradient is at most `max_gradient` cannot reach the threshold;
//! an interval shorter than `accuracy` that changes sign holds a crossing, which is then
//! bisected to full precision so that secondary rays leave the surface cleanly.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::DVec3;

use super::{Aabb, Ray};
use crate::function::Program;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    Box { min: DVec3, max: DVec3 },
    Sphere { center: DVec3, radius: f64 },
}

#[derive(Clone, Debug)]
pub struct IsoData {
    pub function: Arc<Program>,
    pub container: Container,
    pub threshold: f64,
    pub accuracy: f64,
    pub max_gradient: f64,
    /// `open`: the container's surface is not part of the shape.
    pub open: bool,
    /// The steepest gradient the search met, as f64 bits (positive floats order as
    /// their bits do), for POV-Ray's warning when it exceeds `max_gradient`.
    pub steepest: Arc<AtomicU64>,
    /// Where the scene declared it (file:line:column), for the warning.
    pub origin: Arc<str>,
}

impl PartialEq for IsoData {
    fn eq(&self, other: &Self) -> bool {
        self.function == other.function
            && self.container == other.container
            && (self.threshold, self.accuracy, self.max_gradient, self.open)
                == (
                    other.threshold,
                    other.accuracy,
                    other.max_gradient,
                    other.open,
                )
    }
}

/// Pending intervals of the subdivision; deeper than this the interval is far below any
/// accuracy a scene sets.
const STACK: usize = 64;
/// How close to its origin (relative to the container) a ray ignores the surface.
const DEPTH_TOLERANCE: f64 = 1e-9;

impl Container {
    pub fn bounds(&self) -> Aabb {
        match *self {
            Container::Box { min, max } => Aabb::new(min, max),
            Container::Sphere { center, radius } => {
                Aabb::new(center - DVec3::splat(radius), center + DVec3::splat(radius))
            }
        }
    }

    /// The container's span along the whole line, if the line meets it.
    fn span(&self, ray: &Ray) -> Option<(f64, f64)> {
        match *self {
            Container::Box { min, max } => {
                let inv = ray.direction.recip();
                let t1 = (min - ray.origin) * inv;
                let t2 = (max - ray.origin) * inv;
                let near = t1.min(t2).max_element();
                let far = t1.max(t2).min_element();
                (near <= far).then_some((near, far))
            }
            Container::Sphere { center, radius } => {
                let oc = ray.origin - center;
                let a = ray.direction.length_squared();
                let b = oc.dot(ray.direction);
                let disc = b * b - a * (oc.length_squared() - radius * radius);
                if disc < 0.0 {
                    return None;
                }
                let s = disc.sqrt();
                Some(((-b - s) / a, (-b + s) / a))
            }
        }
    }

    fn contains(&self, p: DVec3) -> bool {
        match *self {
            Container::Box { min, max } => p.cmpge(min).all() && p.cmple(max).all(),
            Container::Sphere { center, radius } => {
                (p - center).length_squared() <= radius * radius
            }
        }
    }

    /// Distance from the container's surface, and its outward normal there.
    fn surface(&self, p: DVec3) -> (f64, DVec3) {
        match *self {
            Container::Box { min, max } => {
                let c = (min + max) * 0.5;
                let h = ((max - min) * 0.5).max(DVec3::splat(1e-300));
                let q = p - c;
                let d = h - q.abs();
                let n = if d.x <= d.y && d.x <= d.z {
                    DVec3::new(q.x.signum(), 0.0, 0.0)
                } else if d.y <= d.z {
                    DVec3::new(0.0, q.y.signum(), 0.0)
                } else {
                    DVec3::new(0.0, 0.0, q.z.signum())
                };
                (d.min_element().abs(), n)
            }
            Container::Sphere { center, radius } => {
                let q = p - center;
                ((q.length() - radius).abs(), q)
            }
        }
    }
}

/// One interval of the subdivision with the function's values at its ends.
#[derive(Clone, Copy, Default)]
struct Interval {
    a: f64,
    fa: f64,
    b: f64,
    fb: f64,
}

impl IsoData {
    pub fn bounds(&self) -> Aabb {
        self.container.bounds()
    }

    /// The container's diagonal: tolerances are relative to it.
    fn scale(&self) -> f64 {
        let b = self.bounds();
        (b.max - b.min).length()
    }

    /// The function minus the threshold: negative inside.
    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        self.function.at(p) - self.threshold
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.container.contains(p) && self.value(p) < 0.0
    }

    /// Outward normal: the container's on its surface, else the function's gradient by
    /// central differences.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let scale = self.scale().max(1e-300);
        let (d, n) = self.container.surface(p);
        if !self.open && d <= 1e-7 * scale && self.value(p) < 0.0 {
            return n;
        }
        let h = 1e-6 * scale;
        let dx = DVec3::new(h, 0.0, 0.0);
        let dy = DVec3::new(0.0, h, 0.0);
        let dz = DVec3::new(0.0, 0.0, h);
        DVec3::new(
            self.value(p + dx) - self.value(p - dx),
            self.value(p + dy) - self.value(p - dy),
            self.value(p + dz) - self.value(p - dz),
        )
    }

    /// Calls `f` with each crossing along the whole line in increasing order until it
    /// returns false.
    pub fn each_hit(&self, ray: &Ray, f: impl FnMut(f64) -> bool) {
        self.hits_from(ray, f64::NEG_INFINITY, f);
    }

    /// As [`IsoData::each_hit`], from `t_min` on: a ray's first hit ahead need not search
    /// the container behind it.
    pub fn hits_from(&self, ray: &Ray, t_min: f64, mut f: impl FnMut(f64) -> bool) {
        let Some((enter, t1)) = self.container.span(ray) else {
            return;
        };
        if t1 < t_min {
            return;
        }
        let t0 = enter.max(t_min);
        let length = ray.direction.length();
        let skip = DEPTH_TOLERANCE * self.scale() / length.max(1e-300);
        let (f0, f1) = (self.value(ray.at(t0)), self.value(ray.at(t1)));
        if !self.open && enter >= t_min && f0 < 0.0 && t0.abs() > skip && !f(t0) {
            return;
        }
        let mut search = Search {
            iso: self,
            ray,
            length,
            steepest: 0.0,
        };
        let whole = Interval {
            a: t0,
            fa: f0,
            b: t1,
            fb: f1,
        };
        let go_on = search.roots(whole, skip, &mut f);
        if go_on && !self.open && f1 < 0.0 && t1.abs() > skip {
            f(t1);
        }
        self.note_gradient(search.steepest);
    }

    fn note_gradient(&self, g: f64) {
        let bits = g.to_bits();
        if g.is_finite() && bits > self.steepest.load(Ordering::Relaxed) {
            self.steepest.fetch_max(bits, Ordering::Relaxed);
        }
    }

    /// The steepest gradient met so far, if it exceeds `max_gradient`.
    pub fn gradient_exceeded(&self) -> Option<f64> {
        let g = f64::from_bits(self.steepest.load(Ordering::Relaxed));
        (g > self.max_gradient).then_some(g)
    }
}

struct Search<'a> {
    iso: &'a IsoData,
    ray: &'a Ray,
    length: f64,
    steepest: f64,
}

impl Search<'_> {
    /// Sign changes in `whole`, left to right; false once `f` asked to stop.
    fn roots(&mut self, whole: Interval, skip: f64, f: &mut impl FnMut(f64) -> bool) -> bool {
        let mut stack = [Interval::default(); STACK];
        stack[0] = whole;
        let mut n = 1;
        let reach = self.iso.max_gradient * self.length;
        while n > 0 {
            n -= 1;
            let i = stack[n];
            let width = i.b - i.a;
            if width > 0.0 {
                self.steepest = self
                    .steepest
                    .max((i.fb - i.fa).abs() / (width * self.length));
            }
            let same_sign = (i.fa < 0.0) == (i.fb < 0.0);
            if same_sign && i.fa.abs() + i.fb.abs() > reach * width {
                continue;
            }
            if width * self.length <= self.iso.accuracy || n + 2 > STACK {
                if !same_sign {
                    let t = self.refine(i);
                    if t.abs() > skip && !f(t) {
                        return false;
                    }
                }
                continue;
            }
            let m = 0.5 * (i.a + i.b);
            let fm = self.iso.value(self.ray.at(m));
            // Right half below the left, so the left is searched first.
            stack[n] = Interval { a: m, fa: fm, ..i };
            stack[n + 1] = Interval { b: m, fb: fm, ..i };
            n += 2;
        }
        true
    }

    /// Narrows a sign change to far below `accuracy` by the Illinois variant of regula
    /// falsi (a few evaluations where bisection needs forty), so that secondary rays
    /// leave the surface cleanly.
    fn refine(&self, mut i: Interval) -> f64 {
        let tolerance = 1e-10 * self.iso.scale() / self.length.max(1e-300);
        let mut side = 0i8;
        let mut last = f64::NAN;
        for _ in 0..48 {
            let mut c = (i.a * i.fb - i.b * i.fa) / (i.fb - i.fa);
            if !(c > i.a && c < i.b) {
                c = 0.5 * (i.a + i.b);
            }
            let fc = self.iso.value(self.ray.at(c));
            if fc == 0.0 || (c - last).abs() <= tolerance || i.b - i.a <= tolerance {
                return c;
            }
            last = c;
            if (fc < 0.0) == (i.fa < 0.0) {
                i.a = c;
                i.fa = fc;
                if side == -1 {
                    i.fb *= 0.5;
                }
                side = -1;
            } else {
                i.b = c;
                i.fb = fc;
                if side == 1 {
                    i.fa *= 0.5;
                }
                side = 1;
            }
        }
        0.5 * (i.a + i.b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::function::{Expr, Internal, compile};

    fn unit_sphere(open: bool) -> IsoData {
        let args = vec![Expr::Arg(0), Expr::Arg(1), Expr::Arg(2), Expr::Const(1.0)];
        IsoData {
            function: Arc::new(compile(&Expr::Internal(Internal::Sphere, args), 3).unwrap()),
            container: Container::Box {
                min: DVec3::splat(-1.5),
                max: DVec3::splat(1.5),
            },
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            open,
            steepest: Default::default(),
            origin: "test".into(),
        }
    }

    fn crossings(iso: &IsoData, ray: &Ray) -> Vec<f64> {
        let mut out = Vec::new();
        iso.each_hit(ray, |t| {
            out.push(t);
            true
        });
        out
    }

    #[test]
    fn grazing_rays_find_the_sphere_to_full_precision() {
        let iso = unit_sphere(false);
        // Rays along z at height h: the sphere is met where z = +-sqrt(1 - h^2).
        for h in [0.0, 0.5, 0.9, 0.99, 0.999, 0.9999] {
            let ray = Ray::new(DVec3::new(0.0, h, -5.0), DVec3::Z);
            let got = crossings(&iso, &ray);
            let z = (1.0 - h * h).sqrt();
            assert_eq!(got.len(), 2, "h = {h}: {got:?}");
            assert!((got[0] - (5.0 - z)).abs() < 1e-9, "h = {h}: {got:?}");
            assert!((got[1] - (5.0 + z)).abs() < 1e-9, "h = {h}: {got:?}");
        }
        for h in [1.0001, 1.01, 1.2] {
            let ray = Ray::new(DVec3::new(0.0, h, -5.0), DVec3::Z);
            assert!(crossings(&iso, &ray).is_empty(), "h = {h}");
        }
    }

    #[test]
    fn the_container_closes_what_the_function_leaves_open() {
        // x + 0.2 inside a box: the half-space x < -0.2 is cut by the box, whose faces are
        // part of the shape unless `open`.
        let mut iso = unit_sphere(false);
        let f = Expr::Math2(
            crate::function::Math2::Add,
            Box::new(Expr::Arg(0)),
            Box::new(Expr::Const(0.2)),
        );
        iso.function = Arc::new(compile(&f, 3).unwrap());
        let ray = Ray::new(DVec3::new(-5.0, 0.1, 0.3), DVec3::X);
        let got = crossings(&iso, &ray);
        assert_eq!(got.len(), 2, "{got:?}");
        assert!(
            (got[0] - 3.5).abs() < 1e-12 && (got[1] - 4.8).abs() < 1e-9,
            "{got:?}"
        );
        assert!(iso.inside(DVec3::new(-1.0, 0.0, 0.0)));
        assert!(!iso.inside(DVec3::new(0.0, 0.0, 0.0)));
        assert!(
            !iso.inside(DVec3::new(-2.0, 0.0, 0.0)),
            "outside the container"
        );
        iso.open = true;
        let got = crossings(&iso, &ray);
        assert_eq!(got.len(), 1, "{got:?}");
        assert_eq!(iso.normal(ray.at(got[0])).normalize(), DVec3::X);
    }

    #[test]
    fn a_steeper_function_than_max_gradient_is_reported() {
        let iso = unit_sphere(false);
        for h in [0.0, 0.3, 0.6] {
            crossings(&iso, &Ray::new(DVec3::new(0.0, h, -5.0), DVec3::Z));
        }
        assert!(
            iso.gradient_exceeded().is_none(),
            "|grad| of a distance is 1"
        );
        let mut steep = unit_sphere(false);
        steep.max_gradient = 0.5;
        crossings(&steep, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z));
        let g = steep.gradient_exceeded().expect("slope 1 against 0.5");
        assert!(g > 0.9 && g <= 1.0 + 1e-9, "{g}");
    }
}
