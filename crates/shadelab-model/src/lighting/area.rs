//! Area lights in f64 (docs/area-lights.md): what a rectangle, disk or sphere light of uniform
//! radiance L delivers to a point, as the irradiance factor E/L = ∫ cos θ_p⁺ cos θ_l⁺ / r² dA.
//! Exact where a closed form exists (Lambert's edge formula for a polygon, the spherical cap for a
//! sphere, both clipped at the point's horizon), and the reference integral over the light's
//! area by deterministic midpoint quadrature with binary visibility, which also reports its own
//! error. The penumbra width the shadow filters aim for is here too. The WGSL twin does not exist
//! yet: these are the reference the GPU's area lights will be held to.

use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Squared length under which the cross product of two directions to neighbouring polygon
/// corners counts as zero: the edge is seen end-on (or the corners coincide), its solid angle
/// and its term in Lambert's sum are zero. 1e-24 is (1e-12)², far below any edge a scene in
/// double precision resolves, and far above f64's smallest normal.
pub const EDGE_CROSS_MIN_LEN2: f64 = 1e-24;

/// Distance under which a polygon corner counts as touching the shaded point: its direction is
/// undefined, and the point lies on the light (E/L is then that of half the hemisphere or more,
/// which the clipped formula reaches without it). Same value and reason as `LIGHT_DIST_MIN`.
pub const AREA_CORNER_DIST_MIN: f64 = crate::guards::LIGHT_DIST_MIN;

/// Smallest blocker distance in the penumbra width w_light·(d_r − d_b)/d_b: a receiver touching
/// its occluder has d_b → 0 only when the light touches the occluder too; below 1e-4 (the
/// scenes' unit is a metre: a tenth of a millimetre) the width is capped rather than infinite.
pub const BLOCKER_DIST_MIN: f64 = 1e-4;

/// The shape of an area light, in its own frame: centred at the origin, emitting along +z
/// (rectangle and disk emit from their front face only; a sphere from all of its surface).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AreaShape {
    /// A rectangle of half-sizes (x, y).
    Rect { half_x: f64, half_y: f64 },
    /// A disk of radius r in the xy-plane.
    Disk { radius: f64 },
    /// A sphere of radius r.
    Sphere { radius: f64 },
}

/// An area light placed in the world: its centre, the unit normal of its emitting face (unused by
/// a sphere) and a unit tangent along the rectangle's x.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight {
    pub shape: AreaShape,
    pub center: DVec3,
    pub normal: DVec3,
    pub tangent: DVec3,
}

impl AreaLight {
    /// The light's area in m² (a sphere's whole surface).
    pub fn area(&self) -> f64 {
        match self.shape {
            AreaShape::Rect { half_x, half_y } => 4.0 * half_x.abs() * half_y.abs(),
            AreaShape::Disk { radius } => PI * radius * radius,
            AreaShape::Sphere { radius } => 4.0 * PI * radius * radius,
        }
    }

    /// The rectangle's corners, counter-clockwise seen from the side it emits to.
    pub fn rect_corners(&self) -> Option<[DVec3; 4]> {
        let AreaShape::Rect { half_x, half_y } = self.shape else { return None };
        let (t, b) = (self.tangent, self.normal.cross(self.tangent));
        let at = |sx: f64, sy: f64| self.center + t * (sx * half_x) + b * (sy * half_y);
        Some([at(-1.0, -1.0), at(1.0, -1.0), at(1.0, 1.0), at(-1.0, 1.0)])
    }
}

/// Lambert's edge formula: E/L of a uniform polygon light at point `p` with unit normal `n`,
/// ½ Σ_edges θ_i (n · (v_i × v_{i+1})/|v_i × v_{i+1}|) with v_i the unit directions to the corners.
/// The polygon is first clipped at the plane through `p` normal to `n`, so the part below the
/// horizon adds nothing; it emits towards the side from which its corners run counter-clockwise,
/// and seen from behind it delivers 0.
pub fn polygon_irradiance(p: DVec3, n: DVec3, corners: &[DVec3]) -> f64 {
    let clipped = clip_to_horizon(p, n, corners);
    if clipped.len() < 3 {
        return 0.0;
    }
    let dirs: Vec<DVec3> = clipped.iter().map(|c| *c - p).filter(|d| d.length() > AREA_CORNER_DIST_MIN).collect();
    let mut sum = 0.0;
    for i in 0..dirs.len() {
        let (a, b) = (dirs[i].normalize(), dirs[(i + 1) % dirs.len()].normalize());
        let cross = a.cross(b);
        let len2 = cross.length_squared();
        if len2 <= EDGE_CROSS_MIN_LEN2 {
            continue;
        }
        let theta = a.dot(b).clamp(-1.0, 1.0).acos();
        sum += theta * n.dot(cross) / len2.sqrt();
    }
    // Counter-clockwise seen from p gives a negative sum with this orientation of the cross
    // products: the emitting side is the one whose sum is negative; the back side delivers 0.
    (-0.5 * sum).max(0.0)
}

