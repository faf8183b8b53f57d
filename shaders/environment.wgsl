// An environment's diffuse light from nine spherical-harmonic coefficients (globals.env_sh,
// written by environment.rs's sh_project; Ramamoorthi and Hanrahan): E(n)/π, in the unit of the
// chapter's I_a; and its specular by the split sum, from the prefiltered levels in env_levels
// (bindings.wgsl). Each part only with its effect. The f64 twin is
// crates/shadelab-model/src/lighting/environment.rs.

#if EFFECT_ENVIRONMENT_SH
// The real SH basis's factors: 1/(2√π), √(3/(4π)), √(15/(4π)), √(5/(16π)), √(15/(16π)).
const SH_Y0: f32 = 0.2820947918;
const SH_Y1: f32 = 0.4886025119;
const SH_Y2: f32 = 1.0925484306;
const SH_Y20: f32 = 0.3153915653;
const SH_Y22: f32 = 0.5462742153;

// E(n)/π at unit n: the basis at n weighed by the coefficients (already scaled by the clamped
// cosine's band weights); a negative sum (ringing behind a bright source) is 0.
fn env_sh_radiance(n: vec3<f32>) -> vec3<f32> {
    let x = n.x;
    let y = n.y;
    let z = n.z;
    var e = globals.env_sh[0].rgb * SH_Y0;
    e += globals.env_sh[1].rgb * (SH_Y1 * y) + globals.env_sh[2].rgb * (SH_Y1 * z) + globals.env_sh[3].rgb * (SH_Y1 * x);
    e += globals.env_sh[4].rgb * (SH_Y2 * x * z) + globals.env_sh[5].rgb * (SH_Y2 * y * z);
    e += globals.env_sh[6].rgb * (SH_Y20 * (3.0 * y * y - 1.0));
    e += globals.env_sh[7].rgb * (SH_Y2 * x * y) + globals.env_sh[8].rgb * (SH_Y22 * (x * x - z * z));
    return max(e, vec3(0.0));
}
#endif

#if EFFECT_ENVIRONMENT_SPECULAR||EFFECT_ENVIRONMENT_BACKGROUND
// The prefiltered environment's levels (read by the split sum, and level 0 by the background): level k blurred for roughness k/(ENV_LEVELS − 1), level
// 0 ENV_LEVEL_WIDTH texels wide and half as high, every second level halving both.
const ENV_LEVELS: u32 = 6u;
const ENV_LEVEL_WIDTH: u32 = 64u;
// 1/(2π) and 1/π: turns and half turns from radians.
const ENV_INV_TAU: f32 = 0.15915494;
const ENV_INV_PI: f32 = 0.31830989;

fn env_level_size(k: u32) -> vec2<u32> {
    let w = ENV_LEVEL_WIDTH >> (k / 2u);
    return vec2(w, w / 2u);
}

fn env_level_offset(k: u32) -> u32 {
    var o = 0u;
    for (var j = 0u; j < k; j++) {
        let s = env_level_size(j);
        o += s.x * s.y;
    }
    return o;
}

// Texel (x, y) of level k: x wraps around, y clamps at the poles.
fn env_texel(k: u32, x: i32, y: i32) -> vec3<f32> {
    let s = env_level_size(k);
    let w = i32(s.x);
    let xi = u32(((x % w) + w) % w);
    let yi = u32(clamp(y, 0, i32(s.y) - 1));
    return env_levels[env_level_offset(k) + yi * s.x + xi].rgb;
}

// Level k toward unit world direction d, bilinear between texel centres.
fn env_level_sample(k: u32, d: vec3<f32>) -> vec3<f32> {
    let s = vec2<f32>(env_level_size(k));
    let turns = atan2(d.z, d.x) * ENV_INV_TAU;
    let u = (turns - floor(turns)) * s.x - 0.5;
    // The angle from +y as atan2 of (√(x² + z²), y), not acos(y): accurate at every angle (the
    // environment's sweep found a GPU acos 2e-5 rad off), and defined near the poles.
    let v = atan2(length(d.xz), d.y) * ENV_INV_PI * s.y - 0.5;
    let x0 = floor(u);
    let y0 = floor(v);
    let fu = u - x0;
    let fv = v - y0;
    let xi = i32(x0);
    let yi = i32(y0);
    let top = env_texel(k, xi, yi) * (1.0 - fu) + env_texel(k, xi + 1, yi) * fu;
    let bottom = env_texel(k, xi, yi + 1) * (1.0 - fu) + env_texel(k, xi + 1, yi + 1) * fu;
    return top * (1.0 - fv) + bottom * fv;
}
#endif

#if EFFECT_ENVIRONMENT_SPECULAR

// The prefiltered environment toward r for roughness m (clamped to [0, 1]), linear between the
// two levels around it.
fn env_prefiltered(r: vec3<f32>, m: f32) -> vec3<f32> {
    let t = clamp(m, 0.0, 1.0) * f32(ENV_LEVELS - 1u);
    let k = min(u32(floor(t)), ENV_LEVELS - 2u);
    let f = t - f32(k);
    return env_level_sample(k, r) * (1.0 - f) + env_level_sample(k + 1u, r) * f;
}

// One node of the B table (tables.env_split_b, laid out as the compensation's E table).
fn env_split_b_node(base: u32, j: u32, i: u32) -> f32 {
    let k = base + j * MS_TABLE_SIDE + i;
    return tables.env_split_b[k / 4u][k % 4u];
}

// B, the share of the lobe's albedo Schlick's F adds toward grazing, of the material's D and G
// at n_dot_v and m, bilinear between the nodes as the E table.
fn env_split_b(terms: u32, n_dot_v: f32, m: f32) -> f32 {
    let c = table_cell(terms, n_dot_v, m);
    let low = vec2(env_split_b_node(c.base, c.j, c.i), env_split_b_node(c.base, c.j, c.i + 1u));
    let high = vec2(env_split_b_node(c.base, c.j + 1u, c.i), env_split_b_node(c.base, c.j + 1u, c.i + 1u));
    return table_bilinear(c, low, high);
}

// The split sum before r_s: the prefiltered environment toward the mirror direction, times
// F0·(E − B) + B: E the lobe's albedo for the material's D and G at N·V (ms_table.wgsl), B its
// share toward grazing, F0 the material's F at normal incidence.
fn env_specular(n: vec3<f32>, v: vec3<f32>, m: f32, terms: u32, v_index: vec3<f32>) -> vec3<f32> {
    let n_dot_v = dot(n, v);
    if (n_dot_v <= 0.0) {
        return vec3(0.0);
    }
    let r = safe_normalize(n * (2.0 * n_dot_v) - v, n);
    let e = ms_albedo(terms, n_dot_v, m);
    let b = env_split_b(terms, n_dot_v, m);
    return env_prefiltered(r, m) * (microfacet_f(terms, 1.0, v_index) * (e - b) + b);
}
#endif
