//! The renderer: one pipeline per permutation (cached by key), scene geometry and uniforms on
//! the GPU, and one draw path for every target (offscreen image or the viewer's texture).

use crate::shaders;
use crate::target::Target;
use crate::uniforms::{GlobalsUniform, ObjectUniform};
use shadelab_model::mesh::{self, FlatVertex, SmoothVertex};
use shadelab_model::{Scene, ShadingMode, Shape, SpecularModel};
use std::collections::HashMap;
use wgpu::util::DeviceExt;

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
    pub specular: SpecularModel,
    pub color_format: wgpu::TextureFormat,
    /// The null-shader baseline (constant colour; `shading` and `specular` are then fixed).
    pub null_baseline: bool,
}

impl PipelineKey {
    pub fn new(settings: &RenderSettings, color_format: wgpu::TextureFormat) -> PipelineKey {
        if settings.null_baseline {
            // One baseline pipeline, whatever the shading settings say.
            let d = RenderSettings::default();
            return PipelineKey { shading: d.shading, specular: d.specular, color_format, null_baseline: true };
        }
        PipelineKey { shading: settings.shading, specular: settings.specular, color_format, null_baseline: false }
    }
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
}

pub struct Renderer {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    module: wgpu::ShaderModule,
    globals_layout: wgpu::BindGroupLayout,
    object_layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    /// How many pipelines have been built (the viewer shows it: it must not grow per frame).
    pub pipeline_builds: u32,
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
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("shadelab lighting"),
            source: wgpu::ShaderSource::Wgsl(shaders::lighting_source().into()),
        });
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
            module,
            globals_layout,
            object_layout,
            pipeline_layout,
            pipelines: HashMap::new(),
            pipeline_builds: 0,
        }
    }

    /// Replace the shader source (hot reload). The source is validated by naga first: on an
    /// error nothing changes (the old module and pipelines stay) and naga's message is returned;
    /// on success the cached pipelines are dropped and rebuilt once, on next use.
    pub fn reload_shaders(&mut self, source: &str) -> Result<(), String> {
        shaders::validate(source)?;
        self.module = self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("shadelab lighting (reloaded)"),
            source: wgpu::ShaderSource::Wgsl(source.to_owned().into()),
        });
        self.pipelines.clear();
        Ok(())
    }

    /// The pipeline for a key, built on first use and cached.
    pub fn pipeline(&mut self, key: PipelineKey) -> &wgpu::RenderPipeline {
        if !self.pipelines.contains_key(&key) {
            let p = self.build_pipeline(key);
            self.pipeline_builds += 1;
            self.pipelines.insert(key, p);
        }
        &self.pipelines[&key]
    }

    fn build_pipeline(&self, key: PipelineKey) -> wgpu::RenderPipeline {
        let (vs, fs) =
            if key.null_baseline { shaders::BASELINE_ENTRY_POINTS } else { shaders::entry_points(key.shading) };
        let constants = [("SPECULAR_MODEL", shaders::specular_constant(key.specular))];
        let options = wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() };
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
        self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(&if key.null_baseline {
                "null baseline".to_string()
            } else {
                format!("{:?}/{:?}", key.shading, key.specular)
            }),
            layout: Some(&self.pipeline_layout),
            vertex: wgpu::VertexState {
                module: &self.module,
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
                module: &self.module,
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

    /// Upload a scene's meshes and uniforms.
    pub fn upload(&self, scene: &Scene) -> SceneGpu {
        let device = &self.device;
        let mut meshes = HashMap::new();
        let mut objects = Vec::new();
        for o in &scene.objects {
            let k = (o.shape, o.tessellation);
            // `Shape::Mesh(i)` keys by its index: each file mesh is built once (its normals, else
            // the crease-angle rule), shared by every object that shows it.
            meshes.entry(k).or_insert_with(|| upload_mesh(device, &scene.mesh_data(o)));
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
        SceneGpu { meshes, objects, globals, globals_bind, objects_buf, objects_bind, object_stride, triangle_count }
    }

    /// Write a scene's parameters (materials, lights, camera) into its uniforms. Cheap: the
    /// viewer calls it whenever a parameter changes; geometry stays.
    pub fn write_uniforms(&self, gpu_scene: &SceneGpu, scene: &Scene, target: &Target, settings: &RenderSettings) {
        let flags = if settings.debug_nonfinite { crate::uniforms::FLAG_DEBUG_NONFINITE } else { 0 };
        let g = GlobalsUniform::new(scene, target.width, target.height, flags);
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
        let key = PipelineKey::new(settings, target.format);
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

fn upload_mesh(device: &wgpu::Device, m: &mesh::MeshData) -> MeshGpu {
    let usage = wgpu::BufferUsages::VERTEX;
    MeshGpu {
        smooth: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("smooth vertices"),
            contents: bytemuck::cast_slice(&m.smooth_vertices),
            usage,
        }),
        indices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("indices"),
            contents: bytemuck::cast_slice(&m.indices),
            usage: wgpu::BufferUsages::INDEX,
        }),
        index_count: m.indices.len() as u32,
        flat: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("flat vertices"),
            contents: bytemuck::cast_slice(&m.flat_vertices),
            usage,
        }),
        flat_count: m.flat_vertices.len() as u32,
    }
}
