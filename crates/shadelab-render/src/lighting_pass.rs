//! The per-vertex modes' lighting passes (docs/model.md §8): before the scene pass, a compute
//! dispatch per object evaluates the model once per face (`cs_flat`, at the centroid with the
//! face normal) or once per smooth vertex (`cs_gouraud`) into a colour buffer, which the vertex
//! stage reads (`vs_flat`, `vs_gouraud`). Flat shading is then the chapter's one evaluation per
//! face (the flat mesh's three corners would each evaluate it), and the lighting runs where a
//! CPU rasterizer spreads it over its threads (llvmpipe runs vertex stages on one). The bind
//! groups are @group(3), bindings 1–3 (binding 0 is the shadow pass's).

use crate::buffers::buffer_entry;
pub use crate::shaders::{FLAT_ENTRY_POINT, GOURAUD_ENTRY_POINT, lighting_entry_point as entry_point};
use crate::vertex::{FlatVertex, SmoothVertex};

/// Points per workgroup (`@workgroup_size` of both passes).
pub const LIT_WORKGROUP: u32 = 64;

/// The compute side's @group(3): the flat corners (read) and the face colours (written).
pub(crate) fn compute_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let storage = |binding, read_only| {
        buffer_entry(binding, wgpu::ShaderStages::COMPUTE, wgpu::BufferBindingType::Storage { read_only }, false, None)
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("lit points (compute)"),
        entries: &[storage(1, true), storage(2, false)],
    })
}

/// The flat and Gouraud pipelines' @group(3): the colours, read by the vertex stage.
pub(crate) fn colors_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("lit colours"),
        entries: &[buffer_entry(
            3,
            wgpu::ShaderStages::VERTEX,
            wgpu::BufferBindingType::Storage { read_only: true },
            false,
            None,
        )],
    })
}

/// Bytes of one colour (`vec4<f32>`).
const COLOR_BYTES: u64 = 16;
/// Bytes of one face's three flat corners, `cs_flat`'s input per point.
pub const FACE_BYTES: u64 = 3 * size_of::<FlatVertex>() as u64;
/// Bytes of one smooth vertex, `cs_gouraud`'s input per point.
pub const VERTEX_BYTES: u64 = size_of::<SmoothVertex>() as u64;

/// Points per compute chunk on a device, for inputs of `item_bytes` each: each chunk's two
/// bindings stay within `max_storage_buffer_binding_size`, start at multiples of the storage
/// offset alignment, and its dispatch within `max_compute_workgroups_per_dimension`.
pub fn chunk_points(limits: &wgpu::Limits, item_bytes: u64) -> u64 {
    // A multiple of `align` points starts both bindings at a multiple of `align` bytes.
    let step = (limits.min_storage_buffer_offset_alignment as u64).max(1);
    let by_binding = limits.max_storage_buffer_binding_size / item_bytes.max(COLOR_BYTES);
    let by_dispatch = limits.max_compute_workgroups_per_dimension as u64 * LIT_WORKGROUP as u64;
    (by_binding.min(by_dispatch) / step * step).max(step)
}

/// One object's colours of one pass and the bind groups that reach them.
/// (The bind groups hold the colour buffer.)
pub struct LitColors {
    /// Per chunk: the compute bind group and its point count.
    pub(crate) chunks: Vec<(wgpu::BindGroup, u32)>,
    /// The vertex stage's bind group (all the colours).
    pub(crate) colors_bind: wgpu::BindGroup,
}

