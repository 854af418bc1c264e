use glam::{DAffine3, DMat3, DVec3};

/// An affine map with its inverse kept beside it, because rays go into object space
/// (inverse) and normals come back by the inverse transpose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub forward: DAffine3,
    pub inverse: DAffine3,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::IDENTITY
    }
}

impl Transform {
    pub const IDENTITY: Transform = Transform {
        forward: DAffine3::IDENTITY,
        inverse: DAffine3::IDENTITY,
    };

    /// Builds from a forward map. Returns `None` for a singular map (a zero scale), which
    /// the language reports as an error instead of rendering NaNs.
    pub fn from_affine(forward: DAffine3) -> Option<Transform> {
        let det = forward.matrix3.determinant();
        if !det.is_finite() || det.abs() < 1e-300 {
            return None;
        }
        Some(Transform {
            forward,
            inverse: forward.inverse(),
        })
    }

    pub fn translate(v: DVec3) -> Transform {
        Transform {
            forward: DAffine3::from_translation(v),
            inverse: DAffine3::from_translation(-v),
        }
    }

    /// `None` when a component is zero.
    pub fn scale(v: DVec3) -> Option<Transform> {
        Transform::from_affine(DAffine3::from_scale(v))
    }

    /// POV-Ray's `rotate <a, b, c>`: about x by a degrees, then y by b, then z by c.
    /// With POV-Ray's left-handed axes these are the usual rotation matrices.
    pub fn rotate(degrees: DVec3) -> Transform {
        let r = DMat3::from_rotation_z(degrees.z.to_radians())
            * DMat3::from_rotation_y(degrees.y.to_radians())
            * DMat3::from_rotation_x(degrees.x.to_radians());
        Transform {
            forward: DAffine3::from_mat3(r),
            inverse: DAffine3::from_mat3(r.transpose()),
        }
    }

    /// This transform followed by `next`.
    pub fn then(&self, next: &Transform) -> Transform {
        Transform {
            forward: next.forward * self.forward,
            inverse: self.inverse * next.inverse,
        }
    }

    pub fn inverted(&self) -> Transform {
        Transform {
            forward: self.inverse,
            inverse: self.forward,
        }
    }

    pub fn is_identity(&self) -> bool {
        self.forward == DAffine3::IDENTITY
    }

    pub fn point(&self, p: DVec3) -> DVec3 {
        self.forward.transform_point3(p)
    }

    pub fn vector(&self, v: DVec3) -> DVec3 {
        self.forward.transform_vector3(v)
    }

    pub fn inverse_point(&self, p: DVec3) -> DVec3 {
        self.inverse.transform_point3(p)
    }

    pub fn inverse_vector(&self, v: DVec3) -> DVec3 {
        self.inverse.transform_vector3(v)
    }

    /// A world ray in the object's space. The direction is not normalised, so a distance
    /// along the local ray is the same distance along the world one.
    #[inline]
    pub fn inverse_ray(&self, ray: &super::Ray) -> super::Ray {
        super::Ray::new(
            self.inverse_point(ray.origin),
            self.inverse_vector(ray.direction),
        )
    }

    /// World-space normal to object space (the transpose), not normalised.
    pub fn inverse_normal(&self, n: DVec3) -> DVec3 {
        self.forward.matrix3.transpose() * n
    }

    /// Object-space normal to world space (inverse transpose), not normalised.
    pub fn normal(&self, n: DVec3) -> DVec3 {
        self.inverse.matrix3.transpose() * n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotate_y_turns_x_towards_minus_z() {
        // POV-Ray's left-hand rule: rotate y*90 takes +x to -z.
        let p = Transform::rotate(DVec3::new(0.0, 90.0, 0.0)).point(DVec3::X);
        assert!((p - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12, "{p}");
    }

    #[test]
    fn then_applies_in_order() {
        let t = Transform::scale(DVec3::splat(2.0))
            .unwrap()
            .then(&Transform::translate(DVec3::X));
        assert_eq!(t.point(DVec3::X), DVec3::new(3.0, 0.0, 0.0));
        assert!((t.inverse_point(DVec3::new(3.0, 0.0, 0.0)) - DVec3::X).length() < 1e-12);
    }

    #[test]
    fn zero_scale_is_rejected() {
        assert!(Transform::scale(DVec3::new(1.0, 0.0, 1.0)).is_none());
    }
}
