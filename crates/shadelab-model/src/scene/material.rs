//! Surface materials: the parameters of the chapter's model per surface (docs/model.md §3, §5,
//! §7).

use super::texture::{ColorSpace, Texture, TextureRef, UvFootprint};
use crate::guards::NORMALIZE_MIN_LEN2;
use crate::lighting::common::safe_normalize;
use crate::params::PhongExponent;
use glam::DVec3;

/// Surface material of the chapter's model (docs/model.md §3, §5).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    /// Surface colour `C`, linear RGB in [0, 1].
    pub color: [f64; 3],
    /// Specular share `r_s`.
    pub r_s: f64,
    /// Diffuse share `r_d`.
    pub r_d: f64,
    /// Ambient reflectance `r_a`.
    pub r_a: f64,
    /// Beckmann roughness `m` (Cook–Torrance).
    pub m: f64,
    /// Phong exponent `h` (Phong specular).
    pub h: PhongExponent,
    /// Normal-incidence reflectance `μ` per channel (Cook–Torrance Fresnel).
    pub mu: [f64; 3],
    /// The transmitted share τ = 1 − t of the chapter's transparency t (docs/model.md §2, glTF
    /// `KHR_materials_transmission`): 0 opaque. Above 0 the glass pass draws the material
    /// (docs/transparency.md).
    pub transmission: f64,
    /// The refractive index `v` per channel given directly (`--ior`); `None`: from μ,
    /// `v = (1 + √μ)/(1 − √μ)`. Channels that differ disperse.
    pub ior: Option<[f64; 3]>,
    /// Absorption coefficient `a` per channel, per unit length, of `I_Td = I_T0·e^(−a·d)` (docs/model.md §7,
    /// from glTF `KHR_materials_volume`). The glass pass takes `d` from the geometry.
    pub absorption: [f64; 3],
    /// glTF's authored thickness (`thicknessFactor`), kept for the round trip: shadelab measures
    /// `d` from the geometry instead (docs/transparency.md).
    pub thickness: f64,
    /// Base colour texture: `C` is multiplied by its linear RGB per point (glTF
    /// `baseColorTexture`, docs/textures.md).
    pub base_color_texture: Option<super::TextureRef>,
    /// The part of μ the base colour sets (glTF's metallic M times its base colour factor): the
    /// base colour texture and vertex colours scale it as they scale `C`. 0 for the built-in
    /// materials.
    pub mu_tinted: [f64; 3],
    /// Emitted radiance `I_e`, linear RGB, added to the model's `I` (glTF `emissiveFactor`).
    pub emission: [f64; 3],
    /// The textures that vary the model's other parameters per point (glTF's metallic–roughness,
    /// occlusion, emissive and normal textures; docs/textures.md).
    pub maps: MaterialMaps,
    /// The D, G and F of its Cook–Torrance specular (the chapter's by default).
    pub microfacet: crate::lighting::microfacet::Microfacet,
    /// Phong's lobe scaled to reflect all the light it receives at normal view
    /// (`brdf::phong_normalization`, docs/model.md §3); off in the chapter's model.
    pub phong_normalized: bool,
    /// The dielectric layer whose Fresnel factor weights the diffuse when the terms ask for it
    /// (`Microfacet::fresnel_mix`, docs/model.md §5).
    pub fresnel_mix: FresnelMix,
}

/// The dielectric layer of glTF's `fresnel_mix`: its own normal-incidence reflectance, apart from
/// the μ its metallic part mixes in, and its weight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FresnelMix {
    /// The layer's F0, in [0, 1]: glTF's from `KHR_materials_ior` and the largest channel of
    /// `KHR_materials_specular`'s colour; 0.04 (index 1.5) by default.
    pub f0: f64,
    /// `KHR_materials_specular`'s factor, in [0, 1]; 1 by default.
    pub weight: f64,
}

impl Default for FresnelMix {
    fn default() -> Self {
        FresnelMix { f0: 0.04, weight: 1.0 }
    }
}

/// A material's textures beyond the base colour. Each is optional; a point without one uses the
/// material's own parameter.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct MaterialMaps {
    /// glTF's `metallicRoughnessTexture`: its blue channel scales the metallic factor, its green
    /// channel the roughness.
    pub metal_roughness: Option<MetalRoughnessMap>,
    /// glTF's `occlusionTexture`: its red channel scales the ambient reflectance `r_a`.
    pub occlusion: Option<OcclusionMap>,
    /// glTF's `emissiveTexture`: its (sRGB) colour scales the emission `I_e`.
    pub emissive: Option<TextureRef>,
    /// glTF's `normalTexture`: the shading normal in the mesh's tangent frame.
    pub normal: Option<NormalMap>,
}

