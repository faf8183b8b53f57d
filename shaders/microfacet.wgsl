// The microfacet terms of the Cook–Torrance form F·D·G/(N·V) (docs/model.md §5), one function
// each, and the selectors that pick each term by the material's code (Microfacet::code in the f64
// twin, crates/shadelab-model/src/lighting/microfacet.rs). A new D, G or F is one function here,
// one arm in its selector and one code. Each arm is cut from a pipeline whose scene does not use
// its term (the effects EFFECT_D_…, EFFECT_G_…, EFFECT_F_…). m is every term's width: Beckmann's
// m, GGX's and Smith's α.

// Fields of `object.microfacet`: the distribution D in bits 0–7, the masking G in bits 8–15, the
// Fresnel factor F in bits 16–23.
const MICROFACET_FIELD_BITS: u32 = 8u;
const MICROFACET_FIELD_MASK: u32 = 255u;
// Each term's codes (Distribution::code, Masking::code, Fresnel::code).
const DISTRIBUTION_BECKMANN: u32 = 0u;
const DISTRIBUTION_GGX: u32 = 1u;
const DISTRIBUTION_BLINN_PHONG: u32 = 2u;
const MASKING_V_GROOVE: u32 = 0u;
const MASKING_SMITH: u32 = 1u;
const MASKING_SMITH_CORRELATED: u32 = 2u;
const FRESNEL_EXACT: u32 = 0u;
const FRESNEL_SCHLICK: u32 = 1u;
// The multiple-scattering compensation's bit (MICROFACET_MULTIPLE_SCATTERING, multiscatter.wgsl).
const MICROFACET_MULTIPLE_SCATTERING: u32 = 16777216u;
// The Fresnel-weighted diffuse's bit (MICROFACET_FRESNEL_MIX).
const MICROFACET_FRESNEL_MIX: u32 = 33554432u;
// The chapter's three terms, packed (Microfacet::CHAPTER), and glTF's (Microfacet::GLTF).
const MICROFACET_CHAPTER: u32 = 0u;
const MICROFACET_GLTF: u32 = 33620481u;

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

// docs/model.md §5: Trowbridge–Reitz (GGX) in the chapter's scale, π/4 × the normalized D, with
// α = m: α²/(4 ((N·H)² α² + sin²θ_h)²), (N·H)²(α² − 1) + 1 written as Filament writes it to keep
// its precision at the peak. The denominator is at least min(α², 1)²: no guard beyond M_MIN.
fn d_ggx(n_dot_h: f32, sin2_nh: f32, m: f32) -> f32 {
    let c = min(n_dot_h, 1.0);
    let a = max(m, M_MIN);
    let a2 = a * a;
    let k = c * c * a2 + max(sin2_nh, 0.0);
    return select(0.0, a2 / (4.0 * k * k), n_dot_h > 0.0);
}

// docs/microfacet.md: the normalized Blinn–Phong distribution (h + 2)/2π · cos^h θ_h in the
// chapter's scale, (h + 2)/8 · (N·H)^h with h = 2/m² − 2 held at 0 or more: its peak 1/(4m²) is
// Beckmann's and GGX's at the same m. (N·H)^h is exp(h/2 · ln(1 − sin²θ_h)) from `sin2_nh`
// (|N × H|², as Beckmann's): at h = 2·10⁶ a rounded N·H would be off by 10 %.
fn d_blinn_phong(n_dot_h: f32, sin2_nh: f32, m: f32) -> f32 {
    let a = max(m, M_MIN);
    let h = max(2.0 / (a * a) - 2.0, 0.0);
    let d = (h + 2.0) / 8.0 * exp(h / 2.0 * ln_one_minus(clamp(sin2_nh, 0.0, 1.0)));
    return select(0.0, d, n_dot_h > 0.0);
}

// Γ(x + ½)/Γ(x) for x ≥ 1: the recurrence x/(x + ½) · Γ(x + 3/2)/Γ(x + 1) up to x ≥ 5, then the
// asymptotic series √x·(1 − 1/8x + 1/128x² + 5/1024x³ − 21/32768x⁴), within 5e-7 there.
fn gamma_half_ratio(x_in: f32) -> f32 {
    var x = max(x_in, 1.0);
    var r = 1.0;
    for (var i = 0u; i < 4u; i++) {
        if (x < 5.0) {
            r *= x / (x + 0.5);
            x += 1.0;
        }
    }
    let y = 1.0 / x;
    return r * sqrt(x) * (1.0 - y / 8.0 + y * y / 128.0 + 5.0 * y * y * y / 1024.0 - 21.0 * y * y * y * y / 32768.0);
}

