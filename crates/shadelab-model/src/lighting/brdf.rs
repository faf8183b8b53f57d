//! The twin of `shaders/brdf.wgsl`: the terms of the chapter's illumination model, one function
//! each, and the specular models (the microfacet terms D, G, F are [`super::microfacet`]'s). A specular model is declared here once: its name, its WGSL
//! code, its f64 term and its arm in [`light_contribution`].

#[cfg(test)]
use super::common::safe_normalize;
#[cfg(test)]
pub(crate) use super::microfacet::d_beckmann_normalized;
pub use super::microfacet::{
    Microfacet, d_beckmann, fresnel_dielectric, fresnel_v_from_mu, g_cook_torrance, specular_microfacet,
};
use crate::guards::*;
use crate::scene::material::{FresnelMix, Material};
use glam::DVec3;

/// Which specular term the illumination model uses (docs/model.md §3, §5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SpecularModel {
    /// `(V·R)^h`.
    Phong,
    /// F·D·G/(N·V) with the material's microfacet terms (the chapter's: Beckmann D, min() G,
    /// exact Fresnel F).
    CookTorrance,
}

impl SpecularModel {
    pub const ALL_MODELS: [SpecularModel; 2] = [SpecularModel::Phong, SpecularModel::CookTorrance];

    /// The value of `globals.specular_model` in WGSL: `SPECULAR_<NAME>` of `shaders/brdf.wgsl`.
    pub fn code(self) -> u32 {
        match self {
            SpecularModel::Phong => 0,
            SpecularModel::CookTorrance => 1,
        }
    }
}

crate::named_values!(SpecularModel, "--specular", "phong" => Phong, "cook-torrance" => CookTorrance);

/// docs/model.md §1, §3: Lambert's cosine with the oriented angle; a face turned away
/// (`N·L ≤ 0`) is in its own shadow and gets no direct light.
pub fn diffuse_lambert(n_dot_l: f64) -> f64 {
    n_dot_l.max(0.0)
}

/// docs/model.md §1: the chapter's Lambert rule `I' = R·I·cos α + R·(1 − I)`, with the printed text's
/// garbled second term `R(I − I)` read as the ambient fill `R(1 − I)` (erratum, docs/model.md §1).
/// The tests' whole-rule oracle: the WGSL and the sum use its two parts (`models.rs`).
#[cfg(test)]
pub(crate) fn lambert_rule(r: f64, i: f64, cos_alpha: f64) -> f64 {
    let r = r.clamp(0.0, 1.0);
    let i = i.clamp(0.0, 1.0);
    r * i * diffuse_lambert(cos_alpha) + r * (1.0 - i)
}

/// docs/model.md §3: the factor that normalizes Phong's lobe as the sum uses it, `(h + 1)/2`.
/// The chapter's `(V·R)^h` has no `cos θ_i`, and `(1/π) ∫ (V·R)^h dω = 2/(h + 1)` when the lobe
/// lies above the surface, so this factor makes that albedo 1 (Lewis 1994's `(n + 1)/2π` in the
/// chapter's π scale; `(n + 2)/2π` is for the lobe with the cosine). The mirror setting, a spike
/// of fixed height, keeps 1; `h` is clamped to [1, H_MAX] as the term clamps it.
pub fn phong_normalization(h: f64, mirror: bool) -> f64 {
    if mirror { 1.0 } else { (h.clamp(1.0, H_MAX) + 1.0) / 2.0 }
}

/// docs/model.md §3: Phong specular `(V·R)^h`, as `exp2(h·log2(V·R))` with the argument of
/// `log2` kept at or above `PHONG_LOG2_ARG_MIN`; `mirror` is the `h = ∞` setting (guard
/// `MIRROR_V_DOT_R_MIN`), otherwise `h` is clamped to `[1, H_MAX]`.
pub fn specular_phong(v_dot_r: f64, h: f64, mirror: bool) -> f64 {
    let x = v_dot_r.clamp(0.0, 1.0);
    if mirror {
        return if x >= MIRROR_V_DOT_R_MIN { 1.0 } else { 0.0 };
    }
    let h = h.clamp(1.0, H_MAX);
    if x <= 0.0 { 0.0 } else { (h * x.max(PHONG_LOG2_ARG_MIN).log2()).exp2() }
}

/// docs/model.md §5: the Cook–Torrance term with the chapter's three terms
/// ([`Microfacet::CHAPTER`]; the terms themselves are in [`super::microfacet`]).
pub fn specular_cook_torrance(n: DVec3, v: DVec3, l: DVec3, m: f64, v_index: [f64; 3]) -> [f64; 3] {
    specular_microfacet(n, v, l, m, v_index, Microfacet::CHAPTER, 1.0)
}

