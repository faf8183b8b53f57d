// A surface's colour C and reflectance μ at a point (docs/textures.md): the material's, tinted by
// the vertex colour and the base colour texture. The f64 twins are in
// crates/shadelab-model/src/scene/material.rs and scene/texture.rs.

struct Surface {
    c: vec3<f32>,
    mu: vec3<f32>,
}

// C·t and μ + μ_t·(t − 1), μ clamped to [0, 1]: glTF's base colour scales the diffuse colour and
// a metal's F0 alike (μ_t is the part of μ the base colour sets). Evaluated as (μ − μ_t) + μ_t·t,
// which is exact for a metal (μ = μ_t) at any t, where the printed form cancels to f32 noise.
fn tinted_surface(c: vec3<f32>, mu: vec3<f32>, mu_tinted: vec3<f32>, t: vec3<f32>) -> Surface {
    return Surface(c * t, clamp((mu - mu_tinted) + mu_tinted * t, vec3(0.0), vec3(1.0)));
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

#if EFFECT_BASE_COLOR_TEXTURE
// The object's base colour texture (an sRGB format: decoded per texel, then filtered) and its
// sampler, beside the object's uniforms.
@group(1) @binding(1) var base_color_tex: texture_2d<f32>;
@group(1) @binding(2) var base_color_sampler: sampler;

// A texture coordinate that is not finite samples here.
const NONFINITE_UV: f32 = 0.0;

// KHR_texture_transform: offset + R(rotation)·(scale ⊙ uv), R turning +u towards −v.
fn texture_uv(uv: vec2<f32>, offset: vec2<f32>, rotation: f32, scale: vec2<f32>) -> vec2<f32> {
    let s = sin(rotation);
    let c = cos(rotation);
    let p = uv * scale;
    return vec2(c * p.x + s * p.y, -s * p.x + c * p.y) + offset;
}

// The texture's linear RGB at `uv`, level 0.
fn base_color_texel(uv: vec2<f32>) -> vec3<f32> {
    var safe = uv;
    for (var i = 0; i < 2; i++) {
        if (is_nonfinite(uv[i])) {
            safe[i] = NONFINITE_UV;
        }
    }
    return textureSampleLevel(base_color_tex, base_color_sampler, safe, 0.0).rgb;
}
#endif
