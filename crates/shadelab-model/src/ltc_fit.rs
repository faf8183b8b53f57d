//! The fit of the linearly transformed cosines (LTC) that the GPU draws an area light's specular
//! with (docs/area-lights.md): for each D and each node of (N·V, m), the 3 × 3 matrix M whose
//! clamped cosine, transformed by M, is closest to the microfacet lobe. The method is Heitz,
//! Dupuy, Hill and Neubelt, "Real-Time Polygonal-Light Shading with Linearly Transformed
//! Cosines", SIGGRAPH 2016, §4; the fit below is this project's own.
//!
//! - The lobe is the chapter's `D·G/(N·V)` with F = 1 and Smith's separable G of the same D,
//!   normalized to a distribution of directions (its integral is π·E).
//! - `M = [X Y Z]·[[m11, 0, m13], [0, m22, 0], [0, 0, 1]]`, Z a direction in the plane of N and
//!   V (starting at the lobe's mean) and X its tangent there: four parameters, found by
//!   Nelder–Mead from the neighbouring node's, minimizing `∫ |p − q|³/(p + q)` (p the lobe, q the LTC) over samples of
//!   both distributions, as the paper weighs its error towards the peak.
//! - The table holds `M⁻¹` divided by its middle element (its scale does not change the
//!   distribution), four numbers a node ([`ltc_table`](crate::lighting::ltc_table)).

use crate::lighting::ltc::{LTC_TABLE_SIDE, ltc_node_m, ltc_node_n_dot_v};
use crate::lighting::microfacet::{Distribution, Masking, Microfacet, microfacet_d, microfacet_g};
use crate::params::NamedValue;
use glam::{DMat3, DVec3};
use std::f64::consts::{FRAC_PI_2, PI};

/// Samples per side of each of the fit's two stratified sample sets (the lobe's and the LTC's).
pub const FIT_SAMPLES: usize = 24;
/// Nelder–Mead's iterations at most, per node.
const FIT_ITERATIONS: usize = 300;
/// The smallest m the fit is run at: the lobe of the table's first node (m = 0) is fitted as
/// this one, narrower than a pixel at any view (`M_MIN` is 1e-3; below 0.01 the samples of a
/// 24² set cannot resolve the lobe's peak).
pub const FIT_M_MIN: f64 = 0.01;

/// One node's LTC: the forward matrix's parameters and its frame's mean direction `z` (in the
/// xz plane, V's side).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ltc {
    pub m11: f64,
    pub m22: f64,
    pub m13: f64,
    pub z: DVec3,
}

impl Ltc {
    /// `M` of the paper: the clamped cosine's directions to the lobe's.
    pub fn matrix(&self) -> DMat3 {
        let x = DVec3::new(self.z.z, 0.0, -self.z.x);
        let frame = DMat3::from_cols(x, DVec3::Y, self.z);
        let shape = DMat3::from_cols(
            DVec3::new(self.m11.abs(), 0.0, 0.0),
            DVec3::new(0.0, self.m22.abs(), 0.0),
            DVec3::new(self.m13, 0.0, 1.0),
        );
        frame * shape
    }

    /// `M⁻¹` divided by its middle element: `[a, b, c, d]` of rows `(a, 0, b)`, `(0, 1, 0)`,
    /// `(c, 0, d)`, as the table holds it.
    pub fn table_entry(&self) -> [f64; 4] {
        let inv = self.matrix().inverse();
        let k = inv.y_axis.y;
        [inv.x_axis.x / k, inv.z_axis.x / k, inv.x_axis.z / k, inv.z_axis.z / k]
    }
}

/// The LTC's density of direction `l` for `M⁻¹` (any scale): the clamped cosine at
/// `M⁻¹l/|M⁻¹l|`, times the Jacobian `|det M⁻¹|/|M⁻¹l|³`.
pub fn ltc_pdf(minv: DMat3, l: DVec3) -> f64 {
    let lo = minv * l;
    let len2 = lo.length_squared();
    if len2 <= 0.0 {
        return 0.0;
    }
    let len = len2.sqrt();
    (lo.z / len).max(0.0) / PI * minv.determinant().abs() / (len2 * len)
}

/// The lobe a table node is fitted to: D of `d`, Smith's separable G of the same D, F = 1.
pub fn fit_terms(d: Distribution) -> Microfacet {
    Microfacet { d, g: Masking::Smith, ..Microfacet::CHAPTER }
}

