//! The shadow passes (docs/model.md §0, §6): each casting light's view-projections (from
//! `shadelab_model::shadows`), the frame's shadow maps (one `Depth32Float` 2D array: one layer per
//! spot light, one per cascade of a directional light, six per point light), the depth-only
//! pipeline with the
//! slope-scaled bias, and the passes encoded before the scene pass. Only programs with
//! `Effect::CastShadows` run them; `shaders/shadows.wgsl` samples the maps.
//!
//! Memory: every layer has the array's side, the largest resolution a casting light asks for,
//! halved until all layers fit in `SHADOW_MAP_BUDGET_BYTES`; a light asking for less uses the
//! top-left `resolution²` of its layer (`ShadowLight.uv_scale`).

use crate::light_loop::LightLoop;
use crate::pipelines::{DEPTH_FORMAT, PassKey, PipelineCache};
use crate::renderer::Renderer;
use crate::target::{LinearImage, padded_bytes_per_row};
use crate::uniforms::{ShadowLightUniform, ShadowsUniform};
use crate::upload::SceneGpu;
use crate::vertex::SmoothVertex;
use bytemuck::Zeroable;
use shadelab_model::effects::{Effect, EffectKey};
use shadelab_model::lighting::area_points::area_emitter;
use shadelab_model::shadows::{
    MAX_SHADOW_LAYERS, SHADOW_CONSTANT_BIAS, SHADOW_DEPTH_BIAS_CLAMP, SHADOW_MAP_BUDGET_BYTES, SHADOW_RESOLUTION,
    SHADOW_SLOPE_BIAS, SHADOW_TEXEL_BYTES, cascade_projection, drawn_layers, light_layers, scene_bounds, shadow_cubes,
    shadow_projection,
};
use shadelab_model::{Light, Scene};

/// Where one light's map lies in the array.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightMap {
    pub first_layer: u32,
    /// 1; a directional light's cascades (up to `SHADOW_CASCADES_MAX`); 6 for a point light, and
    /// 6 per cube of an area light drawn as points.
    pub layers: u32,
    /// Cube lights: how many cubes follow `first_layer` (`shadows::shadow_cubes`); 1 otherwise.
    pub cubes: u32,
    /// Its side in texels (its resolution, at most the array's side).
    pub resolution: u32,
}

/// The frame's layers: the array's side and count, and each light slot's map (`None`: no shadow).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShadowPlan {
    pub side: u32,
    pub layers: u32,
    pub lights: Vec<Option<LightMap>>,
}

impl ShadowPlan {
    /// The layers of a scene's casting lights (the first `MAX_LIGHTS`), the side fitted to the
    /// memory budget and the device's limits. No casting light: one 1×1 layer (the bind group
    /// must exist whenever the program samples it).
    pub fn for_scene(scene: &Scene, limits: &wgpu::Limits) -> ShadowPlan {
        let mut lights = Vec::new();
        let (mut layers, mut side) = (0u32, 0u32);
        let cubes = shadow_cubes(scene);
        for (l, &c) in scene.lights.iter().zip(&cubes) {
            if !l.shadow.casts {
                lights.push(None);
                continue;
            }
            // An area light's map is its centre's cube, or one per point source (c cubes).
            let n = light_layers(scene, l) * c.max(1);
            let resolution = l.shadow.clamped().resolution;
            lights.push(Some(LightMap { first_layer: layers, layers: n, cubes: c.max(1), resolution }));
            layers += n;
            side = side.max(resolution);
        }
        if layers == 0 {
            return ShadowPlan { side: 1, layers: 1, lights };
        }
        debug_assert!(layers <= MAX_SHADOW_LAYERS && layers <= limits.max_texture_array_layers);
        side = side.min(limits.max_texture_dimension_2d);
        let min_side = SHADOW_RESOLUTION.min as u32;
        while side > min_side && layers as u64 * (side as u64).pow(2) * SHADOW_TEXEL_BYTES > SHADOW_MAP_BUDGET_BYTES {
            side /= 2;
        }
        for m in lights.iter_mut().flatten() {
            m.resolution = m.resolution.min(side);
        }
        ShadowPlan { side, layers, lights }
    }

    /// The bytes the array takes.
    pub fn bytes(&self) -> u64 {
        self.layers as u64 * (self.side as u64).pow(2) * SHADOW_TEXEL_BYTES
    }
}

/// A scene's shadow maps on the GPU: the array, a view per layer (the passes' attachments), the
/// `Shadows` uniform, and the bind groups of the scene pass (@group(2)) and the shadow pass
/// (@group(3)).
pub(crate) struct ShadowMaps {
    pub(crate) plan: ShadowPlan,
    texture: wgpu::Texture,
    layer_views: Vec<wgpu::TextureView>,
    uniform: wgpu::Buffer,
    pub(crate) bind: wgpu::BindGroup,
    casters_bind: wgpu::BindGroup,
    /// Whether the uniform's lights cast (false: zeroed, every light unshadowed).
    casting: bool,
    /// Per plan light, the layers the uniform uses this frame (a directional light's cascades
    /// may be fewer than its layers): the shadow passes draw only these.
    drawn: Vec<u32>,
}

