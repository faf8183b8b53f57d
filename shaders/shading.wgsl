// The three shading modes (docs/model.md §8) over the chosen illumination model (docs/model.md
// §3a): the Phong model I = I_a + Σ_lights I_L · (r_d·C·(N·L) + r_s·S), S = Phong or Cook–Torrance
// specular, the Lambert rule or the four-term sum (models.wgsl); the f64 twin of `shade` is
// crates/shadelab-model/src/lighting/shading.rs.
// Flat: lit once per face at its centroid (cs_flat), the face's colour read by each of its
// corners. Gouraud: lit once per vertex (cs_gouraud), the colour read by the vertex stage and
// interpolated.
// Phong: normals interpolated, renormalized, lit per pixel.

// Each pipeline's module holds only the effects its scene calls for: the `#if EFFECT_…` blocks
// (see crates/shadelab-model/src/effects/declared.rs). The "uber" permutation keeps them all and leaves
// the choice to the uniforms (globals.specular_model, r_s, α, …).

struct Globals {
    view_proj: mat4x4<f32>,
    // The eye, homogeneous: (position, 1) for a perspective camera, (−forward, 0) for an
    // orthographic one; the view vector is camera_pos.xyz − p·camera_pos.w.
    camera_pos: vec4<f32>,
    // rgb: ambient intensity I_amb.
    ambient: vec4<f32>,
    light_count: u32,
    // bit 0: paint non-finite pixels magenta.
    flags: u32,
    // Which specular term S is: SPECULAR_PHONG or SPECULAR_COOK_TORRANCE.
    specular_model: u32,
    // Which illumination model: ILLUMINATION_PHONG, _LAMBERT or _SUM (models.wgsl).
    illumination: u32,
    lights: array<Light, MAX_LIGHTS>,
}

struct Object {
    model: mat4x4<f32>,
    // Upper 3×3: carries object-space normals to world space ((R S)^-T).
    normal_matrix: mat4x4<f32>,
    // rgb: surface colour C.
    color: vec4<f32>,
    // rgb: normal-incidence reflectance μ.
    mu: vec4<f32>,
    r_s: f32,
    r_d: f32,
    r_a: f32,
    m: f32,
    h: f32,
    // 1: the Phong "mirror" setting (h = ∞).
    mirror: u32,
    // The four-term sum's 1 − t (glTF's transmission factor; 0 is opaque).
    transmission: f32,
    // KHR_texture_transform of the base colour texture: rotation, and offset.xy, scale.zw.
    uv_rotation: f32,
    // rgb: the part of μ the base colour sets (surface.wgsl).
    mu_tinted: vec4<f32>,
    uv_offset_scale: vec4<f32>,
    // rgb: M·F0, the dielectric share of μ the metallic factor replaced (surface.wgsl).
    metallic_f0: vec4<f32>,
    // rgb: emission I_e.
    emission: vec4<f32>,
    // The metallic–roughness, occlusion and emissive textures' transforms: offset.xy, scale.zw;
    // their rotations in uv_rotations.xyz.
    metal_roughness_uv: vec4<f32>,
    occlusion_uv: vec4<f32>,
    emissive_uv: vec4<f32>,
    uv_rotations: vec4<f32>,
    // Which of the material's texture slots hold a texture (MAP_… in surface.wgsl).
    maps: u32,
    occlusion_strength: f32,
    normal_scale: f32,
    // The normal texture's transform (its rotation: uv_rotations.w).
    normal_uv: vec4<f32>,
    // World to object space (the glass pass's analytic exit, glass.wgsl).
    inverse_model: mat4x4<f32>,
    // rgb: the refractive index v per channel; w: 1 where the channels differ.
    ior: vec4<f32>,
    // rgb: the absorption coefficient a per channel per world unit.
    absorption: vec4<f32>,
    // Shape::exit_code (SHAPE_MESH: the back faces).
    exit_shape: u32,
    // The absorption form picked for the object (ABSORPTION_…).
    absorption_form: u32,
    // The longest path inside: the path-length view's white.
    longest_chord: f32,
}

