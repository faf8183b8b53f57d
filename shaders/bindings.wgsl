// Every binding of the shading module but the material's textures (surface.wgsl, whose terms
// the compute passes evaluate with their own bindings): the frame's and the object's uniforms,
// the lighting passes' buffers, the shadow maps and the glass pass's copies of what is behind.
// The Rust side of each group is in crates/shadelab-render/src/pipelines.rs.

@group(0) @binding(0) var<uniform> globals: Globals;
#if EFFECT_ENVIRONMENT_SPECULAR||EFFECT_ENVIRONMENT_BACKGROUND
// The environment's prefiltered levels (environment.wgsl), written only when a scene has one.
@group(0) @binding(1) var<storage, read> env_levels: array<vec4<f32>>;
#endif
#if EFFECT_ENVIRONMENT_OCCLUSION
// The environment's occlusion grid (occlusion.wgsl), written only when a scene asks for it.
@group(0) @binding(2) var<storage, read> env_occlusion_nodes: array<vec2<u32>>;
#endif
// The constant tables (ms_table.wgsl, environment.wgsl), written once per device.
@group(0) @binding(3) var<uniform> tables: Tables;
@group(1) @binding(0) var<uniform> object: Object;

// The per-vertex modes' lighting passes (@group(3); binding 0 is the shadow pass's): a compute
// pass lights each point once into `lit_colors_out` and the vertex stage reads `lit_colors`.
// cs_flat reads the flat mesh's corners and writes one colour per face; cs_gouraud reads the
// smooth vertices and writes one colour per vertex. Each dispatch binds one chunk of input and output.
@group(3) @binding(1) var<storage, read> lit_points: array<f32>;
@group(3) @binding(2) var<storage, read_write> lit_colors_out: array<vec4<f32>>;
@group(3) @binding(3) var<storage, read> lit_colors: array<vec4<f32>>;

#if EFFECT_CAST_SHADOWS
@group(2) @binding(0) var<uniform> shadows: Shadows;
@group(2) @binding(1) var shadow_maps: texture_depth_2d_array;
// Bilinear 2×2 compare (Pcf, Poisson) and one nearest compare (Hard; its binding exists in the
// layout whether or not the permutation samples it).
@group(2) @binding(2) var shadow_linear: sampler_comparison;
#if EFFECT_SHADOW_HARD
@group(2) @binding(3) var shadow_nearest: sampler_comparison;
#endif
@group(3) @binding(0) var<uniform> shadow_casters: ShadowCasters;
#endif

#if EFFECT_TRANSMISSION
// What is behind the object: the target's colour before the object was drawn, the opaque
// scene's depth, and the object's back faces (world position, w = 1 where covered; outward
// normal), drawn just before it for a mesh.
@group(3) @binding(8) var behind_color: texture_2d<f32>;
@group(3) @binding(9) var behind_depth: texture_2d<f32>;
@group(3) @binding(10) var back_position: texture_2d<f32>;
@group(3) @binding(11) var back_normal: texture_2d<f32>;
#endif
