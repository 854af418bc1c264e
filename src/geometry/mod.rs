//! Geometry: rays, shapes, transforms, bounding boxes, the BVH, and the render-ready world.

mod aabb;
mod bicubic;
mod blob;
mod bvh;
mod height_field;
mod isosurface;
mod julia;
mod mesh;
mod poly;
mod polytope;
mod prism;
mod profile;
mod ray;
mod revolve;
mod roots;
mod shaft;
mod shapes;
mod superellipsoid;
mod transform;
mod world;

pub use aabb::Aabb;
pub use bicubic::{
    MAX_STEPS as BICUBIC_MAX_STEPS, Subdivision as BicubicSubdivision,
    tessellate as tessellate_bicubic,
};
pub use blob::{BlobData, BlobPart, OWN_TEXTURE};
pub use bvh::Bvh;
pub use height_field::HeightFieldData;
pub use isosurface::{Container, IsoData};
pub use julia::JuliaData;
pub use mesh::{MeshData, NONE as NO_INDEX};
pub use poly::{MAX_ORDER as POLY_MAX_ORDER, PolyData, term_count as poly_term_count};
pub use prism::PrismData;
pub use ray::{Ray, offset_point, offset_scale};
pub use revolve::{LatheData, SorData};
pub use shaft::Shaft;
pub use shapes::{
    LineInside, PolygonData, ShapeKind, ShapeTables, TriangleData, plane_hit, sphere_first_hit,
};
pub use superellipsoid::Superellipsoid;
pub use transform::Transform;
pub use world::{
    CsgOp, Hit, Item, MaterialBlend, NO_ITEM, Occluders, PREPARED_BYTES_PER_PRIMITIVE, Primitive,
    SurfacePoint, TexturePoint, World, WorldBuilder, flags,
};

/// A deterministic stream of uniform numbers in [0, 1) for tests (xorshift64): rays and
/// points that a seed makes the same on every machine.
#[cfg(test)]
pub(crate) fn uniform_stream(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}
