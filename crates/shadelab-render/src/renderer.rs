//! The renderer of one device: its queue, the bind-group layouts (globals, per-object uniforms,
//! and with cast shadows the shadow maps and the shadow pass's matrices), the shadow samplers,
//! and its pipeline cache. Uploading a scene (`upload.rs`), drawing a frame (`frame.rs`), the
//! shadow passes (`shadow_pass.rs`) and the cache (`pipelines.rs`) live beside it.

use crate::buffers::{buffer_entry, written_buffer};
use crate::pipelines::{Layouts, PipelineCache};
use crate::uniforms::{GlobalsUniform, ObjectUniform, TablesUniform};

pub struct Renderer {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub(crate) globals_layout: wgpu::BindGroupLayout,
    pub(crate) object_layout: wgpu::BindGroupLayout,
    /// The constant tables (`TablesUniform`), bound in every scene's globals group (binding 3)
    /// and written once, by the first frame whose program reads them ([`Renderer::write_tables`]).
    pub(crate) tables: wgpu::Buffer,
    /// Set once the tables are written: a renderer whose scenes never read them never computes
    /// them (about 0.8 s for both).
    tables_written: std::sync::OnceLock<()>,
    /// @group(2) of the permutations with cast shadows: `Shadows`, the maps, two samplers.
    pub(crate) shadow_layout: wgpu::BindGroupLayout,
    /// @group(3) of the shadow pass: `ShadowCasters`.
    pub(crate) casters_layout: wgpu::BindGroupLayout,
    /// @group(3) of the lighting passes and of the flat and Gouraud pipelines (`lighting_pass.rs`).
    pub(crate) flat_compute_layout: wgpu::BindGroupLayout,
    pub(crate) flat_colors_layout: wgpu::BindGroupLayout,
    /// Comparison samplers of the maps: bilinear 2×2 (Pcf, Poisson) and nearest (Hard).
    pub(crate) shadow_samplers: [wgpu::Sampler; 2],
    /// @group(3) of the glass pass (`glass_pass.rs`).
    pub(crate) glass_layout: wgpu::BindGroupLayout,
    /// The glass pass's textures, made for the last target it drew into.
    pub(crate) glass: Option<crate::glass_textures::GlassTextures>,
    /// The shader modules and pipelines, by program and colour format.
    pub pipelines: PipelineCache,
}

fn uniform_entry(dynamic: bool, size: u64) -> wgpu::BindGroupLayoutEntry {
    uniform_entry_at(0, dynamic, size)
}

/// A uniform buffer at `binding`, with a dynamic offset or not, of `size` bytes.
fn uniform_entry_at(binding: u32, dynamic: bool, size: u64) -> wgpu::BindGroupLayoutEntry {
    // Compute too: flat shading's per-face pass shades in a compute stage.
    let stages = wgpu::ShaderStages::VERTEX_FRAGMENT.union(wgpu::ShaderStages::COMPUTE);
    buffer_entry(binding, stages, wgpu::BufferBindingType::Uniform, dynamic, Some(size))
}

/// A read-only storage buffer of the globals' group: the environment's prefiltered levels
/// (binding 1, `env_levels`) and its occlusion grid (binding 2, `env_occlusion_nodes`), each with
/// the size of its element.
fn storage_entry(binding: u32, element: u64) -> wgpu::BindGroupLayoutEntry {
    let stages = wgpu::ShaderStages::FRAGMENT.union(wgpu::ShaderStages::COMPUTE);
    buffer_entry(binding, stages, wgpu::BufferBindingType::Storage { read_only: true }, false, Some(element))
}

impl Renderer {
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Renderer {
        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("globals"),
            entries: &[
                uniform_entry(false, size_of::<GlobalsUniform>() as u64),
                storage_entry(1, 16),
                storage_entry(2, 8),
                uniform_entry_at(3, false, size_of::<TablesUniform>() as u64),
            ],
        });
        let tables = written_buffer(device, "tables", size_of::<TablesUniform>() as u64, wgpu::BufferUsages::UNIFORM);
        let object_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("object"),
            entries: &[vec![uniform_entry(true, size_of::<ObjectUniform>() as u64)], crate::textures::layout_entries()]
                .concat(),
        });
        let shadow_layout = crate::shadow_maps::maps_layout(device);
        let casters = crate::shadow_maps::casters_layout(device);
        let flat_compute = crate::lighting_pass::compute_layout(device);
        let flat_colors = crate::lighting_pass::colors_layout(device);
        let glass = crate::glass_textures::layout(device);
        let layout = |label: &str, groups: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(label),
                bind_group_layouts: groups,
                immediate_size: 0,
            })
        };
        // The groups every lit pipeline starts with: globals (0), the object (1), the shadow maps (2).
        let (g, o, s) = (Some(&globals_layout), Some(&object_layout), Some(&shadow_layout));
        let layouts = Layouts {
            lit: layout("shadelab", &[g, o]),
            lit_shadows: layout("shadelab shadows", &[g, o, s]),
            lit_vertex: layout("shadelab flat", &[g, o, None, Some(&flat_colors)]),
            lit_shadows_vertex: layout("shadelab flat shadows", &[g, o, s, Some(&flat_colors)]),
            lighting_pass: layout("shadelab flat faces", &[g, o, None, Some(&flat_compute)]),
            lighting_pass_shadows: layout("shadelab flat faces shadows", &[g, o, s, Some(&flat_compute)]),
            // The shadow pass reads only the object (group 1) and its layer's matrix (group 3).
            shadow_pass: layout("shadelab shadow pass", &[None, o, None, Some(&casters)]),
            glass: layout("shadelab glass", &[g, o, None, Some(&glass)]),
            glass_shadows: layout("shadelab glass shadows", &[g, o, s, Some(&glass)]),
            glass_back: layout("shadelab glass back faces", &[g, o]),
            background: layout("shadelab environment background", &[g]),
        };
        Renderer {
            device: device.clone(),
            queue: queue.clone(),
            globals_layout,
            object_layout,
            tables,
            tables_written: std::sync::OnceLock::new(),
            shadow_layout,
            casters_layout: casters,
            flat_compute_layout: flat_compute,
            flat_colors_layout: flat_colors,
            glass_layout: glass,
            glass: None,
            shadow_samplers: crate::shadow_maps::samplers(device),
            pipelines: PipelineCache::new(device, layouts),
        }
    }
}

/// The effects whose code reads the constant tables: `ms_table.wgsl`'s `#if` names exactly these
/// (the test `the_table_effects_are_ms_tables_condition` holds it).
pub(crate) const TABLE_EFFECTS: [shadelab_model::effects::Effect; 3] = {
    use shadelab_model::effects::Effect;
    [Effect::MultipleScattering, Effect::EnvironmentSpecular, Effect::AreaLtc]
};

impl Renderer {
    /// Write the constant tables, once per renderer, if `program` reads them (the compensation's
    /// E, the split sum's E and B, the LTC's M⁻¹); a program that does not leaves them uncomputed.
    pub(crate) fn write_tables(&self, program: crate::program::Program) {
        let effects = program.effects();
        if TABLE_EFFECTS.iter().any(|&e| effects.has(e)) {
            self.tables_written
                .get_or_init(|| self.queue.write_buffer(&self.tables, 0, bytemuck::bytes_of(&TablesUniform::new())));
        }
    }
}
