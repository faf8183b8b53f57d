//! The twin of `shaders/brdf.wgsl`: the terms of the chapter's illumination model, one function
//! each, and the specular models. A specular model is declared here once: its name, its WGSL
//! code, its f64 term and its arm in [`light_contribution`].

use super::common::safe_normalize;
use crate::guards::*;
use crate::params::NamedValue;
use crate::scene::Material;
use glam::DVec3;

/// Which specular term the illumination model uses (docs/model.md §3, §5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SpecularModel {
    /// `(V·R)^h`.
    Phong,
    /// Beckmann D, min() G and exact Fresnel F.
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

impl NamedValue for SpecularModel {
    const FLAG: &'static str = "--specular";
    const ALL: &'static [(&'static str, Self)] =
        &[("phong", SpecularModel::Phong), ("cook-torrance", SpecularModel::CookTorrance)];
}

/// docs/model.md §1, §3: Lambert's cosine with the oriented angle; a face turned away
/// (`N·L ≤ 0`) is in its own shadow and gets no direct light.
pub fn diffuse_lambert(n_dot_l: f64) -> f64 {
    n_dot_l.max(0.0)
}

/// docs/model.md §1: the chapter's Lambert rule `I' = R·I·cos α + R·(1 − I)`, with the printed text's
/// garbled second term `R(I − I)` read as the ambient fill `R(1 − I)` (erratum, docs/model.md §1).
#[cfg(test)]
pub(crate) fn lambert_rule(r: f64, i: f64, cos_alpha: f64) -> f64 {
    let r = r.clamp(0.0, 1.0);
    let i = i.clamp(0.0, 1.0);
    r * i * diffuse_lambert(cos_alpha) + r * (1.0 - i)
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

/// docs/model.md §5: the Beckmann facet distribution in the chapter's form
/// `D = 1/(4 m² (N·H)⁴) · exp((1 − 1/(N·H)²)/m²)`; equals π/4 × the normalized Beckmann D.
/// `sin2_nh` = 1 − (N·H)², computed by the caller as |N × H|² (precise at the peak; see the WGSL).
pub fn d_beckmann(n_dot_h: f64, sin2_nh: f64, m: f64) -> f64 {
    if n_dot_h <= 0.0 {
        return 0.0;
    }
    let c = n_dot_h.clamp(N_DOT_H_MIN, 1.0);
    let m2 = m.max(M_MIN).powi(2);
    let c2 = c * c;
    (1.0 / (4.0 * m2 * c2 * c2)) * (-sin2_nh.max(0.0) / (c2 * m2)).exp()
}

/// The normalized Beckmann distribution `exp(−tan²α/m²)/(π m² cos⁴α)` (its projected area
/// integrates to 1), written independently of [`d_beckmann`] so that tests can check the chapter's
/// form against it (docs/model.md §5: the chapter's D = π/4 × this).
#[cfg(test)]
pub(crate) fn d_beckmann_normalized(n_dot_h: f64, m: f64) -> f64 {
    if n_dot_h <= 0.0 {
        return 0.0;
    }
    let cos2 = n_dot_h * n_dot_h;
    let tan2 = (1.0 - cos2) / cos2;
    (-tan2 / (m * m)).exp() / (std::f64::consts::PI * m * m * cos2 * cos2)
}

/// docs/model.md §5: geometric attenuation `G = min{1, 2(N·H)(N·V)/(V·H), 2(N·H)(N·L)/(V·H)}`.
pub fn g_cook_torrance(n_dot_h: f64, n_dot_v: f64, n_dot_l: f64, v_dot_h: f64) -> f64 {
    let nh = n_dot_h.max(0.0);
    let nv = n_dot_v.max(0.0);
    let nl = n_dot_l.max(0.0);
    let vh = v_dot_h.max(0.0);
    // min{1, a/vh, b/vh} without dividing by a zero vh: 2·nh·n ≤ vh ⇔ a/vh ≤ 1.
    let num = (2.0 * nh * nv).min(2.0 * nh * nl);
    if num >= vh { 1.0 } else { num / vh.max(G_V_DOT_H_MIN) }
}

/// docs/model.md §5: refractive index from the reflectance at normal incidence,
/// `v = (1 + √μ)/(1 − √μ)`, with `√μ` capped at `FRESNEL_SQRT_MU_MAX`.
pub fn fresnel_v_from_mu(mu: f64) -> f64 {
    let s = mu.clamp(0.0, 1.0).sqrt().min(FRESNEL_SQRT_MU_MAX);
    (1.0 + s) / (1.0 - s)
}

/// docs/model.md §5: the exact unpolarized Fresnel factor
/// `F = ½ ((g − c)/(g + c))² {1 + [(c(g + c) − 1)/(c(g − c) + 1)]²}`, `c = L·H`,
/// `g = √(v² + c² − 1)`. F(c = 1) = μ and F(c = 0) = 1 (the chapter's "c = 0" is an erratum).
pub fn f_fresnel_exact(c: f64, v: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let v = v.max(1.0);
    let g = ((v - 1.0) * (v + 1.0) + c * c).max(0.0).sqrt();
    let a = (g - c) / (g + c).max(FRESNEL_G_PLUS_C_MIN);
    // c(g − c) + 1 ≥ 1 − c² + c·g ≥ 0 since g ≥ c for v ≥ 1; it is ≥ 1 whenever c ≤ g.
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    0.5 * a * a * (1.0 + b * b)
}

/// docs/model.md §5: the Cook–Torrance specular term as it enters the sum, `π ρ_s (N·L)`
/// `= F·D·G/(N·V)` with the chapter's D, per colour channel (`v` per channel). Multiplying by π keeps
/// it on the scale of the chapter's diffuse term `r_d·C·(N·L)`, which has no 1/π.
pub fn specular_cook_torrance(n: DVec3, v: DVec3, l: DVec3, m: f64, v_index: [f64; 3]) -> [f64; 3] {
    let n_dot_l = n.dot(l);
    let n_dot_v = n.dot(v);
    if n_dot_l <= 0.0 || n_dot_v <= 0.0 {
        return [0.0; 3];
    }
    let h = safe_normalize(l + v, n);
    let n_dot_h = n.dot(h);
    let v_dot_h = v.dot(h).clamp(0.0, 1.0);
    let d = d_beckmann(n_dot_h, n.cross(h).length_squared(), m);
    let g = g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h);
    let k = d * g / n_dot_v.max(N_DOT_V_MIN);
    v_index.map(|vi| f_fresnel_exact(v_dot_h, vi) * k)
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
    let f = f_fresnel_exact(v_dot_h, v_index);
    let g = g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h);
    let seed = f / std::f64::consts::PI * d_beckmann(n_dot_h, n.cross(h).length_squared(), m) * g / (n_dot_v * n_dot_l);
    let modern = f * d_beckmann_normalized(n_dot_h, m) * g / (4.0 * n_dot_v * n_dot_l);
    (seed, modern)
}

