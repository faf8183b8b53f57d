//! The analytic daylight sky of Preetham, Shirley and Smits (1999): Perez's luminance
//! distribution fitted to turbidity, and the zenith's luminance and chromaticity, turned into
//! linear sRGB (docs/environment.md). The sun's disc is not part of it: a directional light is
//! the sun. The values are relative: the zenith has luminance 1, and the environment's intensity
//! scales the whole sky.

use glam::DVec3;

crate::param_ranges! {
    /// The turbidity the model was fitted for: 2 (clear, arctic air) to 10 (haze).
    pub const TURBIDITY = "--turbidity", "T", "the sky's turbidity (2 clear to 10 hazy)", [2.0, 10.0];
}

/// The turbidity a sky starts with unless given one: a clear day, near the clear end of
/// [`TURBIDITY`], where the sky's blue and its bright band round the sun both show.
pub const TURBIDITY_DEFAULT: f64 = 3.0;

/// The cosine of a view's angle from the zenith is taken as at least this in Perez's `1/cos θ`:
/// at the horizon the term `e^{B/cos θ}` (with `B < 0`) is e^{-30} at most there, so the sky stays
/// finite and continuous down to the horizon. Below it the sky is black: the ground is the scene's.
pub const SKY_COS_MIN: f64 = 0.01;

/// The sun's height above the horizon is taken as at least 0: Preetham's fit has no night, and a
/// sun below the horizon would drive the zenith's luminance negative.
pub const SKY_SUN_COS_MIN: f64 = 0.0;

/// Perez's five coefficients, linear in turbidity: `[A, B, C, D, E]` for Y, x and y, each as
/// `(slope, intercept)` (Preetham et al., appendix A.2).
const PEREZ: [[(f64, f64); 5]; 3] = [
    [(0.1787, -1.4630), (-0.3554, 0.4275), (-0.0227, 5.3251), (0.1206, -2.5771), (-0.0670, 0.3703)],
    [(-0.0193, -0.2592), (-0.0665, 0.0008), (-0.0004, 0.2125), (-0.0641, -0.8989), (-0.0033, 0.0452)],
    [(-0.0167, -0.2608), (-0.0950, 0.0092), (-0.0079, 0.2102), (-0.0441, -1.6537), (-0.0109, 0.0529)],
];

/// The zenith's chromaticity x and y: rows for T², T and 1, columns for θ_s³, θ_s², θ_s, 1.
const ZENITH_X: [[f64; 4]; 3] =
    [[0.00166, -0.00375, 0.00209, 0.0], [-0.02903, 0.06377, -0.03202, 0.00394], [0.11693, -0.21196, 0.06052, 0.25886]];
const ZENITH_Y: [[f64; 4]; 3] =
    [[0.00275, -0.00610, 0.00317, 0.0], [-0.04214, 0.08970, -0.04153, 0.00516], [0.15346, -0.26756, 0.06670, 0.26688]];

/// A sky for turbidity `t` and the unit direction toward the sun, with its per-channel constants
/// worked out once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    sun: DVec3,
    /// Perez's coefficients for Y, x, y.
    perez: [[f64; 5]; 3],
    /// The zenith's Y (1), x, y, each over Perez's value at the zenith.
    zenith: [f64; 3],
}

impl Sky {
    /// The sky of turbidity `t` (clamped to [`TURBIDITY`]) with the sun toward unit `sun`, whose
    /// height is clamped to [`SKY_SUN_COS_MIN`].
    pub fn new(t: f64, sun: DVec3) -> Sky {
        let t = if t.is_finite() { t.clamp(TURBIDITY.min, TURBIDITY.max) } else { TURBIDITY.min };
        let flat = DVec3::new(sun.x, 0.0, sun.z);
        let mut s = crate::lighting::common::safe_normalize(sun, DVec3::Y);
        if s.y < SKY_SUN_COS_MIN {
            s = crate::lighting::common::safe_normalize(flat, DVec3::X);
        }
        let theta_s = s.y.clamp(-1.0, 1.0).acos();
        let perez = PEREZ.map(|row| row.map(|(a, b)| a * t + b));
        let poly = |m: &[[f64; 4]; 3]| {
            let th = [theta_s.powi(3), theta_s.powi(2), theta_s, 1.0];
            let row = |r: &[f64; 4]| r.iter().zip(th).map(|(a, b)| a * b).sum::<f64>();
            t * t * row(&m[0]) + t * row(&m[1]) + row(&m[2])
        };
        let zenith_value = [1.0, poly(&ZENITH_X), poly(&ZENITH_Y)];
        let zenith = std::array::from_fn(|i| zenith_value[i] / perez_f(&perez[i], 1.0, s.y));
        Sky { sun: s, perez, zenith }
    }

