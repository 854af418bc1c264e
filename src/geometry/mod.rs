//! Geometry: rays, shapes, transforms, bounding boxes, and the render-ready scene.

mod transform;

pub use transform::Transform;
