//! POV-Ray's numbered internal functions (`function { internal(N) }`, which functions.inc
//! names `f_sphere` and so on). Each formula was fitted to values POV-Ray 3.7 prints with
//! `#debug` for the installed functions.inc; the tests in ../tests.rs hold those values.
//! The numbers not listed here are refused with a positioned error when used.

mod algebraic;
mod blobs;
mod curves;
pub(super) mod fractal;
mod helix;
mod hexagons;
mod tubes;

use glam::DVec3;

pub use algebraic::Field;
pub use curves::Curve;

use crate::appearance::noise::noise_with;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Internal {
    /// A field-strength algebraic surface (see algebraic.rs).
    Field(Field),
    /// A 2-D curve extruded or turned about y (see curves.rs).
    Curve(Curve),
    /// 6: POV-Ray's f_blob.
    Blob,
    /// 7: POV-Ray's f_blob2.
    Blob2,
    /// 10: POV-Ray's f_cross_ellipsoids.
    CrossEllipsoids,
    /// 19: POV-Ray's f_flange_cover.
    FlangeCover,
    /// 32: POV-Ray's f_isect_ellipsoids.
    IsectEllipsoids,
    /// 62: POV-Ray's f_spikes.
    Spikes,
    /// 63: POV-Ray's f_spikes_2d.
    Spikes2d,
    /// 25: POV-Ray's f_helix1.
    Helix1,
    /// 26: POV-Ray's f_helix2.
    Helix2,
    /// 27: POV-Ray's f_hex_x.
    HexX,
    /// 28: POV-Ray's f_hex_y.
    HexY,
    /// 29: POV-Ray's f_hetero_mf (matches in distribution only).
    HeteroMf,
    /// 58: POV-Ray's f_ridge (matches in distribution only).
    Ridge,
    /// 59: POV-Ray's f_ridged_mf (matches in distribution only).
    RidgedMf,
    /// 40: POV-Ray's f_mesh1.
    Mesh1,
    /// 51: POV-Ray's f_poly4.
    Poly4,
    /// 52: POV-Ray's f_polytubes.
    Polytubes,
    /// 64: POV-Ray's f_spiral.
    Spiral,
    /// 17: sqrt((P0 x)² + (P1 y)² + (P2 z)²) (POV-Ray subtracts nothing: the scenes use
    /// threshold 1).
    Ellipsoid,
    /// 47: the polar angle from +y, acos(y / r).
    Ph,
    /// 57: the distance from the origin.
    R,
    /// 60: a box of half-sizes P1..P3 with edges rounded by P0; inside, it is -P0 at most
    /// (not a signed distance): length(max(|p| - (s - r), 0)) - r, measured 1e-6 lower.
    RoundedBox,
    /// 61: distance from the origin minus the radius P0.
    Sphere,
    /// 68: 1 - ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2), e = P0, n = P1:
    /// positive inside, unlike the others.
    Superellipsoid,
    /// 69: the azimuth atan2(x, z).
    Th,
    /// 70: torus around y, major radius P0, minor radius P1.
    Torus,
    /// 76: POV-Ray's noise in [0, 1] (the default generator, 2).
    Noise3d,
    /// 78: noise under the generator P0.
    NoiseGenerator,
}

/// Number, internal function and its parameter count (x, y, z included), by number.
const TABLE: &[(u32, Internal, usize)] = &[
    (0, Internal::Curve(Curve::AlgbrCyl1), 8),
    (1, Internal::Curve(Curve::AlgbrCyl2), 8),
    (2, Internal::Curve(Curve::AlgbrCyl3), 8),
    (3, Internal::Curve(Curve::AlgbrCyl4), 8),
    (4, Internal::Field(Field::Bicorn), 5),
    (5, Internal::Field(Field::Bifolia), 5),
    (6, Internal::Blob, 8),
    (7, Internal::Blob2, 7),
    (8, Internal::Field(Field::BoySurface), 5),
    (10, Internal::CrossEllipsoids, 7),
    (11, Internal::Field(Field::CrossedTrough), 4),
    (12, Internal::Field(Field::CubicSaddle), 4),
    (13, Internal::Field(Field::Cushion), 4),
    (14, Internal::Field(Field::DevilsCurve), 4),
    (15, Internal::Curve(Curve::Devils), 9),
    (16, Internal::Field(Field::DupinCyclid), 9),
    (17, Internal::Ellipsoid, 6),
    (19, Internal::FlangeCover, 7),
    (20, Internal::Field(Field::FoliumSurface), 6),
    (21, Internal::Curve(Curve::Folium), 9),
    (22, Internal::Field(Field::Glob), 4),
    (23, Internal::Field(Field::Heart), 4),
    (25, Internal::Helix1, 10),
    (26, Internal::Helix2, 10),
    (27, Internal::HexX, 4),
    (28, Internal::HexY, 4),
    (29, Internal::HeteroMf, 9),
    (30, Internal::Field(Field::HuntSurface), 4),
    (31, Internal::Field(Field::HyperbolicTorus), 6),
    (32, Internal::IsectEllipsoids, 7),
    (33, Internal::Field(Field::KampyleOfEudoxus), 6),
    (34, Internal::Curve(Curve::Kampyle), 9),
    (35, Internal::Field(Field::KleinBottle), 4),
    (36, Internal::Field(Field::KummerV1), 4),
    (37, Internal::Field(Field::KummerV2), 7),
    (38, Internal::Field(Field::LemniscateOfGerono), 4),
    (39, Internal::Curve(Curve::Lemniscate), 9),
    (40, Internal::Mesh1, 8),
    (41, Internal::Field(Field::Mitre), 4),
    (42, Internal::Field(Field::NodalCubic), 4),
    (43, Internal::Field(Field::Cushion), 4),
    (44, Internal::Field(Field::OvalsOfCassini), 7),
    (45, Internal::Field(Field::Paraboloid), 4),
    (46, Internal::Field(Field::ParabolicTorus), 6),
    (47, Internal::Ph, 3),
    (48, Internal::Field(Field::Pillow), 4),
    (49, Internal::Field(Field::Piriform), 4),
    (50, Internal::Curve(Curve::Piriform), 10),
    (51, Internal::Poly4, 8),
    (52, Internal::Polytubes, 9),
    (54, Internal::Field(Field::QuarticParaboloid), 4),
    (55, Internal::Field(Field::QuarticSaddle), 4),
    (56, Internal::Field(Field::QuarticCylinder), 6),
    (57, Internal::R, 3),
    (58, Internal::Ridge, 9),
    (59, Internal::RidgedMf, 9),
    (60, Internal::RoundedBox, 7),
    (61, Internal::Sphere, 4),
    (62, Internal::Spikes, 8),
    (63, Internal::Spikes2d, 7),
    (64, Internal::Spiral, 9),
    (65, Internal::Field(Field::SteinersRoman), 4),
    (66, Internal::Field(Field::Strophoid), 7),
    (67, Internal::Curve(Curve::Strophoid), 10),
    (68, Internal::Superellipsoid, 5),
    (69, Internal::Th, 3),
    (70, Internal::Torus, 5),
    (71, Internal::Field(Field::Torus2), 6),
    (72, Internal::Field(Field::TorusGumdrop), 4),
    (73, Internal::Field(Field::Umbrella), 4),
    (74, Internal::Field(Field::WitchOfAgnesi), 5),
    (75, Internal::Curve(Curve::Witch), 9),
    (76, Internal::Noise3d, 3),
    (78, Internal::NoiseGenerator, 4),
];

