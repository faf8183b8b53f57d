//! The chapter's approximation of an area light by k point sources (docs/area-lights.md), the
//! twin of `shaders/area_points.wgsl`. The points lie on the light in a deterministic stratified
//! pattern; each is a Lambertian emitter (a flat light's face, or a sphere's surface facing the
//! point) with 1/k of the light's power and its own hard shadow. As k grows their sum converges
//! to the exact area form, the specular integral over the light and the true soft shadow; k = 1
//! is the light's centre, i.e. the point light the chapter calls unnatural (with a flat light's
//! emitter cosine).

use super::area::AreaShape;
use super::lights::{Light, LightSample};
use crate::guards::LIGHT_DIST_MIN;
use glam::{DVec2, DVec3};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// 1/φ: the lattice's second coordinate steps by it, the most even of all steps (the Fibonacci
/// lattice).
pub const AREA_GOLDEN_FRACTION: f64 = 0.618_033_988_749_895;
/// 2π/φ²: the Fibonacci sphere's turn per point.
pub const AREA_GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// One of the point sources: where it is, the normal it emits around (zero: the same in every
/// direction) and the share of the light's power it carries, relative to the centre's point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaEmitter {
    pub position: DVec3,
    pub normal: DVec3,
    pub gain: f64,
}

/// How many samples the light loop takes of `light`: its k where it is drawn as points, else 1.
pub fn area_point_count(light: &Light) -> u32 {
    if light.drawn_as_points() { light.area_points } else { 1 }
}

/// Point `j` of `k` of the Fibonacci lattice on the unit square: x stratified, y stepped by
/// 1/φ; the first of one point is the centre.
pub fn area_lattice(j: u32, k: u32) -> DVec2 {
    let x = (j as f64 + 0.5) / k.max(1) as f64;
    let y = (0.5 + j as f64 * AREA_GOLDEN_FRACTION).fract();
    DVec2::new(x, y)
}

/// The unit square onto the unit disk, area-preserving and keeping strata compact (Shirley and
/// Chiu's concentric map); the square's centre goes to the disk's.
pub fn concentric_disk(u: DVec2) -> DVec2 {
    let a = 2.0 * u.x - 1.0;
    let b = 2.0 * u.y - 1.0;
    if a == 0.0 && b == 0.0 {
        return DVec2::ZERO;
    }
    let (r, phi) = if a.abs() > b.abs() { (a, FRAC_PI_4 * (b / a)) } else { (b, FRAC_PI_2 - FRAC_PI_4 * (a / b)) };
    DVec2::new(r * phi.cos(), r * phi.sin())
}

/// Point `j` of `k` of the Fibonacci sphere: unit directions of equal-area bands, turned by the
/// golden angle, pole along y.
pub fn fibonacci_sphere(j: u32, k: u32) -> DVec3 {
    let y = 1.0 - 2.0 * (j as f64 + 0.5) / k.max(1) as f64;
    let r = (1.0 - y * y).max(0.0).sqrt();
    let phi = AREA_GOLDEN_ANGLE * j as f64;
    DVec3::new(r * phi.cos(), y, r * phi.sin())
}

/// Point source `j` of area light `light` drawn as its `area_points` points: on a flat light
/// the lattice (concentric on a disk), emitting around the light's normal with 1/k of its power;
/// on a sphere the centre alone for k = 1 (the point light), else the Fibonacci points on its
/// surface, each emitting around its own normal with 4/k (the sphere's πr² facing any point is
/// a quarter of its surface).
pub fn area_emitter(light: &Light, j: u32) -> AreaEmitter {
    let k = light.area_points.max(1);
    let Some(area) = light.area_light() else {
        return AreaEmitter { position: light.position, normal: DVec3::ZERO, gain: 1.0 };
    };
    let b = area.normal.cross(area.tangent);
    let u = area_lattice(j, k);
    match area.shape {
        AreaShape::Rect { half_x, half_y } => AreaEmitter {
            position: area.center + area.tangent * ((2.0 * u.x - 1.0) * half_x) + b * ((2.0 * u.y - 1.0) * half_y),
            normal: area.normal,
            gain: 1.0 / k as f64,
        },
        AreaShape::Disk { radius } => {
            let q = concentric_disk(u) * radius;
            AreaEmitter {
                position: area.center + area.tangent * q.x + b * q.y,
                normal: area.normal,
                gain: 1.0 / k as f64,
            }
        }
        AreaShape::Sphere { radius } if k > 1 => {
            let s = fibonacci_sphere(j, k);
            AreaEmitter { position: area.center + s * radius, normal: s, gain: 4.0 / k as f64 }
        }
        AreaShape::Sphere { .. } => AreaEmitter { position: area.center, normal: DVec3::ZERO, gain: 1.0 },
    }
}

