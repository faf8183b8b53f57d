//! The shadow passes (docs/model.md §0, §6): each casting light's view-projections (from
//! `shadelab_model::shadows`), the frame's shadow maps (one `Depth32Float` 2D array: one layer per
//! spot light, one per cascade of a directional light, six per point light), the depth-only
//! pipeline with the
//! slope-scaled bias, and the passes encoded before the scene pass. Only programs with
//! `Effect::CastShadows` run them; `shaders/shadows.wgsl` samples the maps.
//!
//! Memory: every layer has the array's side, the largest resolution a casting light asks for,
//! halved until all layers fit in `SHADOW_MAP_BUDGET_BYTES` (`shadow_maps.rs`); a light asking for less uses the
//! top-left `resolution²` of its layer (`ShadowLight.uv_scale`).
//!
//! Redraws: a layer is drawn again only when its view-projection, its side or an object's
//! transform changed (`LayerState`), each time with only the objects in its frustum. Single maps
//! are fitted to the scene's bounds and cube faces sit at the light, so neither follows the camera;
//! a directional light's cascades are fitted to the view's slices, so an orbit redraws the
//! cascades whose projection it moved (each snapped to its texel grid), and those alone.

use crate::light_loop::LightLoop;
use crate::pipelines::{PassKey, PipelineCache, depth_state, triangles};
use crate::renderer::Renderer;
use crate::shadow_maps::{CASTERS_BYTES, LayerState, ShadowMaps};
pub use crate::shadow_maps::{LightMap, ShadowPlan};
use crate::target::DEPTH_FORMAT;
use crate::target::{PendingReadBack, padded_bytes_per_row};
use crate::uniforms::{ShadowLightUniform, ShadowsUniform};
use crate::upload::SceneGpu;
use crate::vertex::SmoothVertex;
use bytemuck::Zeroable;
use glam::DVec3;
use shadelab_model::effects::{Effect, EffectKey};
use shadelab_model::lighting::area_points::area_emitter;
use shadelab_model::shadows::{
    MAX_SHADOW_LAYERS, SHADOW_CONSTANT_BIAS, SHADOW_DEPTH_BIAS_CLAMP, SHADOW_SLOPE_BIAS, cascade_projection,
    drawn_layers, object_local_box, scene_bounds, shadow_projection,
};
use shadelab_model::{Light, Scene};

/// The shadow pass's pipeline from the cache, built on first use from the shadow permutation.
fn shadow_pipeline(cache: &mut PipelineCache) -> &wgpu::RenderPipeline {
    let effects = EffectKey::NONE.with(Effect::CastShadows);
    let key = PassKey { pass: "shadow", effects, lights: LightLoop::Dynamic, format: None };
    cache.pass_pipeline(key, |cx| build_pipeline(cx.device, &cx.layouts.shadow_pass, cx.module))
}

/// The depth-only pipeline of the shadow pass: `vs_shadow`, no fragment stage, the slope-scaled
/// and constant biases of `shadelab_model::shadows`, no culling (planes are one-sided meshes).
fn build_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("shadow pass"),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_shadow"),
            compilation_options: Default::default(),
            buffers: &[Some(SmoothVertex::LAYOUT)],
        },
        primitive: triangles(None),
        depth_stencil: Some(depth_state(
            true,
            wgpu::CompareFunction::Less,
            wgpu::DepthBiasState {
                constant: SHADOW_CONSTANT_BIAS,
                slope_scale: SHADOW_SLOPE_BIAS,
                clamp: SHADOW_DEPTH_BIAS_CLAMP,
            },
        )),
        multisample: Default::default(),
        fragment: None,
        multiview_mask: None,
        cache: None,
    })
}

