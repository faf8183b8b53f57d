//! A scene on the GPU: each shape's smooth and flat meshes (written in bounded staging batches),
//! the globals and per-object uniform buffers, and the error for a scene the device cannot hold.

use crate::buffers::written_buffer;
use crate::renderer::Renderer;
use crate::uniforms::{GlobalsUniform, ObjectUniform};
use crate::vertex::{FlatVertex, SmoothVertex};
use shadelab_model::scene::ColorSpace;
use shadelab_model::{Scene, Shape};
use std::collections::HashMap;

/// A shape's meshes on the GPU.
pub struct MeshGpu {
    pub smooth: wgpu::Buffer,
    pub smooth_count: u32,
    pub indices: wgpu::Buffer,
    pub index_count: u32,
    /// Corners of the flat mesh (three a triangle); their size is checked at upload.
    pub flat_count: u32,
    /// Flat shading's corners, uploaded by the first frame that draws the mesh flat: a scene
    /// never drawn flat holds none (36 B × 3 a triangle, about 1 GB at 10⁷ triangles).
    flat: std::sync::OnceLock<FlatGpu>,
    /// What the flat corners are made from.
    flat_source: FlatSource,
    /// Each smooth vertex's texture coordinates and colour (`SurfaceVertex`), in scenes that
    /// have any: the textured and vertex-coloured permutations read it.
    pub surface: Option<wgpu::Buffer>,
}

/// The flat mesh on the GPU: its corners and, in scenes with surface attributes, theirs.
pub struct FlatGpu {
    pub corners: wgpu::Buffer,
    pub surface: Option<wgpu::Buffer>,
}

/// Where a mesh's flat corners come from when they are first drawn: a file's mesh (shared with
/// the scene, not copied), or the tessellation made at upload.
enum FlatSource {
    File { meshes: shadelab_model::mesh::Meshes, index: usize, surfaces: bool },
    Tessellated { data: std::sync::Arc<shadelab_model::mesh::MeshData>, surfaces: bool },
}

