//! Tests of the microfacet terms (`microfacet.rs`): each D's normalization and peak, Smith's G1
//! and Λ against their definitions, the Fresnel factors and their complements, the codes.

use super::*;
use std::f64::consts::PI;

/// Each complement is 1 − F where that keeps its digits, and stays in [0, 1] everywhere.
#[test]
fn the_fresnel_complements_are_one_minus_f() {
    for v in [0.0, 0.5, 1.0, 1.0 + 1e-9, 1.33, 1.5, 2.4, 40.0, 1e4] {
        for i in 0..=1000 {
            let c = i as f64 / 1000.0;
            let (e, s) = (fresnel_dielectric_complement(c, v), fresnel_schlick_complement(c, v));
            assert!((e - (1.0 - fresnel_dielectric(c, v))).abs() < 1e-12, "exact c {c} v {v}: {e}");
            assert!((s - (1.0 - fresnel_schlick(c, v))).abs() < 1e-12, "schlick c {c} v {v}: {s}");
            assert!((0.0..=1.0).contains(&e) && (0.0..=1.0).contains(&s));
        }
    }
}

/// glTF's fresnel_mix weight: 1 − F0 at normal incidence (both F), 0 at grazing V·H, 1 with no
/// weight, and never outside [0, 1] between.
#[test]
fn the_fresnel_mix_weight_is_one_minus_f_of_the_layer() {
    let n = DVec3::Z;
    for terms in [Microfacet::GLTF, Microfacet::CHAPTER] {
        assert!((fresnel_mix_weight(terms, n, n, n, 0.04, 1.0) - 0.96).abs() < 1e-9, "{terms}");
        assert_eq!(fresnel_mix_weight(terms, n, n, n, 0.04, 0.0), 1.0);
        // V and L nearly opposite: H ⟂ V, F = 1.
        let v = DVec3::new(1.0, 0.0, 1e-6).normalize();
        let l = DVec3::new(-1.0, 0.0, 1e-6).normalize();
        assert!(fresnel_mix_weight(terms, n, v, l, 0.04, 1.0) < 1e-3, "{terms}");
        for i in 0..=90 {
            let t = (i as f64).to_radians();
            let v = DVec3::new(t.sin(), 0.0, t.cos());
            for f0 in [0.0, 0.04, 0.5, 1.0] {
                let k = fresnel_mix_weight(terms, n, v, n, f0, 0.7);
                assert!((0.0..=1.0).contains(&k), "{terms} θ {i}° F0 {f0}: {k}");
            }
        }
    }
}

/// ∫ D·(N·H) dω_h over the hemisphere by the midpoint rule in θ (D depends on θ only).
fn projected_area(d: impl Fn(f64, f64) -> f64) -> f64 {
    let n = 200_000;
    let dt = 0.5 * PI / n as f64;
    (0..n)
        .map(|i| {
            let t = (i as f64 + 0.5) * dt;
            d(t.cos(), t.sin().powi(2)) * t.cos() * t.sin() * 2.0 * PI * dt
        })
        .sum()
}

#[test]
fn ggx_in_the_chapters_scale_is_pi_over_four_of_a_normalized_d() {
    for m in [0.05, 0.2, 0.5, 1.0] {
        let a = projected_area(|c, s2| d_ggx(c, s2, m)) * 4.0 / PI;
        assert!((a - 1.0).abs() < 1e-3, "m = {m}: ∫D cos = {a}");
        // Its peak equals Beckmann's at the same m.
        assert!((d_ggx(1.0, 0.0, m) - d_beckmann(1.0, 0.0, m)).abs() < 1e-12);
    }
}

