// The lobe's albedo E from the project's table (tables.ms_albedo, ms_table.rs's ms_table):
// per D × G pair, MS_TABLE_SIDE × MS_TABLE_SIDE nodes over N·V (across) and m (down), each in
// [0, 1], read bilinearly; and the LTC table's M⁻¹ (tables.ltc) for ltc.wgsl. Only with the
// multiple-scattering effect, the environment's split sum or the LTC specular (the whole file is
// one #if).
// The f64 twins are crates/shadelab-model/src/lighting/ms_table.rs and ltc.rs (the LTC lookup).

#if EFFECT_MULTIPLE_SCATTERING||EFFECT_ENVIRONMENT_SPECULAR||EFFECT_AREA_LTC

// One node of pair `base`'s table: row j (m), column i (N·V).
fn ms_node(base: u32, j: u32, i: u32) -> f32 {
    let k = base + j * MS_TABLE_SIDE + i;
    return tables.ms_albedo[k / 4u][k % 4u];
}

// Where (n_dot_v, m) falls in a D × G pair's table (the E table and the split sum's B share its
// layout): the pair's first node, the cell's corner (j down in m, i across in N·V), both clamped
// to [0, 1], and the fractions inside the cell.
struct TableCell {
    base: u32,
    j: u32,
    i: u32,
    fw: f32,
    fu: f32,
}

fn table_cell(terms: u32, n_dot_v: f32, m: f32) -> TableCell {
    let d = terms & MICROFACET_FIELD_MASK;
    let g = (terms >> MICROFACET_FIELD_BITS) & MICROFACET_FIELD_MASK;
    let base = (d * MASKING_COUNT + g) * MS_TABLE_SIDE * MS_TABLE_SIDE;
    let last = f32(MS_TABLE_SIDE - 1u);
    let u = clamp(n_dot_v, 0.0, 1.0) * last;
    let w = clamp(m, 0.0, 1.0) * last;
    let i = min(u32(floor(u)), MS_TABLE_SIDE - 2u);
    let j = min(u32(floor(w)), MS_TABLE_SIDE - 2u);
    return TableCell(base, j, i, w - f32(j), u - f32(i));
}

// Bilinear between a cell's four nodes: `low` the row at j (i, i + 1), `high` the row at j + 1.
fn table_bilinear(c: TableCell, low: vec2<f32>, high: vec2<f32>) -> f32 {
    let l = low.x * (1.0 - c.fu) + low.y * c.fu;
    let h = high.x * (1.0 - c.fu) + high.y * c.fu;
    return l * (1.0 - c.fw) + h * c.fw;
}

// docs/microfacet.md: E of the material's D and G (`terms`) at `n_dot_v` and `m`, both clamped to
// [0, 1], bilinear between the table's nodes.
fn ms_albedo(terms: u32, n_dot_v: f32, m: f32) -> f32 {
    let c = table_cell(terms, n_dot_v, m);
    let low = vec2(ms_node(c.base, c.j, c.i), ms_node(c.base, c.j, c.i + 1u));
    let high = vec2(ms_node(c.base, c.j + 1u, c.i), ms_node(c.base, c.j + 1u, c.i + 1u));
    return table_bilinear(c, low, high);
}
#if EFFECT_AREA_LTC

// Where (n_dot_v, m) falls in D `d`'s LTC table: across at √(1 − N·V), down at √m, both clamped
// to [0, 1] (ltc.rs's LTC_TABLE_SIDE nodes a side).
fn ltc_cell(d: u32, n_dot_v: f32, m: f32) -> TableCell {
    let last = f32(LTC_TABLE_SIDE - 1u);
    let u = sqrt(1.0 - clamp(n_dot_v, 0.0, 1.0)) * last;
    let w = sqrt(clamp(m, 0.0, 1.0)) * last;
    let i = min(u32(floor(u)), LTC_TABLE_SIDE - 2u);
    let j = min(u32(floor(w)), LTC_TABLE_SIDE - 2u);
    return TableCell(d * LTC_TABLE_SIDE * LTC_TABLE_SIDE, j, i, w - f32(j), u - f32(i));
}

// One node of the LTC table, [a, b, c, d] of M⁻¹'s rows (a, 0, b), (0, 1, 0), (c, 0, d).
fn ltc_node(base: u32, j: u32, i: u32) -> vec4<f32> {
    return tables.ltc[base + j * LTC_TABLE_SIDE + i];
}

// M⁻¹ of the material's D at n_dot_v and m, each entry bilinear between the nodes, in the frame
// (T, N × T, N) with T the view's tangent.
fn ltc_matrix(d: u32, n_dot_v: f32, m: f32) -> mat3x3<f32> {
    let c = ltc_cell(d, n_dot_v, m);
    let n00 = ltc_node(c.base, c.j, c.i);
    let n01 = ltc_node(c.base, c.j, c.i + 1u);
    let n10 = ltc_node(c.base, c.j + 1u, c.i);
    let n11 = ltc_node(c.base, c.j + 1u, c.i + 1u);
    var e = vec4(0.0);
    for (var k = 0u; k < 4u; k++) {
        e[k] = table_bilinear(c, vec2(n00[k], n01[k]), vec2(n10[k], n11[k]));
    }
    return mat3x3(vec3(e.x, 0.0, e.z), vec3(0.0, 1.0, 0.0), vec3(e.y, 0.0, e.w));
}
#endif
#endif
