// The chosen illumination model at one point (docs/model.md §3a) and the material and normal at
// a pixel: the Phong model I = I_a + Σ_lights I_L · (r_d·C·(N·L) + r_s·S), S = Phong or
// Cook–Torrance specular, the Lambert rule or the four-term sum (models.wgsl). The f64 twin of
// `shade` is crates/shadelab-model/src/lighting/shading.rs. The shading modes' stages that call
// these are in entry_points.wgsl, the uniforms in types.wgsl and bindings.wgsl.

// Each pipeline's module holds only the effects its scene calls for: the `#if EFFECT_…` blocks
// (see crates/shadelab-model/src/effects/declared.rs). The "uber" permutation keeps them all and
// leaves the choice to the uniforms (globals.specular_model, r_s, α, …).

const NONFINITE_COLOR: vec3<f32> = vec3(1.0, 0.0, 1.0);

// The illumination model at world point `p` with (not necessarily unit) normal `n_in`; `pixel`
// seeds the shadow filter's per-pixel rotation (read only with cast shadows). The Lambert rule's
// fill and the sum's transmitted term are not shadowed (see the twin's shade_with_visibility).
fn shade(p: vec3<f32>, n_in: vec3<f32>, surface: Surface, pixel: vec2<f32>) -> vec3<f32> {
    let v = safe_normalize(globals.camera_pos.xyz - p * globals.camera_pos.w, vec3(0.0, 1.0, 0.0));
    // A zero normal (e.g. interpolated between opposite vertex normals) faces the viewer.
    let n = safe_normalize(n_in, v);
    let c = surface.c;
    // The Fresnel index and the microfacet terms are Cook–Torrance's only.
    var v_index = vec3(1.0);
    var terms = MICROFACET_CHAPTER;
#if EFFECT_SPECULAR_COOK_TORRANCE
    v_index = fresnel_v_from_mu(surface.mu);
    terms = object.microfacet;
#endif
    // The lobe's albedo for its multiple-scattering compensation, once a point (1: none).
    var ms_e = 1.0;
#if EFFECT_MULTIPLE_SCATTERING
    if (globals.specular_model == SPECULAR_COOK_TORRANCE && (terms & MICROFACET_MULTIPLE_SCATTERING) != 0u) {
        ms_e = ms_albedo(terms, dot(n, v), surface.m);
    }
#endif
    var total = vec3(0.0);
#if EFFECT_AMBIENT
    total += globals.ambient.rgb * surface.r_a * c;
#endif
#if EFFECT_ENVIRONMENT_SH
    // The environment's diffuse light, the chapter's I_a made directional.
    if (globals.illumination != ILLUMINATION_LAMBERT) {
        // The share of it the precomputed grid lets through, where the scene asks for it.
        var open = 1.0;
#if EFFECT_ENVIRONMENT_OCCLUSION
        open = env_occlusion(p, n);
#endif
        total += env_sh_radiance(n) * open * surface.r_a * c;
    }
#endif
#if EFFECT_ENVIRONMENT_SPECULAR
#if EFFECT_SPECULAR_COOK_TORRANCE
    // The environment's specular by the split sum: Cook–Torrance under the Phong model only.
    if (globals.specular_model == SPECULAR_COOK_TORRANCE && globals.illumination == ILLUMINATION_PHONG) {
        total += object.r_s * env_specular(n, v, surface.m, terms, v_index);
    }
#endif
#endif
    // The Lambert rule's I: the brightest light at the point, per channel, in [0, 1] (model_term
    // raises it; without the rule it stays 0, unread).
    var i_max = vec3(0.0);
    let fixed_loop = LOOP_LIGHTS != LOOP_DYNAMIC;
    let light_count = select(min(globals.light_count, MAX_LIGHTS), min(LOOP_LIGHTS, MAX_LIGHTS), fixed_loop);
    for (var i = 0u; i < light_count; i++) {
        var light = globals.lights[i];
        light.kind = select(light.kind, (LOOP_KINDS >> (LOOP_KIND_BITS * i)) & LOOP_KIND_MASK, fixed_loop);
        var base = light_sample(light, p, n, v, surface.m);
#if EFFECT_POINT_LIGHTS
#if EFFECT_AREA_LIGHTS
#if EFFECT_AREA_LTC
        base = area_ltc_sample(base, light, p, n, v, surface.m, terms);
#endif
#endif
#endif
        // An area light drawn as k point sources is k samples, each with its own shadow.
        var samples = 1u;
#if EFFECT_AREA_POINTS
#if EFFECT_POINT_LIGHTS
        samples = area_point_count(light);
#endif
#endif
        for (var j = 0u; j < samples; j++) {
            var s = base;
            // Where the light's shadow is cast from (a directional light's has no position).
            var origin = vec3(0.0);
#if EFFECT_POINT_LIGHTS
            origin = light.position.xyz;
#endif
#if EFFECT_AREA_POINTS
#if EFFECT_POINT_LIGHTS
            if (drawn_as_points(light)) {
                let e = area_emitter(light, j);
                s = area_point_sample(base, light, e, p, n);
                origin = e.position;
            }
#endif
#endif
            // The chosen model's term of this light (or point source), before its shadow.
            let term = model_term(s, j, n, v, surface, v_index, ms_e, terms, total, i_max);
            total = term.total;
            i_max = term.i_max;
            let lit = term.lit;
            // A term that adds nothing here (the point faces away from the light) needs no
            // shadow query: its map lookups are skipped, as the f64 twin skips its shadow ray.
            if (any(lit != vec3(0.0))) {
                var visibility = 1.0;
#if EFFECT_CAST_SHADOWS
                visibility = shadow_visibility(i, light, origin, j, p, n, pixel);
#endif
                total += visibility * lit;
            }
        }
    }
#if EFFECT_LAMBERT_RULE
    if (globals.illumination == ILLUMINATION_LAMBERT) {
        total += lambert_rule_fill(surface.r_a * c, i_max);
    }
#endif
    return total;
}

