//! The renderer of one device: its queue, the two bind-group layouts every pipeline shares
//! (globals, per-object uniforms), and its pipeline cache. Uploading a scene (`upload.rs`),
//! drawing a frame (`frame.rs`) and the cache (`pipelines.rs`) live beside it.

use crate::pipelines::PipelineCache;
use crate::uniforms::{GlobalsUniform, ObjectUniform};

pub struct Renderer {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub(crate) globals_layout: wgpu::BindGroupLayout,
    pub(crate) object_layout: wgpu::BindGroupLayout,
    /// The shader modules and pipelines, by program and colour format.
    pub pipelines: PipelineCache,
}

fn uniform_entry(dynamic: bool, size: u64) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding: 0,
        visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: dynamic,
            min_binding_size: wgpu::BufferSize::new(size),
        },
        count: None,
    }
}

impl Renderer {
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Renderer {
        let globals_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("globals"),
            entries: &[uniform_entry(false, size_of::<GlobalsUniform>() as u64)],
        });
        let object_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("object"),
            entries: &[uniform_entry(true, size_of::<ObjectUniform>() as u64)],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadelab"),
            bind_group_layouts: &[Some(&globals_layout), Some(&object_layout)],
            immediate_size: 0,
        });
        Renderer {
            device: device.clone(),
            queue: queue.clone(),
            globals_layout,
            object_layout,
            pipelines: PipelineCache::new(device, pipeline_layout),
        }
    }
}
