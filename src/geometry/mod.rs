//! Geometry: rays, shapes, transforms, bounding boxes, the BVH, and the render-ready world.

mod aabb;
mod blob;
mod bvh;
mod ray;
mod roots;
mod shapes;
mod superellipsoid;
mod transform;
mod world;

pub use aabb::Aabb;
pub use blob::{BlobData, BlobPart};
pub use bvh::Bvh;
pub use ray::{Ray, offset_point, offset_scale};
pub use shapes::{PolygonData, ShapeKind, ShapeTables, TriangleData};
pub use superellipsoid::Superellipsoid;
pub use transform::Transform;
pub use world::{
    CsgOp, Hit, Item, Primitive, SurfacePoint, TexturePoint, World, WorldBuilder, flags,
};
