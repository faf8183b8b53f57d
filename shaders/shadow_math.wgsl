// The shadow projection math (docs/model.md §6), without bindings, so the stability sweep runs it
// as the renderer does: the cube face, the map coordinate, the texel sizes behind the normal
// offset. f64 twins in crates/shadelab-model/src/shadows.rs and shadows/cascades.rs, with the
// constants' reasons (shadows::WGSL_TWINS). Only in permutations with EFFECT_CAST_SHADOWS.

#if EFFECT_CAST_SHADOWS
const SHADOW_NORMAL_OFFSET_TEXELS: f32 = 1.5;
const SHADOW_CLIP_W_MIN: f32 = 1e-20;
const SHADOW_RECEIVER_SLOPE_MAX: f32 = 10.0;

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

#if EFFECT_SHADOW_PCSS
// PCSS's math (docs/area-lights.md), twins in crates/shadelab-model/src/shadows.rs.
// The distance along a perspective map's axis of stored depth `depth` (linear depth).
fn shadow_linear_depth(depth: f32, near: f32, far: f32) -> f32 {
    return far * near / max(far - clamp(depth, 0.0, 1.0) * (far - near), near);
}

// The stored depth of a point at linear depth `z` along a perspective map's axis.
// A map without depth range (far ≤ near) or with its eye at depth 0 stores 0 everywhere.
fn shadow_stored_depth(z: f32, near: f32, far: f32) -> f32 {
    let zc = max(z, near);
    if (far <= near || zc <= 0.0) {
        return 0.0;
    }
    return far * (zc - near) / ((far - near) * zc);
}

// The receiver plane's depth change per unit of distance across the light's view, tan θ for the
// cosine `n_dot_l` between its normal and the light, at most SHADOW_RECEIVER_SLOPE_MAX.
fn receiver_slope(n_dot_l: f32) -> f32 {
    let c = clamp(n_dot_l, 0.0, 1.0);
    return min(sqrt(1.0 - c * c) / max(c, 1.0 / SHADOW_RECEIVER_SLOPE_MAX), SHADOW_RECEIVER_SLOPE_MAX);
}

// The blocker search radius in map tangent units: the cone from the receiver at `d_receiver` to
// a light of size `w_light` where it crosses the nearest blocker depth `near`.
fn pcss_search_radius(w_light: f32, d_receiver: f32, near_in: f32) -> f32 {
    let near = max(near_in, BLOCKER_DIST_MIN);
    return max(0.5 * abs(w_light) * (1.0 / near - 1.0 / max(d_receiver, near)), 0.0);
}

// The penumbra's width by similar triangles, w_light·(d_r − d_b)/d_b.
fn penumbra_width(w_light: f32, d_receiver: f32, d_blocker: f32) -> f32 {
    let d_b = max(d_blocker, BLOCKER_DIST_MIN);
    return max(abs(w_light) * (d_receiver - d_b) / d_b, 0.0);
}
#endif

#if EFFECT_SHADOW_CASCADES
// The world size of one texel of orthographic map `m`, `resolution` texels across: the map spans
// 2 / |first row| in world units.
fn shadow_ortho_texel_world(m: mat4x4<f32>, resolution: f32) -> f32 {
    return 2.0 / (length(vec3(m[0].x, m[1].x, m[2].x)) * resolution);
}
#endif
#endif
