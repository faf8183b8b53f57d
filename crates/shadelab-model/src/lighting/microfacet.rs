//! The twin of `shaders/microfacet.wgsl`: the microfacet terms of the Cook–Torrance form
//! `F·D·G/(N·V)` (docs/model.md §5), one function each, and the selectors that pick each term by
//! the material's [`Microfacet`]. A new D, G or F is a variant of its enum, one function here and
//! its twin, one arm in its selector. The roughness m is every term's width: Beckmann's m, GGX's
//! and Smith's α (docs/model.md §5 gives the mapping to glTF's roughness and Phong's h).

use super::common::safe_normalize;
use crate::guards::*;
use crate::params::NamedValue;
use glam::DVec3;

/// The facet distribution D.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Distribution {
    /// The chapter's Beckmann form ([`d_beckmann`]).
    #[default]
    Beckmann,
    /// Trowbridge–Reitz, called GGX ([`d_ggx`]): glTF's, Filament's and Bevy's D.
    Ggx,
    /// The normalized Blinn–Phong lobe `(h + 2)/2π · cos^h θ_h` ([`d_blinn_phong`]): the chapter's
    /// Phong lobe written as a facet distribution, h from m by the project's rule.
    BlinnPhong,
}

/// The masking–shadowing term G.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Masking {
    /// The chapter's V-groove `min{1, …}` ([`g_cook_torrance`]).
    #[default]
    VGroove,
    /// Smith's masking and shadowing as independent factors `G1(V)·G1(L)` ([`g_smith_separable`]).
    Smith,
    /// Smith's height-correlated form `1/(1 + Λ(V) + Λ(L))` ([`g_smith_correlated`]): glTF's and
    /// Filament's.
    SmithCorrelated,
}

/// The Fresnel factor F.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Fresnel {
    /// The exact unpolarized factor of a dielectric ([`fresnel_dielectric`]).
    #[default]
    Exact,
    /// Schlick's approximation `F0 + (1 − F0)(1 − c)⁵` ([`fresnel_schlick`]).
    Schlick,
}

impl Distribution {
    /// `DISTRIBUTION_<NAME>` in WGSL.
    pub fn code(self) -> u32 {
        self as u32
    }

    /// `tan²θ_h` of the half vector at `u` in [0, 1) of the D's inverse CDF of `N·H` (its
    /// projected area's), for `α² = m²`: the furnace samples each D by it.
    pub fn sample_tan2(self, a2: f64, u: f64) -> f64 {
        match self {
            Distribution::Beckmann => -a2 * (1.0 - u).ln(),
            Distribution::Ggx => a2 * u / (1.0 - u),
            // N·H = (1 − u)^(1/(h + 2)) with h + 2 = 2/α² (h ≥ 0: α² ≤ 1).
            Distribution::BlinnPhong => (-a2.min(1.0) * (1.0 - u).ln()).exp_m1(),
        }
    }
}

impl Masking {
    /// `MASKING_<NAME>` in WGSL.
    pub fn code(self) -> u32 {
        self as u32
    }
}

impl Fresnel {
    /// `FRESNEL_<NAME>` in WGSL.
    pub fn code(self) -> u32 {
        self as u32
    }
}

crate::named_values!(Distribution, "--distribution", "beckmann" => Beckmann, "ggx" => Ggx, "blinn-phong" => BlinnPhong);

crate::named_values!(Masking, "--masking",
    "v-groove" => VGroove, "smith" => Smith, "smith-correlated" => SmithCorrelated
);

crate::named_values!(Fresnel, "--fresnel", "exact" => Exact, "schlick" => Schlick);

// The presets by name (`--microfacet`); a combination that is no preset has no name of its own.
crate::named_values!(Microfacet, "--microfacet", "chapter" => CHAPTER, "gltf" => GLTF);

/// A term's name (the CLI's, the files' and the panel's word) and its parse.
macro_rules! named_term {
    ($($t:ty),*) => {$(
        impl std::fmt::Display for $t {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }
        impl std::str::FromStr for $t {
            type Err = crate::params::ParamError;
            fn from_str(s: &str) -> Result<Self, Self::Err> {
                Self::parse_named(s)
            }
        }
    )*};
}
named_term!(Distribution, Masking, Fresnel);

