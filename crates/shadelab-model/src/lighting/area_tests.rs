//! The area lights' closed forms against their reference quadrature, their limits, and their hard
//! cases (docs/area-lights.md).

use super::*;
use crate::lighting::area_exact::{specular_area_quadrature, specular_representative_point};
use crate::shadows::penumbra_width;

fn clear(_: DVec3, _: DVec3) -> bool {
    true
}

fn rect(center: DVec3, normal: DVec3, half: f64) -> AreaLight {
    let t = if normal.x.abs() < 0.9 { DVec3::X } else { DVec3::Y }.cross(normal).normalize();
    AreaLight {
        shape: AreaShape::Rect { half_x: half, half_y: 0.7 * half },
        center,
        normal: normal.normalize(),
        tangent: t,
    }
}

fn with_shape(l: AreaLight, shape: AreaShape) -> AreaLight {
    AreaLight { shape, ..l }
}

/// Lights and receivers of every sort: straight above, tilted, off to the side, partly below the
/// receiver's horizon, seen edge-on.
fn configurations() -> Vec<(AreaLight, DVec3, DVec3)> {
    let mut out = Vec::new();
    let receivers = [
        (DVec3::ZERO, DVec3::Z),
        (DVec3::new(0.3, -0.2, 0.0), DVec3::new(0.2, 0.1, 1.0).normalize()),
        (DVec3::ZERO, DVec3::X),
        (DVec3::ZERO, -DVec3::Z),
    ];
    let lights = [
        (DVec3::new(0.0, 0.0, 2.0), DVec3::new(0.0, 0.0, -1.0)),
        (DVec3::new(1.0, 0.5, 1.5), DVec3::new(-0.5, -0.2, -1.0)),
        (DVec3::new(2.0, 0.0, 0.2), DVec3::new(-1.0, 0.0, 0.1)),
        (DVec3::new(0.5, 1.5, 0.0), DVec3::new(-0.3, -1.0, 0.05)),
    ];
    for (p, n) in receivers {
        for (c, ln) in lights {
            out.push((rect(c, ln, 0.4), p, n.normalize()));
        }
    }
    out
}

#[test]
fn lamberts_edge_formula_equals_the_quadrature() {
    for (light, p, n) in configurations() {
        let exact = area_irradiance_exact(&light, p, n).unwrap();
        let (reference, own_error) = area_irradiance_reference(&light, p, n, 128, &clear);
        assert!(own_error < 1e-4 * reference.max(1e-3), "{light:?} at {p}: reference error {own_error:e}");
        assert!(
            (exact - reference).abs() <= 1e-4 * reference.max(1e-2),
            "{light:?} at {p} n {n}: edge formula {exact} vs quadrature {reference}"
        );
    }
    // Some of those configurations are lit, some clipped by the horizon, some dark.
    let values: Vec<f64> = configurations().iter().map(|(l, p, n)| area_irradiance_exact(l, *p, *n).unwrap()).collect();
    assert!(values.iter().any(|v| *v > 0.05) && values.contains(&0.0), "{values:?}");
}

#[test]
fn the_sphere_cap_equals_the_quadrature_above_across_and_below_the_horizon() {
    let (p, n) = (DVec3::ZERO, DVec3::Z);
    for (r, d) in [(0.3, 2.0), (0.9, 1.2), (0.05, 0.5)] {
        // From straight above through the horizon to below it.
        for deg in [0.0, 30.0, 60.0, 80.0, 88.0, 90.0, 92.0, 100.0, 120.0, 180.0] {
            let theta = f64::to_radians(deg);
            let center = DVec3::new(theta.sin(), 0.0, theta.cos()) * d;
            let light =
                AreaLight { shape: AreaShape::Sphere { radius: r }, center, normal: DVec3::Z, tangent: DVec3::X };
            let exact = area_irradiance_exact(&light, p, n).unwrap();
            let (reference, own_error) = area_irradiance_reference(&light, p, n, 192, &clear);
            assert!(own_error < 1e-3 * reference.max(1e-3), "r {r} d {d} θ {deg}°: reference error {own_error:e}");
            // Across the horizon the integrand has a kink, and the quadrature's own error is what
            // bounds the comparison there.
            assert!(
                (exact - reference).abs() <= (1e-4 * reference).max(2.0 * own_error) + 1e-9,
                "r {r} d {d} θ {deg}°: cap {exact} vs quadrature {reference} (±{own_error:e})"
            );
        }
    }
}

