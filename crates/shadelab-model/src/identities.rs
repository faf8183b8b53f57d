//! The model's identities (docs/model.md §5, §9) as tests: physics, not pictures.

use crate::guards::*;
use crate::lighting::brdf::*;
use glam::DVec3;
use std::f64::consts::PI;

/// A direction on the upper hemisphere from polar angle θ and azimuth φ.
fn dir(theta: f64, phi: f64) -> DVec3 {
    DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin())
}

#[test]
fn fresnel_is_mu_at_normal_incidence_and_one_at_grazing() {
    // The chapter says μ is F "at c = 0"; normal incidence is c = cos 0 = 1 (erratum, docs/model.md §5).
    for i in 0..=1000 {
        let mu = 0.9998 * i as f64 / 1000.0; // below the √μ cap (FRESNEL_SQRT_MU_MAX)
        let v = fresnel_v_from_mu(mu);
        let f1 = fresnel_dielectric(1.0, v);
        assert!((f1 - mu).abs() <= 1e-12 * mu.max(1e-3), "F(c=1) = {f1}, μ = {mu}");
        if mu > 0.0 {
            // Grazing: F = 1 for every real interface. (μ = 0 is no interface at all, v = 1:
            // F = 0 for every c > 0, and the guard FRESNEL_G_PLUS_C_MIN keeps that at c = 0.)
            assert!((fresnel_dielectric(0.0, v) - 1.0).abs() < 1e-12, "F(c=0), μ = {mu}");
        }
    }
    assert_eq!(fresnel_dielectric(0.0, fresnel_v_from_mu(0.0)), 0.0);
    // μ = 1 is capped: v finite, F(1) within 2e-4 of 1.
    let v = fresnel_v_from_mu(1.0);
    assert!(v.is_finite() && (fresnel_dielectric(1.0, v) - 1.0).abs() < 2e-4);
    // F grows monotonically towards grazing for a dielectric.
    let v = fresnel_v_from_mu(0.04);
    let mut last = 0.0;
    for i in (0..=100).rev() {
        let f = fresnel_dielectric(i as f64 / 100.0, v);
        assert!(f >= last - 1e-15);
        last = f;
    }
}

#[test]
fn chapter_beckmann_is_pi_over_4_times_normalized_and_normalized_integrates_to_one() {
    for m in [0.05, 0.1, 0.2, 0.5, 0.8, 1.0] {
        for i in 1..=200 {
            let c = i as f64 / 200.0;
            let seed = d_beckmann(c, 1.0 - c * c, m);
            let normalized = d_beckmann_normalized(c, m);
            assert!((seed - PI / 4.0 * normalized).abs() <= 1e-12 * seed.max(1e-300), "m {m} c {c}");
        }
        // ∫ D_B(h) (N·H) dω_h over the hemisphere = 1 (midpoint rule in θ, fine enough for m ≥ 0.05).
        let steps = 200_000;
        let dtheta = PI / 2.0 / steps as f64;
        let integral: f64 = (0..steps)
            .map(|k| {
                let theta = (k as f64 + 0.5) * dtheta;
                d_beckmann_normalized(theta.cos(), m) * theta.cos() * theta.sin() * 2.0 * PI * dtheta
            })
            .sum();
        assert!((integral - 1.0).abs() < 1e-6, "m {m}: ∫ D cos = {integral}");
    }
}

#[test]
fn chapter_rho_s_equals_the_modern_microfacet_form() {
    let n = DVec3::Y;
    for m in [0.1, 0.3, 0.7] {
        for mu in [0.02, 0.04, 0.5, 0.95] {
            for (tl, pl, tv, pv) in
                [(0.3, 0.0, 0.5, 2.0), (1.2, 1.0, 0.2, 4.0), (0.01, 0.0, 1.5, 3.1), (1.5, 0.0, 1.5, PI)]
            {
                let (seed, modern) = rho_s_forms(n, dir(tv, pv), dir(tl, pl), m, fresnel_v_from_mu(mu));
                assert!((seed - modern).abs() <= 1e-12 * seed.abs().max(1e-300), "{seed} vs {modern}");
            }
        }
    }
}

#[test]
fn brdf_is_reciprocal() {
    let n = DVec3::Y;
    let mut k = 0u32;
    for it in 0..40 {
        for jt in 0..40 {
            k += 1;
            let l = dir(it as f64 * 0.039, k as f64 * 0.7);
            let v = dir(jt as f64 * 0.039, k as f64 * 1.3 + 0.4);
            for m in [0.05, 0.3, 1.0] {
                let vi = fresnel_v_from_mu(0.3);
                let (a, _) = rho_s_forms(n, v, l, m, vi);
                let (b, _) = rho_s_forms(n, l, v, m, vi);
                assert!((a - b).abs() <= 1e-12 * a.abs().max(1e-300), "ρ(L,V) {a} ≠ ρ(V,L) {b}");
                // The term as the renderer uses it, π ρ_s (N·L), divided by N·L is reciprocal too.
                let sa = specular_cook_torrance(n, v, l, m, [vi; 3])[0] / n.dot(l);
                let sb = specular_cook_torrance(n, l, v, m, [vi; 3])[0] / n.dot(v);
                assert!((sa - sb).abs() <= 1e-9 * sa.abs().max(1e-300), "{sa} vs {sb}");
            }
        }
    }
}

