//! Area lights in f64 (docs/area-lights.md), the twin of `shaders/area_lights.wgsl`: what a
//! rectangle, disk or sphere light of uniform radiance L delivers to a point, as the irradiance
//! factor E/L = ∫ cos θ_p⁺ cos θ_l⁺ / r² dA. Exact where a closed form exists (Lambert's edge
//! formula for a polygon, the spherical cap for a sphere, both clipped at the point's horizon;
//! the disk as its equal-area polygon), the representative-point specular, and the reference
//! integral over the light's area by deterministic midpoint quadrature with binary visibility,
//! which also reports its own error. The penumbra width the shadow filters aim for is here too.

use crate::guards::{AREA_POINT_LIMIT_ANGLE, EDGE_CROSS_MIN_LEN2, LIGHT_DIST_MIN, M_MIN};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Sides of the regular polygon a disk light is drawn as (`AREA_DISK_SIDES` in WGSL): of the
/// disk's area, so its E/L is the disk's within 0.3 % (`area_tests`), at the cost of 16 edges.
pub const AREA_DISK_SIDES: usize = 16;

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

    /// The area a point far away sees face-on: a flat light's area, a sphere's disc πr².
    pub fn emitting_area(&self) -> f64 {
        match self.shape {
            AreaShape::Sphere { radius } => PI * radius * radius,
            _ => self.area(),
        }
    }

    /// The radius of the disc the light's farthest point lies on: its half-diagonal, its radius.
    pub fn area_radius(&self) -> f64 {
        match self.shape {
            AreaShape::Rect { half_x, half_y } => half_x.hypot(half_y),
            AreaShape::Disk { radius } | AreaShape::Sphere { radius } => radius.abs(),
        }
    }
}

/// One edge's term of Lambert's edge formula: θ · n·(a × b)/|a × b| for unit directions `a`, `b`
/// to its corners, θ their angle taken as atan2(|a × b|, a·b), which keeps its precision for
/// small angles in f32 (acos of a dot near 1 does not); 0 for an edge seen end-on
/// (`EDGE_CROSS_MIN_LEN2`).
pub fn edge_term(a: DVec3, b: DVec3, n: DVec3) -> f64 {
    let cross = a.cross(b);
    let len2 = cross.length_squared();
    if len2 <= EDGE_CROSS_MIN_LEN2 {
        return 0.0;
    }
    let len = len2.sqrt();
    len.atan2(a.dot(b)) * n.dot(cross) / len
}

/// The circumradius of the regular polygon of [`AREA_DISK_SIDES`] sides whose area is the unit
/// disk's: π = ½·n·R²·sin(2π/n).
pub fn disk_polygon_scale() -> f64 {
    let n = AREA_DISK_SIDES as f64;
    (TAU / (n * (TAU / n).sin())).sqrt()
}

/// Lambert's edge formula: E/L of a uniform polygon light at point `p` with unit normal `n`,
/// −½ Σ_edges [`edge_term`] of the unit directions to its corners. The polygon is first clipped
/// at the plane through `p` normal to `n`, so the part below the horizon adds nothing; it emits
/// towards the side from which its corners run counter-clockwise, and seen from behind it
/// delivers 0. A corner touching `p` (closer than `LIGHT_DIST_MIN`) has no direction and is
/// skipped.
pub fn polygon_irradiance(p: DVec3, n: DVec3, corners: &[DVec3]) -> f64 {
    (-0.5 * polygon_edge_sum(p, n, corners).0).max(0.0)
}

/// Lambert's edge formula over a flat light's corners carried by `xf` from `p` (the identity for
/// the light itself, [`super::ltc`]'s `M⁻¹` for its LTC), clipped at the plane normal to `n`
/// through the origin; 0 seen from behind (WGSL `polygon_walk`).
pub fn polygon_walk(light: &AreaLight, p: DVec3, n: DVec3, xf: glam::DMat3) -> f64 {
    let corners: Vec<DVec3> = area_corners(light).into_iter().map(|c| xf * (c - p)).collect();
    polygon_irradiance(DVec3::ZERO, n, &corners)
}

