//! The buffers the passes bind: one form for a buffer's bind-group layout entry and one for a
//! buffer the CPU writes, so that each pass states only its binding, stages, kind and size.

/// A buffer of kind `ty` at `binding`, seen by `stages`, with a dynamic offset or not, of at least
/// `min_size` bytes (`None`: any size, checked at draw time).
pub(crate) fn buffer_entry(
    binding: u32,
    stages: wgpu::ShaderStages,
    ty: wgpu::BufferBindingType,
    dynamic: bool,
    min_size: Option<u64>,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset: dynamic,
            min_binding_size: min_size.and_then(wgpu::BufferSize::new),
        },
        count: None,
    }
}

/// A buffer of `size` bytes for `usage` that the CPU writes (`COPY_DST` added), unmapped.
pub(crate) fn written_buffer(device: &wgpu::Device, label: &str, size: u64, usage: wgpu::BufferUsages) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        usage: usage | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}