#[test]
fn zero_size_is_the_point_light_limit() {
    // A sphere of radius r and radiance L is a point light of intensity I = L·π r²: E = I cos θ / d².
    let (p, n) = (DVec3::ZERO, DVec3::new(0.1, 0.2, 1.0).normalize());
    let center = DVec3::new(0.7, -0.4, 2.5);
    let (d, l) = (center.length(), center.normalize());
    for r in [1e-2, 1e-3, 1e-6] {
        let sphere = AreaLight { shape: AreaShape::Sphere { radius: r }, center, normal: DVec3::Z, tangent: DVec3::X };
        let point = PI * r * r * n.dot(l) / (d * d);
        let e = area_irradiance_exact(&sphere, p, n).unwrap();
        assert!((e - point).abs() <= 1e-3 * point, "sphere r {r}: {e} vs point {point}");
    }
    // A small rectangle or disk emits like a Lambertian point: I(θ_l) = L·A·cos θ_l.
    let facing = DVec3::new(-0.2, 0.3, -1.0).normalize();
    let point = |area: f64| area * facing.dot(-l) * n.dot(l) / (d * d);
    for half in [1e-2, 1e-3] {
        let r = rect(center, facing, half);
        let e = area_irradiance_exact(&r, p, n).unwrap();
        assert!((e - point(r.area())).abs() <= 1e-3 * point(r.area()), "rect {half}: {e} vs {}", point(r.area()));
        let disk = with_shape(r, AreaShape::Disk { radius: half });
        let e = area_irradiance_quadrature(&disk, p, n, 8, &clear);
        assert!((e - point(disk.area())).abs() <= 1e-3 * point(disk.area()), "disk {half}: {e}");
    }
}

#[test]
fn hard_cases_stay_finite_and_in_range() {
    let p = DVec3::ZERO;
    let n = DVec3::Z;
    let cases = [
        // Zero size.
        rect(DVec3::new(0.0, 0.0, 1.0), -DVec3::Z, 0.0),
        // The light's plane through the shaded point.
        rect(DVec3::new(1.0, 0.0, 0.0), DVec3::Z, 0.5),
        rect(DVec3::new(0.0, 0.0, 0.0), DVec3::Z, 0.5),
        // The point on the light, facing it.
        rect(DVec3::new(0.0, 0.0, 0.0), -DVec3::Z, 0.5),
        // Behind the surface.
        rect(DVec3::new(0.0, 0.0, -1.0), DVec3::Z, 0.5),
        // Huge.
        rect(DVec3::new(0.0, 0.0, 1.0), -DVec3::Z, 1e6),
    ];
    for light in cases {
        for shape in [light.shape, AreaShape::Disk { radius: 0.5 }, AreaShape::Sphere { radius: 0.5 }] {
            let l = with_shape(light, shape);
            let exact = area_irradiance_exact(&l, p, n);
            let quad = area_irradiance_quadrature(&l, p, n, 16, &clear);
            for v in exact.into_iter().chain([quad]) {
                assert!(v.is_finite() && (0.0..=PI + 1e-12).contains(&v), "{l:?}: {v}");
            }
        }
    }
    // A huge light overhead covers the hemisphere: E/L → π.
    let huge = area_irradiance_exact(&cases[5], p, n).unwrap();
    assert!((huge - PI).abs() < 1e-3 * PI, "{huge}");
    // Behind the surface: nothing.
    assert_eq!(area_irradiance_exact(&cases[4], p, n), Some(0.0));
    // The back of a one-sided light gives nothing either.
    assert_eq!(area_irradiance_exact(&rect(DVec3::new(0.0, 0.0, 1.0), DVec3::Z, 0.5), p, n), Some(0.0));
    // A sphere the point is inside of, or touching.
    assert_eq!(sphere_irradiance(1.0, 0.5, 0.3), PI);
    for cos in [-1.0, -0.5, 0.0, 1e-9, 0.5, 1.0, f64::NAN.max(0.2)] {
        let e = sphere_irradiance(1.0, 1.0 + 1e-12, cos);
        assert!(e.is_finite() && (0.0..=PI).contains(&e), "{cos}: {e}");
    }
}

#[test]
fn the_quadrature_takes_the_visibility_it_is_given() {
    // A wall at x = 0 hides the light's half with x > 0: what is left is the rectangle's other
    // half, whose edge formula the quadrature must equal.
    let (p, n) = (DVec3::new(-0.5, 0.0, 0.0), DVec3::Z);
    let light = AreaLight {
        shape: AreaShape::Rect { half_x: 0.5, half_y: 0.5 },
        center: DVec3::new(0.0, 0.0, 1.0),
        normal: -DVec3::Z,
        tangent: DVec3::X,
    };
    let left_half = AreaLight {
        shape: AreaShape::Rect { half_x: 0.25, half_y: 0.5 },
        center: DVec3::new(-0.25, 0.0, 1.0),
        ..light
    };
    let wall = |_: DVec3, x: DVec3| x.x < 0.0;
    let (shadowed, own) = area_irradiance_reference(&light, p, n, 64, &wall);
    let exact = area_irradiance_exact(&left_half, p, n).unwrap();
    assert!((shadowed - exact).abs() < 1e-4 * exact && own < 1e-3 * exact, "{shadowed} vs {exact} (±{own})");
    let whole = area_irradiance_exact(&light, p, n).unwrap();
    assert!(shadowed < 0.9 * whole, "the wall must take light away: {shadowed} of {whole}");
}

