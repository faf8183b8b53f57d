//! The WGSL sources under `shaders/`, compiled into the binary and assembled in dependency order,
//! and the preprocessor that cuts one effect permutation out of them (the defines come from
//! `shadelab_model::effects::DECLARED`).
//!
//! The renderer, the naga validation tests and the stability sweep (`sweep::sweep_source`) all
//! use these same files.

use shadelab_model::effects::EffectKey;

/// `(file name, source)` in the order they are concatenated.
pub const FILES: [(&str, &str); 23] = [
    ("common.wgsl", include_str!("../../../shaders/common.wgsl")),
    ("brdf.wgsl", include_str!("../../../shaders/brdf.wgsl")),
    // Cook–Torrance's D, G and F, each selected by the material's code.
    ("microfacet.wgsl", include_str!("../../../shaders/microfacet.wgsl")),
    // The lobe's multiple-scattering compensation (its table lookup is in ms_table.wgsl).
    ("multiscatter.wgsl", include_str!("../../../shaders/multiscatter.wgsl")),
    ("models.wgsl", include_str!("../../../shaders/models.wgsl")),
    ("lights.wgsl", include_str!("../../../shaders/lights.wgsl")),
    // Only in permutations with area lights (the whole file is one `#if EFFECT_AREA_LIGHTS`).
    ("area_lights.wgsl", include_str!("../../../shaders/area_lights.wgsl")),
    // Only in permutations with area lights drawn as k point sources (`#if EFFECT_AREA_POINTS`).
    ("area_points.wgsl", include_str!("../../../shaders/area_points.wgsl")),
    // Only in permutations with the area lights' LTC specular (`#if EFFECT_AREA_LTC`); its table
    // lookup is ms_table.wgsl's.
    ("ltc.wgsl", include_str!("../../../shaders/ltc.wgsl")),
    // The shadow projection math, without bindings (the sweep runs it): with cast shadows only.
    ("shadow_math.wgsl", include_str!("../../../shaders/shadow_math.wgsl")),
    // C and μ at a point: the material tinted by vertex colours and textures.
    ("surface.wgsl", include_str!("../../../shaders/surface.wgsl")),
    // Light through a surface: only in permutations with transparent objects (and the sweep).
    ("transmission.wgsl", include_str!("../../../shaders/transmission.wgsl")),
    // The shading module's uniform structs and layout constants, then its bindings: after the
    // terms above, which `terms_source` gives compute passes that bind their own.
    ("types.wgsl", include_str!("../../../shaders/types.wgsl")),
    ("bindings.wgsl", include_str!("../../../shaders/bindings.wgsl")),
    // The compensation's table in the globals: with the multiple-scattering effect only.
    ("ms_table.wgsl", include_str!("../../../shaders/ms_table.wgsl")),
    // The environment's SH terms in the globals: with the environment effect only.
    ("environment.wgsl", include_str!("../../../shaders/environment.wgsl")),
    // The environment's occlusion grid: with the occlusion effect only.
    ("occlusion.wgsl", include_str!("../../../shaders/occlusion.wgsl")),
    // Only in permutations with cast shadows (the whole file is one `#if EFFECT_CAST_SHADOWS`).
    ("shadows.wgsl", include_str!("../../../shaders/shadows.wgsl")),
    // The model at a point and the material at a pixel: the functions the entry points call.
    ("shading.wgsl", include_str!("../../../shaders/shading.wgsl")),
    // The mesh passes' entry points: the lighting passes, the three modes, baseline and shadow pass.
    ("entry_points.wgsl", include_str!("../../../shaders/entry_points.wgsl")),
    // Gouraud's and Phong shading's stages with screen-space interpolation.
    ("screen_space.wgsl", include_str!("../../../shaders/screen_space.wgsl")),
    // The environment as the background: only in permutations with its effect.
    ("background.wgsl", include_str!("../../../shaders/background.wgsl")),
    // The glass pass's entry points: only in permutations with transparent objects.
    ("glass.wgsl", include_str!("../../../shaders/glass.wgsl")),
];

mod preprocess;
pub use preprocess::preprocess;

