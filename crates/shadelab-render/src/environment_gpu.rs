//! The environment light on the GPU beside the frame: its nine SH terms, prefiltered levels and
//! occlusion grid, each computed and written only when what it depends on changed, and the
//! pipeline that draws it as the background (`background.wgsl`).

use crate::program::Program;
use crate::renderer::Renderer;
use crate::upload::SceneGpu;
use shadelab_model::Scene;

impl Renderer {
    /// The environment's SH terms, projected again only when the environment (or the sun it
    /// follows) changed since the last write: orbiting writes the uniforms every frame.
    pub(crate) fn env_sh(&self, gpu_scene: &mut SceneGpu, scene: &Scene) -> [[f32; 4]; 9] {
        let Some(env) = &scene.environment else { return [[0.0; 4]; 9] };
        let sun = env_sun(scene);
        let of = &mut gpu_scene.env_sh_of;
        match of.as_ref() {
            Some((e, s, sh)) if e == env && *s == sun => *sh,
            _ => {
                let sh = crate::uniforms::env_sh(env, &scene.lights);
                *of = Some((env.clone(), sun, sh));
                sh
            }
        }
    }

    /// The environment's occlusion grid's placement, the grid baked and written only when the
    /// geometry changed since the last write (the bake traces rays from every node).
    pub(crate) fn write_env_occlusion(&self, gpu_scene: &mut SceneGpu, scene: &Scene) -> [[f32; 4]; 2] {
        let key = crate::upload::OcclusionKey::of(scene);
        let of = &mut gpu_scene.env_occlusion_of;
        if let Some((k, placement)) = of.as_ref()
            && *k == key
        {
            return *placement;
        }
        use shadelab_model::lighting::occlusion::OCC_RAYS;
        let placement = match shadelab_model::reference::bake_occlusion(scene, OCC_RAYS, 1) {
            Some(grid) => {
                self.queue.write_buffer(&gpu_scene.env_occlusion, 0, bytemuck::cast_slice(&grid.gpu_words()));
                grid.gpu_placement()
            }
            None => [[0.0; 4]; 2],
        };
        *of = Some((key, placement));
        placement
    }

    /// The environment's prefiltered levels, computed and written only when the environment (or
    /// the sun it follows) changed since the last write.
    pub(crate) fn write_env_levels(&self, gpu_scene: &mut SceneGpu, scene: &Scene) {
        let Some(env) = &scene.environment else { return };
        let sun = env_sun(scene);
        let of = &mut gpu_scene.env_levels_of;
        if of.as_ref().is_some_and(|(e, s)| e == env && *s == sun) {
            return;
        }
        let levels = env.prefiltered(&scene.lights);
        self.queue.write_buffer(&gpu_scene.env_levels, 0, bytemuck::cast_slice(&levels));
        *of = Some((env.clone(), sun));
    }
}

/// The environment background's vertex and fragment stages (`background.wgsl`).
pub(crate) const BACKGROUND_ENTRY_POINTS: (&str, &str) = ("vs_background", "fs_background");

/// The environment background's pipeline of `program` from the cache, built on first use: one
/// triangle at the far plane, drawn where the depth is still the cleared far plane.
pub(crate) fn background_pipeline(
    cache: &mut crate::pipelines::PipelineCache,
    program: Program,
    format: wgpu::TextureFormat,
) -> &wgpu::RenderPipeline {
    let (effects, lights) = (program.effects(), program.light_loop());
    let key = crate::pipelines::PassKey { pass: "environment background", effects, lights, format: Some(format) };
    cache.pass_pipeline(key, |cx| {
        let options = wgpu::PipelineCompilationOptions { constants: &lights.constants(), ..Default::default() };
        cx.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("shadelab environment background"),
            layout: Some(&cx.layouts.background),
            vertex: wgpu::VertexState {
                module: cx.module,
                entry_point: Some(BACKGROUND_ENTRY_POINTS.0),
                compilation_options: options.clone(),
                buffers: &[],
            },
            primitive: Default::default(),
            depth_stencil: Some(crate::pipelines::depth_tested_over()),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: cx.module,
                entry_point: Some(BACKGROUND_ENTRY_POINTS.1),
                compilation_options: options,
                targets: &[crate::pipelines::opaque_target(format)],
            }),
            multiview_mask: None,
            cache: None,
        })
    })
}

/// The direction of the light a sky follows (the first directional light's), part of the key of
/// what the frame keeps of an environment.
fn env_sun(scene: &Scene) -> Option<glam::DVec3> {
    scene.lights.iter().find(|l| l.kind.is_directional()).map(|l| l.direction)
}