/// The chapter's `D·G/(N·V)` (F = 1) towards unit `l` from unit `v`, N = +z; and the density of
/// `l` when its half vector is drawn from D's distribution of `N·H` (`D_n·(N·H)/(4 V·H)`, the
/// chapter's D being π/4 × the normalized `D_n`).
fn lobe(terms: Microfacet, m: f64, v: DVec3, l: DVec3) -> (f64, f64) {
    if l.z <= 0.0 {
        return (0.0, 0.0);
    }
    let h = (v + l).normalize();
    let v_dot_h = v.dot(h);
    if v_dot_h <= 0.0 {
        return (0.0, 0.0);
    }
    let sin2 = (h.x * h.x + h.y * h.y).max(0.0);
    let d = microfacet_d(terms, h.z, sin2, m);
    let g = microfacet_g(terms, h.z, v.z, l.z, v_dot_h, m);
    (d * g / v.z, d * h.z / (PI * v_dot_h))
}

/// Direction `l` reflected about a half vector drawn from D at `(u1, u2)`.
fn lobe_sample(terms: Microfacet, m: f64, v: DVec3, u1: f64, u2: f64) -> DVec3 {
    let tan2 = terms.d.sample_tan2(m * m, u1);
    let cos_h = 1.0 / (1.0 + tan2).sqrt();
    let sin_h = (1.0 - cos_h * cos_h).max(0.0).sqrt();
    let phi = 2.0 * PI * u2;
    let h = DVec3::new(sin_h * phi.cos(), sin_h * phi.sin(), cos_h);
    2.0 * v.dot(h) * h - v
}

/// The lobe at one node, ready to be fitted: its view, its integral π·E and mean direction.
struct Target {
    terms: Microfacet,
    m: f64,
    v: DVec3,
    norm: f64,
    mean: DVec3,
}

impl Target {
    fn new(d: Distribution, n_dot_v: f64, m: f64) -> Self {
        let terms = fit_terms(d);
        let cos_v = n_dot_v.clamp(1e-4, 1.0);
        let v = DVec3::new((1.0 - cos_v * cos_v).sqrt(), 0.0, cos_v);
        let m = m.max(FIT_M_MIN);
        let (mut norm, mut mean) = (0.0, DVec3::ZERO);
        let n = 64;
        for (u1, u2) in strata(n) {
            let l = lobe_sample(terms, m, v, u1, u2);
            let (f, pdf) = lobe(terms, m, v, l);
            if pdf > 0.0 {
                norm += f / pdf;
                mean += l * (f / pdf);
            }
        }
        norm /= (n * n) as f64;
        let mean = if mean.length_squared() > 0.0 { mean.normalize() } else { DVec3::Z };
        // The lobe's mean, about the mirror direction (x ≤ 0, V being at x ≥ 0), kept in the
        // upper hemisphere.
        let mean = DVec3::new(mean.x, 0.0, mean.z.max(1e-3)).normalize();
        Target { terms, m, v, norm, mean }
    }

    /// The lobe as a distribution of directions, and the density its samples are drawn with.
    fn eval(&self, l: DVec3) -> (f64, f64) {
        let (f, pdf) = lobe(self.terms, self.m, self.v, l);
        (if self.norm > 0.0 { f / self.norm } else { 0.0 }, pdf)
    }

    /// `∫ |p − q|^power/(p + q)` of the LTC of matrix `m` against the lobe, over both sample
    /// sets weighed by the balance heuristic; with `power` 1 it is the L1 distance `∫ |p − q|`,
    /// in [0, 2].
    fn error(&self, m: DMat3, power: i32) -> f64 {
        if !(m.determinant().abs() >= 1e-12) {
            return f64::INFINITY;
        }
        let minv = m.inverse();
        let mut sum = 0.0;
        let n = FIT_SAMPLES;
        for (u1, u2) in strata(n) {
            // A sample of the LTC: the clamped cosine's direction, carried by M.
            let r = u1.sqrt();
            let phi = 2.0 * PI * u2;
            let lo = DVec3::new(r * phi.cos(), r * phi.sin(), (1.0 - u1).max(0.0).sqrt());
            sum += self.mixed(minv, (m * lo).normalize(), power);
            // A sample of the lobe.
            sum += self.mixed(minv, lobe_sample(self.terms, self.m, self.v, u1, u2), power);
        }
        sum / (n * n) as f64
    }

