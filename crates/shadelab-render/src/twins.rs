//! Tests that hold the WGSL and its f64 twin (`shadelab_model::lighting`) together: every WGSL
//! function has a Rust twin of the same name in the matching file, the guards are equal, and the
//! codes Rust writes into the uniforms are the WGSL's constants.
#![cfg(test)]

use crate::shaders::tests::parse;
use crate::shaders::{FILES, lighting_source, terms_source};
use shadelab_model::lighting::microfacet::{Distribution, Fresnel, Masking, Microfacet};
use shadelab_model::params::NamedValue;
use shadelab_model::{FalloffForm, IlluminationModel, LightKind, SpecularModel};

/// Each WGSL file and the source of its f64 twin.
const TWINS: [(&str, &str); 23] = [
    ("common.wgsl", include_str!("../../shadelab-model/src/lighting/common.rs")),
    ("brdf.wgsl", include_str!("../../shadelab-model/src/lighting/brdf.rs")),
    ("microfacet.wgsl", include_str!("../../shadelab-model/src/lighting/microfacet.rs")),
    ("multiscatter.wgsl", include_str!("../../shadelab-model/src/lighting/multiscatter.rs")),
    ("models.wgsl", include_str!("../../shadelab-model/src/lighting/models.rs")),
    ("lights.wgsl", include_str!("../../shadelab-model/src/lighting/lights.rs")),
    ("area_lights.wgsl", include_str!("../../shadelab-model/src/lighting/area.rs")),
    ("area_points.wgsl", include_str!("../../shadelab-model/src/lighting/area_points.rs")),
    ("ltc.wgsl", include_str!("../../shadelab-model/src/lighting/ltc.rs")),
    // The projection and cascade math, and the map lookup around it; the map sampling has
    // none (the reference traces shadow rays).
    (
        "shadow_math.wgsl",
        concat!(
            include_str!("../../shadelab-model/src/shadows.rs"),
            include_str!("../../shadelab-model/src/shadows/cascades.rs")
        ),
    ),
    (
        "surface.wgsl",
        concat!(
            include_str!("../../shadelab-model/src/scene/material.rs"),
            include_str!("../../shadelab-model/src/scene/texture.rs")
        ),
    ),
    ("transmission.wgsl", include_str!("../../shadelab-model/src/lighting/transmission.rs")),
    // Structs and bindings: no functions.
    ("types.wgsl", ""),
    ("bindings.wgsl", ""),
    // The table lookup of the compensation.
    (
        "ms_table.wgsl",
        concat!(
            include_str!("../../shadelab-model/src/lighting/ms_table.rs"),
            include_str!("../../shadelab-model/src/lighting/ltc.rs")
        ),
    ),
    ("environment.wgsl", include_str!("../../shadelab-model/src/lighting/environment.rs")),
    ("occlusion.wgsl", include_str!("../../shadelab-model/src/lighting/occlusion.rs")),
    (
        "shadows.wgsl",
        concat!(
            include_str!("../../shadelab-model/src/shadows.rs"),
            include_str!("../../shadelab-model/src/shadows/cascades.rs")
        ),
    ),
    ("shading.wgsl", include_str!("../../shadelab-model/src/lighting/shading.rs")),
    // Stages and their helpers: their counterpart is the reference's exact per-pixel image.
    ("entry_points.wgsl", include_str!("../../shadelab-model/src/lighting/shading.rs")),
    // Stages only: their counterpart is the reference's exact per-pixel image.
    ("screen_space.wgsl", include_str!("../../shadelab-model/src/lighting/shading.rs")),
    // Stages only: their counterpart is the reference's miss toward the environment.
    ("background.wgsl", include_str!("../../shadelab-model/src/reference.rs")),
    // The glass pass: its counterpart is the reference's tracer, which follows every branch.
    (
        "glass.wgsl",
        concat!(
            include_str!("../../shadelab-model/src/reference/glass.rs"),
            include_str!("../../shadelab-model/src/reference/intersect.rs")
        ),
    ),
];

