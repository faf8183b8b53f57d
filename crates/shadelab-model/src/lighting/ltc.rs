//! The twin of `shaders/ltc.wgsl`: an area light's specular by linearly transformed cosines
//! (docs/area-lights.md). The lobe `D·G/(N·V)` at a point is a clamped cosine carried by a
//! matrix M (fitted per D in `ltc_fit.rs`, held in [`super::ltc_table`]); the integral of that
//! distribution over the light's polygon is the clamped cosine's over the polygon carried back
//! by `M⁻¹`, which is Lambert's edge formula. Times the lobe's integral π·E (the E table of the
//! material's D and G) and F at the representative point's half vector it is the specular of the
//! whole light.

use super::area::{AreaLight, AreaShape, polygon_walk};
use super::common::safe_normalize;
use super::microfacet::{Distribution, Microfacet, microfacet_f};
use super::ms_table::{TableCell, table_bilinear};
use crate::guards::{AREA_POINT_LIMIT_ANGLE, LIGHT_DIST_MIN, SPHERE_DISK_MARGIN};
use crate::params::NamedValue;
use glam::{DMat3, DVec3};
use std::f64::consts::PI;

/// Nodes per side of each D's table: `√(1 − N·V)` across and `√m` down, each at `k/(side − 1)`
/// (the lobe's shape changes fastest at grazing views and low roughness, where these crowd).
pub const LTC_TABLE_SIDE: usize = 16;
/// vec4 slots of `tables.ltc` (WGSL `LTC_TABLE_VEC4S`, generated): one node a slot, every D's.
pub const LTC_TABLE_VEC4S: usize = Distribution::ALL.len() * LTC_TABLE_SIDE * LTC_TABLE_SIDE;
// The generated table has a node for every D's every node: a D added without a refit stops the
// build here.
const _: () = assert!(super::ltc_table::LTC_TABLE.len() == LTC_TABLE_VEC4S, "refit: shadelab fit-ltc --write");

/// `N·V` at column `i`.
pub fn ltc_node_n_dot_v(i: usize) -> f64 {
    let u = i as f64 / (LTC_TABLE_SIDE - 1) as f64;
    1.0 - u * u
}

/// m at row `j`.
pub fn ltc_node_m(j: usize) -> f64 {
    let w = j as f64 / (LTC_TABLE_SIDE - 1) as f64;
    w * w
}

/// Where (`n_dot_v`, `m`) falls in D `d`'s table (the E table's [`TableCell`] and bilinear step):
/// across at `√(1 − N·V)`, down at `√m`, both clamped to [0, 1].
pub fn ltc_cell(d: u32, n_dot_v: f64, m: f64) -> TableCell {
    let last = (LTC_TABLE_SIDE - 1) as f64;
    let u = (1.0 - n_dot_v.clamp(0.0, 1.0)).sqrt() * last;
    let w = m.clamp(0.0, 1.0).sqrt() * last;
    let (i, j) = ((u.floor() as usize).min(LTC_TABLE_SIDE - 2), (w.floor() as usize).min(LTC_TABLE_SIDE - 2));
    let base = d as usize * LTC_TABLE_SIDE * LTC_TABLE_SIDE;
    TableCell { base, j, i, fw: w - j as f64, fu: u - i as f64 }
}

/// One node of the table: `[a, b, c, d]` of `M⁻¹`'s rows `(a, 0, b)`, `(0, 1, 0)`, `(c, 0, d)`.
pub fn ltc_node(base: usize, j: usize, i: usize) -> [f64; 4] {
    super::ltc_table::LTC_TABLE[base + j * LTC_TABLE_SIDE + i].map(f64::from)
}

/// `M⁻¹` of the material's D at `n_dot_v` and `m`, each entry bilinear between the nodes, in the
/// frame (T, N × T, N) with T the view's tangent.
pub fn ltc_matrix(d: u32, n_dot_v: f64, m: f64) -> DMat3 {
    let c = ltc_cell(d, n_dot_v, m);
    let (n00, n01) = (ltc_node(c.base, c.j, c.i), ltc_node(c.base, c.j, c.i + 1));
    let (n10, n11) = (ltc_node(c.base, c.j + 1, c.i), ltc_node(c.base, c.j + 1, c.i + 1));
    let e: [f64; 4] = std::array::from_fn(|k| table_bilinear(c, [n00[k], n01[k]], [n10[k], n11[k]]));
    DMat3::from_cols(DVec3::new(e[0], 0.0, e[2]), DVec3::Y, DVec3::new(e[1], 0.0, e[3]))
}

/// A sphere light as the disk that covers the same cone seen from `p` (facing `p`, radius
/// `r·d/√(d² − r²)` at the centre's distance): the same directions, so the same integral of any
/// lobe; a flat light as it is. Only called off the sphere (`SPHERE_DISK_MARGIN`).
pub fn sphere_as_disk(light: &AreaLight, p: DVec3) -> AreaLight {
    let AreaShape::Sphere { radius } = light.shape else { return *light };
    let to_p = p - light.center;
    let d = to_p.length();
    let r = radius.abs();
    let normal = to_p / d;
    let radius = r * d / (d * d - r * r).max(0.0).sqrt();
    AreaLight { shape: AreaShape::Disk { radius }, normal, tangent: any_tangent(normal), ..*light }
}

