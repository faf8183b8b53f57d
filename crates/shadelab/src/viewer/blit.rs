//! The view drawn into its region of the window by a paint callback inside egui's pass: one
//! triangle over the region whose pixels load the view's texels one to one. egui's own image
//! shader would filter, tint and dither every one of those pixels; on a CPU rasterizer that costs
//! more than many scenes' whole pass (docs/performance.md, "Frame time in the viewer").

use eframe::egui;
use eframe::egui_wgpu::{self, CallbackResources, CallbackTrait};
use shadelab_render::pipelines::fragment_texture;

const BLIT_WGSL: &str = r"
@group(0) @binding(0) var view: texture_2d<f32>;

struct Out {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
}

// One triangle covering the viewport (egui sets it to the callback's rectangle); uv 0..1 over it.
@vertex
fn vs_blit(@builtin(vertex_index) i: u32) -> Out {
    let uv = vec2(f32((i << 1u) & 2u), f32(i & 2u));
    return Out(vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 0.0, 1.0), uv);
}

// The texel under the pixel: the view's texture has the region's size in pixels.
@fragment
fn fs_blit(in: Out) -> @location(0) vec4<f32> {
    let size = vec2<f32>(textureDimensions(view));
    let texel = vec2<i32>(clamp(floor(in.uv * size), vec2(0.0), size - 1.0));
    return vec4(textureLoad(view, texel, 0).rgb, 1.0);
}
";

/// The blit's pipeline and the bind group of the current view texture, kept in egui's callback
/// resources (the paint callback reads them there).
pub(super) struct BlitResources {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    bind: Option<wgpu::BindGroup>,
    /// The window's format: an sRGB one encodes on write, so the blit reads decoded values.
    target_is_srgb: bool,
}

impl BlitResources {
    /// The pipeline for a window of `target_format`.
    pub fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat) -> BlitResources {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("shadelab view blit"),
            source: wgpu::ShaderSource::Wgsl(BLIT_WGSL.into()),
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("shadelab view blit"),
            entries: &[fragment_texture(0, wgpu::TextureSampleType::Float { filterable: false })],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadelab view blit"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("shadelab view blit"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_blit"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: Default::default(),
            depth_stencil: None,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_blit"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: target_format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        BlitResources { pipeline, layout, bind: None, target_is_srgb: target_format.is_srgb() }
    }

    /// Show `target`'s colour from now on (after it is made or resized).
    pub fn set_view(&mut self, device: &wgpu::Device, target: &shadelab_render::Target) {
        // The stored bytes are sRGB-encoded: read them as they are for a window that does not
        // encode, decoded for one that does.
        let view = if self.target_is_srgb { target.color_view.clone() } else { target.encoded_view() };
        self.bind = Some(device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shadelab view blit"),
            layout: &self.layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) }],
        }));
    }
}

/// The paint callback that draws the view (its resources are in egui's renderer).
pub(super) struct BlitCallback;

impl CallbackTrait for BlitCallback {
    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        render_pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(blit) = resources.get::<BlitResources>() else { return };
        let Some(bind) = &blit.bind else { return };
        render_pass.set_pipeline(&blit.pipeline);
        render_pass.set_bind_group(0, bind, &[]);
        render_pass.draw(0..3, 0..1);
    }
}

/// The shape that draws the view into `rect`.
pub(super) fn shape(rect: egui::Rect) -> egui::Shape {
    egui::Shape::Callback(egui_wgpu::Callback::new_paint_callback(rect, BlitCallback))
}
