//! The renderer: one pipeline per permutation (cached by key), scene geometry and uniforms on
//! the GPU, and one draw path for every target (offscreen image or the viewer's texture).

use crate::shaders;
use crate::target::Target;
use crate::uniforms::{GlobalsUniform, ObjectUniform};
use shadelab_model::effects::{self, EffectKey};
use shadelab_model::mesh::{FlatVertex, SmoothVertex};
use shadelab_model::{Scene, ShadingMode, Shape, SpecularModel};
use std::collections::HashMap;

pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// The scene's background (`scene::BACKGROUND`), the same as the f64 reference's.
pub const CLEAR_COLOR: wgpu::Color = wgpu::Color {
    r: shadelab_model::scene::BACKGROUND[0],
    g: shadelab_model::scene::BACKGROUND[1],
    b: shadelab_model::scene::BACKGROUND[2],
    a: 1.0,
};

/// Everything that selects a distinct pipeline. Plain `Copy + Hash`: pipelines are cached by it
/// and never rebuilt per frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PipelineKey {
    pub shading: ShadingMode,
    /// The effects the shader module contains (the specular model is one of them).
    pub effects: EffectKey,
    pub color_format: wgpu::TextureFormat,
    /// The null-shader baseline (constant colour; `shading` and `effects` are then fixed).
    pub null_baseline: bool,
}

impl PipelineKey {
    pub fn new(settings: &RenderSettings, effects: EffectKey, color_format: wgpu::TextureFormat) -> PipelineKey {
        if settings.null_baseline {
            // One baseline pipeline, whatever the shading settings say.
            let shading = RenderSettings::default().shading;
            return PipelineKey { shading, effects: EffectKey::NONE, color_format, null_baseline: true };
        }
        PipelineKey { shading: settings.shading, effects, color_format, null_baseline: false }
    }
}

/// Which effect permutation draws a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Specialization {
    /// Only the effects the scene calls for (`effects::analyze`).
    #[default]
    Specialized,
    /// Every effect present, the unneeded ones switched off at run time by the uniforms.
    Uber,
    /// A given set (the benchmark's floors: the specialized set less one effect).
    Fixed(EffectKey),
}

/// Per-frame choices that do not change the geometry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderSettings {
    pub shading: ShadingMode,
    pub specular: SpecularModel,
    /// Paint pixels whose colour is NaN or infinite magenta.
    pub debug_nonfinite: bool,
    /// Draw the null-shader baseline instead (same geometry, constant colour, no lighting): what
    /// rasterizing the scene costs, the denominator of the cost study.
    pub null_baseline: bool,
    pub specialization: Specialization,
}

impl RenderSettings {
    pub fn new(shading: ShadingMode, specular: SpecularModel) -> RenderSettings {
        RenderSettings { shading, specular, ..Default::default() }
    }
    /// The null-shader baseline.
    pub fn baseline() -> RenderSettings {
        RenderSettings { null_baseline: true, ..Default::default() }
    }
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            shading: ShadingMode::Phong,
            specular: SpecularModel::CookTorrance,
            debug_nonfinite: false,
            null_baseline: false,
            specialization: Specialization::Specialized,
        }
    }
}

/// A shape's meshes on the GPU.
pub struct MeshGpu {
    pub smooth: wgpu::Buffer,
    pub indices: wgpu::Buffer,
    pub index_count: u32,
    pub flat: wgpu::Buffer,
    pub flat_count: u32,
}

/// A scene uploaded to the GPU: meshes (shared between objects of the same shape and
/// tessellation), the globals and the per-object uniforms.
pub struct SceneGpu {
    meshes: HashMap<(Shape, u32), MeshGpu>,
    objects: Vec<(Shape, u32)>,
    globals: wgpu::Buffer,
    globals_bind: wgpu::BindGroup,
    objects_buf: wgpu::Buffer,
    objects_bind: wgpu::BindGroup,
    object_stride: u64,
    pub triangle_count: usize,
    /// The effect set of the last `write_uniforms` (scene + settings).
    effects: std::cell::Cell<EffectKey>,
}

impl SceneGpu {
    /// The effect set the next draw uses.
    pub fn effects(&self) -> EffectKey {
        self.effects.get()
    }
}

/// A pipeline being built on a worker thread (the viewer keeps drawing meanwhile).
struct PendingBuild {
    started: std::time::Instant,
    rx: std::sync::mpsc::Receiver<wgpu::RenderPipeline>,
}

