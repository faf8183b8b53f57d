// The shading module's uniform structs and the constants of their layout, shared with Rust:
// Globals, Tables and Object (crates/shadelab-render/src/uniforms.rs), the shadow uniforms
// (crates/shadelab-render/src/shadow_pass.rs) and the light loop's pipeline constants
// (crates/shadelab-render/src/light_loop.rs). Bindings are in bindings.wgsl.

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
    // The environment's nine SH coefficients (rgb; environment.wgsl); zero without one.
    env_sh: array<vec4<f32>, 9>,
    // The occlusion grid's origin (xyz) and cell (w), then its node counts (xyz; occlusion.wgsl);
    // zero without one.
    env_occlusion: array<vec4<f32>, 2>,
    // The inverse of view_proj: the background's direction through each pixel (background.wgsl).
    inv_view_proj: mat4x4<f32>,
}

// The constant tables, written once per device beside the globals (they never change).
struct Tables {
    // The multiple-scattering compensation's table (ms_table.rs's ms_table), four floats a
    // slot.
    ms_albedo: array<vec4<f32>, MS_TABLE_VEC4S>,
    // The split sum's B table (environment.rs's env_split_b_table), four floats a slot.
    env_split_b: array<vec4<f32>, ENV_SPLIT_B_VEC4S>,
    // The LTC table (ltc_table.rs), one node's M⁻¹ a slot.
    ltc: array<vec4<f32>, LTC_TABLE_VEC4S>,
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
    // 1: Phong's lobe normalized (Material::phong_normalized, brdf.wgsl).
    phong_normalized: u32,
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
    // The material's D, G and F (Microfacet::code; microfacet.wgsl).
    microfacet: u32,
    // The dielectric layer of the Fresnel-weighted diffuse (Material::fresnel_mix): x its F0,
    // y its weight.
    fresnel_mix: vec4<f32>,
}

const FLAG_DEBUG_NONFINITE: u32 = 1u;

// The per-vertex modes' lighting passes read FLAT_CORNER_FLOATS floats a corner of the flat
// mesh (three corners a face) and SMOOTH_VERTEX_FLOATS floats a smooth vertex.
const FLAT_CORNER_FLOATS: u32 = 9u;
const SMOOTH_VERTEX_FLOATS: u32 = 6u;

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

#if EFFECT_CAST_SHADOWS
// One light's shadow map in the frame's array of maps.
struct ShadowLight {
    first_layer: u32,
    // 0: the light casts no shadow; 1: a spot light or a directional light's one map; 2…4: a
    // directional light's cascades, finest first; 6 per cube: a point or area light's faces.
    layers: u32,
    // SHADOW_FILTER_HARD, _PCF or _POISSON.
    shadow_filter: u32,
    // 1: perspective (point, spot), texel_world grows with the distance along the view axis.
    perspective: u32,
    // World size of one texel (per unit of distance along the view axis when perspective).
    texel_world: f32,
    // Share of the layer's side the light's map uses (its resolution / the array's side).
    uv_scale: f32,
    // 1 / the array's side: one texel in layer coordinates.
    texel_uv: f32,
    // The light's size for its penumbra (0: no area); the map's depth range along its axis.
    light_size: f32,
    near: f32,
    far: f32,
    // Cube lights: how many cubes follow first_layer (one per point source of an area light
    // drawn as points, as many as fit); 1 otherwise.
    cubes: u32,
    // Taps of each of PCSS's two passes (ShadowSettings::pcss_taps, 4 to 64).
    pcss_taps: u32,
}

struct Shadows {
    // Each layer's light view-projection.
    matrices: array<mat4x4<f32>, MAX_SHADOW_LAYERS>,
    lights: array<ShadowLight, MAX_LIGHTS>,
}

// The shadow pass's view of the same buffer: only the matrices.
struct ShadowCasters {
    matrices: array<mat4x4<f32>, MAX_SHADOW_LAYERS>,
}

#endif