// One light sample's term under the chosen model, before its shadow, and the running sum and the
// Lambert rule's I as the sample leaves them (WGSL's helpers return what they update).
struct SampleTerm {
    lit: vec3<f32>,
    total: vec3<f32>,
    i_max: vec3<f32>,
}

// The chosen model's term of light sample `s` (point source `j` of its light), before its shadow:
// the Lambert rule raises `i_max` to the sample's I, and the sum adds the light's transmitted term
// (unshadowed, once) to `total`.
fn model_term(
    s: LightSample,
    j: u32,
    n: vec3<f32>,
    v: vec3<f32>,
    surface: Surface,
    v_index: vec3<f32>,
    ms_e: f32,
    terms: u32,
    total: vec3<f32>,
    i_max: vec3<f32>,
) -> SampleTerm {
    let c = surface.c;
    var out = SampleTerm(vec3(0.0), total, i_max);
    var modelled = false;
#if EFFECT_LAMBERT_RULE
    if (globals.illumination == ILLUMINATION_LAMBERT) {
        let li = clamp(s.radiance, vec3(0.0), vec3(1.0));
        out.i_max = max(out.i_max, li);
        out.lit = lambert_rule_lit(object.r_d * c, li, s.form);
        modelled = true;
    }
#endif
#if EFFECT_FOUR_TERM_SUM
    if (!modelled && globals.illumination == ILLUMINATION_SUM) {
#if EFFECT_TRANSMITTED_TERM
        // The transmitted term is the light's, once (not per point source), unshadowed.
        if (j == 0u) {
            out.total += transmitted_term(s.radiance, c, object.transmission);
        }
#endif
        out.lit = sum_contribution(s.radiance, s.form, dot(n, v), c, object.r_d, object.r_s);
        modelled = true;
    }
#endif
    if (!modelled) {
        var normalized = false;
#if EFFECT_PHONG_NORMALIZED
        normalized = object.phong_normalized != 0u;
#endif
        // The dielectric layer that weights the diffuse, for a material with a specular layer.
        var mix = vec2(0.0);
#if EFFECT_SPECULAR_COOK_TORRANCE
#if EFFECT_FRESNEL_MIX
        let asks = (terms & MICROFACET_FRESNEL_MIX) != 0u && object.r_s > 0.0;
        if (globals.specular_model == SPECULAR_COOK_TORRANCE && asks) {
            mix = object.fresnel_mix.xy;
        }
#endif
#endif
        out.lit = light_contribution(
            s, n, v, c, object.r_s, object.r_d, surface.m, surface.h, surface.mirror,
            v_index, globals.specular_model, terms, normalized, ms_e, mix,
        );
    }
    return out;
}

