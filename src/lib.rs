//! penumbra: a stochastic ray tracer for POV-Ray scenes that converges to POV-Ray 3.7's
//! image. Data flows one way:
//!
//! text --[lang]--> syntax tree --[lang::eval]--> [scene] model --[geometry] build-->
//! render-ready scene --[render] sampler + integrator--> film --[output]--> image files
//!
//! [study] holds the tools that measure the renderer against POV-Ray.

pub mod appearance;
pub mod geometry;
pub mod lang;
pub mod output;
pub mod render;
pub mod scene;
pub mod study;