/// The normal texture and glTF's `scale` of its x and y.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct NormalMap {
    pub texture: TextureRef,
    pub scale: f64,
}

/// The metallic–roughness texture and what the metallic scale needs beside the material.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct MetalRoughnessMap {
    pub texture: TextureRef,
    /// `M·F0`: the dielectric F0 share of μ that the metallic factor M replaced (glTF's
    /// `μ = lerp(F0, base, M)`); a texel's metal scale b < 1 gives part of it back.
    pub metallic_f0: [f64; 3],
}

/// The occlusion texture and glTF's `strength`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct OcclusionMap {
    pub texture: TextureRef,
    /// In [0, 1]: 0 leaves `r_a` as it is, 1 scales it by the texel.
    pub strength: f64,
}

/// A material's parameters at one point (what [`Material::surface_at`] gives the reference).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    pub color: [f64; 3],
    pub mu: [f64; 3],
    pub m: f64,
    pub h: PhongExponent,
    pub r_a: f64,
    pub emission: [f64; 3],
}

impl Default for Material {
    fn default() -> Self {
        Material {
            name: "default".into(),
            color: [0.8, 0.8, 0.8],
            r_s: 1.0,
            r_d: 0.8,
            r_a: 0.8,
            m: 0.3,
            h: PhongExponent::Finite(20.0),
            mu: [0.04; 3],
            transmission: 0.0,
            ior: None,
            absorption: [0.0; 3],
            thickness: 0.0,
            base_color_texture: None,
            mu_tinted: [0.0; 3],
            emission: [0.0; 3],
            maps: MaterialMaps::default(),
            microfacet: crate::lighting::microfacet::Microfacet::CHAPTER,
            phong_normalized: false,
            fresnel_mix: FresnelMix::default(),
        }
    }
}

impl Material {
    /// Whether the glass pass draws the material: some light passes through it.
    pub fn transmits(&self) -> bool {
        self.transmission > 0.0
    }

    /// The refractive index `v` per channel: given, or from μ (docs/model.md §5).
    pub fn refractive_index(&self) -> [f64; 3] {
        self.ior.unwrap_or(self.mu.map(crate::lighting::microfacet::fresnel_v_from_mu))
    }

    /// Whether the channels' indices differ, so each channel takes its own path.
    pub fn disperses(&self) -> bool {
        let v = self.refractive_index();
        v[0] != v[1] || v[1] != v[2]
    }

    /// Whether a point's parameters can differ from the material's (a texture, or vertex colours
    /// `vertex_color` other than white).
    pub fn varies(&self, vertex_color: [f64; 3]) -> bool {
        self.base_color_texture.is_some() || self.maps != MaterialMaps::default() || vertex_color != [1.0; 3]
    }

    /// The largest C a point of the material can have: a metallic–roughness texel's metal scale
    /// gives a metal's base colour back to C ([`metallic_scaled`] at b = 0), so a metal with
    /// that texture can still be diffuse.
    pub fn max_color(&self) -> [f64; 3] {
        let back = if self.maps.metal_roughness.is_some() { self.mu_tinted } else { [0.0; 3] };
        std::array::from_fn(|i| self.color[i] + back[i])
    }