// The object's material untinted: C, μ where Cook–Torrance reads it, m, h and r_a.
fn object_surface() -> Surface {
    var mu = vec3(0.0);
#if EFFECT_SPECULAR_COOK_TORRANCE
    mu = object.mu.rgb;
#endif
    return Surface(object.color.rgb, mu, object.m, object.h, object.mirror != 0u, object.r_a);
}

// The material at a pixel: its metallic–roughness texel's metal and roughness scales, the tint
// of the interpolated vertex colour and base colour texture, and its occlusion texel, where the
// permutation has them and the object's material has the texture.
fn pixel_surface(uv: vec2<f32>, tint: vec3<f32>) -> Surface {
    var s = object_surface();
    var mu_tinted = object.mu_tinted.rgb;
#if EFFECT_METAL_ROUGHNESS_TEXTURE
    if ((object.maps & MAP_METAL_ROUGHNESS) != 0u) {
        let x = metal_roughness_texel(texture_uv(uv, object.metal_roughness_uv.xy, object.uv_rotations.x, object.metal_roughness_uv.zw));
        let k = metallic_scaled(s.c, s.mu, mu_tinted, object.metallic_f0.rgb, x.b);
        s.c = k.c;
        s.mu = k.mu;
        mu_tinted = k.mu_tinted;
        s.m = roughness_scaled(s.m, x.g);
        s.h = phong_h_from_m(s.m);
        s.mirror = s.m <= 0.0;
    }
#endif
    let t = tinted_surface(s.c, s.mu, mu_tinted, pixel_tint(uv, tint));
    s.c = t.c;
    s.mu = t.mu;
#if EFFECT_OCCLUSION_TEXTURE
    if ((object.maps & MAP_OCCLUSION) != 0u) {
        let occ = occlusion_texel(texture_uv(uv, object.occlusion_uv.xy, object.uv_rotations.y, object.occlusion_uv.zw));
        s.r_a = occluded(s.r_a, occ, object.occlusion_strength);
    }
#endif
    return s;
}

// The shading normal at a pixel: the interpolated normal, turned by the normal texture in the
// interpolated tangent frame where the material has one.
fn pixel_normal(uv: vec2<f32>, n: vec3<f32>, tangent: vec4<f32>) -> vec3<f32> {
    var out = n;
#if EFFECT_NORMAL_TEXTURE
    if ((object.maps & MAP_NORMAL) != 0u) {
        let texel = normal_texel(texture_uv(uv, object.normal_uv.xy, object.uv_rotations.w, object.normal_uv.zw));
        out = normal_mapped(safe_normalize(n, vec3(0.0, 1.0, 0.0)), tangent, texel, object.normal_scale);
    }
#endif
    return out;
}

// The tint t of C at a pixel: the interpolated vertex colour times the base colour texture.
fn pixel_tint(uv: vec2<f32>, tint: vec3<f32>) -> vec3<f32> {
    var t = vec3(1.0);
#if EFFECT_VERTEX_COLORS
    t *= vertex_tint(tint);
#endif
#if EFFECT_BASE_COLOR_TEXTURE
    t *= base_color_texel(texture_uv(uv, object.uv_offset_scale.xy, object.uv_rotation, object.uv_offset_scale.zw));
#endif
    return t;
}