/// `d/g/f`, e.g. `ggx/smith-correlated/schlick`, with `+ms` when compensated and `+mix` when the
/// diffuse is weighted by the Fresnel factor.
impl std::fmt::Display for Microfacet {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}/{}", self.d, self.g, self.f)?;
        write!(f, "{}{}", if self.multiple_scattering { "+ms" } else { "" }, if self.fresnel_mix { "+mix" } else { "" })
    }
}

/// The D, G and F a material's specular uses, each chosen on its own.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Microfacet {
    pub d: Distribution,
    pub g: Masking,
    pub f: Fresnel,
    /// The multiple-scattering compensation on top (`multiscatter.rs`); neither set has it.
    pub multiple_scattering: bool,
    /// The diffuse weighted by what the dielectric layer's Fresnel leaves it, glTF's
    /// `fresnel_mix` ([`fresnel_mix_weight`]); the glTF set has it, the chapter's does not.
    pub fresnel_mix: bool,
}

/// Bits of each field of [`Microfacet::code`] (WGSL `MICROFACET_FIELD_BITS`).
pub const MICROFACET_FIELD_BITS: u32 = 8;
/// The compensation's bit of [`Microfacet::code`], after the three fields.
pub const MICROFACET_MULTIPLE_SCATTERING: u32 = 1 << (3 * MICROFACET_FIELD_BITS);
/// The Fresnel-weighted diffuse's bit of [`Microfacet::code`], after the compensation's.
pub const MICROFACET_FRESNEL_MIX: u32 = 1 << (3 * MICROFACET_FIELD_BITS + 1);

impl Microfacet {
    /// The chapter's terms: Beckmann D, the V-groove G, the exact dielectric F.
    pub const CHAPTER: Microfacet = Microfacet {
        d: Distribution::Beckmann,
        g: Masking::VGroove,
        f: Fresnel::Exact,
        multiple_scattering: false,
        fresnel_mix: false,
    };
    /// The glTF 2.0 specification's terms (its Appendix B), also Filament's: GGX D, the
    /// height-correlated Smith G and Schlick's F, with α = m, and its diffuse weighted by the
    /// dielectric's Fresnel (docs/model.md §5).
    pub const GLTF: Microfacet = Microfacet {
        d: Distribution::Ggx,
        g: Masking::SmithCorrelated,
        f: Fresnel::Schlick,
        multiple_scattering: false,
        fresnel_mix: true,
    };

