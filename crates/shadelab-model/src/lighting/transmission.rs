//! Light through a surface in f64 (docs/transparency.md, the chapter's 7.5): Snell's law with
//! total internal reflection, the chapter's exact Fresnel factor at an interface met from either
//! side, absorption by Beer–Lambert and by the chapter's rule (linear below a·d = 0.5, neglected
//! below 0.2), and the exact chord through a sphere. The effect analysis reads the rule's
//! thresholds; the renderer does not draw transparent materials yet. The WGSL twin is
//! `shaders/transmission.wgsl`, which only the stability sweep compiles so far.

use crate::guards::FRESNEL_G_PLUS_C_MIN;
use glam::DVec3;

/// Below this a·d the chapter neglects absorption (7.5): the light it drops is under
/// 1 − e^(−0.2) = 18 %.
pub const ABSORPTION_NEGLECT_BELOW: f64 = 0.2;
/// Below this a·d the chapter takes the linear 1 − a·d (7.5): off by under e^(−0.5) − 0.5 = 0.107.
pub const ABSORPTION_LINEAR_BELOW: f64 = 0.5;

/// Which of the chapter's three forms of absorption a path takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AbsorptionForm {
    /// e^(−a·d).
    Exact,
    /// 1 − a·d.
    Linear,
    /// 1: nothing absorbed.
    Neglected,
}

/// The form the chapter's rule picks for the optical depth `ad` = a·d.
pub fn absorption_regime(ad: f64) -> AbsorptionForm {
    if ad < ABSORPTION_NEGLECT_BELOW {
        AbsorptionForm::Neglected
    } else if ad < ABSORPTION_LINEAR_BELOW {
        AbsorptionForm::Linear
    } else {
        AbsorptionForm::Exact
    }
}

/// Beer–Lambert's share of the light left after optical depth `ad`: e^(−a·d), with a·d held at 0
/// or above (a negative depth would amplify); it underflows to exactly 0 past a·d ≈ 745, never NaN.
pub fn absorption_exact(ad: f64) -> f64 {
    (-ad.max(0.0)).exp()
}

/// The chapter's share after optical depth `ad`: 1 (neglected), 1 − a·d (linear) or e^(−a·d), by
/// [`absorption_regime`].
pub fn absorption_rule(ad: f64) -> f64 {
    let ad = ad.max(0.0);
    match absorption_regime(ad) {
        AbsorptionForm::Neglected => 1.0,
        AbsorptionForm::Linear => 1.0 - ad,
        AbsorptionForm::Exact => absorption_exact(ad),
    }
}

/// Snell's law (7.5): the unit direction refracted from unit incident direction `i` (travelling
/// towards the surface) at unit normal `n` (facing the incident side), `eta` = n_i/n_t; `None`
/// under total internal reflection, where η²·sin²θ_i > 1 leaves no refracted ray. At the critical
/// angle the refracted ray runs along the surface.
pub fn refract_snell(i: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let cos_i = (-i.dot(n)).clamp(0.0, 1.0);
    // 1 − η²·sin²θ_i, grouped so that η = 1 gives cos²θ_i without cancelling at grazing angles.
    let cos2_t = (1.0 - eta) * (1.0 + eta) + eta * eta * cos_i * cos_i;
    if cos2_t < 0.0 {
        return None;
    }
    Some(i * eta + n * (eta * cos_i - cos2_t.sqrt()))
}

/// The chapter's exact unpolarized Fresnel factor (docs/model.md §5) at an interface met at
/// cos θ_i = `c`, with `v` = n_t/n_i from either side (below 1 from inside the denser medium):
/// `F = ½ ((g − c)/(g + c))² {1 + [(c(g + c) − 1)/(c(g − c) + 1)]²}`, g = √(v² + c² − 1); 1 under
/// total internal reflection (g² < 0). The transmitted share is 1 − F.
pub fn fresnel_dielectric(c: f64, v: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let v = v.max(0.0);
    // g² = v² − 1 + c², grouped to keep what cancels exact: (v − 1)(v + 1) + c² near grazing (v
    // = 1 gives c² exactly), v² − (1 − c)(1 + c) from c = ½ up (c = 1 gives v² exactly, where the
    // other grouping loses a small v² to the 1s).
    let sin2 = (1.0 - c) * (1.0 + c);
    let g2 = if c < 0.5 { (v - 1.0) * (v + 1.0) + c * c } else { v * v - sin2 };
    if g2 < 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c).max(FRESNEL_G_PLUS_C_MIN);
    // c(g + c) − 1 = cg − sin²θ and c(g − c) + 1 = cg + sin²θ ≥ 0 (v at c = 1), without the 1s.
    let b = (c * g - sin2) / (c * g + sin2).max(FRESNEL_G_PLUS_C_MIN);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