/// WGSL functions with no f64 twin, by file, and why. (Entry points are left out by naga's list:
/// they are the GPU's stages, whose f64 counterpart is `reference::render_reference`.)
const NO_TWIN: [(&str, &str, &str); 41] = [
    ("entry_points.wgsl", "pixel_inputs", "the interpolants at a pixel; the reference has the exact hit"),
    ("glass.wgsl", "project_to_pixel", "a point on the target; the reference traces rays, it has no target"),
    ("glass.wgsl", "texel", "a pixel of the target; the reference traces rays, it has no target"),
    ("glass.wgsl", "scene_behind", "the target behind the pixel; the reference traces the ray on"),
    ("glass.wgsl", "scene_along", "the march through the opaque depth; the reference traces the ray exactly"),
    ("glass.wgsl", "back_face_exit", "a mesh's exit from its back faces; the reference meets its triangles"),
    ("common.wgsl", "is_nonfinite", "the NaN/∞ test on f32 bits; f64 code uses f64::is_finite"),
    ("common.wgsl", "any_nonfinite", "the debug view's test of a colour, built on is_nonfinite"),
    ("surface.wgsl", "sample_slot", "samples a GPU texture; its f64 side is scene::Texture::sample_as"),
    ("surface.wgsl", "base_color_texel", "samples the GPU texture; its f64 side is scene::Texture::sample"),
    ("surface.wgsl", "metal_roughness_texel", "samples the GPU texture; its f64 side is Texture::sample_as"),
    ("surface.wgsl", "occlusion_texel", "samples the GPU texture; its f64 side is Texture::sample_as"),
    ("surface.wgsl", "emissive_texel", "samples the GPU texture; its f64 side is Texture::sample"),
    ("surface.wgsl", "normal_texel", "samples the GPU texture; its f64 side is Texture::sample_as"),
    ("shading.wgsl", "pixel_normal", "the interpolants' normal; its f64 side is Material::normal_at"),
    ("shading.wgsl", "pixel_emission", "the interpolants' emission; its f64 side is Material::surface_at"),
    ("shading.wgsl", "object_surface", "the uniforms' material; the reference reads scene::Material"),
    ("shading.wgsl", "pixel_surface", "the interpolants' tint; its f64 side is Material::surface_at"),
    ("shading.wgsl", "pixel_tint", "the interpolants' tint; its f64 side is Material::surface_at"),
    ("shading.wgsl", "lit_split", "the per-vertex modes' colour layout; the reference lights every pixel"),
    ("shading.wgsl", "write_lit", "the lighting pass's output; the reference lights every pixel exactly"),
    ("shading.wgsl", "lit_count", "the lighting pass's chunk size; the reference has no passes"),
    ("shading.wgsl", "read_lit", "the vertex stage's input; the reference lights every pixel exactly"),
    ("entry_points.wgsl", "per_vertex_pixel", "the per-vertex modes' tinted colour; the reference lights every pixel"),
    ("shading.wgsl", "finish", "the debug view that paints non-finite pixels; the reference has none"),
    ("shading.wgsl", "to_world", "the object transform; its f64 side is scene::Transform::matrix"),
    ("shading.wgsl", "normal_to_world", "the normal transform; its f64 side is Transform::normal_matrix"),
    ("entry_points.wgsl", "gouraud_vertex", "Gouraud's vertex stage; the reference lights every pixel exactly"),
    ("entry_points.wgsl", "phong_vertex", "Phong shading's vertex stage; the reference lights every pixel exactly"),
    ("screen_space.wgsl", "screen_or_perspective", "the rasterizer's screen-space interpolant; the reference has none"),
    ("shading.wgsl", "vertex_seed", "the shadow filter's noise seed; the reference traces exact shadow rays"),
    ("shadows.wgsl", "shadow_rotation", "the soft filters' per-pixel noise; the reference has no filter"),
    ("shadows.wgsl", "shadow_compare", "samples the shadow map; the reference traces rays instead"),
    ("shadows.wgsl", "shadow_compare_hard", "samples the shadow map (nearest); the reference traces rays"),
    ("shadows.wgsl", "shadow_compare_pcf", "samples the shadow map (2×2); the reference traces rays"),
    ("shadows.wgsl", "shadow_compare_poisson", "samples the shadow map (Poisson); the reference traces rays"),
    (
        "shadows.wgsl",
        "shadow_compare_pcss",
        "samples the shadow map (PCSS); the reference traces rays to the light's area",
    ),
    ("shadows.wgsl", "poisson_tap", "the soft filters' tap pattern; the reference has no filter"),
    ("shadows.wgsl", "pcss_search_tap", "PCSS's blocker-search pattern; the reference has no filter"),
    ("shadows.wgsl", "pcss_filter_tap", "PCSS's filter pattern; the reference has no filter"),
    ("shadows.wgsl", "shadow_visibility", "looks the point up in a shadow map; the reference traces a shadow ray"),
];

