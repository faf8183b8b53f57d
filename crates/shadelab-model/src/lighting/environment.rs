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
