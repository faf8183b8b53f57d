//! Textures, images and samplers (glTF 2.0 §3.8): a material's texture decoded once (PNG or
//! JPEG, from a buffer view, a `data:` URI or a file beside the scene) with its sampler and
//! `KHR_texture_transform`; and written back, each image as the file held it or as PNG.

use super::GltfError;
use super::container::{data_uri, read_external_whole};
use super::scene_file::Reader;
use crate::scene::{Filter, Sampler, Scene, Texture, TextureRef, UvTransform, Wrap};
use gltf::json;
use gltf::json::texture::{MagFilter, MinFilter, WrappingMode};
use gltf::json::validation::Checked;
use serde_json::{Value, json};
use std::sync::Arc;

/// Widest and tallest image read: the WebGPU default limit `maxTextureDimension2D`, so every
/// texture read fits any device.
pub const MAX_TEXTURE_SIDE: u32 = 8192;

/// Most decoded texture bytes a scene holds (RGBA8): 1 GiB, four 8192² images. A declared size
/// past it is refused before the image is decoded.
pub const MAX_TEXTURE_BYTES: u64 = 1 << 30;

/// Largest image file read (an external file or a `data:` URI's bytes).
pub const MAX_IMAGE_FILE_BYTES: u64 = 256 << 20;

