// The chapter's illumination models other than the Phong model's sum (docs/model.md §1, §2,
// §3a): the Lambert rule and the four-term sum of equation (1), named as in their f64 twin,
// crates/shadelab-model/src/lighting/models.rs. shade() in shading.wgsl picks the model.

// Codes Rust writes into `globals.illumination` (IlluminationModel::code), held equal by the test
// `wgsl_codes_equal_rust_codes`.
const ILLUMINATION_PHONG: u32 = 0u;
const ILLUMINATION_LAMBERT: u32 = 1u;
const ILLUMINATION_SUM: u32 = 2u;

// docs/model.md §1: the lit part of the Lambert rule for one light, R·I·max(cos α, 0), per channel
// with R and I clamped to [0, 1] (the rule's domain).
fn lambert_rule_lit(r: vec3<f32>, i: vec3<f32>, cos_alpha: f32) -> vec3<f32> {
    return clamp(r, vec3(0.0), vec3(1.0)) * clamp(i, vec3(0.0), vec3(1.0)) * max(cos_alpha, 0.0);
}

// docs/model.md §1: the Lambert rule's fill R·(1 − I), clamped as above.
fn lambert_rule_fill(r: vec3<f32>, i: vec3<f32>) -> vec3<f32> {
    return clamp(r, vec3(0.0), vec3(1.0)) * (1.0 - clamp(i, vec3(0.0), vec3(1.0)));
}

// docs/model.md §2: the reflected term's cos φ = N·V, clamped at 0 (seen from behind), and 0 in
// the point's own shadow (N·L ≤ 0), where no light arrives to be reflected.
fn reflected_cos_phi(n_dot_l: f32, n_dot_v: f32) -> f32 {
    return select(0.0, max(n_dot_v, 0.0), n_dot_l > 0.0);
}

// docs/model.md §2: what one light adds to the four-term sum through the surface,
// I·(K_d·max(N·L, 0) + K_r·cos φ) with K_d = r_d·C and K_r = r_s; 0 in own shadow. `radiance`
// carries the light's 1/(d + d0).
fn sum_contribution(
    radiance: vec3<f32>,
    n_dot_l: f32,
    n_dot_v: f32,
    color: vec3<f32>,
    r_d: f32,
    r_s: f32,
) -> vec3<f32> {
    let lit = r_d * color * n_dot_l + vec3(r_s * reflected_cos_phi(n_dot_l, n_dot_v));
    return select(vec3(0.0), radiance * lit, n_dot_l > 0.0);
}

// docs/model.md §2: the transmitted term K_t·(1 − t)·I with K_t = C and 1 − t the material's
// transmission share (clamped to [0, 1]); it does not depend on the angles.
fn transmitted_term(radiance: vec3<f32>, color: vec3<f32>, share: f32) -> vec3<f32> {
    return radiance * color * clamp(share, 0.0, 1.0);
}