/// The sum of [`edge_term`]s over the polygon clipped at `p`'s horizon, and the sum of their
/// magnitudes: where the horizon leaves a sliver the terms cancel, and an f32 sum keeps only
/// its precision times the second over the first.
pub fn polygon_edge_sum(p: DVec3, n: DVec3, corners: &[DVec3]) -> (f64, f64) {
    let mut w = EdgeWalk::default();
    for (k, &c) in corners.iter().enumerate() {
        let (a, b) = (c - p, corners[(k + 1) % corners.len()] - p);
        let (sa, sb) = (a.dot(n), b.dot(n));
        if sa > 0.0 {
            w = polygon_step(w, a, n);
        }
        if (sa > 0.0) != (sb > 0.0) && sa != sb {
            w = polygon_step(w, a + (b - a) * (sa / (sa - sb)), n);
        }
    }
    if w.clipped < 3 {
        return (0.0, 0.0);
    }
    let t = edge_term(w.prev, w.first, n);
    // Counter-clockwise seen from p gives a negative sum with this orientation of the cross
    // products: the emitting side is the one whose sum is negative; the back side delivers 0.
    (w.sum + t, w.magnitude + t.abs())
}

/// A walk over a polygon's corners clipped at a horizon, in order, without storing them (WGSL
/// `EdgeWalk`): the first and the previous kept unit direction, how many corners were kept and
/// clipped, the edge terms' sum and (here only) the sum of their magnitudes.
#[derive(Clone, Copy, Debug, Default)]
pub struct EdgeWalk {
    pub first: DVec3,
    pub prev: DVec3,
    pub kept: u32,
    pub clipped: u32,
    pub sum: f64,
    pub magnitude: f64,
}

/// The walk's next corner of the clipped polygon, `v` from the shaded point: counted, and unless
/// it touches the point (`LIGHT_DIST_MIN`, no direction) joined to the previous by its edge term.
pub fn polygon_step(mut w: EdgeWalk, v: DVec3, n: DVec3) -> EdgeWalk {
    w.clipped += 1;
    if v.length() > LIGHT_DIST_MIN {
        let u = v.normalize();
        if w.kept == 0 {
            w.first = u;
        } else {
            let t = edge_term(w.prev, u, n);
            w.sum += t;
            w.magnitude += t.abs();
        }
        w.prev = u;
        w.kept += 1;
    }
    w
}

/// How far [`area_form`] moves when each term of its sum moves by its own size (times 1):
/// `d²·Σ|terms|/A_emit`, the edge terms' ½Σ|t| or the cap's two brackets; the stability sweep
/// scales it by its input perturbation to tell a sliver the horizon leaves, where f32's sum
/// cancels, from a well-conditioned form. 0 under the point limit.
pub fn area_form_rounding(light: &AreaLight, p: DVec3, n: DVec3) -> f64 {
    let to = light.center - p;
    let d = to.length();
    if d <= LIGHT_DIST_MIN || light.area_radius() < AREA_POINT_LIMIT_ANGLE * d {
        return 0.0;
    }
    let magnitude = match light.shape {
        AreaShape::Sphere { radius } => sphere_cap_terms(radius, d, n.dot(to) / d).1,
        _ => 0.5 * polygon_edge_sum(p, n, &area_corners(light)).1,
    };
    d * d * magnitude / light.emitting_area()
}

/// E/L of a uniform sphere light of radius `r` whose centre is at `d` from the point, at angle θ
/// (`cos_theta`) from the point's normal: the spherical cap of half-angle σ = asin(r/d),
/// π sin²σ cos θ while the cap is wholly above the horizon, 0 once it is wholly below, and the
/// closed form of the horizon-clipped cap between. A point inside the sphere sees light all round:
/// π.
pub fn sphere_irradiance(radius: f64, d: f64, cos_theta: f64) -> f64 {
    sphere_cap_terms(radius, d, cos_theta).0
}

