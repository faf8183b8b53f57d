//! The twin of `shaders/shading.wgsl`: the Phong illumination model summed over the lights at
//! one point (docs/model.md §3, §8), each light weighted by how much of it reaches the point
//! (its cast shadow, docs/model.md §0). The GPU's transforms, entry points and debug view have no
//! f64 twin here (see the exception list of `every_wgsl_function_has_a_rust_twin`).

use super::brdf::{SpecularModel, fresnel_v_from_mu, light_contribution};
use super::common::safe_normalize;
use super::lights::{Light, MAX_LIGHTS, light_sample};
use crate::scene::Material;
use glam::DVec3;

/// docs/model.md §3: the Phong illumination model `I_a + Σ I_L (r_d C (N·L) + r_s S)` at world
/// point `p` with (not necessarily unit) normal `n_in`, seen from `eye`, every light reaching it.
pub fn shade(
    p: DVec3,
    n_in: DVec3,
    eye: DVec3,
    mat: &Material,
    lights: &[Light],
    ambient: [f64; 3],
    specular: SpecularModel,
) -> [f64; 3] {
    shade_with_visibility(p, n_in, eye, mat, lights, ambient, specular, |_, _, _| 1.0)
}

/// [`shade`] with each light's term scaled by `visibility(i, light, l)`, the share of light `i`
/// that reaches `p` along the unit direction `l` to it (1: lit, 0: in a cast shadow). It is
/// asked only of lights that would add something (a non-zero term), so a point in its own
/// shadow (N·L ≤ 0) costs no shadow query; a visibility of 1 adds the term exactly as `shade`.
#[allow(clippy::too_many_arguments)]
pub fn shade_with_visibility(
    p: DVec3,
    n_in: DVec3,
    eye: DVec3,
    mat: &Material,
    lights: &[Light],
    ambient: [f64; 3],
    specular: SpecularModel,
    mut visibility: impl FnMut(usize, &Light, DVec3) -> f64,
) -> [f64; 3] {
    let v = safe_normalize(eye - p, DVec3::Y);
    let n = safe_normalize(n_in, v);
    let v_index = mat.mu.map(fresnel_v_from_mu);
    let mut total: [f64; 3] = std::array::from_fn(|i| ambient[i] * mat.r_a * mat.color[i]);
    for (k, light) in lights.iter().take(MAX_LIGHTS).enumerate() {
        let (l, radiance) = light_sample(light, p, n);
        let c = light_contribution(l, radiance, n, v, mat, v_index, specular);
        if c == [0.0; 3] {
            continue;
        }
        // A NaN visibility counts as none, like 0.
        let w = visibility(k, light, l).clamp(0.0, 1.0);
        if w.is_nan() || w == 0.0 {
            continue;
        }
        for i in 0..3 {
            total[i] += if w == 1.0 { c[i] } else { c[i] * w };
        }
    }
    total
}
