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
mod prism;
mod profile;
mod ray;
mod revolve;
mod roots;
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
pub use shapes::{PolygonData, ShapeKind, ShapeTables, TriangleData};
pub use superellipsoid::Superellipsoid;
pub use transform::Transform;
pub use world::{
    CsgOp, Hit, Item, MaterialBlend, PREPARED_BYTES_PER_PRIMITIVE, Primitive, SurfacePoint,
    TexturePoint, World, WorldBuilder, flags,
};
