//! Area lights as surfaces for the path tracer (docs/reference.md, "Light between surfaces"): a
//! bounce that meets a rectangle, disk or sphere light ends there. Its front (a sphere's whole
//! outside) emits, its back is black; nothing passes through. Where the vertex it left from
//! sampled that light's direct light by area, the two estimates are weighed by the power
//! heuristic (`path.rs`); otherwise the direct light already holds all of it.

use crate::Light;
use crate::lighting::area::{AreaLight, AreaShape};
use glam::DVec3;
use std::f64::consts::TAU;

/// A bounce's meeting with a light.
pub(super) struct LightHit {
    /// Ray parameter of the meeting (the ray's direction is unit).
    pub t: f64,
    /// The light's index in the scene.
    pub light: usize,
    /// Whether the ray meets the emitting side.
    pub front: bool,
    /// The density, per solid angle at the ray's origin, with which the light's own sampling
    /// (`area::random_cell`) draws this point: `r²/(cos θ_l·A_s)`.
    pub density: f64,
}

/// The nearest area light the unit ray from `o` along `dir` meets, if any, of the scene's
/// lights' surfaces `areas` (`Light::area_light` of each).
pub(super) fn light_hit(areas: &[Option<AreaLight>], o: DVec3, dir: DVec3) -> Option<LightHit> {
    let mut best: Option<LightHit> = None;
    for (i, area) in areas.iter().enumerate() {
        let Some(area) = area else { continue };
        if let Some(hit) = meet(area, o, dir, i)
            && best.as_ref().is_none_or(|b| hit.t < b.t)
        {
            best = Some(hit);
        }
    }
    best
}

/// Where the ray meets `area`: the nearest point ahead on its surface.
fn meet(area: &AreaLight, o: DVec3, dir: DVec3, light: usize) -> Option<LightHit> {
    let b = area.normal.cross(area.tangent);
    let (t, normal, sampled_area) = match area.shape {
        AreaShape::Rect { half_x, half_y } => {
            let t = plane(area, o, dir)?;
            let q = o + dir * t - area.center;
            let inside = q.dot(area.tangent).abs() <= half_x && q.dot(b).abs() <= half_y;
            inside.then_some((t, area.normal, area.area()))?
        }
        AreaShape::Disk { radius } => {
            let t = plane(area, o, dir)?;
            let inside = (o + dir * t - area.center).length_squared() <= radius * radius;
            inside.then_some((t, area.normal, area.area()))?
        }
        AreaShape::Sphere { radius } => {
            // The near root of |o + t·dir − c|² = r²; from inside no light is met (none is drawn).
            let oc = o - area.center;
            let (half_b, c) = (oc.dot(dir), oc.length_squared() - radius * radius);
            let disc = half_b * half_b - c;
            if c <= 0.0 || disc < 0.0 {
                return None;
            }
            let t = -half_b - disc.sqrt();
            if t <= 0.0 {
                return None;
            }
            let normal = (o + dir * t - area.center) / radius.abs();
            // The cap `o` sees is what the light's sampling covers.
            let cap = TAU * radius * radius * (1.0 - radius.abs() / oc.length());
            (t, normal, cap)
        }
    };
    let cos_l = -normal.dot(dir);
    let front = cos_l > 0.0;
    let density = if front && sampled_area > 0.0 { t * t / (cos_l * sampled_area) } else { 0.0 };
    Some(LightHit { t, light, front, density })
}

/// The ray parameter where the ray crosses the flat light's plane, ahead of it.
fn plane(area: &AreaLight, o: DVec3, dir: DVec3) -> Option<f64> {
    let denom = area.normal.dot(dir);
    if denom == 0.0 {
        return None;
    }
    let t = area.normal.dot(area.center - o) / denom;
    (t > 0.0 && t.is_finite()).then_some(t)
}

/// The radiance of `light`'s front towards a point `p`, in the image's units: the chapter's area
/// light is its centre's point light spread over its area, `π·I·f(d)·d²/A` for `p` at `d` from
/// its centre (`π·I_L` being the irradiance a light of intensity `I_L` stands for). `None` for a
/// light without area, or `p` at its centre.
pub(super) fn light_radiance(light: &Light, p: DVec3) -> Option<[f64; 3]> {
    let area = light.area_light()?;
    let (d2, emitting) = ((area.center - p).length_squared(), area.emitting_area());
    if d2 <= crate::guards::LIGHT_DIST_MIN.powi(2) || emitting <= 0.0 || !emitting.is_finite() {
        return None;
    }
    // The radiance at the centre's distance, with its falloff, range and cone (no area term).
    let at = crate::lighting::lights::light_radiance_at(light, p, DVec3::Z);
    Some(at.map(|r| std::f64::consts::PI * r * d2 / emitting))
}