#[test]
fn the_penumbra_widens_with_the_light_and_the_gap() {
    assert_eq!(penumbra_width(0.5, 2.0, 1.0), 0.5);
    assert_eq!(penumbra_width(1.0, 2.0, 1.0), 1.0);
    assert_eq!(penumbra_width(0.5, 3.0, 1.0), 1.0);
    // Receiver touching the occluder, or in front of it: no penumbra.
    assert_eq!(penumbra_width(0.5, 1.0, 1.0), 0.0);
    assert_eq!(penumbra_width(0.5, 0.5, 1.0), 0.0);
    // A blocker at the light: capped, finite.
    let w = penumbra_width(0.5, 2.0, 0.0);
    assert!(w.is_finite() && w > 0.0, "{w}");
}

#[test]
fn the_chapters_point_sources_converge_to_the_reference_and_one_point_is_far_off() {
    // A light close above the receiver, where one point source is what the chapter calls
    // unnatural: its error falls as the light is cut into more points.
    let light = rect(DVec3::new(0.3, 0.0, 0.6), DVec3::new(-0.3, 0.0, -1.0), 0.5);
    let (p, n) = (DVec3::ZERO, DVec3::Z);
    let exact = area_irradiance_exact(&light, p, n).unwrap();
    let errors: Vec<f64> = [1, 2, 4, 8, 16]
        .iter()
        .map(|&k| (area_irradiance_quadrature(&light, p, n, k, &clear) - exact).abs() / exact)
        .collect();
    assert!(errors[0] > 0.05, "one point source should be visibly off here: {errors:?}");
    assert!(errors.windows(2).all(|w| w[1] < w[0]), "the error must fall with k: {errors:?}");
    assert!(errors[4] < 1e-3, "{errors:?}");
    // k = 1 is the light's centre, carrying its whole area.
    let one: Vec<_> = samples(&light, p, 1).collect();
    assert_eq!(one.len(), 1);
    assert!((one[0].0 - light.center).length() < 1e-12 && (one[0].2 - light.area()).abs() < 1e-12, "{one:?}");
}

#[test]
fn the_specular_integral_converges_and_its_zero_size_limit_is_the_point_light() {
    let (p, n) = (DVec3::ZERO, DVec3::Z);
    let v = DVec3::new(-0.6, 0.1, 0.8).normalize();
    let v_index = [1.5, 1.6, 1.7];
    let light = rect(DVec3::new(1.0, -0.1, 1.4), DVec3::new(-0.6, 0.0, -1.0), 0.3);
    for m in [0.15, 0.4] {
        let coarse = specular_area_quadrature(&light, p, n, v, m, v_index, 64, &clear);
        let fine = specular_area_quadrature(&light, p, n, v, m, v_index, 128, &clear);
        for c in 0..3 {
            assert!(fine[c] > 0.0 && (fine[c] - coarse[c]).abs() < 1e-3 * fine[c], "m {m}: {coarse:?} vs {fine:?}");
        }
    }
    // A tiny light: the point light of intensity L·A·cos θ_l at its centre.
    let tiny = rect(light.center, light.normal, 1e-4);
    let to = tiny.center - p;
    let l = to.normalize();
    let i = tiny.area() * (-tiny.normal.dot(l)) / to.length_squared();
    let point = super::super::brdf::specular_cook_torrance(n, v, l, 0.3, v_index).map(|s| s * i);
    let area = specular_area_quadrature(&tiny, p, n, v, 0.3, v_index, 4, &clear);
    for c in 0..3 {
        assert!((area[c] - point[c]).abs() <= 1e-3 * point[c], "{area:?} vs {point:?}");
    }
}

