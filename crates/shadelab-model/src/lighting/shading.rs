//! The twin of `shaders/shading.wgsl`: the chosen illumination model (docs/model.md §1–§3a)
//! summed over the lights at one point (§8), each light weighted by how much of it reaches the
//! point (its cast shadow, docs/model.md §0). The GPU's transforms, entry points and debug view have no
//! f64 twin here (see the exception list of `every_wgsl_function_has_a_rust_twin`).

use super::area_points::{area_emitter, area_point_count, area_point_sample};
use super::brdf::{SpecularModel, fresnel_v_from_mu, light_contribution};
use super::common::safe_normalize;
use super::environment::{ShCoefficients, env_sh_radiance, env_specular};
use super::lights::{AreaSpecular, Light, LightSample, MAX_LIGHTS, light_radiance_at, light_sample};
use super::microfacet::Microfacet;
use super::models::{IlluminationModel, lambert_rule_fill, lambert_rule_lit, sum_contribution, transmitted_term};
use crate::scene::Material;
use glam::{DVec3, DVec4};

/// The illumination model `model` at world point `p` with (not necessarily unit) normal `n_in`,
/// seen from `eye`, every light reaching it; for the Phong model (docs/model.md §3)
/// `I_a + Σ I_L (r_d C (N·L) + r_s S)`.
#[allow(clippy::too_many_arguments)]
pub fn shade(
    p: DVec3,
    n_in: DVec3,
    eye: DVec4,
    mat: &Material,
    lights: &[Light],
    ambient: [f64; 3],
    specular: SpecularModel,
    model: IlluminationModel,
) -> [f64; 3] {
    let at = ShadePoint {
        p,
        n_in,
        eye,
        mat,
        ambient,
        env_sh: None,
        env_prefiltered: None,
        env_occlusion: None,
        specular,
        model,
    };
    shade_exact(&at, lights, |_, _, _, _| 1.0, &mut |_| None)
}

/// Where and how [`shade_exact`] shades.
pub struct ShadePoint<'a> {
    pub p: DVec3,
    pub n_in: DVec3,
    pub eye: DVec4,
    pub mat: &'a Material,
    pub ambient: [f64; 3],
    /// The environment light's nine SH terms, where it is drawn by them (docs/environment.md).
    pub env_sh: Option<&'a ShCoefficients>,
    /// Its prefiltered levels, where its specular is drawn by the split sum.
    pub env_prefiltered: Option<&'a [[f32; 4]]>,
    /// Its occlusion grid, where its diffuse light is occluded by it.
    pub env_occlusion: Option<&'a super::occlusion::OcclusionGrid>,
    pub specular: SpecularModel,
    pub model: IlluminationModel,
}

/// One area light at one point, as [`shade_exact`] hands it to the reference's exact integral.
pub struct AreaAt<'a> {
    /// The light's index and the light.
    pub index: usize,
    pub light: &'a Light,
    /// Its radiance at the point (`LightSample.radiance`: intensity, falloff, window, cone).
    pub radiance: [f64; 3],
    pub p: DVec3,
    /// Unit shading normal and unit view vector.
    pub n: DVec3,
    pub v: DVec3,
    pub mat: &'a Material,
    pub v_index: [f64; 3],
    pub ms_e: f64,
    pub specular: SpecularModel,
}