/// docs/model.md §3: what one light adds, `I_L · (r_d·C·max(form, 0) + r_s·S(L)·spec_scale)`
/// for the light's sample `s` ([`super::lights::light_sample`]; `form` is `N·L` for a point
/// light), the specular zero where `N·L ≤ 0` (the point's own shadow).
pub fn light_contribution(
    s: &super::lights::LightSample,
    n: DVec3,
    v: DVec3,
    mat: &Material,
    v_index: [f64; 3],
    specular: SpecularModel,
) -> [f64; 3] {
    let n_dot_l = n.dot(s.l);
    if n_dot_l <= 0.0 && s.form <= 0.0 {
        return [0.0; 3];
    }
    let spec = if n_dot_l <= 0.0 {
        [0.0; 3]
    } else {
        match specular {
            SpecularModel::CookTorrance => specular_cook_torrance(n, v, s.l, mat.m, v_index),
            SpecularModel::Phong => {
                let r = 2.0 * n_dot_l * n - s.l;
                let x = if n.dot(v) > 0.0 { specular_phong(v.dot(r), mat.h.value(), mat.h.is_mirror()) } else { 0.0 };
                [x; 3]
            }
        }
    };
    std::array::from_fn(|i| {
        s.radiance[i] * (mat.r_d * mat.color[i] * diffuse_lambert(s.form) + mat.r_s * spec[i] * s.spec_scale)
    })
}