impl LitColors {
    /// The colour buffer and bind groups for `count` points of `item_bytes` each in `input`,
    /// `per_point` colours each (2: split, `lit_split` in the WGSL); `None` for an empty mesh
    /// (nothing to light or draw).
    pub(crate) fn new(
        device: &wgpu::Device,
        layouts: (&wgpu::BindGroupLayout, &wgpu::BindGroupLayout),
        input: &wgpu::Buffer,
        count: u64,
        item_bytes: u64,
        per_point: u64,
    ) -> Option<LitColors> {
        if count == 0 {
            return None;
        }
        let color_bytes = COLOR_BYTES * per_point;
        let colors = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("lit colours"),
            size: count * color_bytes,
            usage: wgpu::BufferUsages::STORAGE,
            mapped_at_creation: false,
        });
        let per = chunk_points(&device.limits(), item_bytes.max(color_bytes));
        let range = |buffer, first: u64, n: u64, bytes: u64| {
            wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer,
                offset: first * bytes,
                size: wgpu::BufferSize::new(n * bytes),
            })
        };
        let chunks = (0..count)
            .step_by(per as usize)
            .map(|first| {
                let n = per.min(count - first);
                let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("lit points chunk"),
                    layout: layouts.0,
                    entries: &[
                        wgpu::BindGroupEntry { binding: 1, resource: range(input, first, n, item_bytes) },
                        wgpu::BindGroupEntry { binding: 2, resource: range(&colors, first, n, color_bytes) },
                    ],
                });
                (bind, n as u32)
            })
            .collect();
        let colors_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("lit colours"),
            layout: layouts.1,
            entries: &[wgpu::BindGroupEntry { binding: 3, resource: colors.as_entire_binding() }],
        });
        Some(LitColors { chunks, colors_bind })
    }
}

/// The lighting pass `entry` (`cs_flat`, `cs_gouraud`) of a program from the cache: its effect
/// set and light loop, built on first use.
pub(crate) fn pipeline<'c>(
    cache: &'c mut crate::pipelines::PipelineCache,
    program: crate::program::Program,
    entry: &'static str,
) -> &'c wgpu::ComputePipeline {
    let (effects, lights) = (program.effects(), program.light_loop());
    let key = crate::pipelines::PassKey { pass: entry, effects, lights, format: None };
    cache.pass_compute(key, |cx| {
        let shadows = effects.has(shadelab_model::effects::Effect::CastShadows);
        let layout = if shadows { &cx.layouts.lighting_pass_shadows } else { &cx.layouts.lighting_pass };
        let label = format!("{entry} [{}] {}", effects.label(), lights.label());
        build_pipeline(cx.device, layout, cx.module, entry, &label, lights)
    })
}

/// Build the compute pipeline of `entry` (a lighting pass) from a permutation's module.
fn build_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    entry: &str,
    label: &str,
    lights: crate::light_loop::LightLoop,
) -> wgpu::ComputePipeline {
    let constants = lights.constants();
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        module,
        entry_point: Some(entry),
        compilation_options: wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() },
        cache: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chunks_are_aligned_and_within_the_limits() {
        for (binding, align, groups) in [(128u64 << 20, 256u32, 65535u32), (1 << 31, 64, 65535), (1 << 20, 256, 16)] {
            let limits = wgpu::Limits {
                max_storage_buffer_binding_size: binding,
                min_storage_buffer_offset_alignment: align,
                max_compute_workgroups_per_dimension: groups,
                ..wgpu::Limits::default()
            };
            for item in [FACE_BYTES, VERTEX_BYTES] {
                let n = chunk_points(&limits, item);
                assert!(n * item <= binding && n * COLOR_BYTES <= binding && n <= groups as u64 * 64, "{n}");
                assert_eq!(n * item % align as u64, 0);
                assert_eq!(n * COLOR_BYTES % align as u64, 0);
            }
        }
    }

    /// The shader's strides are the vertex formats'.
    #[test]
    fn the_strides_are_the_wgsl_constants() {
        let src = include_str!("../../../shaders/types.wgsl");
        for (name, bytes) in
            [("FLAT_CORNER_FLOATS", size_of::<FlatVertex>()), ("SMOOTH_VERTEX_FLOATS", size_of::<SmoothVertex>())]
        {
            let line = src.lines().find(|l| l.starts_with(&format!("const {name}"))).expect("declared");
            assert!(line.contains(&format!("= {}u;", bytes / 4)), "{line}");
        }
    }
}
