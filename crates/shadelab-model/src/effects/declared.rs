//! The declared effects: one table entry per effect (its names, label, WGSL define, the WGSL
//! functions and uniform members only it uses), in the form of `declaration.rs`. Everything else
//! about an effect (the uber and none keys, the preprocessor defines, `--explain`, the
//! structural test) is derived from this table.

use super::declaration::declare_effects;

declare_effects! {
    /// Lambert diffuse `r_d·C·(N·L)` (docs/model.md §1).
    Diffuse {
        explain: "diffuse (Lambert)",
        name: "diffuse",
        label: "diffuse",
        define: Some("EFFECT_DIFFUSE"),
        functions: &["diffuse_lambert"],
        // r_d is passed to light_contribution in every permutation (unused there without the
        // effect): its function is the proof.
        members: &[],
    },
    /// Phong specular `(V·R)^h` (docs/model.md §3).
    SpecularPhong {
        explain: "Phong specular (V·R)^h",
        name: "Phong specular",
        label: "phong",
        define: Some("EFFECT_SPECULAR_PHONG"),
        functions: &["specular_phong"],
        // h and mirror are passed in every permutation, as r_d is.
        members: &[],
    },
    /// Phong's lobe normalized by `(h + 1)/2` (docs/model.md §3), for a material that asks for it.
    PhongNormalized {
        explain: "Phong lobe normalized (h + 1)/2",
        name: "Phong normalization",
        label: "phong-norm",
        define: Some("EFFECT_PHONG_NORMALIZED"),
        functions: &["phong_normalization"],
        members: &[("Object", "phong_normalized")],
    },
    /// Cook–Torrance specular `F·D·G/(N·V)` and the Fresnel index from μ (docs/model.md §5).
    SpecularCookTorrance {
        explain: "Cook–Torrance specular",
        name: "Cook–Torrance specular",
        label: "cook-torrance",
        define: Some("EFFECT_SPECULAR_COOK_TORRANCE"),
        functions: &["specular_microfacet", "microfacet_d", "microfacet_g", "microfacet_f", "fresnel_v_from_mu"],
        members: &[("Object", "mu"), ("Object", "microfacet")],
    },
    /// The chapter's Beckmann D (docs/model.md §5), for a material that uses it.
    DistributionBeckmann {
        explain: "Beckmann D (the chapter's)",
        name: "Beckmann D",
        label: "beckmann",
        define: Some("EFFECT_D_BECKMANN"),
        functions: &["d_beckmann"],
        members: &[],
    },
    /// GGX (Trowbridge–Reitz) D (docs/model.md §5).
    DistributionGgx {
        explain: "GGX D (Trowbridge–Reitz)",
        name: "GGX D",
        label: "ggx",
        define: Some("EFFECT_D_GGX"),
        functions: &["d_ggx"],
        members: &[],
    },
    /// The normalized Blinn–Phong D, the chapter's Phong lobe as a facet distribution
    /// (docs/microfacet.md).
    DistributionBlinnPhong {
        explain: "Blinn–Phong D (the Phong lobe as facets)",
        name: "Blinn–Phong D",
        label: "blinn-phong",
        define: Some("EFFECT_D_BLINN_PHONG"),
        functions: &["d_blinn_phong", "lambda_blinn_phong", "gamma_half_ratio", "one_minus_exp", "ln_one_minus"],
        members: &[],
    },
    /// The chapter's V-groove G `min{1, …}` (docs/model.md §5).
    MaskingVGroove {
        explain: "V-groove G min{1, …} (the chapter's)",
        name: "V-groove G",
        label: "vgroove",
        define: Some("EFFECT_G_V_GROOVE"),
        functions: &["g_cook_torrance"],
        members: &[],
    },
    /// Smith's separable G1(V)·G1(L) (docs/model.md §5).
    MaskingSmith {
        explain: "Smith G, separable G1(V)·G1(L)",
        name: "separable Smith G",
        label: "smith",
        define: Some("EFFECT_G_SMITH"),
        functions: &["g_smith_separable"],
        members: &[],
    },
    /// Smith's height-correlated G (docs/model.md §5).
    MaskingSmithCorrelated {
        explain: "Smith G, height-correlated 1/(1 + Λ(V) + Λ(L))",
        name: "height-correlated Smith G",
        label: "smith-hc",
        define: Some("EFFECT_G_SMITH_CORRELATED"),
        functions: &["g_smith_correlated"],
        members: &[],
    },
    /// The exact Fresnel F as the specular's F (docs/model.md §5).
    FresnelExact {
        explain: "exact Fresnel F (the chapter's)",
        name: "exact F",
        label: "exact-f",
        define: Some("EFFECT_F_EXACT"),
        // fresnel_dielectric is the glass's Fresnel too: a glass pass reaches it without this
        // effect, so only the specular's call is this effect's (effect_structure_tests checks it); its
        // complement serves the Fresnel-weighted diffuse.
        functions: &["fresnel_dielectric_complement"],
        members: &[],
    },
    /// Schlick's F (docs/model.md §5).
    FresnelSchlick {
        explain: "Schlick's F0 + (1 − F0)(1 − c)⁵",
        name: "Schlick F",
        label: "schlick",
        define: Some("EFFECT_F_SCHLICK"),
        functions: &["fresnel_schlick", "fresnel_schlick_complement"],
        members: &[],
    },
    /// The microfacet lobe's multiple-scattering compensation (docs/microfacet.md).
    MultipleScattering {
        explain: "multiple scattering 1 + F0·(1 − E)/E",
        name: "multiple-scattering compensation",
        label: "ms",
        define: Some("EFFECT_MULTIPLE_SCATTERING"),
        // The table's lookup (ms_albedo, and the tables' uniform) is shared with the environment's
        // split sum, so it is neither effect's alone.
        functions: &["ms_compensation"],
        members: &[],
    },
    /// The diffuse weighted by what the dielectric layer's Fresnel leaves it, glTF's
    /// `fresnel_mix` (docs/model.md §5).
    FresnelMix {
        explain: "diffuse weighted by 1 − F (glTF's fresnel_mix)",
        name: "Fresnel-weighted diffuse",
        label: "fmix",
        define: Some("EFFECT_FRESNEL_MIX"),
        functions: &["fresnel_mix_weight"],
        members: &[("Object", "fresnel_mix")],
    },
    /// Ambient `I_amb·r_a·C` (docs/model.md §2).
    Ambient {
        explain: "ambient I_amb·r_a·C",
        name: "ambient",
        label: "ambient",
        define: Some("EFFECT_AMBIENT"),
        functions: &[],
        members: &[("Globals", "ambient")],
    },
    /// The environment light's diffuse term `r_a·C·E(n)/π` from nine SH coefficients
    /// (docs/environment.md).
    EnvironmentSh {
        explain: "environment diffuse r_a·C·E(n)/π from nine SH terms",
        name: "environment",
        label: "env-sh",
        define: Some("EFFECT_ENVIRONMENT_SH"),
        functions: &["env_sh_radiance"],
        members: &[("Globals", "env_sh")],
    },
    /// The environment's diffuse term occluded by a grid of ambient occlusion precomputed over
    /// the scene (docs/environment.md, "Occlusion").
    EnvironmentOcclusion {
        explain: "environment diffuse times the precomputed occlusion grid's open share",
        name: "environment occlusion",
        label: "env-occ",
        define: Some("EFFECT_ENVIRONMENT_OCCLUSION"),
        functions: &["occ_cube", "env_occlusion"],
        members: &[("Globals", "env_occlusion")],
    },
    /// The environment light's specular by the split sum: a prefiltered environment times the
    /// lobe's albedo split by Schlick's F (docs/environment.md).
    EnvironmentSpecular {
        explain: "environment specular r_s·L_pre(R, m)·(F0·(E − B) + B) by the split sum",
        name: "environment specular",
        label: "env-spec",
        define: Some("EFFECT_ENVIRONMENT_SPECULAR"),
        // The levels' lookup (env_level_size … env_level_sample) is shared with the background.
        functions: &[
            "env_prefiltered",
            "env_split_b_node",
            "env_split_b",
            "env_specular",
        ],
        members: &[("Tables", "env_split_b")],
    },
    /// The environment drawn where the camera sees nothing, from its prefiltered level 0
    /// (docs/environment.md, "As the background").
    EnvironmentBackground {
        explain: "the environment as the background, level 0 of its prefiltered levels",
        name: "environment background",
        label: "env-bg",
        define: Some("EFFECT_ENVIRONMENT_BACKGROUND"),
        functions: &[],
        members: &[("Globals", "inv_view_proj")],
    },
    /// The Lambert rule's lit part and fill (docs/model.md §1), the illumination model
    /// `IlluminationModel::Lambert`.
    LambertRule {
        explain: "Lambert rule R·I·cos α + R·(1 − I)",
        name: "Lambert rule",
        label: "lambert",
        define: Some("EFFECT_LAMBERT_RULE"),
        functions: &["lambert_rule_lit", "lambert_rule_fill"],
        members: &[],
    },
    /// The four-term sum's diffuse and reflected terms (docs/model.md §2), the illumination model
    /// `IlluminationModel::Sum`.
    FourTermSum {
        explain: "four-term sum K_d·I_d + K_r·I_r",
        name: "four-term sum",
        label: "sum",
        define: Some("EFFECT_FOUR_TERM_SUM"),
        functions: &["sum_contribution", "reflected_cos_phi"],
        members: &[],
    },
    /// The four-term sum's transmitted term `K_t·(1 − t)·I/(d + d0)` (docs/model.md §2).
    TransmittedTerm {
        explain: "transmitted term K_t·I_t",
        name: "transmitted term",
        label: "it",
        define: Some("EFFECT_TRANSMITTED_TERM"),
        functions: &["transmitted_term"],
        // The glass pass reads Object.transmission too: the function is the proof.
        members: &[],
    },
    /// Directional lights (docs/model.md §6).
    DirectionalLights {
        explain: "directional lights",
        name: "directional lights",
        label: "dir",
        define: Some("EFFECT_DIRECTIONAL_LIGHTS"),
        functions: &[],
        members: &[("Light", "direction")],
    },
    /// Point lights: distance and direction per point (docs/model.md §6).
    PointLights {
        explain: "point lights",
        name: "point lights",
        label: "point",
        define: Some("EFFECT_POINT_LIGHTS"),
        functions: &[],
        members: &[("Light", "position")],
    },
    /// `1/(1 + α d²)` for point lights with α > 0 (docs/model.md §6).
    FalloffQuadratic {
        explain: "falloff 1/(1+αd²)",
        name: "falloff 1/(1+αd²)",
        label: "quad",
        define: Some("EFFECT_FALLOFF_QUADRATIC"),
        functions: &["falloff_quadratic"],
        members: &[("Light", "falloff_alpha")],
    },
    /// The chapter's `1/(d + d0)` (docs/model.md §6).
    FalloffLinear {
        explain: "falloff 1/(d+d0)",
        name: "falloff 1/(d+d0)",
        label: "linear",
        define: Some("EFFECT_FALLOFF_LINEAR"),
        functions: &["falloff_linear"],
        members: &[("Light", "d0")],
    },
    /// Spot cones, on top of point lights: a spot light is a point light with a cone
    /// (docs/model.md §9).
    SpotLights {
        explain: "spot cones",
        name: "spot cones",
        label: "spot",
        define: Some("EFFECT_SPOT_LIGHTS"),
        functions: &["spot_cone"],
        members: &[("Light", "spot_axis"), ("Light", "cos_inner"), ("Light", "cos_outer")],
    },
    /// Rectangle, disk and sphere lights (docs/area-lights.md): the exact area form for the
    /// diffuse term and the representative point for the specular, on the point-light path.
    AreaLights {
        explain: "area lights",
        name: "area lights",
        label: "area",
        define: Some("EFFECT_AREA_LIGHTS"),
        functions: &[
            "emitting_area",
            "area_radius",
            "area_corner_count",
            "area_corner",
            "edge_term",
            "polygon_step",
            "polygon_irradiance",
            "sphere_irradiance",
            "sin_minus_phi_cos",
            "atan_minus_u",
            "area_irradiance",
            "area_form",
            "clamp_to_shape",
            "area_specular_point",
        ],
        // Its shape's members (normal, tangent, half sizes) are read by area_points too.
        members: &[],
    },
    /// Area lights drawn as the chapter's k point sources (docs/area-lights.md): k samples in
    /// the light loop, each with its own hard shadow; also a light too small on screen for its
    /// area to show, drawn as one.
    AreaPoints {
        explain: "area lights as points",
        name: "area lights as points",
        label: "apoints",
        define: Some("EFFECT_AREA_POINTS"),
        functions: &[
            "area_point_count",
            "area_lattice",
            "concentric_disk",
            "fibonacci_sphere",
            "area_emitter",
            "area_point_sample",
        ],
        members: &[("Light", "area_points"), ("ShadowLight", "cubes")],
    },
    /// An area light's Cook–Torrance specular by linearly transformed cosines (docs/area-lights.md):
    /// the lobe's fitted LTC integrated over the light, in place of its representative point.
    AreaLtc {
        explain: "area lights' specular by LTC",
        name: "LTC specular",
        label: "ltc",
        define: Some("EFFECT_AREA_LTC"),
        functions: &[
            "any_tangent",
            "sphere_as_disk",
            "ltc_polygon",
            "area_specular_ltc",
            "specular_ltc",
            "ltc_cell",
            "ltc_node",
            "ltc_matrix",
            "area_ltc_sample",
        ],
        members: &[("Light", "area_specular"), ("Tables", "ltc")],
    },
    /// glTF's range window on point and spot lights that have a range (docs/model.md §9).
    LightRange {
        explain: "light range",
        name: "light range",
        label: "range",
        define: Some("EFFECT_LIGHT_RANGE"),
        functions: &["window_range"],
        members: &[("Light", "range")],
    },
    /// Shadows cast by other objects, from a shadow map per light (docs/model.md §0, §6): the
    /// shadow passes, the maps' bind group (@group(2)) and the compare code.
    CastShadows {
        explain: "cast shadows",
        name: "cast shadows",
        label: "shadows",
        define: Some("EFFECT_CAST_SHADOWS"),
        functions: &["shadow_visibility", "shadow_face", "shadow_map_coord", "shadow_texel_world", "shadow_compare"],
        members: &[("Shadows", "matrices"), ("Shadows", "lights"), ("ShadowLight", "shadow_filter")],
    },
    /// The `hard` shadow filter: one compare at the nearest texel (docs/model.md §6).
    ShadowFilterHard {
        explain: "shadow filter hard",
        name: "hard shadow filter",
        label: "hard",
        define: Some("EFFECT_SHADOW_HARD"),
        functions: &["shadow_compare_hard"],
        members: &[],
    },
    /// The `pcf` shadow filter: the hardware's bilinear 2×2 compare (docs/model.md §6).
    ShadowFilterPcf {
        explain: "shadow filter pcf",
        name: "PCF shadow filter",
        label: "pcf",
        define: Some("EFFECT_SHADOW_PCF"),
        functions: &["shadow_compare_pcf"],
        members: &[],
    },
    /// The `poisson` shadow filter: rotated Poisson-disk taps (docs/model.md §6).
    ShadowFilterPoisson {
        explain: "shadow filter poisson",
        name: "Poisson shadow filter",
        label: "poisson",
        define: Some("EFFECT_SHADOW_POISSON"),
        functions: &["shadow_compare_poisson"],
        members: &[],
    },
    /// The `pcss` shadow filter: an area light's penumbra from a blocker search and a filter as
    /// wide as the penumbra (docs/area-lights.md). Shares the per-pixel rotation with `poisson`.
    ShadowFilterPcss {
        explain: "shadow filter pcss",
        name: "PCSS shadow filter",
        label: "pcss",
        define: Some("EFFECT_SHADOW_PCSS"),
        functions: &[
            "shadow_compare_pcss",
            "pcss_search_tap",
            "pcss_filter_tap",
            "shadow_linear_depth",
            "shadow_stored_depth",
            "receiver_slope",
            "pcss_search_radius",
            "penumbra_width",
        ],
        members: &[
            ("ShadowLight", "light_size"),
            ("ShadowLight", "near"),
            ("ShadowLight", "far"),
            ("ShadowLight", "pcss_taps"),
        ],
    },
    /// A directional light's shadow map split along the view's depth into cascades, finest near
    /// the camera (docs/model.md §6).
    ShadowCascades {
        explain: "shadow cascades",
        name: "shadow cascades",
        label: "cascades",
        define: Some("EFFECT_SHADOW_CASCADES"),
        functions: &["shadow_cascade", "shadow_ortho_texel_world"],
        members: &[],
    },
    /// The base colour texture sampled per pixel (docs/textures.md): C and the tinted part of μ.
    BaseColorTexture {
        explain: "base colour texture",
        name: "base colour texture",
        label: "texture",
        define: Some("EFFECT_BASE_COLOR_TEXTURE"),
        functions: &["base_color_texel"],
        members: &[("Object", "uv_offset_scale"), ("Object", "uv_rotation")],
    },
    /// Vertex colours (glTF `COLOR_0`) interpolated and multiplied into C (docs/textures.md).
    VertexColors {
        explain: "vertex colours",
        name: "vertex colours",
        label: "vcolor",
        define: Some("EFFECT_VERTEX_COLORS"),
        functions: &["vertex_tint"],
        members: &[],
    },
    /// glTF's metallic–roughness texture sampled per pixel (docs/textures.md): its metal scale
    /// moves C and μ between the dielectric and the metal, its roughness scale m (and h with it).
    MetalRoughnessTexture {
        explain: "metallic–roughness texture",
        name: "metallic–roughness texture",
        label: "mrtex",
        define: Some("EFFECT_METAL_ROUGHNESS_TEXTURE"),
        functions: &["metal_roughness_texel", "metallic_scaled", "roughness_scaled", "phong_h_from_m"],
        members: &[("Object", "metallic_f0"), ("Object", "metal_roughness_uv")],
    },
    /// glTF's occlusion texture sampled per pixel: it scales the ambient reflectance r_a
    /// (docs/textures.md).
    OcclusionTexture {
        explain: "occlusion texture",
        name: "occlusion texture",
        label: "aotex",
        define: Some("EFFECT_OCCLUSION_TEXTURE"),
        functions: &["occlusion_texel", "occluded"],
        members: &[("Object", "occlusion_strength"), ("Object", "occlusion_uv")],
    },
    /// Emitted light I_e added to the model's I (glTF `emissiveFactor`, docs/textures.md).
    Emission {
        explain: "emission I_e",
        name: "emission",
        label: "emit",
        define: Some("EFFECT_EMISSION"),
        functions: &["emitted"],
        members: &[("Object", "emission")],
    },
    /// glTF's emissive texture sampled per pixel: its colour scales I_e (docs/textures.md).
    EmissiveTexture {
        explain: "emissive texture",
        name: "emissive texture",
        label: "emittex",
        define: Some("EFFECT_EMISSIVE_TEXTURE"),
        functions: &["emissive_texel"],
        members: &[("Object", "emissive_uv")],
    },
    /// glTF's normal texture sampled per pixel: the shading normal turned in the mesh's tangent
    /// frame (docs/textures.md).
    NormalTexture {
        explain: "normal texture",
        name: "normal texture",
        label: "normtex",
        define: Some("EFFECT_NORMAL_TEXTURE"),
        functions: &["normal_texel", "normal_mapped"],
        members: &[("Object", "normal_scale"), ("Object", "normal_uv")],
    },
    /// Transparent objects (docs/transparency.md): drawn after the opaque scene, far to near,
    /// each over a copy of what is behind it; their surface's own light with C·(1 − τ) and τ of
    /// what comes through; the exit from the analytic shapes or a mesh's back faces.
    Transmission {
        explain: "transmission",
        name: "transmission",
        label: "glass",
        define: Some("EFFECT_TRANSMISSION"),
        functions: &[
            "glass_color",
            "glass_path",
            "glass_exit",
            "back_face_exit",
            "shape_exit",
            "quadric_exit",
            "planes_exit",
            "project_to_pixel",
        ],
        members: &[("Object", "inverse_model"), ("Object", "exit_shape")],
    },
    /// Snell's law and the exact Fresnel factor at both interfaces, total internal reflection, and
    /// the scene found along the bent and mirrored rays (docs/transparency.md).
    Refraction {
        explain: "refraction",
        name: "refraction",
        label: "refract",
        define: Some("EFFECT_REFRACTION"),
        // fresnel_dielectric is shared with Cook–Torrance's F, so it is not the glass's alone.
        functions: &["refract_snell", "reflect_about", "scene_along"],
        members: &[("Object", "ior")],
    },
    /// Absorption inside a transparent object over the path measured from its geometry, in the
    /// form the chapter's rule (or `--absorption exact`) picks per object (docs/transparency.md).
    Absorption {
        explain: "absorption",
        name: "absorption",
        label: "absorb",
        define: Some("EFFECT_ABSORPTION"),
        functions: &["absorption_in_form", "absorption_exact"],
        members: &[("Object", "absorption")],
    },
}

/// The effects that sample a material texture at the pixel's texture coordinates.
pub const TEXTURE_EFFECTS: [Effect; 5] = [
    Effect::BaseColorTexture,
    Effect::MetalRoughnessTexture,
    Effect::OcclusionTexture,
    Effect::EmissiveTexture,
    Effect::NormalTexture,
];

/// The preprocessor name defined when a permutation samples some texture: the texture
/// coordinates' vertex attribute and interpolant.
pub const TEXTURE_COORDS: &str = "TEXTURE_COORDS";

/// How many declared effects are simulated (have a define).
const fn simulated_count() -> usize {
    let (mut i, mut n) = (0, 0);
    while i < DECLARED.len() {
        if DECLARED[i].define.is_some() {
            n += 1;
        }
        i += 1;
    }
    n
}