    /// One sample's share of [`Target::error`]: `|p − q|^power` over the two sampling densities.
    fn mixed(&self, minv: DMat3, l: DVec3, power: i32) -> f64 {
        let q = ltc_pdf(minv, l);
        let (p, pdf_lobe) = self.eval(l);
        let weight = q + pdf_lobe;
        if weight <= 0.0 || !weight.is_finite() {
            return 0.0;
        }
        (p - q).abs().powi(power) / weight
    }
}

/// The `n × n` midpoints of the unit square.
fn strata(n: usize) -> impl Iterator<Item = (f64, f64)> {
    (0..n * n)
        .map(move |k| ((k / n) as f64 + 0.5, (k % n) as f64 + 0.5))
        .map(move |(a, b)| (a / n as f64, b / n as f64))
}

/// Nelder–Mead's minimum of `f` from `start`, with a first simplex `step` wide on each axis.
fn nelder_mead<const N: usize>(f: impl Fn(&[f64; N]) -> f64, start: [f64; N], step: f64) -> [f64; N] {
    let mut simplex: Vec<([f64; N], f64)> = (0..=N)
        .map(|i| {
            let mut x = start;
            if i > 0 {
                x[i - 1] += step * x[i - 1].abs().max(0.05);
            }
            (x, f(&x))
        })
        .collect();
    let combine =
        |a: &[f64; N], b: &[f64; N], t: f64| -> [f64; N] { std::array::from_fn(|k| a[k] + (b[k] - a[k]) * t) };
    for _ in 0..FIT_ITERATIONS {
        simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
        if (simplex[N].1 - simplex[0].1).abs() <= 1e-9 * simplex[0].1.abs().max(1e-12) {
            break;
        }
        let centroid: [f64; N] = std::array::from_fn(|k| simplex[..N].iter().map(|s| s.0[k]).sum::<f64>() / N as f64);
        let worst = simplex[N];
        let reflected = combine(&centroid, &worst.0, -1.0);
        let fr = f(&reflected);
        if fr < simplex[0].1 {
            let expanded = combine(&centroid, &worst.0, -2.0);
            let fe = f(&expanded);
            simplex[N] = if fe < fr { (expanded, fe) } else { (reflected, fr) };
        } else if fr < simplex[N - 1].1 {
            simplex[N] = (reflected, fr);
        } else {
            let contracted = combine(&centroid, &worst.0, 0.5);
            let fc = f(&contracted);
            if fc < worst.1 {
                simplex[N] = (contracted, fc);
            } else {
                let best = simplex[0].0;
                for s in simplex.iter_mut().skip(1) {
                    s.0 = combine(&best, &s.0, 0.5);
                    s.1 = f(&s.0);
                }
            }
        }
    }
    simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
    simplex[0].0
}

/// The fit at one node from a first guess (its neighbour's shape): the frame starts at the lobe's
/// own mean direction and turns with the shape (four parameters); at normal view the lobe is
/// round about N, so `m22 = m11`, `m13 = 0` and the frame is N's.
pub fn fit_node(d: Distribution, n_dot_v: f64, m: f64, guess: Ltc) -> Ltc {
    let target = Target::new(d, n_dot_v, m);
    if n_dot_v >= 1.0 - 1e-9 {
        let err = |x: &[f64; 1]| target.error(Ltc { m11: x[0], m22: x[0], m13: 0.0, z: DVec3::Z }.matrix(), 3);
        let [m11] = nelder_mead(err, [guess.m11.abs()], 0.1);
        return Ltc { m11: m11.abs(), m22: m11.abs(), m13: 0.0, z: DVec3::Z };
    }
    let ltc = |x: &[f64; 4]| {
        let angle = x[3].clamp(-FRAC_PI_2 + 1e-3, FRAC_PI_2 - 1e-3);
        Ltc { m11: x[0], m22: x[1], m13: x[2], z: DVec3::new(angle.sin(), 0.0, angle.cos()) }
    };
    let err = |x: &[f64; 4]| target.error(ltc(x).matrix(), 3);
    let start = [guess.m11.abs(), guess.m22.abs(), guess.m13, target.mean.x.atan2(target.mean.z)];
    let x = nelder_mead(err, start, 0.1);
    // Where the simplex wandered off (a lobe narrower than the samples resolve), the neighbour's
    // shape is kept.
    let best = if err(&x) <= err(&start) { x } else { start };
    let fit = ltc(&best);
    Ltc { m11: fit.m11.abs(), m22: fit.m22.abs(), ..fit }
}

