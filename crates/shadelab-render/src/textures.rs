//! A scene's textures on the GPU (docs/textures.md): each an `Rgba8UnormSrgb` image with its
//! sampler, bound beside the object uniforms (@group(1), bindings 1 and 2), and the per-vertex
//! surface attributes (texture coordinates, vertex colours) the textured permutations read.

use crate::vertex::SurfaceVertex;
use shadelab_model::mesh::TriangleMesh;
use shadelab_model::{Filter, Scene, Texture, Wrap};

/// The object group's layout entries for the base colour texture and its sampler.
pub(crate) fn layout_entries() -> [wgpu::BindGroupLayoutEntry; 2] {
    [
        wgpu::BindGroupLayoutEntry {
            binding: 1,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: true },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        },
        wgpu::BindGroupLayoutEntry {
            binding: 2,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            count: None,
        },
    ]
}

fn address(w: Wrap) -> wgpu::AddressMode {
    match w {
        Wrap::Repeat => wgpu::AddressMode::Repeat,
        Wrap::MirroredRepeat => wgpu::AddressMode::MirrorRepeat,
        Wrap::ClampToEdge => wgpu::AddressMode::ClampToEdge,
    }
}

/// A texture's image and sampler on the GPU, level 0 only (as the f64 reference samples it).
pub(crate) fn upload(device: &wgpu::Device, queue: &wgpu::Queue, t: &Texture) -> (wgpu::TextureView, wgpu::Sampler) {
    let size = wgpu::Extent3d { width: t.width, height: t.height, depth_or_array_layers: 1 };
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some(&t.name),
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8UnormSrgb,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    queue.write_texture(
        texture.as_image_copy(),
        &t.rgba8,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * t.width), rows_per_image: Some(t.height) },
        size,
    );
    let filter = match t.sampler.filter {
        Filter::Nearest => wgpu::FilterMode::Nearest,
        Filter::Linear => wgpu::FilterMode::Linear,
    };
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some(&t.name),
        address_mode_u: address(t.sampler.wrap[0]),
        address_mode_v: address(t.sampler.wrap[1]),
        mag_filter: filter,
        min_filter: filter,
        ..Default::default()
    });
    (texture.create_view(&Default::default()), sampler)
}

/// Which of the object bind groups each object uses: 0 for no texture (a white texel), `k + 1`
/// for the scene's texture `k`.
pub(crate) fn bind_of_objects(scene: &Scene) -> Vec<usize> {
    scene.objects.iter().map(|o| scene.base_color_texture(o).map_or(0, |r| r.texture + 1)).collect()
}

/// Whether any mesh of the scene has surface attributes (then every mesh gets a surface buffer:
/// a textured permutation reads one for every object it draws).
pub(crate) fn scene_has_surfaces(scene: &Scene) -> bool {
    scene.meshes.iter().any(|m| m.uvs.is_some() || m.colors.is_some())
}

/// Smooth vertex `i`'s surface attributes from a file mesh whose vertices are its smooth
/// vertices (absent ones: no texture coordinates, no tint).
pub(crate) fn surface_vertex(m: Option<&TriangleMesh>, i: usize) -> SurfaceVertex {
    let d = SurfaceVertex::default();
    let Some(m) = m else { return d };
    SurfaceVertex {
        uv: m.uvs.as_ref().and_then(|u| u.get(i)).copied().unwrap_or(d.uv),
        color: m.colors.as_ref().and_then(|c| c.get(i)).copied().unwrap_or(d.color),
    }
}