/// The part of a polygon on the lit side of the plane through `p` normal to `n`
/// (Sutherland–Hodgman against one plane).
fn clip_to_horizon(p: DVec3, n: DVec3, corners: &[DVec3]) -> Vec<DVec3> {
    let side = |c: DVec3| (c - p).dot(n);
    let mut out = Vec::with_capacity(corners.len() + 1);
    for i in 0..corners.len() {
        let (a, b) = (corners[i], corners[(i + 1) % corners.len()]);
        let (sa, sb) = (side(a), side(b));
        if sa > 0.0 {
            out.push(a);
        }
        if (sa > 0.0) != (sb > 0.0) && sa != sb {
            out.push(a + (b - a) * (sa / (sa - sb)));
        }
    }
    out
}

/// E/L of a uniform sphere light of radius `r` whose centre is at `d` from the point, at angle θ
/// (`cos_theta`) from the point's normal: the spherical cap of half-angle σ = asin(r/d),
/// π sin²σ cos θ while the cap is wholly above the horizon, 0 once it is wholly below, and the
/// closed form of the horizon-clipped cap between. A point inside the sphere sees light all round:
/// π.
pub fn sphere_irradiance(radius: f64, d: f64, cos_theta: f64) -> f64 {
    let r = radius.abs();
    if d <= r {
        return PI;
    }
    let sin2_sigma = (r / d).powi(2);
    let cos_t = cos_theta.clamp(-1.0, 1.0);
    let sin_t = (1.0 - cos_t * cos_t).max(0.0).sqrt();
    if cos_t * cos_t >= sin2_sigma || sin2_sigma <= 0.0 {
        return (PI * sin2_sigma * cos_t).max(0.0);
    }
    // Partly below the horizon (|cos θ| < sin σ, so sin θ > cos σ ≥ 0): x = cot σ, y = −x cot θ.
    let x = (1.0 / sin2_sigma - 1.0).max(0.0).sqrt();
    let y = (-x * cos_t / sin_t).clamp(-1.0, 1.0);
    let s = sin_t * (1.0 - y * y).max(0.0).sqrt();
    let e = (cos_t * y.acos() - x * s) * sin2_sigma + s.atan2(x);
    e.clamp(0.0, PI)
}

/// E/L of `light` at point `p` with unit normal `n` in closed form, where one exists: the
/// rectangle by Lambert's edge formula and the sphere by its cap; `None` for the disk, whose
/// tilted, clipped form has no closed form here (the quadrature is its reference).
pub fn area_irradiance_exact(light: &AreaLight, p: DVec3, n: DVec3) -> Option<f64> {
    match light.shape {
        AreaShape::Rect { .. } => light.rect_corners().map(|c| polygon_irradiance(p, n, &c)),
        AreaShape::Sphere { radius } => {
            let to = light.center - p;
            let d = to.length();
            let cos_theta = if d > 0.0 { n.dot(to) / d } else { 1.0 };
            Some(sphere_irradiance(radius, d, cos_theta))
        }
        AreaShape::Disk { .. } => None,
    }
}

/// One sample of the quadrature: a point on the light, its outward unit normal, and its area.
type Sample = (DVec3, DVec3, f64);

