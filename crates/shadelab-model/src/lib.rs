//! The shadelab model: scenes, materials, lights, validated parameters, tessellation, and the
//! lighting model in f64 (the reference). No GPU, no window: everything else depends on it.

pub mod assets;
pub mod brdf;
pub mod effects;
pub mod furnace;
pub mod gltf_io;
pub mod guards;
#[cfg(test)]
mod identities;
pub mod lighting;
pub mod lobe;
pub mod ltc_fit;
pub mod mesh;
pub mod mesh_lines;
pub mod params;
pub mod presets;
pub mod reference;
pub mod scene;
pub mod scene_variants;
pub mod shadow_settings;
pub mod shadows;
pub mod terminator;
pub mod terms;

pub use params::{
    AreaSpecular, FalloffForm, IlluminationModel, Interpolation, LightKind, ModelChoice, PhongExponent, ShadingMode,
    SpecularModel,
};
pub use scene::{Camera, Filter, Light, Material, Object, Overrides, Scene, Shape, Texture, Transform, Wrap};
