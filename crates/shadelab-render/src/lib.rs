//! The shadelab renderer on wgpu: adapter choice (headless or window), meshes on the GPU, one
//! pipeline per permutation (cached), capture to a linear float image, GPU timing. Knows nothing
//! of egui.

pub mod accuracy;
pub mod gpu;
pub mod renderer;
pub mod shaders;
pub mod sweep;
pub mod target;
pub mod timing;
pub mod uniforms;

pub use gpu::{AdapterChoice, Gpu};
pub use renderer::{PipelineKey, RenderSettings, Renderer, SceneGpu, Specialization, UploadError};
pub use target::{LinearImage, Target};

/// Render a scene offscreen to a linear float image: the path `shadelab render` and the image
/// tests share. Fails only for a scene the device cannot hold ([`UploadError`]).
pub fn render_image(
    gpu: &Gpu,
    scene: &shadelab_model::Scene,
    width: u32,
    height: u32,
    settings: &RenderSettings,
) -> Result<LinearImage, UploadError> {
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let gs = r.upload(scene)?;
    let target = Target::new(&gpu.device, width, height, target::HDR_FORMAT);
    r.render(&gs, scene, &target, settings);
    Ok(target::read_back(&gpu.device, &gpu.queue, &target))
}
