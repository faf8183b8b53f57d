//! The white furnace (docs/microfacet.md): the directional albedo of the microfacet specular with
//! F = 1, `E(V) = (1/π) ∫ F·D·G/(N·V) dω_L` in the chapter's scale (where a white Lambert surface
//! has E = 1). A lobe that loses no energy has E = 1; single scattering loses the light that
//! bounces between facets, most at high roughness, and a G that over-counts
//! visible facets gives E > 1.

use crate::lighting::microfacet::{Distribution, Masking, Microfacet, microfacet_g};
use glam::DVec3;

/// Samples per side of the stratified grid (n² half vectors).
pub const FURNACE_SAMPLES: usize = 512;

/// `E(V)` at `N·V = cos_v` for the D and G of `terms` (its F is replaced by 1), with `n × n`
/// half vectors drawn from D's own distribution of `N·H` (its inverse CDF of `u`): with
/// `pdf(H) = D_n (N·H)` and `dω_L = 4 (V·H) dω_H`, `E = ∫ G·(V·H)/((N·V)(N·H)) du dφ/2π` over the
/// reflected directions above the surface. `u = 1 − (1 − t)³` on a midpoint grid in `t` puts
/// more samples in the tails (GGX's reach far), where a grid in `u` errs by up to 1/n.
pub fn directional_albedo(terms: Microfacet, m: f64, cos_v: f64, n: usize) -> f64 {
    weighted_albedo(terms, m, cos_v, n, |_| 1.0)
}

/// [`directional_albedo`] with each half vector's reflection weighed by `weight(V·H)`: with
/// `(1 − V·H)⁵` it is the share B of the lobe's albedo that Schlick's F adds toward grazing, so
/// that `∫ F f cos = F0·(E − B) + B` (the environment's split sum, docs/environment.md).
pub fn weighted_albedo(terms: Microfacet, m: f64, cos_v: f64, n: usize, weight: impl Fn(f64) -> f64) -> f64 {
    let cos_v = cos_v.clamp(1e-6, 1.0);
    let v = DVec3::new((1.0 - cos_v * cos_v).max(0.0).sqrt(), 0.0, cos_v);
    let a2 = m.max(crate::guards::M_MIN).powi(2);
    let mut sum = 0.0;
    for i in 0..n {
        let t = (i as f64 + 0.5) / n as f64;
        let u = 1.0 - (1.0 - t).powi(3);
        let du_dt = 3.0 * (1.0 - t).powi(2);
        let tan2 = terms.d.sample_tan2(a2, u);
        let cos_h = 1.0 / (1.0 + tan2).sqrt();
        let sin_h = (tan2 / (1.0 + tan2)).sqrt();
        for j in 0..n {
            let phi = 2.0 * std::f64::consts::PI * (j as f64 + 0.5) / n as f64;
            let h = DVec3::new(sin_h * phi.cos(), sin_h * phi.sin(), cos_h);
            let v_dot_h = v.dot(h);
            let l = 2.0 * v_dot_h * h - v;
            if v_dot_h <= 0.0 || l.z <= 0.0 {
                continue;
            }
            let g = microfacet_g(terms, cos_h, cos_v, l.z, v_dot_h, m);
            sum += du_dt * g * v_dot_h / (cos_v * cos_h) * weight(v_dot_h);
        }
    }
    sum / (n * n) as f64
}

/// Every D × G pair (F is 1 in the furnace), the chapter's first.
pub fn pairs() -> Vec<Microfacet> {
    use crate::params::NamedValue;
    let mut out = Vec::new();
    for &(_, d) in Distribution::ALL {
        for &(_, g) in Masking::ALL {
            out.push(Microfacet { d, g, ..Microfacet::CHAPTER });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same integral taken independently, over the light's direction on a midpoint grid in
    /// (cos θ_L, φ), from `specular_microfacet` itself: `(1/π) ∫ S dω_L`. It converges only for
    /// wide lobes, so the check runs at m = 0.5 and 1.
    fn over_the_light(terms: Microfacet, m: f64, cos_v: f64) -> f64 {
        let n_v = DVec3::Z;
        let v = DVec3::new((1.0 - cos_v * cos_v).sqrt(), 0.0, cos_v);
        let (nc, np) = (600, 1200);
        let mut sum = 0.0;
        for i in 0..nc {
            let cl = (i as f64 + 0.5) / nc as f64;
            let sl = (1.0 - cl * cl).sqrt();
            for j in 0..np {
                let phi = 2.0 * std::f64::consts::PI * (j as f64 + 0.5) / np as f64;
                let l = DVec3::new(sl * phi.cos(), sl * phi.sin(), cl);
                // F = 1: a μ whose factor is 1 within 2e-4 everywhere.
                let s = crate::lighting::microfacet::specular_microfacet(n_v, v, l, m, [1e9; 3], terms, 1.0)[0];
                sum += s;
            }
        }
        // dω = d(cos θ) dφ; the 1/π of the chapter's scale.
        sum * (1.0 / nc as f64) * (2.0 * std::f64::consts::PI / np as f64) / std::f64::consts::PI
    }

    #[test]
    fn the_estimate_agrees_with_a_quadrature_over_the_light() {
        for t in pairs() {
            for (m, cos_v) in [(0.5, 1.0), (1.0, 0.5)] {
                let (a, b) = (directional_albedo(t, m, cos_v, 256), over_the_light(t, m, cos_v));
                assert!((a - b).abs() < 2e-3, "{t} m = {m}, N·V = {cos_v}: {a} against {b}");
            }
        }
    }

    #[test]
    fn smith_loses_energy_with_roughness() {
        let t = Microfacet::GLTF;
        let smooth = directional_albedo(t, 0.1, 1.0, 256);
        let rough = directional_albedo(t, 1.0, 1.0, 256);
        // At α = 0.1 GGX's tail beyond 45° (1 − 1/(1 + α²) = 0.0099) is lost at normal view.
        assert!(smooth > 0.98 && smooth < 1.0 / 1.01, "{smooth}");
        // At α = 1 and normal view: 0.3068, which an independent Monte Carlo over the light's
        // direction also gives (the half vectors beyond 45° reflect into the surface).
        assert!((rough - 0.3068).abs() < 2e-3, "{rough}");
        // The height-correlated form keeps more than the separable one (it counts the overlap once).
        let separable = directional_albedo(Microfacet { g: Masking::Smith, ..t }, 1.0, 0.5, 256);
        assert!(directional_albedo(t, 1.0, 0.5, 256) > separable);
    }
}
