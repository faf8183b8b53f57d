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

/// A texture's sampler (glTF `sampler`): wrap per axis, the magnification and minification
/// filters, and how mipmap levels are chosen (`None`: level 0 only).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sampler {
    /// `[s, t]`: along u and along v.
    pub wrap: [Wrap; 2],
    /// `magFilter`.
    pub filter: Filter,
    /// `minFilter`'s filter within a level.
    pub min: Filter,
    /// `minFilter`'s choice between levels: the nearest level, or the two around the level of
    /// detail blended; `None` for NEAREST and LINEAR (level 0 only).
    pub mipmap: Option<Filter>,
}

/// glTF leaves an absent sampler's filters to the viewer: bilinear, and trilinear when minified.
impl Default for Sampler {
    fn default() -> Self {
        Sampler { wrap: [Wrap::Repeat; 2], filter: Filter::Linear, min: Filter::Linear, mipmap: Some(Filter::Linear) }
    }
}

/// One mipmap level: `4·width·height` bytes, encoded as the level chain's colour space reads them.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    pub width: u32,
    pub height: u32,
    /// Level 0 shares the texture's own pixels.
    pub rgba8: Arc<[u8]>,
}

/// How a texture's derivatives of (u, v) along the image's x and y are given to the sampler:
/// the footprint of a pixel in texture coordinates (before any `KHR_texture_transform`).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct UvFootprint {
    pub dx: [f64; 2],
    pub dy: [f64; 2],
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
    /// The mipmap chains of `rgba8`, made on first use (sRGB, linear). A texture's pixels are not
    /// changed after it is made: a new `Texture` is.
    pub levels: MipCache,
}

/// A texture's mipmap chains, once made (not part of its value: equality ignores it).
#[derive(Clone, Debug, Default)]
pub struct MipCache([std::sync::OnceLock<Arc<Vec<Level>>>; 2]);

impl PartialEq for MipCache {
    fn eq(&self, _: &MipCache) -> bool {
        true
    }
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