impl MeshGpu {
    /// The flat mesh's buffers, written on first use (the lighting pass and the flat draw).
    pub fn flat(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> &FlatGpu {
        self.flat.get_or_init(|| {
            let count = self.flat_count as usize;
            let usage = wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::STORAGE;
            let (corners, surface) = match &self.flat_source {
                FlatSource::File { meshes, index, surfaces } => {
                    let m = meshes.get(*index).expect("the mesh was uploaded from this index");
                    let corners = buffer_from_pieces(device, queue, "flat vertices", usage, count, |r, out| {
                        out.extend(
                            (r.start / 3..r.end / 3).flat_map(|k| m.flat_corners(k).map(|c| FlatVertex::from(&c))),
                        )
                    });
                    // Corner 3k + c of the flat mesh is corner c of triangle k.
                    let surface = surfaces.then(|| {
                        flat_surface(device, queue, count, |c| {
                            crate::textures::surface_vertex(Some(m), m.indices[c / 3][c % 3] as usize)
                        })
                    });
                    (corners, surface)
                }
                FlatSource::Tessellated { data, surfaces } => {
                    let corners = buffer_from_pieces(device, queue, "flat vertices", usage, count, |r, out| {
                        out.extend(data.flat_vertices[r].iter().map(FlatVertex::from))
                    });
                    (corners, surfaces.then(|| flat_surface(device, queue, count, |_| Default::default())))
                }
            };
            FlatGpu { corners, surface }
        })
    }
}

/// The flat mesh's surface attributes, corner `c`'s from `at(c)`.
fn flat_surface(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    count: usize,
    at: impl Fn(usize) -> crate::vertex::SurfaceVertex,
) -> wgpu::Buffer {
    buffer_from_pieces(device, queue, "flat surface attributes", wgpu::BufferUsages::VERTEX, count, |r, out| {
        out.extend(r.map(&at))
    })
}

/// A scene uploaded to the GPU: meshes (shared between objects of the same shape and
/// tessellation), the globals and the per-object uniforms.
pub struct SceneGpu {
    pub(crate) meshes: HashMap<(Shape, u32), MeshGpu>,
    /// Each object's mesh, in the scene's object order.
    pub(crate) objects: Vec<(Shape, u32)>,
    /// Each object's colours of the lighting passes (`lighting_pass.rs`), flat shading's per
    /// face and Gouraud's per vertex (`None` for an empty mesh), made by the first frame that
    /// needs them: a scene drawn only with Phong shading never holds them.
    /// Indexed by `2·flat + split` (split: two colours a point, the textured permutations').
    lit: [std::sync::OnceLock<Vec<Option<crate::lighting_pass::LitColors>>>; 4],
    pub(crate) globals: wgpu::Buffer,
    pub(crate) globals_bind: wgpu::BindGroup,
    /// The environment's prefiltered levels (86 KiB), written only when a program draws its
    /// split sum, and the environment (with the sun it follows) they were written for.
    pub(crate) env_levels: wgpu::Buffer,
    pub(crate) env_levels_of: Option<(shadelab_model::lighting::env_map::Environment, Option<glam::DVec3>)>,
    /// The environment's occlusion grid (64 KiB), written only when a program draws it, and
    /// the geometry it was baked for with the grid's placement in the globals.
    pub(crate) env_occlusion: wgpu::Buffer,
    pub(crate) env_occlusion_of: Option<(OcclusionKey, [[f32; 4]; 2])>,
    /// The environment's nine SH terms as the globals hold them, and the environment (with its
    /// sun) they were projected for: a large map's projection reads every texel.
    pub(crate) env_sh_of: Option<(shadelab_model::lighting::env_map::Environment, Option<glam::DVec3>, [[f32; 4]; 9])>,
    pub(crate) objects_buf: wgpu::Buffer,
    /// The object groups (uniforms, each slot's texture and sampler), one per distinct set of
    /// textures (`textures::bind_sets`): 0 with white texels for objects without any.
    pub(crate) objects_binds: Vec<wgpu::BindGroup>,
    /// Which of `objects_binds` each object uses.
    pub(crate) object_bind_of: Vec<usize>,
    /// Whether the meshes have surface buffers (`MeshGpu::surface`).
    pub(crate) has_surfaces: bool,
    /// Bytes between two objects' uniforms (`ObjectUniform` rounded up to the device's offset
    /// alignment).
    pub(crate) object_stride: u64,
    pub triangle_count: usize,
    /// The shadow maps, made by the first frame whose program has cast shadows
    /// (`shadow_pass.rs`): the frame owns them, writing and drawing through `&mut SceneGpu`.
    pub(crate) shadows: Option<crate::shadow_maps::ShadowMaps>,
    /// How many shadow-map layers the shadow passes have drawn: a layer is drawn again only when
    /// its light's projection, its resolution or an object's transform changed.
    pub shadow_layer_draws: u64,
    /// The transparent objects far to near, and each object's exit shape as last written
    /// (`write_uniforms`): what the glass pass draws and how.
    pub(crate) glass_order: Vec<usize>,
    pub(crate) glass_exits: Vec<u32>,
    /// The scene pass's clear colour as last written (`uniforms::clear_color` of the scene).
    pub(crate) clear: wgpu::Color,
    /// Whether the last uniforms written draw the environment as the background (the uber
    /// pipeline, which a frame may draw with meanwhile, holds the background for every scene).
    pub(crate) env_background: bool,
    /// How many times the uniforms were written: a caller that keeps them between frames sees
    /// here whether another draw (another target, another scene's parameters) wrote over them.
    pub uniform_writes: u64,
}

impl SceneGpu {
    /// Object `i`'s bind group (@group(1)), set with its uniforms' dynamic offset.
    pub(crate) fn object_bind(&self, i: usize) -> &wgpu::BindGroup {
        &self.objects_binds[self.object_bind_of[i]]
    }

    /// The lighting pass's colours per object, flat shading's (`flat`) or Gouraud's, made on first
    /// use: objects share meshes, not their colours.
    pub(crate) fn lit_colors(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layouts: (&wgpu::BindGroupLayout, &wgpu::BindGroupLayout),
        flat: bool,
        split: bool,
    ) -> &[Option<crate::lighting_pass::LitColors>] {
        use crate::lighting_pass::{FACE_BYTES, LitColors, VERTEX_BYTES};
        let cell = &self.lit[2 * flat as usize + split as usize];
        cell.get_or_init(|| {
            self.objects
                .iter()
                .map(|k| {
                    let m = &self.meshes[k];
                    let (input, count, bytes) = if flat {
                        (&m.flat(device, queue).corners, m.flat_count as u64 / 3, FACE_BYTES)
                    } else {
                        (&m.smooth, m.smooth_count as u64, VERTEX_BYTES)
                    };
                    LitColors::new(device, layouts, input, count, bytes, if split { 2 } else { 1 })
                })
                .collect()
        })
    }
}

/// A scene the device cannot hold.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UploadError {
    #[error(
        "object '{object}': its {what} need {bytes} bytes, more than this device's largest buffer ({limit} bytes, max_buffer_size)"
    )]
    BufferTooLarge { object: String, what: &'static str, bytes: u64, limit: u64 },
}