pub struct Renderer {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    /// The WGSL before preprocessing (shipped, or hot-reloaded).
    raw_source: String,
    modules: HashMap<EffectKey, wgpu::ShaderModule>,
    globals_layout: wgpu::BindGroupLayout,
    object_layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    pending: HashMap<PipelineKey, PendingBuild>,
    /// Build missing pipelines on a worker thread and draw with the uber pipeline meanwhile
    /// (the viewer); off, a missing pipeline is built before the draw (renders, tests, benches).
    pub build_in_background: bool,
    /// How many pipelines have been built (the viewer shows it: it must not grow per frame).
    pub pipeline_builds: u32,
    /// The last pipeline built and how long it took (module + pipeline creation).
    pub last_build: Option<(PipelineKey, std::time::Duration)>,
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

const SMOOTH_ATTRS: [wgpu::VertexAttribute; 2] = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
const FLAT_ATTRS: [wgpu::VertexAttribute; 3] = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3];

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
            raw_source: shaders::raw_lighting_source(),
            modules: HashMap::new(),
            globals_layout,
            object_layout,
            pipeline_layout,
            pipelines: HashMap::new(),
            pending: HashMap::new(),
            build_in_background: false,
            pipeline_builds: 0,
            last_build: None,
        }
    }

    /// Replace the shader source (hot reload). The source is preprocessed and validated by naga
    /// first: on an error nothing changes (the old modules and pipelines stay) and the message is
    /// returned; on success the cached modules and pipelines are dropped and rebuilt on next use.
    pub fn reload_shaders(&mut self, raw_source: &str) -> Result<(), String> {
        shaders::validate_raw(raw_source)?;
        self.raw_source = raw_source.to_owned();
        self.modules.clear();
        self.pipelines.clear();
        self.pending.clear();
        Ok(())
    }

    fn module(&mut self, effects: EffectKey) -> wgpu::ShaderModule {
        let (device, raw) = (&self.device, &self.raw_source);
        self.modules
            .entry(effects)
            .or_insert_with(|| {
                let src = shaders::lighting_source_for(raw, effects).expect("validated when loaded");
                device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(&format!("shadelab lighting [{}]", effects.label())),
                    source: wgpu::ShaderSource::Wgsl(src.into()),
                })
            })
            .clone()
    }

    /// The pipeline for a key, built on first use and cached.
    pub fn pipeline(&mut self, key: PipelineKey) -> &wgpu::RenderPipeline {
        if !self.pipelines.contains_key(&key) {
            let start = std::time::Instant::now();
            let module = self.module(key.effects);
            let p = build_pipeline(&self.device, &self.pipeline_layout, &module, key);
            self.finish_build(key, p, start.elapsed());
        }
        &self.pipelines[&key]
    }

    fn finish_build(&mut self, key: PipelineKey, p: wgpu::RenderPipeline, took: std::time::Duration) {
        self.pipeline_builds += 1;
        self.last_build = Some((key, took));
        log::info!("pipeline {:?} [{}] built in {:.1} ms", key.shading, key.effects.label(), took.as_secs_f64() * 1e3);
        self.pipelines.insert(key, p);
    }

    /// Move pipelines finished on worker threads into the cache.
    pub fn poll_builds(&mut self) {
        let done: Vec<(PipelineKey, wgpu::RenderPipeline, std::time::Duration)> = self
            .pending
            .iter()
            .filter_map(|(k, b)| b.rx.try_recv().ok().map(|p| (*k, p, b.started.elapsed())))
            .collect();
        for (k, p, took) in done {
            self.pending.remove(&k);
            self.finish_build(k, p, took);
        }
    }

    /// Whether pipelines are being built in the background.
    pub fn building(&self) -> bool {
        !self.pending.is_empty()
    }

    /// The key to draw with now: `key` if its pipeline is ready; with `build_in_background`, the
    /// uber pipeline of the same shading while `key` is built on a worker thread.
    fn ready_key(&mut self, key: PipelineKey) -> PipelineKey {
        self.poll_builds();
        if !self.build_in_background || self.pipelines.contains_key(&key) || key.null_baseline {
            return key;
        }
        if !self.pending.contains_key(&key) {
            let (tx, rx) = std::sync::mpsc::channel();
            let (device, layout) = (self.device.clone(), self.pipeline_layout.clone());
            let module = self.module(key.effects);
            std::thread::spawn(move || {
                // A send fails only if the renderer is gone: nothing to do then.
                let _ = tx.send(build_pipeline(&device, &layout, &module, key));
            });
            self.pending.insert(key, PendingBuild { started: std::time::Instant::now(), rx });
        }
        PipelineKey { effects: EffectKey::UBER, ..key }
    }

    /// Upload a scene's meshes and uniforms. A mesh whose vertex or index buffer would be larger
    /// than the device allows (`max_buffer_size`) is an error, not a GPU validation failure.
    pub fn upload(&self, scene: &Scene) -> Result<SceneGpu, UploadError> {
        let device = &self.device;
        let mut meshes = HashMap::new();
        let mut objects = Vec::new();
        for o in &scene.objects {
            let k = (o.shape, o.tessellation);
            // `Shape::Mesh(i)` keys by its index: each file mesh is built once (its normals, else
            // the crease-angle rule), shared by every object that shows it.
            if let std::collections::hash_map::Entry::Vacant(e) = meshes.entry(k) {
                let file_mesh = match o.shape {
                    Shape::Mesh(i) => scene.meshes.get(i),
                    _ => None,
                };
                let mesh = match file_mesh {
                    // The file's vertices as they are: written to the GPU piece by piece.
                    Some(m) if m.has_usable_normals() && m.check_finite().is_ok() => MeshGpu::new(
                        device,
                        &self.queue,
                        &o.name,
                        [m.positions.len(), 3 * m.triangle_count(), 3 * m.triangle_count()],
                        |r, out| out.extend(r.map(|i| m.smooth_vertex(i))),
                        |r, out| out.extend(m.indices[r.start / 3..r.end / 3].iter().flatten()),
                        |r, out| out.extend((r.start / 3..r.end / 3).flat_map(|k| m.flat_corners(k))),
                    )?,
                    _ => {
                        let d = scene.mesh_data(o);
                        MeshGpu::new(
                            device,
                            &self.queue,
                            &o.name,
                            [d.smooth_vertices.len(), d.indices.len(), d.flat_vertices.len()],
                            |r, out| out.extend_from_slice(&d.smooth_vertices[r]),
                            |r, out| out.extend_from_slice(&d.indices[r]),
                            |r, out| out.extend_from_slice(&d.flat_vertices[r]),
                        )?
                    }
                };
                e.insert(mesh);
            }
            objects.push(k);
        }
        let triangle_count = scene.triangle_count();
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("globals"),
            size: size_of::<GlobalsUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let align = device.limits().min_uniform_buffer_offset_alignment as u64;
        let object_stride = (size_of::<ObjectUniform>() as u64).div_ceil(align) * align;
        let objects_buf = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("objects"),
            size: object_stride * scene.objects.len().max(1) as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let globals_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("globals"),
            layout: &self.globals_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: globals.as_entire_binding() }],
        });
        let objects_bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("objects"),
            layout: &self.object_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &objects_buf,
                    offset: 0,
                    size: wgpu::BufferSize::new(size_of::<ObjectUniform>() as u64),
                }),
            }],
        });
        Ok(SceneGpu {
            meshes,
            objects,
            globals,
            globals_bind,
            objects_buf,
            objects_bind,
            object_stride,
            triangle_count,
            effects: std::cell::Cell::new(EffectKey::UBER),
        })
    }

    /// Write a scene's parameters (materials, lights, camera) into its uniforms. Cheap: the
    /// viewer calls it whenever a parameter changes; geometry stays.
    pub fn write_uniforms(&self, gpu_scene: &SceneGpu, scene: &Scene, target: &Target, settings: &RenderSettings) {
        let flags = if settings.debug_nonfinite { crate::uniforms::FLAG_DEBUG_NONFINITE } else { 0 };
        let g = GlobalsUniform::new(scene, target.width, target.height, flags, settings.specular);
        gpu_scene.effects.set(match settings.specialization {
            Specialization::Specialized => effects::analyze(scene, settings.specular).key,
            Specialization::Uber => EffectKey::UBER,
            Specialization::Fixed(k) => k,
        });
        self.queue.write_buffer(&gpu_scene.globals, 0, bytemuck::bytes_of(&g));
        let mut bytes = vec![0u8; (gpu_scene.object_stride as usize) * scene.objects.len()];
        for (i, o) in scene.objects.iter().enumerate() {
            let u = ObjectUniform::new(o, &scene.materials[o.material]);
            let at = i * gpu_scene.object_stride as usize;
            bytes[at..at + size_of::<ObjectUniform>()].copy_from_slice(bytemuck::bytes_of(&u));
        }
        self.queue.write_buffer(&gpu_scene.objects_buf, 0, &bytes);
    }

    /// Record the scene pass into `encoder`, drawing into `target`. `timestamps` (a query set
    /// and the index of its first of two slots) brackets the pass when the device has them.
    pub fn encode(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        gpu_scene: &SceneGpu,
        target: &Target,
        settings: &RenderSettings,
        timestamps: Option<(&wgpu::QuerySet, u32)>,
    ) {
        let key = PipelineKey::new(settings, gpu_scene.effects(), target.format);
        let key = self.ready_key(key);
        self.pipeline(key);
        let pipeline = &self.pipelines[&key];
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shadelab scene"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &target.color_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(CLEAR_COLOR), store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &target.depth_view,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
                stencil_ops: None,
            }),
            timestamp_writes: timestamps.map(|(qs, i)| wgpu::RenderPassTimestampWrites {
                query_set: qs,
                beginning_of_pass_write_index: Some(i),
                end_of_pass_write_index: Some(i + 1),
            }),
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &gpu_scene.globals_bind, &[]);
        for (i, k) in gpu_scene.objects.iter().enumerate() {
            let mesh = &gpu_scene.meshes[k];
            pass.set_bind_group(1, &gpu_scene.objects_bind, &[(i as u64 * gpu_scene.object_stride) as u32]);
            if key.shading == ShadingMode::Flat {
                pass.set_vertex_buffer(0, mesh.flat.slice(..));
                pass.draw(0..mesh.flat_count, 0..1);
            } else {
                pass.set_vertex_buffer(0, mesh.smooth.slice(..));
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.index_count, 0, 0..1);
            }
        }
    }

    /// Draw the scene into `target` and submit.
    pub fn render(&mut self, gpu_scene: &SceneGpu, scene: &Scene, target: &Target, settings: &RenderSettings) {
        self.write_uniforms(gpu_scene, scene, target, settings);
        let mut encoder = self.device.create_command_encoder(&Default::default());
        self.encode(&mut encoder, gpu_scene, target, settings, None);
        self.queue.submit([encoder.finish()]);
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

/// Elements written per piece by [`buffer_from_pieces`]: 2¹⁶ flat vertices are 2.25 MiB, small
/// beside any mesh worth writing in pieces, large enough that the per-piece cost vanishes.
const PIECE_ELEMENTS: usize = 1 << 16;

/// Most staging memory one upload holds at a time: pieces are written into batches of this
/// size, and each batch's submission is waited for before the next is mapped, so a 10⁷-triangle
/// mesh never has a second whole copy of its 1.3 GB of vertex data in staging memory.
pub const STAGING_BATCH_BYTES: u64 = 64 << 20;

impl MeshGpu {
    /// A mesh's three GPU buffers, each of `counts` elements (smooth vertices, indices, flat
    /// vertices) made by its `fill(range, out)`, which appends the elements of `range`. A range
    /// of indices always covers whole triangles (it starts and ends at multiples of 3).
    #[allow(clippy::too_many_arguments)]
    fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        object: &str,
        counts: [usize; 3],
        smooth: impl Fn(std::ops::Range<usize>, &mut Vec<SmoothVertex>),
        indices: impl Fn(std::ops::Range<usize>, &mut Vec<u32>),
        flat: impl Fn(std::ops::Range<usize>, &mut Vec<FlatVertex>),
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
            smooth: buffer_from_pieces(device, queue, "smooth vertices", vertex, counts[0], smooth),
            indices: buffer_from_pieces(device, queue, "indices", wgpu::BufferUsages::INDEX, counts[1], indices),
            index_count: counts[1] as u32,
            flat: buffer_from_pieces(device, queue, "flat vertices", vertex, counts[2], flat),
            flat_count: counts[2] as u32,
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
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: bytes.max(wgpu::COPY_BUFFER_ALIGNMENT),
        usage: usage | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
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

/// Build the pipeline of a key from its module (free, so worker threads can run it).
fn build_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    key: PipelineKey,
) -> wgpu::RenderPipeline {
    let (vs, fs) = if key.null_baseline { shaders::BASELINE_ENTRY_POINTS } else { shaders::entry_points(key.shading) };
    let options = wgpu::PipelineCompilationOptions::default();
    let buffers = match key.shading {
        ShadingMode::Flat if !key.null_baseline => [Some(wgpu::VertexBufferLayout {
            array_stride: size_of::<FlatVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &FLAT_ATTRS,
        })],
        _ => [Some(wgpu::VertexBufferLayout {
            array_stride: size_of::<SmoothVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &SMOOTH_ATTRS,
        })],
    };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(&if key.null_baseline {
            "null baseline".to_string()
        } else {
            format!("{:?} [{}]", key.shading, key.effects.label())
        }),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(vs),
            compilation_options: options.clone(),
            buffers: &buffers,
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            // Every mesh is closed or seen from its front, but no culling keeps a wrong
            // winding from making geometry vanish.
            cull_mode: None,
            ..Default::default()
        },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fs),
            compilation_options: options,
            targets: &[Some(wgpu::ColorTargetState {
                format: key.color_format,
                blend: None,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}
