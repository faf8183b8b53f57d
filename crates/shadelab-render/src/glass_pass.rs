//! The glass pass on the GPU (docs/transparency.md; only in programs with transparent objects):
//! after the opaque scene, each transparent object far to near, over a copy of the target as it
//! stands (what is behind it, the farther glass included), reading the opaque depth; a mesh's
//! back faces drawn just before it give its exit (`shaders/glass.wgsl`).

use crate::glass_textures::{BACK_FORMAT, GlassTextures};
use crate::pipelines::{PassKey, PipelineCache, depth_state, opaque_target, triangles};
use crate::program::Program;
use crate::renderer::Renderer;
use crate::target::{Target, color_attachment};
use crate::upload::{MeshGpu, SceneGpu};
use crate::vertex::SmoothVertex;
use shadelab_model::Scene;
use shadelab_model::effects::{Effect, EffectKey};

/// The glass pipelines' entry points: the object over what is behind it, and a mesh's back faces.
pub const GLASS_ENTRY_POINTS: (&str, &str) = ("vs_phong", "fs_glass");
pub const BACK_ENTRY_POINTS: (&str, &str) = ("vs_phong", "fs_glass_back");

/// Begin the pass that draws a transparent object over `target`, testing against its opaque depth
/// without writing it; `end`: the timestamp slot it writes at its end (the last object's pass).
fn front_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    target: &Target,
    end: Option<(&wgpu::QuerySet, u32)>,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("shadelab glass"),
        color_attachments: &[color_attachment(&target.color_view, wgpu::LoadOp::Load)],
        // Read-only: the pass tests against the opaque depth and samples it.
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: &target.depth_view,
            depth_ops: None,
            stencil_ops: None,
        }),
        timestamp_writes: end.map(|(qs, i)| wgpu::RenderPassTimestampWrites {
            query_set: qs,
            beginning_of_pass_write_index: None,
            end_of_pass_write_index: Some(i),
        }),
        occlusion_query_set: None,
        multiview_mask: None,
    })
}

/// Set object `i`'s globals, uniforms and mesh buffers on `pass` (its surface attributes when the
/// program reads them, `surfaces`), ready for its indexed draw.
fn set_object(pass: &mut wgpu::RenderPass<'_>, gpu_scene: &SceneGpu, i: usize, mesh: &MeshGpu, surfaces: bool) {
    pass.set_bind_group(0, &gpu_scene.globals_bind, &[]);
    pass.set_bind_group(1, gpu_scene.object_bind(i), &[(i as u64 * gpu_scene.object_stride) as u32]);
    pass.set_vertex_buffer(0, mesh.smooth.slice(..));
    if surfaces && let Some(s) = &mesh.surface {
        pass.set_vertex_buffer(1, s.slice(..));
    }
    pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
}

/// The transparent objects of `scene` the glass pass draws, far to near by the distance from the
/// eye to each object's centre (a later one is drawn over the copy that holds the earlier ones).
pub fn glass_order(scene: &Scene) -> Vec<usize> {
    let eye = scene.camera.eye_h();
    let mut order: Vec<(f64, usize)> = (0..scene.objects.len())
        .filter(|&i| scene.drawn_as_glass(i))
        .map(|i| {
            let c = scene.objects[i].transform.translation;
            // An orthographic view (w = 0) sorts along its direction.
            let key = if eye.w == 0.0 { -c.dot(eye.truncate()) } else { c.distance(eye.truncate()) };
            (key, i)
        })
        .collect();
    order.sort_by(|a, b| b.0.total_cmp(&a.0));
    order.into_iter().map(|(_, i)| i).collect()
}

/// The glass pass's pipeline of `program` from the cache (`back`: a mesh's back faces), built on
/// first use.
fn glass_pipeline(
    cache: &mut PipelineCache,
    program: Program,
    format: wgpu::TextureFormat,
    back: bool,
) -> &wgpu::RenderPipeline {
    let (effects, lights) = (program.effects(), program.light_loop());
    let pass = if back { "glass back faces" } else { "glass" };
    let key = PassKey { pass, effects, lights, format: Some(format) };
    cache.pass_pipeline(key, |cx| {
        let layout = match (back, effects.has(Effect::CastShadows)) {
            (true, _) => &cx.layouts.glass_back,
            (false, false) => &cx.layouts.glass,
            (false, true) => &cx.layouts.glass_shadows,
        };
        build_pipeline(cx.device, layout, cx.module, effects, &lights.constants(), format, back)
    })
}

