//! The WGSL sources under `shaders/`, compiled into the binary and assembled in dependency order.
//!
//! The renderer, the naga validation tests and the stability sweep all use these same files.

/// `(file name, source)` in the order they are concatenated.
pub const FILES: [(&str, &str); 4] = [
    ("common.wgsl", include_str!("../../../shaders/common.wgsl")),
    ("brdf.wgsl", include_str!("../../../shaders/brdf.wgsl")),
    ("lights.wgsl", include_str!("../../../shaders/lights.wgsl")),
    ("shading.wgsl", include_str!("../../../shaders/shading.wgsl")),
];

/// Constants, guards and the lighting terms, without bindings or entry points (for compute
/// passes that evaluate the terms directly).
pub fn terms_source() -> String {
    FILES[..3].iter().map(|(_, s)| *s).collect::<Vec<_>>().join("\n")
}

/// The stability sweep's kernel (`shaders/sweep.wgsl`), appended to the terms.
pub const SWEEP_KERNEL: &str = include_str!("../../../shaders/sweep.wgsl");

/// The sweep's compute module: the shipped terms followed by the kernel.
pub fn sweep_source() -> String {
    format!("{}\n{}", terms_source(), SWEEP_KERNEL)
}

/// The whole renderer module: terms plus the shading entry points.
pub fn lighting_source() -> String {
    FILES.iter().map(|(_, s)| *s).collect::<Vec<_>>().join("\n")
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

/// The renderer's WGSL read from a folder holding the files of [`FILES`] (hot reload).
pub fn read_lighting_source(dir: &std::path::Path) -> std::io::Result<String> {
    let mut parts = Vec::new();
    for (name, _) in FILES {
        parts.push(std::fs::read_to_string(dir.join(name))?);
    }
    Ok(parts.join("\n"))
}

/// The newest modification time among those files (to notice an edit).
pub fn newest_change(dir: &std::path::Path) -> Option<std::time::SystemTime> {
    FILES.iter().filter_map(|(name, _)| std::fs::metadata(dir.join(name)).and_then(|m| m.modified()).ok()).max()
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

/// The value of the `SPECULAR_MODEL` override constant for a specular model.
pub fn specular_constant(model: shadelab_model::SpecularModel) -> f64 {
    match model {
        shadelab_model::SpecularModel::Phong => 0.0,
        shadelab_model::SpecularModel::CookTorrance => 1.0,
    }
}

#[cfg(test)]
mod tests {
    //! Plain unit tests (no GPU): every permutation validates in naga, the uniform structs'
    //! layouts and the numerical guards are the same in WGSL and Rust.
    use super::*;
    use crate::uniforms::{GlobalsUniform, LightUniform, ObjectUniform};
    use naga::valid::{Capabilities, ValidationFlags, Validator};
    use shadelab_model::{ShadingMode, SpecularModel};
    use std::mem::offset_of;

    fn parse(src: &str) -> naga::Module {
        naga::front::wgsl::parse_str(src).unwrap_or_else(|e| panic!("{}", e.emit_to_string(src)))
    }

    fn validate(m: &naga::Module) -> naga::valid::ModuleInfo {
        Validator::new(ValidationFlags::all(), Capabilities::default()).validate(m).unwrap_or_else(|e| panic!("{e:?}"))
    }

    #[test]
    fn every_permutation_validates_in_naga() {
        let module = parse(&lighting_source());
        let info = validate(&module);
        for shading in ShadingMode::ALL_MODES {
            let (vs, fs) = entry_points(shading);
            for specular in SpecularModel::ALL_MODELS {
                let mut constants = naga::back::PipelineConstants::default();
                constants.insert("SPECULAR_MODEL".to_string(), specular_constant(specular));
                for (stage, ep) in [(naga::ShaderStage::Vertex, vs), (naga::ShaderStage::Fragment, fs)] {
                    let (m, _) = naga::back::pipeline_constants::process_overrides(
                        &module,
                        &info,
                        Some((stage, ep)),
                        &constants,
                    )
                    .unwrap_or_else(|e| panic!("{shading:?}/{specular:?} {ep}: {e:?}"));
                    assert!(m.entry_points.iter().any(|e| e.name == ep));
                    validate(&m);
                }
            }
        }
        let (vs, fs) = BASELINE_ENTRY_POINTS;
        assert!(module.entry_points.iter().any(|e| e.name == vs) && module.entry_points.iter().any(|e| e.name == fs));
        // The terms alone, and the sweep's compute module, are valid too.
        validate(&parse(&terms_source()));
        validate(&parse(&sweep_source()));
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
            rust_layout!(LightUniform: position, direction, radiance, kind, falloff_form, falloff_alpha, d0)
        );
        assert_eq!(
            wgsl_layout(&module, "Globals"),
            rust_layout!(GlobalsUniform: view_proj, camera_pos, ambient, light_count, flags, _pad0, _pad1, lights)
        );
        assert_eq!(
            wgsl_layout(&module, "Object"),
            rust_layout!(ObjectUniform: model, normal_matrix, color, mu, r_s, r_d, r_a, m, h, mirror, _pad0, _pad1)
        );
    }

    /// The value of a named `const` in the module, as f64.
    pub(crate) fn wgsl_constant(module: &naga::Module, name: &str) -> Option<f64> {
        let (_, c) = module.constants.iter().find(|(_, c)| c.name.as_deref() == Some(name))?;
        match module.global_expressions[c.init] {
            naga::Expression::Literal(naga::Literal::F32(v)) => Some(v as f64),
            naga::Expression::Literal(naga::Literal::U32(v)) => Some(v as f64),
            naga::Expression::Literal(naga::Literal::AbstractFloat(v)) => Some(v),
            ref e => panic!("{name}: unexpected initializer {e:?}"),
        }
    }

    #[test]
    fn wgsl_guards_equal_rust_guards() {
        let module = parse(&terms_source());
        for (name, value) in shadelab_model::guards::ALL {
            let w = wgsl_constant(&module, name).unwrap_or_else(|| panic!("{name} missing from common.wgsl"));
            assert_eq!(w as f32, *value as f32, "{name}: WGSL {w} vs Rust {value}");
        }
        assert_eq!(wgsl_constant(&module, "MAX_LIGHTS"), Some(shadelab_model::scene::MAX_LIGHTS as f64));
    }
}
