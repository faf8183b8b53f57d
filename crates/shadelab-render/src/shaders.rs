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

/// The whole renderer module: terms plus the shading entry points.
pub fn lighting_source() -> String {
    FILES.iter().map(|(_, s)| *s).collect::<Vec<_>>().join("\n")
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

/// The value of the `SPECULAR_MODEL` override constant for a specular model.
pub fn specular_constant(model: shadelab_model::SpecularModel) -> f64 {
    match model {
        shadelab_model::SpecularModel::Phong => 0.0,
        shadelab_model::SpecularModel::CookTorrance => 1.0,
    }
}