/// The `Shadows` uniform of a scene for a plan and an image of `aspect` (width / height): each
/// casting light's matrices (fitted to the scene's bounding sphere, or a directional light's
/// cascades to the slices of the view) and map. No objects: nothing casts.
pub fn shadows_uniform(scene: &Scene, plan: &ShadowPlan, aspect: f64) -> ShadowsUniform {
    let mut u = ShadowsUniform::zeroed();
    let Some((centre, radius)) = scene_bounds(scene) else { return u };
    for ((slot, light), map) in u.lights.iter_mut().zip(&scene.lights).zip(&plan.lights) {
        let Some(map) = map else { continue };
        // A directional light's cascades this frame: as many of its layers as the view needs.
        let cascades = if light.kind.is_directional() { drawn_layers(scene, light) } else { 1 };
        // One projection per cube (an area light drawn as points has one per point source, each
        // from where it sits); the others have one map, from the light itself.
        let project = |at: &Light| {
            if cascades > 1 {
                cascade_projection(at, scene, aspect, (centre, radius), map.resolution, cascades)
            } else {
                shadow_projection(at, centre, radius, map.resolution)
            }
        };
        let mut first = None;
        for j in 0..map.cubes {
            let q = if light.drawn_as_points() {
                project(&Light { position: area_emitter(light, j).position, ..light.clone() })
            } else {
                project(light)
            };
            for (k, m) in q.matrices.iter().enumerate() {
                u.matrices[(map.first_layer as usize + 6 * j as usize + k).min(MAX_SHADOW_LAYERS as usize - 1)] =
                    m.as_mat4().to_cols_array_2d();
            }
            first.get_or_insert(q);
        }
        let Some(p) = first else { continue };
        *slot = ShadowLightUniform {
            first_layer: map.first_layer,
            // The layers drawn this frame (a directional light's cascade count is a runtime value).
            layers: if light.kind.is_directional() { cascades } else { map.layers },
            shadow_filter: light.drawn_shadow_filter().code(),
            perspective: p.perspective as u32,
            texel_world: p.texel_world as f32,
            uv_scale: map.resolution as f32 / plan.side as f32,
            texel_uv: 1.0 / plan.side as f32,
            // Drawn as points, each point's shadow is hard: no penumbra of its own.
            light_size: if light.drawn_as_points() { 0.0 } else { light.penumbra_size() as f32 },
            near: p.near as f32,
            far: p.far as f32,
            cubes: map.cubes,
            pcss_taps: light.shadow.clamped().pcss_taps,
        };
    }
    u
}

/// Each object's box in its own space (`shadows::object_local_box`); `None`: never culled.
fn object_bounds(scene: &Scene) -> Vec<Option<(DVec3, DVec3)>> {
    scene.objects.iter().map(|o| object_local_box(scene, o)).collect()
}

/// The objects whose box reaches the clip volume of a layer's view-projection `matrix` (wgpu's:
/// |x|, |y| ≤ w, 0 ≤ z ≤ w), each box carried by its model matrix in `models`: an object with all
/// eight corners beyond one plane covers no texel of the layer. A small margin covers f32 rounding.
fn layer_casters(bounds: &[Option<(DVec3, DVec3)>], models: &[[[f32; 4]; 4]], matrix: &[[f32; 4]; 4]) -> Vec<usize> {
    let vp = glam::Mat4::from_cols_array_2d(matrix).as_dmat4();
    let outside = |(lo, hi): (DVec3, DVec3), model: &[[f32; 4]; 4]| {
        let m = vp * glam::Mat4::from_cols_array_2d(model).as_dmat4();
        let corners = (0..8).map(|k| {
            let c = DVec3::new(
                if k & 1 == 0 { lo.x } else { hi.x },
                if k & 2 == 0 { lo.y } else { hi.y },
                if k & 4 == 0 { lo.z } else { hi.z },
            );
            m * c.extend(1.0)
        });
        let corners: Vec<glam::DVec4> = corners.collect();
        (0..6).any(|plane| {
            corners.iter().all(|v| {
                let d = match plane {
                    0 => v.w + v.x,
                    1 => v.w - v.x,
                    2 => v.w + v.y,
                    3 => v.w - v.y,
                    4 => v.z,
                    _ => v.w - v.z,
                };
                d < -1e-4 * (v.x.abs() + v.y.abs() + v.z.abs() + v.w.abs())
            })
        })
    };
    (0..models.len())
        .filter(|&i| match bounds.get(i).copied().flatten() {
            Some(b) if b.0.is_finite() && b.1.is_finite() => !outside(b, &models[i]),
            _ => true,
        })
        .collect()
}

