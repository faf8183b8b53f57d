//! Light through a surface in f64 (docs/transparency.md, the chapter's 7.5): Snell's law with
//! total internal reflection, the chapter's exact Fresnel factor at an interface met from either
//! side, absorption by Beer–Lambert and by the chapter's rule (linear below a·d = 0.5, neglected
//! below 0.2), the exact chord through a sphere and the exact exit from each analytic shape. The
//! effect analysis reads the rule's thresholds; the glass pass (`shaders/glass.wgsl`) and the
//! reference's tracer (`reference/glass.rs`) use the rest. The WGSL twin is
//! `shaders/transmission.wgsl`.

pub use super::microfacet::fresnel_dielectric;
use crate::guards::QUADRIC_A_MIN;
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

/// How the glass pass absorbs (`--absorption`, docs/transparency.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum AbsorptionChoice {
    /// e^(−a·d) everywhere.
    Exact,
    /// The chapter's rule picks each object's form from its largest a·d (its longest chord).
    #[default]
    Rule,
}

crate::named_values!(AbsorptionChoice, "--absorption", "exact" => Exact, "rule" => Rule);

/// Where the glass pass finds a path's exit (`--glass-exit`, docs/transparency.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum GlassExit {
    /// Exactly, for the analytic shapes; a mesh's from its back faces.
    #[default]
    Analytic,
    /// From the back faces for every object (to compare the two).
    BackFaces,
}

crate::named_values!(GlassExit, "--glass-exit", "analytic" => Analytic, "back-faces" => BackFaces);

/// What a transparent object's pixels show (`--glass-view`, docs/transparency.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum GlassView {
    /// Its colour.
    #[default]
    Color,
    /// Red where an exit reflected the path back inside (total internal reflection).
    Tir,
    /// The path length inside, white at the object's longest chord.
    Path,
    /// The form the chapter's rule takes for the pixel's a·d: green neglected, yellow linear, red
    /// exact.
    Regime,
}

crate::named_values!(GlassView, "--glass-view", "color" => Color, "tir" => Tir, "path" => Path, "regime" => Regime);

impl GlassView {
    /// The view's code in the WGSL (`GLASS_VIEW_…`).
    pub fn code(self) -> u32 {
        self as u32
    }
}

impl AbsorptionForm {
    /// The form's code in the WGSL (`ABSORPTION_…`).
    pub fn code(self) -> u32 {
        match self {
            AbsorptionForm::Exact => 0,
            AbsorptionForm::Linear => 1,
            AbsorptionForm::Neglected => 2,
        }
    }
}

/// The share of light left after optical depth `ad` in `form`: 1 − a·d held at 0 or above (a
/// path longer than the one the form was picked for cannot go negative).
pub fn absorption_in_form(ad_in: f64, form: u32) -> f64 {
    let ad = ad_in.max(0.0);
    match form {
        2 => 1.0,
        1 => (1.0 - ad).max(0.0),
        _ => absorption_exact(ad),
    }
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
    absorption_in_form(ad, absorption_regime(ad.max(0.0)).code())
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

/// An analytic shape's code in the exit functions (the WGSL's `SHAPE_…`; `Shape::exit_code`).
pub const SHAPE_SPHERE: u32 = 0;
pub const SHAPE_CYLINDER: u32 = 1;
pub const SHAPE_CUBE: u32 = 2;
pub const SHAPE_PLANE: u32 = 3;
pub const SHAPE_PYRAMID: u32 = 4;
/// A file's mesh: no analytic exit; the glass pass reads its back faces.
pub const SHAPE_MESH: u32 = 5;

/// The unit cube's faces as `n·p ≤ 1`.
pub const CUBE_PLANES: [DVec3; 6] = [DVec3::X, DVec3::NEG_X, DVec3::Y, DVec3::NEG_Y, DVec3::Z, DVec3::NEG_Z];
/// The unit pyramid's faces as `n·p ≤ 1`: the sides through the apex (0, 1, 0) and a base edge at
/// e·x = 1, y = −1 (2 e·x + y ≤ 1); the base −y ≤ 1.
pub const PYRAMID_PLANES: [DVec3; 5] = [
    DVec3::new(2.0, 1.0, 0.0),
    DVec3::new(-2.0, 1.0, 0.0),
    DVec3::new(0.0, 1.0, 2.0),
    DVec3::new(0.0, 1.0, -2.0),
    DVec3::NEG_Y,
];

/// Where the ray from `o` inside unit shape `shape` (object space, `SHAPE_…`) along `d` (any
/// length) leaves it: `(t, n)`, the exit at `o + t·d` and the outward normal `n` there (not
/// unit). A point a rounding outside counts as on the surface (t = 0: the exit touches the
/// entry). The plane has no inside: t = 0, the normal facing along `d`. `None` for a mesh or a
/// zero direction.
pub fn shape_exit(shape: u32, o: DVec3, d: DVec3) -> Option<(f64, DVec3)> {
    if d == DVec3::ZERO {
        return None;
    }
    match shape {
        SHAPE_SPHERE => {
            let t = quadric_exit(d.dot(d), o.dot(d), o.dot(o) - 1.0);
            Some((t, o + d * t))
        }
        SHAPE_CYLINDER => {
            let (a, b, c) = (d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - 1.0);
            let side = if a > 0.0 { quadric_exit(a, b, c) } else { f64::INFINITY };
            let cap = if d.y != 0.0 { ((d.y.signum() - o.y) / d.y).max(0.0) } else { f64::INFINITY };
            if cap < side {
                Some((cap, DVec3::new(0.0, d.y.signum(), 0.0)))
            } else {
                let p = o + d * side;
                Some((side, DVec3::new(p.x, 0.0, p.z)))
            }
        }
        SHAPE_CUBE => planes_exit(o, d, &CUBE_PLANES),
        SHAPE_PLANE => Some((0.0, if d.y < 0.0 { DVec3::NEG_Y } else { DVec3::Y })),
        SHAPE_PYRAMID => planes_exit(o, d, &PYRAMID_PLANES),
        _ => None,
    }
}

/// The far root of `a·t² + 2b·t + c = 0` for a point inside (`c ≤ 0`, held there), in the form
/// that does not cancel: `−c/(b + √disc)` for `b > 0`, else `(√disc − b)/a`; at least 0.
pub fn quadric_exit(a: f64, b: f64, c_in: f64) -> f64 {
    let c = c_in.min(0.0);
    let root = (b * b - a * c).max(0.0).sqrt();
    if b > 0.0 { -c / (b + root) } else { (root - b) / a.max(QUADRIC_A_MIN) }
}

/// The exit through convex planes `n·p ≤ 1`: the nearest plane the ray runs towards (n·d > 0),
/// at least 0.
pub fn planes_exit(o: DVec3, d: DVec3, planes: &[DVec3]) -> Option<(f64, DVec3)> {
    let mut best: Option<(f64, DVec3)> = None;
    for &n in planes {
        let towards = n.dot(d);
        if towards <= 0.0 {
            continue;
        }
        let t = ((1.0 - n.dot(o)) / towards).max(0.0);
        if best.is_none_or(|b| t < b.0) {
            best = Some((t, n));
        }
    }
    best
}

/// The mirror direction of `i` about unit normal `n`.
pub fn reflect_about(i: DVec3, n: DVec3) -> DVec3 {
    i - n * (2.0 * i.dot(n))
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
