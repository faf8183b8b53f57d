//! One frame: the scene's parameters written into its uniforms, and the scene pass recorded
//! with the pipeline of a given [`Program`] into a target (offscreen image or the viewer's
//! texture), after the shadow passes when the program has cast shadows (`shadow_pass.rs`).

use crate::pipelines::PipelineKey;
use crate::program::{Program, RenderSettings};
use crate::renderer::Renderer;
use crate::target::{Target, color_attachment};
use crate::uniforms::{GlobalsUniform, ObjectUniform};
use crate::upload::SceneGpu;
use shadelab_model::Scene;
use shadelab_model::effects::Effect;

impl Renderer {
    /// Write a scene's parameters (materials, lights, camera) into its uniforms. Cheap: the
    /// viewer calls it whenever a parameter changes; geometry stays.
    pub fn write_uniforms(&self, gpu_scene: &mut SceneGpu, scene: &Scene, target: &Target, settings: &RenderSettings) {
        self.write_uniforms_for(gpu_scene, scene, target, settings, Program::for_scene(scene, settings));
    }

    /// [`Self::write_uniforms`] for the program already derived for this scene and these settings
    /// (the viewer derives it once per change). Counts the write in `gpu_scene.uniform_writes`.
    pub fn write_uniforms_for(
        &self,
        gpu_scene: &mut SceneGpu,
        scene: &Scene,
        target: &Target,
        settings: &RenderSettings,
        program: Program,
    ) {
        gpu_scene.uniform_writes += 1;
        self.write_tables(program);
        gpu_scene.clear = crate::uniforms::clear_color(scene);
        let flags = if settings.debug_nonfinite { crate::uniforms::FLAG_DEBUG_NONFINITE } else { 0 }
            | settings.glass_view.code() << crate::uniforms::GLASS_VIEW_SHIFT;
        let env_sh = self.env_sh(gpu_scene, scene);
        let mut g = GlobalsUniform::new(scene, target.width, target.height, flags, settings.specular, env_sh);
        if program.effects().has(Effect::EnvironmentOcclusion) {
            g.env_occlusion = self.write_env_occlusion(gpu_scene, scene);
        }
        self.queue.write_buffer(&gpu_scene.globals, 0, bytemuck::bytes_of(&g));
        let mut bytes = vec![0u8; (gpu_scene.object_stride as usize) * scene.objects.len()];
        let mut exits = Vec::with_capacity(scene.objects.len());
        for (i, o) in scene.objects.iter().enumerate() {
            let mut u = ObjectUniform::new(scene, i, o);
            if settings.glass_exit == shadelab_model::lighting::transmission::GlassExit::BackFaces {
                u.exit_shape = shadelab_model::lighting::transmission::SHAPE_MESH;
            }
            exits.push(u.exit_shape);
            let at = i * gpu_scene.object_stride as usize;
            bytes[at..at + size_of::<ObjectUniform>()].copy_from_slice(bytemuck::bytes_of(&u));
        }
        self.queue.write_buffer(&gpu_scene.objects_buf, 0, &bytes);
        gpu_scene.glass_exits = exits;
        gpu_scene.glass_order = crate::glass_pass::glass_order(scene);
        let background = program.effects().has(Effect::EnvironmentBackground);
        gpu_scene.env_background = background;
        if program.effects().has(Effect::EnvironmentSpecular) || background {
            self.write_env_levels(gpu_scene, scene);
        }
        let shadows = program.effects().has(Effect::CastShadows);
        self.write_shadows(gpu_scene, scene, shadows, target.width as f64 / target.height.max(1) as f64);
    }

