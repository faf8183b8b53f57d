//! The twin of `shaders/environment.wgsl`: an environment's diffuse light from nine spherical
//! harmonic coefficients (Ramamoorthi and Hanrahan 2001; docs/environment.md). The coefficients
//! are the environment's radiance projected on the real SH basis of bands 0–2, each band scaled by
//! the clamped cosine's `Â_l / π`, so that [`env_sh_radiance`] is `E(n)/π`: the irradiance over π,
//! the unit of the chapter's `I_a`. A uniform radiance `L` gives `L` for every normal, and the
//! term `r_a·C·env_sh_radiance(n)` is then the chapter's ambient `I_a·r_a·C` with `I_a = L`.

use glam::DVec3;

/// The SH coefficients the GPU reads: nine RGB triples, band 0 first.
pub type ShCoefficients = [[f64; 3]; 9];

/// The real SH basis of bands 0–2 at unit `n`, in world axes (y up). Each band spans the same
/// space in any orthonormal axes, so the order of x, y and z within a band is a naming choice.
pub fn env_sh_basis(n: DVec3) -> [f64; 9] {
    let (x, y, z) = (n.x, n.y, n.z);
    [
        SH_Y0,
        SH_Y1 * y,
        SH_Y1 * z,
        SH_Y1 * x,
        SH_Y2 * x * z,
        SH_Y2 * y * z,
        SH_Y20 * (3.0 * y * y - 1.0),
        SH_Y2 * x * y,
        SH_Y22 * (x * x - z * z),
    ]
}

/// `Y_00 = 1/(2√π)`.
pub const SH_Y0: f64 = 0.282_094_791_773_878_14;
/// `√(3/(4π))`, the band-1 functions' factor.
pub const SH_Y1: f64 = 0.488_602_511_902_919_9;
/// `√(15/(4π))`, the factor of the three products of two axes.
pub const SH_Y2: f64 = 1.092_548_430_592_079_3;
/// `√(5/(16π))`, the factor of `3y² − 1`.
pub const SH_Y20: f64 = 0.315_391_565_252_520_05;
/// `√(15/(16π))`, the factor of `x² − z²`.
pub const SH_Y22: f64 = 0.546_274_215_296_039_6;

/// The clamped cosine's band weights over π: `Â_0 = π`, `Â_1 = 2π/3`, `Â_2 = π/4` (Ramamoorthi
/// and Hanrahan), divided by π so the sum is in the unit of `I_a`.
pub const SH_BAND_WEIGHT: [f64; 3] = [1.0, 2.0 / 3.0, 0.25];

/// How far the nine terms can overshoot the radiance: they convolve it with the kernel
/// `K(t) = (1 + 2t + 5/8·(3t² − 1))/4` of `t = n·ω`, which dips below 0 between its roots
/// `t = (−16 ± √76)/30`, so `E(n)/π ≤ 2∫ max(K, 0) dt · max L`, this constant (closed form; a
/// test integrates it). The stability sweep holds the GPU's SH diffuse under it.
pub const SH_RINGING_BOUND: f64 = 1.030_673_733_306_397;

/// `E(n)/π` at unit `n` from coefficients already scaled by [`SH_BAND_WEIGHT`]: the twin of the
/// WGSL, which reads the same nine triples from the globals. Negative sums (ringing of the nine
/// terms behind a bright source) are clamped to 0: light is never negative.
pub fn env_sh_radiance(sh: &ShCoefficients, n: DVec3) -> [f64; 3] {
    let y = env_sh_basis(n);
    std::array::from_fn(|c| y.iter().zip(sh).map(|(b, k)| b * k[c]).sum::<f64>().max(0.0))
}