// The light a pixel emits: I_e, times the emissive texture where the material has one; added to
// the model's I in every mode (it is not lit, so the per-vertex modes add it per pixel exactly).
fn pixel_emission(uv: vec2<f32>) -> vec3<f32> {
    var e = vec3(0.0);
#if EFFECT_EMISSION
    var texel = vec3(1.0);
#if EFFECT_EMISSIVE_TEXTURE
    if ((object.maps & MAP_EMISSIVE) != 0u) {
        texel = emissive_texel(texture_uv(uv, object.emissive_uv.xy, object.uv_rotations.z, object.emissive_uv.zw));
    }
#endif
    e = emitted(object.emission.rgb, texel);
#endif
    return e;
}

// Whether the per-vertex modes split their colours: with a texture or vertex colours C is tinted
// per pixel, and since every model is affine in C (I = C ⊙ A + B), the lighting pass writes the
// part C scales, C ⊙ A, and B, and the fragment stage draws t ⊙ (C ⊙ A) + B. (μ keeps its
// untinted value there: its tint is drawn in Phong shading only.)
fn lit_split() -> bool {
    var split = false;
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    split = true;
#endif
    return split;
}

// The lighting pass's colours of point `i`: the model, or with lit_split() C ⊙ A at 2i and B at
// 2i + 1.
fn write_lit(i: u32, p: vec3<f32>, n: vec3<f32>, seed: vec2<f32>) {
    let s = object_surface();
    if (lit_split()) {
        var dark = s;
        dark.c = vec3(0.0);
        let b = shade(p, n, dark, seed);
        lit_colors_out[2u * i] = vec4(shade(p, n, s, seed) - b, 1.0);
        lit_colors_out[2u * i + 1u] = vec4(b, 1.0);
    } else {
        lit_colors_out[i] = vec4(shade(p, n, s, seed), 1.0);
    }
}

// Points the lighting pass's chunk holds.
fn lit_count() -> u32 {
    return arrayLength(&lit_colors_out) / select(1u, 2u, lit_split());
}

// Point `i`'s colours for the vertex stage: (the model or C ⊙ A, B or 0).
fn read_lit(i: u32) -> array<vec3<f32>, 2> {
    if (lit_split()) {
        return array(lit_colors[2u * i].rgb, lit_colors[2u * i + 1u].rgb);
    }
    return array(lit_colors[i].rgb, vec3(0.0));
}

fn finish(color: vec3<f32>) -> vec4<f32> {
    if ((globals.flags & FLAG_DEBUG_NONFINITE) != 0u && any_nonfinite(color)) {
        return vec4(NONFINITE_COLOR, 1.0);
    }
    return vec4(color, 1.0);
}

fn to_world(p: vec3<f32>) -> vec3<f32> {
    return (object.model * vec4(p, 1.0)).xyz;
}

fn normal_to_world(n: vec3<f32>) -> vec3<f32> {
    return mat3x3(object.normal_matrix[0].xyz, object.normal_matrix[1].xyz, object.normal_matrix[2].xyz) * n;
}

// The vertex stages' stand-in for a pixel position (they have none): the world position scaled to
// vary from vertex to vertex.
fn vertex_seed(p: vec3<f32>) -> vec2<f32> {
    return (p.xz + p.yy) * 1024.0;
}

#if EFFECT_AREA_LIGHTS
#if EFFECT_AREA_LTC
// Light sample `s` of `light` with its specular by LTC (ltc.wgsl), where the light asks for it
// and is drawn in its exact area form; M⁻¹ and the lobe's albedo E are the material's D's and
// D × G pair's at N·V and m.
fn area_ltc_sample(s_in: LightSample, light: Light, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, m: f32, terms: u32) -> LightSample {
    var s = s_in;
    if (light.kind >= LIGHT_RECT && light.area_specular == AREA_SPECULAR_LTC && !drawn_as_points(light)) {
        let n_dot_v = dot(n, v);
        let minv = ltc_matrix(terms & MICROFACET_FIELD_MASK, n_dot_v, m);
        s.ltc = area_specular_ltc(light, p, n, v, minv, ms_albedo(terms, max(n_dot_v, N_DOT_V_MIN), m));
    }
    return s;
}
#endif
#endif