    /// A footprint in transformed coordinates: `R·S` of each derivative (the offset drops out).
    pub fn footprint(&self, f: &UvFootprint) -> UvFootprint {
        let d = |v: [f64; 2]| texture_uv(v, [0.0; 2], self.rotation, self.scale);
        UvFootprint { dx: d(f.dx), dy: d(f.dy) }
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
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
            levels: MipCache::default(),
        }
    }

    /// The mipmap chain of the image as `space` reads it: level 0 the image, each next level
    /// half the size (at least 1), each texel the mean of the 2×2 below it in linear values
    /// (sRGB decoded, averaged, encoded again for a colour chain), rounded to 8 bits as the GPU
    /// stores it. The GPU uploads these same bytes.
    pub fn mip_levels(&self, space: ColorSpace) -> Arc<Vec<Level>> {
        let k = match space {
            ColorSpace::Srgb => 0,
            ColorSpace::Linear => 1,
        };
        self.levels.0[k].get_or_init(|| Arc::new(self.chain(space))).clone()
    }

    fn chain(&self, space: ColorSpace) -> Vec<Level> {
        let mut out = vec![Level { width: self.width, height: self.height, rgba8: self.rgba8.clone() }];
        while let Some(prev) = out.last().filter(|l| l.width > 1 || l.height > 1) {
            let (w, h) = ((prev.width / 2).max(1), (prev.height / 2).max(1));
            let mut rgba8 = Vec::with_capacity(4 * (w * h) as usize);
            for y in 0..h {
                for x in 0..w {
                    let mut sum = [0.0f64; 4];
                    for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                        let (sx, sy) = ((2 * x + dx).min(prev.width - 1), (2 * y + dy).min(prev.height - 1));
                        let t = texel_of(prev, sx, sy, space);
                        for k in 0..4 {
                            sum[k] += t[k] / 4.0;
                        }
                    }
                    rgba8.extend(encode(sum, space));
                }
            }
            out.push(Level { width: w, height: h, rgba8: rgba8.into() });
        }
        out
    }

    /// The texture at `uv` read as colour (sRGB decoded per texel), as the GPU samples an
    /// `Rgba8UnormSrgb` view at level 0 with its magnification filter.
    pub fn sample(&self, uv: [f64; 2]) -> [f64; 4] {
        self.sample_as(uv, ColorSpace::Srgb)
    }

    /// The texture at `uv` at level 0 with its magnification filter, each texel decoded as `space`
    /// says.
    pub fn sample_as(&self, uv: [f64; 2], space: ColorSpace) -> [f64; 4] {
        self.sample_level(self.width, self.height, &self.rgba8, uv, space, self.sampler.filter)
    }

    /// The level of detail λ = log2 ρ of a pixel's footprint in texels (the larger of the
    /// footprint's two axes, as Vulkan's scale factor); `None` for a footprint that is not finite.
    pub fn lod(&self, f: &UvFootprint) -> Option<f64> {
        let (w, h) = (self.width as f64, self.height as f64);
        let rho = |d: [f64; 2]| (d[0] * w).hypot(d[1] * h);
        let r = rho(f.dx).max(rho(f.dy));
        (r.is_finite() && r > 0.0).then(|| r.log2())
    }

    /// The texture at `uv` as the GPU samples it with implicit derivatives `footprint`: level 0
    /// and the magnification filter at λ ≤ 0; above it the minification filter, at level 0
    /// without mipmaps, at the nearest level (`ceil(λ + ½) − 1`), or blended between the two
    /// levels around λ.
    pub fn sample_footprint(&self, uv: [f64; 2], footprint: &UvFootprint, space: ColorSpace) -> [f64; 4] {
        let lambda = match self.lod(footprint) {
            Some(l) if l > 0.0 => l,
            _ => return self.sample_as(uv, space),
        };
        let levels = self.mip_levels(space);
        let q = (levels.len() - 1) as f64;
        let at = |d: f64| {
            let l = &levels[d as usize];
            self.sample_level(l.width, l.height, &l.rgba8, uv, space, self.sampler.min)
        };
        match self.sampler.mipmap {
            None => at(0.0),
            Some(Filter::Nearest) => at(((lambda + 0.5).ceil() - 1.0).clamp(0.0, q)),
            Some(Filter::Linear) => {
                let lambda = lambda.min(q);
                let (d0, frac) = (lambda.floor(), lambda - lambda.floor());
                let (a, b) = (at(d0), at((d0 + 1.0).min(q)));
                std::array::from_fn(|k| a[k] * (1.0 - frac) + b[k] * frac)
            }
        }
    }

    /// A level of `width × height` pixels `px` at `uv` with `filter`: texel centres at `(i + ½)/n`, the wrap mode
    /// per axis, nearest or bilinear, after each texel is decoded as `space` says.
    fn sample_level(
        &self,
        width: u32,
        height: u32,
        px: &[u8],
        uv: [f64; 2],
        space: ColorSpace,
        filter: Filter,
    ) -> [f64; 4] {
        let uv = uv.map(|c| if c.is_finite() { c } else { NONFINITE_UV });
        let texel = |x: u32, y: u32| decode(&px[4 * (y as usize * width as usize + x as usize)..][..4], space);
        // Far outside [0, 1] f64 keeps no fraction; such a coordinate repeats the same texels.
        let (x, y) = (uv[0] * width as f64, uv[1] * height as f64);
        let [ws, wt] = self.sampler.wrap;
        match filter {
            Filter::Nearest => {
                let (i, j) = (x.floor() as i64, y.floor() as i64);
                texel(wrap_index(i, width, ws), wrap_index(j, height, wt))
            }
            Filter::Linear => {
                let (x, y) = (x - 0.5, y - 0.5);
                let (i, j) = (x.floor(), y.floor());
                let (fx, fy) = (x - i, y - j);
                let (i, j) = (i as i64, j as i64);
                let (i0, i1) = (wrap_index(i, width, ws), wrap_index(i.saturating_add(1), width, ws));
                let (j0, j1) = (wrap_index(j, height, wt), wrap_index(j.saturating_add(1), height, wt));
                let (a, b, c, d) = (texel(i0, j0), texel(i1, j0), texel(i0, j1), texel(i1, j1));
                std::array::from_fn(|k| {
                    (a[k] * (1.0 - fx) + b[k] * fx) * (1.0 - fy) + (c[k] * (1.0 - fx) + d[k] * fx) * fy
                })
            }
        }
    }
}

