//! Plain unit tests of the WGSL sources (no GPU): the preprocessor, the uniform structs' layouts
//! and the WGSL compiles (the guards and codes shared with Rust: `twins.rs`).

use super::*;
use crate::uniforms::{GlobalsUniform, LightUniform, ObjectUniform, ShadowLightUniform, ShadowsUniform, TablesUniform};
use std::mem::offset_of;

pub(crate) fn parse(src: &str) -> naga::Module {
    naga::front::wgsl::parse_str(src).unwrap_or_else(|e| panic!("{}", e.emit_to_string(src)))
}

#[test]
fn preprocessor_keeps_and_cuts_blocks() {
    let src = "a\n#if X\nb\n#if Y\nc\n#else\nd\n#endif\n#else\ne\n#endif\nf";
    let lines = |defs: &[&str]| -> Vec<String> {
        preprocess(src, defs).unwrap().lines().filter(|l| !l.is_empty()).map(String::from).collect()
    };
    assert_eq!(lines(&[]), ["a", "e", "f"]);
    assert_eq!(lines(&["X"]), ["a", "b", "d", "f"]);
    assert_eq!(lines(&["X", "Y"]), ["a", "b", "c", "f"]);
    assert_eq!(lines(&["Y"]), ["a", "e", "f"]);
    // Line numbers are kept.
    assert_eq!(preprocess(src, &[]).unwrap().lines().count(), src.lines().count());
    assert!(preprocess("#if X\n", &[]).unwrap_err().contains("line 1: #if without #endif"));
    assert!(preprocess("#endif\n", &[]).unwrap_err().contains("#endif without #if"));
    assert!(preprocess("#else\n", &[]).unwrap_err().contains("#else without #if"));
    assert!(preprocess("#ifdef X\n#endif", &[]).unwrap_err().contains("unknown directive"));
    // Either of two names keeps a block.
    let either = |defs: &[&str]| preprocess("#if X||Y\nb\n#endif", defs).unwrap().contains('b');
    assert!(either(&["X"]) && either(&["Y"]) && either(&["X", "Y"]) && !either(&["Z"]));
}

#[test]
fn preprocessor_inserts_named_blocks_on_one_line() {
    let src = "#block B\n  a, // one\n#if X\n  b,\n#endif\n#endblock\nx {\n#insert B\n}\n#if Y\n#insert B\n#endif";
    let out = |defs: &[&str]| preprocess(src, defs).unwrap();
    // The insert's kept lines, comments dropped, on the insert's own line: line numbers are kept.
    assert_eq!(out(&[]).lines().nth(7), Some("a,"));
    assert_eq!(out(&["X"]).lines().nth(7), Some("a, b,"));
    assert_eq!(out(&["X"]).lines().count(), src.lines().count());
    // An insert inside a cut #if is cut; the block's own lines are never emitted where written.
    assert_eq!(out(&["X"]).lines().filter(|l| l.contains("a,")).count(), 1);
    assert_eq!(out(&["X", "Y"]).lines().filter(|l| l.contains("a,")).count(), 2);
    let err = |s: &str| preprocess(s, &[]).unwrap_err();
    assert!(err("#insert B").contains("line 1: #insert of unknown block B"));
    assert!(err("#block B\na").contains("line 1: #block B without #endblock"));
    assert!(err("#endblock").contains("#endblock without #block"));
    assert!(err("#if X\n#block B\n#endblock\n#endif").contains("line 2: #block inside #if"));
    assert!(err("#block B\n#block C\n#endblock").contains("#block inside block B"));
    assert!(err("#block B\n#if X\n#endblock\n#insert B").contains("line 4: in block B: line 1: #if without #endif"));
    // A block may insert an earlier one, never itself.
    let nested = preprocess("#block A\na\n#endblock\n#block B\n#insert A\nb\n#endblock\n#insert B", &[]).unwrap();
    assert_eq!(nested.lines().nth(7), Some("a b"));
    assert!(
        err("#block A\n#insert A\n#endblock\n#insert A").contains("in block A: line 1: #insert of unknown block A")
    );
}

/// (size, [(field, offset)]) of a WGSL struct as naga lays it out.
fn wgsl_layout(module: &naga::Module, name: &str) -> (u32, Vec<(String, u32)>) {
    let ty = module.types.iter().find(|(_, t)| t.name.as_deref() == Some(name)).unwrap_or_else(|| panic!("{name}"));
    match &ty.1.inner {
        naga::TypeInner::Struct { members, span } => {
            (*span, members.iter().map(|m| (m.name.clone().unwrap(), m.offset)).collect())
        }
        _ => panic!("{name} is not a struct"),
    }
}

macro_rules! rust_layout {
    ($t:ty: $($f:ident),*) => {
        (size_of::<$t>() as u32, vec![$((stringify!($f).to_string(), offset_of!($t, $f) as u32)),*])
    };
}

#[test]
fn uniform_layouts_match_wgsl() {
    let module = parse(&lighting_source());
    assert_eq!(
        wgsl_layout(&module, "Light"),
        rust_layout!(LightUniform: position, direction, radiance, kind, falloff_form, falloff_alpha, d0, spot_axis, cos_inner, cos_outer, range, _pad, normal, tangent, half_x, half_y, area_points, area_specular)
    );
    assert_eq!(
        wgsl_layout(&module, "Globals"),
        rust_layout!(GlobalsUniform: view_proj, camera_pos, ambient, light_count, flags, specular_model, illumination, lights, env_sh, env_occlusion, inv_view_proj)
    );
    assert_eq!(wgsl_layout(&module, "Tables"), rust_layout!(TablesUniform: ms_albedo, env_split_b, ltc));
    assert_eq!(
        wgsl_layout(&module, "Object"),
        rust_layout!(ObjectUniform: model, normal_matrix, color, mu, r_s, r_d, r_a, m, h, mirror, transmission, uv_rotation, mu_tinted, uv_offset_scale, metallic_f0, emission, metal_roughness_uv, occlusion_uv, emissive_uv, uv_rotations, maps, occlusion_strength, normal_scale, phong_normalized, normal_uv, inverse_model, ior, absorption, exit_shape, absorption_form, longest_chord, microfacet, fresnel_mix)
    );
    assert_eq!(
        wgsl_layout(&module, "ShadowLight"),
        rust_layout!(ShadowLightUniform: first_layer, layers, shadow_filter, perspective, texel_world, uv_scale, texel_uv, light_size, near, far, cubes, pcss_taps)
    );
    assert_eq!(wgsl_layout(&module, "Shadows"), rust_layout!(ShadowsUniform: matrices, lights));
}
