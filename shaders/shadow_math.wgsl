// The shadow projection math (docs/model.md §6), without bindings, so the stability sweep runs it
// as the renderer does: the cube face, the map coordinate, the texel sizes behind the normal
// offset. f64 twins in crates/shadelab-model/src/shadows.rs and shadows/cascades.rs, with the
// constants' reasons (shadows::WGSL_TWINS). Only in permutations with EFFECT_CAST_SHADOWS.

#if EFFECT_CAST_SHADOWS
const SHADOW_NORMAL_OFFSET_TEXELS: f32 = 1.5;
const SHADOW_CLIP_W_MIN: f32 = 1e-20;

// The cube face that sees direction `d` from a point light: its largest axis, ties to x then y;
// 0 +x, 1 −x, 2 +y, 3 −y, 4 +z, 5 −z.
fn shadow_face(d: vec3<f32>) -> u32 {
    let a = abs(d);
    if (a.x >= a.y && a.x >= a.z) {
        return select(1u, 0u, d.x >= 0.0);
    }
    if (a.y >= a.z) {
        return select(3u, 2u, d.y >= 0.0);
    }
    return select(5u, 4u, d.z >= 0.0);
}

// (u, v, depth) of world point `p` in the map of view-projection `m`: u, v in [0, 1], v down.
// A point at a perspective map's eye or behind it (w < SHADOW_CLIP_W_MIN) is outside the map.
fn shadow_map_coord(m: mat4x4<f32>, p: vec3<f32>) -> vec3<f32> {
    let c = m * vec4(p, 1.0);
    if (c.w < SHADOW_CLIP_W_MIN) {
        return vec3(-1.0);
    }
    let ndc = c.xyz / c.w;
    return vec3(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5, ndc.z);
}

// World size of one texel at distance `dist` along the map's view axis.
fn shadow_texel_world(texel_world: f32, perspective: bool, dist: f32) -> f32 {
    return select(texel_world, texel_world * max(dist, 0.0), perspective);
}

#if EFFECT_SHADOW_CASCADES
// The world size of one texel of orthographic map `m`, `resolution` texels across: the map spans
// 2 / |first row| in world units.
fn shadow_ortho_texel_world(m: mat4x4<f32>, resolution: f32) -> f32 {
    return 2.0 / (length(vec3(m[0].x, m[1].x, m[2].x)) * resolution);
}
#endif
#endif
