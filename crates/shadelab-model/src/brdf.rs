//! The lighting model's f64 terms under one path: the functions of `lighting/`'s twin files
//! ([`crate::lighting`]), re-exported together for callers that use terms of several files.

pub use crate::lighting::brdf::{
    SpecularModel, d_beckmann, diffuse_lambert, fresnel_dielectric, fresnel_v_from_mu, g_cook_torrance,
    light_contribution, specular_cook_torrance, specular_microfacet, specular_phong,
};
pub use crate::lighting::common::safe_normalize;
pub use crate::lighting::lights::{falloff_linear, falloff_quadratic, light_sample, spot_cone, window_range};
pub use crate::lighting::shading::shade;
