//! The lighting model in f64: the reference the GPU is tested against.
//!
//! One function per term, named as in `shaders/brdf.wgsl` and `shaders/lights.wgsl`, each citing
//! the section of `shared/spec/lighting-model.md` it implements. The guards are the named
//! constants of [`crate::guards`], the same values as in the WGSL.

use crate::guards::*;
use crate::params::{FalloffForm, LightKind, SpecularModel};
use crate::scene::{Light, Material};
use glam::DVec3;

/// Normalize `v`, or return `fallback` when `v` is (nearly) zero (guard `NORMALIZE_MIN_LEN2`).
pub fn safe_normalize(v: DVec3, fallback: DVec3) -> DVec3 {
    let len2 = v.length_squared();
    if len2 > NORMALIZE_MIN_LEN2 && len2.is_finite() { v / len2.sqrt() } else { fallback }
}

/// Spec §1, §3: Lambert's cosine with the oriented angle; a face turned away (`N·L ≤ 0`) is in its
/// own shadow and gets no direct light.
pub fn diffuse_lambert(n_dot_l: f64) -> f64 {
    n_dot_l.max(0.0)
}

/// Spec §1: the chapter's Lambert rule `I' = R·I·cos α + R·(1 − I)`, with the seed's garbled
/// second term `R(I − I)` read as the ambient fill `R(1 − I)` (erratum, see the spec).
pub fn lambert_rule(r: f64, i: f64, cos_alpha: f64) -> f64 {
    let r = r.clamp(0.0, 1.0);
    let i = i.clamp(0.0, 1.0);
    r * i * diffuse_lambert(cos_alpha) + r * (1.0 - i)
}

/// Spec §3: Phong specular `(V·R)^h`; `mirror` is the `h = ∞` setting (guard
/// `MIRROR_V_DOT_R_MIN`), otherwise `h` is clamped to `[1, H_MAX]`.
pub fn specular_phong(v_dot_r: f64, h: f64, mirror: bool) -> f64 {
    let x = v_dot_r.clamp(0.0, 1.0);
    if mirror {
        return if x >= MIRROR_V_DOT_R_MIN { 1.0 } else { 0.0 };
    }
    let h = h.clamp(1.0, H_MAX);
    if x <= 0.0 { 0.0 } else { (h * x.log2()).exp2() }
}

/// Spec §5: the Beckmann facet distribution in the seed's form
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
/// integrates to 1), written independently of [`d_beckmann`] so that tests can check the seed's
/// form against it (spec §5: seed D = π/4 × this).
pub fn d_beckmann_normalized(n_dot_h: f64, m: f64) -> f64 {
    if n_dot_h <= 0.0 {
        return 0.0;
    }
    let cos2 = n_dot_h * n_dot_h;
    let tan2 = (1.0 - cos2) / cos2;
    (-tan2 / (m * m)).exp() / (std::f64::consts::PI * m * m * cos2 * cos2)
}

/// Spec §5: geometric attenuation `G = min{1, 2(N·H)(N·V)/(V·H), 2(N·H)(N·L)/(V·H)}`.
pub fn g_cook_torrance(n_dot_h: f64, n_dot_v: f64, n_dot_l: f64, v_dot_h: f64) -> f64 {
    let nh = n_dot_h.max(0.0);
    let nv = n_dot_v.max(0.0);
    let nl = n_dot_l.max(0.0);
    let vh = v_dot_h.max(0.0);
    // min{1, a/vh, b/vh} without dividing by a zero vh: 2·nh·n ≤ vh ⇔ a/vh ≤ 1.
    let num = (2.0 * nh * nv).min(2.0 * nh * nl);
    if num >= vh { 1.0 } else { num / vh }
}

/// Spec §5: refractive index from the reflectance at normal incidence,
/// `v = (1 + √μ)/(1 − √μ)`, with `√μ` capped at `FRESNEL_SQRT_MU_MAX`.
pub fn fresnel_v_from_mu(mu: f64) -> f64 {
    let s = mu.clamp(0.0, 1.0).sqrt().min(FRESNEL_SQRT_MU_MAX);
    (1.0 + s) / (1.0 - s)
}

/// Spec §5: the exact unpolarized Fresnel factor
/// `F = ½ ((g − c)/(g + c))² {1 + [(c(g + c) − 1)/(c(g − c) + 1)]²}`, `c = L·H`,
/// `g = √(v² + c² − 1)`. F(c = 1) = μ and F(c = 0) = 1 (the seed's "c = 0" is an erratum).
pub fn f_fresnel_exact(c: f64, v: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let v = v.max(1.0);
    let g = ((v - 1.0) * (v + 1.0) + c * c).max(0.0).sqrt();
    let a = (g - c) / (g + c).max(FRESNEL_G_PLUS_C_MIN);
    // c(g − c) + 1 ≥ 1 − c² + c·g ≥ 0 since g ≥ c for v ≥ 1; it is ≥ 1 whenever c ≤ g.
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    0.5 * a * a * (1.0 + b * b)
}

/// Spec §5: the Cook–Torrance specular term as it enters the sum, `π ρ_s (N·L)`
/// `= F·D·G/(N·V)` with the seed's D, per colour channel (`v` per channel). Multiplying by π keeps
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

