//! Surface materials: the parameters of the chapter's model per surface (docs/model.md §3, §5,
//! §7).

use crate::params::PhongExponent;

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
    /// Transparency `t` in [0, 1] (docs/model.md §2, glTF `KHR_materials_transmission`). Stored, not
    /// rendered yet.
    pub transmission: f64,
    /// Absorption coefficient `a` per channel, per unit length, of `I_Td = I_T0·e^(−a·d)` (docs/model.md §7,
    /// from glTF `KHR_materials_volume`). Stored, not rendered yet.
    pub absorption: [f64; 3],
    /// Thickness `d` of the material for that absorption (docs/model.md §7). Stored, not rendered yet.
    pub thickness: f64,
    /// Base colour texture: `C` is multiplied by its linear RGB per point (glTF
    /// `baseColorTexture`, docs/textures.md).
    pub base_color_texture: Option<super::TextureRef>,
    /// The part of μ the base colour sets (glTF's metallic M times its base colour factor): the
    /// base colour texture and vertex colours scale it as they scale `C`. 0 for the built-in
    /// materials.
    pub mu_tinted: [f64; 3],
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
            absorption: [0.0; 3],
            thickness: 0.0,
            base_color_texture: None,
            mu_tinted: [0.0; 3],
        }
    }
}

impl Material {
    /// The surface colour `C` and reflectance μ at a point with texture coordinates `uv` and
    /// vertex colour `vertex_color` ([`tinted_surface`] with `t` = the vertex colour times the
    /// base colour texture's linear RGB there). A texture index past `textures` counts as none.
    pub fn surface_at(
        &self,
        textures: &[super::Texture],
        uv: [f64; 2],
        vertex_color: [f64; 3],
    ) -> ([f64; 3], [f64; 3]) {
        let texel = self
            .base_color_texture
            .and_then(|r| textures.get(r.texture).map(|t| t.sample(r.transform.apply(uv))))
            .unwrap_or([1.0; 4]);
        let tint = vertex_tint(vertex_color);
        tinted_surface(self.color, self.mu, self.mu_tinted, std::array::from_fn(|i| tint[i] * texel[i]))
    }
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
