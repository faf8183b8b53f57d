// The environment's sweep kernel. It evaluates the environment's functions of environment.wgsl
// and occlusion.wgsl — the files the renderer uses, with the globals and bindings they read,
// concatenated before this one — for one combination of inputs per invocation, one environment
// and occlusion grid per dispatch, bound in group 0 as the renderer binds them. Its columns
// (ENV_SWEEP_OUTPUTS, ENV_COL_…) are generated from crates/shadelab-render/src/sweep/environment.rs
// and put before it.

struct EnvSweepCounts {
    geometry: u32,
    m: u32,
    mu: u32,
    d: u32,
    total: u32,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
    // The occlusion grid's point of departure: the occlusion column reads the grid at centre + l·d.
    centre: vec4<f32>,
}

// Group 1 past the object's and the material textures' bindings (0 to 10), none of which the
// kernel reads.
@group(1) @binding(11) var<uniform> env_counts: EnvSweepCounts;
// Rows: geometry (n, v, l) × count, then m (x), μ (xyz), d (x).
@group(1) @binding(12) var<storage, read> env_table: array<vec4<f32>>;
@group(1) @binding(13) var<storage, read_write> env_outputs: array<f32>;

@compute @workgroup_size(64)
fn sweep_environment(@builtin(global_invocation_id) gid: vec3<u32>) {
    let idx = gid.x;
    if (idx >= env_counts.total) {
        return;
    }
    var rest = idx;
    let di = rest % env_counts.d;
    rest /= env_counts.d;
    let ui = rest % env_counts.mu;
    rest /= env_counts.mu;
    let mi = rest % env_counts.m;
    let gi = rest / env_counts.m;
    let n_raw = env_table[gi * 3u].xyz;
    let v = env_table[gi * 3u + 1u].xyz;
    let l = env_table[gi * 3u + 2u].xyz;
    let o = env_counts.geometry * 3u;
    let m = env_table[o + mi].x;
    let mu = env_table[o + env_counts.m + ui].xyz;
    let d = env_table[o + env_counts.m + env_counts.mu + di].x;
    let n = safe_normalize(n_raw, v);
    let v_index = fresnel_v_from_mu(mu);

    let base = idx * ENV_SWEEP_OUTPUTS;
    env_put_rgb(base + ENV_COL_SH_RADIANCE, env_sh_radiance(n));
    // Level 0 along the eye's ray −V, as the background reads it; the split sum's lookup toward
    // N's mirror of V.
    env_put_rgb(base + ENV_COL_LEVEL_SAMPLE, env_level_sample(0u, -v));
    let r = safe_normalize(n * (2.0 * dot(n, v)) - v, n);
    env_put_rgb(base + ENV_COL_PREFILTERED, env_prefiltered(r, m));
    // B of every D × G pair, in the table's order (d·MASKING_COUNT + g).
    for (var pair = 0u; pair < MS_PAIRS; pair++) {
        let terms = (pair / MASKING_COUNT) | ((pair % MASKING_COUNT) << MICROFACET_FIELD_BITS);
        env_outputs[base + ENV_COL_SPLIT_B + pair] = env_split_b(terms, dot(n, v), m);
    }
    env_put_rgb(base + ENV_COL_SPECULAR, env_specular(n, v, m, MICROFACET_CHAPTER, v_index));
    env_put_rgb(base + ENV_COL_SPECULAR + 3u, env_specular(n, v, m, MICROFACET_GLTF, v_index));
    env_outputs[base + ENV_COL_OCCLUSION] = env_occlusion(env_counts.centre.xyz + l * d, n);
    env_area_ltc(base, n, v, l * d, m);
}

// The area lights' LTC (ltc.wgsl) for each shape at `to` from the point, facing it, half as
// wide as far, and every D: its share of π·E·d²/A_emit (E = 1), in [0, 1]; 0 at the point limit.
fn env_area_ltc(base: u32, n: vec3<f32>, v: vec3<f32>, to: vec3<f32>, m: f32) {
    let d = length(to);
    var area: Light;
    area.position = vec4(to, 1.0);
    area.normal = vec4(-safe_normalize(to, n), 0.0);
    area.tangent = vec4(any_tangent(area.normal.xyz), 0.0);
    area.half_x = 0.5 * d;
    for (var k = 0u; k < 3u; k++) {
        area.kind = LIGHT_RECT + k;
        area.half_y = select(area.half_x, area.half_x * DISK_POLYGON_SCALE, area.kind == LIGHT_DISK);
        for (var dk = 0u; dk < DISTRIBUTION_COUNT; dk++) {
            let s = area_specular_ltc(area, vec3(0.0), n, v, ltc_matrix(dk, dot(n, v), m), 1.0);
            let share = select(0.0, s * emitting_area(area) / (AREA_PI * d * d), s > 0.0);
            env_outputs[base + ENV_COL_AREA_LTC + k * DISTRIBUTION_COUNT + dk] = share;
        }
    }
}

// A colour's three channels into consecutive outputs from `at`.
fn env_put_rgb(at: u32, c: vec3<f32>) {
    env_outputs[at] = c.x;
    env_outputs[at + 1u] = c.y;
    env_outputs[at + 2u] = c.z;
}