impl Reader<'_> {
    /// The material's use of texture `info` (`what` names the slot): the scene's index of the
    /// decoded texture and its coordinate transform; `None`, with a warning, for a texture that
    /// cannot be used (another texture coordinate set, an image that does not decode). A slice
    /// ends after each image decoded (`slices.rs`).
    pub(super) async fn texture_ref(
        &mut self,
        scene: &mut Scene,
        info: &json::texture::Info,
        what: &str,
    ) -> Result<Option<TextureRef>, GltfError> {
        let ti = info.index.value();
        self.get(&self.root.textures, ti, "texture", &format!("{what}: "))?;
        let ext = info.extensions.as_ref().and_then(|e| e.texture_transform.as_ref());
        let set = ext.and_then(|t| t.tex_coord).unwrap_or(info.tex_coord);
        if set != 0 {
            self.cx
                .warn(format!("{what}: texture coordinate set {set} is not read (only TEXCOORD_0): texture not used"));
            return Ok(None);
        }
        let transform = match ext {
            Some(t) => {
                let v = [t.offset.0[0], t.offset.0[1], t.rotation.0, t.scale.0[0], t.scale.0[1]].map(f64::from);
                if v.iter().any(|x| !x.is_finite()) {
                    return Err(self
                        .cx
                        .invalid(format!("{what}: KHR_texture_transform has a value that is not finite")));
                }
                UvTransform { offset: [v[0], v[1]], rotation: v[2], scale: [v[3], v[4]] }
            }
            None => UvTransform::default(),
        };
        let texture = match self.textures.get(&ti) {
            Some(&t) => t,
            None => {
                let t = self.decode_texture(ti)?.map(|t| {
                    scene.textures.push(t);
                    scene.textures.len() - 1
                });
                self.textures.insert(ti, t);
                // A decode is one pass over the whole image: its own slice.
                super::slices::slice_end().await;
                t
            }
        };
        Ok(texture.map(|texture| TextureRef { texture, transform }))
    }

    /// Texture `ti`: its image decoded and its sampler read; `None`, with a warning, when the
    /// image is not a PNG or JPEG the decoder reads.
    fn decode_texture(&mut self, ti: usize) -> Result<Option<Texture>, GltfError> {
        let tex = &self.root.textures[ti];
        let ii = tex.source.value();
        let image = self.get(&self.root.images, ii, "image", &format!("texture {ti}: "))?;
        let what = format!("image {ii}");
        let bytes: Vec<u8> = match (&image.buffer_view, &image.uri) {
            (Some(v), _) => self.buffer_view(v.value(), &format!("{what}: "))?.bytes.to_vec(),
            (None, Some(uri)) if uri.starts_with("data:") => data_uri(&self.cx, &what, uri)?,
            (None, Some(uri)) => read_external_whole(&self.cx, &what, uri, MAX_IMAGE_FILE_BYTES, self.externals)?,
            (None, None) => return Err(self.cx.invalid(format!("{what} has neither a bufferView nor a uri"))),
        };
        let format = match image::guess_format(&bytes) {
            Ok(f @ (image::ImageFormat::Png | image::ImageFormat::Jpeg)) => f,
            _ => {
                self.cx.warn(format!("{what}: not a PNG or JPEG image: texture {ti} not used"));
                return Ok(None);
            }
        };
        let mut reader = image::ImageReader::with_format(std::io::Cursor::new(&bytes), format);
        let (w, h) = match reader.into_dimensions() {
            Ok(d) => d,
            Err(e) => {
                self.cx.warn(format!("{what}: {e}: texture {ti} not used"));
                return Ok(None);
            }
        };
        if w > MAX_TEXTURE_SIDE || h > MAX_TEXTURE_SIDE || w == 0 || h == 0 {
            return Err(self.cx.too_large(format!(
                "{what}: {w}×{h} pixels, outside 1..={MAX_TEXTURE_SIDE} per side (MAX_TEXTURE_SIDE)"
            )));
        }
        let total = self.texture_bytes + 4 * w as u64 * h as u64;
        if total > MAX_TEXTURE_BYTES {
            return Err(self.cx.too_large(format!(
                "{what}: the textures would need {total} bytes, more than the limit of {MAX_TEXTURE_BYTES} (MAX_TEXTURE_BYTES)"
            )));
        }
        reader = image::ImageReader::with_format(std::io::Cursor::new(&bytes), format);
        let mut limits = image::Limits::default();
        limits.max_image_width = Some(MAX_TEXTURE_SIDE);
        limits.max_image_height = Some(MAX_TEXTURE_SIDE);
        limits.max_alloc = Some(MAX_TEXTURE_BYTES);
        reader.limits(limits);
        let rgba = match reader.decode() {
            Ok(img) => img.into_rgba8(),
            Err(e) => {
                self.cx.warn(format!("{what}: {e}: texture {ti} not used"));
                return Ok(None);
            }
        };
        self.texture_bytes = total;
        let sampler = self.sampler(tex.sampler.map(|s| s.value()), ti)?;
        let mime = if format == image::ImageFormat::Png { "image/png" } else { "image/jpeg" };
        let name = tex.name.clone().or_else(|| image.name.clone()).unwrap_or_else(|| format!("texture {ti}"));
        Ok(Some(Texture {
            name,
            width: w,
            height: h,
            rgba8: Arc::from(rgba.into_raw()),
            sampler,
            encoded: Some((Arc::from(bytes), mime)),
            levels: Default::default(),
        }))
    }

    /// Sampler `si` of texture `ti` (none: repeat, linear and trilinear, glTF 2.0 §3.8.4 leaving
    /// the filters to the viewer). A value glTF does not define is its default, with a warning.
    fn sampler(&mut self, si: Option<usize>, ti: usize) -> Result<Sampler, GltfError> {
        let Some(si) = si else { return Ok(Sampler::default()) };
        let s = self.get(&self.root.samplers, si, "sampler", &format!("texture {ti}: "))?;
        let what = format!("sampler {si}");
        let mut warnings = Vec::new();
        let wrap = [("wrapS", &s.wrap_s), ("wrapT", &s.wrap_t)].map(|(name, w)| match w {
            Checked::Valid(WrappingMode::Repeat) => Wrap::Repeat,
            Checked::Valid(WrappingMode::MirroredRepeat) => Wrap::MirroredRepeat,
            Checked::Valid(WrappingMode::ClampToEdge) => Wrap::ClampToEdge,
            Checked::Invalid => {
                warnings.push(format!("{what}: {name} is not a glTF wrap mode: REPEAT used"));
                Wrap::Repeat
            }
        });
        let filter = match s.mag_filter {
            Some(Checked::Valid(MagFilter::Nearest)) => Filter::Nearest,
            Some(Checked::Valid(MagFilter::Linear)) | None => Filter::Linear,
            Some(Checked::Invalid) => {
                warnings.push(format!("{what}: magFilter is not a glTF filter: LINEAR used"));
                Filter::Linear
            }
        };
        // glTF's minFilter: a filter within a level, and the mipmap mode (none for NEAREST and
        // LINEAR); absent, the viewer's choice: trilinear.
        let (min, mipmap) = match s.min_filter {
            None => (Filter::Linear, Some(Filter::Linear)),
            Some(Checked::Valid(m)) => match m {
                MinFilter::Nearest => (Filter::Nearest, None),
                MinFilter::Linear => (Filter::Linear, None),
                MinFilter::NearestMipmapNearest => (Filter::Nearest, Some(Filter::Nearest)),
                MinFilter::LinearMipmapNearest => (Filter::Linear, Some(Filter::Nearest)),
                MinFilter::NearestMipmapLinear => (Filter::Nearest, Some(Filter::Linear)),
                MinFilter::LinearMipmapLinear => (Filter::Linear, Some(Filter::Linear)),
            },
            Some(Checked::Invalid) => {
                warnings.push(format!("{what}: minFilter is not a glTF filter: LINEAR_MIPMAP_LINEAR used"));
                (Filter::Linear, Some(Filter::Linear))
            }
        };
        for w in warnings {
            self.cx.warn(w);
        }
        Ok(Sampler { wrap, filter, min, mipmap })
    }
}