/// The chapter's specular BRDF `ρ_s = (F/π)·D·G/((N·V)(N·L))` for one channel, and the modern form
/// `F·D_B·G/(4 (N·V)(N·L))`; the two agree (docs/model.md §5). Returned as (chapter's, modern).
#[cfg(test)]
pub(crate) fn rho_s_forms(n: DVec3, v: DVec3, l: DVec3, m: f64, v_index: f64) -> (f64, f64) {
    let n_dot_l = n.dot(l);
    let n_dot_v = n.dot(v);
    let h = safe_normalize(l + v, n);
    let n_dot_h = n.dot(h);
    let v_dot_h = v.dot(h);
    let f = fresnel_dielectric(v_dot_h, v_index);
    let g = g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h);
    let seed = f / std::f64::consts::PI * d_beckmann(n_dot_h, n.cross(h).length_squared(), m) * g / (n_dot_v * n_dot_l);
    let modern = f * d_beckmann_normalized(n_dot_h, m) * g / (4.0 * n_dot_v * n_dot_l);
    (seed, modern)
}

/// One light at one point, as the illumination model uses it (WGSL `LightSample`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit direction from the point towards the light (an area light's representative point).
    pub l: DVec3,
    /// Incident intensity `I_L` per channel after falloff.
    pub radiance: [f64; 3],
    /// The diffuse term's cosine factor: `N·L` for a point, spot or directional light; an area
    /// light's [`super::area::area_form`].
    pub form: f64,
    /// What the specular term at `l` is scaled by: 1, or an area light's [`super::area::area_specular_point`]
    /// scale.
    pub spec_scale: f64,
    /// An area light's specular by LTC relative to its centre's point light
    /// ([`super::ltc::area_specular_ltc`]), which replaces the lobe at `l` under Cook–Torrance;
    /// `None`: the lobe at `l` times `spec_scale` (WGSL: negative).
    pub ltc: Option<f64>,
}

/// The share of the diffuse the dielectric layer passes (`microfacet::fresnel_mix_weight`): only
/// under Cook–Torrance, for a material with a specular layer (r_s > 0) whose terms ask for it.
pub fn diffuse_weight(l: DVec3, n: DVec3, v: DVec3, mat: &Material, specular: SpecularModel) -> f64 {
    if !diffuse_weighted(mat, specular) {
        return 1.0;
    }
    let FresnelMix { f0, weight } = mat.fresnel_mix;
    super::microfacet::fresnel_mix_weight(mat.microfacet, n, v, l, f0, weight)
}

/// Whether [`diffuse_weight`] can be below 1: Cook–Torrance, a specular layer, and terms asking.
pub fn diffuse_weighted(mat: &Material, specular: SpecularModel) -> bool {
    specular == SpecularModel::CookTorrance && mat.microfacet.fresnel_mix && mat.r_s > 0.0
}

/// The specular `S(L)` of one light along unit `l` at unit normal `n` and view `v`, before `r_s`,
/// the light's intensity and its `spec_scale`: 0 where `N·L ≤ 0` (the point's own shadow).
pub fn light_specular(
    l: DVec3,
    n: DVec3,
    v: DVec3,
    mat: &Material,
    v_index: [f64; 3],
    specular: SpecularModel,
    ms_e: f64,
) -> [f64; 3] {
    let n_dot_l = n.dot(l);
    if n_dot_l <= 0.0 {
        return [0.0; 3];
    }
    match specular {
        SpecularModel::CookTorrance => specular_microfacet(n, v, l, mat.m, v_index, mat.microfacet, ms_e),
        SpecularModel::Phong => {
            let r = 2.0 * n_dot_l * n - l;
            let (h, mirror) = (mat.h.value(), mat.h.is_mirror());
            let k = if mat.phong_normalized { phong_normalization(h, mirror) } else { 1.0 };
            let x = if n.dot(v) > 0.0 { k * specular_phong(v.dot(r), h, mirror) } else { 0.0 };
            [x; 3]
        }
    }
}

/// docs/model.md §3: what one light adds, `I_L · (r_d·C·max(form, 0) + r_s·S(L)·spec_scale)`
/// for the light's sample `s` ([`super::lights::light_sample`]; `form` is `N·L` for a point
/// light), the specular zero where `N·L ≤ 0` (the point's own shadow).
pub fn light_contribution(
    s: &LightSample,
    n: DVec3,
    v: DVec3,
    mat: &Material,
    v_index: [f64; 3],
    specular: SpecularModel,
    ms_e: f64,
) -> [f64; 3] {
    if n.dot(s.l) <= 0.0 && s.form <= 0.0 {
        return [0.0; 3];
    }
    // An area light's LTC replaces the lobe at its representative point under Cook–Torrance.
    // Without a specular (r_s = 0) the lobe is multiplied away and not evaluated: the WGSL
    // multiplies it by 0, the same wherever it is finite, which the stability sweep holds.
    let (spec, scale) = match s.ltc.filter(|_| specular == SpecularModel::CookTorrance) {
        _ if mat.r_s == 0.0 => ([0.0; 3], 0.0),
        Some(ltc) => (super::ltc::specular_ltc(n, v, s.l, v_index, mat.microfacet, ms_e, ltc), 1.0),
        None => (light_specular(s.l, n, v, mat, v_index, specular, ms_e), s.spec_scale),
    };
    let kd = diffuse_weight(s.l, n, v, mat, specular);
    std::array::from_fn(|i| {
        s.radiance[i] * (mat.r_d * mat.color[i] * kd * diffuse_lambert(s.form) + mat.r_s * spec[i] * scale)
    })
}
