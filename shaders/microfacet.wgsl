// The microfacet terms of the Cook–Torrance form F·D·G/(N·V) (docs/model.md §5), one function
// each, and the selectors that pick each term by the material's code (Microfacet::code in the f64
// twin, crates/shadelab-model/src/lighting/microfacet.rs). A new D, G or F is one function here,
// one arm in its selector and one code.

// Fields of `object.microfacet`: the distribution D in bits 0–7, the masking G in bits 8–15, the
// Fresnel factor F in bits 16–23.
const MICROFACET_FIELD_BITS: u32 = 8u;
const MICROFACET_FIELD_MASK: u32 = 255u;
// Each term's codes (Distribution::code, Masking::code, Fresnel::code).
const DISTRIBUTION_BECKMANN: u32 = 0u;
const MASKING_COOK_TORRANCE: u32 = 0u;
const FRESNEL_DIELECTRIC: u32 = 0u;
// The chapter's three terms, packed (Microfacet::CHAPTER).
const MICROFACET_CHAPTER: u32 = 0u;

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

// docs/model.md §5, §7: the exact unpolarized Fresnel factor met at cos θ_i = c, v = n_t/n_i from
// either side (below 1 from inside the denser medium; the specular's v from μ is at least 1):
// ½ ((g − c)/(g + c))² {1 + [(c(g + c) − 1)/(c(g − c) + 1)]²}, g = √(v² + c² − 1); 1 under total
// internal reflection. F(c = 1) = μ and F(c = 0) = 1; the chapter's "μ at c = 0" is an erratum.
fn fresnel_dielectric(c_in: f32, v_in: f32) -> f32 {
    let c = clamp(c_in, 0.0, 1.0);
    let v = max(v_in, 0.0);
    // g² = v² − 1 + c², grouped as the twin says: exact at grazing for v = 1 and at c = 1.
    let sin2 = (1.0 - c) * (1.0 + c);
    let g2 = select(v * v - sin2, (v - 1.0) * (v + 1.0) + c * c, c < 0.5);
    if (g2 < 0.0) {
        return 1.0;
    }
    let g = sqrt(g2);
    let a = (g - c) / max(g + c, FRESNEL_G_PLUS_C_MIN);
    // c(g + c) − 1 and c(g − c) + 1 without the cancelling 1s.
    let b = (c * g - sin2) / max(c * g + sin2, FRESNEL_G_PLUS_C_MIN);
    return clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
}

// The material's distribution D (field 0 of `terms`).
fn microfacet_d(terms: u32, n_dot_h: f32, sin2_nh: f32, m: f32) -> f32 {
    switch (terms & MICROFACET_FIELD_MASK) {
        case DISTRIBUTION_BECKMANN, default: {
            return d_beckmann(n_dot_h, sin2_nh, m);
        }
    }
}

// The material's masking G (field 1 of `terms`).
fn microfacet_g(terms: u32, n_dot_h: f32, n_dot_v: f32, n_dot_l: f32, v_dot_h: f32) -> f32 {
    switch ((terms >> MICROFACET_FIELD_BITS) & MICROFACET_FIELD_MASK) {
        case MASKING_COOK_TORRANCE, default: {
            return g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h);
        }
    }
}

// The material's Fresnel factor F (field 2 of `terms`) at c = V·H, per channel of `v_index`.
fn microfacet_f(terms: u32, c: f32, v_index: vec3<f32>) -> vec3<f32> {
    switch ((terms >> (2u * MICROFACET_FIELD_BITS)) & MICROFACET_FIELD_MASK) {
        case FRESNEL_DIELECTRIC, default: {
            return vec3(fresnel_dielectric(c, v_index.x), fresnel_dielectric(c, v_index.y), fresnel_dielectric(c, v_index.z));
        }
    }
}

// docs/model.md §5: the Cook–Torrance form as it enters the sum, π·ρ_s·(N·L) = F·D·G/(N·V), with
// the material's D, G and F; π keeps it on the scale of the chapter's diffuse term r_d·C·(N·L).
fn specular_microfacet(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, m: f32, v_index: vec3<f32>, terms: u32) -> vec3<f32> {
    let n_dot_l = dot(n, l);
    let n_dot_v = dot(n, v);
    let h = safe_normalize(l + v, n);
    let n_dot_h = dot(n, h);
    let v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    let n_x_h = cross(n, h);
    let d = microfacet_d(terms, n_dot_h, dot(n_x_h, n_x_h), m);
    let g = microfacet_g(terms, n_dot_h, n_dot_v, n_dot_l, v_dot_h);
    let k = d * g / max(n_dot_v, N_DOT_V_MIN);
    let lit = n_dot_l > 0.0 && n_dot_v > 0.0;
    return select(vec3(0.0), microfacet_f(terms, v_dot_h, v_index) * k, lit);
}