/// The maps' bind group layout (@group(2)): `Shadows`, the depth array, two comparison samplers.
/// Visible to every stage: Gouraud shades in the vertex stage, flat in a compute pass.
pub(crate) fn maps_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let stages = wgpu::ShaderStages::VERTEX_FRAGMENT.union(wgpu::ShaderStages::COMPUTE);
    let sampler = |binding| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("shadow maps"),
        entries: &[
            wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: stages,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(size_of::<ShadowsUniform>() as u64),
                },
                count: None,
            },
            wgpu::BindGroupLayoutEntry {
                binding: 1,
                visibility: stages,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Depth,
                    view_dimension: wgpu::TextureViewDimension::D2Array,
                    multisampled: false,
                },
                count: None,
            },
            sampler(2),
            sampler(3),
        ],
    })
}

/// Bytes of `ShadowCasters`: the matrices at the start of `Shadows`.
const CASTERS_BYTES: u64 = MAX_SHADOW_LAYERS as u64 * 64;

/// The shadow pass's bind group layout (@group(3)): `ShadowCasters`.
pub(crate) fn casters_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("shadow casters"),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: wgpu::BufferSize::new(CASTERS_BYTES),
            },
            count: None,
        }],
    })
}

/// The comparison samplers: `[bilinear, nearest]`, comparing `reference ≤ stored` (lit), clamped
/// to the map's edge.
pub(crate) fn samplers(device: &wgpu::Device) -> [wgpu::Sampler; 2] {
    [wgpu::FilterMode::Linear, wgpu::FilterMode::Nearest].map(|f| {
        device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("shadow compare"),
            mag_filter: f,
            min_filter: f,
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..Default::default()
        })
    })
}

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
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            cull_mode: None,
            ..Default::default()
        },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: wgpu::DepthBiasState {
                constant: SHADOW_CONSTANT_BIAS,
                slope_scale: SHADOW_SLOPE_BIAS,
                clamp: SHADOW_DEPTH_BIAS_CLAMP,
            },
        }),
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
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("shadows"),
            size: size_of::<ShadowsUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
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
        ShadowMaps { plan, texture, layer_views, uniform, bind, casters_bind, casting: false, drawn: Vec::new() }
    }

    /// Plan the scene's shadow maps, (re)allocate them when the plan changed, and write their
    /// uniform for an image of `aspect` (`write_uniforms` calls it when the program has cast
    /// shadows). With `casting` false only an existing uniform is zeroed (every light
    /// unshadowed), so a stand-in program that still samples the maps shows no stale shadows.
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
        maps.drawn = u.lights.iter().zip(&maps.plan.lights).map(|(l, m)| m.map_or(0, |_| l.layers)).collect();
        maps.casting = true;
    }

    /// Record the shadow passes into `encoder` (one per layer of a casting light), and return the
    /// scene pass's @group(2). Maps are made (unshadowed) if the uniforms never asked for them.
    /// `timestamp` is written at the start of the first pass.
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
        let gpu_scene: &SceneGpu = gpu_scene;
        let maps = gpu_scene.shadows.as_ref().expect("made above");
        let mut timestamp = timestamp;
        if maps.casting {
            for (map, &drawn) in maps.plan.lights.iter().zip(&maps.drawn) {
                let Some(map) = map else { continue };
                for layer in map.first_layer..map.first_layer + drawn.min(map.layers) {
                    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                        label: Some("shadow pass"),
                        color_attachments: &[],
                        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                            view: &maps.layer_views[layer as usize],
                            depth_ops: Some(wgpu::Operations {
                                load: wgpu::LoadOp::Clear(1.0),
                                store: wgpu::StoreOp::Store,
                            }),
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
                    let r = map.resolution as f32;
                    pass.set_viewport(0.0, 0.0, r, r, 0.0, 1.0);
                    pass.set_pipeline(&pipeline);
                    pass.set_bind_group(3, &maps.casters_bind, &[]);
                    for (i, k) in gpu_scene.objects.iter().enumerate() {
                        let mesh = &gpu_scene.meshes[k];
                        let offset = (i as u64 * gpu_scene.object_stride) as u32;
                        pass.set_bind_group(1, gpu_scene.object_bind(i), &[offset]);
                        pass.set_vertex_buffer(0, mesh.smooth.slice(..));
                        pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                        pass.draw_indexed(0..mesh.index_count, 0, layer..layer + 1);
                    }
                }
            }
        }
        (maps.bind.clone(), timestamp.is_none())
    }

    /// The plan of a scene's shadow maps as last written (`None` before a program with cast
    /// shadows drew it).
    pub fn shadow_plan(&self, gpu_scene: &SceneGpu) -> Option<ShadowPlan> {
        gpu_scene.shadows.as_ref().map(|m| m.plan.clone())
    }

    /// Read back one layer of light `light`'s shadow map (`face` 0…5 of a point light, else 0)
    /// after a frame drew it: its `resolution²` texels, the stored depth in [0, 1] (1: nothing)
    /// in r, g and b, rows top to bottom as the map is addressed. `None` if the light has no map.
    pub fn read_shadow_map(&self, gpu_scene: &SceneGpu, light: usize, face: u32) -> Option<LinearImage> {
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
        let slice = buffer.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        self.device.poll(wgpu::PollType::wait_indefinitely()).ok()?;
        let data = slice.get_mapped_range().ok()?;
        let mut pixels = Vec::with_capacity((n * n) as usize);
        for y in 0..n as usize {
            let r = &data[y * row as usize..][..n as usize * 4];
            pixels.extend(r.chunks_exact(4).map(|b| {
                let d = f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
                [d, d, d, 1.0]
            }));
        }
        Some(LinearImage { width: n, height: n, pixels })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Gpu, RenderSettings, render_image};
    use glam::DVec3;
    use shadelab_model::LightKind;
    use shadelab_model::shadows::ShadowFilter;
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