/// The L1 distance `∫ |p − q|` between the lobe at a node and the LTC of `entry` (a table
/// entry: `M⁻¹` normalized), in [0, 2]: the share of the lobe the LTC puts elsewhere, twice.
pub fn entry_error(d: Distribution, n_dot_v: f64, m: f64, entry: [f64; 4]) -> f64 {
    let minv = entry_matrix(entry);
    if !(minv.determinant().abs() >= 1e-30) {
        return 2.0;
    }
    Target::new(d, n_dot_v, m).error(minv.inverse(), 1)
}

/// `M⁻¹` of a table entry `[a, b, c, d]`: rows `(a, 0, b)`, `(0, 1, 0)`, `(c, 0, d)`.
pub fn entry_matrix([a, b, c, d]: [f64; 4]) -> DMat3 {
    DMat3::from_cols(DVec3::new(a, 0.0, c), DVec3::Y, DVec3::new(b, 0.0, d))
}

/// Every D's table, fitted node by node: for each D, rows of m from the roughest down (each row
/// starts from the row above it at normal view), N·V across from normal view (column 0) to
/// grazing (each node starts from its neighbour). The D's run in parallel. Returns, per D in
/// [`Distribution::ALL`]'s order, `LTC_TABLE_SIDE²` entries, row j (m) by column i (N·V).
pub fn fit_tables() -> Vec<Vec<[f64; 4]>> {
    use rayon::prelude::*;
    Distribution::ALL.par_iter().map(|&(_, d)| fit_table(d)).collect()
}

/// One D's table ([`fit_tables`]).
pub fn fit_table(d: Distribution) -> Vec<[f64; 4]> {
    let side = LTC_TABLE_SIDE;
    let mut out = vec![[0.0; 4]; side * side];
    let mut above = Ltc { m11: 1.0, m22: 1.0, m13: 0.0, z: DVec3::Z };
    for j in (0..side).rev() {
        let m = ltc_node_m(j);
        let mut guess = above;
        for i in 0..side {
            let n_dot_v = ltc_node_n_dot_v(i);
            let fit = fit_node(d, n_dot_v, m, guess);
            if i == 0 {
                above = fit;
            }
            out[j * side + i] = fit.table_entry();
            guess = fit;
        }
    }
    out
}

/// The Rust source of `lighting/ltc_table.rs` for `tables` ([`fit_tables`]), as `shadelab
/// fit-ltc --write` writes it: each node's entry in f32, one node a line.
pub fn table_source(tables: &[Vec<[f64; 4]>]) -> String {
    let nodes: usize = tables.iter().map(Vec::len).sum();
    let mut s = String::from(
        "//! The LTC table (docs/area-lights.md), written by `shadelab fit-ltc --write` from the fit in\n\
         //! `crates/shadelab-model/src/ltc_fit.rs`; not edited by hand. Per D in `Distribution::ALL`'s\n\
         //! order, `LTC_TABLE_SIDE²` nodes, row j (m = (j/15)²) by column i (N·V = 1 − (i/15)²): `M⁻¹`\n\
         //! divided by its middle element, `[a, b, c, d]` of its rows `(a, 0, b)`, `(0, 1, 0)`, `(c, 0, d)`.\n\
         //! Its length is the fit's; `ltc.rs` holds it equal to `LTC_TABLE_VEC4S` when it compiles.\n\n\
         #[rustfmt::skip]\n",
    );
    s += &format!("pub const LTC_TABLE: [[f32; 4]; {nodes}] = [\n");
    for table in tables {
        for e in table {
            let f = e.map(|x| x as f32);
            s += &format!("    [{:?}, {:?}, {:?}, {:?}],\n", f[0], f[1], f[2], f[3]);
        }
    }
    s += "];\n";
    s
}

#[cfg(test)]
#[path = "ltc_fit_tests.rs"]
mod tests;
