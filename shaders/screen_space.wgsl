// The shading modes' stages with the chapter's screen-space interpolation, beside the
// perspective-correct ones of shading.wgsl (their vertex stages and per-pixel work are those).

// The optional varyings in both interpolations, screen-space and perspective-correct.
#block UV_TINT_SCREEN
#if TEXTURE_COORDS
    @location(4) @interpolate(linear) uv: vec2<f32>,
    @location(5) uv_perspective: vec2<f32>,
#endif
#if EFFECT_VERTEX_COLORS
    @location(6) @interpolate(linear) tint: vec3<f32>,
    @location(7) tint_perspective: vec3<f32>,
#endif
#endblock

// Those varyings from a perspective-correct vertex stage's output `v` into `out`.
#block UV_TINT_SCREEN_COPY
#if TEXTURE_COORDS
    out.uv = v.uv;
    out.uv_perspective = v.uv;
#endif
#if EFFECT_VERTEX_COLORS
    out.tint = v.tint;
    out.tint_perspective = v.tint;
#endif
#endblock

// The chapter's interpolation (docs/model.md §8): linear in screen space along the scanlines, as
// the chapter writes it, not perspective-correct; the same stages with `@interpolate(linear)`.
// Screen-space interpolation has no meaning on a triangle clipped at the eye plane (a corner
// behind the eye projects nowhere), where a rasterizer may give ∞: there the perspective-correct
// value, carried beside it, stands in.
struct ColorScreenOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(linear) color: vec3<f32>,
    @location(1) color_perspective: vec3<f32>,
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    @location(2) @interpolate(linear) rest: vec3<f32>,
    @location(3) rest_perspective: vec3<f32>,
#endif
#insert UV_TINT_SCREEN
}

struct PhongScreenOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(linear) world_pos: vec3<f32>,
    @location(1) @interpolate(linear) world_normal: vec3<f32>,
    @location(2) world_pos_perspective: vec3<f32>,
    @location(3) world_normal_perspective: vec3<f32>,
#insert UV_TINT_SCREEN
#if EFFECT_NORMAL_TEXTURE
    // The tangent frame stays perspective-correct: a texture's frame, not the chapter's colour.
    @location(8) world_tangent: vec4<f32>,
#endif
}

// The screen-space value, or the perspective-correct one where it is not finite.
fn screen_or_perspective(screen: vec3<f32>, perspective: vec3<f32>) -> vec3<f32> {
    return select(screen, perspective, any_nonfinite(screen));
}

@vertex
fn vs_gouraud_screen(in: SmoothIn, @builtin(vertex_index) vertex: u32) -> ColorScreenOut {
    let v = gouraud_vertex(in, vertex);
    var out: ColorScreenOut;
    out.clip = v.clip;
    out.color = v.color;
    out.color_perspective = v.color;
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    out.rest = v.rest;
    out.rest_perspective = v.rest;
#endif
#insert UV_TINT_SCREEN_COPY
    return out;
}

@fragment
fn fs_gouraud_screen(in: ColorScreenOut) -> @location(0) vec4<f32> {
    var g: ColorOut;
    g.clip = in.clip;
    g.color = screen_or_perspective(in.color, in.color_perspective);
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    g.rest = screen_or_perspective(in.rest, in.rest_perspective);
#endif
#if TEXTURE_COORDS
    g.uv = select(in.uv, in.uv_perspective, any_nonfinite(vec3(in.uv, 0.0)));
#endif
#if EFFECT_VERTEX_COLORS
    g.tint = screen_or_perspective(in.tint, in.tint_perspective);
#endif
    return finish(per_vertex_pixel(g));
}

@vertex
fn vs_phong_screen(in: SmoothIn) -> PhongScreenOut {
    let v = phong_vertex(in);
    var out: PhongScreenOut;
    out.clip = v.clip;
    out.world_pos = v.world_pos;
    out.world_normal = v.world_normal;
    out.world_pos_perspective = v.world_pos;
    out.world_normal_perspective = v.world_normal;
#insert UV_TINT_SCREEN_COPY
#if EFFECT_NORMAL_TEXTURE
    out.world_tangent = v.world_tangent;
#endif
    return out;
}

@fragment
fn fs_phong_screen(in: PhongScreenOut) -> @location(0) vec4<f32> {
    let p = screen_or_perspective(in.world_pos, in.world_pos_perspective);
    let n = screen_or_perspective(in.world_normal, in.world_normal_perspective);
    var uv = vec2(0.0);
    var tint = vec3(1.0);
#if TEXTURE_COORDS
    uv = select(in.uv, in.uv_perspective, any_nonfinite(vec3(in.uv, 0.0)));
#endif
#if EFFECT_VERTEX_COLORS
    tint = screen_or_perspective(in.tint, in.tint_perspective);
#endif
    var tangent = vec4(0.0);
#if EFFECT_NORMAL_TEXTURE
    tangent = in.world_tangent;
#endif
    return finish(shade(p, pixel_normal(uv, n, tangent), pixel_surface(uv, tint), in.clip.xy) + pixel_emission(uv));
}
