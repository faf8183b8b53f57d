// The multiple-scattering compensation of the microfacet lobe (docs/microfacet.md): Turquin's
// 1 + F0·(1 − E)/E as Filament uses it, E the single-scatter lobe's albedo with F = 1, which
// ms_albedo (ms_table.wgsl) reads from the project's table. The f64 twin is
// crates/shadelab-model/src/lighting/multiscatter.rs.

// docs/microfacet.md: the compensation per channel, F0 = ((v − 1)/(v + 1))² of each channel's
// index (μ for the specular's v), E clamped to [MS_ALBEDO_MIN, 1] (E = 1 puts nothing back).
fn ms_compensation(e_in: f32, v_index: vec3<f32>) -> vec3<f32> {
    let e = clamp(e_in, MS_ALBEDO_MIN, 1.0);
    let v = max(v_index, vec3(0.0));
    let r = (v - 1.0) / (v + 1.0);
    return 1.0 + r * r * (1.0 - e) / e;
}