/// [`sphere_irradiance`] and the magnitude of the terms it sums: where the horizon leaves a
/// sliver of the cap they cancel, and an f32 sum keeps only its precision times the second over
/// the first.
pub fn sphere_cap_terms(radius: f64, d: f64, cos_theta: f64) -> (f64, f64) {
    let r = radius.abs();
    let sin2_sigma = (r / d).powi(2);
    // On or inside the sphere (also where r/d rounds to 1) the light is all round: π.
    if d <= r || sin2_sigma >= 1.0 {
        return (PI, PI);
    }
    let cos_t = cos_theta.clamp(-1.0, 1.0);
    let sin_t = (1.0 - cos_t * cos_t).max(0.0).sqrt();
    if cos_t * cos_t >= sin2_sigma || sin2_sigma <= 0.0 {
        let e = (PI * sin2_sigma * cos_t).max(0.0);
        return (e, e);
    }
    // Partly below the horizon (|cos θ| < sin σ, so sin θ > cos σ ≥ 0). The textbook form
    // (cos θ·acos y − cot σ·s)·sin²σ + atan(s/cot σ), y = −cot σ·cot θ, cancels from terms of
    // size φ = acos y down to φ⁵ near the horizon's tangency; rewritten as
    // sin²σ·sin θ·tan σ·(sin φ − φ cos φ) + (atan u − u), u = √δ/cos σ, δ = sin²σ − cos²θ, with
    // both brackets as series for small arguments, it keeps more of f32's precision.
    let delta = (sin2_sigma - cos_t * cos_t).max(0.0);
    let sin_sigma = sin2_sigma.sqrt();
    let cos_sigma = (1.0 - sin2_sigma).max(0.0).sqrt();
    let sin_phi = (delta.sqrt() / (sin_sigma * sin_t)).min(1.0);
    let cos_phi = (-cos_sigma * cos_t / (sin_sigma * sin_t)).clamp(-1.0, 1.0);
    let phi = sin_phi.atan2(cos_phi);
    let u = delta.sqrt() / cos_sigma;
    let k = sin2_sigma * sin_t * (sin_sigma / cos_sigma);
    let (a, b) = (k * sin_minus_phi_cos(phi, sin_phi, cos_phi), atan_minus_u(u));
    // Each bracket's own terms: its series' leading term, or the two it subtracts.
    let magnitude = if phi.abs() < AREA_SERIES_MAX { a.abs() } else { k * (sin_phi + (phi * cos_phi).abs()) }
        + if u.abs() < AREA_SERIES_MAX { b.abs() } else { u.atan() + u };
    ((a + b).clamp(0.0, PI), magnitude)
}

/// Below this argument the series of `sin φ − φ cos φ` and `atan u − u` replace their direct
/// forms (`AREA_SERIES_MAX` in WGSL): there the direct forms cancel to 1/x² of their terms, and
/// the series' first omitted term is under 4e-6 of the sum.
pub const AREA_SERIES_MAX: f64 = 0.25;

/// sin φ − φ cos φ, from φ³/3 − φ⁵/30 + φ⁷/840 − φ⁹/45360 below `AREA_SERIES_MAX`.
pub fn sin_minus_phi_cos(phi: f64, sin_phi: f64, cos_phi: f64) -> f64 {
    if phi.abs() < AREA_SERIES_MAX {
        let p2 = phi * phi;
        return phi * p2 * (1.0 / 3.0 - p2 * (1.0 / 30.0 - p2 * (1.0 / 840.0 - p2 / 45360.0)));
    }
    sin_phi - phi * cos_phi
}

/// atan u − u, from −u³/3 + u⁵/5 − u⁷/7 + u⁹/9 below `AREA_SERIES_MAX`.
pub fn atan_minus_u(u: f64) -> f64 {
    if u.abs() < AREA_SERIES_MAX {
        let u2 = u * u;
        return u * u2 * (-1.0 / 3.0 + u2 * (1.0 / 5.0 - u2 * (1.0 / 7.0 - u2 / 9.0)));
    }
    u.atan() - u
}

/// E/L of `light` at point `p` with unit normal `n` in closed form, where one exists: the
/// rectangle by Lambert's edge formula and the sphere by its cap; `None` for the disk, whose
/// tilted, clipped form has no closed form here (the quadrature is its reference).
pub fn area_irradiance_exact(light: &AreaLight, p: DVec3, n: DVec3) -> Option<f64> {
    match light.shape {
        AreaShape::Disk { .. } => None,
        _ => Some(area_irradiance(light, p, n)),
    }
}

/// E/L as the renderer computes it: [`area_irradiance_exact`], and the disk as its equal-area
/// regular polygon of [`AREA_DISK_SIDES`] sides ([`area_corner`]).
pub fn area_irradiance(light: &AreaLight, p: DVec3, n: DVec3) -> f64 {
    match light.shape {
        AreaShape::Rect { .. } | AreaShape::Disk { .. } => polygon_irradiance(p, n, &area_corners(light)),
        AreaShape::Sphere { radius } => {
            let to = light.center - p;
            let d = to.length();
            let cos_theta = if d > 0.0 { n.dot(to) / d } else { 1.0 };
            sphere_irradiance(radius, d, cos_theta)
        }
    }
}