// 1 − eˣ for x ≤ 0, by its series −x − x²/2 − x³/6 where |x| < 1e-2: 1 − exp(x) in f32 would keep
// none of its digits there.
fn one_minus_exp(x: f32) -> f32 {
    return select(1.0 - exp(x), -x * (1.0 + x * (0.5 + x / 6.0)), abs(x) < 1e-2);
}

// ln(1 − y) for y in [0, 1), by its series −y − y²/2 − y³/3 − y⁴/4 where y < 1e-2: 1 − y in f32
// would round y away there. (At y = 1, log(0) is discarded by the select and by its caller.)
fn ln_one_minus(y: f32) -> f32 {
    let far = log(max(1.0 - y, PHONG_LOG2_ARG_MIN));
    return select(far, -y * (1.0 + y * (0.5 + y * (1.0 / 3.0 + y / 4.0))), y < 1e-2);
}

// docs/microfacet.md: Smith's Λ of the normalized Blinn–Phong D at N·X = c, h = 2/m² − 2 held at
// 0 or more: Student's t slopes with h + 2 degrees of freedom, Λ = sⁿ⁺¹/(n·B(½, (n + 1)/2)) ·
// ∫₀¹ (1/c − u^(1/n)/√(1 − s²·u^(2/n))) du, n = h + 1, by BLINN_PHONG_LAMBDA_NODES on
// u = 1 − (1 − t)² (generated from the f64 twin's table). c is held at BLINN_PHONG_COS_MIN or more.
fn lambda_blinn_phong(c_in: f32, m: f32) -> f32 {
    let c = clamp(c_in, BLINN_PHONG_COS_MIN, 1.0);
    let a = max(m, M_MIN);
    let h = max(2.0 / (a * a) - 2.0, 0.0);
    let n = h + 1.0;
    var k = 0.0;
    for (var i = 0u; i < 8u; i++) {
        let t = BLINN_PHONG_LAMBDA_NODES[i].x;
        let u = t * (2.0 - t);
        let root = exp(log(u) / n);
        // 1 − s²·u^(2/n) = (1 − u^(2/n)) + c²·u^(2/n), each part kept to its digits.
        let d = one_minus_exp(2.0 * log(u) / n) + c * c * root * root;
        k += BLINN_PHONG_LAMBDA_NODES[i].y * 2.0 * (1.0 - t) * (1.0 / c - root / sqrt(d));
    }
    let s_pow = exp((n + 1.0) / 2.0 * ln_one_minus(c * c));
    // 1/B(½, (n + 1)/2) = Γ((n + 2)/2)/(√π·Γ((n + 1)/2)); 0.5641896 is 1/√π.
    let inv_beta = gamma_half_ratio((h + 2.0) / 2.0) * 0.5641896;
    return select(s_pow * inv_beta / n * k, 0.0, c >= 1.0);
}

// Smith's single-direction masking G1 = 1/(1 + Λ) at N·X = c for the distribution `d`, α = m.
// GGX: 2c/(c + √(α² + (1 − α²)c²)), exact. Beckmann: Walter et al. 2007's rational fit (eq. 27)
// in a = c/(α sin θ), multiplied through by (α sin θ)² so that sin θ = 0 never divides; 1 from
// a = 1.6 up. Blinn–Phong: its own Λ (lambda_blinn_phong), 0 at c = 0.
fn smith_g1(d: u32, c_in: f32, m: f32) -> f32 {
    let c = clamp(c_in, 0.0, 1.0);
    let a = max(m, M_MIN);
    if (d == DISTRIBUTION_GGX) {
        return 2.0 * c / (c + sqrt(a * a + (1.0 - a * a) * c * c));
    }
#if EFFECT_D_BLINN_PHONG
    if (d == DISTRIBUTION_BLINN_PHONG) {
        return select(0.0, 1.0 / (1.0 + lambda_blinn_phong(c, a)), c > 0.0);
    }
#endif
    let t = a * sqrt((1.0 - c) * (1.0 + c));
    // min(…, 1): the fit overshoots 1 by 3e-7 just below a = 1.6.
    let fit = min((3.535 * c * t + 2.181 * c * c) / (t * t + 2.276 * c * t + 2.577 * c * c), 1.0);
    return select(fit, 1.0, c >= 1.6 * t);
}

// docs/model.md §5: Smith's G with masking and shadowing independent, G1(N·V)·G1(N·L).
fn g_smith_separable(d: u32, n_dot_v: f32, n_dot_l: f32, m: f32) -> f32 {
    return smith_g1(d, n_dot_v, m) * smith_g1(d, n_dot_l, m);
}