/// What uploading a scene needs of a renderer, apart from it: a worker thread can upload while
/// the renderer draws the old scene (the viewer's loading).
#[derive(Clone)]
pub struct Uploader {
    device: wgpu::Device,
    queue: wgpu::Queue,
    globals_layout: wgpu::BindGroupLayout,
    object_layout: wgpu::BindGroupLayout,
    tables: wgpu::Buffer,
}

impl Renderer {
    /// The uploader of this renderer's device and layouts.
    pub fn uploader(&self) -> Uploader {
        Uploader {
            device: self.device.clone(),
            queue: self.queue.clone(),
            globals_layout: self.globals_layout.clone(),
            object_layout: self.object_layout.clone(),
            tables: self.tables.clone(),
        }
    }

    /// Upload a scene's meshes and uniforms ([`Uploader::upload`]).
    pub fn upload(&self, scene: &Scene) -> Result<SceneGpu, UploadError> {
        self.uploader().upload(scene)
    }
}

impl Uploader {
    /// Upload a scene's meshes and uniforms. A mesh whose vertex or index buffer would be larger
    /// than the device allows (`max_buffer_size`) is an error, not a GPU validation failure.
    pub fn upload(&self, scene: &Scene) -> Result<SceneGpu, UploadError> {
        let device = &self.device;
        let mut meshes = HashMap::new();
        let mut objects = Vec::new();
        let surfaces = crate::textures::scene_has_surfaces(scene);
        for o in &scene.objects {
            let k = (o.shape, o.tessellation);
            // `Shape::Mesh(i)` keys by its index: each file mesh is built once (its normals, else
            // the crease-angle rule), shared by every object that shows it.
            if let std::collections::hash_map::Entry::Vacant(e) = meshes.entry(k) {
                e.insert(self.upload_mesh(scene, o, surfaces)?);
            }
            objects.push(k);
        }
        let triangle_count = scene.triangle_count();
        let globals =
            written_buffer(device, "globals", size_of::<GlobalsUniform>() as u64, wgpu::BufferUsages::UNIFORM);
        let align = device.limits().min_uniform_buffer_offset_alignment as u64;
        let object_stride = (size_of::<ObjectUniform>() as u64).div_ceil(align) * align;
        let objects_size = object_stride * scene.objects.len().max(1) as u64;
        let objects_buf = written_buffer(device, "objects", objects_size, wgpu::BufferUsages::UNIFORM);
        let levels_size = (shadelab_model::lighting::environment::ENV_PREFILTERED_TEXELS * 16) as u64;
        let env_levels = written_buffer(device, "environment levels", levels_size, wgpu::BufferUsages::STORAGE);
        let occlusion_size = (shadelab_model::lighting::occlusion::OCC_NODES_MAX * 8) as u64;
        let env_occlusion =
            written_buffer(device, "environment occlusion", occlusion_size, wgpu::BufferUsages::STORAGE);
        let globals_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("globals"),
            layout: &self.globals_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: globals.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: env_levels.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: env_occlusion.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 3, resource: self.tables.as_entire_binding() },
            ],
        });
        let (sets, object_bind_of) = crate::textures::bind_sets(scene);
        let objects_binds = self.objects_binds(scene, &objects_buf, &sets);
        Ok(SceneGpu {
            meshes,
            objects,
            lit: Default::default(),
            globals,
            globals_bind,
            env_levels,
            env_levels_of: Default::default(),
            env_sh_of: Default::default(),
            env_occlusion,
            env_occlusion_of: Default::default(),
            objects_buf,
            objects_binds,
            object_bind_of,
            has_surfaces: surfaces,
            object_stride,
            triangle_count,
            shadows: None,
            shadow_layer_draws: 0,
            glass_order: Default::default(),
            glass_exits: Default::default(),
            clear: crate::uniforms::CLEAR_COLOR,
            env_background: false,
            uniform_writes: Default::default(),
        })
    }

    /// Object `o`'s mesh on the GPU: a file's vertices as they are when its normals are usable,
    /// else the tessellation (or the built file mesh), with surface attributes when `surfaces`.
    fn upload_mesh(&self, scene: &Scene, o: &shadelab_model::Object, surfaces: bool) -> Result<MeshGpu, UploadError> {
        let device = &self.device;
        let file_mesh = match o.shape {
            Shape::Mesh(i) => scene.meshes.get(i),
            _ => None,
        };
        let mut mesh = match (file_mesh, o.shape) {
            // The file's vertices as they are: written to the GPU piece by piece.
            (Some(m), Shape::Mesh(index)) if m.has_usable_normals() && m.check_finite().is_ok() => MeshGpu::new(
                device,
                &self.queue,
                &o.name,
                [m.positions.len(), 3 * m.triangle_count(), 3 * m.triangle_count()],
                |r, out| out.extend(r.map(|i| SmoothVertex::from(&m.smooth_vertex(i)))),
                |r, out| out.extend(m.indices[r.start / 3..r.end / 3].iter().flatten()),
                FlatSource::File { meshes: scene.meshes.clone(), index, surfaces },
            )?,
            _ => {
                let d = std::sync::Arc::new(scene.mesh_data(o));
                MeshGpu::new(
                    device,
                    &self.queue,
                    &o.name,
                    [d.smooth_vertices.len(), d.indices.len(), d.flat_vertices.len()],
                    |r, out| out.extend(d.smooth_vertices[r].iter().map(SmoothVertex::from)),
                    |r, out| out.extend_from_slice(&d.indices[r]),
                    FlatSource::Tessellated { data: d.clone(), surfaces },
                )?
            }
        };
        if surfaces {
            // The file's vertices are the smooth vertices only on the first path above.
            let m = file_mesh.filter(|m| m.has_usable_normals() && m.check_finite().is_ok());
            let count = mesh.smooth_count as usize;
            mesh.surface = Some(buffer_from_pieces(
                device,
                &self.queue,
                "surface attributes",
                wgpu::BufferUsages::VERTEX,
                count,
                |r, out| out.extend(r.map(|i| crate::textures::surface_vertex(m, i))),
            ));
        }
        Ok(mesh)
    }

    /// One object bind group per slot set of `sets` (`textures::bind_sets`): the uniforms in
    /// `objects_buf`, then each slot's texture view and sampler.
    fn objects_binds(
        &self,
        scene: &Scene,
        objects_buf: &wgpu::Buffer,
        sets: &[crate::textures::SlotTextures],
    ) -> Vec<wgpu::BindGroup> {
        let device = &self.device;
        // Each texture uploaded once; a slot without one reads a white texel (the identity of
        // every slot's rule).
        let white = shadelab_model::Texture::solid("white", [255; 4]);
        let white =
            [ColorSpace::Srgb, ColorSpace::Linear].map(|s| crate::textures::upload(device, &self.queue, &white, s));
        // Each scene texture once per colour space a slot reads it in.
        let mut textures: HashMap<(usize, ColorSpace), crate::textures::GpuTexture> = HashMap::new();
        sets.iter()
            .map(|set| {
                let mut entries = vec![wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                        buffer: objects_buf,
                        offset: 0,
                        size: wgpu::BufferSize::new(size_of::<ObjectUniform>() as u64),
                    }),
                }];
                for (slot, (_, space)) in set.iter().zip(crate::textures::SLOTS) {
                    if let Some(i) = slot {
                        textures.entry((*i, space)).or_insert_with(|| {
                            crate::textures::upload(device, &self.queue, &scene.textures[*i], space)
                        });
                    }
                }
                for (k, (slot, (_, space))) in set.iter().zip(crate::textures::SLOTS).enumerate() {
                    let t = match slot {
                        Some(i) => &textures[&(*i, space)],
                        None => &white[(space == ColorSpace::Linear) as usize],
                    };
                    let k = k as u32;
                    entries.push(wgpu::BindGroupEntry {
                        binding: 1 + 2 * k,
                        resource: wgpu::BindingResource::TextureView(t.view()),
                    });
                    entries.push(wgpu::BindGroupEntry {
                        binding: 2 + 2 * k,
                        resource: wgpu::BindingResource::Sampler(t.sampler()),
                    });
                }
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("objects"),
                    layout: &self.object_layout,
                    entries: &entries,
                })
            })
            .collect()
    }
}