/// A texel's 4 bytes: RGB decoded from sRGB (colour) or read as stored (data), and alpha.
fn decode(p: &[u8], space: ColorSpace) -> [f64; 4] {
    let rgb = |v: u8| match space {
        ColorSpace::Srgb => srgb_to_linear(v),
        ColorSpace::Linear => v as f64 / 255.0,
    };
    [rgb(p[0]), rgb(p[1]), rgb(p[2]), p[3] as f64 / 255.0]
}

fn texel_of(l: &Level, x: u32, y: u32, space: ColorSpace) -> [f64; 4] {
    decode(&l.rgba8[4 * (y as usize * l.width as usize + x as usize)..][..4], space)
}

/// Linear values back to 8 bits: RGB encoded to sRGB for a colour chain, alpha linear.
fn encode(v: [f64; 4], space: ColorSpace) -> [u8; 4] {
    let q = |c: f64| (c.clamp(0.0, 1.0) * 255.0).round() as u8;
    let rgb = |c: f64| match space {
        ColorSpace::Srgb => q(linear_to_srgb(c)),
        ColorSpace::Linear => q(c),
    };
    [rgb(v[0]), rgb(v[1]), rgb(v[2]), q(v[3])]
}

/// Linear → sRGB-encoded in [0, 1] (IEC 61966-2-1).
pub fn linear_to_srgb(c: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    if c <= 0.0031308 { c * 12.92 } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 }
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
    fn mip_chains_average_in_linear_values() {
        let t = checker();
        let srgb = t.mip_levels(ColorSpace::Srgb);
        assert_eq!(srgb.iter().map(|l| (l.width, l.height)).collect::<Vec<_>>(), [(2, 2), (1, 1)]);
        // Black and white average to linear ½: sRGB 188 (0.735…), not 128.
        assert_eq!(&srgb[1].rgba8[..], &[188, 188, 188, 255]);
        let linear = t.mip_levels(ColorSpace::Linear);
        assert_eq!(&linear[1].rgba8[..], &[128, 128, 128, 255]);
        // An odd side halves down to 1, repeating its last texel.
        let odd = Texture { width: 3, height: 1, rgba8: Arc::from(&[0u8; 12][..]), ..Texture::solid("odd", [0; 4]) };
        let sizes: Vec<_> = odd.mip_levels(ColorSpace::Linear).iter().map(|l| (l.width, l.height)).collect();
        assert_eq!(sizes, [(3, 1), (1, 1)]);
    }

    #[test]
    fn the_footprint_picks_the_level() {
        let t = checker();
        let at = |texels: f64| UvFootprint { dx: [texels / 2.0, 0.0], dy: [0.0, 0.0] };
        // Magnified or 1:1 (λ ≤ 0): level 0 with the magnification filter.
        assert_eq!(t.sample_footprint([0.25, 0.25], &at(0.5), ColorSpace::Srgb), t.sample([0.25, 0.25]));
        assert_eq!(t.lod(&at(2.0)), Some(1.0));
        // λ = 1: the 1×1 level, linear ½ everywhere.
        let one = t.sample_footprint([0.25, 0.25], &at(2.0), ColorSpace::Srgb);
        assert!((one[0] - srgb_to_linear(188)).abs() < 1e-12, "{one:?}");
        // λ = ½: halfway between the black texel of level 0 and level 1.
        let half = t.sample_footprint([0.25, 0.25], &at(2f64.sqrt()), ColorSpace::Srgb);
        assert!((half[0] - 0.5 * srgb_to_linear(188)).abs() < 1e-9, "{half:?}");
        // Without mipmaps: level 0, with the minification filter.
        let mut flat = checker();
        flat.sampler = Sampler { mipmap: None, min: Filter::Nearest, ..Sampler::default() };
        assert_eq!(flat.sample_footprint([0.3, 0.25], &at(4.0), ColorSpace::Srgb)[0], 0.0);
        // A footprint that is not finite reads level 0.
        let nan = UvFootprint { dx: [f64::NAN, 0.0], dy: [0.0, 0.0] };
        assert_eq!(t.sample_footprint([0.25, 0.25], &nan, ColorSpace::Srgb), t.sample([0.25, 0.25]));
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
