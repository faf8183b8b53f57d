//! The twin of `shaders/ms_table.wgsl`: the table of the microfacet lobe's directional albedo E
//! with F = 1 (docs/microfacet.md), every D × G pair at `N·V` and m, which the multiple-scattering
//! compensation (`multiscatter.rs`) and the environment's split sum read. The project computes it
//! from [`crate::furnace::directional_albedo`] ([`ms_table`]), the same f32 values on the GPU
//! (`tables.ms_albedo`) and here.

use super::microfacet::{Distribution, Masking, Microfacet};
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

/// Where (`n_dot_v`, `m`) falls in a D × G pair's table (the E table and the split sum's B share
/// its layout): the pair's first node, the cell's corner (j down in m, i across in `N·V`), both
/// clamped to [0, 1], and the fractions inside the cell.
#[derive(Clone, Copy, Debug)]
pub struct TableCell {
    pub base: usize,
    pub j: usize,
    pub i: usize,
    pub fw: f64,
    pub fu: f64,
}

pub fn table_cell(terms: Microfacet, n_dot_v: f64, m: f64) -> TableCell {
    let last = (MS_TABLE_SIDE - 1) as f64;
    let u = n_dot_v.clamp(0.0, 1.0) * last;
    let w = m.clamp(0.0, 1.0) * last;
    let (i, j) = ((u.floor() as usize).min(MS_TABLE_SIDE - 2), (w.floor() as usize).min(MS_TABLE_SIDE - 2));
    let base = ms_pair(terms) * MS_TABLE_SIDE * MS_TABLE_SIDE;
    TableCell { base, j, i, fw: w - j as f64, fu: u - i as f64 }
}

/// Bilinear between a cell's four nodes: `low` the row at j (i, i + 1), `high` the row at j + 1.
pub fn table_bilinear(c: TableCell, low: [f64; 2], high: [f64; 2]) -> f64 {
    let l = low[0] * (1.0 - c.fu) + low[1] * c.fu;
    let h = high[0] * (1.0 - c.fu) + high[1] * c.fu;
    l * (1.0 - c.fw) + h * c.fw
}

/// One node of the E table: pair `base`'s row j (m), column i (`N·V`).
pub fn ms_node(base: usize, j: usize, i: usize) -> f64 {
    f64::from(ms_table()[base + j * MS_TABLE_SIDE + i])
}

/// docs/microfacet.md: E of the material's D and G at `n_dot_v` and `m`, bilinear between the
/// table's nodes (both clamped to [0, 1]).
pub fn ms_albedo(terms: Microfacet, n_dot_v: f64, m: f64) -> f64 {
    let c = table_cell(terms, n_dot_v, m);
    let low = [ms_node(c.base, c.j, c.i), ms_node(c.base, c.j, c.i + 1)];
    let high = [ms_node(c.base, c.j + 1, c.i), ms_node(c.base, c.j + 1, c.i + 1)];
    table_bilinear(c, low, high)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::furnace::directional_albedo;
    use crate::lighting::multiscatter::ms_compensation;

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
    }

    /// Measured: 1.7e-3 at the nodes (the 64² estimate), 4.9e-3 at the cells' centres (the
    /// bilinear step added). About twice that.
    const MS_NODE_ERROR: f64 = 3.5e-3;
    const MS_BETWEEN_ERROR: f64 = 1e-2;
}
