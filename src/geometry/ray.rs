use glam::DVec3;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin: DVec3,
    pub direction: DVec3,
}

impl Ray {
    pub fn new(origin: DVec3, direction: DVec3) -> Ray {
        Ray { origin, direction }
    }

    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.direction * t
    }
}

/// How far a new ray must start from the surface it leaves. Floating-point error in a hit
/// point grows with its magnitude, so a single fixed epsilon breaks either for tiny or for
/// huge scenes; this bound follows the point's magnitude instead.
pub fn offset_scale(p: DVec3) -> f64 {
    (p.abs().max_element() + 1e-3) * 1e-11
}

/// Moves `p` off the surface with geometric normal `n`, to the side `towards` points to.
pub fn offset_point(p: DVec3, n: DVec3, towards: DVec3) -> DVec3 {
    let eps = offset_scale(p);
    if n.dot(towards) >= 0.0 {
        p + n * eps
    } else {
        p - n * eps
    }
}