/// The light's surface cut into `k`×`k` cells of equal area (rectangle: a grid; disk: rings equal
/// in r² times sectors; sphere: the cap seen from `p`, rings equal in cos times sectors), each
/// sampled at its centre.
fn samples(light: &AreaLight, p: DVec3, k: usize) -> Vec<Sample> {
    let k = k.max(1);
    let t = light.tangent;
    let b = light.normal.cross(t);
    let mid = |i: usize| (i as f64 + 0.5) / k as f64;
    let mut out = Vec::with_capacity(k * k);
    match light.shape {
        AreaShape::Rect { half_x, half_y } => {
            let da = 4.0 * half_x.abs() * half_y.abs() / (k * k) as f64;
            for i in 0..k {
                for j in 0..k {
                    let at = light.center + t * ((2.0 * mid(i) - 1.0) * half_x) + b * ((2.0 * mid(j) - 1.0) * half_y);
                    out.push((at, light.normal, da));
                }
            }
        }
        AreaShape::Disk { radius } => {
            let da = PI * radius * radius / (k * k) as f64;
            for i in 0..k {
                let rho = radius * mid(i).sqrt();
                for j in 0..k {
                    let phi = TAU * mid(j);
                    out.push((light.center + (t * phi.cos() + b * phi.sin()) * rho, light.normal, da));
                }
            }
        }
        AreaShape::Sphere { radius } => {
            // Only the cap facing p can be seen from it: cos ψ ≥ r/d about the axis towards p.
            let to_p = p - light.center;
            let d = to_p.length();
            if d <= radius.abs() {
                return out;
            }
            let axis = to_p / d;
            let u = if axis.x.abs() < 0.9 { DVec3::X } else { DVec3::Y }.cross(axis).normalize();
            let w = axis.cross(u);
            let c0 = radius.abs() / d;
            let da = TAU * radius * radius * (1.0 - c0) / (k * k) as f64;
            for i in 0..k {
                let cos_psi = c0 + (1.0 - c0) * mid(i);
                let sin_psi = (1.0 - cos_psi * cos_psi).max(0.0).sqrt();
                for j in 0..k {
                    let phi = TAU * mid(j);
                    let normal = axis * cos_psi + (u * phi.cos() + w * phi.sin()) * sin_psi;
                    out.push((light.center + normal * radius.abs(), normal, da));
                }
            }
        }
    }
    out
}

/// The reference: E/L = Σ cos θ_p⁺ cos θ_l⁺ / r² ΔA · V over `k`×`k` equal-area cells of the
/// light, where `visible(p, x)` says whether the segment from `p` to the light point `x` is
/// clear (binary visibility: an occluder blocks or it does not).
pub fn area_irradiance_quadrature(
    light: &AreaLight,
    p: DVec3,
    n: DVec3,
    k: usize,
    visible: &dyn Fn(DVec3, DVec3) -> bool,
) -> f64 {
    seen_cells(light, p, k, visible).map(|(l, weight)| weight * n.dot(l).max(0.0)).sum()
}

/// The light's cells that `p` sees: for each, the unit direction `l` to it and its weight
/// cos θ_l ΔA / r² (what a point light's I/d² becomes), front faces only, visible only.
fn seen_cells<'a>(
    light: &AreaLight,
    p: DVec3,
    k: usize,
    visible: &'a dyn Fn(DVec3, DVec3) -> bool,
) -> impl Iterator<Item = (DVec3, f64)> + 'a {
    samples(light, p, k).into_iter().filter_map(move |(x, nx, da)| {
        let to = x - p;
        let r2 = to.length_squared();
        if r2 <= AREA_CORNER_DIST_MIN * AREA_CORNER_DIST_MIN {
            return None;
        }
        let l = to / r2.sqrt();
        let cos_l = -nx.dot(l);
        (cos_l > 0.0 && visible(p, x)).then_some((l, cos_l * da / r2))
    })
}

/// The reference with its own error: the quadrature at `k` and at 2`k` cells a side, returning
/// the finer value and the difference of the two (the midpoint rule's error falls at least as
/// fast as 1/k, so the difference bounds the finer value's error from above for a smooth
/// integrand; across a shadow edge it is the estimate the study reports).
pub fn area_irradiance_reference(
    light: &AreaLight,
    p: DVec3,
    n: DVec3,
    k: usize,
    visible: &dyn Fn(DVec3, DVec3) -> bool,
) -> (f64, f64) {
    let coarse = area_irradiance_quadrature(light, p, n, k, visible);
    let fine = area_irradiance_quadrature(light, p, n, 2 * k.max(1), visible);
    (fine, (fine - coarse).abs())
}

/// The chapter's "replace the area source by point sources": the light's `k`×`k` equal-area
/// cells as point lights at their centres, each (position, outward unit normal, area); a cell
/// emits like a Lambertian point, intensity `L·ΔA·cos θ_l` towards `p`. Summed with binary
/// visibility they are the quadrature above; `k = 1` is one point at the centre.
pub fn point_sources(light: &AreaLight, p: DVec3, k: usize) -> Vec<(DVec3, DVec3, f64)> {
    samples(light, p, k)
}

