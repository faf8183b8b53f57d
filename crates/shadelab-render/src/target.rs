//! Render targets and readback: an offscreen colour + depth target of any size, and a linear
//! float image read back from it (rows padded to 256 bytes on the GPU side).

use std::sync::{Arc, OnceLock};

/// The depth format of every target and depth pass (the shadow maps', the glass pass's back
/// faces'): 32-bit float, which every backend renders to and samples.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// A colour texture with its depth buffer: what the renderer draws into. The viewer and
/// `shadelab render` both draw into one of these.
pub struct Target {
    pub color: wgpu::Texture,
    pub color_view: wgpu::TextureView,
    pub depth_view: wgpu::TextureView,
    pub width: u32,
    pub height: u32,
    pub format: wgpu::TextureFormat,
}

/// The format headless renders use: 32-bit float, so that out-of-range and non-finite values
/// survive to the EXR output.
pub const HDR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

impl Target {
    pub fn new(device: &wgpu::Device, width: u32, height: u32, format: wgpu::TextureFormat) -> Target {
        let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
        // An sRGB target can also be viewed without decoding (see `encoded_view`).
        let plain = format.remove_srgb_suffix();
        let view_formats: &[wgpu::TextureFormat] = if plain != format { &[plain] } else { &[] };
        let color = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("shadelab color"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::COPY_DST
                | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats,
        });
        let depth = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("shadelab depth"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            // The glass pass reads the opaque scene's depth.
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        Target {
            color_view: color.create_view(&Default::default()),
            depth_view: depth.create_view(&Default::default()),
            color,
            width,
            height,
            format,
        }
    }

    /// A view of the colour that reads the stored (sRGB-encoded) bytes without decoding them:
    /// what egui expects of a texture it shows.
    pub fn encoded_view(&self) -> wgpu::TextureView {
        self.color.create_view(&wgpu::TextureViewDescriptor {
            format: Some(self.format.remove_srgb_suffix()),
            ..Default::default()
        })
    }
}

/// A linear RGBA float image, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearImage {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<[f32; 4]>,
}

/// Linear → sRGB transfer function (IEC 61966-2-1), input clamped to [0, 1].
pub fn linear_to_srgb(x: f32) -> f32 {
    let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
    if x <= 0.003_130_8 { 12.92 * x } else { 1.055 * x.powf(1.0 / 2.4) - 0.055 }
}

/// sRGB → linear transfer function (IEC 61966-2-1), the inverse of [`linear_to_srgb`].
pub fn srgb_to_linear(x: f32) -> f32 {
    if x <= 0.040_45 { x / 12.92 } else { ((x + 0.055) / 1.055).powf(2.4) }
}

impl LinearImage {
    /// An 8-bit sRGB RGB image as linear values (alpha 1); [`Self::to_srgb8`] gives its bytes back.
    pub fn from_srgb8(width: u32, height: u32, rgb: &[u8]) -> LinearImage {
        let lin = |b: u8| srgb_to_linear(b as f32 / 255.0);
        let pixels = rgb.chunks_exact(3).map(|p| [lin(p[0]), lin(p[1]), lin(p[2]), 1.0]).collect();
        LinearImage { width, height, pixels }
    }

    pub fn get(&self, x: u32, y: u32) -> [f32; 4] {
        self.pixels[(y * self.width + x) as usize]
    }

    /// 8-bit sRGB RGB bytes (clamped; NaN as 0), as the PNG output and FLIP comparisons use.
    pub fn to_srgb8(&self) -> Vec<u8> {
        self.pixels.iter().flat_map(|p| [p[0], p[1], p[2]].map(|c| (linear_to_srgb(c) * 255.0 + 0.5) as u8)).collect()
    }

    /// Number of pixels with a NaN or infinite channel.
    pub fn nonfinite_count(&self) -> usize {
        self.pixels.iter().filter(|p| p.iter().any(|c| !c.is_finite())).count()
    }
}

/// A colour attachment of `view` that begins with `load` and keeps what the pass draws.
pub(crate) fn color_attachment(
    view: &wgpu::TextureView,
    load: wgpu::LoadOp<wgpu::Color>,
) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    let ops = wgpu::Operations { load, store: wgpu::StoreOp::Store };
    Some(wgpu::RenderPassColorAttachment { view, depth_slice: None, resolve_target: None, ops })
}

/// Bytes a buffer row needs for `width` texels of `bytes_per_texel`, padded to the copy
/// alignment (256).
pub fn padded_bytes_per_row(width: u32, bytes_per_texel: u32) -> u32 {
    let unpadded = width * bytes_per_texel;
    unpadded.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT
}

/// Most bytes one readback band may take: large images are read in bands of rows so the staging
/// buffer stays small (an 8192² float image is 1 GiB).
const READBACK_BAND_BYTES: u64 = 64 << 20;