/// The integrals of the nine basis functions over the cell `cos θ ∈ [μ0, μ1]`,
/// `φ ∈ [φ0, φ1]` of the sphere (θ from +y, φ from +x toward +z), in closed form, so that a
/// map's projection is exact for a piecewise-constant map whatever its resolution: a 1×1 map
/// has nothing above band 0.
pub fn sh_cell_integrals(mu: [f64; 2], phi: [f64; 2]) -> [f64; 9] {
    let [m0, m1] = mu;
    let [p0, p1] = phi;
    // ∫dμ, ∫μ dμ, ∫(3μ² − 1) dμ, ∫(1 − μ²) dμ, ∫√(1 − μ²) dμ, ∫μ√(1 − μ²) dμ.
    let s = |m: f64| (1.0 - m * m).max(0.0).sqrt();
    let d1 = m1 - m0;
    let dmu = (m1 * m1 - m0 * m0) / 2.0;
    let d3 = (m1 * m1 * m1 - m1) - (m0 * m0 * m0 - m0);
    let dsq = d1 - (m1 * m1 * m1 - m0 * m0 * m0) / 3.0;
    let ds = 0.5 * ((m1 * s(m1) + m1.clamp(-1.0, 1.0).asin()) - (m0 * s(m0) + m0.clamp(-1.0, 1.0).asin()));
    let dms = -((s(m1).powi(3)) - (s(m0).powi(3))) / 3.0;
    let dphi = p1 - p0;
    let dcos = p1.sin() - p0.sin(); // ∫cos φ
    let dsin = p0.cos() - p1.cos(); // ∫sin φ
    let dsin2 = (p0 * 2.0).cos() - (p1 * 2.0).cos(); // 2∫sin 2φ
    let dcos2 = (p1 * 2.0).sin() - (p0 * 2.0).sin(); // 2∫cos 2φ
    // x = s cos φ, z = s sin φ, y = μ; xz = s² sin 2φ / 2, x² − z² = s² cos 2φ.
    [
        SH_Y0 * d1 * dphi,
        SH_Y1 * dmu * dphi,
        SH_Y1 * ds * dsin,
        SH_Y1 * ds * dcos,
        SH_Y2 * dsq * dsin2 / 4.0,
        SH_Y2 * dms * dsin,
        SH_Y20 * d3 * dphi,
        SH_Y2 * dms * dcos,
        SH_Y22 * dsq * dcos2 / 2.0,
    ]
}

/// The nine coefficients of an equirectangular map of `width × height` cells (row 0 at +y, θ
/// uniform over rows; column 0 starting at φ = `phi0`, φ growing with the column), whose cell
/// `(x, y)` has the constant radiance `texel(x, y)`; scaled by [`SH_BAND_WEIGHT`].
pub fn sh_project(width: u32, height: u32, phi0: f64, texel: impl Fn(u32, u32) -> [f64; 3]) -> ShCoefficients {
    use std::f64::consts::{PI, TAU};
    let mut sh = [[0.0; 3]; 9];
    for y in 0..height {
        let theta = |r: u32| PI * f64::from(r) / f64::from(height);
        let mu = [theta(y + 1).cos(), theta(y).cos()];
        for x in 0..width {
            let phi = |c: u32| phi0 + TAU * f64::from(c) / f64::from(width);
            let w = sh_cell_integrals(mu, [phi(x), phi(x + 1)]);
            let l = texel(x, y);
            for (k, wk) in w.iter().enumerate() {
                for c in 0..3 {
                    sh[k][c] += wk * l[c];
                }
            }
        }
    }
    for (k, coefficient) in sh.iter_mut().enumerate() {
        let band = if k == 0 {
            0
        } else if k < 4 {
            1
        } else {
            2
        };
        *coefficient = coefficient.map(|v| v * SH_BAND_WEIGHT[band]);
    }
    sh
}

/// Levels of the prefiltered environment (its specular, docs/environment.md): level k is the
/// environment blurred by the lobe of roughness `m_k = k/(ENV_LEVELS − 1)`, so m in [0, 1] is
/// read between two levels.
pub const ENV_LEVELS: u32 = 6;
/// Level 0's width in texels (height half of it): 5.6° texels; every second level halves both.
pub const ENV_LEVEL_WIDTH: u32 = 64;
/// Texels of every level together (vec4 slots of the GPU's buffer).
pub const ENV_PREFILTERED_TEXELS: usize = 2 * (64 * 32 + 32 * 16 + 16 * 8);

/// Level `k`'s width and height in texels.
pub fn env_level_size(k: u32) -> (u32, u32) {
    let w = ENV_LEVEL_WIDTH >> (k / 2);
    (w, w / 2)
}

/// Where level `k`'s texels start in the buffer.
pub fn env_level_offset(k: u32) -> u32 {
    (0..k).map(|j| env_level_size(j).0 * env_level_size(j).1).sum()
}

