//! Appearance: what colour a surface point has (patterns, pigments) and how it answers light
//! (finish). Everything here follows what POV-Ray 3.7 computes (shared/pov-semantics.md),
//! including where that is not physical.

pub mod finish;
pub mod pigment;

pub use pigment::evaluate_pigment;