/// Point source `e` of `light` ([`area_emitter`]) at point `p` with unit normal `n`: the centre's
/// sample `base` (its falloff and colour) with the direction to the point source and its factor
/// gain·cos θ_e·d²/r² (d to the centre, r to the source, r² at least LIGHT_DIST_MIN²) on both
/// the diffuse form and the specular. Summed over j this converges to the area form.
pub fn area_point_sample(base: &LightSample, light: &Light, e: &AreaEmitter, p: DVec3, n: DVec3) -> LightSample {
    let d2 = (light.position - p).length_squared();
    let to = e.position - p;
    let r = to.length();
    let l = if r > LIGHT_DIST_MIN { to / r } else { n };
    let cos_e = if e.normal == DVec3::ZERO { 1.0 } else { (-e.normal.dot(l)).max(0.0) };
    let scale = e.gain * cos_e * d2 / (r * r).max(LIGHT_DIST_MIN * LIGHT_DIST_MIN);
    LightSample { l, radiance: base.radiance, form: scale * n.dot(l), spec_scale: scale, ltc: None }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::LightKind;
    use crate::lighting::area::area_form;
    use crate::lighting::lights::light_sample;

    fn area(kind: LightKind, k: u32) -> Light {
        let mut l = Light::area(kind, DVec3::new(0.3, 2.0, -0.1), DVec3::NEG_Y, [0.8, 0.5], [1.0; 3], 1.0, 0.0);
        l.tangent = DVec3::new(1.0, 0.0, 0.4);
        l.area_points = k;
        l
    }

    fn form_sum(light: &Light, p: DVec3, n: DVec3) -> f64 {
        let base = light_sample(light, p, n, DVec3::Y, 0.3);
        (0..area_point_count(light)).map(|j| area_point_sample(&base, light, &area_emitter(light, j), p, n).form).sum()
    }

    #[test]
    fn one_point_is_the_centre_point_light() {
        let (p, n) = (DVec3::new(0.7, 0.0, 0.2), DVec3::new(0.1, 1.0, 0.0).normalize());
        for kind in [LightKind::Rect, LightKind::Disk, LightKind::Sphere] {
            let light = area(kind, 1);
            let l = (light.position - p).normalize();
            let cos_e = if kind == LightKind::Sphere { 1.0 } else { l.y };
            let got = form_sum(&light, p, n);
            assert!((got - n.dot(l) * cos_e).abs() < 1e-12, "{kind:?}: {got}");
        }
    }

    #[test]
    fn many_points_converge_to_the_exact_area_form() {
        // A point 2 m under a 0.8 × 0.5 m light, off its axis: close enough that k matters.
        let (p, n) = (DVec3::new(0.4, 0.0, 0.9), DVec3::new(-0.2, 1.0, 0.1).normalize());
        for kind in [LightKind::Rect, LightKind::Disk, LightKind::Sphere] {
            let exact = area_form(&area(kind, 0).area_light().unwrap(), p, n);
            let err = |k| (form_sum(&area(kind, k), p, n) - exact).abs() / exact;
            // The method converges: past the CLI's 16 points too (the functions take any k). The
            // disk's exact form is its equal-area polygon's, within 0.3 % of the disk's.
            assert!(err(256) < 3e-3, "{kind:?}: k = 256 off by {}", err(256));
            assert!(err(64) < err(4), "{kind:?}: k = 4 off by {}, k = 64 by {}", err(4), err(64));
        }
    }

    #[test]
    fn lattice_and_maps_stay_on_the_shape() {
        for k in 1..=16 {
            for j in 0..k {
                let u = area_lattice(j, k);
                assert!((0.0..1.0).contains(&u.x) && (0.0..1.0).contains(&u.y));
                assert!(concentric_disk(u).length() <= 1.0 + 1e-12);
                assert!((fibonacci_sphere(j, k).length() - 1.0).abs() < 1e-12);
            }
        }
        assert_eq!(concentric_disk(DVec2::splat(0.5)), DVec2::ZERO);
    }
}