/// The seed's specular BRDF `ρ_s = (F/π)·D·G/((N·V)(N·L))` for one channel, and the modern form
/// `F·D_B·G/(4 (N·V)(N·L))`; the two agree (spec §5). Returned as (seed, modern).
pub fn rho_s_forms(n: DVec3, v: DVec3, l: DVec3, m: f64, v_index: f64) -> (f64, f64) {
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

/// Spec §6: falloff `1/(1 + α d²)`; in (0, 1] for α ≥ 0.
pub fn falloff_quadratic(d: f64, alpha: f64) -> f64 {
    1.0 / (1.0 + alpha.max(0.0) * d * d)
}

/// Spec §2: the chapter's `1/(d + d0)` falloff, `d0` kept at or above `D0_MIN`.
pub fn falloff_linear(d: f64, d0: f64) -> f64 {
    1.0 / (d.max(0.0) + d0.max(D0_MIN))
}

/// KHR_lights_punctual's spot cone (the extension's recommended form): 1 inside the inner cone,
/// 0 outside the outer one, between them the square of a ramp linear in the cosine. `cos_angle`
/// is the cosine between the spot's axis and the direction from the light to the point; the
/// span `cos_inner − cos_outer` is kept at or above `SPOT_COS_SPAN_MIN`.
pub fn spot_cone(cos_angle: f64, cos_inner: f64, cos_outer: f64) -> f64 {
    let t = ((cos_angle - cos_outer) / (cos_inner - cos_outer).max(SPOT_COS_SPAN_MIN)).clamp(0.0, 1.0);
    t * t
}

/// KHR_lights_punctual's range window (the extension's recommended form)
/// `clamp(1 − (d/range)⁴, 0, 1)`: the light fades to exactly 0 at `d = range`, with hardly any
/// change near the light. A range of 0 or less is none (1 everywhere).
pub fn window_range(d: f64, range: f64) -> f64 {
    if range <= 0.0 {
        return 1.0;
    }
    let x = (d.max(0.0) / range).min(1.0);
    let x2 = x * x;
    1.0 - x2 * x2
}

/// Direction to a light (unit) and its incident intensity `I_L` per channel at point `p` with
/// normal `n`. A point or spot light closer than `LIGHT_DIST_MIN` touches the surface: `L = N`.
pub fn light_sample(light: &Light, p: DVec3, n: DVec3) -> (DVec3, [f64; 3]) {
    let radiance = light.color.map(|c| c * light.intensity);
    match light.kind {
        LightKind::Point | LightKind::Spot => {
            let to_light = light.position - p;
            let d = to_light.length();
            let l = if d > LIGHT_DIST_MIN { to_light / d } else { n };
            let mut f = match light.falloff_form {
                FalloffForm::Quadratic => falloff_quadratic(d, light.falloff_alpha),
                FalloffForm::Linear => falloff_linear(d, light.d0),
            };
            if let Some(range) = light.range {
                f *= window_range(d, range);
            }
            if light.kind == LightKind::Spot {
                let axis = safe_normalize(light.direction, DVec3::NEG_Y);
                f *= spot_cone((-l).dot(axis), light.inner_cone.cos(), light.outer_cone.cos());
            }
            (l, radiance.map(|r| r * f))
        }
        LightKind::Directional => (safe_normalize(-light.direction, n), radiance),
    }
}

/// Spec §3: what one light adds, `I_L · (r_d·C·max(N·L, 0) + r_s·S)`, zero in own shadow.
#[allow(clippy::too_many_arguments)]
pub fn light_contribution(
    l: DVec3,
    radiance: [f64; 3],
    n: DVec3,
    v: DVec3,
    mat: &Material,
    v_index: [f64; 3],
    specular: SpecularModel,
) -> [f64; 3] {
    let n_dot_l = n.dot(l);
    if n_dot_l <= 0.0 {
        return [0.0; 3];
    }
    let spec = match specular {
        SpecularModel::CookTorrance => specular_cook_torrance(n, v, l, mat.m, v_index),
        SpecularModel::Phong => {
            let r = 2.0 * n_dot_l * n - l;
            let s = if n.dot(v) > 0.0 { specular_phong(v.dot(r), mat.h.value(), mat.h.is_mirror()) } else { 0.0 };
            [s; 3]
        }
    };
    std::array::from_fn(|i| radiance[i] * (mat.r_d * mat.color[i] * diffuse_lambert(n_dot_l) + mat.r_s * spec[i]))
}

/// Spec §3: the Phong illumination model `I_a + Σ I_L (r_d C (N·L) + r_s S)` at world point `p`
/// with (not necessarily unit) normal `n_in`, seen from `eye`; the twin of `shade` in
/// `shaders/shading.wgsl`.
pub fn shade(
    p: DVec3,
    n_in: DVec3,
    eye: DVec3,
    mat: &Material,
    lights: &[Light],
    ambient: [f64; 3],
    specular: SpecularModel,
) -> [f64; 3] {
    let v = safe_normalize(eye - p, DVec3::Y);
    let n = safe_normalize(n_in, v);
    let v_index = mat.mu.map(fresnel_v_from_mu);
    let mut total: [f64; 3] = std::array::from_fn(|i| ambient[i] * mat.r_a * mat.color[i]);
    for light in lights.iter().take(crate::scene::MAX_LIGHTS) {
        let (l, radiance) = light_sample(light, p, n);
        let c = light_contribution(l, radiance, n, v, mat, v_index, specular);
        for i in 0..3 {
            total[i] += c[i];
        }
    }
    total
}
