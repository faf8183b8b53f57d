//! A scene's textures on the GPU (docs/textures.md): each image uploaded once as `Rgba8Unorm`,
//! viewed as `Rgba8UnormSrgb` where a material reads it as colour; per material, the textures
//! of its five slots with their samplers, bound beside the object uniforms (@group(1)); and the
//! per-vertex surface attributes (texture coordinates, vertex colours) the textured permutations
//! read.

use crate::vertex::SurfaceVertex;
use shadelab_model::mesh::TriangleMesh;
use shadelab_model::scene::{ColorSpace, Level};
use shadelab_model::{Filter, Object, Scene, Texture, Wrap};

/// The material texture slots, in binding order: slot k is bound at `1 + 2k` (texture) and
/// `2 + 2k` (sampler), and read as the colour space it names.
pub(crate) const SLOTS: [(&str, ColorSpace); 5] = [
    ("base colour", ColorSpace::Srgb),
    ("metallic–roughness", ColorSpace::Linear),
    ("occlusion", ColorSpace::Linear),
    ("emissive", ColorSpace::Srgb),
    ("normal", ColorSpace::Linear),
];

/// Bit k of `ObjectUniform::maps`: the object's material has slot k's texture (surface.wgsl's
/// `MAP_…` constants).
pub(crate) const MAP_BITS: [u32; 5] = [1, 2, 4, 8, 16];

/// The textures of an object's material, by slot: scene texture indices, `None` for a slot
/// without one (or with an index past the scene's textures).
pub(crate) type SlotTextures = [Option<usize>; 5];

/// Object `o`'s textures by slot.
pub(crate) fn object_slots(scene: &Scene, o: &Object) -> SlotTextures {
    let Some(m) = scene.materials.get(o.material) else { return [None; 5] };
    let maps = &m.maps;
    [
        m.base_color_texture.map(|r| r.texture),
        maps.metal_roughness.map(|r| r.texture.texture),
        maps.occlusion.map(|r| r.texture.texture),
        maps.emissive.map(|r| r.texture),
        maps.normal.map(|r| r.texture.texture),
    ]
    .map(|t| t.filter(|&i| i < scene.textures.len()))
}

/// The object group's layout entries for the slots' textures and samplers.
pub(crate) fn layout_entries() -> Vec<wgpu::BindGroupLayoutEntry> {
    (0..SLOTS.len() as u32)
        .flat_map(|k| {
            [
                crate::pipelines::fragment_texture(1 + 2 * k, wgpu::TextureSampleType::Float { filterable: true }),
                wgpu::BindGroupLayoutEntry {
                    binding: 2 + 2 * k,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ]
        })
        .collect()
}

fn address(w: Wrap) -> wgpu::AddressMode {
    match w {
        Wrap::Repeat => wgpu::AddressMode::Repeat,
        Wrap::MirroredRepeat => wgpu::AddressMode::MirrorRepeat,
        Wrap::ClampToEdge => wgpu::AddressMode::ClampToEdge,
    }
}

/// A texture on the GPU as one colour space reads it: its image with its mipmap chain (the
/// model's `Texture::mip_levels`, the bytes the f64 reference samples) where its sampler asks
/// for mipmaps, and its sampler.
pub(crate) struct GpuTexture {
    view: wgpu::TextureView,
    sampler: wgpu::Sampler,
}

impl GpuTexture {
    pub(crate) fn view(&self) -> &wgpu::TextureView {
        &self.view
    }

    pub(crate) fn sampler(&self) -> &wgpu::Sampler {
        &self.sampler
    }
}

fn filter_mode(f: Filter) -> wgpu::FilterMode {
    match f {
        Filter::Nearest => wgpu::FilterMode::Nearest,
        Filter::Linear => wgpu::FilterMode::Linear,
    }
}

/// Upload texture `t` as `space` reads it: `Rgba8UnormSrgb` for colour (decoded per texel, then
/// filtered), `Rgba8Unorm` for data, with every level of its chain when it is mipmapped.
pub(crate) fn upload(device: &wgpu::Device, queue: &wgpu::Queue, t: &Texture, space: ColorSpace) -> GpuTexture {
    // Without mipmaps the image alone: no chain is made.
    let chain = match t.sampler.mipmap {
        Some(_) => t.mip_levels(space),
        None => std::sync::Arc::new(vec![Level { width: t.width, height: t.height, rgba8: t.rgba8.clone() }]),
    };
    let levels = &chain[..];
    let size = wgpu::Extent3d { width: t.width, height: t.height, depth_or_array_layers: 1 };
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some(&t.name),
        size,
        mip_level_count: levels.len() as u32,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: match space {
            ColorSpace::Srgb => wgpu::TextureFormat::Rgba8UnormSrgb,
            ColorSpace::Linear => wgpu::TextureFormat::Rgba8Unorm,
        },
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (k, l) in levels.iter().enumerate() {
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &texture,
                mip_level: k as u32,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            &l.rgba8,
            wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * l.width), rows_per_image: Some(l.height) },
            wgpu::Extent3d { width: l.width, height: l.height, depth_or_array_layers: 1 },
        );
    }
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some(&t.name),
        address_mode_u: address(t.sampler.wrap[0]),
        address_mode_v: address(t.sampler.wrap[1]),
        mag_filter: filter_mode(t.sampler.filter),
        min_filter: filter_mode(t.sampler.min),
        mipmap_filter: match t.sampler.mipmap {
            Some(Filter::Linear) => wgpu::MipmapFilterMode::Linear,
            _ => wgpu::MipmapFilterMode::Nearest,
        },
        ..Default::default()
    });
    GpuTexture { view: texture.create_view(&Default::default()), sampler }
}

/// The distinct slot sets of the scene's objects (the first is the empty set, for objects with
/// no texture: white texels) and which one each object uses: one object bind group per set.
pub(crate) fn bind_sets(scene: &Scene) -> (Vec<SlotTextures>, Vec<usize>) {
    let mut sets: Vec<SlotTextures> = vec![[None; 5]];
    let of = scene
        .objects
        .iter()
        .map(|o| {
            let s = object_slots(scene, o);
            sets.iter().position(|x| *x == s).unwrap_or_else(|| {
                sets.push(s);
                sets.len() - 1
            })
        })
        .collect();
    (sets, of)
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
        tangent: m.tangents.as_ref().and_then(|t| t.get(i)).copied().unwrap_or(d.tangent),
    }
}