/// Elements written per piece by [`buffer_from_pieces`]: 2¹⁶ flat vertices are 2.25 MiB, small
/// beside any mesh worth writing in pieces, large enough that the per-piece cost vanishes.
const PIECE_ELEMENTS: usize = 1 << 16;

/// Most staging memory one upload holds at a time: pieces are written into batches of this
/// size, and each batch's submission is waited for before the next is mapped, so a 10⁷-triangle
/// mesh never has a second whole copy of its 1.3 GB of vertex data in staging memory.
pub const STAGING_BATCH_BYTES: u64 = 64 << 20;

impl MeshGpu {
    /// A mesh's smooth vertices and indices on the GPU, `counts[0]` and `counts[1]` elements
    /// made by their `fill(range, out)`, which appends the elements of `range` (a range of
    /// indices covers whole triangles). The `counts[2]` flat corners are only sized here: they are
    /// written from `flat` when first drawn ([`MeshGpu::flat`]).
    #[allow(clippy::too_many_arguments)]
    fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        object: &str,
        counts: [usize; 3],
        smooth: impl Fn(std::ops::Range<usize>, &mut Vec<SmoothVertex>),
        indices: impl Fn(std::ops::Range<usize>, &mut Vec<u32>),
        flat: FlatSource,
    ) -> Result<MeshGpu, UploadError> {
        let limit = device.limits().max_buffer_size;
        let sizes = [size_of::<SmoothVertex>(), size_of::<u32>(), size_of::<FlatVertex>()];
        for ((what, count), size) in ["smooth vertices", "indices", "flat vertices"].into_iter().zip(counts).zip(sizes)
        {
            let bytes = (count as u64).saturating_mul(size as u64);
            if bytes > limit {
                return Err(UploadError::BufferTooLarge { object: object.into(), what, bytes, limit });
            }
        }
        let vertex = wgpu::BufferUsages::VERTEX;
        Ok(MeshGpu {
            // Also read as storage by the per-vertex pass (lighting_pass.rs).
            smooth: buffer_from_pieces(
                device,
                queue,
                "smooth vertices",
                vertex | wgpu::BufferUsages::STORAGE,
                counts[0],
                smooth,
            ),
            smooth_count: counts[0] as u32,
            indices: buffer_from_pieces(device, queue, "indices", wgpu::BufferUsages::INDEX, counts[1], indices),
            index_count: counts[1] as u32,
            // Also read as storage by the per-face pass (lighting_pass.rs), once written.
            flat: std::sync::OnceLock::new(),
            flat_source: flat,
            flat_count: counts[2] as u32,
            surface: None,
        })
    }
}

