//! The twin of `shaders/multiscatter.wgsl`: the multiple-scattering compensation of the
//! microfacet lobe (docs/microfacet.md), Turquin's form as Filament uses it: the single-scatter
//! lobe times `1 + F0·(1 − E)/E`, E its directional albedo with F = 1 for the material's D and G
//! at `N·V` and m (`ms_table.rs`). A single-scatter lobe drops the light that bounces between
//! facets; E says how much, and the factor puts it back, coloured by F0 as the bounces are.

use crate::guards::MS_ALBEDO_MIN;

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

    /// F0 = 0 puts nothing back; E is floored, so the factor stays finite at E = 0.
    #[test]
    fn the_compensation_is_one_without_f0_and_bounded() {
        assert_eq!(ms_compensation(0.3, [1.0; 3]), [1.0; 3]);
        assert!(ms_compensation(0.0, [1e9; 3])[0] <= 1.0 / MS_ALBEDO_MIN);
    }
}
