//! Appearance: what colour a surface point has (patterns, pigments, textures) and how it
//! answers light (finish). Everything here follows what POV-Ray 3.7 computes
//! (shared/pov-semantics.md), including where that is not physical.

pub mod blend;
pub mod crackle;
pub mod finish;
pub mod fractal;
pub mod noise;
pub mod normal;
pub mod pattern;
pub mod pigment;
pub mod sky;
pub mod texture;
pub mod tiling;
pub mod warps;

pub use pigment::evaluate_pigment;
pub use sky::sky_colour;
pub use texture::{Layer, Layers, blended_layers, may_transmit, perturbed_normal, texture_layers};