/// A GPU buffer of `count` elements, made `PIECE_ELEMENTS` at a time by `fill` straight into the
/// queue's staging memory: the whole array never exists on the CPU beside it. (Also not
/// `create_buffer_init`: it maps the buffer at creation, which wgpu zero-fills before the data is
/// copied in, a second pass over more than a gigabyte at 10⁷ triangles. A queue write marks the
/// buffer initialized, so nothing is cleared.)
fn buffer_from_pieces<T: bytemuck::Pod>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    label: &str,
    usage: wgpu::BufferUsages,
    count: usize,
    fill: impl Fn(std::ops::Range<usize>, &mut Vec<T>),
) -> wgpu::Buffer {
    let bytes = (count * size_of::<T>()) as u64;
    // wgpu buffers are at least COPY_BUFFER_ALIGNMENT (4) bytes; every element here is a multiple
    // of 4 bytes already, so only an empty mesh needs the minimum.
    let buffer = written_buffer(device, label, bytes.max(wgpu::COPY_BUFFER_ALIGNMENT), usage);
    // Whole triangles per piece when T is an index (3 per triangle) or a flat corner, and whole
    // pieces per batch.
    let step = PIECE_ELEMENTS - PIECE_ELEMENTS % 3;
    let batch = (STAGING_BATCH_BYTES as usize / size_of::<T>() / step).max(1) * step;
    let mut piece = Vec::with_capacity(step);
    for first in (0..count).step_by(batch) {
        let last = (first + batch).min(count);
        let offset = (first * size_of::<T>()) as u64;
        let size = wgpu::BufferSize::new(((last - first) * size_of::<T>()) as u64).expect("a batch is not empty");
        let mut view = queue.write_buffer_with(&buffer, offset, size).expect("a write inside the buffer just made");
        for start in (first..last).step_by(step) {
            piece.clear();
            fill(start..(start + step).min(last), &mut piece);
            let at = (start - first) * size_of::<T>();
            let b: &[u8] = bytemuck::cast_slice(&piece);
            view.slice(at..at + b.len()).copy_from_slice(b);
        }
        drop(view);
        if last < count {
            // Let this batch's copy run and its staging memory go before the next is mapped.
            queue.submit([]);
            let _ = device.poll(wgpu::PollType::wait_indefinitely());
        }
    }
    buffer
}

/// What the occlusion grid is baked from: each object's shape and transform, and the meshes.
#[derive(PartialEq)]
pub(crate) struct OcclusionKey {
    objects: Vec<(shadelab_model::Shape, shadelab_model::Transform)>,
    meshes: shadelab_model::mesh::Meshes,
}

impl OcclusionKey {
    pub(crate) fn of(scene: &Scene) -> OcclusionKey {
        OcclusionKey {
            objects: scene.objects.iter().map(|o| (o.shape, o.transform)).collect(),
            meshes: scene.meshes.clone(),
        }
    }
}