const FLAG_DEBUG_NONFINITE: u32 = 1u;
const NONFINITE_COLOR: vec3<f32> = vec3(1.0, 0.0, 1.0);

@group(0) @binding(0) var<uniform> globals: Globals;
@group(1) @binding(0) var<uniform> object: Object;

// The per-vertex modes' lighting passes (@group(3); binding 0 is the shadow pass's): a compute
// pass lights each point once into `lit_colors_out` and the vertex stage reads `lit_colors`.
// cs_flat reads the flat mesh's corners (FLAT_CORNER_FLOATS floats each, three per face) and
// writes one colour per face; cs_gouraud reads the smooth vertices (SMOOTH_VERTEX_FLOATS floats
// each) and writes one colour per vertex. Each dispatch binds one chunk of input and output.
const FLAT_CORNER_FLOATS: u32 = 9u;
const SMOOTH_VERTEX_FLOATS: u32 = 6u;
@group(3) @binding(1) var<storage, read> lit_points: array<f32>;
@group(3) @binding(2) var<storage, read_write> lit_colors_out: array<vec4<f32>>;
@group(3) @binding(3) var<storage, read> lit_colors: array<vec4<f32>>;

// The light loop of a pipeline built for its scene's lights (LightLoop in
// crates/shadelab-render/src/light_loop.rs): LOOP_LIGHTS lights whose kinds are LOOP_KINDS,
// LOOP_KIND_BITS a slot. Both are known when the pipeline is built, so the compiler unrolls the
// loop, reads each light's uniforms at a fixed offset and keeps only its kind's code. The default,
// LOOP_DYNAMIC, reads the count and the kinds from the uniforms (the uber pipeline).
const LOOP_DYNAMIC: u32 = 0xffffffffu;
const LOOP_KIND_BITS: u32 = 3u;
const LOOP_KIND_MASK: u32 = 7u;
override LOOP_LIGHTS: u32 = LOOP_DYNAMIC;
override LOOP_KINDS: u32 = 0u;

