//! The GPU vertex formats (`#[repr(C)]` + bytemuck) and their buffer layouts, packed from the
//! model's mesh vertices (`shadelab_model::mesh`) field for field.

use shadelab_model::mesh::{FlatCorner, MeshVertex};

/// A vertex of the smooth (indexed) mesh: Gouraud and Phong shading, and the baseline.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct SmoothVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
}

/// A corner of the flat (unindexed) mesh: each face carries its own normal and the centroid where
/// flat shading evaluates the lighting once for the whole face.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FlatVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub centroid: [f32; 3],
}

const SMOOTH_ATTRS: [wgpu::VertexAttribute; 2] = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
const FLAT_ATTRS: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![0 => Float32x3];

impl SmoothVertex {
    /// Its vertex buffer layout (locations 0 position, 1 normal).
    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: size_of::<SmoothVertex>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &SMOOTH_ATTRS,
    };
}

impl FlatVertex {
    /// Its vertex buffer layout: location 0, the position (the normal and the centroid are read
    /// by the per-face pass, `lighting_pass.rs`, as storage).
    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: size_of::<FlatVertex>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &FLAT_ATTRS,
    };
}

impl From<&MeshVertex> for SmoothVertex {
    fn from(v: &MeshVertex) -> SmoothVertex {
        SmoothVertex { position: v.position, normal: v.normal }
    }
}

impl From<&FlatCorner> for FlatVertex {
    fn from(c: &FlatCorner) -> FlatVertex {
        FlatVertex { position: c.position, normal: c.normal, centroid: c.centroid }
    }
}