/// Texel `(x, y)` of level `k` (x wraps around, y clamps at the poles).
pub fn env_texel(pre: &[[f32; 4]], k: u32, x: i32, y: i32) -> [f64; 3] {
    let (w, h) = env_level_size(k);
    let xi = x.rem_euclid(w as i32) as u32;
    let yi = y.clamp(0, h as i32 - 1) as u32;
    let t = pre[(env_level_offset(k) + yi * w + xi) as usize];
    [t[0], t[1], t[2]].map(f64::from)
}

/// Level `k` toward unit world direction `d`, bilinear between texel centres.
pub fn env_level_sample(pre: &[[f32; 4]], k: u32, d: DVec3) -> [f64; 3] {
    use std::f64::consts::{PI, TAU};
    let (w, h) = env_level_size(k);
    let phi = d.z.atan2(d.x);
    let u = (phi / TAU).rem_euclid(1.0) * f64::from(w) - 0.5;
    // The angle from +y as the WGSL takes it: atan2 of (√(x² + z²), y).
    let v = d.x.hypot(d.z).atan2(d.y) / PI * f64::from(h) - 0.5;
    let (x0, y0) = (u.floor(), v.floor());
    let (fu, fv) = (u - x0, v - y0);
    let (x0, y0) = (x0 as i32, y0 as i32);
    let at = |x, y| env_texel(pre, k, x, y);
    let (a, b, c, e) = (at(x0, y0), at(x0 + 1, y0), at(x0, y0 + 1), at(x0 + 1, y0 + 1));
    std::array::from_fn(|i| (a[i] * (1.0 - fu) + b[i] * fu) * (1.0 - fv) + (c[i] * (1.0 - fu) + e[i] * fu) * fv)
}

/// The prefiltered environment toward `r` for roughness `m` (clamped to [0, 1]), linear between
/// the two levels around it.
pub fn env_prefiltered(pre: &[[f32; 4]], r: DVec3, m: f64) -> [f64; 3] {
    let t = m.clamp(0.0, 1.0) * f64::from(ENV_LEVELS - 1);
    let k = (t.floor() as u32).min(ENV_LEVELS - 2);
    let f = t - f64::from(k);
    let (a, b) = (env_level_sample(pre, k, r), env_level_sample(pre, k + 1, r));
    std::array::from_fn(|i| a[i] * (1.0 - f) + b[i] * f)
}

/// Every D × G pair's B (the lobe's albedo weighed by `(1 − V·H)⁵`, [`crate::furnace::weighted_albedo`])
/// at the nodes of the compensation's table (`ms_table::ms_table`: m down, `N·V` across),
/// computed once; `tables.env_split_b` holds it four floats a slot.
pub fn env_split_b_table() -> &'static [f32] {
    use super::microfacet::{Distribution, Masking, Microfacet};
    use super::ms_table::{MS_TABLE_SAMPLES, MS_TABLE_SIDE};
    use crate::params::NamedValue;
    static TABLE: std::sync::OnceLock<Vec<f32>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let node = |k: usize| k as f64 / (MS_TABLE_SIDE - 1) as f64;
        let mut out = Vec::new();
        for &(_, d) in Distribution::ALL {
            for &(_, g) in Masking::ALL {
                let terms = Microfacet { d, g, ..Microfacet::CHAPTER };
                for j in 0..MS_TABLE_SIDE {
                    for i in 0..MS_TABLE_SIDE {
                        let grazing = |c: f64| (1.0 - c).clamp(0.0, 1.0).powi(5);
                        out.push(
                            crate::furnace::weighted_albedo(terms, node(j), node(i), MS_TABLE_SAMPLES, grazing) as f32
                        );
                    }
                }
            }
        }
        out
    })
}

/// The table as `tables.env_split_b` holds it: four floats a slot.
pub fn env_split_b_vec4s() -> [[f32; 4]; ENV_SPLIT_B_VEC4S] {
    let mut out = [[0.0; 4]; ENV_SPLIT_B_VEC4S];
    for (k, b) in env_split_b_table().iter().enumerate() {
        out[k / 4][k % 4] = *b;
    }
    out
}

/// vec4 slots of `tables.env_split_b` (WGSL `ENV_SPLIT_B_VEC4S`, generated): every D × G pair's
/// nodes, four floats a slot, laid out as the E table.
pub const ENV_SPLIT_B_VEC4S: usize = super::ms_table::MS_TABLE_VEC4S;