/// The Blinn–Phong D in the chapter's scale is π/4 of a normalized D, peaks as Beckmann does,
/// and is the chapter's Phong lobe (N·H)^h with h = 2/m² − 2 times its normalization.
#[test]
fn blinn_phong_in_the_chapters_scale_is_pi_over_four_of_a_normalized_d() {
    for m in [0.05, 0.2, 0.5, 1.0] {
        let a = projected_area(|c, s2| d_blinn_phong(c, s2, m)) * 4.0 / PI;
        assert!((a - 1.0).abs() < 1e-3, "m = {m}: ∫D cos = {a}");
        assert!((d_blinn_phong(1.0, 0.0, m) - d_beckmann(1.0, 0.0, m)).abs() < 1e-9, "m = {m}");
        let h = 2.0 / (m * m) - 2.0;
        for c in [0.3f64, 0.9, 0.999] {
            let lobe = (h + 2.0) / 8.0 * c.powf(h);
            assert!((d_blinn_phong(c, 1.0 - c * c, m) - lobe).abs() <= 1e-9 * lobe.max(1.0), "m = {m} c = {c}");
        }
    }
    // Hard cases: below the surface, at M_MIN (h = 2·10⁶), and m = 0.
    assert_eq!(d_blinn_phong(-0.5, 0.75, 0.3), 0.0);
    let grazing = d_blinn_phong(0.999, 1.0 - 0.999 * 0.999, M_MIN);
    assert!(grazing.is_finite() && grazing >= 0.0);
    assert_eq!(d_blinn_phong(1.0, 0.0, 0.0), d_blinn_phong(1.0, 0.0, M_MIN));
    // Past its domain (sin² > 1 from a short normal) it stays finite.
    assert!(d_blinn_phong(0.5, 2.0, 0.3).is_finite());
}

/// Blinn–Phong's Λ against Smith's own definition, computed independently: `(1 + Λ)·c` is the
/// facets' projected area toward the direction, `∫ max(0, ω·ω_m)·D(ω_m) dω_m` of the normalized
/// lobe `(h + 2)/2π·cos^h θ_m`, summed over a fine grid of facet normals. At h = 0 (m = 1) Λ is
/// `(1 − c)/(2c)`, GGX's at α = 1 (both lobes are uniform there).
#[test]
fn blinn_phong_lambda_is_smiths_projected_area() {
    let projected = |c: f64, h: f64| {
        let (s, theta_max) = ((1.0 - c * c).sqrt(), if h > 0.0 { (1e-14f64.ln() / h).exp().acos() } else { 0.5 * PI });
        let (nt, np) = (2000, 512);
        let (dt, dp) = (theta_max / nt as f64, 2.0 * PI / np as f64);
        let mut sum = 0.0;
        for i in 0..nt {
            let t = (i as f64 + 0.5) * dt;
            let d = (h + 2.0) / (2.0 * PI) * t.cos().powf(h) * t.sin() * dt * dp;
            for j in 0..np {
                let p = (j as f64 + 0.5) * dp;
                sum += d * (c * t.cos() + s * t.sin() * p.cos()).max(0.0);
            }
        }
        sum
    };
    let mut worst = 0.0f64;
    for m in [0.1, 0.3, 0.6, 0.9, 1.0] {
        let h = 2.0 / (m * m) - 2.0;
        for c in [0.05, 0.2, 0.5, 0.9] {
            let reference = c / projected(c, h);
            let g1 = smith_g1(Distribution::BlinnPhong, c, m);
            worst = worst.max((g1 - reference).abs());
        }
    }
    eprintln!("|G1 − Smith's projected area|: at most {worst:.2e}");
    assert!(worst < BLINN_PHONG_G1_ERROR, "{worst}");
    for c in [0.01, 0.3, 0.99] {
        let g1 = smith_g1(Distribution::BlinnPhong, c, 1.0);
        assert!((g1 - 2.0 * c / (1.0 + c)).abs() < 1e-5, "c = {c}: {g1}");
    }
    // Hard cases: at the normal, at grazing, below the guard and at the smallest m.
    assert_eq!(lambda_blinn_phong(1.0, 0.3), 0.0);
    assert_eq!(smith_g1(Distribution::BlinnPhong, 0.0, 0.3), 0.0);
    for m in [0.0, M_MIN, 0.5, 1.0] {
        for c in [1e-30, BLINN_PHONG_COS_MIN, 1e-6, 0.5, 1.0 - 1e-9] {
            let l = lambda_blinn_phong(c, m);
            assert!(l.is_finite() && l >= 0.0, "m = {m} c = {c}: {l}");
        }
    }
}

/// Measured: 9.8e-5 at most over the grid above (the 8-node quadrature; the grid's own sum is
/// good to about 1e-6). About twice that.
const BLINN_PHONG_G1_ERROR: f64 = 2e-4;

