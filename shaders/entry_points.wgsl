// The entry points of the mesh passes (docs/shading.md): the per-vertex modes' lighting passes,
// the stages of flat, Gouraud and Phong shading, the null baseline and the shadow pass. Flat: lit
// once per face at its centroid (cs_flat), the colour read by each of its corners. Gouraud: lit
// once per vertex (cs_gouraud), the colour interpolated. Phong: normals interpolated,
// renormalized, lit per pixel. The lighting itself is shading.wgsl's; the screen-space variants
// are in screen_space.wgsl and the glass pass's in glass.wgsl.

// The optional vertex attributes, carried on as varyings at the same locations: texture
// coordinates and vertex colours, each only in the permutations that use it.
#block UV_TINT_FIELDS
#if TEXTURE_COORDS
    @location(2) uv: vec2<f32>,
#endif
#if EFFECT_VERTEX_COLORS
    @location(3) tint: vec3<f32>,
#endif
#endblock

// Those varyings copied from `in` to `out`.
#block UV_TINT_COPY
#if TEXTURE_COORDS
    out.uv = in.uv;
#endif
#if EFFECT_VERTEX_COLORS
    out.tint = in.tint;
#endif
#endblock

// The lit colour of a face or vertex (`lit`, from read_lit) and the attributes into `out`.
#block LIT_COPY
    out.color = lit[0];
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    out.rest = lit[1];
#endif
#insert UV_TINT_COPY
#endblock

struct SmoothIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
#insert UV_TINT_FIELDS
#if EFFECT_NORMAL_TEXTURE
    @location(4) tangent: vec4<f32>,
#endif
}

struct FlatIn {
    @location(0) position: vec3<f32>,
#insert UV_TINT_FIELDS
}

// The per-vertex modes' outputs: the colour (with a split, C ⊙ A), its rest B, and what tints C.
struct ColorOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec3<f32>,
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    @location(1) rest: vec3<f32>,
#endif
#insert UV_TINT_FIELDS
}

struct FlatOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(flat) color: vec3<f32>,
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    @location(1) @interpolate(flat) rest: vec3<f32>,
#endif
#insert UV_TINT_FIELDS
}

struct PhongOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world_pos: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
#insert UV_TINT_FIELDS
#if EFFECT_NORMAL_TEXTURE
    // World tangent (xyz, by the model matrix) and bitangent sign (w).
    @location(4) world_tangent: vec4<f32>,
#endif
}

// One invocation per face: the model at the face's centroid with its normal (its first corner
// holds both), the only evaluation flat shading makes.
@compute @workgroup_size(64)
fn cs_flat(@builtin(global_invocation_id) gid: vec3<u32>) {
    let face = gid.x;
    if (face >= lit_count()) {
        return;
    }
    let at = face * 3u * FLAT_CORNER_FLOATS;
    let normal = vec3(lit_points[at + 3u], lit_points[at + 4u], lit_points[at + 5u]);
    let centroid = vec3(lit_points[at + 6u], lit_points[at + 7u], lit_points[at + 8u]);
    let c = to_world(centroid);
    write_lit(face, c, normal_to_world(normal), vertex_seed(c));
}

@vertex
fn vs_flat(in: FlatIn, @builtin(vertex_index) corner: u32) -> FlatOut {
    var out: FlatOut;
    out.clip = globals.view_proj * vec4(to_world(in.position), 1.0);
    let lit = read_lit(corner / 3u);
#insert LIT_COPY
    return out;
}

@fragment
fn fs_flat(in: FlatOut) -> @location(0) vec4<f32> {
    var out: ColorOut;
    out.clip = in.clip;
    out.color = in.color;
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    out.rest = in.rest;
#endif
#insert UV_TINT_COPY
    return finish(per_vertex_pixel(out));
}

// One invocation per smooth vertex: the model at the vertex, the only evaluation Gouraud shading
// makes. (A compute pass, not the vertex stage: llvmpipe runs vertex stages on one thread and
// compute on all of its threads.)
@compute @workgroup_size(64)
fn cs_gouraud(@builtin(global_invocation_id) gid: vec3<u32>) {
    let v = gid.x;
    if (v >= lit_count()) {
        return;
    }
    let at = v * SMOOTH_VERTEX_FLOATS;
    let position = vec3(lit_points[at], lit_points[at + 1u], lit_points[at + 2u]);
    let normal = vec3(lit_points[at + 3u], lit_points[at + 4u], lit_points[at + 5u]);
    let p = to_world(position);
    write_lit(v, p, normal_to_world(normal), vertex_seed(p));
}