// docs/model.md §5: Smith's height-correlated G, 1/(1 + Λ(V) + Λ(L)) = G1v·G1l/(G1v + G1l −
// G1v·G1l); the numerator never exceeds the denominator, whose floor SMITH_DENOM_MIN only makes
// 0/0 (both grazing) 0.
fn g_smith_correlated(d: u32, n_dot_v: f32, n_dot_l: f32, m: f32) -> f32 {
    let gv = smith_g1(d, n_dot_v, m);
    let gl = smith_g1(d, n_dot_l, m);
    return gv * gl / max(gv + gl - gv * gl, SMITH_DENOM_MIN);
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

// docs/model.md §5: Schlick's approximation F0 + (1 − F0)(1 − c)⁵ with F0 = ((v − 1)/(v + 1))²,
// the normal-incidence reflectance of index v (μ itself for the specular's v from μ).
fn fresnel_schlick(c_in: f32, v_in: f32) -> f32 {
    let c = clamp(c_in, 0.0, 1.0);
    let v = max(v_in, 0.0);
    let r = (v - 1.0) / (v + 1.0);
    let f0 = r * r;
    let x = 1.0 - c;
    let x2 = x * x;
    return f0 + (1.0 - f0) * x2 * x2 * x;
}

// 1 − fresnel_dielectric(c, v), summed from positive parts to keep its precision where F → 1:
// 1 − F = (1 − a²) + ½a²(1 − b²), 1 − a² = 4gc/(g + c)², 1 − b² = 4cg·sin²θ/(cg + sin²θ)².
fn fresnel_dielectric_complement(c_in: f32, v_in: f32) -> f32 {
    let c = clamp(c_in, 0.0, 1.0);
    let v = max(v_in, 0.0);
    let sin2 = (1.0 - c) * (1.0 + c);
    let g2 = select(v * v - sin2, (v - 1.0) * (v + 1.0) + c * c, c < 0.5);
    if (g2 < 0.0) {
        return 0.0;
    }
    let g = sqrt(g2);
    let gpc = max(g + c, FRESNEL_G_PLUS_C_MIN);
    let a = (g - c) / gpc;
    let den = max(c * g + sin2, FRESNEL_G_PLUS_C_MIN);
    let b = (c * g - sin2) / den;
    // Where a guard holds a denominator (g + c → 0 at v = 1 grazing, cg + sin²θ → 0 at v = 0 and
    // c = 1) the identity does not: there 1 − a² and 1 − b² themselves.
    let one_minus_a2 = select(4.0 * g * c / (gpc * gpc), (1.0 - a) * (1.0 + a), g + c < FRESNEL_G_PLUS_C_MIN);
    let guarded = c * g + sin2 < FRESNEL_G_PLUS_C_MIN;
    let one_minus_b2 = select(4.0 * c * g * sin2 / (den * den), (1.0 - b) * (1.0 + b), guarded);
    return clamp(one_minus_a2 + 0.5 * a * a * one_minus_b2, 0.0, 1.0);
}

// 1 − fresnel_schlick(c, v) as (1 − F0)(1 − (1 − c)⁵), 1 − F0 = 4v/(v + 1)² and
// 1 − x⁵ = c(1 + x + x² + x³ + x⁴), x = 1 − c: no cancellation where F → 1.
fn fresnel_schlick_complement(c_in: f32, v_in: f32) -> f32 {
    let c = clamp(c_in, 0.0, 1.0);
    let v = max(v_in, 0.0);
    let t0 = 4.0 * v / ((v + 1.0) * (v + 1.0));
    let x = 1.0 - c;
    return t0 * c * (1.0 + x * (1.0 + x * (1.0 + x * (1.0 + x))));
}

// The material's 1 − F (field 2 of `terms`) at c = V·H for index v (microfacet_f's complement).
fn microfacet_f_complement(terms: u32, c: f32, v: f32) -> f32 {
    let f = (terms >> (2u * MICROFACET_FIELD_BITS)) & MICROFACET_FIELD_MASK;
#if EFFECT_F_EXACT
    if (f == FRESNEL_EXACT) {
        return fresnel_dielectric_complement(c, v);
    }
#endif
#if EFFECT_F_SCHLICK
    if (f == FRESNEL_SCHLICK) {
        return fresnel_schlick_complement(c, v);
    }
#endif
    return 1.0;
}

// The material's distribution D (field 0 of `terms`); 0 for a D this pipeline does not hold.
fn microfacet_d(terms: u32, n_dot_h: f32, sin2_nh: f32, m: f32) -> f32 {
    let d = terms & MICROFACET_FIELD_MASK;
#if EFFECT_D_BECKMANN
    if (d == DISTRIBUTION_BECKMANN) {
        return d_beckmann(n_dot_h, sin2_nh, m);
    }
#endif
#if EFFECT_D_GGX
    if (d == DISTRIBUTION_GGX) {
        return d_ggx(n_dot_h, sin2_nh, m);
    }
#endif
#if EFFECT_D_BLINN_PHONG
    if (d == DISTRIBUTION_BLINN_PHONG) {
        return d_blinn_phong(n_dot_h, sin2_nh, m);
    }
#endif
    return 0.0;
}

// The material's masking G (field 1 of `terms`); Smith's forms use the Λ of the material's D.
fn microfacet_g(terms: u32, n_dot_h: f32, n_dot_v: f32, n_dot_l: f32, v_dot_h: f32, m: f32) -> f32 {
    let g = (terms >> MICROFACET_FIELD_BITS) & MICROFACET_FIELD_MASK;
    let d = terms & MICROFACET_FIELD_MASK;
#if EFFECT_G_V_GROOVE
    if (g == MASKING_V_GROOVE) {
        return g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h);
    }
#endif
#if EFFECT_G_SMITH
    if (g == MASKING_SMITH) {
        return g_smith_separable(d, n_dot_v, n_dot_l, m);
    }
#endif
#if EFFECT_G_SMITH_CORRELATED
    if (g == MASKING_SMITH_CORRELATED) {
        return g_smith_correlated(d, n_dot_v, n_dot_l, m);
    }
#endif
    return 0.0;
}

