//! Material presets: reflectance at normal incidence `μ` per channel (linear RGB).
//!
//! Metals: Filament's table "Reflectance at normal incidence of common metals" (Romain Guy,
//! Mathias Agopian, *Physically Based Rendering in Filament*, section 4.8.3.2). Dielectrics:
//! `μ = ((n − 1)/(n + 1))²` with the refractive index `n` given (water 1.33, glass 1.5,
//! plastic 1.5), which is the inverse of the chapter's `v = (1 + √μ)/(1 − √μ)`.

/// A named μ with its source, and a base colour that suits it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaterialPreset {
    pub name: &'static str,
    pub mu: [f64; 3],
    pub color: [f64; 3],
    /// Metals reflect almost nothing diffusely.
    pub metal: bool,
    pub source: &'static str,
}

const FILAMENT: &str = "Filament, PBR in Filament §4.8.3.2";

/// μ of a dielectric with refractive index `n` (docs/model.md §5, the inverse of v(μ)).
pub fn mu_from_ior(n: f64) -> f64 {
    ((n - 1.0) / (n + 1.0)).powi(2)
}

/// A metal of Filament's table: its colour is its μ.
const fn metal(name: &'static str, mu: [f64; 3]) -> MaterialPreset {
    MaterialPreset { name, mu, color: mu, metal: true, source: FILAMENT }
}

pub const PRESETS: [MaterialPreset; 8] = [
    metal("gold", [1.000, 0.766, 0.336]),
    metal("silver", [0.972, 0.960, 0.915]),
    metal("copper", [0.955, 0.637, 0.538]),
    metal("aluminium", [0.913, 0.922, 0.924]),
    metal("iron", [0.560, 0.570, 0.580]),
    // ((1.5 − 1)/(1.5 + 1))² = 0.04
    MaterialPreset { name: "glass", mu: [0.04; 3], color: [0.9, 0.95, 0.95], metal: false, source: "n = 1.5" },
    // ((1.33 − 1)/(1.33 + 1))² ≈ 0.02
    MaterialPreset { name: "water", mu: [0.02; 3], color: [0.2, 0.4, 0.6], metal: false, source: "n = 1.33" },
    MaterialPreset { name: "plastic", mu: [0.04; 3], color: [0.75, 0.12, 0.08], metal: false, source: "n ≈ 1.5" },
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dielectric_presets_follow_their_index() {
        for p in PRESETS.iter().filter(|p| !p.metal) {
            let n: f64 = p.source.trim_start_matches("n ≈ ").trim_start_matches("n = ").parse().unwrap();
            assert!((p.mu[0] - mu_from_ior(n)).abs() < 1e-3, "{}", p.name);
            // and v(μ) gives the index back
            assert!((crate::lighting::brdf::fresnel_v_from_mu(mu_from_ior(n)) - n).abs() < 1e-9);
        }
    }
}
