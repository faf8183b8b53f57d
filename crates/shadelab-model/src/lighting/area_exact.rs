//! The reference's exact term of an area light under the chapter's Phong illumination model
//! (docs/area-lights.md): the diffuse and the specular integrated over the light's area, in place
//! of the representative point the GPU draws the specular at. The integral is the midpoint rule
//! over the light's equal-area cells, refined until two refinements agree, and each part is
//! shadowed by its own share of the light that reaches the point.

use super::area::{AreaLight, area_irradiance_exact, area_specular_point, front_cells, random_cell, seen_cells};
use super::brdf::{diffuse_weight, diffuse_weighted, light_specular, specular_cook_torrance};
use super::shading::AreaAt;
use crate::guards::LIGHT_DIST_MIN;
use glam::DVec3;

/// Cells a side the integral starts from: a 16×16 grid already resolves a lobe wider than the
/// light's cells, and it is the shadow's grid (`REFERENCE_AREA_CELLS`).
pub const AREA_EXACT_CELLS_MIN: usize = 16;
/// Cells a side the refinement stops at: 256² cells resolve a lobe of m ≈ 0.01 across a light
/// seen at 90°; a narrower lobe keeps the error estimate the result reports.
pub const AREA_EXACT_CELLS_MAX: usize = 256;
/// Relative change between two refinements at which the integral counts as converged: a tenth
/// of an 8-bit step at white, and the midpoint rule's error falls 4× a refinement.
pub const AREA_EXACT_TOLERANCE: f64 = 1e-3;

/// An area light's exact term at a point: per channel, and its estimated error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaTerm {
    /// The light's term, shadowed, and without its shadow.
    pub lit: [f64; 3],
    pub clear: [f64; 3],
    /// |finest − the refinement before| of the unshadowed term, largest channel: the midpoint
    /// rule's error is below it for a smooth integrand.
    pub error: f64,
    /// Cells a side the integral ended at.
    pub cells: usize,
    /// The share of the light's diffuse that reaches the point (1 without shadows).
    pub diffuse_share: f64,
}

/// One walk over `k`×`k` cells, per unit radiance: the diffuse `Σ kd·(N·L)⁺·w` and the specular
/// `Σ S(L)·w` per channel, `w = cos θ_l ΔA/r²`; with `visible(p, x)`, also the share of each part
/// that reaches the point (1 where a part delivers nothing).
struct Sums {
    d: f64,
    s: [f64; 3],
    shares: (f64, f64),
}

fn sums(area: &AreaLight, a: &AreaAt, k: usize, visible: Option<&dyn Fn(DVec3, DVec3) -> bool>) -> Sums {
    let (mut d, mut s, mut d_seen, mut s_seen) = (0.0, [0.0; 3], 0.0, 0.0);
    let specular = has_specular(a);
    for (x, l, w) in front_cells(area, a.p, k) {
        let dd = diffuse_weight(l, a.n, a.v, a.mat, a.specular) * a.n.dot(l).max(0.0) * w;
        let spec = if specular {
            light_specular(l, a.n, a.v, a.mat, a.v_index, a.specular, a.ms_e).map(|x| x * w)
        } else {
            [0.0; 3]
        };
        d += dd;
        for c in 0..3 {
            s[c] += spec[c];
        }
        if let Some(seen) = visible
            && (dd > 0.0 || spec.iter().any(|x| *x > 0.0))
            && seen(a.p, x)
        {
            d_seen += dd;
            s_seen += spec.iter().sum::<f64>();
        }
    }
    let share = |seen: f64, all: f64| if visible.is_none() || all <= 0.0 { 1.0 } else { seen / all };
    Sums { d, s, shares: (share(d_seen, d), share(s_seen, s.iter().sum())) }
}

/// Whether the material's specular adds to the term: with `r_s = 0` it is multiplied away, so
/// the walks skip it (and a diffuse with a closed form needs no refinement at all).
fn has_specular(a: &AreaAt) -> bool {
    a.mat.r_s != 0.0
}

