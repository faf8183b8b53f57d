//! The shadelab renderer on wgpu: adapter choice (headless or window), meshes on the GPU, one
//! pipeline per permutation (cached), capture to a linear float image, GPU timing. Knows nothing
//! of egui.

mod buffers;
mod environment_gpu;
pub mod flip;
pub mod frame;
pub mod glass_pass;
mod glass_textures;
pub mod gpu;
pub mod image_error;
pub mod light_loop;
pub mod lighting_pass;
pub mod overlay_pass;
pub mod pipelines;
pub mod program;
pub mod renderer;
pub mod shaders;
mod shadow_maps;
pub mod shadow_pass;
pub mod sweep;
pub mod target;
mod textures;
pub mod timestamp_ring;
pub mod timing;
mod twins;
pub mod uniforms;
pub mod upload;
pub mod vertex;

pub use gpu::{AdapterChoice, Gpu};
pub use pipelines::{PipelineCache, PipelineKey};
pub use program::{Program, RenderSettings, Specialization};
pub use renderer::Renderer;
pub use target::{LinearImage, Target};
pub use upload::{SceneGpu, UploadError, Uploader};

/// Render a scene offscreen to a linear float image with the program `settings` resolve for it
/// ([`Program::for_scene`]): the path `shadelab render` and the image tests share. Fails only for
/// a scene the device cannot hold ([`UploadError`]).
pub fn render_image(
    gpu: &Gpu,
    scene: &shadelab_model::Scene,
    width: u32,
    height: u32,
    settings: &RenderSettings,
) -> Result<LinearImage, UploadError> {
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(scene)?;
    let target = Target::new(&gpu.device, width, height, target::HDR_FORMAT);
    r.render(&mut gs, scene, &target, settings);
    Ok(target::read_back(&gpu.device, &gpu.queue, &target))
}

/// The cast-shadow factor of `scene` (`terms::Term::Shadow`: its lit terms) as grey, what
/// `render --term shadow` writes: per pixel, the share of the light with cast shadows over that
/// without (`terms::shadow_factor`); the background stays as it is.
pub fn render_shadow_factor(
    gpu: &Gpu,
    scene: &shadelab_model::Scene,
    (width, height): (u32, u32),
    settings: &RenderSettings,
) -> Result<LinearImage, UploadError> {
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(scene)?;
    let target = Target::new(&gpu.device, width, height, target::HDR_FORMAT);
    Ok(shadow_factor_with(&mut r, &mut gs, scene, &target, settings))
}

/// The cast-shadow factor of `scene` drawn by `r` into `target` (an HDR target), the scene
/// already uploaded as `gs`: the frame with its shadows and without, read back and divided.
pub fn shadow_factor_with(
    r: &mut Renderer,
    gs: &mut SceneGpu,
    scene: &shadelab_model::Scene,
    target: &Target,
    settings: &RenderSettings,
) -> LinearImage {
    r.render(gs, scene, target, settings);
    let shadowed = target::read_back(&r.device, &r.queue, target);
    let mut off = scene.clone();
    off.set_shadows(false);
    r.render(gs, &off, target, settings);
    let unshadowed = target::read_back(&r.device, &r.queue, target);
    shadow_factor_image(&shadowed, &unshadowed)
}

/// The cast-shadow factor per pixel of two renders of the same frame, with cast shadows and
/// without (`terms::shadow_factor`), as grey; the background stays as it is.
pub fn shadow_factor_image(shadowed: &LinearImage, unshadowed: &LinearImage) -> LinearImage {
    let background = shadelab_model::scene::BACKGROUND.map(|c| c as f32);
    let rgb = |p: &[f32; 4]| [p[0] as f64, p[1] as f64, p[2] as f64];
    let pixels = shadowed
        .pixels
        .iter()
        .zip(&unshadowed.pixels)
        .map(|(s, u)| {
            if u[..3] == background {
                return *u;
            }
            let v = shadelab_model::terms::shadow_factor(rgb(s), rgb(u)) as f32;
            [v, v, v, 1.0]
        })
        .collect();
    LinearImage { width: shadowed.width, height: shadowed.height, pixels }
}