/// Read an `Rgba32Float` target back to the CPU.
pub fn read_back(device: &wgpu::Device, queue: &wgpu::Queue, target: &Target) -> LinearImage {
    assert_eq!(target.format, HDR_FORMAT, "read_back reads Rgba32Float targets");
    let (w, h) = (target.width, target.height);
    let bpr = padded_bytes_per_row(w, 16);
    let band_rows = ((READBACK_BAND_BYTES / bpr as u64).max(1) as u32).min(h);
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("shadelab readback"),
        size: bpr as u64 * band_rows as u64,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut pixels = Vec::with_capacity((w * h) as usize);
    let mut y0 = 0;
    while y0 < h {
        let rows = band_rows.min(h - y0);
        let mut enc = device.create_command_encoder(&Default::default());
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &target.color,
                mip_level: 0,
                origin: wgpu::Origin3d { x: 0, y: y0, z: 0 },
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &staging,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(bpr), rows_per_image: Some(rows) },
            },
            wgpu::Extent3d { width: w, height: rows, depth_or_array_layers: 1 },
        );
        queue.submit([enc.finish()]);
        let slice = staging.slice(..bpr as u64 * rows as u64);
        slice.map_async(wgpu::MapMode::Read, |r| r.expect("map readback buffer"));
        device.poll(wgpu::PollType::wait_indefinitely()).expect("device poll");
        {
            let data = slice.get_mapped_range().expect("mapped range");
            for row in 0..rows as usize {
                let start = row * bpr as usize;
                let bytes = &data[start..start + w as usize * 16];
                pixels.extend(bytes.chunks_exact(16).map(|t| {
                    let f: [f32; 4] = bytemuck::pod_read_unaligned(t);
                    f
                }));
            }
        }
        staging.unmap();
        y0 += rows;
    }
    LinearImage { width: w, height: h, pixels }
}

/// A readback in flight: the copy is submitted and the map requested, and
/// [`PendingReadBack::try_take`] returns the image once the map has completed, without waiting.
/// The browser must work this way: a map completes only between frames, never inside a wait.
pub struct PendingReadBack {
    staging: wgpu::Buffer,
    width: u32,
    height: u32,
    bytes_per_row: u32,
    /// A depth map's one f32 a texel (read as grey `[d, d, d, 1]`), else `Rgba32Float`.
    depth: bool,
    mapped: Arc<OnceLock<Result<(), wgpu::BufferAsyncError>>>,
}

/// Start reading an `Rgba32Float` target back in one buffer (a view-sized image: 1920×1080 is
/// 33 MB; [`read_back`] reads larger ones in bands).
pub fn start_read_back(device: &wgpu::Device, queue: &wgpu::Queue, target: &Target) -> PendingReadBack {
    assert_eq!(target.format, HDR_FORMAT, "read_back reads Rgba32Float targets");
    let (width, height) = (target.width, target.height);
    let bytes_per_row = padded_bytes_per_row(width, 16);
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("shadelab readback (pending)"),
        size: bytes_per_row as u64 * height as u64,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut enc = device.create_command_encoder(&Default::default());
    enc.copy_texture_to_buffer(
        target.color.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &staging,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(bytes_per_row),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
    );
    queue.submit([enc.finish()]);
    PendingReadBack::requested(staging, (width, height), bytes_per_row, false)
}

impl PendingReadBack {
    /// Ask for `staging` (a copy of `width × height` texels submitted into it) to be mapped.
    pub(crate) fn requested(
        staging: wgpu::Buffer,
        (width, height): (u32, u32),
        bytes_per_row: u32,
        depth: bool,
    ) -> Self {
        let mapped = Arc::new(OnceLock::new());
        let done = mapped.clone();
        staging.slice(..).map_async(wgpu::MapMode::Read, move |r| {
            let _ = done.set(r);
        });
        PendingReadBack { staging, width, height, bytes_per_row, depth, mapped }
    }

    /// The image once mapped (`None`: not yet), or why the map failed (a lost device).
    pub fn try_take(&self, device: &wgpu::Device) -> Option<Result<LinearImage, String>> {
        let _ = device.poll(wgpu::PollType::Poll);
        match self.mapped.get()? {
            Err(e) => Some(Err(format!("reading the image back failed: {e}"))),
            Ok(()) => Some(self.read()),
        }
    }

    fn read(&self) -> Result<LinearImage, String> {
        let (w, h) = (self.width as usize, self.height as usize);
        let mut pixels = Vec::with_capacity(w * h);
        {
            let data = self.staging.slice(..).get_mapped_range().map_err(|e| format!("mapped range: {e}"))?;
            let texel = if self.depth { 4 } else { 16 };
            for row in 0..h {
                let bytes = &data[row * self.bytes_per_row as usize..][..w * texel];
                if self.depth {
                    pixels.extend(bytes.chunks_exact(4).map(|b| {
                        let d = f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
                        [d, d, d, 1.0]
                    }));
                } else {
                    pixels.extend(bytes.chunks_exact(16).map(|t| bytemuck::pod_read_unaligned::<[f32; 4]>(t)));
                }
            }
        }
        self.staging.unmap();
        Ok(LinearImage { width: self.width, height: self.height, pixels })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_bytes_round_trip() {
        let bytes: Vec<u8> = (0..=255u8).flat_map(|b| [b, 255 - b, b / 2]).collect();
        assert_eq!(LinearImage::from_srgb8(256, 1, &bytes).to_srgb8(), bytes);
    }

    #[test]
    fn rows_are_padded_to_256_bytes() {
        assert_eq!(padded_bytes_per_row(1, 16), 256);
        assert_eq!(padded_bytes_per_row(16, 16), 256);
        assert_eq!(padded_bytes_per_row(17, 16), 512);
        assert_eq!(padded_bytes_per_row(8192, 16), 8192 * 16);
    }

    #[test]
    fn srgb_transfer_ends_and_nan() {
        assert_eq!(linear_to_srgb(0.0), 0.0);
        assert!((linear_to_srgb(1.0) - 1.0).abs() < 1e-6);
        assert_eq!(linear_to_srgb(f32::NAN), 0.0);
        assert!((linear_to_srgb(0.214) - 0.5).abs() < 2e-3);
    }
}
