// The terms of the chapter's illumination model, one function each, and the specular models;
// named as in the f64 twin, crates/shadelab-model/src/lighting/brdf.rs. Sections (§n) are those
// of docs/model.md.

// Codes Rust writes into `globals.specular_model` (SpecularModel::code in
// crates/shadelab-model/src/lighting/brdf.rs), held equal by the test `wgsl_codes_equal_rust_codes`.
const SPECULAR_PHONG: u32 = 0u;
const SPECULAR_COOK_TORRANCE: u32 = 1u;

// docs/model.md §1, §3: Lambert's cosine with the oriented angle; N·L ≤ 0 is the face's own shadow.
fn diffuse_lambert(n_dot_l: f32) -> f32 {
    return max(n_dot_l, 0.0);
}

// docs/model.md §1: the Lambert rule I' = R·I·cos α + R·(1 − I); the chapter's garbled R(I − I) is read as
// the ambient fill R(1 − I) (erratum, docs/model.md §1).
fn lambert_rule(r_in: f32, i_in: f32, cos_alpha: f32) -> f32 {
    let r = clamp(r_in, 0.0, 1.0);
    let i = clamp(i_in, 0.0, 1.0);
    return r * i * diffuse_lambert(cos_alpha) + r * (1.0 - i);
}

// docs/model.md §3: Phong specular (V·R)^h, evaluated as exp2(h·log2(V·R)) with the argument of
// log2 at least PHONG_LOG2_ARG_MIN; `mirror` is h = ∞ (guard MIRROR_V_DOT_R_MIN), otherwise h is
// clamped to [1, H_MAX].
fn specular_phong(v_dot_r: f32, h_in: f32, mirror: bool) -> f32 {
    let x = clamp(v_dot_r, 0.0, 1.0);
    if (mirror) {
        return select(0.0, 1.0, x >= MIRROR_V_DOT_R_MIN);
    }
    let h = clamp(h_in, 1.0, H_MAX);
    return select(0.0, exp2(h * log2(max(x, PHONG_LOG2_ARG_MIN))), x > 0.0);
}

// docs/model.md §5: Beckmann facet distribution in the chapter's form
// D = 1/(4 m² (N·H)⁴) · exp((1 − 1/(N·H)²)/m²), which is π/4 × the normalized Beckmann D.
// `sin2_nh` = 1 − (N·H)², passed in because computed as |N × H|² it keeps its precision at the
// peak (Filament computes GGX's 1 − (N·H)² the same way): with m = M_MIN the peak spans only
// ~8 f32 ulps of N·H, and 1 − 1/(N·H)² from a rounded N·H would be off by 10 %.
fn d_beckmann(n_dot_h: f32, sin2_nh: f32, m_in: f32) -> f32 {
    let c = clamp(n_dot_h, N_DOT_H_MIN, 1.0);
    let m = max(m_in, M_MIN);
    let m2 = m * m;
    let c2 = c * c;
    // 1 − 1/c² = −sin²/c²
    let d = (1.0 / (4.0 * m2 * c2 * c2)) * exp(-max(sin2_nh, 0.0) / (c2 * m2));
    return select(0.0, d, n_dot_h > 0.0);
}

// docs/model.md §5: geometric attenuation G = min{1, 2(N·H)(N·V)/(V·H), 2(N·H)(N·L)/(V·H)}, written so
// that a zero V·H never divides (guard G_V_DOT_H_MIN).
fn g_cook_torrance(n_dot_h: f32, n_dot_v: f32, n_dot_l: f32, v_dot_h: f32) -> f32 {
    let nh = max(n_dot_h, 0.0);
    let vh = max(v_dot_h, 0.0);
    let num = min(2.0 * nh * max(n_dot_v, 0.0), 2.0 * nh * max(n_dot_l, 0.0));
    return select(num / max(vh, G_V_DOT_H_MIN), 1.0, num >= vh);
}