    /// Record the scene pass of `program` into `encoder`, drawing into `target` with the uniforms
    /// last written. With background builds on, a program whose pipeline is not built yet draws
    /// with the uber pipeline of its shading meanwhile. `timestamps` (a query set and the index
    /// of its first of two slots) brackets the passes when the device has them: the shadow passes
    /// too, when the program has cast shadows (they are part of its cost).
    pub fn encode(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        gpu_scene: &mut SceneGpu,
        target: &Target,
        program: Program,
        timestamps: Option<(&wgpu::QuerySet, u32)>,
    ) {
        // A scene without texture coordinates or vertex colours has no buffer for them to read.
        let program = if gpu_scene.has_surfaces { program } else { program.without_surfaces() };
        let key = self.pipelines.ready_key(PipelineKey { program, color_format: target.format });
        let shadows = key
            .program
            .effects()
            .has(Effect::CastShadows)
            .then(|| self.encode_shadow_passes(encoder, gpu_scene, timestamps));
        // The rest of the frame only reads the scene's state.
        let gpu_scene: &SceneGpu = gpu_scene;
        let mut begun = shadows.as_ref().is_some_and(|s| s.1);
        let flat = key.program.draws_flat_mesh();
        let lit_pass = key.program.lighting_pass();
        let layouts = (&self.flat_compute_layout, &self.flat_colors_layout);
        let fx = key.program.effects();
        // The surface buffer feeds any texture's coordinates and the vertex colours; the lighting
        // pass splits its colours when C is tinted per pixel.
        let surfaces = fx.samples_textures() || fx.has(Effect::VertexColors);
        let split = fx.has(Effect::BaseColorTexture) || fx.has(Effect::VertexColors);
        let lit_colors = lit_pass.map(|_| gpu_scene.lit_colors(&self.device, &self.queue, layouts, flat, split));
        if let (Some(entry), Some(colors)) = (lit_pass, lit_colors) {
            // The lighting pass is part of the mode's cost: the first timestamp opens it.
            let start = timestamps.filter(|_| !begun);
            let maps = shadows.as_ref().map(|s| &s.0);
            self.encode_lighting_pass(encoder, gpu_scene, key.program, entry, colors, maps, start);
            begun |= start.is_some();
        }
        // Transparent objects are drawn after the scene pass, over it (glass_pass.rs).
        let glass: Vec<usize> = if fx.has(Effect::Transmission) { gpu_scene.glass_order.clone() } else { Vec::new() };
        let clear = gpu_scene.clear;
        let pipeline = self.pipelines.pipeline(key);
        // Opened here unless an earlier pass opened it; closed here unless the glass pass follows.
        let mut pass = scene_pass(encoder, target, clear, timestamps, !begun, glass.is_empty());
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &gpu_scene.globals_bind, &[]);
        if let Some((maps, _)) = &shadows {
            pass.set_bind_group(2, maps, &[]);
        }
        self.draw_objects(&mut pass, gpu_scene, lit_colors, &glass, flat, surfaces);
        // The environment behind the opaque scene, before the glass, which sees it through.
        if fx.has(Effect::EnvironmentBackground) && gpu_scene.env_background {
            let background =
                crate::environment_gpu::background_pipeline(&mut self.pipelines, key.program, target.format);
            pass.set_pipeline(background);
            pass.set_bind_group(0, &gpu_scene.globals_bind, &[]);
            pass.draw(0..3, 0..1);
        }
        drop(pass);
        if !glass.is_empty() {
            let maps = shadows.as_ref().map(|s| &s.0);
            let end = timestamps.map(|(qs, i)| (qs, i + 1));
            self.encode_glass(encoder, gpu_scene, target, key.program, &glass, maps, end);
        }
    }

    /// Draw the scene pass's objects but the transparent ones (`glass`), each with its uniforms,
    /// its lighting pass's colours when there are some, and its flat or smooth mesh.
    #[allow(clippy::too_many_arguments)]
    fn draw_objects(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        gpu_scene: &SceneGpu,
        lit_colors: Option<&[Option<crate::lighting_pass::LitColors>]>,
        glass: &[usize],
        flat: bool,
        surfaces: bool,
    ) {
        for (i, k) in gpu_scene.objects.iter().enumerate() {
            if glass.contains(&i) {
                continue;
            }
            let mesh = &gpu_scene.meshes[k];
            pass.set_bind_group(1, gpu_scene.object_bind(i), &[(i as u64 * gpu_scene.object_stride) as u32]);
            if let Some(colors) = lit_colors {
                // An empty mesh has no colours and nothing to draw.
                let Some(c) = &colors[i] else { continue };
                pass.set_bind_group(3, &c.colors_bind, &[]);
            }
            if flat {
                let flat_mesh = mesh.flat(&self.device, &self.queue);
                pass.set_vertex_buffer(0, flat_mesh.corners.slice(..));
                if surfaces && let Some(s) = &flat_mesh.surface {
                    pass.set_vertex_buffer(1, s.slice(..));
                }
                pass.draw(0..mesh.flat_count, 0..1);
            } else {
                pass.set_vertex_buffer(0, mesh.smooth.slice(..));
                if surfaces && let Some(s) = &mesh.surface {
                    pass.set_vertex_buffer(1, s.slice(..));
                }
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.index_count, 0, 0..1);
            }
        }
    }

    /// The lighting pass `entry` of flat or Gouraud shading: each object's faces or vertices lit
    /// once into its colours (`lighting_pass.rs`), with the uniforms last written and, with cast
    /// shadows, the maps.
    #[allow(clippy::too_many_arguments)]
    fn encode_lighting_pass(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        gpu_scene: &SceneGpu,
        program: Program,
        entry: &'static str,
        per_object: &[Option<crate::lighting_pass::LitColors>],
        maps: Option<&wgpu::BindGroup>,
        start: Option<(&wgpu::QuerySet, u32)>,
    ) {
        let pipeline = crate::lighting_pass::pipeline(&mut self.pipelines, program, entry);
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some(entry),
            timestamp_writes: start.map(|(qs, i)| wgpu::ComputePassTimestampWrites {
                query_set: qs,
                beginning_of_pass_write_index: Some(i),
                end_of_pass_write_index: None,
            }),
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &gpu_scene.globals_bind, &[]);
        if let Some(maps) = maps {
            pass.set_bind_group(2, maps, &[]);
        }
        for (i, faces) in per_object.iter().enumerate() {
            let Some(faces) = faces else { continue };
            pass.set_bind_group(1, gpu_scene.object_bind(i), &[(i as u64 * gpu_scene.object_stride) as u32]);
            for (bind, n) in &faces.chunks {
                pass.set_bind_group(3, bind, &[]);
                pass.dispatch_workgroups(n.div_ceil(crate::lighting_pass::LIT_WORKGROUP), 1, 1);
            }
        }
    }

    /// Draw the scene into `target` with `settings` and submit: the program is the one
    /// [`Program::for_scene`] resolves.
    pub fn render(&mut self, gpu_scene: &mut SceneGpu, scene: &Scene, target: &Target, settings: &RenderSettings) {
        let program = Program::for_scene(scene, settings);
        self.write_uniforms(gpu_scene, scene, target, settings);
        let mut encoder = self.device.create_command_encoder(&Default::default());
        self.encode(&mut encoder, gpu_scene, target, program, None);
        self.queue.submit([encoder.finish()]);
    }
}

/// Begin the scene pass into `target`, clearing its colour to `clear` and its depth; with
/// `timestamps`, it writes the first slot when it `opens` the frame and the second when it `closes` it.
fn scene_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    target: &Target,
    clear: wgpu::Color,
    timestamps: Option<(&wgpu::QuerySet, u32)>,
    opens: bool,
    closes: bool,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("shadelab scene"),
        color_attachments: &[color_attachment(&target.color_view, wgpu::LoadOp::Clear(clear))],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: &target.depth_view,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
            stencil_ops: None,
        }),
        timestamp_writes: timestamps.filter(|_| opens || closes).map(|(qs, i)| wgpu::RenderPassTimestampWrites {
            query_set: qs,
            beginning_of_pass_write_index: opens.then_some(i),
            end_of_pass_write_index: closes.then_some(i + 1),
        }),
        occlusion_query_set: None,
        multiview_mask: None,
    })
}