// The illumination model at world point `p` with (not necessarily unit) normal `n_in`; `pixel`
// seeds the shadow filter's per-pixel rotation (read only with cast shadows). The Lambert rule's
// fill and the sum's transmitted term are not shadowed (see the twin's shade_with_visibility).
fn shade(p: vec3<f32>, n_in: vec3<f32>, surface: Surface, pixel: vec2<f32>) -> vec3<f32> {
    let v = safe_normalize(globals.camera_pos.xyz - p * globals.camera_pos.w, vec3(0.0, 1.0, 0.0));
    // A zero normal (e.g. interpolated between opposite vertex normals) faces the viewer.
    let n = safe_normalize(n_in, v);
    let c = surface.c;
    // The Fresnel index is used by Cook–Torrance only.
    var v_index = vec3(1.0);
#if EFFECT_SPECULAR_COOK_TORRANCE
    v_index = fresnel_v_from_mu(surface.mu);
#endif
    var total = vec3(0.0);
#if EFFECT_AMBIENT
    total += globals.ambient.rgb * surface.r_a * c;
#endif
#if EFFECT_LAMBERT_RULE
    // The Lambert rule's I: the brightest light at the point, per channel, in [0, 1].
    var i_max = vec3(0.0);
#endif
    let fixed_loop = LOOP_LIGHTS != LOOP_DYNAMIC;
    let light_count = select(min(globals.light_count, MAX_LIGHTS), min(LOOP_LIGHTS, MAX_LIGHTS), fixed_loop);
    for (var i = 0u; i < light_count; i++) {
        var light = globals.lights[i];
        light.kind = select(light.kind, (LOOP_KINDS >> (LOOP_KIND_BITS * i)) & LOOP_KIND_MASK, fixed_loop);
        let base = light_sample(light, p, n, v, surface.m);
        // An area light drawn as k point sources is k samples, each with its own shadow.
        var samples = 1u;
#if EFFECT_AREA_POINTS
#if EFFECT_POINT_LIGHTS
        samples = area_point_count(light);
#endif
#endif
        for (var j = 0u; j < samples; j++) {
            var s = base;
            // Where the light's shadow is cast from (a directional light's has no position).
            var origin = vec3(0.0);
#if EFFECT_POINT_LIGHTS
            origin = light.position.xyz;
#endif
#if EFFECT_AREA_POINTS
#if EFFECT_POINT_LIGHTS
            if (drawn_as_points(light)) {
                let e = area_emitter(light, j);
                s = area_point_sample(base, light, e, p, n);
                origin = e.position;
            }
#endif
#endif
            // The chosen model's term of this light (or point source), before its shadow.
            var lit = vec3(0.0);
            var modelled = false;
#if EFFECT_LAMBERT_RULE
            if (globals.illumination == ILLUMINATION_LAMBERT) {
                let li = clamp(s.radiance, vec3(0.0), vec3(1.0));
                i_max = max(i_max, li);
                lit = lambert_rule_lit(object.r_d * c, li, s.form);
                modelled = true;
            }
#endif
#if EFFECT_FOUR_TERM_SUM
            if (!modelled && globals.illumination == ILLUMINATION_SUM) {
#if EFFECT_TRANSMITTED_TERM
                // The transmitted term is the light's, once (not per point source), unshadowed.
                if (j == 0u) {
                    total += transmitted_term(s.radiance, c, object.transmission);
                }
#endif
                lit = sum_contribution(s.radiance, s.form, dot(n, v), c, object.r_d, object.r_s);
                modelled = true;
            }
#endif
            if (!modelled) {
                lit = light_contribution(
                    s, n, v, c, object.r_s, object.r_d, surface.m, surface.h, surface.mirror,
                    v_index, globals.specular_model,
                );
            }
            // A term that adds nothing here (the point faces away from the light) needs no
            // shadow query: its map lookups are skipped, as the f64 twin skips its shadow ray.
            if (any(lit != vec3(0.0))) {
                var visibility = 1.0;
#if EFFECT_CAST_SHADOWS
                visibility = shadow_visibility(i, light, origin, j, p, n, pixel);
#endif
                total += visibility * lit;
            }
        }
    }
#if EFFECT_LAMBERT_RULE
    if (globals.illumination == ILLUMINATION_LAMBERT) {
        total += lambert_rule_fill(surface.r_a * c, i_max);
    }
#endif
    return total;
}

// The object's material untinted: C, μ where Cook–Torrance reads it, m, h and r_a.
fn object_surface() -> Surface {
    var mu = vec3(0.0);
#if EFFECT_SPECULAR_COOK_TORRANCE
    mu = object.mu.rgb;
#endif
    return Surface(object.color.rgb, mu, object.m, object.h, object.mirror != 0u, object.r_a);
}

// The material at a pixel: its metallic–roughness texel's metal and roughness scales, the tint
// of the interpolated vertex colour and base colour texture, and its occlusion texel, where the
// permutation has them and the object's material has the texture.
fn pixel_surface(uv: vec2<f32>, tint: vec3<f32>) -> Surface {
    var s = object_surface();
    var mu_tinted = object.mu_tinted.rgb;
#if EFFECT_METAL_ROUGHNESS_TEXTURE
    if ((object.maps & MAP_METAL_ROUGHNESS) != 0u) {
        let x = metal_roughness_texel(texture_uv(uv, object.metal_roughness_uv.xy, object.uv_rotations.x, object.metal_roughness_uv.zw));
        let k = metallic_scaled(s.c, s.mu, mu_tinted, object.metallic_f0.rgb, x.b);
        s.c = k.c;
        s.mu = k.mu;
        mu_tinted = k.mu_tinted;
        s.m = roughness_scaled(s.m, x.g);
        s.h = phong_h_from_m(s.m);
        s.mirror = s.m <= 0.0;
    }
#endif
    let t = tinted_surface(s.c, s.mu, mu_tinted, pixel_tint(uv, tint));
    s.c = t.c;
    s.mu = t.mu;
#if EFFECT_OCCLUSION_TEXTURE
    if ((object.maps & MAP_OCCLUSION) != 0u) {
        let occ = occlusion_texel(texture_uv(uv, object.occlusion_uv.xy, object.uv_rotations.y, object.occlusion_uv.zw));
        s.r_a = occluded(s.r_a, occ, object.occlusion_strength);
    }
#endif
    return s;
}

