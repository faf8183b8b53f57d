//! Flat shading's per-face pass (docs/model.md §8): before the scene pass, a compute dispatch per
//! object evaluates the model once per face (`cs_flat`, at the centroid with the face normal)
//! into a colour buffer, which the flat pipeline's corners read (`vs_flat`). The chapter's flat
//! shading is one evaluation per face; the flat mesh's three corners would otherwise each
//! evaluate it. Its bind groups are @group(3), bindings 1–3 (binding 0 is the shadow pass's).

use crate::vertex::FlatVertex;

/// The per-face pass's entry point in the lighting module.
pub const FLAT_ENTRY_POINT: &str = "cs_flat";

/// Faces per workgroup (`@workgroup_size` of `cs_flat`).
pub const FLAT_WORKGROUP: u32 = 64;

/// The compute side's @group(3): the flat corners (read) and the face colours (written).
pub(crate) fn compute_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("flat faces (compute)"),
        entries: &[storage(1, true), storage(2, false)],
    })
}

/// The flat pipeline's @group(3): the face colours, read by the corners.
pub(crate) fn colors_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("flat face colours"),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 3,
            visibility: wgpu::ShaderStages::VERTEX,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only: true },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }],
    })
}

/// Bytes of one face's colour (`vec4<f32>`).
const COLOR_BYTES: u64 = 16;
/// Bytes of one face's three flat corners.
const FACE_BYTES: u64 = 3 * size_of::<FlatVertex>() as u64;

/// Faces per compute chunk on a device: each chunk's two bindings stay within
/// `max_storage_buffer_binding_size`, start at multiples of the storage offset alignment, and its
/// dispatch within `max_compute_workgroups_per_dimension`.
pub fn chunk_faces(limits: &wgpu::Limits) -> u64 {
    // A multiple of `align` faces starts both bindings at a multiple of `align` bytes.
    let step = (limits.min_storage_buffer_offset_alignment as u64).max(1);
    let by_binding = limits.max_storage_buffer_binding_size / FACE_BYTES;
    let by_dispatch = limits.max_compute_workgroups_per_dimension as u64 * FLAT_WORKGROUP as u64;
    (by_binding.min(by_dispatch) / step * step).max(step)
}

/// One mesh's face colours and the bind groups that reach them.
pub struct FlatFaces {
    pub(crate) colors: wgpu::Buffer,
    /// Per chunk: the compute bind group and its face count.
    pub(crate) chunks: Vec<(wgpu::BindGroup, u32)>,
    /// The flat pipeline's bind group (all the mesh's colours).
    pub(crate) colors_bind: wgpu::BindGroup,
}

impl FlatFaces {
    /// The colour buffer and bind groups of a flat mesh of `faces` faces in `corners`; `None` for
    /// an empty mesh (nothing to shade or draw).
    pub(crate) fn new(
        device: &wgpu::Device,
        layouts: (&wgpu::BindGroupLayout, &wgpu::BindGroupLayout),
        corners: &wgpu::Buffer,
        faces: u64,
    ) -> Option<FlatFaces> {
        if faces == 0 {
            return None;
        }
        let colors = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("flat face colours"),
            size: faces * COLOR_BYTES,
            usage: wgpu::BufferUsages::STORAGE,
            mapped_at_creation: false,
        });
        let per = chunk_faces(&device.limits());
        let range = |buffer, first: u64, n: u64, bytes: u64| {
            wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer,
                offset: first * bytes,
                size: wgpu::BufferSize::new(n * bytes),
            })
        };
        let chunks = (0..faces)
            .step_by(per as usize)
            .map(|first| {
                let n = per.min(faces - first);
                let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("flat faces chunk"),
                    layout: layouts.0,
                    entries: &[
                        wgpu::BindGroupEntry { binding: 1, resource: range(corners, first, n, FACE_BYTES) },
                        wgpu::BindGroupEntry { binding: 2, resource: range(&colors, first, n, COLOR_BYTES) },
                    ],
                });
                (bind, n as u32)
            })
            .collect();
        let colors_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("flat face colours"),
            layout: layouts.1,
            entries: &[wgpu::BindGroupEntry { binding: 3, resource: colors.as_entire_binding() }],
        });
        Some(FlatFaces { colors, chunks, colors_bind })
    }

    /// Bytes of GPU memory the colours take.
    pub fn bytes(&self) -> u64 {
        self.colors.size()
    }
}

/// Build the compute pipeline of `cs_flat` from a permutation's module.
pub(crate) fn build_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    label: &str,
) -> wgpu::ComputePipeline {
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        module,
        entry_point: Some(FLAT_ENTRY_POINT),
        compilation_options: Default::default(),
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
            let n = chunk_faces(&limits);
            assert!(n * FACE_BYTES <= binding && n <= groups as u64 * 64, "{n}");
            assert_eq!(n * FACE_BYTES % align as u64, 0);
            assert_eq!(n * COLOR_BYTES % align as u64, 0);
        }
    }

    /// The shader's corner size is the vertex format's.
    #[test]
    fn the_corner_stride_is_the_wgsl_constant() {
        let src = include_str!("../../../shaders/shading.wgsl");
        let line = src.lines().find(|l| l.starts_with("const FLAT_CORNER_FLOATS")).expect("declared");
        assert!(line.contains(&format!("= {}u;", size_of::<FlatVertex>() / 4)), "{line}");
    }
}