/// A flat light's corners, counter-clockwise seen from the side it emits to: the rectangle's
/// four, the disk's equal-area polygon; none for a sphere.
pub fn area_corners(light: &AreaLight) -> Vec<DVec3> {
    (0..area_corner_count(light)).map(|i| area_corner(light, i)).collect()
}

/// How many corners a flat light has: the rectangle's four, the disk's polygon's
/// [`AREA_DISK_SIDES`]; none for a sphere.
pub fn area_corner_count(light: &AreaLight) -> usize {
    match light.shape {
        AreaShape::Rect { .. } => 4,
        AreaShape::Disk { .. } => AREA_DISK_SIDES,
        AreaShape::Sphere { .. } => 0,
    }
}

/// Corner `i` of a flat light, counter-clockwise seen from the side it emits to: the
/// rectangle's, or the disk's regular polygon of [`AREA_DISK_SIDES`] sides with the disk's area
/// (WGSL `area_corner`, which computes it the same way rather than indexing a list).
pub fn area_corner(light: &AreaLight, i: usize) -> DVec3 {
    let (t, b) = (light.tangent, light.normal.cross(light.tangent));
    match light.shape {
        AreaShape::Rect { half_x, half_y } => {
            let sx = if i % 4 == 1 || i % 4 == 2 { 1.0 } else { -1.0 };
            let sy = if i % 4 >= 2 { 1.0 } else { -1.0 };
            light.center + t * (sx * half_x) + b * (sy * half_y)
        }
        AreaShape::Disk { radius } => {
            let phi = TAU * (i % AREA_DISK_SIDES) as f64 / AREA_DISK_SIDES as f64;
            light.center + (t * phi.cos() + b * phi.sin()) * (radius.abs() * disk_polygon_scale())
        }
        AreaShape::Sphere { .. } => light.center,
    }
}

/// The light's diffuse factor at `p` relative to its centre's point light (what `N·L` is for a
/// point light; `LightSample.form` in WGSL): `d²·(E/L)/A_emit`, with `d` the distance to the
/// centre and `A_emit` the area a point far away sees face-on (a sphere's disc πr², a flat light's
/// area). Times the point light's `I·f(d)` it is the exact area integral, scaled to the point
/// light at the centre; it tends to `cos θ_p` (sphere) or `cos θ_p·cos θ_l` (rectangle, disk: a
/// Lambertian point) as the light shrinks. Under `AREA_POINT_LIMIT_ANGLE` it is that limit.
pub fn area_form(light: &AreaLight, p: DVec3, n: DVec3) -> f64 {
    let to = light.center - p;
    let d = to.length();
    if d <= LIGHT_DIST_MIN {
        return 0.0;
    }
    let l = to / d;
    if light.area_radius() < AREA_POINT_LIMIT_ANGLE * d {
        let cos_l = if matches!(light.shape, AreaShape::Sphere { .. }) { 1.0 } else { (-light.normal.dot(l)).max(0.0) };
        return n.dot(l).max(0.0) * cos_l;
    }
    d * d * area_irradiance(light, p, n) / light.emitting_area()
}

/// One sample of the quadrature: a point on the light, its outward unit normal, and its area.
type Sample = (DVec3, DVec3, f64);

/// The light's surface cut into `k`×`k` cells of equal area (rectangle: a grid; disk: rings equal
/// in r² times sectors; sphere: the cap seen from `p`, rings equal in cos times sectors), each
/// sampled at its centre. An iterator, so the reference's walks over up to 256² cells allocate
/// nothing.
fn samples(light: &AreaLight, p: DVec3, k: usize) -> impl Iterator<Item = Sample> + use<> {
    let (light, k) = (*light, k.max(1));
    let mid = move |i: usize| (i as f64 + 0.5) / k as f64;
    let cells = (0..k).flat_map(move |i| (0..k).map(move |j| (i, j)));
    cells
        .filter_map(move |(i, j)| point_on(&light, p, mid(i), mid(j)))
        .map(move |(x, normal, area)| (x, normal, area / (k * k) as f64))
}

