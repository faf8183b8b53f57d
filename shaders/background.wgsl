// The environment as the background (only with its effect): one triangle over the whole target
// at the far plane, depth-tested against the scene so that only the pixels where the camera sees
// nothing take it. Each shows level 0 of the prefiltered levels toward its pixel's ray. Its f64
// twin is the reference's miss (EnvLight::background_toward, crates/shadelab-model/src/reference.rs).

#if EFFECT_ENVIRONMENT_BACKGROUND
struct BackgroundOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) ndc: vec2<f32>,
}

@vertex
fn vs_background(@builtin(vertex_index) i: u32) -> BackgroundOut {
    // Corners (−1, −1), (3, −1), (−1, 3): the triangle covers the target.
    let xy = vec2(f32((i << 1u) & 2u), f32(i & 2u)) * 2.0 - 1.0;
    var out: BackgroundOut;
    out.clip = vec4(xy, 1.0, 1.0);
    out.ndc = xy;
    return out;
}

@fragment
fn fs_background(in: BackgroundOut) -> @location(0) vec4<f32> {
    // The pixel's ray: from its point on the near plane toward its point on the far plane.
    let near = globals.inv_view_proj * vec4(in.ndc, 0.0, 1.0);
    let far = globals.inv_view_proj * vec4(in.ndc, 1.0, 1.0);
    let d = safe_normalize(far.xyz / far.w - near.xyz / near.w, vec3(0.0, 0.0, -1.0));
    return finish(env_level_sample(0u, d));
}
#endif