/// [`shade`] at `at`, each light's term scaled by `visibility(i, light, j, l)`, the share of
/// light `i` (its point source `j` where it is drawn as points, else 0) that reaches `p` along
/// the unit direction `l` to it (1: lit, 0: in a cast shadow). It is asked only of lights that
/// would add something, so a point in its own shadow (N·L ≤ 0) costs no shadow query. The Lambert
/// rule's fill and the four-term sum's transmitted term are not shadowed: the fill stands for
/// light from everywhere, and the transmitted light is what passes the body that the shadow test
/// would find in the way. `exact` may give an area light's whole term, shadowed, in place of its
/// drawn one: for an area light with its exact form under the Phong model, a `Some`
/// is added as it is (the visibility is not asked), a `None` keeps the drawn term. The reference
/// passes [`super::area_exact`]'s integral.
pub fn shade_exact(
    at: &ShadePoint,
    lights: &[Light],
    mut visibility: impl FnMut(usize, &Light, u32, DVec3) -> f64,
    exact: &mut dyn FnMut(&AreaAt) -> Option<[f64; 3]>,
) -> [f64; 3] {
    let ShadePoint { p, n_in, eye, mat, ambient, env_sh, env_prefiltered, env_occlusion, specular, model } = *at;
    // The view vector: toward the eye (w = 1), or the orthographic camera's one direction (w = 0).
    let v = safe_normalize(eye.truncate() - p * eye.w, DVec3::Y);
    let n = safe_normalize(n_in, v);
    let v_index = mat.mu.map(fresnel_v_from_mu);
    // The lobe's albedo for its multiple-scattering compensation: once a point, as the WGSL.
    let ms_e = if specular == SpecularModel::CookTorrance && mat.microfacet.multiple_scattering {
        super::ms_table::ms_albedo(mat.microfacet, n.dot(v), mat.m)
    } else {
        1.0
    };
    let c = mat.color;
    let mut total = [0.0; 3];
    if model != IlluminationModel::Lambert {
        total = std::array::from_fn(|i| ambient[i] * mat.r_a * c[i]);
        // The environment's diffuse light, the chapter's I_a made directional.
        if let Some(sh) = env_sh {
            let e = env_sh_radiance(sh, n);
            // The share of it the precomputed grid lets through, where the scene asks for it.
            let open = env_occlusion.map_or(1.0, |g| super::occlusion::env_occlusion(g, p, n));
            for i in 0..3 {
                total[i] += e[i] * open * mat.r_a * c[i];
            }
        }
    }
    // The environment's specular by the split sum: Cook–Torrance under the Phong model only.
    if let Some(pre) =
        env_prefiltered.filter(|_| model == IlluminationModel::Phong && specular == SpecularModel::CookTorrance)
    {
        let e = env_specular(pre, n, v, mat.m, mat.microfacet, v_index);
        for i in 0..3 {
            total[i] += mat.r_s * e[i];
        }
    }
    // The Lambert rule's I: the brightest light at the point, per channel, in [0, 1].
    let mut i_max = [0.0f64; 3];
    for (k, light) in lights.iter().take(MAX_LIGHTS).enumerate() {
        // An area light's exact term needs only its radiance here: the representative point and
        // the form are computed only where the exact term declines.
        if model == IlluminationModel::Phong && light.kind.is_area() && !light.drawn_as_points() {
            let radiance = light_radiance_at(light, p, n);
            let area = AreaAt { index: k, light, radiance, p, n, v, mat, v_index, ms_e, specular };
            if let Some(lit) = exact(&area) {
                for i in 0..3 {
                    total[i] += lit[i];
                }
                continue;
            }
        }
        let base = area_ltc_sample(light_sample(light, p, n, v, mat.m), light, p, n, v, mat.m, mat.microfacet);
        // An area light drawn as k point sources is k samples, each with its own visibility.
        for j in 0..area_point_count(light) {
            let s = if light.drawn_as_points() {
                area_point_sample(&base, light, &area_emitter(light, j), p, n)
            } else {
                base
            };
            let lit = model_term(model, &s, j, n, v, mat, v_index, ms_e, specular, &mut i_max, &mut total);
            if lit == [0.0; 3] {
                continue;
            }
            // A NaN visibility counts as none, like 0.
            let w = visibility(k, light, j, s.l).clamp(0.0, 1.0);
            if w.is_nan() || w == 0.0 {
                continue;
            }
            for i in 0..3 {
                total[i] += if w == 1.0 { lit[i] } else { lit[i] * w };
            }
        }
    }
    if model == IlluminationModel::Lambert {
        let fill = lambert_rule_fill(c.map(|x| x * mat.r_a), i_max);
        for i in 0..3 {
            total[i] += fill[i];
        }
    }
    total
}

/// Light sample `s` of `light` with its specular by LTC ([`super::ltc`]), where the light asks
/// for it and is drawn in its exact area form; `M⁻¹` and the lobe's albedo E are the material's
/// D's and D × G pair's at `N·V` and m.
pub fn area_ltc_sample(
    s: LightSample,
    light: &Light,
    p: DVec3,
    n: DVec3,
    v: DVec3,
    m: f64,
    terms: Microfacet,
) -> LightSample {
    if light.area_specular != AreaSpecular::Ltc || light.drawn_as_points() {
        return s;
    }
    let Some(area) = light.area_light() else { return s };
    let n_dot_v = n.dot(v);
    let minv = super::ltc::ltc_matrix(terms.d.code(), n_dot_v, m);
    let e = super::ms_table::ms_albedo(terms, n_dot_v.max(crate::guards::N_DOT_V_MIN), m);
    LightSample { ltc: super::ltc::area_specular_ltc(&area, p, n, v, minv, e), ..s }
}

/// The chosen model's term of light sample `s` (point source `j` of its light), before its shadow:
/// the Lambert rule raises `i_max` to the sample's I, and the sum adds the light's transmitted
/// term (unshadowed, once) to `total`.
#[allow(clippy::too_many_arguments)]
fn model_term(
    model: IlluminationModel,
    s: &LightSample,
    j: u32,
    n: DVec3,
    v: DVec3,
    mat: &Material,
    v_index: [f64; 3],
    ms_e: f64,
    specular: SpecularModel,
    i_max: &mut [f64; 3],
    total: &mut [f64; 3],
) -> [f64; 3] {
    let c = mat.color;
    let radiance = s.radiance;
    match model {
        IlluminationModel::Lambert => {
            let i = radiance.map(|x| x.clamp(0.0, 1.0));
            let raised: [f64; 3] = std::array::from_fn(|j| i_max[j].max(i[j]));
            *i_max = raised;
            lambert_rule_lit(c.map(|x| x * mat.r_d), i, s.form)
        }
        IlluminationModel::Sum => {
            // The transmitted term is the light's, once (not per point source).
            let t = if j == 0 { transmitted_term(radiance, c, mat.transmission) } else { [0.0; 3] };
            for i in 0..3 {
                total[i] += t[i];
            }
            sum_contribution(radiance, s.form, n.dot(v), c, mat.r_d, mat.r_s)
        }
        IlluminationModel::Phong => light_contribution(s, n, v, mat, v_index, specular, ms_e),
    }
}