fn uber_defines() -> Vec<&'static str> {
    EffectKey::UBER.defines()
}

/// Constants, guards and the lighting terms with every effect, without entry points (for compute
/// passes that evaluate the terms directly; the one texture binding of `surface` goes unused):
/// `common`, `brdf`, `microfacet`, `multiscatter`, `models`, `lights`, `area_lights`, `area_points`,
/// `ltc`, `shadow_math`, `surface` and `transmission`: the files before `types.wgsl`.
pub fn terms_source() -> String {
    uber_files_before("types.wgsl")
}

/// The terms with the globals and bindings they read, through the environment's functions
/// (`environment.wgsl`, `occlusion.wgsl`) and the shadow maps' (whose file holds a constant the
/// uniform structs size an array by), with every effect and no entry points: the module the
/// environment's sweep appends its kernel to, so that it reads the environment as the renderer
/// binds it.
pub fn environment_terms_source() -> String {
    uber_files_before("shading.wgsl")
}

/// The shipped files before `file`, after the generated constants, concatenated and
/// preprocessed with every effect.
fn uber_files_before(file: &str) -> String {
    let end = FILES.iter().position(|(name, _)| *name == file).expect("a shipped file");
    let raw = assemble(FILES[..end].iter().map(|(_, s)| *s));
    preprocess(&raw, &uber_defines()).expect("the shipped WGSL preprocesses")
}

/// The renderer's WGSL as shipped, before preprocessing.
pub fn raw_lighting_source() -> String {
    assemble(FILES.iter().map(|(_, s)| *s))
}

/// The counts and table sizes the WGSL shares with the model, as WGSL constants generated from
/// the model's term tables: no file writes them, so a new D, G or F term cannot leave a stale
/// copy behind.
pub fn generated_constants() -> Vec<(&'static str, usize)> {
    use shadelab_model::lighting::microfacet::{Distribution, Fresnel, Masking};
    use shadelab_model::lighting::{environment::ENV_SPLIT_B_VEC4S, ltc, ms_table};
    use shadelab_model::params::NamedValue;
    vec![
        ("DISTRIBUTION_COUNT", Distribution::ALL.len()),
        ("MASKING_COUNT", Masking::ALL.len()),
        ("FRESNEL_COUNT", Fresnel::ALL.len()),
        ("MS_PAIRS", ms_table::MS_PAIRS),
        ("MS_TABLE_SIDE", ms_table::MS_TABLE_SIDE),
        ("MS_TABLE_VEC4S", ms_table::MS_TABLE_VEC4S),
        ("ENV_SPLIT_B_VEC4S", ENV_SPLIT_B_VEC4S),
        ("LTC_TABLE_SIDE", ltc::LTC_TABLE_SIDE),
        ("LTC_TABLE_VEC4S", ltc::LTC_TABLE_VEC4S),
    ]
}

/// Blinn–Phong's Λ quadrature (t, w) as a WGSL constant, from the f64 twin's table, so that both
/// integrate with the same nodes.
fn blinn_phong_lambda_nodes() -> String {
    use shadelab_model::lighting::microfacet::BLINN_PHONG_LAMBDA_NODES as NODES;
    let items: Vec<String> = NODES.iter().map(|[t, w]| format!("vec2({:?}, {:?})", *t as f32, *w as f32)).collect();
    format!("const BLINN_PHONG_LAMBDA_NODES = array<vec2<f32>, {}>({});\n", NODES.len(), items.join(", "))
}

/// The generated constants, then `files`, one after another.
fn assemble<'a>(files: impl Iterator<Item = &'a str>) -> String {
    let mut out = String::from("// Generated from the model's term tables (shaders.rs, generated_constants).\n");
    for (name, value) in generated_constants() {
        out += &format!("const {name}: u32 = {value}u;\n");
    }
    out += &blinn_phong_lambda_nodes();
    // The circumradius of the disk's equal-area polygon per unit radius (area.rs).
    let scale = shadelab_model::lighting::area::disk_polygon_scale() as f32;
    out += &format!("const DISK_POLYGON_SCALE: f32 = {scale:?};\n");
    out + &files.collect::<Vec<_>>().join("\n")
}