/// The point of the light's surface at parameters `(s, t)` in [0, 1)², its unit normal, and the
/// area the parameters cover (uniform `(s, t)` is uniform over it): the rectangle's grid, the
/// disk's rings equal in r² times sectors, and the cap of a sphere that `p` sees (rings equal
/// in cos times sectors); `None` for a point inside a sphere light.
fn point_on(light: &AreaLight, p: DVec3, s: f64, t: f64) -> Option<Sample> {
    let tangent = light.tangent;
    let b = light.normal.cross(tangent);
    match light.shape {
        AreaShape::Rect { half_x, half_y } => {
            let at = light.center + tangent * ((2.0 * s - 1.0) * half_x) + b * ((2.0 * t - 1.0) * half_y);
            Some((at, light.normal, 4.0 * half_x.abs() * half_y.abs()))
        }
        AreaShape::Disk { radius } => {
            let (rho, phi) = (radius * s.sqrt(), TAU * t);
            Some((light.center + (tangent * phi.cos() + b * phi.sin()) * rho, light.normal, PI * radius * radius))
        }
        AreaShape::Sphere { radius } => {
            // Only the cap facing p can be seen from it: cos ψ ≥ r/d about the axis towards p.
            let to_p = p - light.center;
            let d = to_p.length();
            if d <= radius.abs() {
                return None;
            }
            let axis = to_p / d;
            let u = if axis.x.abs() < 0.9 { DVec3::X } else { DVec3::Y }.cross(axis).normalize();
            let w = axis.cross(u);
            let c0 = radius.abs() / d;
            let cos_psi = c0 + (1.0 - c0) * s;
            let sin_psi = (1.0 - cos_psi * cos_psi).max(0.0).sqrt();
            let phi = TAU * t;
            let normal = axis * cos_psi + (u * phi.cos() + w * phi.sin()) * sin_psi;
            Some((light.center + normal * radius.abs(), normal, TAU * radius * radius * (1.0 - c0)))
        }
    }
}

/// One point of the light drawn uniformly over the part of it `p` can see, at parameters
/// `(s, t)` uniform in [0, 1)²: its position, the unit direction `l` to it and its weight
/// `cos θ_l·A/r²`, whose mean over `(s, t)` is the light's E/L times the share `p` faces;
/// `None` where `p` faces its back, touches it or is inside it.
pub(crate) fn random_cell(light: &AreaLight, p: DVec3, s: f64, t: f64) -> Option<(DVec3, DVec3, f64)> {
    let (x, nx, area) = point_on(light, p, s, t)?;
    front_cell(p, x, nx, area)
}

/// A cell at `x` (unit normal `nx`, area `da`) as `p` sees it: the direction `l` to it and its
/// weight `cos θ_l·da/r²`; `None` behind it or touching it.
fn front_cell(p: DVec3, x: DVec3, nx: DVec3, da: f64) -> Option<(DVec3, DVec3, f64)> {
    let to = x - p;
    let r2 = to.length_squared();
    if r2 <= LIGHT_DIST_MIN * LIGHT_DIST_MIN {
        return None;
    }
    let l = to / r2.sqrt();
    let cos_l = -nx.dot(l);
    (cos_l > 0.0).then_some((x, l, cos_l * da / r2))
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
pub(crate) fn seen_cells<'a>(
    light: &AreaLight,
    p: DVec3,
    k: usize,
    visible: &'a dyn Fn(DVec3, DVec3) -> bool,
) -> impl Iterator<Item = (DVec3, f64)> + 'a {
    front_cells(light, p, k).filter(move |c| visible(p, c.0)).map(|(_, l, weight)| (l, weight))
}

/// The light's cells whose front `p` faces: each cell's point, the unit direction `l` to it and
/// its weight cos θ_l ΔA / r², visible or not.
pub(crate) fn front_cells(light: &AreaLight, p: DVec3, k: usize) -> impl Iterator<Item = (DVec3, DVec3, f64)> + use<> {
    samples(light, p, k).filter_map(move |(x, nx, da)| front_cell(p, x, nx, da))
}

