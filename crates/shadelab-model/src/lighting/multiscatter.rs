//! The twin of `shaders/multiscatter.wgsl`: the multiple-scattering compensation of the
//! microfacet lobe (docs/microfacet.md), Turquin's form as Filament uses it: the single-scatter
//! lobe times `1 + F0·(1 − E)/E`, E its directional albedo with F = 1 for the material's D and G
//! at `N·V` and m. A single-scatter lobe drops the light that bounces between facets; E says how
//! much, and the factor puts it back, coloured by F0 as the bounces are. E comes from a table the
//! project computes from [`crate::furnace::directional_albedo`] ([`ms_table`]), the same f32
//! values on the GPU (`tables.ms_albedo`) and here.

use super::microfacet::{Distribution, Masking, Microfacet};
use crate::guards::MS_ALBEDO_MIN;
use crate::params::NamedValue;
use std::sync::OnceLock;

/// Nodes per side of each D × G pair's table: `N·V` and m each at `k/(side − 1)`.
pub const MS_TABLE_SIDE: usize = 16;
/// The D × G pairs, `d.code()·MASKING_COUNT + g.code()`, from the term tables (the WGSL's
/// `MS_PAIRS` is generated from it, `shaders::generated_constants`).
pub const MS_PAIRS: usize = Distribution::ALL.len() * Masking::ALL.len();
/// vec4 slots of `tables.ms_albedo` (WGSL `MS_TABLE_VEC4S`, generated): every pair's nodes, four
/// floats a slot.
pub const MS_TABLE_VEC4S: usize = (MS_PAIRS * MS_TABLE_SIDE * MS_TABLE_SIDE).div_ceil(4);
/// Half vectors per side the table's integrals take (64² each: its error is under the
/// interpolation's, docs/microfacet.md).
pub const MS_TABLE_SAMPLES: usize = 64;

/// The table's index of a material's D × G pair.
pub fn ms_pair(terms: Microfacet) -> usize {
    terms.d.code() as usize * Masking::ALL.len() + terms.g.code() as usize
}

/// Every pair's E at its nodes, row by row in m, `N·V` across, computed once (about 0.2 s).
pub fn ms_table() -> &'static [f32] {
    static TABLE: OnceLock<Vec<f32>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let node = |k: usize| k as f64 / (MS_TABLE_SIDE - 1) as f64;
        let mut out = Vec::with_capacity(MS_PAIRS * MS_TABLE_SIDE * MS_TABLE_SIDE);
        for &(_, d) in Distribution::ALL {
            for &(_, g) in Masking::ALL {
                let terms = Microfacet { d, g, ..Microfacet::CHAPTER };
                for j in 0..MS_TABLE_SIDE {
                    for i in 0..MS_TABLE_SIDE {
                        let e = crate::furnace::directional_albedo(terms, node(j), node(i), MS_TABLE_SAMPLES);
                        // A lobe reflects at most what arrives: the quadrature overshoots 1 by up
                        // to 8e-4 at m → 0 near grazing (found by the environment's sweep).
                        out.push(e.min(1.0) as f32);
                    }
                }
            }
        }
        out
    })
}

/// The table as `tables.ms_albedo` holds it: four floats a slot, the rest zero.
pub fn ms_table_vec4s() -> [[f32; 4]; MS_TABLE_VEC4S] {
    let mut out = [[0.0; 4]; MS_TABLE_VEC4S];
    for (k, e) in ms_table().iter().enumerate() {
        out[k / 4][k % 4] = *e;
    }
    out
}

/// docs/microfacet.md: E of the material's D and G at `n_dot_v` and `m`, bilinear between the
/// table's nodes (both clamped to [0, 1]).
pub fn ms_albedo(terms: Microfacet, n_dot_v: f64, m: f64) -> f64 {
    let table = ms_table();
    let last = (MS_TABLE_SIDE - 1) as f64;
    let u = n_dot_v.clamp(0.0, 1.0) * last;
    let w = m.clamp(0.0, 1.0) * last;
    let (i, j) = ((u.floor() as usize).min(MS_TABLE_SIDE - 2), (w.floor() as usize).min(MS_TABLE_SIDE - 2));
    let (fu, fw) = (u - i as f64, w - j as f64);
    let base = ms_pair(terms) * MS_TABLE_SIDE * MS_TABLE_SIDE;
    let at = |jj: usize, ii: usize| table[base + jj * MS_TABLE_SIDE + ii] as f64;
    let low = at(j, i) * (1.0 - fu) + at(j, i + 1) * fu;
    let high = at(j + 1, i) * (1.0 - fu) + at(j + 1, i + 1) * fu;
    low * (1.0 - fw) + high * fw
}