impl SceneGpu {
    /// Forget what the shadow maps hold, so the next uniforms' write queues every layer again:
    /// the benches time a frame with its shadow passes, as a changed light or object draws them.
    pub fn redraw_shadows(&mut self) {
        if let Some(maps) = self.shadows.as_mut() {
            maps.layer_states.iter_mut().for_each(|s| *s = None);
        }
    }
}

impl Renderer {
    fn create_shadow_maps(&self, plan: ShadowPlan) -> ShadowMaps {
        let device = &self.device;
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("shadow maps"),
            size: wgpu::Extent3d { width: plan.side, height: plan.side, depth_or_array_layers: plan.layers },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let layer_views = (0..plan.layers)
            .map(|i| {
                texture.create_view(&wgpu::TextureViewDescriptor {
                    dimension: Some(wgpu::TextureViewDimension::D2),
                    base_array_layer: i,
                    array_layer_count: Some(1),
                    ..Default::default()
                })
            })
            .collect();
        let array_view = texture.create_view(&wgpu::TextureViewDescriptor {
            dimension: Some(wgpu::TextureViewDimension::D2Array),
            ..Default::default()
        });
        let uniform = crate::buffers::written_buffer(
            device,
            "shadows",
            size_of::<ShadowsUniform>() as u64,
            wgpu::BufferUsages::UNIFORM,
        );
        self.queue.write_buffer(&uniform, 0, bytemuck::bytes_of(&ShadowsUniform::zeroed()));
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shadow maps"),
            layout: &self.shadow_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&array_view) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&self.shadow_samplers[0]) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&self.shadow_samplers[1]) },
            ],
        });
        let casters_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shadow casters"),
            layout: &self.casters_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &uniform,
                    offset: 0,
                    size: wgpu::BufferSize::new(CASTERS_BYTES),
                }),
            }],
        });
        let layer_states = vec![None; plan.layers as usize];
        ShadowMaps {
            plan,
            texture,
            layer_views,
            uniform,
            bind,
            casters_bind,
            casting: false,
            layer_states,
            pending: Vec::new(),
        }
    }

    /// Plan the scene's shadow maps, (re)allocate them when the plan changed, and write their
    /// uniform for an image of `aspect` (`write_uniforms` calls it when the program has cast
    /// shadows). With `casting` false only an existing uniform is zeroed (every light
    /// unshadowed), so a stand-in program that still samples the maps shows no stale shadows.
    /// Queues for drawing only the layers whose state changed (`LayerState`).
    pub(crate) fn write_shadows(&self, gpu_scene: &mut SceneGpu, scene: &Scene, casting: bool, aspect: f64) {
        let slot = &mut gpu_scene.shadows;
        if !casting {
            if let Some(maps) = slot.as_mut().filter(|m| m.casting) {
                self.queue.write_buffer(&maps.uniform, 0, bytemuck::bytes_of(&ShadowsUniform::zeroed()));
                maps.casting = false;
            }
            return;
        }
        let plan = ShadowPlan::for_scene(scene, &self.device.limits());
        let u = shadows_uniform(scene, &plan, aspect);
        if slot.as_ref().is_none_or(|m| m.plan != plan) {
            *slot = Some(self.create_shadow_maps(plan));
        }
        let maps = slot.as_mut().expect("made above");
        self.queue.write_buffer(&maps.uniform, 0, bytemuck::bytes_of(&u));
        maps.casting = true;
        let casters = std::sync::Arc::new(
            scene.objects.iter().map(|o| o.transform.matrix().as_mat4().to_cols_array_2d()).collect::<Vec<_>>(),
        );
        let bounds = object_bounds(scene);
        for (light, map) in u.lights.iter().zip(&maps.plan.lights) {
            let Some(map) = map else { continue };
            // The layers the uniform uses this frame (a directional light's cascades may be
            // fewer than its layers).
            for layer in map.first_layer..map.first_layer + light.layers.min(map.layers) {
                let Some(&matrix) = u.matrices.get(layer as usize) else { continue };
                let state = LayerState { matrix, resolution: map.resolution, casters: casters.clone() };
                if maps.layer_states[layer as usize].as_ref() == Some(&state) {
                    continue;
                }
                let inside = layer_casters(&bounds, &casters, &matrix);
                maps.pending.retain(|(l, _)| *l != layer);
                maps.pending.push((layer, inside));
                maps.layer_states[layer as usize] = Some(state);
            }
        }
    }

    /// Record the shadow passes into `encoder` (one per layer queued by `write_shadows`, drawing
    /// only the objects in its frustum), and return the scene pass's @group(2). Maps are made
    /// (unshadowed) if the uniforms never asked for them. `timestamp` is written at the start of
    /// the first pass; the second value says whether a pass wrote it.
    pub(crate) fn encode_shadow_passes(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        gpu_scene: &mut SceneGpu,
        timestamp: Option<(&wgpu::QuerySet, u32)>,
    ) -> (wgpu::BindGroup, bool) {
        let pipeline = shadow_pipeline(&mut self.pipelines).clone();
        if gpu_scene.shadows.is_none() {
            let plan = ShadowPlan { side: 1, layers: 1, lights: Vec::new() };
            gpu_scene.shadows = Some(self.create_shadow_maps(plan));
        }
        let maps = gpu_scene.shadows.as_mut().expect("made above");
        let pending = if maps.casting { std::mem::take(&mut maps.pending) } else { Vec::new() };
        let resolution = |layer: u32| {
            maps.plan.lights.iter().flatten().find(|m| (m.first_layer..m.first_layer + m.layers).contains(&layer))
        };
        let mut timestamp = timestamp;
        for (layer, objects) in &pending {
            let r = resolution(*layer).map_or(maps.plan.side, |m| m.resolution) as f32;
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("shadow pass"),
                color_attachments: &[],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &maps.layer_views[*layer as usize],
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                timestamp_writes: timestamp.take().map(|(qs, i)| wgpu::RenderPassTimestampWrites {
                    query_set: qs,
                    beginning_of_pass_write_index: Some(i),
                    end_of_pass_write_index: None,
                }),
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_viewport(0.0, 0.0, r, r, 0.0, 1.0);
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(3, &maps.casters_bind, &[]);
            for &i in objects {
                let Some(k) = gpu_scene.objects.get(i) else { continue };
                let mesh = &gpu_scene.meshes[k];
                let offset = (i as u64 * gpu_scene.object_stride) as u32;
                pass.set_bind_group(1, &gpu_scene.objects_binds[gpu_scene.object_bind_of[i]], &[offset]);
                pass.set_vertex_buffer(0, mesh.smooth.slice(..));
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.index_count, 0, *layer..*layer + 1);
            }
        }
        gpu_scene.shadow_layer_draws += pending.len() as u64;
        (maps.bind.clone(), timestamp.is_none())
    }

    /// The plan of a scene's shadow maps as last written (`None` before a program with cast
    /// shadows drew it).
    pub fn shadow_plan(&self, gpu_scene: &SceneGpu) -> Option<ShadowPlan> {
        gpu_scene.shadows.as_ref().map(|m| m.plan.clone())
    }

    /// Start reading one layer of light `light`'s shadow map (`face`: a cube face or a cascade)
    /// back: `resolution²` texels, the stored depth in [0, 1] (1: nothing) in r, g and b, rows top
    /// to bottom as the map is addressed; `None` when the light has no map or no such layer. The
    /// map completes between frames ([`PendingReadBack::try_take`]): the page cannot wait.
    pub fn start_shadow_map_read(&self, gpu_scene: &SceneGpu, light: usize, face: u32) -> Option<PendingReadBack> {
        let maps = gpu_scene.shadows.as_ref()?;
        let map = (*maps.plan.lights.get(light)?)?;
        if face >= map.layers {
            return None;
        }
        let n = map.resolution;
        let row = padded_bytes_per_row(n, 4);
        let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("shadow map readback"),
            size: row as u64 * n as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = self.device.create_command_encoder(&Default::default());
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &maps.texture,
                mip_level: 0,
                origin: wgpu::Origin3d { x: 0, y: 0, z: map.first_layer + face },
                aspect: wgpu::TextureAspect::DepthOnly,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: Some(n) },
            },
            wgpu::Extent3d { width: n, height: n, depth_or_array_layers: 1 },
        );
        self.queue.submit([encoder.finish()]);
        Some(PendingReadBack::requested(buffer, (n, n), row, true))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Gpu, RenderSettings, render_image};
    use glam::DVec3;
    use shadelab_model::LightKind;
    use shadelab_model::shadows::{SHADOW_MAP_BUDGET_BYTES, ShadowFilter};
    use shadelab_model::{Light, ShadingMode, Shape, SpecularModel};

    /// The ground alone in view, lit from `elevation` degrees, with a small cube hidden under it
    /// (so the analysis turns shadows on and nothing can shadow the ground's top).
    fn lit_plane(kind: LightKind, elevation: f64, filter: ShadowFilter) -> Scene {
        let mut s = Scene::builtin("cube").unwrap();
        let o = s.objects.iter_mut().find(|o| o.shape == Shape::Cube).unwrap();
        o.transform.translation = DVec3::new(0.0, -1.0, 0.0);
        o.transform.scale = DVec3::splat(0.1);
        let e = elevation.to_radians();
        let towards = DVec3::new(e.cos() * 0.6, e.sin(), e.cos() * 0.8);
        s.lights = vec![match kind {
            LightKind::Directional => Light::directional(-towards, [1.0; 3], 1.0),
            LightKind::Point => Light::point(towards * 6.0, [1.0; 3], 1.0, 0.0),
            LightKind::Spot => Light::spot(towards * 6.0, -towards, [1.0; 3], 1.0, 0.0, (0.9, 1.2)),
            k => Light::area(k, towards * 6.0, -towards, [0.5; 2], [1.0; 3], 1.0, 0.0),
        }];
        for l in &mut s.lights {
            l.shadow.filter = filter;
        }
        s
    }

    /// A layer draws the objects whose box reaches its clip volume: inside, straddling its edge,
    /// or without a box; none wholly beyond one plane (a side, behind the light, past the far plane).
    #[test]
    fn a_layer_draws_only_the_objects_in_its_frustum() {
        use glam::DMat4;
        // Looking down from 5 m up, a 4 × 4 m window, depths 0.1 to 10 m.
        let view = DMat4::look_at_rh(DVec3::new(0.0, 5.0, 0.0), DVec3::ZERO, DVec3::Z);
        let vp = DMat4::orthographic_rh(-2.0, 2.0, -2.0, 2.0, 0.1, 10.0) * view;
        let matrix = vp.as_mat4().to_cols_array_2d();
        let at = |x: f64, y: f64| DMat4::from_translation(DVec3::new(x, y, 0.0)).as_mat4().to_cols_array_2d();
        let unit = Some((DVec3::splat(-1.0), DVec3::splat(1.0)));
        let models = [at(0.0, 0.0), at(2.5, 0.0), at(4.0, 0.0), at(0.0, 10.0), at(0.0, -20.0), at(0.0, -20.0)];
        let bounds = [unit, unit, unit, unit, unit, None];
        assert_eq!(layer_casters(&bounds, &models, &matrix), vec![0, 1, 5]);
    }

    /// The plan keeps each light's own side, and halves the array's side only past the budget.
    #[test]
    fn the_plan_keeps_each_lights_side_within_the_budget() {
        let limits = wgpu::Limits::default();
        let mut s = Scene::builtin("default").unwrap();
        for l in &mut s.lights {
            l.shadow.resolution = 4096;
        }
        // The directional light holds SHADOW_CASCADES_MAX layers whatever the view: with the
        // point light's six, 10 layers of 64 MiB pass the budget, so the side halves.
        let plan = ShadowPlan::for_scene(&s, &limits);
        assert_eq!((plan.side, plan.layers), (2048, 10), "a directional light with cascades and a point light");
        assert!(plan.bytes() <= SHADOW_MAP_BUDGET_BYTES);
        // Its orbit changes no plan: a camera twice as far keeps the same layers.
        let mut far = s.clone();
        far.camera.eye = far.camera.target + (s.camera.eye - s.camera.target) * 2.0;
        assert!(ShadowPlan::for_scene(&far, &limits) == plan, "the plan follows the camera");
        s.lights[0].shadow.cascades = false;
        let plan = ShadowPlan::for_scene(&s, &limits);
        assert_eq!((plan.side, plan.layers), (4096, 7), "one directional map and a point light at 4096");
        s.lights[0].shadow.resolution = 256;
        let plan = ShadowPlan::for_scene(&s, &limits);
        assert_eq!(plan.lights[0].map(|m| m.resolution), Some(256), "a light asking less keeps its side");
        assert_eq!(plan.lights[1].map(|m| (m.first_layer, m.layers, m.resolution)), Some((1, 6, 4096)));
        // Eight point lights at 4096 (48 layers, 3 GiB) are halved until they fit: 1024.
        s.lights = (0..8).map(|i| Light::point(DVec3::new(i as f64, 3.0, 0.0), [1.0; 3], 1.0, 0.0)).collect();
        for l in &mut s.lights {
            l.shadow.resolution = 4096;
        }
        let plan = ShadowPlan::for_scene(&s, &limits);
        assert_eq!((plan.side, plan.layers), (1024, 48));
        assert!(plan.bytes() <= SHADOW_MAP_BUDGET_BYTES && plan.lights.iter().flatten().all(|m| m.resolution == 1024));
        s.set_shadows(false);
        assert_eq!(ShadowPlan::for_scene(&s, &limits).layers, 1, "no caster: one 1×1 layer for the binding");
    }

    /// Pixels darker with shadows than without (by more than 1/255): all false, nothing can
    /// shadow the plane. Prints the counts (the acne study of issue 13).
    #[test]
    fn a_lit_plane_has_no_acne() {
        let Ok(gpu) = Gpu::lavapipe() else { return };
        let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::Phong);
        let mut worst = 0;
        for kind in [LightKind::Directional, LightKind::Point, LightKind::Spot] {
            for filter in [ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Poisson] {
                let mut row = Vec::new();
                for elevation in [90.0, 60.0, 30.0, 15.0, 10.0, 5.0] {
                    let mut s = lit_plane(kind, elevation, filter);
                    let on = render_image(&gpu, &s, 640, 360, &settings).unwrap();
                    s.set_shadows(false);
                    let off = render_image(&gpu, &s, 640, 360, &settings).unwrap();
                    let n = on.pixels.iter().zip(&off.pixels).filter(|(a, b)| a[0] < b[0] - 1.0 / 255.0).count();
                    row.push(format!("{elevation}°: {n}"));
                    worst = worst.max(n);
                }
                println!("{kind:?} {filter:?}: {}", row.join(", "));
            }
        }
        assert_eq!(worst, 0, "falsely shadowed pixels on a lit plane");
    }
}