// The shading normal at a pixel: the interpolated normal, turned by the normal texture in the
// interpolated tangent frame where the material has one.
fn pixel_normal(uv: vec2<f32>, n: vec3<f32>, tangent: vec4<f32>) -> vec3<f32> {
    var out = n;
#if EFFECT_NORMAL_TEXTURE
    if ((object.maps & MAP_NORMAL) != 0u) {
        let texel = normal_texel(texture_uv(uv, object.normal_uv.xy, object.uv_rotations.w, object.normal_uv.zw));
        out = normal_mapped(safe_normalize(n, vec3(0.0, 1.0, 0.0)), tangent, texel, object.normal_scale);
    }
#endif
    return out;
}

// The tint t of C at a pixel: the interpolated vertex colour times the base colour texture.
fn pixel_tint(uv: vec2<f32>, tint: vec3<f32>) -> vec3<f32> {
    var t = vec3(1.0);
#if EFFECT_VERTEX_COLORS
    t *= vertex_tint(tint);
#endif
#if EFFECT_BASE_COLOR_TEXTURE
    t *= base_color_texel(texture_uv(uv, object.uv_offset_scale.xy, object.uv_rotation, object.uv_offset_scale.zw));
#endif
    return t;
}

// The light a pixel emits: I_e, times the emissive texture where the material has one; added to
// the model's I in every mode (it is not lit, so the per-vertex modes add it per pixel exactly).
fn pixel_emission(uv: vec2<f32>) -> vec3<f32> {
    var e = vec3(0.0);
#if EFFECT_EMISSION
    var texel = vec3(1.0);
#if EFFECT_EMISSIVE_TEXTURE
    if ((object.maps & MAP_EMISSIVE) != 0u) {
        texel = emissive_texel(texture_uv(uv, object.emissive_uv.xy, object.uv_rotations.z, object.emissive_uv.zw));
    }
#endif
    e = emitted(object.emission.rgb, texel);
#endif
    return e;
}

// Whether the per-vertex modes split their colours: with a texture or vertex colours C is tinted
// per pixel, and since every model is affine in C (I = C ⊙ A + B), the lighting pass writes the
// part C scales, C ⊙ A, and B, and the fragment stage draws t ⊙ (C ⊙ A) + B. (μ keeps its
// untinted value there: its tint is drawn in Phong shading only.)
fn lit_split() -> bool {
    var split = false;
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    split = true;
#endif
    return split;
}

// The lighting pass's colours of point `i`: the model, or with lit_split() C ⊙ A at 2i and B at
// 2i + 1.
fn write_lit(i: u32, p: vec3<f32>, n: vec3<f32>, seed: vec2<f32>) {
    let s = object_surface();
    if (lit_split()) {
        var dark = s;
        dark.c = vec3(0.0);
        let b = shade(p, n, dark, seed);
        lit_colors_out[2u * i] = vec4(shade(p, n, s, seed) - b, 1.0);
        lit_colors_out[2u * i + 1u] = vec4(b, 1.0);
    } else {
        lit_colors_out[i] = vec4(shade(p, n, s, seed), 1.0);
    }
}

// Points the lighting pass's chunk holds.
fn lit_count() -> u32 {
    return arrayLength(&lit_colors_out) / select(1u, 2u, lit_split());
}