/// The share of the light's E/L over `k`×`k` cells that reaches `p`, the cells `visible` hides
/// taken out, in one walk over the cells; 1 where the light delivers nothing. The reference's
/// soft shadow.
pub fn area_visible_share(
    light: &AreaLight,
    p: DVec3,
    n: DVec3,
    k: usize,
    visible: &dyn Fn(DVec3, DVec3) -> bool,
) -> f64 {
    let (mut clear, mut seen) = (0.0, 0.0);
    for (x, l, weight) in front_cells(light, p, k) {
        let e = weight * n.dot(l).max(0.0);
        if e > 0.0 {
            clear += e;
            if visible(p, x) {
                seen += e;
            }
        }
    }
    if clear > 0.0 { seen / clear } else { 1.0 }
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

/// The representative point of `light` for the specular term at `p` (unit normal `n`, unit view
/// vector `v`, roughness `m`): the unit direction `l` to the light's point nearest the mirror
/// direction R = 2(N·V)N − V (the sphere: nearest to the ray; a rectangle or disk: where the ray
/// meets its plane, clamped to the shape, or the shape's edge in the ray's direction when the ray
/// leaves the plane), and the scale of the centre's point light's specular there
/// (`LightSample.spec_scale`): the flat light's `cos θ_l·d²/r²` at that point (1 for a sphere),
/// times m²/m'², m'² = m² + σ²/8 for a light of angular radius σ = ρ/d (ρ the radius of the disc of
/// its area): the reflected lobe spreads like a Gaussian of variance about m² per axis, a uniform
/// disc of angular radius σ adds σ²/8, and the widened lobe's peak falls as the variance grows.
/// Under `AREA_POINT_LIMIT_ANGLE` it is the centre with its point limit's scale.
pub fn area_specular_point(light: &AreaLight, p: DVec3, n: DVec3, v: DVec3, m: f64) -> (DVec3, f64) {
    let to_c = light.center - p;
    let d = to_c.length();
    if d <= LIGHT_DIST_MIN {
        return (n, 0.0);
    }
    let flat = !matches!(light.shape, AreaShape::Sphere { .. });
    let cos_at = |q: DVec3| if flat { (-light.normal.dot((q - p).normalize_or_zero())).max(0.0) } else { 1.0 };
    if light.area_radius() < AREA_POINT_LIMIT_ANGLE * d {
        return (to_c / d, cos_at(light.center));
    }
    let r_dir = (2.0 * n.dot(v) * n - v).normalize_or(n);
    let (q, scale) = match light.shape {
        AreaShape::Sphere { radius } => {
            let along = to_c.dot(r_dir) * r_dir - to_c;
            let len = along.length();
            let reach = if len > 0.0 { (radius.abs() / len).min(1.0) } else { 0.0 };
            (light.center + along * reach, 1.0)
        }
        AreaShape::Rect { .. } | AreaShape::Disk { .. } => {
            let denom = r_dir.dot(light.normal);
            let local = if denom < 0.0 {
                p + r_dir * (to_c.dot(light.normal) / denom).max(0.0) - light.center
            } else {
                (r_dir - light.normal * denom).normalize_or_zero() * (2.0 * light.area_radius())
            };
            let q = light.center + clamp_to_shape(light, local);
            let r2 = (q - p).length_squared().max(LIGHT_DIST_MIN * LIGHT_DIST_MIN);
            (q, cos_at(q) * d * d / r2)
        }
    };
    let m = m.max(M_MIN);
    let sigma = (light.emitting_area() / PI).sqrt() / d;
    let norm = m * m / (m * m + sigma * sigma / 8.0);
    ((q - p).normalize_or(to_c / d), scale * norm)
}

/// A vector in a flat light's plane (from its centre) moved onto the shape: each axis clamped to
/// the rectangle's half-size, or the length to the disk's radius.
pub fn clamp_to_shape(light: &AreaLight, local: DVec3) -> DVec3 {
    let (t, b) = (light.tangent, light.normal.cross(light.tangent));
    let (x, y) = (local.dot(t), local.dot(b));
    match light.shape {
        AreaShape::Rect { half_x, half_y } => {
            t * x.clamp(-half_x.abs(), half_x.abs()) + b * y.clamp(-half_y.abs(), half_y.abs())
        }
        AreaShape::Disk { radius } => {
            let len = x.hypot(y);
            let k = if len > radius.abs() { radius.abs() / len } else { 1.0 };
            (t * x + b * y) * k
        }
        AreaShape::Sphere { .. } => local,
    }
}

#[cfg(test)]
#[path = "area_tests.rs"]
mod tests;

#[cfg(test)]
#[path = "area_sample_tests.rs"]
mod sample_tests;