#[test]
fn smith_g1_is_one_at_the_normal_zero_at_grazing_and_falls_between() {
    for d in [Distribution::Ggx, Distribution::Beckmann, Distribution::BlinnPhong] {
        for m in [M_MIN, 0.1, 0.5, 1.0] {
            assert!((smith_g1(d, 1.0, m) - 1.0).abs() < 1e-12, "{d:?} m = {m}");
            assert_eq!(smith_g1(d, 0.0, m), 0.0, "{d:?} m = {m}");
            let mut last = 0.0;
            for i in 0..=1000 {
                let g = smith_g1(d, i as f64 / 1000.0, m);
                assert!((0.0..=1.0 + 1e-12).contains(&g) && g >= last - 1e-3, "{d:?} m = {m} c = {i}e-3: {g}");
                last = g;
            }
        }
    }
    // GGX's G1 against 1/(1 + Λ), Λ = (√(1 + α² tan²θ) − 1)/2 (Heitz 2014, eq. 72).
    let (c, a): (f64, f64) = (0.3, 0.4);
    let tan2 = (1.0 - c * c) / (c * c);
    let lambda = ((1.0 + a * a * tan2).sqrt() - 1.0) / 2.0;
    assert!((smith_g1(Distribution::Ggx, c, a) - 1.0 / (1.0 + lambda)).abs() < 1e-12);
    // Walter's fit is continuous where it turns to 1 (a = 1.6).
    let c = 1.6 / (1.0f64 + 1.6 * 1.6).sqrt();
    let g = smith_g1(Distribution::Beckmann, c - 1e-9, 1.0);
    assert!((g - 1.0).abs() < 1e-3, "{g}");
}

#[test]
fn height_correlated_smith_lies_between_the_product_and_the_smaller_g1() {
    for d in [Distribution::Ggx, Distribution::Beckmann, Distribution::BlinnPhong] {
        for (nv, nl, m) in [(0.9, 0.2, 0.3), (0.5, 0.5, 0.8), (0.05, 0.99, 0.1), (0.0, 0.0, 0.5)] {
            let (gv, gl) = (smith_g1(d, nv, m), smith_g1(d, nl, m));
            let hc = g_smith_correlated(d, nv, nl, m);
            assert!(hc.is_finite() && hc >= gv * gl - 1e-15 && hc <= gv.min(gl) + 1e-15, "{d:?} {nv} {nl}: {hc}");
            assert_eq!(g_smith_separable(d, nv, nl, m), gv * gl);
        }
    }
}

#[test]
fn schlick_meets_the_exact_factor_at_its_ends() {
    for mu in [0.0, 0.04, 0.5, 0.95] {
        let v = fresnel_v_from_mu(mu);
        assert!((fresnel_schlick(1.0, v) - mu).abs() < 1e-12, "μ = {mu}");
        assert!((fresnel_schlick(1.0, v) - fresnel_dielectric(1.0, v)).abs() < 1e-12);
        assert_eq!(fresnel_schlick(0.0, v), 1.0);
    }
    // Between them it is an approximation, worst near grazing where the exact factor dips
    // towards Brewster's angle: for glass-like μ = 0.04 the largest gap is 0.0357 (at c ≈
    // 0.09), for μ = 0.5 (v ≈ 5.8) it is 0.296 (at c ≈ 0.1).
    for (mu, gap) in [(0.04, 0.0357), (0.5, 0.2962)] {
        let v = fresnel_v_from_mu(mu);
        let worst = (0..=1000)
            .map(|i| i as f64 / 1000.0)
            .map(|c| (fresnel_schlick(c, v) - fresnel_dielectric(c, v)).abs())
            .fold(0.0, f64::max);
        assert!((worst - gap).abs() < 5e-4, "μ = {mu}: {worst}");
    }
}

#[test]
fn presets_and_names_round_trip() {
    for &(name, d) in Distribution::ALL {
        assert_eq!(d.to_string(), name);
        assert_eq!(name.parse::<Distribution>().unwrap(), d);
    }
    for &(name, g) in Masking::ALL {
        assert_eq!(name.parse::<Masking>().unwrap(), g);
    }
    for &(name, f) in Fresnel::ALL {
        assert_eq!(name.parse::<Fresnel>().unwrap(), f);
    }
    assert!("blinn".parse::<Distribution>().unwrap_err().to_string().contains("beckmann, ggx"));
    assert_eq!(Microfacet::GLTF.to_string(), "ggx/smith-correlated/schlick+mix");
    assert_eq!(Microfacet::parse_named("gltf").unwrap(), Microfacet::GLTF);
    assert_eq!(Microfacet::CHAPTER.code(), 0);
    assert_ne!(Microfacet::GLTF.code(), 0);
}