// Point `i`'s colours for the vertex stage: (the model or C ⊙ A, B or 0).
fn read_lit(i: u32) -> array<vec3<f32>, 2> {
    if (lit_split()) {
        return array(lit_colors[2u * i].rgb, lit_colors[2u * i + 1u].rgb);
    }
    return array(lit_colors[i].rgb, vec3(0.0));
}

fn finish(color: vec3<f32>) -> vec4<f32> {
    if ((globals.flags & FLAG_DEBUG_NONFINITE) != 0u && any_nonfinite(color)) {
        return vec4(NONFINITE_COLOR, 1.0);
    }
    return vec4(color, 1.0);
}

fn to_world(p: vec3<f32>) -> vec3<f32> {
    return (object.model * vec4(p, 1.0)).xyz;
}

fn normal_to_world(n: vec3<f32>) -> vec3<f32> {
    return mat3x3(object.normal_matrix[0].xyz, object.normal_matrix[1].xyz, object.normal_matrix[2].xyz) * n;
}

// The vertex stages' stand-in for a pixel position (they have none): the world position scaled to
// vary from vertex to vertex.
fn vertex_seed(p: vec3<f32>) -> vec2<f32> {
    return (p.xz + p.yy) * 1024.0;
}

struct SmoothIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
#if TEXTURE_COORDS
    @location(2) uv: vec2<f32>,
#endif
#if EFFECT_VERTEX_COLORS
    @location(3) tint: vec3<f32>,
#endif
#if EFFECT_NORMAL_TEXTURE
    @location(4) tangent: vec4<f32>,
#endif
}

struct FlatIn {
    @location(0) position: vec3<f32>,
#if TEXTURE_COORDS
    @location(2) uv: vec2<f32>,
#endif
#if EFFECT_VERTEX_COLORS
    @location(3) tint: vec3<f32>,
#endif
}

// The per-vertex modes' outputs: the colour (with a split, C ⊙ A), its rest B, and what tints C.
struct ColorOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec3<f32>,
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    @location(1) rest: vec3<f32>,
#endif
#if TEXTURE_COORDS
    @location(2) uv: vec2<f32>,
#endif
#if EFFECT_VERTEX_COLORS
    @location(3) tint: vec3<f32>,
#endif
}

struct FlatOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) @interpolate(flat) color: vec3<f32>,
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    @location(1) @interpolate(flat) rest: vec3<f32>,
#endif
#if TEXTURE_COORDS
    @location(2) uv: vec2<f32>,
#endif
#if EFFECT_VERTEX_COLORS
    @location(3) tint: vec3<f32>,
#endif
}

struct PhongOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world_pos: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
#if TEXTURE_COORDS
    @location(2) uv: vec2<f32>,
#endif
#if EFFECT_VERTEX_COLORS
    @location(3) tint: vec3<f32>,
#endif
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
    out.color = lit[0];
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    out.rest = lit[1];
#endif
#if TEXTURE_COORDS
    out.uv = in.uv;
#endif
#if EFFECT_VERTEX_COLORS
    out.tint = in.tint;
#endif
    return out;
}

@fragment
fn fs_flat(in: FlatOut) -> @location(0) vec4<f32> {
    var g: ColorOut;
    g.clip = in.clip;
    g.color = in.color;
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    g.rest = in.rest;
#endif
#if TEXTURE_COORDS
    g.uv = in.uv;
#endif
#if EFFECT_VERTEX_COLORS
    g.tint = in.tint;
#endif
    return finish(per_vertex_pixel(g));
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
    out.color = lit[0];
#if EFFECT_BASE_COLOR_TEXTURE||EFFECT_VERTEX_COLORS
    out.rest = lit[1];
#endif
#if TEXTURE_COORDS
    out.uv = in.uv;
#endif
#if EFFECT_VERTEX_COLORS
    out.tint = in.tint;
#endif
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
#if TEXTURE_COORDS
    out.uv = in.uv;
#endif
#if EFFECT_VERTEX_COLORS
    out.tint = in.tint;
#endif
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