/// docs/microfacet.md: the compensation `1 + F0·(1 − E)/E` per channel, `F0 = ((v − 1)/(v + 1))²`
/// of each channel's index (μ for the specular's v), E floored at `MS_ALBEDO_MIN`.
pub fn ms_compensation(e: f64, v_index: [f64; 3]) -> [f64; 3] {
    let e = e.clamp(MS_ALBEDO_MIN, 1.0);
    v_index.map(|v| {
        let r = (v.max(0.0) - 1.0) / (v.max(0.0) + 1.0);
        1.0 + r * r * (1.0 - e) / e
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::furnace::directional_albedo;

    /// The table against the furnace's integral at 256² samples: at the nodes it is the
    /// integral's own estimate, between them the bilinear step adds the interpolation's error.
    #[test]
    fn the_table_is_the_furnace_integral_within_its_interpolation() {
        let (mut at_nodes, mut between) = (0.0f64, 0.0f64);
        for terms in crate::furnace::pairs() {
            let node = |k: f64| k / (MS_TABLE_SIDE - 1) as f64;
            for (x, m) in
                [(1.0, node(3.0)), (node(7.0), node(8.0)), (node(3.0), 1.0), (1.0, 1.0), (node(1.0), node(6.0))]
            {
                let e = directional_albedo(terms, m, x, 256);
                at_nodes = at_nodes.max((ms_albedo(terms, x, m) - e).abs());
            }
            let mid = |k: f64| (k + 0.5) / (MS_TABLE_SIDE - 1) as f64;
            for (x, m) in [(mid(14.0), mid(3.0)), (mid(7.0), mid(7.0)), (mid(4.0), mid(13.0)), (mid(1.0), mid(14.0))] {
                let e = directional_albedo(terms, m, x, 256);
                between = between.max((ms_albedo(terms, x, m) - e).abs());
            }
        }
        eprintln!("|table − integral|: {at_nodes:.2e} at nodes, {between:.2e} between them");
        assert!(at_nodes < MS_NODE_ERROR, "{at_nodes}");
        assert!(between < MS_BETWEEN_ERROR, "{between}");
    }

    /// Every node is an albedo: in [0, 1] (the quadrature's overshoot near m = 0 is clamped).
    #[test]
    fn the_table_holds_albedos() {
        assert!(ms_table().iter().all(|e| (0.0..=1.0).contains(e)));
    }

    /// With F0 = 1 (a white furnace) the compensated lobe reflects all it receives: E·factor = 1
    /// wherever the table is exact, and within its error elsewhere.
    #[test]
    fn the_compensated_furnace_is_white() {
        let white = [1e9; 3];
        for terms in crate::furnace::pairs() {
            for (x, m) in [(1.0, 1.0), (0.53, 0.47), (0.2, 0.8)] {
                let e = directional_albedo(terms, m, x, 256);
                let k = ms_compensation(ms_albedo(terms, x, m), white)[0];
                assert!((e * k - 1.0).abs() < MS_BETWEEN_ERROR / e, "{terms} N·V = {x}, m = {m}: {}", e * k);
            }
        }
        // F0 = 0: nothing to put back.
        assert_eq!(ms_compensation(0.3, [1.0; 3]), [1.0; 3]);
        assert!(ms_compensation(0.0, [1e9; 3])[0] <= 1.0 / MS_ALBEDO_MIN);
    }

    /// Measured: 1.7e-3 at the nodes (the 64² estimate), 4.9e-3 at the cells' centres (the
    /// bilinear step added). About twice that.
    const MS_NODE_ERROR: f64 = 3.5e-3;
    const MS_BETWEEN_ERROR: f64 = 1e-2;
}
