//! The textures the glass pass reads beside the target (docs/transparency.md): the copy of the
//! target's colour behind the glass, a mesh's back faces with their depth, and their bind-group
//! layout, which the renderer builds. The pass that fills and reads them is `glass_pass.rs`.

use crate::pipelines::fragment_texture;
use crate::target::{DEPTH_FORMAT, Target, color_attachment};

/// The back faces' world position (w = 1 where covered) and outward normal.
pub const BACK_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

/// The glass bindings (@group(3), bindings 8–11 of `glass.wgsl`): four unfilterable textures read
/// with `textureLoad`.
pub(crate) fn layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let entry = |binding| fragment_texture(binding, wgpu::TextureSampleType::Float { filterable: false });
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("shadelab glass"),
        entries: &[entry(8), entry(9), entry(10), entry(11)],
    })
}

/// The textures the glass pass reads beside the target: the copy of its colour, and a mesh's
/// back faces with their own depth. Made for one size and colour format.
pub(crate) struct GlassTextures {
    pub(crate) size: (u32, u32, wgpu::TextureFormat),
    pub(crate) behind: wgpu::Texture,
    behind_view: wgpu::TextureView,
    back_position: wgpu::TextureView,
    back_normal: wgpu::TextureView,
    back_depth: wgpu::TextureView,
    /// The bind group, made for the target whose depth view it holds.
    bind: Option<(wgpu::TextureView, wgpu::BindGroup)>,
}

impl GlassTextures {
    pub(crate) fn new(device: &wgpu::Device, target: &Target) -> GlassTextures {
        let size = wgpu::Extent3d { width: target.width, height: target.height, depth_or_array_layers: 1 };
        let texture = |label, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        use wgpu::TextureUsages as U;
        let behind = texture("shadelab glass behind", target.format, U::COPY_DST | U::TEXTURE_BINDING);
        let view = |t: wgpu::Texture| t.create_view(&Default::default());
        GlassTextures {
            size: (target.width, target.height, target.format),
            behind_view: behind.create_view(&Default::default()),
            behind,
            back_position: view(texture(
                "shadelab back position",
                BACK_FORMAT,
                U::RENDER_ATTACHMENT | U::TEXTURE_BINDING,
            )),
            back_normal: view(texture("shadelab back normal", BACK_FORMAT, U::RENDER_ATTACHMENT | U::TEXTURE_BINDING)),
            back_depth: view(texture("shadelab back depth", DEPTH_FORMAT, U::RENDER_ATTACHMENT)),
            bind: None,
        }
    }

    /// The glass bind group for `target`'s depth, made once per target: the views it holds stay.
    pub(crate) fn bind_group(
        &mut self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        target: &Target,
    ) -> wgpu::BindGroup {
        if self.bind.as_ref().is_none_or(|(depth, _)| *depth != target.depth_view) {
            let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("shadelab glass"),
                layout,
                entries: &[
                    (8, &self.behind_view),
                    (9, &target.depth_view),
                    (10, &self.back_position),
                    (11, &self.back_normal),
                ]
                .map(|(binding, view)| wgpu::BindGroupEntry {
                    binding,
                    resource: wgpu::BindingResource::TextureView(view),
                }),
            });
            self.bind = Some((target.depth_view.clone(), bind));
        }
        self.bind.as_ref().expect("made above").1.clone()
    }

    /// Begin the pass that draws a mesh's back faces into the two back targets and their depth,
    /// all cleared.
    pub(crate) fn back_faces_pass<'e>(&self, encoder: &'e mut wgpu::CommandEncoder) -> wgpu::RenderPass<'e> {
        let clear = |view| color_attachment(view, wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT));
        encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shadelab glass back faces"),
            color_attachments: &[clear(&self.back_position), clear(&self.back_normal)],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.back_depth,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        })
    }
}
