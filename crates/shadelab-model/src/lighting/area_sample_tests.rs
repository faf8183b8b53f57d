//! What the renderer computes for an area light, against the reference: the disk's polygon, the
//! diffuse form's point-light limit and its continuity at the switch, the light sample of each
//! kind, and the hard cases (docs/area-lights.md).

use super::*;
use crate::lighting::lights::{Light, LightKind, light_sample};

fn clear(_: DVec3, _: DVec3) -> bool {
    true
}

fn flat(shape: AreaShape, center: DVec3, normal: DVec3) -> AreaLight {
    let normal = normal.normalize();
    let tangent = if normal.x.abs() < 0.9 { DVec3::X } else { DVec3::Y }.cross(normal).normalize();
    AreaLight { shape, center, normal, tangent }
}

/// The disk's equal-area polygon against the disk's quadrature: within 0.3 % wherever the light
/// delivers over 1 % of its peak, across tilts, distances and the receiver's horizon.
#[test]
fn the_disks_polygon_is_the_disk_within_three_tenths_of_a_percent() {
    let mut worst: f64 = 0.0;
    for (c, ln) in [
        (DVec3::new(0.0, 0.0, 2.0), -DVec3::Z),
        (DVec3::new(0.0, 0.0, 0.3), -DVec3::Z),
        (DVec3::new(1.0, 0.5, 1.5), DVec3::new(-0.5, -0.2, -1.0)),
        (DVec3::new(2.0, 0.0, 0.2), DVec3::new(-1.0, 0.0, 0.1)),
        (DVec3::new(0.5, 1.5, 0.1), DVec3::new(-0.3, -1.0, 0.05)),
    ] {
        let light = flat(AreaShape::Disk { radius: 0.4 }, c, ln);
        for n in [DVec3::Z, DVec3::new(0.3, 0.2, 1.0).normalize(), DVec3::X] {
            let (reference, own) = area_irradiance_reference(&light, DVec3::ZERO, n, 128, &clear);
            let polygon = area_irradiance(&light, DVec3::ZERO, n);
            if reference < 0.01 * PI * 0.16 / c.length_squared() {
                continue;
            }
            let err = (polygon - reference).abs() / reference;
            assert!(err <= 3e-3 + own / reference, "{c} {n}: polygon {polygon} vs disk {reference} (±{own})");
            worst = worst.max(err);
        }
    }
    eprintln!("disk polygon: worst relative error {worst:.2e}");
}

/// As a light shrinks its form tends to its point limit (cos θ_p for a sphere, cos θ_p·cos θ_l
/// for a flat light), and the switch to that limit at AREA_POINT_LIMIT_ANGLE moves it by under
/// 1e-3.
#[test]
fn the_form_tends_to_the_point_limit_and_switches_to_it_smoothly() {
    let (p, n) = (DVec3::ZERO, DVec3::new(0.2, 0.1, 1.0).normalize());
    let c = DVec3::new(0.7, -0.4, 2.0);
    let d = c.length();
    let l = c / d;
    let normal = DVec3::new(-0.2, 0.3, -1.0).normalize();
    for (shape, cos_l) in [
        (AreaShape::Sphere { radius: 1.0 }, 1.0),
        (AreaShape::Rect { half_x: 1.0, half_y: 0.6 }, -normal.dot(l)),
        (AreaShape::Disk { radius: 1.0 }, -normal.dot(l)),
    ] {
        let limit = n.dot(l) * cos_l;
        let scaled = |k: f64| {
            let shape = match shape {
                AreaShape::Sphere { radius } => AreaShape::Sphere { radius: radius * k },
                AreaShape::Rect { half_x, half_y } => AreaShape::Rect { half_x: half_x * k, half_y: half_y * k },
                AreaShape::Disk { radius } => AreaShape::Disk { radius: radius * k },
            };
            flat(shape, c, normal)
        };
        // Just above and just below the switch: the formula and the limit agree there.
        let at = AREA_POINT_LIMIT_ANGLE * d / scaled(1.0).area_radius();
        let (above, below) = (area_form(&scaled(at * 1.0001), p, n), area_form(&scaled(at * 0.9999), p, n));
        assert!((above - below).abs() <= 1e-3 * limit, "{shape:?}: {above} above the switch, {below} below");
        assert_eq!(below, limit.max(0.0));
        // Zero size: exactly the limit.
        assert_eq!(area_form(&scaled(0.0), p, n), limit.max(0.0));
        // Larger lights part from it, the form staying finite and positive.
        let big = area_form(&scaled(0.5), p, n);
        assert!(big.is_finite() && big > 0.0, "{shape:?}: {big}");
    }
}

