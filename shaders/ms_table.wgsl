// The lobe's albedo E from the project's table (tables.ms_albedo, multiscatter.rs's ms_table):
// per D × G pair, MS_TABLE_SIDE × MS_TABLE_SIDE nodes over N·V (across) and m (down), each in
// [0, 1], read bilinearly. Only with the multiple-scattering effect or the environment's split sum
// (the whole file is one #if).
// The f64 twin is crates/shadelab-model/src/lighting/multiscatter.rs.

#if EFFECT_MULTIPLE_SCATTERING||EFFECT_ENVIRONMENT_SPECULAR

// One node of pair `base`'s table: row j (m), column i (N·V).
fn ms_node(base: u32, j: u32, i: u32) -> f32 {
    let k = base + j * MS_TABLE_SIDE + i;
    return tables.ms_albedo[k / 4u][k % 4u];
}

// docs/microfacet.md: E of the material's D and G (`terms`) at `n_dot_v` and `m`, both clamped to
// [0, 1], bilinear between the table's nodes.
fn ms_albedo(terms: u32, n_dot_v: f32, m: f32) -> f32 {
    let d = terms & MICROFACET_FIELD_MASK;
    let g = (terms >> MICROFACET_FIELD_BITS) & MICROFACET_FIELD_MASK;
    let base = (d * MASKING_COUNT + g) * MS_TABLE_SIDE * MS_TABLE_SIDE;
    let last = f32(MS_TABLE_SIDE - 1u);
    let u = clamp(n_dot_v, 0.0, 1.0) * last;
    let w = clamp(m, 0.0, 1.0) * last;
    let i = min(u32(floor(u)), MS_TABLE_SIDE - 2u);
    let j = min(u32(floor(w)), MS_TABLE_SIDE - 2u);
    let fu = u - f32(i);
    let fw = w - f32(j);
    let low = ms_node(base, j, i) * (1.0 - fu) + ms_node(base, j, i + 1u) * fu;
    let high = ms_node(base, j + 1u, i) * (1.0 - fu) + ms_node(base, j + 1u, i + 1u) * fu;
    return low * (1.0 - fw) + high * fw;
}
#endif
