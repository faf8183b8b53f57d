//! The shadow maps' plan and state (docs/model.md §0, §6): which layers of the one `Depth32Float`
//! 2D array each casting light takes (`ShadowPlan`), the maps a scene holds on the GPU with what
//! each layer was last drawn from (`ShadowMaps`), and the bind-group layouts and samplers the
//! renderer builds for them. The passes that draw and read them are in `shadow_pass.rs`.

use crate::buffers::buffer_entry;
use crate::uniforms::ShadowsUniform;
use shadelab_model::Scene;
use shadelab_model::shadows::{
    MAX_SHADOW_LAYERS, SHADOW_MAP_BUDGET_BYTES, SHADOW_RESOLUTION, SHADOW_TEXEL_BYTES, light_layers, shadow_cubes,
};
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
    pub(crate) texture: wgpu::Texture,
    pub(crate) layer_views: Vec<wgpu::TextureView>,
    pub(crate) uniform: wgpu::Buffer,
    pub(crate) bind: wgpu::BindGroup,
    pub(crate) casters_bind: wgpu::BindGroup,
    /// Whether the uniform's lights cast (false: zeroed, every light unshadowed).
    pub(crate) casting: bool,
    /// What each layer holds: the light view-projection, side and casters' transforms it was
    /// last drawn with (`None`: never drawn). A layer whose state is unchanged is not redrawn.
    pub(crate) layer_states: Vec<Option<LayerState>>,
    /// The layers to draw at the next shadow pass, each with the objects inside its frustum.
    pub(crate) pending: Vec<(u32, Vec<usize>)>,
}

/// What one layer of the maps was drawn from: its matrix, its side in texels and every object's
/// model matrix (the casters), as the uniforms hold them.
#[derive(Clone, PartialEq)]
pub(crate) struct LayerState {
    pub(crate) matrix: [[f32; 4]; 4],
    pub(crate) resolution: u32,
    pub(crate) casters: std::sync::Arc<Vec<[[f32; 4]; 4]>>,
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
            buffer_entry(0, stages, wgpu::BufferBindingType::Uniform, false, Some(size_of::<ShadowsUniform>() as u64)),
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
pub(crate) const CASTERS_BYTES: u64 = MAX_SHADOW_LAYERS as u64 * 64;

/// The shadow pass's bind group layout (@group(3)): `ShadowCasters`.
pub(crate) fn casters_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("shadow casters"),
        entries: &[buffer_entry(
            0,
            wgpu::ShaderStages::VERTEX,
            wgpu::BufferBindingType::Uniform,
            false,
            Some(CASTERS_BYTES),
        )],
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