/// A zero-size area light is its point light: the sphere exactly the point light, a rectangle
/// or disk the point light times cos θ_l (a Lambertian point), within 1e-3 on the diffuse and
/// the specular factors.
#[test]
fn a_zero_size_area_light_is_the_point_light() {
    let point = Light::point(DVec3::new(0.8, 2.0, 0.5), [1.0, 0.9, 0.8], 2.0, 0.05);
    let (p, n) = (DVec3::new(0.1, 0.0, -0.2), DVec3::new(0.1, 1.0, 0.2).normalize());
    let v = DVec3::new(-0.3, 0.8, 0.4).normalize();
    let ps = light_sample(&point, p, n, v, 0.3);
    for kind in [LightKind::Sphere, LightKind::Rect, LightKind::Disk] {
        let axis = DVec3::new(0.1, -1.0, 0.3);
        let area = Light::area(kind, point.position, axis, [0.0; 2], point.color, point.intensity, point.falloff_alpha);
        let s = light_sample(&area, p, n, v, 0.3);
        let cos_l = if kind == LightKind::Sphere { 1.0 } else { -area.spot_axis().dot(ps.l) };
        assert!((s.l - ps.l).length() < 1e-9, "{kind:?}");
        assert_eq!(s.radiance, ps.radiance, "{kind:?}");
        assert!((s.form - ps.form * cos_l).abs() <= 1e-3 * ps.form, "{kind:?}: {} vs {}", s.form, ps.form * cos_l);
        assert!((s.spec_scale - cos_l).abs() <= 1e-3, "{kind:?}: {}", s.spec_scale);
    }
}

/// Every kind's sample stays finite over the hard cases: zero size, the light's plane through
/// the point, the point on the light and at its centre, a light behind the surface, a 10⁶ m
/// light, grazing and backward views, roughness 0.
#[test]
fn area_samples_stay_finite_in_the_hard_cases() {
    let (p, n) = (DVec3::ZERO, DVec3::Y);
    let mut checked = 0;
    for kind in [LightKind::Rect, LightKind::Disk, LightKind::Sphere] {
        for (center, axis) in [
            (DVec3::new(0.0, 1.0, 0.0), DVec3::NEG_Y),
            (DVec3::new(1.0, 0.0, 0.0), DVec3::Y),
            (DVec3::new(1.0, 0.0, 0.0), DVec3::NEG_X),
            (DVec3::ZERO, DVec3::NEG_Y),
            (DVec3::new(0.2, 0.0, 0.0), DVec3::NEG_Y),
            (DVec3::new(0.0, -1.0, 0.0), DVec3::Y),
            (DVec3::new(0.0, 1.0, 0.0), DVec3::Y),
        ] {
            for size in [0.0, 1e-9, 0.5, 2.0, 1e6] {
                for v in [DVec3::Y, DVec3::new(1.0, 1e-7, 0.0).normalize(), DVec3::new(0.0, -0.5, 1.0).normalize()] {
                    for m in [0.0, 0.05, 1.0] {
                        let light = Light::area(kind, center, axis, [size; 2], [1.0; 3], 1.0, 0.1);
                        let s = light_sample(&light, p, n, v, m);
                        let ok = s.l.is_finite()
                            && (s.l.length() - 1.0).abs() < 1e-6
                            && s.form.is_finite()
                            && s.form >= 0.0
                            && s.spec_scale.is_finite()
                            && s.spec_scale >= 0.0
                            && s.radiance.iter().all(|r| r.is_finite());
                        assert!(ok, "{kind:?} at {center} facing {axis}, size {size}, v {v}, m {m}: {s:?}");
                        checked += 1;
                    }
                }
            }
        }
    }
    assert_eq!(checked, 3 * 7 * 5 * 3 * 3);
}
