// Lines drawn over a rendered frame (the self-shadow boundary): world-space segments with the
// scene's view-projection, in one fixed colour. Used by crates/shadelab-render/src/overlay_pass.rs.

struct Overlay {
    view_proj: mat4x4<f32>,
    // xyz: the camera's eye; w: how far each end is pulled towards it (OVERLAY_DEPTH_PULL).
    eye_pull: vec4<f32>,
    color: vec4<f32>,
    // xy: one pixel in clip units (2/width, 2/height).
    pixel: vec4<f32>,
};

@group(0) @binding(0) var<uniform> overlay: Overlay;

@vertex
fn vs_overlay(@location(0) position: vec3<f32>, @builtin(instance_index) copy: u32) -> @builtin(position) vec4<f32> {
    // Pulled a little towards the eye, so that a line passes the depth test of the faces it lies on.
    let p = mix(position, overlay.eye_pull.xyz, overlay.eye_pull.w);
    var clip = overlay.view_proj * vec4<f32>(p, 1.0);
    // Each copy of the line is shifted by whole pixels (0 or 1 in x and y): a line two pixels wide.
    let shift = vec2<f32>(f32(copy & 1u), f32(copy >> 1u));
    clip = vec4<f32>(clip.xy + shift * overlay.pixel.xy * clip.w, clip.zw);
    return clip;
}

@fragment
fn fs_overlay() -> @location(0) vec4<f32> {
    return overlay.color;
}