/// Directional albedo of the chapter's Cook–Torrance lobe with F = 1 (a white furnace,
/// [`crate::furnace`]).
fn white_furnace_albedo(m: f64, theta_v: f64) -> f64 {
    crate::furnace::directional_albedo(crate::lighting::microfacet::Microfacet::CHAPTER, m, theta_v.cos(), 512)
}

#[test]
fn white_furnace_albedo_of_the_cook_torrance_lobe_is_at_most_one() {
    let mut table = String::from(
        "white furnace (F = 1): albedo of the Cook–Torrance lobe\n   m  | θv=0°  30°    60°    80°    89°\n",
    );
    for m in [0.05, 0.1, 0.2, 0.5, 0.8, 1.0] {
        table += &format!("{m:5.2} |");
        for theta_deg in [0.0f64, 30.0, 60.0, 80.0, 89.0] {
            let a = white_furnace_albedo(m, theta_deg.to_radians());
            table += &format!(" {a:.4}");
            // Stratified sampling error at 512² samples is far below 1e-3 here.
            assert!(a <= 1.0 + 1e-3, "m {m}, θv {theta_deg}: albedo {a}");
            assert!(a > 0.0);
        }
        table += "\n";
    }
    eprintln!("{table}");
}

/// Phong's normalized lobe reflects all it receives at normal view: `(1/π) ∫ k·(N·L)^h dω_L = 1`
/// with `k = phong_normalization(h)` (V = N, so V·R = N·L), for small and large h.
#[test]
fn the_normalized_phong_lobe_has_albedo_one_at_normal_view() {
    use crate::lighting::brdf::phong_normalization;
    for h in [1.0, 10.0, 100.0, 1e4] {
        let n = 200_000;
        let sum: f64 = (0..n)
            .map(|i| {
                let c = (i as f64 + 0.5) / n as f64;
                specular_phong(c, h, false) * 2.0 * PI / n as f64
            })
            .sum();
        let albedo = phong_normalization(h, false) * sum / PI;
        assert!((albedo - 1.0).abs() < 1e-3, "h = {h}: {albedo}");
        // Unnormalized, the chapter's lobe reflects 2/(h + 1) of it.
        assert!((sum / PI - 2.0 / (h + 1.0)).abs() < 1e-3 * 2.0 / (h + 1.0), "h = {h}");
    }
    assert_eq!(phong_normalization(1e9, true), 1.0);
}

#[test]
fn phong_lobe_tends_to_the_mirror_as_h_grows() {
    // Monotonically narrower as h grows, 1 exactly at the mirror direction.
    for x in [0.1, 0.5, 0.9, 0.99, 0.999_999] {
        let mut last = 1.0;
        for h in [1.0, 2.0, 10.0, 100.0, 1e4, 1e6, H_MAX] {
            let s = specular_phong(x, h, false);
            assert!(s <= last && s >= 0.0 && s.is_finite());
            last = s;
        }
        // At h = H_MAX only directions within about 0.003° of the mirror keep anything.
        assert!(specular_phong(x, H_MAX, false) < 1e-6 || x > 1.0 - 1e-8);
    }
    assert_eq!(specular_phong(1.0, H_MAX, false), 1.0);
    // The lobe's solid angle ∫ (V·R)^h dω = 2π/(h + 1) → 0.
    for h in [1.0, 10.0, 100.0, 1000.0] {
        let steps = 400_000;
        let dt = PI / 2.0 / steps as f64;
        let integral: f64 = (0..steps)
            .map(|k| {
                let t = (k as f64 + 0.5) * dt;
                specular_phong(t.cos(), h, false) * t.sin() * 2.0 * PI * dt
            })
            .sum();
        assert!((integral - 2.0 * PI / (h + 1.0)).abs() < 1e-6 * (2.0 * PI / (h + 1.0)) + 1e-9, "h {h}: {integral}");
    }
    // The mirror setting: 1 within MIRROR_V_DOT_R_MIN of the mirror direction, 0 elsewhere.
    assert_eq!(specular_phong(1.0, 1.0, true), 1.0);
    assert_eq!(specular_phong(MIRROR_V_DOT_R_MIN, 1.0, true), 1.0);
    assert_eq!(specular_phong(0.9999, 1.0, true), 0.0);
}

#[test]
fn lambert_rule_ends() {
    // Facing a full light: R; at the terminator: R(1 − I); turned away: the ambient fill only.
    assert_eq!(lambert_rule(0.6, 1.0, 1.0), 0.6);
    assert!((lambert_rule(0.6, 0.7, 0.0) - 0.6 * 0.3).abs() < 1e-15);
    assert_eq!(lambert_rule(0.6, 0.7, -0.5), lambert_rule(0.6, 0.7, 0.0));
}