// docs/model.md §5: refractive index from the normal-incidence reflectance, v = (1 + √μ)/(1 − √μ), with
// √μ capped at FRESNEL_SQRT_MU_MAX; per colour channel.
fn fresnel_v_from_mu(mu: vec3<f32>) -> vec3<f32> {
    let s = min(sqrt(clamp(mu, vec3(0.0), vec3(1.0))), vec3(FRESNEL_SQRT_MU_MAX));
    return (1.0 + s) / (1.0 - s);
}

// docs/model.md §5: the exact unpolarized Fresnel factor, c = L·H, g = √(v² + c² − 1).
// F(c = 1) = μ and F(c = 0) = 1; the chapter's "μ at c = 0" is an erratum.
fn f_fresnel_exact(c_in: f32, v_in: vec3<f32>) -> vec3<f32> {
    let c = clamp(c_in, 0.0, 1.0);
    let v = max(v_in, vec3(1.0));
    // g² = (v − 1)(v + 1) + c²: exact for v = 1 (μ = 0), where v² + c² − 1 cancels in f32.
    let g = sqrt(max((v - 1.0) * (v + 1.0) + c * c, vec3(0.0)));
    let a = (g - c) / max(g + c, vec3(FRESNEL_G_PLUS_C_MIN));
    // c(g − c) + 1 ≥ 1 − c² + c·g > 0 for v ≥ 1, so this division is safe.
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

// docs/model.md §5: the Cook–Torrance term as it enters the sum, π·ρ_s·(N·L) = F·D·G/(N·V) with the
// seed's D; π keeps it on the scale of the chapter's diffuse term r_d·C·(N·L).
fn specular_cook_torrance(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, m: f32, v_index: vec3<f32>) -> vec3<f32> {
    let n_dot_l = dot(n, l);
    let n_dot_v = dot(n, v);
    let h = safe_normalize(l + v, n);
    let n_dot_h = dot(n, h);
    let v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    let n_x_h = cross(n, h);
    let d = d_beckmann(n_dot_h, dot(n_x_h, n_x_h), m);
    let g = g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h);
    let k = d * g / max(n_dot_v, N_DOT_V_MIN);
    let lit = n_dot_l > 0.0 && n_dot_v > 0.0;
    return select(vec3(0.0), f_fresnel_exact(v_dot_h, v_index) * k, lit);
}

// What one light adds to the Phong illumination model (docs/model.md §3) at a point with unit
// normal `n` and unit view vector `v`, for the light's sample `s` (light_sample in lights.wgsl):
// I_L · (r_d·C·max(form, 0) + r_s·S(L)·spec_scale), form being N·L for a point light; the
// specular is zero where N·L ≤ 0 (the point's own shadow).
// `specular_model` is SPECULAR_PHONG or SPECULAR_COOK_TORRANCE; `v_index` is per channel.
fn light_contribution(
    s: LightSample,
    n: vec3<f32>,
    v: vec3<f32>,
    color: vec3<f32>,
    r_s: f32,
    r_d: f32,
    m: f32,
    h: f32,
    mirror: bool,
    v_index: vec3<f32>,
    specular_model: u32,
) -> vec3<f32> {
    let n_dot_l = dot(n, s.l);
    let l = s.l;
    var spec = vec3(0.0);
#if EFFECT_SPECULAR_COOK_TORRANCE
    if (specular_model == SPECULAR_COOK_TORRANCE) {
        spec += r_s * specular_cook_torrance(n, v, l, m, v_index);
    }
#endif
#if EFFECT_SPECULAR_PHONG
    if (specular_model == SPECULAR_PHONG) {
        let r = 2.0 * n_dot_l * n - l;
        spec += r_s * vec3(select(0.0, specular_phong(dot(v, r), h, mirror), dot(n, v) > 0.0));
    }
#endif
    var lit = select(vec3(0.0), spec * s.spec_scale, n_dot_l > 0.0);
#if EFFECT_DIFFUSE
    lit += r_d * color * diffuse_lambert(s.form);
#endif
    return s.radiance * lit;
}
