//! The twin of `shaders/microfacet.wgsl`: the microfacet terms of the Cook–Torrance form
//! `F·D·G/(N·V)` (docs/model.md §5), one function each, and the selectors that pick each term by
//! the material's [`Microfacet`]. A new D, G or F is a variant of its enum, one function here and
//! its twin, one arm in its selector.

use super::common::safe_normalize;
use crate::guards::*;
use glam::DVec3;

/// The facet distribution D.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Distribution {
    /// The chapter's Beckmann form ([`d_beckmann`]).
    #[default]
    Beckmann,
}

/// The masking–shadowing term G.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Masking {
    /// The chapter's `min{1, …}` ([`g_cook_torrance`]).
    #[default]
    CookTorrance,
}

/// The Fresnel factor F.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Fresnel {
    /// The exact unpolarized factor of a dielectric ([`fresnel_dielectric`]).
    #[default]
    Dielectric,
}

impl Distribution {
    /// Each distribution by its name; `DISTRIBUTION_<NAME>` is its WGSL code.
    pub const ALL: [(&'static str, Distribution); 1] = [("beckmann", Distribution::Beckmann)];
    pub fn code(self) -> u32 {
        match self {
            Distribution::Beckmann => 0,
        }
    }
}

impl Masking {
    /// Each masking term by its name; `MASKING_<NAME>` is its WGSL code.
    pub const ALL: [(&'static str, Masking); 1] = [("cook-torrance", Masking::CookTorrance)];
    pub fn code(self) -> u32 {
        match self {
            Masking::CookTorrance => 0,
        }
    }
}

impl Fresnel {
    /// Each Fresnel factor by its name; `FRESNEL_<NAME>` is its WGSL code.
    pub const ALL: [(&'static str, Fresnel); 1] = [("dielectric", Fresnel::Dielectric)];
    pub fn code(self) -> u32 {
        match self {
            Fresnel::Dielectric => 0,
        }
    }
}

/// The D, G and F a material's specular uses, each chosen on its own.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Microfacet {
    pub d: Distribution,
    pub g: Masking,
    pub f: Fresnel,
}

/// Bits of each field of [`Microfacet::code`] (WGSL `MICROFACET_FIELD_BITS`).
pub const MICROFACET_FIELD_BITS: u32 = 8;

impl Microfacet {
    /// The chapter's terms: Beckmann D, the min() G, the exact dielectric F.
    pub const CHAPTER: Microfacet =
        Microfacet { d: Distribution::Beckmann, g: Masking::CookTorrance, f: Fresnel::Dielectric };

    /// `object.microfacet` in WGSL: D in bits 0–7, G in 8–15, F in 16–23.
    pub fn code(self) -> u32 {
        self.d.code() | self.g.code() << MICROFACET_FIELD_BITS | self.f.code() << (2 * MICROFACET_FIELD_BITS)
    }
}

/// docs/model.md §5: the Beckmann facet distribution in the chapter's form
/// `D = 1/(4 m² (N·H)⁴) · exp((1 − 1/(N·H)²)/m²)`; equals π/4 × the normalized Beckmann D.
/// `sin2_nh` = 1 − (N·H)², computed by the caller as |N × H|² (precise at the peak; see the WGSL).
pub fn d_beckmann(n_dot_h: f64, sin2_nh: f64, m: f64) -> f64 {
    if n_dot_h <= 0.0 {
        return 0.0;
    }
    let c = n_dot_h.clamp(N_DOT_H_MIN, 1.0);
    let m2 = m.max(M_MIN).powi(2);
    let c2 = c * c;
    (1.0 / (4.0 * m2 * c2 * c2)) * (-sin2_nh.max(0.0) / (c2 * m2)).exp()
}

/// The normalized Beckmann distribution `exp(−tan²α/m²)/(π m² cos⁴α)` (its projected area
/// integrates to 1), written independently of [`d_beckmann`] so that tests can check the chapter's
/// form against it (docs/model.md §5: the chapter's D = π/4 × this).
#[cfg(test)]
pub(crate) fn d_beckmann_normalized(n_dot_h: f64, m: f64) -> f64 {
    if n_dot_h <= 0.0 {
        return 0.0;
    }
    let cos2 = n_dot_h * n_dot_h;
    let tan2 = (1.0 - cos2) / cos2;
    (-tan2 / (m * m)).exp() / (std::f64::consts::PI * m * m * cos2 * cos2)
}

/// docs/model.md §5: geometric attenuation `G = min{1, 2(N·H)(N·V)/(V·H), 2(N·H)(N·L)/(V·H)}`.
pub fn g_cook_torrance(n_dot_h: f64, n_dot_v: f64, n_dot_l: f64, v_dot_h: f64) -> f64 {
    let nh = n_dot_h.max(0.0);
    let nv = n_dot_v.max(0.0);
    let nl = n_dot_l.max(0.0);
    let vh = v_dot_h.max(0.0);
    // min{1, a/vh, b/vh} without dividing by a zero vh: 2·nh·n ≤ vh ⇔ a/vh ≤ 1.
    let num = (2.0 * nh * nv).min(2.0 * nh * nl);
    if num >= vh { 1.0 } else { num / vh.max(G_V_DOT_H_MIN) }
}

/// docs/model.md §5: refractive index from the reflectance at normal incidence,
/// `v = (1 + √μ)/(1 − √μ)`, with `√μ` capped at `FRESNEL_SQRT_MU_MAX`.
pub fn fresnel_v_from_mu(mu: f64) -> f64 {
    let s = mu.clamp(0.0, 1.0).sqrt().min(FRESNEL_SQRT_MU_MAX);
    (1.0 + s) / (1.0 - s)
}

/// docs/model.md §5, §7: the chapter's exact unpolarized Fresnel factor at an interface met at
/// cos θ_i = `c`, with `v` = n_t/n_i from either side (below 1 from inside the denser medium; the
/// specular's `v` from μ is at least 1):
/// `F = ½ ((g − c)/(g + c))² {1 + [(c(g + c) − 1)/(c(g − c) + 1)]²}`, g = √(v² + c² − 1); 1 under
/// total internal reflection (g² < 0). F(c = 1) = μ and F(c = 0) = 1 (the chapter's "c = 0" is an
/// erratum). The transmitted share is 1 − F. pbrt's `FrDielectric` also serves both sides.
pub fn fresnel_dielectric(c: f64, v: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let v = v.max(0.0);
    // g² = v² − 1 + c², grouped to keep what cancels exact: (v − 1)(v + 1) + c² near grazing (v
    // = 1 gives c² exactly), v² − (1 − c)(1 + c) from c = ½ up (c = 1 gives v² exactly, where the
    // other grouping loses a small v² to the 1s).
    let sin2 = (1.0 - c) * (1.0 + c);
    let g2 = if c < 0.5 { (v - 1.0) * (v + 1.0) + c * c } else { v * v - sin2 };
    if g2 < 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c).max(FRESNEL_G_PLUS_C_MIN);
    // c(g + c) − 1 = cg − sin²θ and c(g − c) + 1 = cg + sin²θ ≥ 0 (v at c = 1), without the 1s.
    let b = (c * g - sin2) / (c * g + sin2).max(FRESNEL_G_PLUS_C_MIN);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

/// The material's distribution D.
pub fn microfacet_d(terms: Microfacet, n_dot_h: f64, sin2_nh: f64, m: f64) -> f64 {
    match terms.d {
        Distribution::Beckmann => d_beckmann(n_dot_h, sin2_nh, m),
    }
}

/// The material's masking G.
pub fn microfacet_g(terms: Microfacet, n_dot_h: f64, n_dot_v: f64, n_dot_l: f64, v_dot_h: f64) -> f64 {
    match terms.g {
        Masking::CookTorrance => g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h),
    }
}

/// The material's Fresnel factor F at `c` = V·H, per channel of `v_index`.
pub fn microfacet_f(terms: Microfacet, c: f64, v_index: [f64; 3]) -> [f64; 3] {
    match terms.f {
        Fresnel::Dielectric => v_index.map(|v| fresnel_dielectric(c, v)),
    }
}

/// docs/model.md §5: the Cook–Torrance form as it enters the sum, `π ρ_s (N·L) = F·D·G/(N·V)`,
/// with the material's D, G and F, per colour channel (`v` per channel). Multiplying by π keeps it
/// on the scale of the chapter's diffuse term `r_d·C·(N·L)`, which has no 1/π.
pub fn specular_microfacet(n: DVec3, v: DVec3, l: DVec3, m: f64, v_index: [f64; 3], terms: Microfacet) -> [f64; 3] {
    let n_dot_l = n.dot(l);
    let n_dot_v = n.dot(v);
    if n_dot_l <= 0.0 || n_dot_v <= 0.0 {
        return [0.0; 3];
    }
    let h = safe_normalize(l + v, n);
    let n_dot_h = n.dot(h);
    let v_dot_h = v.dot(h).clamp(0.0, 1.0);
    let d = microfacet_d(terms, n_dot_h, n.cross(h).length_squared(), m);
    let g = microfacet_g(terms, n_dot_h, n_dot_v, n_dot_l, v_dot_h);
    let k = d * g / n_dot_v.max(N_DOT_V_MIN);
    microfacet_f(terms, v_dot_h, v_index).map(|f| f * k)
}