/// One node of the B table: pair `base`'s row j (m), column i (N·V).
pub fn env_split_b_node(base: usize, j: usize, i: usize) -> f64 {
    f64::from(env_split_b_table()[base + j * super::ms_table::MS_TABLE_SIDE + i])
}

/// B of the material's D and G at `n_dot_v` and `m`, bilinear between the nodes as the
/// compensation's E.
pub fn env_split_b(terms: super::microfacet::Microfacet, n_dot_v: f64, m: f64) -> f64 {
    use super::ms_table::{table_bilinear, table_cell};
    let c = table_cell(terms, n_dot_v, m);
    let low = [env_split_b_node(c.base, c.j, c.i), env_split_b_node(c.base, c.j, c.i + 1)];
    let high = [env_split_b_node(c.base, c.j + 1, c.i), env_split_b_node(c.base, c.j + 1, c.i + 1)];
    table_bilinear(c, low, high)
}

/// The split sum (docs/environment.md): the environment's specular light at a point seen along
/// `v`, before `r_s`: the prefiltered environment toward the mirror direction, times
/// `F0·(E − B) + B`: E the lobe's albedo for the material's D and G at `N·V` (the compensation's
/// table), B its share toward grazing, F0 the material's F at normal incidence.
pub fn env_specular(
    pre: &[[f32; 4]],
    n: DVec3,
    v: DVec3,
    m: f64,
    terms: super::microfacet::Microfacet,
    v_index: [f64; 3],
) -> [f64; 3] {
    let n_dot_v = n.dot(v);
    if n_dot_v <= 0.0 {
        return [0.0; 3];
    }
    let r = super::common::safe_normalize(n * (2.0 * n_dot_v) - v, n);
    let l = env_prefiltered(pre, r, m);
    let e = super::ms_table::ms_albedo(terms, n_dot_v, m);
    let b = env_split_b(terms, n_dot_v, m);
    let f0 = super::microfacet::microfacet_f(terms, 1.0, v_index);
    std::array::from_fn(|i| l[i] * (f0[i] * (e - b) + b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The cells' integrals add up to the basis's integrals over the sphere: 2√π for band 0
    /// (that is 4π·Y_00), 0 for the others; and the basis is orthonormal by quadrature.
    #[test]
    fn cell_integrals_sum_to_the_spheres() {
        let (w, h) = (7, 5);
        let mut total = [0.0; 9];
        for y in 0..h {
            let t = |r: u32| PI * f64::from(r) / f64::from(h);
            for x in 0..w {
                let p = |c: u32| 0.3 + 2.0 * PI * f64::from(c) / f64::from(w);
                let c = sh_cell_integrals([t(y + 1).cos(), t(y).cos()], [p(x), p(x + 1)]);
                for k in 0..9 {
                    total[k] += c[k];
                }
            }
        }
        assert!((total[0] - 4.0 * PI * SH_Y0).abs() < 1e-12, "{total:?}");
        assert!(total[1..].iter().all(|t| t.abs() < 1e-12), "{total:?}");
    }

    /// Each cell's closed form agrees with a fine midpoint quadrature of the basis over it.
    #[test]
    fn cell_integrals_match_quadrature() {
        let (mu, phi) = ([-0.3, 0.55], [0.4, 1.9]);
        let exact = sh_cell_integrals(mu, phi);
        let n = 400;
        let mut sum = [0.0; 9];
        for i in 0..n {
            let m = mu[0] + (mu[1] - mu[0]) * (f64::from(i) + 0.5) / f64::from(n);
            for j in 0..n {
                let p = phi[0] + (phi[1] - phi[0]) * (f64::from(j) + 0.5) / f64::from(n);
                let s = (1.0 - m * m).sqrt();
                let b = env_sh_basis(DVec3::new(s * p.cos(), m, s * p.sin()));
                for k in 0..9 {
                    sum[k] += b[k] * (mu[1] - mu[0]) * (phi[1] - phi[0]) / f64::from(n * n);
                }
            }
        }
        for k in 0..9 {
            assert!((sum[k] - exact[k]).abs() < 1e-5, "basis {k}: quadrature {} closed form {}", sum[k], exact[k]);
        }
    }

    /// The B table against the f64 integral at 256² samples between its nodes: within the
    /// bilinear interpolation's error, as the E table, for every D × G pair; and B never above E.
    #[test]
    fn the_b_table_matches_its_integral() {
        use crate::lighting::microfacet::{Distribution, Masking, Microfacet};
        use crate::params::NamedValue;
        let mut worst = 0.0f64;
        for &(_, d) in Distribution::ALL {
            for &(_, g) in Masking::ALL {
                let terms = Microfacet { d, g, ..Microfacet::CHAPTER };
                for (n_dot_v, m) in [(0.53, 0.47), (0.9, 0.2), (0.2, 0.8), (0.1, 0.35)] {
                    let grazing = |c: f64| (1.0f64 - c).clamp(0.0, 1.0).powi(5);
                    let exact = crate::furnace::weighted_albedo(terms, m, n_dot_v, 256, grazing);
                    let table = env_split_b(terms, n_dot_v, m);
                    worst = worst.max((exact - table).abs());
                    assert!(table <= crate::lighting::ms_table::ms_albedo(terms, n_dot_v, m) + 1e-6);
                }
            }
        }
        // Measured 5.2e-3; the E table's bound between its nodes (ms_table.rs) is 1e-2.
        assert!(worst < 1e-2, "largest |table − integral| {worst}");
    }

    /// The ringing bound is the nine terms' kernel's positive mass, by quadrature, and the whole
    /// kernel's mass is 1.
    #[test]
    fn the_ringing_bound_is_the_kernels_positive_mass() {
        // The kernel from the band weights: Σ_l Â_l (2l + 1)/4 · P_l(t), t = n·ω.
        let k = |t: f64| {
            let w = SH_BAND_WEIGHT;
            (w[0] + 3.0 * w[1] * t + 5.0 * w[2] * 0.5 * (3.0 * t * t - 1.0)) / 4.0
        };
        let steps = 200_000;
        let positive: f64 = (0..steps).map(|i| k(-1.0 + (i as f64 + 0.5) * 2.0 / steps as f64).max(0.0)).sum::<f64>()
            * 2.0
            / steps as f64;
        assert!((2.0 * positive - SH_RINGING_BOUND).abs() < 1e-8, "{}", 2.0 * positive);
        // The whole kernel's mass is 1: a uniform environment is its own ambient.
        let whole: f64 =
            (0..steps).map(|i| k(-1.0 + (i as f64 + 0.5) * 2.0 / steps as f64)).sum::<f64>() * 2.0 / steps as f64;
        assert!((2.0 * whole - 1.0).abs() < 1e-9);
    }

    /// A 1×1 map is the uniform ambient it stands for: `E/π = L` for every normal, to rounding.
    #[test]
    fn one_texel_is_the_uniform_ambient() {
        let l = [0.12, 0.3, 0.05];
        let sh = sh_project(1, 1, 0.0, |_, _| l);
        for n in [DVec3::Y, DVec3::NEG_Y, DVec3::new(0.3, -0.5, 0.8).normalize(), DVec3::X] {
            let e = env_sh_radiance(&sh, n);
            for c in 0..3 {
                assert!((e[c] - l[c]).abs() < 1e-15, "{n}: {e:?} against {l:?}");
            }
        }
    }

    /// For a sky bright above and dark below (radiance `1 + y`, inside bands 0–1), the nine terms
    /// give its cosine convolution `E/π = 1 + (2/3)·n_y`, to the map's own step of 256 rows.
    #[test]
    fn band_limited_map_is_exact() {
        let (w, h) = (4, 256);
        // Each cell's mean of 1 + y, so that the piecewise-constant map projects exactly.
        let sh = sh_project(w, h, 0.0, |_, y| {
            let t = |r: u32| PI * f64::from(r) / f64::from(h);
            let (m0, m1) = (t(y + 1).cos(), t(y).cos());
            [1.0 + (m0 + m1) / 2.0; 3]
        });
        for n in [DVec3::Y, DVec3::NEG_Y, DVec3::new(0.6, 0.0, 0.8), DVec3::new(0.1, 0.7, -0.2).normalize()] {
            let e = env_sh_radiance(&sh, n)[0];
            assert!((e - (1.0 + 2.0 / 3.0 * n.y)).abs() < 1e-4, "{n}: {e}");
        }
    }
}
