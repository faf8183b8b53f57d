//! Lines drawn over a rendered frame (the self-shadow boundary of `render --overlay terminator`
//! and the viewer): a small `LineList` pipeline (`shaders/overlay.wgsl`) with the scene's
//! view-projection, drawn after the scene pass into the same target and depth-tested against the
//! depth that pass keeps (`LessEqual`), so that an edge behind an object is hidden.

use crate::buffers::{buffer_entry, written_buffer};
use crate::program::RenderSettings;
use crate::target::{self, LinearImage, Target, color_attachment};
use crate::upload::UploadError;
use crate::{Gpu, Renderer};
use glam::DVec3;
use shadelab_model::{Camera, Scene};
use std::collections::HashMap;
use wgpu::util::DeviceExt;

/// The self-shadow boundary's colour (linear RGB): saturated cyan, which no material of the
/// built-in scenes comes near (all are greys, warm stone, red and gold), and unlike the
/// magenta of the non-finite debug paint.
pub const TERMINATOR_COLOR: [f32; 3] = [0.0, 1.0, 1.0];
/// The vertex normals' colour (linear RGB): saturated yellow, apart from the cyan boundary and
/// from every built-in material.
pub const NORMALS_COLOR: [f32; 3] = [1.0, 1.0, 0.0];
/// The kept creases' colour (linear RGB): saturated orange, apart from the other overlays and
/// from the gold cylinder (whose blue is 0.34, not 0).
pub const CREASES_COLOR: [f32; 3] = [1.0, 0.35, 0.0];

/// How far each end of a line is pulled towards the eye, as a share of its distance (the
/// overlay's depth bias): 2e-3 is about two pixels' footprint at 720 rows and a 40° field of
/// view, enough for a line to pass the depth test of the faces it lies on where their depth
/// changes across the pixel, and far too little to show an edge through an object in front.
pub const OVERLAY_DEPTH_PULL: f32 = 2e-3;

/// Copies of each line, shifted by 0 or 1 pixel in x and y (`overlay.wgsl`): lines two pixels
/// wide, since wgpu draws lines one pixel wide and one pixel is hard to see at 1280×720.
const LINE_COPIES: u32 = 4;

const SHADER: &str = include_str!("../../../shaders/overlay.wgsl");

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct OverlayUniform {
    view_proj: [[f32; 4]; 4],
    eye_pull: [f32; 4],
    color: [f32; 4],
    pixel: [f32; 4],
}

/// The overlay pipeline (one per colour format), its uniform and the lines to draw.
pub struct OverlayPass {
    module: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    pipelines: HashMap<wgpu::TextureFormat, wgpu::RenderPipeline>,
    uniform: wgpu::Buffer,
    bind: wgpu::BindGroup,
    lines: Option<wgpu::Buffer>,
    vertex_count: u32,
    color: [f32; 3],
}

