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

/// A smooth vertex's surface attributes, in a second vertex buffer that only the permutations
/// with a base colour texture or vertex colours read: texture coordinates and the vertex colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct SurfaceVertex {
    pub uv: [f32; 2],
    pub color: [f32; 3],
    /// Object-space tangent and bitangent sign (zero: none, the normal texture leaves N).
    pub tangent: [f32; 4],
}

impl Default for SurfaceVertex {
    /// No texture coordinates and no tint.
    fn default() -> Self {
        SurfaceVertex { uv: [0.0; 2], color: [1.0; 3], tangent: [0.0; 4] }
    }
}

const SURFACE_UV: wgpu::VertexAttribute =
    wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x2, offset: 0, shader_location: 2 };
const SURFACE_COLOR: wgpu::VertexAttribute =
    wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 8, shader_location: 3 };
const SURFACE_TANGENT: wgpu::VertexAttribute =
    wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 20, shader_location: 4 };
const UV: [wgpu::VertexAttribute; 1] = [SURFACE_UV];
const COLOR: [wgpu::VertexAttribute; 1] = [SURFACE_COLOR];
const UV_COLOR: [wgpu::VertexAttribute; 2] = [SURFACE_UV, SURFACE_COLOR];
const UV_TANGENT: [wgpu::VertexAttribute; 2] = [SURFACE_UV, SURFACE_TANGENT];
const ALL: [wgpu::VertexAttribute; 3] = [SURFACE_UV, SURFACE_COLOR, SURFACE_TANGENT];

impl SurfaceVertex {
    /// Its buffer layout with the attributes a permutation reads (locations 2 uv, 3 colour,
    /// 4 tangent, which comes only with texture coordinates), `None` when it reads none.
    pub fn layout(uv: bool, color: bool, tangent: bool) -> Option<wgpu::VertexBufferLayout<'static>> {
        let attributes: &'static [wgpu::VertexAttribute] = match (uv, color, tangent && uv) {
            (false, false, _) => return None,
            (true, false, false) => &UV,
            (false, true, _) => &COLOR,
            (true, true, false) => &UV_COLOR,
            (true, false, true) => &UV_TANGENT,
            (true, true, true) => &ALL,
        };
        Some(wgpu::VertexBufferLayout {
            array_stride: size_of::<SurfaceVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes,
        })
    }
}

/// The vertex buffers a pipeline of `effects` reads: `first` (the smooth or flat mesh), then the
/// surface buffer where the permutation reads one.
pub fn buffers(
    first: wgpu::VertexBufferLayout<'static>,
    effects: shadelab_model::effects::EffectKey,
) -> Vec<Option<wgpu::VertexBufferLayout<'static>>> {
    use shadelab_model::effects::Effect;
    let surface = SurfaceVertex::layout(
        effects.samples_textures(),
        effects.has(Effect::VertexColors),
        effects.has(Effect::NormalTexture),
    );
    std::iter::once(Some(first)).chain(surface.map(Some)).collect()
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