/// The renderer module of one effect permutation: terms plus the shading entry points, holding
/// only the effects of `key`.
pub fn lighting_source_for(raw: &str, key: EffectKey) -> Result<String, String> {
    preprocess(raw, &key.defines())
}

/// The shipped renderer module with every effect (the "uber" permutation).
pub fn lighting_source() -> String {
    lighting_source_for(&raw_lighting_source(), EffectKey::UBER).expect("the shipped WGSL preprocesses")
}

/// Check a raw (unpreprocessed) renderer source: it preprocesses, and its permutation with every
/// effect and the one with none both validate in naga (hot reload runs this before using it).
pub fn validate_raw(raw: &str) -> Result<(), String> {
    for key in [EffectKey::UBER, EffectKey::NONE] {
        validate(&lighting_source_for(raw, key)?)?;
    }
    Ok(())
}

/// Parse and validate a WGSL module with naga; the error is naga's own message, with the
/// offending line shown.
pub fn validate(source: &str) -> Result<(), String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
        .validate(&module)
        .map_err(|e| e.emit_to_string(source))?;
    Ok(())
}

/// The renderer's raw WGSL read from a folder holding the files of [`FILES`] (hot reload).
pub fn read_lighting_source(dir: &std::path::Path) -> std::io::Result<String> {
    let mut parts = Vec::new();
    for (name, _) in FILES {
        parts.push(std::fs::read_to_string(dir.join(name))?);
    }
    Ok(assemble(parts.iter().map(String::as_str)))
}

/// The newest modification time among those files (to notice an edit).
pub fn newest_change(dir: &std::path::Path) -> Option<std::time::SystemTime> {
    FILES.iter().filter_map(|(name, _)| std::fs::metadata(dir.join(name)).and_then(|m| m.modified()).ok()).max()
}

/// Entry points of a shading mode with an interpolation: (vertex, fragment). Screen-space
/// interpolation has its own Gouraud and Phong stages (`@interpolate(linear)`); flat has none.
pub fn entry_points_with(
    mode: shadelab_model::ShadingMode,
    interpolation: shadelab_model::Interpolation,
) -> (&'static str, &'static str) {
    use shadelab_model::ShadingMode::*;
    match (mode, interpolation) {
        (Gouraud, shadelab_model::Interpolation::Screen) => ("vs_gouraud_screen", "fs_gouraud_screen"),
        (Phong, shadelab_model::Interpolation::Screen) => ("vs_phong_screen", "fs_phong_screen"),
        _ => entry_points(mode),
    }
}

/// Entry points of a shading mode: (vertex, fragment).
pub fn entry_points(mode: shadelab_model::ShadingMode) -> (&'static str, &'static str) {
    use shadelab_model::ShadingMode::*;
    match mode {
        Flat => ("vs_flat", "fs_flat"),
        Gouraud => ("vs_gouraud", "fs_gouraud"),
        Phong => ("vs_phong", "fs_phong"),
    }
}

/// Entry points of the null-shader baseline (constant colour): (vertex, fragment).
pub const BASELINE_ENTRY_POINTS: (&str, &str) = ("vs_baseline", "fs_baseline");

/// The per-face lighting pass's entry point (`lighting_pass.rs`).
pub const FLAT_ENTRY_POINT: &str = "cs_flat";
/// The per-vertex lighting pass's entry point.
pub const GOURAUD_ENTRY_POINT: &str = "cs_gouraud";

/// The lighting pass's entry point of a shading mode (`None`: Phong shading lights per pixel).
pub fn lighting_entry_point(shading: shadelab_model::ShadingMode) -> Option<&'static str> {
    use shadelab_model::ShadingMode::*;
    match shading {
        Flat => Some(FLAT_ENTRY_POINT),
        Gouraud => Some(GOURAUD_ENTRY_POINT),
        Phong => None,
    }
}

#[cfg(test)]
mod effect_structure_tests;
#[cfg(test)]
pub(crate) mod tests;
#[cfg(test)]
mod validated_before;
