//! penumbra: a stochastic ray tracer for POV-Ray scenes that converges to POV-Ray 3.7's
//! image. Data flows one way:
//!
//! text --[lang]--> syntax tree --[lang::eval]--> [scene] model --[geometry] build-->
//! render-ready scene --[render] sampler + integrator--> film --[output]--> image files
//!
//! [study] holds the tools that measure the renderer against POV-Ray.

pub mod appearance;
pub mod function;
pub mod geometry;
pub mod lang;
pub mod output;
pub mod povray_args;
pub mod render;
pub mod render_job;
pub mod scene;
pub mod study;

use render::{Film, PreparedScene, Progress, RenderError, RenderOptions, RenderStats};

/// Renders a scene model into a linear image: builds the render-ready scene (BVH, baked
/// transforms), runs the sampler and integrator over tiles, and averages the film.
pub fn render_scene(
    scene: &scene::Scene,
    options: &RenderOptions,
    progress: &dyn Progress,
) -> Result<(output::Image, RenderStats), RenderError> {
    let (film, stats) = render_film(scene, options, progress)?;
    Ok((film_image(&film), stats))
}

/// Like [`render_scene`], but keeps the film's per-pixel sums (for merging sample ranges).
pub fn render_film(
    scene: &scene::Scene,
    options: &RenderOptions,
    progress: &dyn Progress,
) -> Result<(Film, RenderStats), RenderError> {
    let prepared = PreparedScene::new(scene);
    render::render(&prepared, options, progress)
}

/// The film's mean per pixel as an image.
pub fn film_image(film: &Film) -> output::Image {
    output::Image {
        width: film.width,
        height: film.height,
        pixels: film.means(),
    }
}

/// One line describing a scene, for `penumbra check`.
pub fn summary(scene: &scene::Scene) -> String {
    fn count(objects: &[scene::Object]) -> usize {
        objects
            .iter()
            .map(|o| match &o.shape {
                scene::Shape::Instance(shared) => count(std::slice::from_ref(&**shared)),
                shape => 1 + shape.children().map_or(0, count),
            })
            .sum()
    }
    let area = scene.lights.iter().filter(|l| l.area.is_some()).count();
    format!(
        "{} objects ({} top-level), {} lights ({} area), #version {}",
        count(&scene.objects),
        scene.objects.len(),
        scene.lights.len(),
        area,
        scene.version
    )
}
