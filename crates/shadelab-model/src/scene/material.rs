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
        }
    }
}