    /// The material at a point with texture coordinates `uv` (the pixel's `footprint` in them
    /// choosing each texture's mipmap level; `None`: level 0) and vertex colour `vertex_color`:
    /// C and μ tinted by the vertex colour and base colour texture ([`tinted_surface`]), after
    /// the metallic–roughness texel's metal scale ([`metallic_scaled`]); m scaled by its
    /// roughness ([`roughness_scaled`]) and h following m ([`phong_h_from_m`]); `r_a` by the
    /// occlusion texel ([`occluded`]); I_e by the emissive texel ([`emitted`]). A texture index
    /// past `textures` counts as none.
    pub fn surface_at(
        &self,
        textures: &[Texture],
        uv: [f64; 2],
        footprint: Option<&UvFootprint>,
        vertex_color: [f64; 3],
    ) -> SurfacePoint {
        let sample = |r: &TextureRef, space| sample_ref(textures, r, uv, footprint, space);
        let texel = self.base_color_texture.and_then(|r| sample(&r, ColorSpace::Srgb)).unwrap_or([1.0; 4]);
        let tint = vertex_tint(vertex_color);
        let t = std::array::from_fn(|i| tint[i] * texel[i]);
        let (mut c, mut mu, mut mu_t) = (self.color, self.mu, self.mu_tinted);
        let (mut m, mut h) = (self.m, self.h);
        if let Some(mr) = &self.maps.metal_roughness
            && let Some(x) = sample(&mr.texture, ColorSpace::Linear)
        {
            (c, mu, mu_t) = metallic_scaled(c, mu, mu_t, mr.metallic_f0, x[2]);
            m = roughness_scaled(m, x[1]);
            h = PhongExponent::from_m(m);
        }
        let (color, mu) = tinted_surface(c, mu, mu_t, t);
        let r_a = match &self.maps.occlusion {
            Some(o) => {
                sample(&o.texture, ColorSpace::Linear).map_or(self.r_a, |x| occluded(self.r_a, x[0], o.strength))
            }
            None => self.r_a,
        };
        let emissive = self.maps.emissive.and_then(|r| sample(&r, ColorSpace::Srgb)).unwrap_or([1.0; 4]);
        let emission = emitted(self.emission, [emissive[0], emissive[1], emissive[2]]);
        SurfacePoint { color, mu, m, h, r_a, emission }
    }
}

impl Material {
    /// The shading normal at a point with texture coordinates `uv` (and `footprint`), unit normal `n` and tangent
    /// `tangent` (xyz, and the bitangent's sign w): `n` perturbed by the normal texture
    /// ([`normal_mapped`]), or `n` itself without one.
    pub fn normal_at(
        &self,
        textures: &[Texture],
        uv: [f64; 2],
        footprint: Option<&UvFootprint>,
        n: DVec3,
        tangent: [f64; 4],
    ) -> DVec3 {
        let Some(map) = &self.maps.normal else { return n };
        let Some(x) = sample_ref(textures, &map.texture, uv, footprint, ColorSpace::Linear) else { return n };
        normal_mapped(n, tangent, [x[0], x[1], x[2]], map.scale)
    }
}

/// Texture `r` at `uv` as `space` reads it, at the level `footprint` picks (level 0 without one);
/// `None` for an index past `textures`.
fn sample_ref(
    textures: &[Texture],
    r: &TextureRef,
    uv: [f64; 2],
    footprint: Option<&UvFootprint>,
    space: ColorSpace,
) -> Option<[f64; 4]> {
    let t = textures.get(r.texture)?;
    let uv = r.transform.apply(uv);
    Some(match footprint {
        Some(f) => t.sample_footprint(uv, &r.transform.footprint(f), space),
        None => t.sample_as(uv, space),
    })
}

/// glTF's normal texture: the texel `2·x − 1` in the frame (T, B = w·N×T, N), x and y scaled by
/// `scale`, T made perpendicular to N first (twin of `normal_mapped` in shaders/surface.wgsl). A
/// tangent that frames nothing (zero, non-finite, along N) leaves N as it is; so does a
/// non-finite texel (read as the flat (½, ½, 1)).
pub fn normal_mapped(n: DVec3, tangent: [f64; 4], texel: [f64; 3], scale: f64) -> DVec3 {
    let t = DVec3::new(tangent[0], tangent[1], tangent[2]);
    let g = t - n * n.dot(t);
    // A NaN length counts as none.
    let len2 = g.length_squared();
    if len2.is_nan() || len2 <= NORMALIZE_MIN_LEN2 {
        return n;
    }
    let t = g.normalize();
    let sign = if tangent[3] < 0.0 { -1.0 } else { 1.0 };
    let b = n.cross(t) * sign;
    let flat = [0.5, 0.5, 1.0];
    let x: [f64; 3] = std::array::from_fn(|i| if texel[i].is_finite() { texel[i].clamp(0.0, 1.0) } else { flat[i] });
    let scale = if scale.is_finite() { scale } else { 1.0 };
    let m = t * ((2.0 * x[0] - 1.0) * scale) + b * ((2.0 * x[1] - 1.0) * scale) + n * (2.0 * x[2] - 1.0);
    safe_normalize(m, n)
}