/// The integral over the light of the distribution `M⁻¹` carries to the clamped cosine, at `p`
/// with unit normal `n` and view tangent `t` (in [0, 1]): Lambert's edge formula over the
/// corners carried to the cosine's frame, clipped at its horizon, over π.
pub fn ltc_polygon(light: &AreaLight, p: DVec3, n: DVec3, t: DVec3, minv: DMat3) -> f64 {
    let xf = minv * DMat3::from_cols(t, n.cross(t), n).transpose();
    (polygon_walk(light, p, DVec3::Z, xf) / PI).clamp(0.0, 1.0)
}

/// The specular of area light `light` at `p` (normal `n`, view `v`) by LTC, relative to its
/// centre's point light as [`super::area::area_form`] is: `d²/A_emit · π·E · ∫_light D_ltc`
/// for `M⁻¹` `minv` ([`ltc_matrix`]) and the lobe's albedo `e` at `N·V`; F and the compensation
/// are the caller's. `None` where the representative point stands: the point limit
/// (`AREA_POINT_LIMIT_ANGLE`: the point is exact there, and f32's edge sum is not), or a point
/// on the light.
pub fn area_specular_ltc(light: &AreaLight, p: DVec3, n: DVec3, v: DVec3, minv: DMat3, e: f64) -> Option<f64> {
    let to_c = light.center - p;
    let d = to_c.length();
    if d <= LIGHT_DIST_MIN || light.area_radius() < AREA_POINT_LIMIT_ANGLE * d {
        return None;
    }
    let n_dot_v = n.dot(v);
    if n_dot_v <= 0.0 {
        return Some(0.0);
    }
    let scale = d * d / light.emitting_area() * PI * e;
    if let AreaShape::Sphere { radius } = light.shape
        && d <= radius.abs() * (1.0 + SPHERE_DISK_MARGIN)
    {
        return Some(scale);
    }
    let t = safe_normalize(v - n * n_dot_v, any_tangent(n));
    Some(scale * ltc_polygon(&sphere_as_disk(light, p), p, n, t, minv))
}

/// How far [`ltc_polygon`]'s share moves, in the sweep, when each edge term of its sum moves by
/// its own size: `½Σ|terms|/π` over the corners carried by `M⁻¹`, as [`super::area::area_form_rounding`]
/// is for the form. Where the horizon leaves a sliver of the transformed light, or the fitted
/// lobe is narrow, the terms cancel and f32 keeps only their size times its precision. 0 where
/// [`area_specular_ltc`] takes no polygon.
pub fn ltc_rounding(light: &AreaLight, p: DVec3, n: DVec3, v: DVec3, minv: DMat3) -> f64 {
    let d = (light.center - p).length();
    let n_dot_v = n.dot(v);
    let inside = matches!(light.shape, AreaShape::Sphere { radius } if d <= radius.abs() * (1.0 + SPHERE_DISK_MARGIN));
    if d <= LIGHT_DIST_MIN || light.area_radius() < AREA_POINT_LIMIT_ANGLE * d || n_dot_v <= 0.0 || inside {
        return 0.0;
    }
    let t = safe_normalize(v - n * n_dot_v, any_tangent(n));
    let xf = minv * DMat3::from_cols(t, n.cross(t), n).transpose();
    let flat = sphere_as_disk(light, p);
    let corners: Vec<DVec3> = super::area::area_corners(&flat).into_iter().map(|c| xf * (c - p)).collect();
    0.5 * super::area::polygon_edge_sum(DVec3::ZERO, DVec3::Z, &corners).1 / PI
}

/// A unit vector perpendicular to unit `n` (the view's tangent where V is along N, where the
/// lobe is round and any tangent serves).
pub fn any_tangent(n: DVec3) -> DVec3 {
    let helper = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    n.cross(helper).normalize()
}

/// docs/area-lights.md: the Cook–Torrance specular of an area light by LTC, `F·comp·ltc`: F of
/// the material at the half vector of `v` and `l` (the representative point's direction), the
/// lobe's compensation for `ms_e` (1: none), and the light's integral `ltc`
/// ([`area_specular_ltc`]); 0 where the view is below the surface.
pub fn specular_ltc(
    n: DVec3,
    v: DVec3,
    l: DVec3,
    v_index: [f64; 3],
    terms: Microfacet,
    ms_e: f64,
    ltc: f64,
) -> [f64; 3] {
    if n.dot(v) <= 0.0 {
        return [0.0; 3];
    }
    let h = safe_normalize(l + v, n);
    let f = microfacet_f(terms, v.dot(h).clamp(0.0, 1.0), v_index);
    let comp = super::multiscatter::ms_compensation(ms_e, v_index);
    std::array::from_fn(|c| f[c] * comp[c] * ltc)
}

#[cfg(test)]
#[path = "ltc_tests.rs"]
mod tests;
