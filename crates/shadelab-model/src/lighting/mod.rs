//! The lighting model in f64: the reference the GPU is tested against, one file per WGSL file
//! under `shaders/` with the same function names and the same guards ([`crate::guards`]).
//!
//! - [`common`] ↔ `common.wgsl`: the shared helpers.
//! - [`brdf`] ↔ `brdf.wgsl`: the terms of the illumination model and the specular models.
//! - [`microfacet`] ↔ `microfacet.wgsl`: Cook–Torrance's D, G and F, each chosen by the material.
//! - [`multiscatter`] ↔ `multiscatter.wgsl`: the lobe's multiple-scattering compensation.
//! - [`lights`] ↔ `lights.wgsl`: the light sources, their parameters and falloffs.
//! - [`models`] ↔ `models.wgsl`: the Lambert rule and the four-term sum, and the model choice.
//! - [`area`] ↔ `area_lights.wgsl`, [`area_points`] ↔ `area_points.wgsl`: area lights, exact and
//!   as k point sources; [`ltc`] ↔ `ltc.wgsl`: their specular by linearly transformed cosines,
//!   from [`ltc_table`] (written by the fit, `ltc_fit.rs`).
//! - [`shading`] ↔ `shading.wgsl`: the sum over the lights at one point (and the stages of
//!   `entry_points.wgsl` and `screen_space.wgsl`, whose counterpart is the reference's image).
//! - [`transmission`] ↔ `transmission.wgsl`: light through a surface (Snell, absorption, the
//!   exits of the analytic shapes); the Fresnel factor from either side is [`microfacet`]'s.
//!
//! - [`environment`] ↔ `environment.wgsl`: an environment's diffuse light from nine SH
//!   coefficients; [`env_map`] (the environment light, its radiance and sampling), [`sky`]
//!   (Preetham's sky) and [`env_file`] (HDR and EXR maps) have no WGSL twin.
//! - [`occlusion`] ↔ `occlusion.wgsl`: the environment's occlusion, from a precomputed grid.
//!
//! `shadows.rs` and `shadows/cascades.rs` at the crate root are the twins of `shadow_math.wgsl`
//! and `shadows.wgsl`; `scene/material.rs` and `scene/texture.rs` those of `surface.wgsl`.
//! The test `every_wgsl_function_has_a_rust_twin` (in `shadelab-render`) holds the pairing.

pub mod area;
pub mod area_exact;
pub mod area_points;
pub mod brdf;
pub mod common;
pub mod env_file;
pub mod env_map;
pub mod environment;
pub mod lights;
pub mod ltc;
pub mod ltc_table;
pub mod microfacet;
pub mod models;
pub mod ms_table;
pub mod multiscatter;
pub mod occlusion;
pub mod shading;
pub mod sky;
pub mod transmission;