impl OverlayPass {
    pub fn new(device: &wgpu::Device) -> OverlayPass {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("overlay"),
            source: wgpu::ShaderSource::Wgsl(SHADER.into()),
        });
        let bind_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("overlay"),
            entries: &[buffer_entry(
                0,
                wgpu::ShaderStages::VERTEX_FRAGMENT,
                wgpu::BufferBindingType::Uniform,
                false,
                Some(size_of::<OverlayUniform>() as u64),
            )],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("overlay"),
            bind_group_layouts: &[Some(&bind_layout)],
            immediate_size: 0,
        });
        let uniform =
            written_buffer(device, "overlay", size_of::<OverlayUniform>() as u64, wgpu::BufferUsages::UNIFORM);
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("overlay"),
            layout: &bind_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() }],
        });
        OverlayPass {
            module,
            layout,
            pipelines: HashMap::new(),
            uniform,
            bind,
            lines: None,
            vertex_count: 0,
            color: TERMINATOR_COLOR,
        }
    }

    /// The lines to draw from now on (world space), and their colour. Non-finite ends are left
    /// out.
    pub fn set_lines(&mut self, device: &wgpu::Device, segments: &[[DVec3; 2]], color: [f32; 3]) {
        let vertices: Vec<[f32; 3]> = segments
            .iter()
            .filter(|s| s.iter().all(|p| p.is_finite()))
            .flat_map(|s| s.map(|p| p.as_vec3().to_array()))
            .collect();
        self.vertex_count = vertices.len() as u32;
        self.color = color;
        self.lines = (!vertices.is_empty()).then(|| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("overlay lines"),
                contents: bytemuck::cast_slice(&vertices),
                usage: wgpu::BufferUsages::VERTEX,
            })
        });
    }

    /// How many lines are set.
    pub fn line_count(&self) -> u32 {
        self.vertex_count / 2
    }

    /// Record the lines into `target` seen through `camera` (the scene's, at the target's
    /// size), over the colour and depth the scene pass left there: the scene pass must store
    /// its depth. Nothing is recorded when there are no lines.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        target: &Target,
        camera: &Camera,
    ) {
        let Some(lines) = &self.lines else { return };
        let u = OverlayUniform {
            view_proj: camera.view_proj(target.width, target.height).to_cols_array_2d(),
            eye_pull: camera.eye.as_vec3().extend(OVERLAY_DEPTH_PULL).to_array(),
            color: [self.color[0], self.color[1], self.color[2], 1.0],
            pixel: [2.0 / target.width.max(1) as f32, 2.0 / target.height.max(1) as f32, 0.0, 0.0],
        };
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&u));
        let (module, layout) = (&self.module, &self.layout);
        let pipeline = self
            .pipelines
            .entry(target.format)
            .or_insert_with(|| build_pipeline(device, layout, module, target.format));
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shadelab overlay"),
            color_attachments: &[color_attachment(&target.color_view, wgpu::LoadOp::Load)],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &target.depth_view,
                // Kept: a later overlay pass tests its lines against the same depth.
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Load, store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &self.bind, &[]);
        pass.set_vertex_buffer(0, lines.slice(..));
        pass.draw(0..self.vertex_count, 0..LINE_COPIES);
    }
}

impl OverlayPass {
    /// Record the lines into `target` ([`OverlayPass::encode`]) and submit them.
    pub fn draw(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, target: &Target, camera: &Camera) {
        let mut encoder = device.create_command_encoder(&Default::default());
        self.encode(device, queue, &mut encoder, target, camera);
        queue.submit([encoder.finish()]);
    }
}

const LINE_ATTRS: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![0 => Float32x3];

fn build_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let options = wgpu::PipelineCompilationOptions::default();
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("overlay lines"),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_overlay"),
            compilation_options: options.clone(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<[f32; 3]>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &LINE_ATTRS,
            })],
        },
        primitive: wgpu::PrimitiveState { topology: wgpu::PrimitiveTopology::LineList, ..Default::default() },
        // Lines are drawn over the scene; they hide nothing of each other's by depth.
        depth_stencil: Some(crate::pipelines::depth_tested_over()),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some("fs_overlay"),
            compilation_options: options,
            targets: &[crate::pipelines::opaque_target(format)],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// [`crate::render_image`] with `segments` drawn over it in `color`: the scene pass, then the
/// overlay pass into the same target, then the readback.
pub fn render_image_with_lines(
    gpu: &Gpu,
    scene: &Scene,
    size: (u32, u32),
    settings: &RenderSettings,
    segments: &[[DVec3; 2]],
    color: [f32; 3],
) -> Result<LinearImage, UploadError> {
    render_image_with_line_sets(gpu, scene, size, settings, &[(segments, color)])
}

/// [`crate::render_image`] with each set of lines drawn over it in its colour, the later sets
/// over the earlier ones (one submission each: the uniform a set writes is read by its own).
pub fn render_image_with_line_sets(
    gpu: &Gpu,
    scene: &Scene,
    (width, height): (u32, u32),
    settings: &RenderSettings,
    sets: &[(&[[DVec3; 2]], [f32; 3])],
) -> Result<LinearImage, UploadError> {
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(scene)?;
    let target = Target::new(&gpu.device, width, height, target::HDR_FORMAT);
    r.render(&mut gs, scene, &target, settings);
    let mut overlay = OverlayPass::new(&gpu.device);
    for (segments, color) in sets {
        overlay.set_lines(&gpu.device, segments, *color);
        overlay.draw(&gpu.device, &gpu.queue, &target, &scene.camera);
    }
    Ok(target::read_back(&gpu.device, &gpu.queue, &target))
}