// The material's Fresnel factor F (field 2 of `terms`) at c = V·H, per channel of `v_index`.
fn microfacet_f(terms: u32, c: f32, v_index: vec3<f32>) -> vec3<f32> {
    let f = (terms >> (2u * MICROFACET_FIELD_BITS)) & MICROFACET_FIELD_MASK;
#if EFFECT_F_EXACT
    if (f == FRESNEL_EXACT) {
        return vec3(fresnel_dielectric(c, v_index.x), fresnel_dielectric(c, v_index.y), fresnel_dielectric(c, v_index.z));
    }
#endif
#if EFFECT_F_SCHLICK
    if (f == FRESNEL_SCHLICK) {
        return vec3(fresnel_schlick(c, v_index.x), fresnel_schlick(c, v_index.y), fresnel_schlick(c, v_index.z));
    }
#endif
    return vec3(0.0);
}

// docs/model.md §5: the share of a light's diffuse that the dielectric layer above it passes,
// glTF 2.0's fresnel_mix: 1 − w·F(V·H), F being the material's Fresnel term at the layer's F0
// `f0` (through its index, as μ's) and `w` its weight; H the half vector of `l` and `v`.
// Summed as (1 − w) + w·(1 − F) from 1 − F itself, which keeps its precision where F → 1.
fn fresnel_mix_weight(terms: u32, n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, f0: f32, w_in: f32) -> f32 {
    let h = safe_normalize(l + v, n);
    let t = microfacet_f_complement(terms, clamp(dot(v, h), 0.0, 1.0), fresnel_v_from_mu(vec3(f0)).x);
    let w = clamp(w_in, 0.0, 1.0);
    return (1.0 - w) + w * t;
}

// docs/model.md §5: the Cook–Torrance form as it enters the sum, π·ρ_s·(N·L) = F·D·G/(N·V), with
// the material's D, G and F; π keeps it on the scale of the chapter's diffuse term r_d·C·(N·L).
// `ms_e` is the lobe's albedo E for the multiple-scattering compensation (multiscatter.wgsl); 1
// puts nothing back.
fn specular_microfacet(
    n: vec3<f32>,
    v: vec3<f32>,
    l: vec3<f32>,
    m: f32,
    v_index: vec3<f32>,
    terms: u32,
    ms_e: f32,
) -> vec3<f32> {
    let n_dot_l = dot(n, l);
    let n_dot_v = dot(n, v);
    let h = safe_normalize(l + v, n);
    let n_dot_h = dot(n, h);
    let v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    let n_x_h = cross(n, h);
    let d = microfacet_d(terms, n_dot_h, dot(n_x_h, n_x_h), m);
    let g = microfacet_g(terms, n_dot_h, n_dot_v, n_dot_l, v_dot_h, m);
    let k = d * g / max(n_dot_v, N_DOT_V_MIN);
    let lit = n_dot_l > 0.0 && n_dot_v > 0.0;
    var comp = vec3(1.0);
#if EFFECT_MULTIPLE_SCATTERING
    comp = ms_compensation(ms_e, v_index);
#endif
    return select(vec3(0.0), microfacet_f(terms, v_dot_h, v_index) * k * comp, lit);
}