/// The representative point against the specular integral, and against the plain point light at
/// the centre, over roughness and light size: prints the table docs/area-lights.md gives.
#[test]
fn representative_point_specular_against_the_integral() {
    let (p, n) = (DVec3::ZERO, DVec3::Z);
    let v = DVec3::new(-0.5, 0.0, 0.85).normalize();
    let v_index = [1.5; 3];
    // Lights on the mirror direction of v and turned 8° and 20° off it, 2 m away.
    let mut rows = Vec::new();
    for off in [0.0f64, 8.0, 20.0] {
        let mirror = f64::atan2(0.5, 0.85) + off.to_radians();
        let c = DVec3::new(mirror.sin(), 0.0, mirror.cos()) * 2.0;
        for (name, shape) in [
            ("sphere r 0.1", AreaShape::Sphere { radius: 0.1 }),
            ("sphere r 0.4", AreaShape::Sphere { radius: 0.4 }),
            ("rect 0.2", AreaShape::Rect { half_x: 0.1, half_y: 0.1 }),
            ("rect 0.8", AreaShape::Rect { half_x: 0.4, half_y: 0.4 }),
        ] {
            let light = AreaLight { shape, center: c, normal: (-c).normalize(), tangent: DVec3::Y };
            for m in [0.1, 0.2, 0.4, 0.7] {
                let reference = specular_area_quadrature(&light, p, n, v, m, v_index, 256, &clear)[0];
                let rp = specular_representative_point(&light, p, n, v, m, v_index)[0];
                let l = c.normalize();
                let point_i = match shape {
                    AreaShape::Sphere { radius } => PI * radius * radius,
                    _ => light.area(),
                } / c.length_squared();
                let centre = super::super::brdf::specular_cook_torrance(n, v, l, m, v_index)[0] * point_i;
                assert!(reference.is_finite() && rp.is_finite() && reference > 0.0, "{name} m {m}");
                rows.push((name, m, off, (rp - reference) / reference, (centre - reference) / reference));
            }
        }
    }
    for (name, m, off, rp, centre) in &rows {
        eprintln!("AREA-SPEC | {name} | {off}° | {m} | {rp:+.3} | {centre:+.3} |");
    }
    // Where the highlight falls on a light large against the lobe, the representative point must
    // beat the point light at the centre (the widening is what it adds there).
    let on_light: Vec<_> =
        rows.iter().filter(|r| r.2 == 0.0 && (r.0.ends_with("0.4") || r.0.ends_with("0.8")) && r.1 <= 0.2).collect();
    assert_eq!(on_light.len(), 4);
    for (name, m, _, rp, centre) in on_light {
        assert!(rp.abs() < centre.abs(), "{name} m {m}: representative point {rp:+.3} vs centre {centre:+.3}");
    }
    // Off the light's edge it overshoots (docs/area-lights.md has the table this prints).
}

/// A sphere occluder in front of a sphere light, exactly: seen from the point, the light and the
/// occluder are two spherical caps, and where the occluder's cap lies wholly inside the light's
/// (both above the horizon) the light the point loses is the occluder's cap's own E/L, the light's
/// radiance being the same over it; where the caps do not meet it loses nothing. The reference
/// (the quadrature with a shadow ray to each cell) meets both within its own error. Where the caps
/// overlap in part their lens has no closed form (the projected lens of two ellipses) and the
/// quadrature is the reference.
#[test]
fn a_sphere_occluder_removes_its_own_cap_from_a_sphere_light() {
    let (p, n) = (DVec3::ZERO, DVec3::new(0.1, 0.0, 1.0).normalize());
    let (light_r, light_at) = (0.6, DVec3::new(0.4, 0.2, 3.0));
    let light = AreaLight {
        shape: AreaShape::Sphere { radius: light_r },
        center: light_at,
        normal: DVec3::Z,
        tangent: DVec3::X,
    };
    let axis = light_at.normalize();
    let side = axis.cross(DVec3::Y).normalize();
    // Inside the light's cap (σ_L = asin(0.6/3.04) ≈ 11.4°): the occluder's cap, σ_O = asin(0.1/1.2)
    // ≈ 4.8°, 3° off the light's axis; then well clear of it.
    let inside = (axis * (3.0f64.to_radians()).cos() + side * (3.0f64.to_radians()).sin()) * 1.2;
    let clear_of = (axis * (30.0f64.to_radians()).cos() + side * (30.0f64.to_radians()).sin()) * 1.2;
    let occluder_r = 0.1;
    let unoccluded = area_irradiance_exact(&light, p, n).unwrap();
    for (centre, cut) in [(inside, true), (clear_of, false)] {
        let blocked = |a: DVec3, b: DVec3| {
            // The segment a→b misses the occluder: its nearest point is farther than the radius.
            let ab = b - a;
            let t = ((centre - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
            (a + ab * t - centre).length() > occluder_r
        };
        let d = centre.length();
        let lost = if cut { sphere_irradiance(occluder_r, d, n.dot(centre) / d) } else { 0.0 };
        let exact = unoccluded - lost;
        let (reference, own_error) = area_irradiance_reference(&light, p, n, 96, &blocked);
        assert!(own_error < 5e-3 * reference, "reference error {own_error:e} of {reference}");
        assert!(
            (exact - reference).abs() <= 2.0 * own_error + 1e-6,
            "occluder inside = {cut}: two caps {exact} vs quadrature {reference} (±{own_error:e}), unoccluded {unoccluded}"
        );
        if cut {
            assert!(lost > 0.1 * unoccluded, "the occluder must take a visible share: {lost} of {unoccluded}");
        }
    }
}
