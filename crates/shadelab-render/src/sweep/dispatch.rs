//! The sweep on the GPU: the compute module (the shipped terms, the generated columns and the
//! kernel), its buffers, one dispatch and the readback.

use super::columns::{OUTPUTS, wgsl_columns};
use super::inputs::SweepInputs;
use crate::gpu::Gpu;
use crate::shaders;
use wgpu::util::DeviceExt;

/// The stability sweep's kernel (`shaders/sweep.wgsl`).
pub const SWEEP_KERNEL: &str = include_str!("../../../../shaders/sweep.wgsl");

/// The sweep's compute module: the shipped terms (the transmission terms among them), the
/// generated columns, then the kernel.
pub fn sweep_source() -> String {
    format!("{}\n{}\n{}", shaders::terms_source(), wgsl_columns(), SWEEP_KERNEL)
}

/// Run the kernel over every combination and read its outputs back (`OUTPUTS` floats each).
pub(super) fn dispatch(gpu: &Gpu, inputs: &SweepInputs, total: usize) -> Vec<f32> {
    let device = &gpu.device;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("sweep"),
        source: wgpu::ShaderSource::Wgsl(sweep_source().into()),
    });
    let table_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("sweep table"),
        contents: bytemuck::cast_slice(&inputs.table()),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let out_size = (total * OUTPUTS * 4) as u64;
    let out_buf = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("sweep outputs"),
        size: out_size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let read_buf = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("sweep readback"),
        size: out_size,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("sweep"),
        layout: None,
        module: &module,
        entry_point: Some("sweep"),
        compilation_options: Default::default(),
        cache: None,
    });
    // Chunks of whole workgroups whose outputs fit one storage binding; 64 combinations of
    // OUTPUTS floats are a multiple of 256 bytes, the offset alignment.
    let limit = device.limits().max_storage_buffer_binding_size as usize;
    let per_chunk = (limit / (OUTPUTS * 4) / 64 * 64).max(64);
    let mut enc = device.create_command_encoder(&Default::default());
    for first in (0..total).step_by(per_chunk) {
        let chunk = per_chunk.min(total - first);
        let counts = chunk_counts(inputs, total, first, chunk);
        let counts_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("sweep counts"),
            contents: bytemuck::cast_slice(&counts),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("sweep"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: counts_buf.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: table_buf.as_entire_binding() },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                        buffer: &out_buf,
                        offset: (first * OUTPUTS * 4) as u64,
                        size: wgpu::BufferSize::new((chunk * OUTPUTS * 4) as u64),
                    }),
                },
            ],
        });
        let groups = chunk.div_ceil(64) as u32;
        let max = device.limits().max_compute_workgroups_per_dimension;
        let (gx, gy) = if groups <= max { (groups, 1) } else { (max, groups.div_ceil(max)) };
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
    }
    enc.copy_buffer_to_buffer(&out_buf, 0, &read_buf, 0, out_size);
    gpu.queue.submit([enc.finish()]);
    read_back(device, &read_buf)
}

/// The kernel's uniform for one chunk: the axes' lengths, the total and the chunk's range.
fn chunk_counts(inputs: &SweepInputs, total: usize, first: usize, chunk: usize) -> [u32; 12] {
    [
        inputs.geometry.len() as u32,
        inputs.m.len() as u32,
        inputs.h.len() as u32,
        inputs.mu.len() as u32,
        inputs.d.len() as u32,
        inputs.alpha.len() as u32,
        total as u32,
        (inputs.geometry.len() * 3) as u32,
        inputs.shadow.len() as u32,
        first as u32,
        chunk as u32,
        0,
    ]
}

/// The readback buffer's floats, once the GPU has written them (waits for it).
pub(super) fn read_back(device: &wgpu::Device, read_buf: &wgpu::Buffer) -> Vec<f32> {
    let slice = read_buf.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("map sweep outputs"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    let data = slice.get_mapped_range().expect("mapped").to_vec();
    read_buf.unmap();
    bytemuck::cast_slice(&data).to_vec()
}
