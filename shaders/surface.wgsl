// A surface's colour C and reflectance μ at a point (docs/textures.md): the material's, tinted by
// the vertex colour and the base colour texture. The f64 twins are in
// crates/shadelab-model/src/scene/material.rs and scene/texture.rs.

// A point's material as `shade` reads it.
struct Surface {
    c: vec3<f32>,
    mu: vec3<f32>,
    m: f32,
    h: f32,
    // The Phong "mirror" setting (h = ∞).
    mirror: bool,
    r_a: f32,
}

struct ColorAndMu {
    c: vec3<f32>,
    mu: vec3<f32>,
}

// C·t and μ + μ_t·(t − 1), μ clamped to [0, 1]: glTF's base colour scales the diffuse colour and
// a metal's F0 alike (μ_t is the part of μ the base colour sets). Evaluated as (μ − μ_t) + μ_t·t,
// which is exact for a metal (μ = μ_t) at any t, where the printed form cancels to f32 noise.
fn tinted_surface(c: vec3<f32>, mu: vec3<f32>, mu_tinted: vec3<f32>, t: vec3<f32>) -> ColorAndMu {
    return ColorAndMu(c * t, clamp((mu - mu_tinted) + mu_tinted * t, vec3(0.0), vec3(1.0)));
}

// Bits of Object.maps: the material has that slot's texture.
const MAP_METAL_ROUGHNESS: u32 = 2u;
const MAP_OCCLUSION: u32 = 4u;
const MAP_EMISSIVE: u32 = 8u;
const MAP_NORMAL: u32 = 16u;

struct Metallic {
    c: vec3<f32>,
    mu: vec3<f32>,
    mu_tinted: vec3<f32>,
}

// The material's C, μ and μ_t at a metallic–roughness texel whose metal scale is b (glTF's
// metallic becomes M·b): C + μ_t·(1 − b), μ + (M·F0 − μ_t)·(1 − b), μ_t·b. b = 1 changes
// nothing; b = 0 is the dielectric of the same base colour.
fn metallic_scaled(c: vec3<f32>, mu: vec3<f32>, mu_tinted: vec3<f32>, metallic_f0: vec3<f32>, b_in: f32) -> Metallic {
    let b = select(clamp(b_in, 0.0, 1.0), 1.0, is_nonfinite(b_in));
    let k = 1.0 - b;
    return Metallic(c + mu_tinted * k, mu + (metallic_f0 - mu_tinted) * k, mu_tinted * b);
}

// Roughness at a texel whose roughness scale is g: glTF's roughness r·g, so m = r²·g², in [0, 1].
fn roughness_scaled(m: f32, g_in: f32) -> f32 {
    let g = select(clamp(g_in, 0.0, 1.0), 1.0, is_nonfinite(g_in));
    return clamp(m * g * g, 0.0, 1.0);
}

// The Phong exponent a roughness implies, 2/m² − 2 in [1, H_MAX]; m = 0 (the mirror) gives H_MAX.
fn phong_h_from_m(m: f32) -> f32 {
    if (m <= 0.0) {
        return H_MAX;
    }
    return clamp(2.0 / (m * m) - 2.0, 1.0, H_MAX);
}

// glTF's occlusion: r_a·(1 + strength·(occ − 1)), occ and strength in [0, 1].
fn occluded(r_a: f32, occ_in: f32, strength_in: f32) -> f32 {
    let occ = select(clamp(occ_in, 0.0, 1.0), 1.0, is_nonfinite(occ_in));
    let strength = select(clamp(strength_in, 0.0, 1.0), 1.0, is_nonfinite(strength_in));
    return r_a * (1.0 + strength * (occ - 1.0));
}

// glTF's normal texture: the texel 2·x − 1 in the frame (T, B = w·N×T, N), x and y scaled by
// `scale`, T made perpendicular to N first. A tangent that frames nothing (zero, non-finite,
// along N) leaves N; a non-finite texel channel reads as the flat (½, ½, 1).
fn normal_mapped(n: vec3<f32>, tangent: vec4<f32>, texel: vec3<f32>, scale_in: f32) -> vec3<f32> {
    let g = tangent.xyz - n * dot(n, tangent.xyz);
    // NaN fails the comparison too.
    if (!(dot(g, g) > NORMALIZE_MIN_LEN2)) {
        return n;
    }
    let t = normalize(g);
    let b = cross(n, t) * select(1.0, -1.0, tangent.w < 0.0);
    var x = clamp(texel, vec3(0.0), vec3(1.0));
    let flat_texel = vec3(0.5, 0.5, 1.0);
    for (var i = 0; i < 3; i++) {
        if (is_nonfinite(texel[i])) {
            x[i] = flat_texel[i];
        }
    }
    let scale = select(scale_in, 1.0, is_nonfinite(scale_in));
    let m = t * ((2.0 * x.x - 1.0) * scale) + b * ((2.0 * x.y - 1.0) * scale) + n * (2.0 * x.z - 1.0);
    return safe_normalize(m, n);
}