/// Rounded boxes read this much lower than the formula in POV-Ray's output.
const ROUNDED_BOX_OFFSET: f64 = 1e-6;

impl Internal {
    pub fn numbered(n: u32) -> Option<Internal> {
        TABLE.iter().find(|e| e.0 == n).map(|e| e.1)
    }

    pub fn arity(self) -> usize {
        TABLE.iter().find(|e| e.1 == self).map_or(3, |e| e.2)
    }

    pub fn eval(self, a: &[f64]) -> f64 {
        let p = DVec3::new(a[0], a[1], a[2]);
        match self {
            Internal::Field(f) => f.eval(p, &a[3..]),
            Internal::Curve(f) => f.eval(p, &a[3..]),
            Internal::Blob => blobs::blob(p, &a[3..]),
            Internal::Blob2 => blobs::blob2(p, &a[3..]),
            Internal::CrossEllipsoids => blobs::crossed_ellipsoids(p, &a[3..], false),
            Internal::FlangeCover => blobs::flange_cover(p, &a[3..]),
            Internal::IsectEllipsoids => blobs::crossed_ellipsoids(p, &a[3..], true),
            Internal::Spikes => blobs::spikes(p, &a[3..]),
            Internal::Spikes2d => blobs::spikes_2d(p, &a[3..]),
            Internal::Helix1 => helix::helix1(p, &a[3..]),
            Internal::Helix2 => helix::helix2(p, &a[3..]),
            Internal::HexX => hexagons::hex_x(p),
            Internal::HexY => hexagons::hex_y(p),
            Internal::HeteroMf => fractal::hetero_mf(p, &a[3..]),
            Internal::Ridge => fractal::ridge(p, &a[3..]),
            Internal::RidgedMf => fractal::ridged_mf(p, &a[3..]),
            Internal::Mesh1 => tubes::mesh1(p, &a[3..]),
            Internal::Poly4 => tubes::poly4(p, &a[3..]),
            Internal::Polytubes => tubes::polytubes(p, &a[3..]),
            Internal::Spiral => helix::spiral(p, &a[3..]),
            Internal::Ellipsoid => (p * DVec3::new(a[3], a[4], a[5])).length(),
            Internal::Ph => {
                let r = p.length();
                if r == 0.0 { 0.0 } else { (p.y / r).acos() }
            }
            Internal::R => p.length(),
            Internal::RoundedBox => {
                let r = a[3];
                let q = p.abs() - (DVec3::new(a[4], a[5], a[6]) - r);
                q.max(DVec3::ZERO).length() - r - ROUNDED_BOX_OFFSET
            }
            Internal::Sphere => p.length() - a[3],
            Internal::Superellipsoid => superellipsoid(p, a[3], a[4]),
            Internal::Th => p.x.atan2(p.z),
            Internal::Torus => {
                let ring = p.x.hypot(p.z) - a[3];
                ring.hypot(p.y) - a[4]
            }
            Internal::Noise3d => noise_with(p, 2),
            Internal::NoiseGenerator => noise_with(p, a[3] as u8),
        }
    }
}

fn superellipsoid(p: DVec3, e: f64, n: f64) -> f64 {
    let p = p.abs();
    let xy = (p.x.powf(2.0 / e) + p.y.powf(2.0 / e)).powf(e / n);
    1.0 - (xy + p.z.powf(2.0 / n)).powf(n / 2.0)
}