/// Build one of the glass pipelines: `back` draws a mesh's back faces into the two back targets,
/// otherwise the object's front faces over the target, depth-tested against the opaque scene
/// without writing it.
fn build_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    effects: EffectKey,
    constants: &[(&str, f64)],
    color_format: wgpu::TextureFormat,
    back: bool,
) -> wgpu::RenderPipeline {
    let (vs, fs) = if back { BACK_ENTRY_POINTS } else { GLASS_ENTRY_POINTS };
    let options = wgpu::PipelineCompilationOptions { constants, ..Default::default() };
    let buffers = &crate::vertex::buffers(SmoothVertex::LAYOUT, effects);
    let targets = if back { vec![opaque_target(BACK_FORMAT); 2] } else { vec![opaque_target(color_format)] };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(if back { "shadelab glass back faces" } else { "shadelab glass" }),
        layout: Some(layout),
        vertex: wgpu::VertexState { module, entry_point: Some(vs), compilation_options: options.clone(), buffers },
        // Meshes wind their triangles counter-clockwise seen from outside.
        primitive: triangles(Some(if back { wgpu::Face::Front } else { wgpu::Face::Back })),
        depth_stencil: Some(depth_state(back, wgpu::CompareFunction::Less, Default::default())),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fs),
            compilation_options: options,
            targets: &targets,
        }),
        multiview_mask: None,
        cache: None,
    })
}

impl Renderer {
    /// Record the glass pass of `program` after its scene pass: each transparent object in
    /// `order` over a copy of the target, a mesh's back faces first. `shadows`: the maps' bind
    /// group when the program has cast shadows; `end`: the timestamp slot the last pass writes.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn encode_glass(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        gpu_scene: &SceneGpu,
        target: &Target,
        program: crate::program::Program,
        order: &[usize],
        shadows: Option<&wgpu::BindGroup>,
        end: Option<(&wgpu::QuerySet, u32)>,
    ) {
        let fits = self.glass.as_ref().is_some_and(|g| g.size == (target.width, target.height, target.format));
        if !fits {
            self.glass = Some(GlassTextures::new(&self.device, target));
        }
        let bind = self.glass.as_mut().expect("made above").bind_group(&self.device, &self.glass_layout, target);
        let exits = gpu_scene.glass_exits.clone();
        let fx = program.effects();
        let surfaces = fx.samples_textures() || fx.has(Effect::VertexColors);
        let front = glass_pipeline(&mut self.pipelines, program, target.format, false).clone();
        // The back-face pipeline only where some object in the pass is a mesh.
        let needs_back = |i: &usize| exits.get(*i).copied() == Some(shadelab_model::lighting::transmission::SHAPE_MESH);
        let back = order
            .iter()
            .any(needs_back)
            .then(|| glass_pipeline(&mut self.pipelines, program, target.format, true).clone());
        let g = self.glass.as_ref().expect("made above");
        for (n, &i) in order.iter().enumerate() {
            let Some(mesh) = gpu_scene.objects.get(i).and_then(|k| gpu_scene.meshes.get(k)) else { continue };
            // What is behind the object, the farther glass included.
            encoder.copy_texture_to_texture(
                target.color.as_image_copy(),
                g.behind.as_image_copy(),
                wgpu::Extent3d { width: target.width, height: target.height, depth_or_array_layers: 1 },
            );
            if let Some(back) = back.as_ref().filter(|_| needs_back(&i)) {
                let mut pass = g.back_faces_pass(encoder);
                pass.set_pipeline(back);
                set_object(&mut pass, gpu_scene, i, mesh, surfaces);
                pass.draw_indexed(0..mesh.index_count, 0, 0..1);
            }
            let last = n + 1 == order.len();
            let mut pass = front_pass(encoder, target, end.filter(|_| last));
            pass.set_pipeline(&front);
            if let Some(maps) = shadows {
                pass.set_bind_group(2, maps, &[]);
            }
            pass.set_bind_group(3, &bind, &[]);
            set_object(&mut pass, gpu_scene, i, mesh, surfaces);
            pass.draw_indexed(0..mesh.index_count, 0, 0..1);
        }
    }
}