/// The exact term of `a.light` at `a.p`: `I·f(d)·(d²/A_emit)·(r_d·C·E_d + r_s·E_s)`, the point
/// light at the centre's intensity spread over the area as the drawn form spreads it (`area_form`),
/// with `E_d` the diffuse integral (Lambert's closed form or the sphere's cap where the diffuse is
/// not Fresnel-weighted and the shape has one) and `E_s` the specular's; `visible` shadows each
/// part by its own share. `None` for a light with no area or touching the point.
pub fn area_term_exact(a: &AreaAt, visible: Option<&dyn Fn(DVec3, DVec3) -> bool>) -> Option<AreaTerm> {
    let area = a.light.area_light()?;
    let d2 = (area.center - a.p).length_squared();
    let emitting = area.emitting_area();
    if d2 <= LIGHT_DIST_MIN * LIGHT_DIST_MIN || emitting <= 0.0 || !emitting.is_finite() {
        return None;
    }
    let weighted = diffuse_weighted(a.mat, a.specular);
    let closed = if weighted { None } else { area_irradiance_exact(&area, a.p, a.n) };
    // The shadow's shares come from the first walk, on the shadow's 16² grid.
    let mut k = AREA_EXACT_CELLS_MIN;
    let first = sums(&area, a, k, visible);
    let (share_d, share_s) = first.shares;
    let (mut d, mut s) = (first.d, first.s);
    // A closed-form diffuse is exact: only the specular's walk is refined, and without a
    // specular nothing is.
    let refined = closed.is_none() || has_specular(a);
    let mut error = if refined { f64::INFINITY } else { 0.0 };
    while refined && k < AREA_EXACT_CELLS_MAX {
        let next = sums(&area, a, 2 * k, None);
        let d_change = if closed.is_some() { 0.0 } else { (next.d - d).abs() };
        let change = (0..3).map(|c| (next.s[c] - s[c]).abs()).fold(d_change, f64::max);
        let size = next.s.iter().copied().fold(closed.unwrap_or(next.d), f64::max);
        (d, s, k, error) = (next.d, next.s, 2 * k, change);
        if change <= AREA_EXACT_TOLERANCE * size {
            break;
        }
    }
    let e_d = closed.unwrap_or(d);
    let scale = d2 / emitting;
    let (mat, radiance) = (a.mat, a.radiance);
    let term = |sd: f64, ss: f64| -> [f64; 3] {
        std::array::from_fn(|c| radiance[c] * scale * (mat.r_d * mat.color[c] * e_d * sd + mat.r_s * s[c] * ss))
    };
    let error = error * scale * radiance.iter().copied().fold(0.0, f64::max);
    Some(AreaTerm { lit: term(share_d, share_s), clear: term(1.0, 1.0), error, cells: k, diffuse_share: share_d })
}

/// One random point's estimate of the same term: a point `(s, t)` drawn uniformly over the
/// part of the light the point can see ([`random_cell`]), its integrand times that area, and
/// binary visibility by `visible`. Its mean over `(s, t)` is the light's whole shadowed
/// integral; the path tracer's bounces take it in place of the refined integral, which would
/// cost some 10⁵ evaluations at every vertex. `weight(l, p)` scales the estimate, given the
/// direction to the point and the density per solid angle it was drawn with (`r²/(cos θ_l·A)`):
/// the path tracer's multiple importance weight. `None` as [`area_term_exact`].
pub fn area_term_sampled(
    a: &AreaAt,
    visible: Option<&dyn Fn(DVec3, DVec3) -> bool>,
    (s, t): (f64, f64),
    weight: &dyn Fn(DVec3, f64) -> f64,
) -> Option<AreaTerm> {
    let area = a.light.area_light()?;
    let d2 = (area.center - a.p).length_squared();
    let emitting = area.emitting_area();
    if d2 <= LIGHT_DIST_MIN * LIGHT_DIST_MIN || emitting <= 0.0 || !emitting.is_finite() {
        return None;
    }
    let Some((x, l, w)) = random_cell(&area, a.p, s, t) else {
        let none = [0.0; 3];
        return Some(AreaTerm { lit: none, clear: none, error: 0.0, cells: 1, diffuse_share: 1.0 });
    };
    let dd = diffuse_weight(l, a.n, a.v, a.mat, a.specular) * a.n.dot(l).max(0.0) * w;
    let spec = if has_specular(a) {
        light_specular(l, a.n, a.v, a.mat, a.v_index, a.specular, a.ms_e).map(|x| x * w)
    } else {
        [0.0; 3]
    };
    let (scale, mat, radiance) = (d2 / emitting * weight(l, 1.0 / w), a.mat, a.radiance);
    let clear: [f64; 3] =
        std::array::from_fn(|c| radiance[c] * scale * (mat.r_d * mat.color[c] * dd + mat.r_s * spec[c]));
    let seen = visible.is_none_or(|v| clear == [0.0; 3] || v(a.p, x));
    let lit = if seen { clear } else { [0.0; 3] };
    Some(AreaTerm { lit, clear, error: 0.0, cells: 1, diffuse_share: if seen { 1.0 } else { 0.0 } })
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
        let s = specular_cook_torrance(n, v, l, m, v_index);
        for (c, sc) in sum.iter_mut().zip(s) {
            *c += sc * weight;
        }
    }
    sum
}