/// The material's C, μ and tinted μ at a metallic–roughness texel whose metal scale (blue) is
/// `b`, so that glTF's metallic is `M·b`: `C + μ_t·(1 − b)`, `μ + (M·F0 − μ_t)·(1 − b)`, `μ_t·b`
/// (twin of `metallic_scaled` in shaders/surface.wgsl). At b = 1 the material is unchanged;
/// at b = 0 it is the dielectric with the same base colour.
pub fn metallic_scaled(
    c: [f64; 3],
    mu: [f64; 3],
    mu_tinted: [f64; 3],
    metallic_f0: [f64; 3],
    b: f64,
) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let b = if b.is_finite() { b.clamp(0.0, 1.0) } else { 1.0 };
    let k = 1.0 - b;
    (
        std::array::from_fn(|i| c[i] + mu_tinted[i] * k),
        std::array::from_fn(|i| mu[i] + (metallic_f0[i] - mu_tinted[i]) * k),
        mu_tinted.map(|t| t * b),
    )
}

/// Roughness m at a texel whose roughness scale (green) is `g`: glTF's roughness is `r·g`, and
/// m = r², so `m·g²`, in [0, 1] (twin of `roughness_scaled` in shaders/surface.wgsl).
pub fn roughness_scaled(m: f64, g: f64) -> f64 {
    let g = if g.is_finite() { g.clamp(0.0, 1.0) } else { 1.0 };
    (m * g * g).clamp(0.0, 1.0)
}

/// The Phong exponent a point's roughness implies, `2/m² − 2` in [1, H_MAX], the mirror's H_MAX
/// at m = 0 (twin of `phong_h_from_m` in shaders/surface.wgsl; the rule is
/// `PhongExponent::from_m`).
pub fn phong_h_from_m(m: f64) -> f64 {
    PhongExponent::from_m(m).value()
}

/// Ambient reflectance under an occlusion texel `occ` (red) of strength `strength`:
/// `r_a·(1 + strength·(occ − 1))`, glTF's occlusion rule (twin of `occluded` in
/// shaders/surface.wgsl).
pub fn occluded(r_a: f64, occ: f64, strength: f64) -> f64 {
    let occ = if occ.is_finite() { occ.clamp(0.0, 1.0) } else { 1.0 };
    let strength = if strength.is_finite() { strength.clamp(0.0, 1.0) } else { 1.0 };
    r_a * (1.0 + strength * (occ - 1.0))
}

/// Emission I_e scaled by an emissive texel's linear colour (twin of `emitted` in
/// shaders/surface.wgsl).
pub fn emitted(e: [f64; 3], texel: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| e[i] * if texel[i].is_finite() { texel[i].clamp(0.0, 1.0) } else { 1.0 })
}

/// `C·t` and `μ + μ_t·(t − 1)`, μ clamped to [0, 1]: glTF's base colour scales the diffuse colour
/// and a metal's F0 alike (twin of `tinted_surface` in shaders/surface.wgsl). Evaluated as
/// `(μ − μ_t) + μ_t·t`, exact for a metal (μ = μ_t) at any t, where the printed form cancels.
pub fn tinted_surface(c: [f64; 3], mu: [f64; 3], mu_tinted: [f64; 3], t: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    (
        std::array::from_fn(|i| c[i] * t[i]),
        std::array::from_fn(|i| ((mu[i] - mu_tinted[i]) + mu_tinted[i] * t[i]).clamp(0.0, 1.0)),
    )
}