/// What the light adds to the Cook–Torrance specular term at `p` (unit normal `n`, unit view
/// vector `v`), per channel and per unit radiance: Σ cos θ_l⁺ ΔA / r² · S(l) over `k`×`k`
/// cells, where S is `specular_cook_torrance` (π ρ_s (N·L), the scale a point light of intensity
/// I multiplies by I/d²). The reference at large `k`, the chapter's point sources at small `k`.
#[allow(clippy::too_many_arguments)]
pub fn specular_area_quadrature(
    light: &AreaLight,
    p: DVec3,
    n: DVec3,
    v: DVec3,
    m: f64,
    v_index: [f64; 3],
    k: usize,
    visible: &dyn Fn(DVec3, DVec3) -> bool,
) -> [f64; 3] {
    let mut sum = [0.0; 3];
    for (l, weight) in seen_cells(light, p, k, visible) {
        let s = super::brdf::specular_cook_torrance(n, v, l, m, v_index);
        for (c, sc) in sum.iter_mut().zip(s) {
            *c += sc * weight;
        }
    }
    sum
}

/// The representative-point specular of a rectangle or sphere light, per unit radiance: the
/// light's point nearest the mirror direction R = 2(N·V)N − V (the sphere: nearest to the ray;
/// the rectangle: where the ray meets its plane, clamped to it), lit as a point light carrying the
/// whole light (sphere: L·πr² at the centre's distance; rectangle: L·A·cos θ_l at that point's),
/// with the lobe's peak scaled by m²/m'², m'² = m² + σ²/8 for a light of angular radius
/// σ = ρ/d (ρ its equivalent radius): the reflected lobe spreads like a Gaussian of variance about
/// m² per axis, a uniform disc of angular radius σ adds σ²/4·½, and the peak of the widened lobe
/// falls as the variance grows, the total kept. `None` for the disk. docs/area-lights.md
/// measures it against `specular_area_quadrature`.
pub fn specular_representative_point(
    light: &AreaLight,
    p: DVec3,
    n: DVec3,
    v: DVec3,
    m: f64,
    v_index: [f64; 3],
) -> Option<[f64; 3]> {
    let r_dir = (2.0 * n.dot(v) * n - v).normalize_or_zero();
    let to_c = light.center - p;
    let d = to_c.length().max(AREA_CORNER_DIST_MIN);
    let (point, intensity, rho) = match light.shape {
        AreaShape::Sphere { radius } => {
            let along = to_c.dot(r_dir) * r_dir - to_c;
            let len = along.length();
            let reach = if len > 0.0 { (radius.abs() / len).min(1.0) } else { 0.0 };
            (p + to_c + along * reach, PI * radius * radius / (d * d), radius.abs())
        }
        AreaShape::Rect { half_x, half_y } => {
            let b = light.normal.cross(light.tangent);
            let denom = r_dir.dot(light.normal);
            // The ray meets the plane ahead of p, or else its farthest reach along the plane.
            let t = if denom < -1e-9 { (light.center - p).dot(light.normal) / denom } else { 1e6 * d };
            let hit = p + r_dir * t.max(0.0) - light.center;
            let x = hit.dot(light.tangent).clamp(-half_x.abs(), half_x.abs());
            let y = hit.dot(b).clamp(-half_y.abs(), half_y.abs());
            let q = light.center + light.tangent * x + b * y;
            let to_q = q - p;
            let r2 = to_q.length_squared().max(AREA_CORNER_DIST_MIN * AREA_CORNER_DIST_MIN);
            let cos_l = (-light.normal.dot(to_q) / r2.sqrt()).max(0.0);
            (q, light.area() * cos_l / r2, (light.area() / PI).sqrt())
        }
        AreaShape::Disk { .. } => return None,
    };
    let l = (point - p).normalize_or_zero();
    let m = m.max(crate::guards::M_MIN);
    let sigma = rho / d;
    let norm = m * m / (m * m + sigma * sigma / 8.0);
    Some(super::brdf::specular_cook_torrance(n, v, l, m, v_index).map(|s| s * intensity * norm))
}

/// The penumbra's width on a receiver at distance `d_receiver` from a light of size `w_light`
/// whose blocker is at `d_blocker` (both measured from the light, in linear depth): similar
/// triangles, w = w_light·(d_r − d_b)/d_b; 0 where the receiver is not behind the blocker.
pub fn penumbra_width(w_light: f64, d_receiver: f64, d_blocker: f64) -> f64 {
    let d_b = d_blocker.max(BLOCKER_DIST_MIN);
    (w_light.abs() * (d_receiver - d_b) / d_b).max(0.0)
}

#[cfg(test)]
#[path = "area_tests.rs"]
mod tests;