// Emission I_e scaled by an emissive texel's linear colour, in [0, 1] per channel.
fn emitted(e: vec3<f32>, texel: vec3<f32>) -> vec3<f32> {
    var t = clamp(texel, vec3(0.0), vec3(1.0));
    for (var i = 0; i < 3; i++) {
        if (is_nonfinite(texel[i])) {
            t[i] = 1.0;
        }
    }
    return e * t;
}

#if EFFECT_VERTEX_COLORS
// A vertex colour as a tint: clamped to [0, 1], a non-finite channel white (the loader's rule).
fn vertex_tint(color: vec3<f32>) -> vec3<f32> {
    var out = clamp(color, vec3(0.0), vec3(1.0));
    for (var i = 0; i < 3; i++) {
        if (is_nonfinite(color[i])) {
            out[i] = 1.0;
        }
    }
    return out;
}
#endif

#if TEXTURE_COORDS
// A texture coordinate that is not finite samples here.
const NONFINITE_UV: f32 = 0.0;

// KHR_texture_transform: offset + R(rotation)·(scale ⊙ uv), R turning +u towards −v.
fn texture_uv(uv: vec2<f32>, offset: vec2<f32>, rotation: f32, scale: vec2<f32>) -> vec2<f32> {
    let s = sin(rotation);
    let c = cos(rotation);
    let p = uv * scale;
    return vec2(c * p.x + s * p.y, -s * p.x + c * p.y) + offset;
}

// A texture at `uv` with the pixel's implicit derivatives (its sampler's filters and mipmap
// levels: the reference's Texture::sample_footprint), a non-finite coordinate read at NONFINITE_UV.
fn sample_slot(t: texture_2d<f32>, s: sampler, uv: vec2<f32>) -> vec4<f32> {
    var safe = uv;
    for (var i = 0; i < 2; i++) {
        if (is_nonfinite(uv[i])) {
            safe[i] = NONFINITE_UV;
        }
    }
    return textureSample(t, s, safe);
}
#endif

// The material's textures, each beside the object's uniforms with its sampler: colour slots
// through an sRGB view (decoded per texel, then filtered), data slots as stored.
#if EFFECT_BASE_COLOR_TEXTURE
@group(1) @binding(1) var base_color_tex: texture_2d<f32>;
@group(1) @binding(2) var base_color_sampler: sampler;

// The base colour texture's linear RGB at `uv`.
fn base_color_texel(uv: vec2<f32>) -> vec3<f32> {
    return sample_slot(base_color_tex, base_color_sampler, uv).rgb;
}
#endif

#if EFFECT_METAL_ROUGHNESS_TEXTURE
@group(1) @binding(3) var metal_roughness_tex: texture_2d<f32>;
@group(1) @binding(4) var metal_roughness_sampler: sampler;

// The metallic–roughness texel at `uv`: green scales roughness, blue metallic.
fn metal_roughness_texel(uv: vec2<f32>) -> vec3<f32> {
    return sample_slot(metal_roughness_tex, metal_roughness_sampler, uv).rgb;
}
#endif

#if EFFECT_OCCLUSION_TEXTURE
@group(1) @binding(5) var occlusion_tex: texture_2d<f32>;
@group(1) @binding(6) var occlusion_sampler: sampler;

// The occlusion texel (red) at `uv`.
fn occlusion_texel(uv: vec2<f32>) -> f32 {
    return sample_slot(occlusion_tex, occlusion_sampler, uv).r;
}
#endif

#if EFFECT_NORMAL_TEXTURE
@group(1) @binding(9) var normal_tex: texture_2d<f32>;
@group(1) @binding(10) var normal_sampler: sampler;

// The normal texture's texel at `uv`, as stored.
fn normal_texel(uv: vec2<f32>) -> vec3<f32> {
    return sample_slot(normal_tex, normal_sampler, uv).rgb;
}
#endif

#if EFFECT_EMISSIVE_TEXTURE
@group(1) @binding(7) var emissive_tex: texture_2d<f32>;
@group(1) @binding(8) var emissive_sampler: sampler;

// The emissive texture's linear RGB at `uv`.
fn emissive_texel(uv: vec2<f32>) -> vec3<f32> {
    return sample_slot(emissive_tex, emissive_sampler, uv).rgb;
}
#endif