/// A vertex colour as a tint: clamped to [0, 1], a non-finite channel white (twin of `vertex_tint`
/// in shaders/surface.wgsl).
pub fn vertex_tint(color: [f64; 3]) -> [f64; 3] {
    color.map(|c| if c.is_finite() { c.clamp(0.0, 1.0) } else { 1.0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_metal_scale_of_one_changes_nothing_and_zero_gives_the_dielectric() {
        // glTF base 0.6, metallic 0.75, F0 0.04: C = 0.15, μ_t = 0.45, μ = 0.01 + 0.45.
        let (c, mu, mu_t, mf0) = ([0.15; 3], [0.46; 3], [0.45; 3], [0.03; 3]);
        assert_eq!(metallic_scaled(c, mu, mu_t, mf0, 1.0), (c, mu, mu_t));
        let (c0, mu0, t0) = metallic_scaled(c, mu, mu_t, mf0, 0.0);
        for i in 0..3 {
            assert!((c0[i] - 0.6).abs() < 1e-12 && (mu0[i] - 0.04).abs() < 1e-12 && t0[i] == 0.0);
        }
        // A non-finite texel counts as 1 (the material as it is).
        assert_eq!(metallic_scaled(c, mu, mu_t, mf0, f64::NAN), (c, mu, mu_t));
    }

    #[test]
    fn roughness_occlusion_and_emission_follow_gltf() {
        assert!((roughness_scaled(0.25, 0.5) - 0.0625).abs() < 1e-15);
        assert_eq!(roughness_scaled(0.25, 2.0), 0.25);
        assert_eq!(phong_h_from_m(0.0), crate::guards::H_MAX);
        assert_eq!(phong_h_from_m(1.0), 1.0);
        assert_eq!(occluded(0.8, 0.5, 1.0), 0.4);
        assert_eq!(occluded(0.8, 0.5, 0.0), 0.8);
        assert_eq!(occluded(0.8, f64::NAN, 1.0), 0.8);
        assert_eq!(emitted([0.5; 3], [1.0, 0.5, f64::INFINITY]), [0.5, 0.25, 0.5]);
    }

    #[test]
    fn normal_texels_turn_the_normal_in_the_tangent_frame() {
        let (n, t) = (DVec3::Y, [1.0, 0.0, 0.0, 1.0]);
        // The flat texel (½, ½, 1) is the normal itself.
        assert!((normal_mapped(n, t, [0.5, 0.5, 1.0], 1.0) - n).length() < 1e-12);
        // x = 1, z = 0: the tangent; y = 1 with w = −1: minus the bitangent N × T.
        assert!((normal_mapped(n, t, [1.0, 0.5, 0.5], 1.0) - DVec3::X).length() < 1e-12);
        let b = n.cross(DVec3::X);
        assert!((normal_mapped(n, [1.0, 0.0, 0.0, -1.0], [0.5, 1.0, 0.5], 1.0) + b).length() < 1e-12);
        // A tangent with a part along N is made perpendicular first.
        assert!((normal_mapped(n, [1.0, 5.0, 0.0, 1.0], [1.0, 0.5, 0.5], 1.0) - DVec3::X).length() < 1e-12);
        // Scale 0 flattens the texture; frames of nothing leave N.
        assert!((normal_mapped(n, t, [1.0, 0.5, 0.5], 0.0) - n).length() < 1e-12);
        for bad in [[0.0; 4], [0.0, 1.0, 0.0, 1.0], [f64::NAN, 0.0, 0.0, 1.0]] {
            assert_eq!(normal_mapped(n, bad, [1.0, 0.0, 0.0], 1.0), n, "{bad:?}");
        }
        assert!((normal_mapped(n, t, [f64::NAN, 0.5, f64::INFINITY], 1.0) - n).length() < 1e-12);
    }

    #[test]
    fn surface_at_applies_each_map() {
        let tex = |rgba| Texture::solid("t", rgba);
        let textures = [tex([0, 128, 0, 255]), tex([64, 0, 0, 255]), tex([255, 255, 255, 255])];
        let r = |texture| TextureRef { texture, ..Default::default() };
        let plain = Material { emission: [0.2; 3], ..Material::default() };
        let at = plain.surface_at(&textures, [0.5; 2], None, [1.0; 3]);
        assert_eq!((at.m, at.r_a, at.emission, at.h), (plain.m, plain.r_a, [0.2; 3], plain.h));
        let mut mapped = plain.clone();
        mapped.maps = MaterialMaps {
            metal_roughness: Some(MetalRoughnessMap { texture: r(0), metallic_f0: [0.04; 3] }),
            occlusion: Some(OcclusionMap { texture: r(1), strength: 1.0 }),
            emissive: Some(r(2)),
            normal: None,
        };
        let at = mapped.surface_at(&textures, [0.5; 2], None, [1.0; 3]);
        let g = 128.0 / 255.0;
        assert!((at.m - plain.m * g * g).abs() < 1e-12, "{}", at.m);
        assert_eq!(at.h, PhongExponent::from_m(at.m));
        assert!((at.r_a - plain.r_a * 64.0 / 255.0).abs() < 1e-12);
        assert_eq!(at.emission, [0.2; 3]);
        // b = 0: the μ_t-free built-in material gets M·F0 back in μ.
        assert!((at.mu[0] - (plain.mu[0] + 0.04)).abs() < 1e-12);
    }
}