/// How long the part of the ray from `o` along unit `d` inside a sphere (`centre`, `radius`) is:
/// from inside, the chord to the far side; from outside, the whole chord ahead; 0 for a ray that
/// misses it, touches it, has it behind, or leaves it from the surface. The roots of
/// |o + t·d − c|² = r² are taken each in the form that does not cancel (their product is c), so a
/// point next to the surface keeps its precision, and b² − c as r² less the squared distance
/// from the centre to the line, |oc × d|², so a near miss far away is not lost to the rounding
/// of b².
pub fn sphere_chord(o: DVec3, d: DVec3, centre: DVec3, radius: f64) -> f64 {
    let oc = o - centre;
    let b = oc.dot(d);
    let c = oc.length_squared() - radius * radius;
    // |oc × d| is the line's distance from the centre (|d| = 1), without the cancellation of
    // oc − (oc·d)·d when the ray aims almost at the centre from far away.
    let disc = radius * radius - oc.cross(d).length_squared();
    if disc <= 0.0 {
        return 0.0;
    }
    let root = disc.sqrt();
    // Far root −b + √disc and near root −b − √disc; where one would cancel it is c over the other.
    let (far, near) = if b <= 0.0 { (-b + root, c / (-b + root)) } else { (-c / (b + root), -b - root) };
    // Behind: nothing; from inside: to the far side; from outside: far − near, which is 2√disc
    // without cancelling two long distances.
    if far <= 0.0 {
        0.0
    } else if near <= 0.0 {
        far
    } else {
        2.0 * root
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::brdf::fresnel_v_from_mu;

    fn incident(theta: f64) -> DVec3 {
        DVec3::new(theta.sin(), -theta.cos(), 0.0)
    }

    #[test]
    fn snell_holds_and_total_internal_reflection_begins_at_the_critical_angle() {
        let n = DVec3::Y;
        for (n_i, n_t) in [(1.0, 1.5), (1.5, 1.0), (1.33, 2.4), (1.0, 1.0)] {
            let eta = n_i / n_t;
            for deg in [0.0, 10.0, 30.0, 45.0, 60.0, 80.0, 89.9] {
                let theta = f64::to_radians(deg);
                let Some(t) = refract_snell(incident(theta), n, eta) else {
                    assert!(eta * theta.sin() > 1.0, "{n_i}→{n_t} at {deg}°: no ray below the critical angle");
                    continue;
                };
                assert!((t.length() - 1.0).abs() < 1e-12);
                // n_i sin θ_i = n_t sin θ_t, and the ray goes on through the surface.
                assert!((n_i * theta.sin() - n_t * t.x).abs() < 1e-12, "{n_i}→{n_t} at {deg}°");
                assert!(t.y <= 0.0);
            }
        }
        // Glass to air: the critical angle asin(1/1.5), and 1e-7 either side of it.
        let critical = (1.0f64 / 1.5).asin();
        assert!(refract_snell(incident(critical - 1e-7), n, 1.5).is_some());
        assert!(refract_snell(incident(critical + 1e-7), n, 1.5).is_none());
        let grazing = refract_snell(incident(critical - 1e-7), n, 1.5).unwrap();
        assert!(grazing.is_finite() && grazing.y.abs() < 1e-3, "near the critical angle the ray hugs the surface");
        // ior = 1: no interface, the ray goes straight on.
        assert!((refract_snell(incident(0.7), n, 1.0).unwrap() - incident(0.7)).length() < 1e-15);
    }

    #[test]
    fn fresnel_from_either_side_agrees_and_is_one_under_total_internal_reflection() {
        for mu in [0.02, 0.04, 0.1, 0.5] {
            let v = fresnel_v_from_mu(mu);
            // Normal incidence from either side: μ.
            assert!((fresnel_dielectric(1.0, v) - mu).abs() < 1e-12, "μ {mu} from outside");
            assert!((fresnel_dielectric(1.0, 1.0 / v) - mu).abs() < 1e-12, "μ {mu} from inside");
            // Reciprocity: the same reflectance from θ_i outside and θ_t inside.
            for deg in [10.0, 40.0, 70.0, 85.0] {
                let theta = f64::to_radians(deg);
                let t = refract_snell(incident(theta), DVec3::Y, 1.0 / v).unwrap();
                let (outside, inside) = (fresnel_dielectric(theta.cos(), v), fresnel_dielectric(-t.y, 1.0 / v));
                assert!((outside - inside).abs() < 1e-12, "μ {mu} at {deg}°: {outside} vs {inside}");
            }
            // Grazing: everything reflects; past the critical angle from inside, too.
            assert!((fresnel_dielectric(0.0, v) - 1.0).abs() < 1e-12);
            let critical = (1.0 / v).asin();
            assert_eq!(fresnel_dielectric((critical + 1e-7).cos(), 1.0 / v), 1.0);
            assert!(fresnel_dielectric((critical - 1e-3).cos(), 1.0 / v) < 1.0);
        }
        // No interface: nothing reflects.
        assert!(fresnel_dielectric(0.6, 1.0).abs() < 1e-15);
    }

    #[test]
    fn the_chapters_absorption_rule_and_its_error() {
        // Just under a·d = 0.2 the neglected form loses 18 % of the light; at 0.5 the linear form
        // would be off by 0.107 (the rule takes e^(−a·d) from there).
        let under = ABSORPTION_NEGLECT_BELOW - 1e-9;
        assert_eq!(absorption_rule(under), 1.0);
        assert!((absorption_rule(under) - absorption_exact(under) - 0.1813).abs() < 1e-4);
        let just = ABSORPTION_LINEAR_BELOW - 1e-9;
        assert!((absorption_exact(just) - absorption_rule(just) - 0.1065).abs() < 1e-4);
        assert_eq!(absorption_rule(ABSORPTION_LINEAR_BELOW), absorption_exact(ABSORPTION_LINEAR_BELOW));
        assert_eq!(absorption_regime(0.3), AbsorptionForm::Linear);
        // The whole range from 0 to 1e6: finite, in [0, 1], underflowing to 0, no NaN.
        for ad in [0.0, 1e-12, 0.1, 0.2, 0.5, 1.0, 10.0, 745.0, 800.0, 1e6, -1.0] {
            for f in [absorption_exact(ad), absorption_rule(ad)] {
                assert!(f.is_finite() && (0.0..=1.0).contains(&f), "a·d {ad}: {f}");
            }
        }
        assert_eq!(absorption_exact(1e6), 0.0);
    }

    #[test]
    fn the_chord_through_a_sphere_is_exact() {
        let (c, r) = (DVec3::new(0.5, 1.0, -2.0), 0.8);
        // From the centre: the radius; along a chord at distance b from the centre: 2√(r² − b²).
        assert!((sphere_chord(c, DVec3::X, c, r) - r).abs() < 1e-15);
        let b = 0.3;
        let entry = c + DVec3::new(-(r * r - b * b).sqrt(), b, 0.0);
        assert!((sphere_chord(entry, DVec3::X, c, r) - 2.0 * (r * r - b * b).sqrt()).abs() < 1e-12);
        // Zero thickness: at the exit, heading out.
        let exit = c + DVec3::new((r * r - b * b).sqrt(), b, 0.0);
        assert!(sphere_chord(exit, DVec3::X, c, r) < 1e-12);
        // A point a hair inside the surface, heading in: the whole chord, to full precision.
        let d = (c - exit).normalize();
        assert!((sphere_chord(exit + d * 1e-12, d, c, r) - 2.0 * r).abs() < 1e-9);
        // From outside: the whole chord ahead; nothing for a miss, a touch or a sphere behind.
        let far = c - DVec3::X * 10.0 + DVec3::Y * b;
        assert!((sphere_chord(far, DVec3::X, c, r) - 2.0 * (r * r - b * b).sqrt()).abs() < 1e-12);
        assert_eq!(sphere_chord(far + DVec3::Y, DVec3::X, c, r), 0.0);
        assert_eq!(sphere_chord(c - DVec3::X * 10.0 + DVec3::Y * r, DVec3::X, c, r), 0.0);
        assert_eq!(sphere_chord(far, -DVec3::X, c, r), 0.0);
    }
}