/// The representative-point Cook–Torrance specular per unit radiance, for comparison with
/// [`specular_area_quadrature`]: [`area_specular_point`]'s direction and scale times the centre's
/// point light `A_emit/d²` (the unit-radiance light seen from afar). docs/area-lights.md measures
/// it.
pub fn specular_representative_point(
    light: &AreaLight,
    p: DVec3,
    n: DVec3,
    v: DVec3,
    m: f64,
    v_index: [f64; 3],
) -> [f64; 3] {
    let d2 = (light.center - p).length_squared().max(LIGHT_DIST_MIN * LIGHT_DIST_MIN);
    let (l, scale) = area_specular_point(light, p, n, v, m);
    let k = scale * light.emitting_area() / d2;
    specular_cook_torrance(n, v, l, m, v_index).map(|s| s * k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::brdf::light_contribution;
    use crate::lighting::lights::{Light, LightKind, light_sample};
    use crate::params::SpecularModel;
    use crate::scene::Material;

    /// The point p on the plane z = 0, seen from `eye`, under `light`, as `shade_exact` hands it.
    fn at<'a>(
        light: &'a Light,
        s: &'a crate::lighting::lights::LightSample,
        mat: &'a Material,
        v: DVec3,
    ) -> AreaAt<'a> {
        let v_index = mat.mu.map(crate::lighting::microfacet::fresnel_v_from_mu);
        let specular = SpecularModel::CookTorrance;
        AreaAt {
            index: 0,
            light,
            radiance: s.radiance,
            p: DVec3::ZERO,
            n: DVec3::Z,
            v,
            mat,
            v_index,
            ms_e: 1.0,
            specular,
        }
    }

    fn rect_light(size: [f64; 2]) -> Light {
        let c = DVec3::new(0.8, 0.1, 1.5);
        Light::area(LightKind::Rect, c, -c, size, [1.0; 3], 2.0, 0.1)
    }

    /// The specular integral is the quadrature of the chapter's Cook–Torrance term over the
    /// light (converged well below its tolerance), and the diffuse is the closed form as drawn.
    #[test]
    fn the_exact_term_is_the_integral_of_the_whole_model() {
        let light = rect_light([1.2, 0.8]);
        let area = light.area_light().unwrap();
        let v = DVec3::new(-0.5, 0.0, 0.9).normalize();
        let mat = Material { m: 0.2, ..Material::default() };
        let s = light_sample(&light, DVec3::ZERO, DVec3::Z, v, mat.m);
        let a = at(&light, &s, &mat, v);
        let term = area_term_exact(&a, None).unwrap();
        let clear = |_: DVec3, _: DVec3| true;
        let quad = specular_area_quadrature(&area, a.p, a.n, v, mat.m, a.v_index, 512, &clear);
        let d2 = (area.center - a.p).length_squared();
        let scale = d2 / area.emitting_area();
        let diffuse_only =
            light_contribution(&s, a.n, v, &Material { r_s: 0.0, ..mat.clone() }, a.v_index, a.specular, 1.0);
        for c in 0..3 {
            let want = diffuse_only[c] + s.radiance[c] * scale * mat.r_s * quad[c];
            assert!((term.lit[c] - want).abs() < 2e-3 * want, "channel {c}: {} vs {want}", term.lit[c]);
        }
        assert!(term.error < 1e-3 * term.lit[0] && term.cells >= 32, "{term:?}");
        assert_eq!(term.lit, term.clear);
    }

    /// The one-point estimate's mean over a fine grid of `(s, t)` is the refined integral, for
    /// each shape, unshadowed and half shadowed.
    #[test]
    fn the_sampled_term_averages_to_the_integral() {
        let v = DVec3::new(-0.5, 0.0, 0.9).normalize();
        let mat = Material { m: 0.3, ..Material::default() };
        for kind in [LightKind::Rect, LightKind::Disk, LightKind::Sphere] {
            let c = DVec3::new(0.8, 0.1, 1.5);
            let light = Light::area(kind, c, -c, [1.2, 0.8], [1.0; 3], 2.0, 0.1);
            let s = light_sample(&light, DVec3::ZERO, DVec3::Z, v, mat.m);
            let a = at(&light, &s, &mat, v);
            let tangent = light.area_tangent();
            let half = move |_: DVec3, x: DVec3| (x - c).dot(tangent) > 0.0;
            for shadow in [None, Some(&half as &dyn Fn(DVec3, DVec3) -> bool)] {
                let n = 256;
                let mut mean = [0.0; 3];
                for i in 0..n {
                    for j in 0..n {
                        let (u, w) = ((i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / n as f64);
                        let t = area_term_sampled(&a, shadow, (u, w), &|_, _| 1.0).unwrap();
                        for ch in 0..3 {
                            mean[ch] += t.lit[ch] / (n * n) as f64;
                        }
                    }
                }
                // The exact term's own shadow is each part's share of the light on its 16² grid,
                // within a few thousandths of the integral for this half-plane occluder; without
                // one, the two are the same integral (measured within 1e-4).
                let exact = area_term_exact(&a, shadow).unwrap().lit;
                let tolerance = if shadow.is_some() { 3e-3 } else { 2e-4 };
                for ch in 0..3 {
                    assert!(
                        (mean[ch] - exact[ch]).abs() < tolerance * exact[ch],
                        "{kind:?} {}: {mean:?} vs {exact:?}",
                        shadow.is_some()
                    );
                }
            }
        }
    }

    /// A light a thousandth of a metre wide is its centre's point light, as drawn.
    #[test]
    fn a_tiny_light_is_the_drawn_point_light() {
        let light = rect_light([1e-3, 1e-3]);
        let v = DVec3::new(-0.5, 0.0, 0.9).normalize();
        let mat = Material { m: 0.3, ..Material::default() };
        let s = light_sample(&light, DVec3::ZERO, DVec3::Z, v, mat.m);
        let a = at(&light, &s, &mat, v);
        let exact = area_term_exact(&a, None).unwrap().lit;
        let drawn = light_contribution(&s, a.n, v, &mat, a.v_index, a.specular, 1.0);
        for c in 0..3 {
            assert!((exact[c] - drawn[c]).abs() < 1e-4 * drawn[c], "{exact:?} vs {drawn:?}");
        }
    }

    /// Shadows: a point that sees none of the light gets nothing, and half a light blocked takes
    /// about half of each part.
    #[test]
    fn each_part_is_shadowed_by_its_own_share() {
        let light = rect_light([1.2, 0.8]);
        let v = DVec3::new(-0.5, 0.0, 0.9).normalize();
        let mat = Material { m: 0.4, ..Material::default() };
        let s = light_sample(&light, DVec3::ZERO, DVec3::Z, v, mat.m);
        let a = at(&light, &s, &mat, v);
        let none = area_term_exact(&a, Some(&|_, _| false)).unwrap();
        assert_eq!(none.lit, [0.0; 3]);
        assert!(none.clear[0] > 0.0 && none.diffuse_share == 0.0);
        let centre = light.position;
        let tangent = light.area_tangent();
        let half = area_term_exact(&a, Some(&|_, x: DVec3| (x - centre).dot(tangent) > 0.0)).unwrap();
        assert!((half.diffuse_share - 0.5).abs() < 0.2, "{half:?}");
        assert!(half.lit[0] > 0.2 * half.clear[0] && half.lit[0] < 0.8 * half.clear[0], "{half:?}");
    }
}