    /// `object.microfacet` in WGSL: D in bits 0–7, G in 8–15, F in 16–23, the compensation in
    /// bit 24 (`MICROFACET_MULTIPLE_SCATTERING`), the Fresnel-weighted diffuse in bit 25
    /// (`MICROFACET_FRESNEL_MIX`).
    pub fn code(self) -> u32 {
        let terms =
            self.d.code() | self.g.code() << MICROFACET_FIELD_BITS | self.f.code() << (2 * MICROFACET_FIELD_BITS);
        let ms = if self.multiple_scattering { MICROFACET_MULTIPLE_SCATTERING } else { 0 };
        terms | ms | if self.fresnel_mix { MICROFACET_FRESNEL_MIX } else { 0 }
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

/// docs/model.md §5: Trowbridge–Reitz (GGX) in the chapter's scale, π/4 × the normalized
/// `α²/(π ((N·H)²(α² − 1) + 1)²)`, with α = m: `D = α²/(4 ((N·H)² α² + sin²)²)`, writing
/// `(N·H)²(α² − 1) + 1` as `(N·H)²α² + sin²θ_h` (Filament's form, precise at the peak). Its peak
/// `1/(4α²)` equals Beckmann's at the same m; the denominator is at least min(α², 1)², so no guard
/// beyond M_MIN is needed.
pub fn d_ggx(n_dot_h: f64, sin2_nh: f64, m: f64) -> f64 {
    if n_dot_h <= 0.0 {
        return 0.0;
    }
    let c = n_dot_h.min(1.0);
    let a2 = m.max(M_MIN).powi(2);
    let k = c * c * a2 + sin2_nh.max(0.0);
    a2 / (4.0 * k * k)
}

/// docs/microfacet.md: the normalized Blinn–Phong distribution `(h + 2)/2π · cos^h θ_h` in the
/// chapter's scale (π/4 × it, as the other two): `D = (h + 2)/8 · (N·H)^h` with `h = 2/m² − 2`
/// (`PhongExponent::from_m`'s rule, without its clamp to [1, H_MAX]: h = 0, a uniform lobe, is a
/// valid D), so that its peak `1/(4m²)` equals Beckmann's and GGX's at the same m. h is held at
/// 0 or more, where the normalization holds. `(N·H)^h` is taken as `exp(h/2 · ln(1 − sin²θ_h))`
/// from `sin2_nh` (|N × H|², as Beckmann's): at h = 2·10⁶ a rounded N·H would be off by 10 %.
pub fn d_blinn_phong(n_dot_h: f64, sin2_nh: f64, m: f64) -> f64 {
    if n_dot_h <= 0.0 {
        return 0.0;
    }
    let h = (2.0 / m.max(M_MIN).powi(2) - 2.0).max(0.0);
    (h + 2.0) / 8.0 * (h / 2.0 * ln_one_minus(sin2_nh.clamp(0.0, 1.0))).exp()
}

/// Gauss–Legendre nodes and weights (t, w) on [0, 1], 8 of them, for [`lambda_blinn_phong`]'s
/// integral; the WGSL's `BLINN_PHONG_LAMBDA_NODES` is generated from this table (`shaders.rs`).
pub const BLINN_PHONG_LAMBDA_NODES: [[f64; 2]; 8] = [
    [0.019855071751231884, 0.05061426814518813],
    [0.10166676129318663, 0.11119051722668724],
    [0.23723379504183551, 0.15685332293894364],
    [0.4082826787521751, 0.18134189168918099],
    [0.5917173212478249, 0.18134189168918099],
    [0.7627662049581645, 0.15685332293894364],
    [0.8983332387068134, 0.11119051722668724],
    [0.9801449282487681, 0.05061426814518813],
];

/// `Γ(x + ½)/Γ(x)` for x ≥ 1: the recurrence `Γ(x + ½)/Γ(x) = x/(x + ½) · Γ(x + 3/2)/Γ(x + 1)`
/// up to x ≥ 5, then the asymptotic series `√x·(1 − 1/8x + 1/128x² + 5/1024x³ − 21/32768x⁴)`,
/// whose next term is under 5e-7 of it there.
pub fn gamma_half_ratio(x_in: f64) -> f64 {
    let (mut x, mut r) = (x_in.max(1.0), 1.0);
    for _ in 0..4 {
        if x < 5.0 {
            r *= x / (x + 0.5);
            x += 1.0;
        }
    }
    let y = 1.0 / x;
    r * x.sqrt() * (1.0 - y / 8.0 + y * y / 128.0 + 5.0 * y * y * y / 1024.0 - 21.0 * y * y * y * y / 32768.0)
}

/// `1 − eˣ` for x ≤ 0, by its series `−x − x²/2 − x³/6` where |x| < 1e-2 (error under 5e-10 of
/// it), where `1 − exp(x)` in f32 would keep none of its digits.
pub fn one_minus_exp(x: f64) -> f64 {
    if x.abs() < 1e-2 { -x * (1.0 + x * (0.5 + x / 6.0)) } else { 1.0 - x.exp() }
}

/// `ln(1 − y)` for y in [0, 1], by its series `−y − y²/2 − y³/3 − y⁴/4` where y < 1e-2 (error
/// under 3e-11 of it), where `1 − y` in f32 would round y away; `1 − y` is floored at
/// `PHONG_LOG2_ARG_MIN`, as the WGSL's, so that y = 1 gives a finite −87.
pub fn ln_one_minus(y: f64) -> f64 {
    if y < 1e-2 { -y * (1.0 + y * (0.5 + y * (1.0 / 3.0 + y / 4.0))) } else { (1.0 - y).max(PHONG_LOG2_ARG_MIN).ln() }
}

/// docs/microfacet.md: Smith's Λ of the normalized Blinn–Phong D at `N·X = c`, h = 2/m² − 2 held
/// at 0 or more. Its slopes follow Student's t-distribution with h + 2 degrees of freedom, for
/// which `Λ = sⁿ⁺¹/(n·B(½, (n + 1)/2)) · ∫₀¹ (1/c − u^(1/n)/√(1 − s²·u^(2/n))) du`, n = h + 1,
/// s = sin θ; the integral by [`BLINN_PHONG_LAMBDA_NODES`] on `u = 1 − (1 − t)²`. 0 at c = 1;
/// c is held at `BLINN_PHONG_COS_MIN` or more.
pub fn lambda_blinn_phong(c_in: f64, m: f64) -> f64 {
    let c = c_in.clamp(BLINN_PHONG_COS_MIN, 1.0);
    let a = m.max(M_MIN);
    let h = (2.0 / (a * a) - 2.0).max(0.0);
    let n = h + 1.0;
    let mut k = 0.0;
    for [t, w] in BLINN_PHONG_LAMBDA_NODES {
        let u = t * (2.0 - t);
        let root = (u.ln() / n).exp();
        // 1 − s²·u^(2/n) = (1 − u^(2/n)) + c²·u^(2/n), each part kept to its digits.
        let d = one_minus_exp(2.0 * u.ln() / n) + c * c * root * root;
        k += w * 2.0 * (1.0 - t) * (1.0 / c - root / d.sqrt());
    }
    let s_pow = ((n + 1.0) / 2.0 * ln_one_minus(c * c)).exp();
    // 1/B(½, (n + 1)/2) = Γ((n + 2)/2)/(√π·Γ((n + 1)/2)).
    let inv_beta = gamma_half_ratio((h + 2.0) / 2.0) * 0.5 * std::f64::consts::FRAC_2_SQRT_PI;
    if c >= 1.0 { 0.0 } else { s_pow * inv_beta / n * k }
}

/// Smith's single-direction masking `G1 = 1/(1 + Λ)` at `N·X = c` for the material's D, with α = m:
/// - GGX: `2c/(c + √(α² + (1 − α²)c²))`, exact; the denominator is at least min(α, 1).
/// - Beckmann: Walter et al. 2007's rational fit (their eq. 27) in `a = c/(α sin θ)`,
///   `(3.535a + 2.181a²)/(1 + 2.276a + 2.577a²)` below a = 1.6 and 1 above, multiplied through by
///   (α sin θ)² so that nothing divides by sin θ = 0.
/// - Blinn–Phong: its own Λ ([`lambda_blinn_phong`]), `1/(1 + Λ)`; 0 at c = 0.
pub fn smith_g1(d: Distribution, c_in: f64, m: f64) -> f64 {
    let c = c_in.clamp(0.0, 1.0);
    let a = m.max(M_MIN);
    match d {
        Distribution::Ggx => 2.0 * c / (c + (a * a + (1.0 - a * a) * c * c).sqrt()),
        Distribution::BlinnPhong => {
            if c <= 0.0 {
                return 0.0;
            }
            1.0 / (1.0 + lambda_blinn_phong(c, a))
        }
        Distribution::Beckmann => {
            let t = a * ((1.0 - c) * (1.0 + c)).sqrt();
            if c >= 1.6 * t {
                return 1.0;
            }
            // The fit overshoots 1 by 3e-7 just below a = 1.6: held at the bound it approximates.
            ((3.535 * c * t + 2.181 * c * c) / (t * t + 2.276 * c * t + 2.577 * c * c)).min(1.0)
        }
    }
}

/// docs/model.md §5: Smith's G with masking and shadowing independent, `G1(N·V)·G1(N·L)`.
pub fn g_smith_separable(d: Distribution, n_dot_v: f64, n_dot_l: f64, m: f64) -> f64 {
    smith_g1(d, n_dot_v, m) * smith_g1(d, n_dot_l, m)
}

/// docs/model.md §5: Smith's height-correlated G, `1/(1 + Λ(V) + Λ(L))` with `Λ = 1/G1 − 1`, as
/// `G1v·G1l/(G1v + G1l − G1v·G1l)`. The numerator never exceeds the denominator (G1 ≤ 1), so the
/// floor SMITH_DENOM_MIN only turns 0/0 (both directions grazing) into 0.
pub fn g_smith_correlated(d: Distribution, n_dot_v: f64, n_dot_l: f64, m: f64) -> f64 {
    let gv = smith_g1(d, n_dot_v, m);
    let gl = smith_g1(d, n_dot_l, m);
    gv * gl / (gv + gl - gv * gl).max(SMITH_DENOM_MIN)
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

/// docs/model.md §5: Schlick's approximation of the exact factor, `F0 + (1 − F0)(1 − c)⁵` with
/// `F0 = ((v − 1)/(v + 1))²`, the normal-incidence reflectance of index `v` (for the specular's
/// `v` from μ that is μ itself, within FRESNEL_SQRT_MU_MAX).
pub fn fresnel_schlick(c: f64, v: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let v = v.max(0.0);
    let r = (v - 1.0) / (v + 1.0);
    let f0 = r * r;
    let x = 1.0 - c;
    let x2 = x * x;
    f0 + (1.0 - f0) * x2 * x2 * x
}

/// `1 − fresnel_dielectric(c, v)`, the transmitted share, summed from positive parts so that it
/// keeps its precision where F → 1 (grazing `c`, or μ → 1): with F = ½a²(1 + b²),
/// `1 − F = (1 − a²) + ½a²(1 − b²)`, `1 − a² = 4gc/(g + c)²`, `1 − b² = 4cg·sin²θ/(cg + sin²θ)²`.
pub fn fresnel_dielectric_complement(c: f64, v: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let v = v.max(0.0);
    let sin2 = (1.0 - c) * (1.0 + c);
    let g2 = if c < 0.5 { (v - 1.0) * (v + 1.0) + c * c } else { v * v - sin2 };
    if g2 < 0.0 {
        return 0.0;
    }
    let g = g2.sqrt();
    let gpc = (g + c).max(FRESNEL_G_PLUS_C_MIN);
    let a = (g - c) / gpc;
    let den = (c * g + sin2).max(FRESNEL_G_PLUS_C_MIN);
    let b = (c * g - sin2) / den;
    // Where a guard holds a denominator (g + c → 0 at v = 1 grazing, cg + sin²θ → 0 at v = 0 and
    // c = 1) the identity does not: there 1 − a² and 1 − b² themselves.
    let one_minus_a2 = if g + c < FRESNEL_G_PLUS_C_MIN { (1.0 - a) * (1.0 + a) } else { 4.0 * g * c / (gpc * gpc) };
    let guarded = c * g + sin2 < FRESNEL_G_PLUS_C_MIN;
    let one_minus_b2 = if guarded { (1.0 - b) * (1.0 + b) } else { 4.0 * c * g * sin2 / (den * den) };
    (one_minus_a2 + 0.5 * a * a * one_minus_b2).clamp(0.0, 1.0)
}

/// `1 − fresnel_schlick(c, v)` as the product `(1 − F0)(1 − (1 − c)⁵)` of its two small factors,
/// `1 − F0 = 4v/(v + 1)²` and `1 − (1 − c)⁵ = c(1 + x + x² + x³ + x⁴)` with `x = 1 − c`, so that it
/// keeps its precision where F → 1.
pub fn fresnel_schlick_complement(c: f64, v: f64) -> f64 {
    let c = c.clamp(0.0, 1.0);
    let v = v.max(0.0);
    let t0 = 4.0 * v / ((v + 1.0) * (v + 1.0));
    let x = 1.0 - c;
    t0 * c * (1.0 + x * (1.0 + x * (1.0 + x * (1.0 + x))))
}

/// The material's `1 − F` at `c` = V·H for index `v` (the complement of [`microfacet_f`]).
pub fn microfacet_f_complement(terms: Microfacet, c: f64, v: f64) -> f64 {
    match terms.f {
        Fresnel::Exact => fresnel_dielectric_complement(c, v),
        Fresnel::Schlick => fresnel_schlick_complement(c, v),
    }
}

/// The material's distribution D.
pub fn microfacet_d(terms: Microfacet, n_dot_h: f64, sin2_nh: f64, m: f64) -> f64 {
    match terms.d {
        Distribution::Beckmann => d_beckmann(n_dot_h, sin2_nh, m),
        Distribution::Ggx => d_ggx(n_dot_h, sin2_nh, m),
        Distribution::BlinnPhong => d_blinn_phong(n_dot_h, sin2_nh, m),
    }
}

/// The material's masking G; Smith's forms use the Λ of the material's D.
pub fn microfacet_g(terms: Microfacet, n_dot_h: f64, n_dot_v: f64, n_dot_l: f64, v_dot_h: f64, m: f64) -> f64 {
    match terms.g {
        Masking::VGroove => g_cook_torrance(n_dot_h, n_dot_v, n_dot_l, v_dot_h),
        Masking::Smith => g_smith_separable(terms.d, n_dot_v, n_dot_l, m),
        Masking::SmithCorrelated => g_smith_correlated(terms.d, n_dot_v, n_dot_l, m),
    }
}

/// The material's Fresnel factor F at `c` = V·H, per channel of `v_index`.
pub fn microfacet_f(terms: Microfacet, c: f64, v_index: [f64; 3]) -> [f64; 3] {
    match terms.f {
        Fresnel::Exact => v_index.map(|v| fresnel_dielectric(c, v)),
        Fresnel::Schlick => v_index.map(|v| fresnel_schlick(c, v)),
    }
}

/// docs/model.md §5: the share of a light's diffuse that the dielectric layer above it passes,
/// glTF 2.0's `fresnel_mix`: `1 − w·F(V·H)`, F being the material's Fresnel term at the layer's
/// normal-incidence reflectance `f0` (through its index, as μ's) and `w` the layer's weight
/// (`KHR_materials_specular`'s factor, 1 without it). H is the half vector of `l` and `v`.
/// It is summed as `(1 − w) + w·(1 − F)` from `1 − F` itself, which keeps its precision where F → 1.
pub fn fresnel_mix_weight(terms: Microfacet, n: DVec3, v: DVec3, l: DVec3, f0: f64, w: f64) -> f64 {
    let h = safe_normalize(l + v, n);
    let t = microfacet_f_complement(terms, v.dot(h).clamp(0.0, 1.0), fresnel_v_from_mu(f0));
    let w = w.clamp(0.0, 1.0);
    (1.0 - w) + w * t
}

/// docs/model.md §5: the Cook–Torrance form as it enters the sum, `π ρ_s (N·L) = F·D·G/(N·V)`,
/// with the material's D, G and F, per colour channel (`v` per channel). Multiplying by π keeps it
/// on the scale of the chapter's diffuse term `r_d·C·(N·L)`, which has no 1/π. `ms_e` is the
/// lobe's albedo E for the compensation (`multiscatter.rs`); 1 (nothing to put back) without it.
pub fn specular_microfacet(
    n: DVec3,
    v: DVec3,
    l: DVec3,
    m: f64,
    v_index: [f64; 3],
    terms: Microfacet,
    ms_e: f64,
) -> [f64; 3] {
    let n_dot_l = n.dot(l);
    let n_dot_v = n.dot(v);
    if n_dot_l <= 0.0 || n_dot_v <= 0.0 {
        return [0.0; 3];
    }
    let h = safe_normalize(l + v, n);
    let n_dot_h = n.dot(h);
    let v_dot_h = v.dot(h).clamp(0.0, 1.0);
    let d = microfacet_d(terms, n_dot_h, n.cross(h).length_squared(), m);
    let g = microfacet_g(terms, n_dot_h, n_dot_v, n_dot_l, v_dot_h, m);
    let k = d * g / n_dot_v.max(N_DOT_V_MIN);
    let comp = super::multiscatter::ms_compensation(ms_e, v_index);
    let f = microfacet_f(terms, v_dot_h, v_index);
    std::array::from_fn(|c| f[c] * k * comp[c])
}

#[cfg(test)]
#[path = "microfacet_tests.rs"]
mod tests;
