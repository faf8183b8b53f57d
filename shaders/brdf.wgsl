// The terms of the chapter's illumination model, one function each, and the specular models
// (the microfacet terms of Cook–Torrance are microfacet.wgsl's);
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

// docs/model.md §3: the factor (h + 1)/2 that makes Phong's lobe reflect all it receives at
// normal view ((1/π) ∫ (V·R)^h dω = 2/(h + 1)); 1 for the mirror setting; h clamped as the term
// clamps it.
fn phong_normalization(h: f32, mirror: bool) -> f32 {
    return select((clamp(h, 1.0, H_MAX) + 1.0) / 2.0, 1.0, mirror);
}

// docs/model.md §5: the Cook–Torrance term with the chapter's three terms (microfacet.wgsl).
fn specular_cook_torrance(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, m: f32, v_index: vec3<f32>) -> vec3<f32> {
    return specular_microfacet(n, v, l, m, v_index, MICROFACET_CHAPTER, 1.0);
}

// What one light adds to the Phong illumination model (docs/model.md §3) at a point with unit
// normal `n` and unit view vector `v`, for the light's sample `s` (light_sample in lights.wgsl):
// I_L · (r_d·C·max(form, 0) + r_s·S(L)·spec_scale), form being N·L for a point light; the
// specular is zero where N·L ≤ 0 (the point's own shadow).
// `specular_model` is SPECULAR_PHONG or SPECULAR_COOK_TORRANCE; `v_index` is per channel;
// `terms` the material's microfacet terms (Microfacet::code); `phong_normalized` scales Phong's
// lobe by phong_normalization; `ms_e` is the lobe's albedo for its compensation (1: none);
// `mix` the dielectric layer (F0, weight) that weights the diffuse (weight 0: none).
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
    terms: u32,
    phong_normalized: bool,
    ms_e: f32,
    mix: vec2<f32>,
) -> vec3<f32> {
    let n_dot_l = dot(n, s.l);
    let l = s.l;
    var spec = vec3(0.0);
#if EFFECT_SPECULAR_COOK_TORRANCE
    if (specular_model == SPECULAR_COOK_TORRANCE) {
        spec += r_s * specular_microfacet(n, v, l, m, v_index, terms, ms_e);
    }
#endif
#if EFFECT_SPECULAR_PHONG
    if (specular_model == SPECULAR_PHONG) {
        let r = 2.0 * n_dot_l * n - l;
        var k = 1.0;
#if EFFECT_PHONG_NORMALIZED
        k = select(1.0, phong_normalization(h, mirror), phong_normalized);
#endif
        spec += r_s * k * vec3(select(0.0, specular_phong(dot(v, r), h, mirror), dot(n, v) > 0.0));
    }
#endif
    var lit = select(vec3(0.0), spec * s.spec_scale, n_dot_l > 0.0);
#if EFFECT_AREA_LIGHTS
#if EFFECT_AREA_LTC
#if EFFECT_SPECULAR_COOK_TORRANCE
    // An area light's LTC replaces the lobe at its representative point under Cook–Torrance.
    if (s.ltc >= 0.0 && specular_model == SPECULAR_COOK_TORRANCE) {
        lit = r_s * specular_ltc(n, v, l, v_index, terms, ms_e, s.ltc);
    }
#endif
#endif
#endif
#if EFFECT_DIFFUSE
    var kd = 1.0;
#if EFFECT_SPECULAR_COOK_TORRANCE
#if EFFECT_FRESNEL_MIX
    kd = select(1.0, fresnel_mix_weight(terms, n, v, l, mix.x, mix.y), mix.y > 0.0);
#endif
#endif
    lit += r_d * color * kd * diffuse_lambert(s.form);
#endif
    return s.radiance * lit;
}
