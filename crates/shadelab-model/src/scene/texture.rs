//! Textures of a scene's materials (docs/textures.md): 8-bit RGBA images with their sampler, and
//! the f64 sampling the reference uses, the same texel centres, wrap modes and filter as the GPU's
//! sampler over an `Rgba8UnormSrgb` texture (sRGB decoded per texel, then filtered in linear).

use crate::guards::NONFINITE_UV;
use std::sync::Arc;

/// How a texture coordinate outside [0, 1] is brought back (glTF `wrapS`/`wrapT`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Wrap {
    #[default]
    Repeat,
    MirroredRepeat,
    ClampToEdge,
}

/// How texels are combined (glTF `magFilter`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Filter {
    Nearest,
    #[default]
    Linear,
}

/// A texture's sampler: one filter for magnification and minification, level 0 only (the loader
/// warns when a file asks for another minification filter or for mipmaps).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Sampler {
    /// `[s, t]`: along u and along v.
    pub wrap: [Wrap; 2],
    pub filter: Filter,
}

/// An 8-bit RGBA image, rows top to bottom (glTF's uv (0, 0) is the first texel of the first row),
/// colour channels sRGB-encoded as image files store them. The pixels are shared: a scene clones
/// cheaply.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    pub name: String,
    pub width: u32,
    pub height: u32,
    /// `4·width·height` bytes.
    pub rgba8: Arc<[u8]>,
    pub sampler: Sampler,
    /// The image's encoded bytes and MIME type as the file held them (PNG or JPEG), written back
    /// unchanged when the scene is saved; `None`: encode `rgba8` as PNG.
    pub encoded: Option<(Arc<[u8]>, &'static str)>,
}

/// `KHR_texture_transform`: `uv' = offset + R(rotation)·(scale ⊙ uv)`, R turning +u towards −v
/// as the extension defines it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvTransform {
    pub offset: [f64; 2],
    pub rotation: f64,
    pub scale: [f64; 2],
}

impl Default for UvTransform {
    fn default() -> Self {
        UvTransform { offset: [0.0; 2], rotation: 0.0, scale: [1.0; 2] }
    }
}

impl UvTransform {
    pub fn is_identity(&self) -> bool {
        *self == UvTransform::default()
    }

    /// The transformed coordinate (the extension's matrix `T·R·S`).
    pub fn apply(&self, uv: [f64; 2]) -> [f64; 2] {
        texture_uv(uv, self.offset, self.rotation, self.scale)
    }
}

/// `KHR_texture_transform`: `offset + R(rotation)·(scale ⊙ uv)`, R turning +u towards −v (twin of
/// `texture_uv` in shaders/surface.wgsl).
pub fn texture_uv(uv: [f64; 2], offset: [f64; 2], rotation: f64, scale: [f64; 2]) -> [f64; 2] {
    let (s, c) = rotation.sin_cos();
    let (x, y) = (uv[0] * scale[0], uv[1] * scale[1]);
    [c * x + s * y + offset[0], -s * x + c * y + offset[1]]
}

/// How a texture's bytes are read: glTF's colour textures (base colour, emissive) are
/// sRGB-encoded, its data textures (metallic–roughness, occlusion, normal) are linear.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorSpace {
    Srgb,
    Linear,
}

/// A material's use of a texture: which one, and the transform of its coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct TextureRef {
    /// Index into `Scene::textures`.
    pub texture: usize,
    pub transform: UvTransform,
}