// Gouraud's vertex stage, shared by its two interpolations: the vertex's colour from cs_gouraud.
fn gouraud_vertex(in: SmoothIn, vertex: u32) -> ColorOut {
    var out: ColorOut;
    out.clip = globals.view_proj * vec4(to_world(in.position), 1.0);
    let lit = read_lit(vertex);
#insert LIT_COPY
    return out;
}

// The per-vertex modes' colour at a pixel: the face's or interpolated colour, tinted where it is
// split (t ⊙ (C ⊙ A) + B).
fn per_vertex_pixel(in: ColorOut) -> vec3<f32> {
    var color = in.color;
    var uv = vec2(0.0);
#if TEXTURE_COORDS
    uv = in.uv;
#endif
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    var tint = vec3(1.0);
#if EFFECT_VERTEX_COLORS
    tint = in.tint;
#endif
    color = pixel_tint(uv, tint) * in.color + in.rest;
#endif
    return color + pixel_emission(uv);
}

@vertex
fn vs_gouraud(in: SmoothIn, @builtin(vertex_index) vertex: u32) -> ColorOut {
    return gouraud_vertex(in, vertex);
}

@fragment
fn fs_gouraud(in: ColorOut) -> @location(0) vec4<f32> {
    return finish(per_vertex_pixel(in));
}

// Phong shading's vertex stage, shared by its two interpolations.
fn phong_vertex(in: SmoothIn) -> PhongOut {
    var out: PhongOut;
    out.world_pos = to_world(in.position);
    out.clip = globals.view_proj * vec4(out.world_pos, 1.0);
    out.world_normal = normal_to_world(in.normal);
#insert UV_TINT_COPY
#if EFFECT_NORMAL_TEXTURE
    out.world_tangent = vec4((object.model * vec4(in.tangent.xyz, 0.0)).xyz, in.tangent.w);
#endif
    return out;
}

@vertex
fn vs_phong(in: SmoothIn) -> PhongOut {
    return phong_vertex(in);
}

// Phong shading's interpolants at a pixel: texture coordinates, tint and the shading normal.
struct PixelInputs {
    texcoord: vec2<f32>,
    tint: vec3<f32>,
    normal: vec3<f32>,
}

fn pixel_inputs(in: PhongOut) -> PixelInputs {
    var out = PixelInputs(vec2(0.0), vec3(1.0), vec3(0.0));
#if TEXTURE_COORDS
    out.texcoord = in.uv;
#endif
#if EFFECT_VERTEX_COLORS
    out.tint = in.tint;
#endif
    var tangent = vec4(0.0);
#if EFFECT_NORMAL_TEXTURE
    tangent = in.world_tangent;
#endif
    out.normal = pixel_normal(out.texcoord, in.world_normal, tangent);
    return out;
}

@fragment
fn fs_phong(in: PhongOut) -> @location(0) vec4<f32> {
    let px = pixel_inputs(in);
    let lit = shade(in.world_pos, px.normal, pixel_surface(px.texcoord, px.tint), in.clip.xy);
    return finish(lit + pixel_emission(px.texcoord));
}

// The null-shader baseline of the cost study: the same geometry, vertex fetch, transform and
// depth test, but no lighting at all (a constant colour). What rasterizing the scene costs.
const BASELINE_COLOR: vec3<f32> = vec3(0.5, 0.5, 0.5);

@vertex
fn vs_baseline(in: SmoothIn) -> @builtin(position) vec4<f32> {
    return globals.view_proj * vec4(to_world(in.position), 1.0);
}

@fragment
fn fs_baseline() -> @location(0) vec4<f32> {
    return vec4(BASELINE_COLOR, 1.0);
}

#if EFFECT_CAST_SHADOWS
// The shadow pass: an object's smooth mesh drawn into one layer of the light's maps, the layer
// being the instance index (crates/shadelab-render/src/shadow_pass.rs draws one instance).
@vertex
fn vs_shadow(@location(0) position: vec3<f32>, @builtin(instance_index) layer: u32) -> @builtin(position) vec4<f32> {
    return shadow_casters.matrices[min(layer, MAX_SHADOW_LAYERS - 1u)] * vec4(to_world(position), 1.0);
}
#endif