    /// The unit direction toward the sun, as the sky uses it.
    pub fn sun(&self) -> DVec3 {
        self.sun
    }

    /// Linear sRGB radiance toward unit `d` (from the point, looking out); 0 below the horizon.
    pub fn radiance(&self, d: DVec3) -> [f64; 3] {
        if !(d.y > 0.0) {
            return [0.0; 3];
        }
        let cos_theta = d.y.max(SKY_COS_MIN);
        let cos_gamma = d.dot(self.sun).clamp(-1.0, 1.0);
        let [lum, x, y] = std::array::from_fn(|i| self.zenith[i] * perez_f(&self.perez[i], cos_theta, cos_gamma));
        xyy_to_linear_srgb(lum, x, y)
    }
}

/// Perez's `F(θ, γ) = (1 + A e^{B/cos θ})(1 + C e^{Dγ} + E cos²γ)`.
fn perez_f(k: &[f64; 5], cos_theta: f64, cos_gamma: f64) -> f64 {
    let [a, b, c, d, e] = *k;
    let gamma = cos_gamma.clamp(-1.0, 1.0).acos();
    (1.0 + a * (b / cos_theta.max(SKY_COS_MIN)).exp()) * (1.0 + c * (d * gamma).exp() + e * cos_gamma * cos_gamma)
}

/// CIE Yxy to linear sRGB (D65), negative channels (outside the gamut) clamped to 0.
fn xyy_to_linear_srgb(lum: f64, x: f64, y: f64) -> [f64; 3] {
    if !(y > 0.0) || !lum.is_finite() {
        return [0.0; 3];
    }
    let (cx, cy, cz) = (x / y * lum, lum, (1.0 - x - y) / y * lum);
    [
        (3.2406 * cx - 1.5372 * cy - 0.4986 * cz).max(0.0),
        (-0.9689 * cx + 1.8758 * cy + 0.0415 * cz).max(0.0),
        (0.0557 * cx - 0.2040 * cy + 1.0570 * cz).max(0.0),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lum(c: [f64; 3]) -> f64 {
        0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
    }

    /// The zenith has luminance 1 by construction; the sky is bluer than white overhead, brighter
    /// toward the sun than away from it, and black below the horizon.
    #[test]
    fn the_sky_looks_like_a_sky() {
        let sky = Sky::new(3.0, DVec3::new(0.5, 0.5, 0.0).normalize());
        let up = sky.radiance(DVec3::Y);
        assert!((lum(up) - 1.0).abs() < 0.02, "{up:?}");
        assert!(up[2] > up[0], "a clear zenith is blue: {up:?}");
        let toward = sky.radiance(DVec3::new(0.6, 0.3, 0.0).normalize());
        let away = sky.radiance(DVec3::new(-0.6, 0.3, 0.0).normalize());
        assert!(lum(toward) > 2.0 * lum(away), "{toward:?} {away:?}");
        assert_eq!(sky.radiance(DVec3::new(0.0, -0.1, 1.0).normalize()), [0.0; 3]);
    }

    /// Hard cases stay finite and non-negative: the sun at and below the horizon, a view along
    /// the horizon, at the sun, and every turbidity, NaN included.
    #[test]
    fn hard_cases_stay_finite() {
        let views = [DVec3::X, DVec3::Y, DVec3::new(1.0, 1e-12, 0.0), DVec3::new(0.0, 1e-3, 1.0).normalize()];
        for t in [2.0, 10.0, 0.0, 50.0, f64::NAN] {
            for sun in [DVec3::X, DVec3::new(1.0, -0.5, 0.0), DVec3::Y, DVec3::ZERO, DVec3::new(0.0, 1e-9, 1.0)] {
                let sky = Sky::new(t, sun);
                for v in views.iter().copied().chain([sky.sun()]) {
                    let c = sky.radiance(v);
                    assert!(c.iter().all(|x| x.is_finite() && *x >= 0.0), "T {t} sun {sun} view {v}: {c:?}");
                }
            }
        }
    }
}