/// glTF's codes for a sampler (glTF 2.0 §5.26).
fn sampler_json(s: &Sampler) -> Value {
    let wrap = |w: Wrap| match w {
        Wrap::Repeat => 10497,
        Wrap::MirroredRepeat => 33648,
        Wrap::ClampToEdge => 33071,
    };
    let filter = match s.filter {
        Filter::Nearest => 9728,
        Filter::Linear => 9729,
    };
    let min = match (s.min, s.mipmap) {
        (Filter::Nearest, None) => 9728,
        (Filter::Linear, None) => 9729,
        (Filter::Nearest, Some(Filter::Nearest)) => 9984,
        (Filter::Linear, Some(Filter::Nearest)) => 9985,
        (Filter::Nearest, Some(Filter::Linear)) => 9986,
        (Filter::Linear, Some(Filter::Linear)) => 9987,
    };
    json!({ "magFilter": filter, "minFilter": min, "wrapS": wrap(s.wrap[0]), "wrapT": wrap(s.wrap[1]) })
}

/// The `images`, `samplers` and `textures` arrays of a saved scene, texture `i` of the scene
/// being glTF texture `i`: each image in a buffer view of `bin` (`view` appends one and returns
/// its index), as the file held it, or as PNG.
pub(super) fn write_textures(scene: &Scene, mut view: impl FnMut(&[u8]) -> usize) -> (Value, Value, Value) {
    let (mut images, mut samplers, mut textures) = (Vec::new(), Vec::new(), Vec::new());
    for (i, t) in scene.textures.iter().enumerate() {
        let (bytes, mime): (std::borrow::Cow<[u8]>, &str) = match &t.encoded {
            Some((b, m)) => (b.as_ref().into(), m),
            None => (png(t).into(), "image/png"),
        };
        images.push(json!({ "name": t.name, "bufferView": view(&bytes), "mimeType": mime }));
        samplers.push(sampler_json(&t.sampler));
        textures.push(json!({ "name": t.name, "source": i, "sampler": i }));
    }
    (Value::Array(images), Value::Array(samplers), Value::Array(textures))
}

/// A texture's pixels as PNG.
fn png(t: &Texture) -> Vec<u8> {
    let mut out = Vec::new();
    let encoder = image::codecs::png::PngEncoder::new(&mut out);
    image::ImageEncoder::write_image(encoder, &t.rgba8, t.width, t.height, image::ExtendedColorType::Rgba8)
        .expect("RGBA8 of the stated size encodes");
    out
}

/// A material's `textureInfo` for a texture reference, with `KHR_texture_transform` when it is not
/// the identity (the extension is then added to `used`).
pub(super) fn texture_info(r: &TextureRef, used: &mut Vec<&'static str>) -> Value {
    let mut info = json!({ "index": r.texture });
    if !r.transform.is_identity() {
        let t = &r.transform;
        info["extensions"] = json!({ "KHR_texture_transform": {
            "offset": [super::scene_file::num(t.offset[0]), super::scene_file::num(t.offset[1])],
            "rotation": super::scene_file::num(t.rotation),
            "scale": [super::scene_file::num(t.scale[0]), super::scene_file::num(t.scale[1])],
        }});
        used.push("KHR_texture_transform");
    }
    info
}
