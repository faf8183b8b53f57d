//! The twin of `shaders/shading.wgsl`: the Phong illumination model summed over the lights at
//! one point (docs/model.md §3, §8). The GPU's transforms, entry points and debug view have no
//! f64 twin here (see the exception list of `every_wgsl_function_has_a_rust_twin`).

use super::brdf::{SpecularModel, fresnel_v_from_mu, light_contribution};
use super::common::safe_normalize;
use super::lights::{Light, MAX_LIGHTS, light_sample};
use crate::scene::Material;
use glam::DVec3;

/// docs/model.md §3: the Phong illumination model `I_a + Σ I_L (r_d C (N·L) + r_s S)` at world
/// point `p` with (not necessarily unit) normal `n_in`, seen from `eye`.
pub fn shade(
    p: DVec3,
    n_in: DVec3,
    eye: DVec3,
    mat: &Material,
    lights: &[Light],
    ambient: [f64; 3],
    specular: SpecularModel,
) -> [f64; 3] {
    let v = safe_normalize(eye - p, DVec3::Y);
    let n = safe_normalize(n_in, v);
    let v_index = mat.mu.map(fresnel_v_from_mu);
    let mut total: [f64; 3] = std::array::from_fn(|i| ambient[i] * mat.r_a * mat.color[i]);
    for light in lights.iter().take(MAX_LIGHTS) {
        let (l, radiance) = light_sample(light, p, n);
        let c = light_contribution(l, radiance, n, v, mat, v_index, specular);
        for i in 0..3 {
            total[i] += c[i];
        }
    }
    total
}
