// Shared constants and helpers of the shadelab lighting model; the f64 twin is
// crates/shadelab-model/src/lighting/common.rs.
//
// The guards below are twins of crates/shadelab-model/src/guards.rs, where each value's reason
// is given; the test `wgsl_guards_equal_rust_guards` holds the two equal. They clamp inputs:
// WGSL may assume no NaN or infinity, so filtering bad values afterwards would not work.

const NORMALIZE_MIN_LEN2: f32 = 1e-20;
const N_DOT_V_MIN: f32 = 1e-4;
const N_DOT_H_MIN: f32 = 1e-4;
const M_MIN: f32 = 1e-3;
const H_MAX: f32 = 1e9;
const PHONG_LOG2_ARG_MIN: f32 = 1e-38;
const MIRROR_V_DOT_R_MIN: f32 = 0.999999;
const G_V_DOT_H_MIN: f32 = 1e-30;
const FRESNEL_SQRT_MU_MAX: f32 = 0.9999;
const FRESNEL_G_PLUS_C_MIN: f32 = 1e-6;
const SMITH_DENOM_MIN: f32 = 1e-30;
const BLINN_PHONG_COS_MIN: f32 = 1e-12;
const MS_ALBEDO_MIN: f32 = 0.05;
const LIGHT_DIST_MIN: f32 = 1e-4;
const D0_MIN: f32 = 1e-3;
const SPOT_COS_SPAN_MIN: f32 = 1e-3;
const EDGE_CROSS_MIN_LEN2: f32 = 1e-24;
const AREA_POINT_LIMIT_ANGLE: f32 = 0.02;
const SPHERE_DISK_MARGIN: f32 = 1e-3;
const BLOCKER_DIST_MIN: f32 = 1e-4;
const QUADRIC_A_MIN: f32 = 1e-30;

// Light slots in the scene uniform (scene::MAX_LIGHTS).
const MAX_LIGHTS: u32 = 8u;

// Normalize `v`, or return `fallback` when `v` is (nearly) zero (guard NORMALIZE_MIN_LEN2).
fn safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2 = dot(v, v);
    return select(fallback, v * inverseSqrt(max(len2, NORMALIZE_MIN_LEN2)), len2 > NORMALIZE_MIN_LEN2);
}

// True for NaN or ±infinity, tested on the bits so that no fast-math assumption removes it.
fn is_nonfinite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7f800000u) == 0x7f800000u;
}

fn any_nonfinite(c: vec3<f32>) -> bool {
    return is_nonfinite(c.x) || is_nonfinite(c.y) || is_nonfinite(c.z);
}