/// sRGB-encoded 8-bit value → linear (IEC 61966-2-1), as the GPU's sRGB formats decode.
pub fn srgb_to_linear(v: u8) -> f64 {
    let c = v as f64 / 255.0;
    if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

/// Texel index `i` (any integer) brought into `0..n` by the wrap mode.
fn wrap_index(i: i64, n: u32, wrap: Wrap) -> u32 {
    let n = n as i64;
    match wrap {
        Wrap::Repeat => i.rem_euclid(n) as u32,
        Wrap::ClampToEdge => i.clamp(0, n - 1) as u32,
        Wrap::MirroredRepeat => {
            let period = i.rem_euclid(2 * n);
            (if period < n { period } else { 2 * n - 1 - period }) as u32
        }
    }
}

impl Texture {
    /// A texture of one sRGB-encoded colour, 1×1.
    pub fn solid(name: &str, rgba: [u8; 4]) -> Texture {
        Texture {
            name: name.into(),
            width: 1,
            height: 1,
            rgba8: Arc::from(rgba.as_slice()),
            sampler: Sampler::default(),
            encoded: None,
        }
    }

    /// Texel `(x, y)`: RGB decoded from sRGB (colour) or read as stored (data), and alpha.
    fn texel(&self, x: u32, y: u32, space: ColorSpace) -> [f64; 4] {
        let at = 4 * (y as usize * self.width as usize + x as usize);
        let p = &self.rgba8[at..at + 4];
        let rgb = |v: u8| match space {
            ColorSpace::Srgb => srgb_to_linear(v),
            ColorSpace::Linear => v as f64 / 255.0,
        };
        [rgb(p[0]), rgb(p[1]), rgb(p[2]), p[3] as f64 / 255.0]
    }

    /// The texture at `uv` read as colour (sRGB decoded per texel), as the GPU samples an
    /// `Rgba8UnormSrgb` view at level 0.
    pub fn sample(&self, uv: [f64; 2]) -> [f64; 4] {
        self.sample_as(uv, ColorSpace::Srgb)
    }

    /// The texture at `uv` as the GPU samples it at level 0: texel centres at `(i + ½)/n`, the
    /// wrap mode per axis, nearest or bilinear, after each texel is decoded as `space` says.
    pub fn sample_as(&self, uv: [f64; 2], space: ColorSpace) -> [f64; 4] {
        let uv = uv.map(|c| if c.is_finite() { c } else { NONFINITE_UV });
        // Far outside [0, 1] f64 keeps no fraction; such a coordinate repeats the same texels.
        let (x, y) = (uv[0] * self.width as f64, uv[1] * self.height as f64);
        let [ws, wt] = self.sampler.wrap;
        match self.sampler.filter {
            Filter::Nearest => {
                let (i, j) = (x.floor() as i64, y.floor() as i64);
                self.texel(wrap_index(i, self.width, ws), wrap_index(j, self.height, wt), space)
            }
            Filter::Linear => {
                let (x, y) = (x - 0.5, y - 0.5);
                let (i, j) = (x.floor(), y.floor());
                let (fx, fy) = (x - i, y - j);
                let (i, j) = (i as i64, j as i64);
                let (i0, i1) = (wrap_index(i, self.width, ws), wrap_index(i.saturating_add(1), self.width, ws));
                let (j0, j1) = (wrap_index(j, self.height, wt), wrap_index(j.saturating_add(1), self.height, wt));
                let (a, b, c, d) = (
                    self.texel(i0, j0, space),
                    self.texel(i1, j0, space),
                    self.texel(i0, j1, space),
                    self.texel(i1, j1, space),
                );
                std::array::from_fn(|k| {
                    (a[k] * (1.0 - fx) + b[k] * fx) * (1.0 - fy) + (c[k] * (1.0 - fx) + d[k] * fx) * fy
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn checker() -> Texture {
        // 2×2: black, white / white, black.
        let px = [0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255];
        Texture { rgba8: Arc::from(px.as_slice()), width: 2, height: 2, ..Texture::solid("checker", [0; 4]) }
    }

    #[test]
    fn texel_centres_give_the_texel_and_midpoints_the_mean() {
        let t = checker();
        assert_eq!(t.sample([0.25, 0.25])[0], 0.0);
        assert_eq!(t.sample([0.75, 0.25])[0], 1.0);
        // Halfway between a black and a white texel, in linear colour.
        assert!((t.sample([0.5, 0.25])[0] - 0.5).abs() < 1e-12);
    }

    #[test]
    fn wrap_modes_bring_coordinates_back() {
        let mut t = checker();
        assert_eq!(t.sample([1.25, 0.25]), t.sample([0.25, 0.25]));
        t.sampler.wrap = [Wrap::MirroredRepeat; 2];
        assert_eq!(t.sample([1.25, 0.25]), t.sample([0.75, 0.25]));
        t.sampler.wrap = [Wrap::ClampToEdge; 2];
        assert_eq!(t.sample([7.0, 0.25]), t.sample([0.75, 0.25]));
        assert_eq!(wrap_index(-1, 4, Wrap::MirroredRepeat), 0);
        assert_eq!(wrap_index(-5, 4, Wrap::Repeat), 3);
    }

    #[test]
    fn hostile_coordinates_stay_finite() {
        let t = checker();
        for uv in [[f64::NAN, 0.5], [f64::INFINITY, f64::NEG_INFINITY], [1e300, -1e300], [-0.0, 1e-300]] {
            assert!(t.sample(uv).iter().all(|c| c.is_finite()), "{uv:?}");
        }
    }

    #[test]
    fn the_transform_follows_the_extension() {
        // Rotation by 90°: +u goes to −v.
        let r = UvTransform { rotation: std::f64::consts::FRAC_PI_2, ..Default::default() };
        let p = r.apply([1.0, 0.0]);
        assert!(p[0].abs() < 1e-12 && (p[1] + 1.0).abs() < 1e-12, "{p:?}");
        let s = UvTransform { offset: [0.5, 0.0], scale: [2.0, 3.0], rotation: 0.0 };
        assert_eq!(s.apply([1.0, 1.0]), [2.5, 3.0]);
    }
}