/// Names of the functions a WGSL (or Rust) source declares: `fn name(` at the start of a line,
/// after any `pub`, `pub(crate)`, `pub(super)` or attribute-free indentation.
fn declared(src: &str) -> Vec<String> {
    src.lines()
        .filter_map(|line| {
            let t = line.trim_start();
            let t = ["pub(crate) ", "pub(super) ", "pub "].iter().find_map(|p| t.strip_prefix(p)).unwrap_or(t);
            let rest = t.strip_prefix("fn ")?;
            let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            (!name.is_empty()).then_some(name)
        })
        .collect()
}

fn wgsl_file(name: &str) -> &'static str {
    FILES.iter().find(|(n, _)| *n == name).unwrap_or_else(|| panic!("{name} is not among shaders::FILES")).1
}

#[test]
fn every_wgsl_function_has_a_rust_twin() {
    let module = parse(&lighting_source());
    let entry_points: Vec<&str> = module.entry_points.iter().map(|e| e.name.as_str()).collect();
    let functions: Vec<String> = module.functions.iter().filter_map(|(_, f)| f.name.clone()).collect();
    // The line scan finds exactly the functions naga sees, so no function escapes the check.
    let mut scanned: Vec<String> = TWINS.iter().flat_map(|(w, _)| declared(wgsl_file(w))).collect();
    scanned.retain(|f| !entry_points.contains(&f.as_str()));
    let (mut a, mut b) = (scanned.clone(), functions.clone());
    a.sort();
    b.sort();
    assert_eq!(a, b, "functions found by the line scan vs naga's");
    assert_eq!(TWINS.map(|t| t.0), FILES.map(|f| f.0), "one twin per shipped WGSL file");

    let mut missing = Vec::new();
    for (wgsl, rust) in TWINS {
        let rust_fns = declared(rust);
        for f in declared(wgsl_file(wgsl)) {
            if entry_points.contains(&f.as_str()) || NO_TWIN.iter().any(|(w, n, _)| *w == wgsl && *n == f) {
                continue;
            }
            if !rust_fns.contains(&f) {
                missing.push(format!("{wgsl}: fn {f} has no twin in lighting/{}", wgsl.replace(".wgsl", ".rs")));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
    // The exceptions name real functions of their files (the list does not go stale).
    for (wgsl, f, why) in NO_TWIN {
        assert!(declared(wgsl_file(wgsl)).iter().any(|d| d == f), "{wgsl} has no fn {f} (listed: {why})");
    }
}

/// The value of a named `const` in the module, as f64.
fn wgsl_constant(module: &naga::Module, name: &str) -> Option<f64> {
    let (_, c) = module.constants.iter().find(|(_, c)| c.name.as_deref() == Some(name))?;
    match module.global_expressions[c.init] {
        naga::Expression::Literal(naga::Literal::F32(v)) => Some(v as f64),
        naga::Expression::Literal(naga::Literal::U32(v)) => Some(v as f64),
        naga::Expression::Literal(naga::Literal::AbstractFloat(v)) => Some(v),
        ref e => panic!("{name}: unexpected initializer {e:?}"),
    }
}

/// `(name, type)` of the `const` declarations of a WGSL source, by a line scan.
fn wgsl_consts(src: &str) -> Vec<(String, String)> {
    src.lines()
        .filter_map(|line| {
            let rest = line.strip_prefix("const ")?;
            let (name, rest) = rest.split_once(':')?;
            let ty = rest.split('=').next()?.trim();
            Some((name.trim().to_string(), ty.to_string()))
        })
        .collect()
}

#[test]
fn wgsl_guards_equal_rust_guards() {
    let module = parse(&terms_source());
    for (name, value) in shadelab_model::guards::ALL {
        let w = wgsl_constant(&module, name).unwrap_or_else(|| panic!("{name} missing from common.wgsl"));
        assert_eq!(w as f32, *value as f32, "{name}: WGSL {w} vs Rust {value}");
    }
    // Every f32 constant of common.wgsl and surface.wgsl is a guard with its reason in guards.rs.
    for (name, ty) in ["common.wgsl", "surface.wgsl"].into_iter().flat_map(|f| wgsl_consts(wgsl_file(f))) {
        if ty == "f32" {
            assert!(shadelab_model::guards::ALL.iter().any(|(g, _)| *g == name), "{name} is not in guards::ALL");
        }
    }
    assert_eq!(wgsl_constant(&module, "MAX_LIGHTS"), Some(shadelab_model::scene::MAX_LIGHTS as f64));
}

/// The shadow constants `shaders/shadows.wgsl` repeats equal `shadows::WGSL_TWINS`, every `f32` or
/// `u32` constant there is one of them or a filter code, and the filter codes equal `code()`.
#[test]
fn wgsl_shadow_constants_equal_rust() {
    use shadelab_model::shadows::{ShadowFilter, WGSL_TWINS};
    let module = parse(&lighting_source());
    for (name, value) in WGSL_TWINS {
        let w = wgsl_constant(&module, name).unwrap_or_else(|| panic!("{name} missing from shadows.wgsl"));
        assert_eq!(w as f32, value as f32, "{name}: WGSL {w} vs Rust {value}");
    }
    let codes: Vec<(String, u32)> =
        ShadowFilter::ALL.iter().map(|(n, f)| (code_name("SHADOW_FILTER", n), f.code())).collect();
    for (name, code) in &codes {
        assert_eq!(wgsl_constant(&module, name), Some(*code as f64), "{name}: WGSL vs ShadowFilter::code");
    }
    for (name, ty) in ["shadows.wgsl", "shadow_math.wgsl"].into_iter().flat_map(|f| wgsl_consts(wgsl_file(f))) {
        if ty == "f32" || ty == "u32" {
            let known = WGSL_TWINS.iter().any(|(n, _)| *n == name) || codes.iter().any(|(n, _)| *n == name);
            assert!(known, "{name} in shadows.wgsl is neither in shadows::WGSL_TWINS nor a filter code");
        }
    }
}

/// `PREFIX_NAME` for a named value: `cook-torrance` → `SPECULAR_COOK_TORRANCE`.
fn code_name(prefix: &str, name: &str) -> String {
    format!("{prefix}_{}", name.to_ascii_uppercase().replace('-', "_"))
}

#[test]
fn wgsl_codes_equal_rust_codes() {
    let module = parse(&terms_source());
    let mut rust: Vec<(String, u32)> = Vec::new();
    rust.extend(LightKind::ALL.iter().map(|(n, k)| (code_name("LIGHT", n), k.code())));
    rust.extend(FalloffForm::ALL.iter().map(|(n, f)| (code_name("FALLOFF", n), f.code())));
    rust.extend(SpecularModel::ALL.iter().map(|(n, s)| (code_name("SPECULAR", n), s.code())));
    rust.extend(IlluminationModel::ALL.iter().map(|(n, s)| (code_name("ILLUMINATION", n), s.code())));
    rust.extend(Distribution::ALL.iter().map(|(n, d)| (code_name("DISTRIBUTION", n), d.code())));
    rust.extend(Masking::ALL.iter().map(|(n, g)| (code_name("MASKING", n), g.code())));
    rust.extend(Fresnel::ALL.iter().map(|(n, f)| (code_name("FRESNEL", n), f.code())));
    rust.push(("MICROFACET_CHAPTER".into(), Microfacet::CHAPTER.code()));
    rust.push(("MICROFACET_GLTF".into(), Microfacet::GLTF.code()));
    rust.push((
        "MICROFACET_MULTIPLE_SCATTERING".into(),
        shadelab_model::lighting::microfacet::MICROFACET_MULTIPLE_SCATTERING,
    ));
    rust.push(("MICROFACET_FRESNEL_MIX".into(), shadelab_model::lighting::microfacet::MICROFACET_FRESNEL_MIX));
    let field_bits = shadelab_model::lighting::microfacet::MICROFACET_FIELD_BITS;
    rust.push(("MICROFACET_FIELD_BITS".into(), field_bits));
    rust.push(("MICROFACET_FIELD_MASK".into(), (1 << field_bits) - 1));
    for (name, code) in &rust {
        assert_eq!(wgsl_constant(&module, name), Some(*code as f64), "{name}: WGSL vs Rust code()");
    }
    // Every u32 code of the WGSL with one of these prefixes has its Rust value.
    for (name, ty) in FILES.iter().flat_map(|(_, src)| wgsl_consts(src)) {
        let coded = [
            "LIGHT_",
            "FALLOFF_",
            "SPECULAR_",
            "ILLUMINATION_",
            "DISTRIBUTION_",
            "MASKING_",
            "FRESNEL_",
            "MICROFACET_",
        ]
        .iter()
        .any(|p| name.starts_with(p));
        if ty == "u32" && coded {
            assert!(rust.iter().any(|(n, _)| *n == name), "{name} has no Rust code()");
        }
    }
    // The object's texture-slot bits (`textures::MAP_BITS`, slot 0 has no WGSL name: the base
    // colour texture is sampled whenever its effect is in).
    let lighting = parse(&lighting_source());
    for (name, bit) in ["MAP_METAL_ROUGHNESS", "MAP_OCCLUSION", "MAP_EMISSIVE", "MAP_NORMAL"]
        .into_iter()
        .zip(&crate::textures::MAP_BITS[1..])
    {
        assert_eq!(wgsl_constant(&lighting, name), Some(*bit as f64), "{name}: WGSL vs textures::MAP_BITS");
    }
    // The compensation's table: its shape, as ms_table.rs lays it out, generated into the
    // WGSL and written by no shipped file (a hand-written copy could fall behind the tables).
    use shadelab_model::lighting::ms_table::{MS_PAIRS, MS_TABLE_SIDE, MS_TABLE_VEC4S};
    for (name, value) in crate::shaders::generated_constants() {
        assert_eq!(wgsl_constant(&lighting, name), Some(value as f64), "{name}: the generated constant");
        let written: Vec<&str> =
            FILES.iter().filter(|(_, src)| wgsl_consts(src).iter().any(|(n, _)| n == name)).map(|f| f.0).collect();
        assert!(written.is_empty(), "{name} is generated; {written:?} must not define it");
    }
    assert_eq!(wgsl_constant(&lighting, "MS_TABLE_SIDE"), Some(MS_TABLE_SIDE as f64));
    assert_eq!(wgsl_constant(&lighting, "MS_PAIRS"), Some(MS_PAIRS as f64));
    assert_eq!(wgsl_constant(&lighting, "MS_TABLE_VEC4S"), Some(MS_TABLE_VEC4S as f64));
    assert!(MS_PAIRS * MS_TABLE_SIDE * MS_TABLE_SIDE <= 4 * MS_TABLE_VEC4S);
    // The prefiltered levels' shape, as environment.rs lays it out.
    use shadelab_model::lighting::environment::{ENV_LEVEL_WIDTH, ENV_LEVELS};
    assert_eq!(wgsl_constant(&lighting, "ENV_LEVELS"), Some(ENV_LEVELS as f64));
    assert_eq!(wgsl_constant(&lighting, "ENV_LEVEL_WIDTH"), Some(ENV_LEVEL_WIDTH as f64));
    let vec4s = shadelab_model::lighting::environment::ENV_SPLIT_B_VEC4S;
    assert_eq!(wgsl_constant(&lighting, "ENV_SPLIT_B_VEC4S"), Some(vec4s as f64));
    assert!(MS_PAIRS * MS_TABLE_SIDE * MS_TABLE_SIDE <= 4 * vec4s);
    // The SH basis's factors, as environment.rs writes them, to f32.
    use shadelab_model::lighting::environment::{SH_Y0, SH_Y1, SH_Y2, SH_Y20, SH_Y22};
    for (name, v) in [("SH_Y0", SH_Y0), ("SH_Y1", SH_Y1), ("SH_Y2", SH_Y2), ("SH_Y20", SH_Y20), ("SH_Y22", SH_Y22)] {
        assert_eq!(wgsl_constant(&lighting, name), Some(v as f32 as f64), "{name}: WGSL vs environment.rs");
    }
    // The occlusion grid's lookup guards, as occlusion.rs names them, to f32.
    use shadelab_model::lighting::occlusion::{OCC_COORD_MAX, OCC_LOOKUP_CELLS, OCC_WEIGHT_MIN};
    for (name, v) in
        [("OCC_LOOKUP_CELLS", OCC_LOOKUP_CELLS), ("OCC_WEIGHT_MIN", OCC_WEIGHT_MIN), ("OCC_COORD_MAX", OCC_COORD_MAX)]
    {
        assert_eq!(wgsl_constant(&lighting, name), Some(v as f32 as f64), "{name}: WGSL vs occlusion.rs");
    }
    // Codes are distinct within a kind.
    for prefix in ["LIGHT_", "FALLOFF_", "SPECULAR_", "ILLUMINATION_", "DISTRIBUTION_", "MASKING_", "FRESNEL_"] {
        let mut codes: Vec<u32> = rust.iter().filter(|(n, _)| n.starts_with(prefix)).map(|(_, c)| *c).collect();
        let len = codes.len();
        codes.sort();
        codes.dedup();
        assert_eq!(codes.len(), len, "{prefix}* codes repeat");
    }
}

/// The uniform carries the values the model derives for both sides (cone cosines, spot axis,
/// radiance), not a second computation of them.
#[test]
fn a_light_is_packed_from_the_models_derived_values() {
    use glam::DVec3;
    let l = shadelab_model::Light::spot(
        DVec3::new(1.0, 3.0, 0.5),
        DVec3::new(0.2, -2.0, 0.1),
        [1.0, 0.5, 0.25],
        2.0,
        0.1,
        (0.3, 0.6),
    );
    let u = crate::uniforms::LightUniform::new(&l);
    let (ci, co) = l.cone_cosines();
    assert_eq!((u.cos_inner, u.cos_outer), (ci as f32, co as f32));
    assert_eq!(u.spot_axis, l.spot_axis().as_vec3().extend(0.0).to_array());
    assert_eq!(u.radiance, [2.0, 1.0, 0.5, 1.0]);
    assert_eq!((u.kind, u.falloff_form), (LightKind::Spot.code(), FalloffForm::Quadratic.code()));
}

/// The transmission terms' constants (their functions' twins are held by
/// `every_wgsl_function_has_a_rust_twin`): the rule's thresholds, the regime codes, the shape
/// codes, the glass views and the background equal the model's.
#[test]
fn the_transmission_constants_equal_the_models() {
    use shadelab_model::lighting::transmission::{
        ABSORPTION_LINEAR_BELOW, ABSORPTION_NEGLECT_BELOW, AbsorptionForm as F,
    };
    let module = parse(&crate::sweep::sweep_source());
    assert_eq!(wgsl_constant(&module, "ABSORPTION_NEGLECT_BELOW"), Some(ABSORPTION_NEGLECT_BELOW as f32 as f64));
    assert_eq!(wgsl_constant(&module, "ABSORPTION_LINEAR_BELOW"), Some(ABSORPTION_LINEAR_BELOW as f32 as f64));
    for (name, form) in
        [("ABSORPTION_EXACT", F::Exact), ("ABSORPTION_LINEAR", F::Linear), ("ABSORPTION_NEGLECTED", F::Neglected)]
    {
        assert_eq!(wgsl_constant(&module, name), Some(form as u32 as f64), "{name}: AbsorptionForm's code");
        assert_eq!(form.code(), form as u32);
    }
    use shadelab_model::scene::Shape;
    for (name, shape) in [
        ("SHAPE_SPHERE", Shape::Sphere),
        ("SHAPE_CYLINDER", Shape::Cylinder),
        ("SHAPE_CUBE", Shape::Cube),
        ("SHAPE_PLANE", Shape::Plane),
        ("SHAPE_PYRAMID", Shape::Pyramid),
        ("SHAPE_MESH", Shape::Mesh(0)),
    ] {
        assert_eq!(wgsl_constant(&module, name), Some(shape.exit_code() as f64), "{name}: Shape::exit_code");
    }
    use shadelab_model::lighting::transmission::GlassView;
    let lit = parse(&lighting_source());
    for (name, view) in [
        ("GLASS_VIEW_TIR", GlassView::Tir),
        ("GLASS_VIEW_PATH", GlassView::Path),
        ("GLASS_VIEW_REGIME", GlassView::Regime),
    ] {
        assert_eq!(wgsl_constant(&lit, name), Some(view.code() as f64), "{name}: GlassView::code");
    }
    assert_eq!(wgsl_constant(&lit, "GLASS_VIEW_SHIFT"), Some(crate::uniforms::GLASS_VIEW_SHIFT as f64));
    let glass = wgsl_file("glass.wgsl");
    let background = shadelab_model::scene::BACKGROUND.map(|c| c as f32);
    let line = format!(
        "const GLASS_BACKGROUND: vec3<f32> = vec3({:?}, {:?}, {:?});",
        background[0], background[1], background[2]
    );
    assert!(glass.contains(&line), "glass.wgsl's background is scene::BACKGROUND: {line}");
}

/// The renderer writes the constant tables for exactly the effects whose code reads them: the
/// condition that wraps `ms_table.wgsl` (the tables' lookups) names `TABLE_EFFECTS`' defines.
#[test]
fn the_table_effects_are_ms_tables_condition() {
    let condition =
        wgsl_file("ms_table.wgsl").lines().find(|l| l.starts_with("#if ")).expect("ms_table.wgsl is one #if");
    let defines: Vec<&str> = crate::renderer::TABLE_EFFECTS.iter().map(|e| e.define().expect("simulated")).collect();
    assert_eq!(condition.trim_start_matches("#if ").split("||").collect::<Vec<_>>(), defines);
}
