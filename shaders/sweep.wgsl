// The stability sweep's kernel. It evaluates the lighting terms of brdf.wgsl and lights.wgsl —
// the files the renderer uses, concatenated before this one — for one combination of inputs per
// invocation, so that the sweep tests exactly what ships.

struct SweepCounts {
    geometry: u32,
    m: u32,
    h: u32,
    mu: u32,
    d: u32,
    alpha: u32,
    total: u32,
    // Index of the first m row in `table` (geometry rows come first, 3 per entry).
    m_offset: u32,
}

// Material used for the per-light contribution.
const SWEEP_COLOR: vec3<f32> = vec3(0.8, 0.5, 0.2);
// Floats written per combination.
const SWEEP_OUTPUTS: u32 = 20u;
// Spot cones: the outer half-angle is m·SWEEP_CONE_PER_M (m in [0, 1] spans 0 to 90°), the inner
// one the share min(α, 1) of it (α ≥ 1: inner = outer, the SPOT_COS_SPAN_MIN guard's case).
const SWEEP_CONE_PER_M: f32 = 1.5707964;

@group(0) @binding(0) var<uniform> counts: SweepCounts;
// Rows: geometry (n, v, l) × count, then m (x), h (x = h, y = 1 for mirror), μ (xyz), d (x),
// α (x = α, y = d0 of the linear falloff).
@group(0) @binding(1) var<storage, read> table: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> outputs: array<f32>;

@compute @workgroup_size(64)
fn sweep(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let idx = gid.x + gid.y * groups.x * 64u;
    if (idx >= counts.total) {
        return;
    }
    var rest = idx;
    let ai = rest % counts.alpha;
    rest /= counts.alpha;
    let di = rest % counts.d;
    rest /= counts.d;
    let ui = rest % counts.mu;
    rest /= counts.mu;
    let hi = rest % counts.h;
    rest /= counts.h;
    let mi = rest % counts.m;
    let gi = rest / counts.m;

    let n_raw = table[gi * 3u].xyz;
    let v = table[gi * 3u + 1u].xyz;
    let l = table[gi * 3u + 2u].xyz;
    let o = counts.m_offset;
    let m = table[o + mi].x;
    let h_row = table[o + counts.m + hi];
    let mu = table[o + counts.m + counts.h + ui].xyz;
    let d = table[o + counts.m + counts.h + counts.mu + di].x;
    let a_row = table[o + counts.m + counts.h + counts.mu + counts.d + ai];

    let n = safe_normalize(n_raw, v);
    let half = safe_normalize(l + v, n);
    let r = 2.0 * dot(n, l) * n - l;
    let v_index = fresnel_v_from_mu(mu);
    let mirror = h_row.y > 0.5;

    var light: Light;
    light.position = vec4(l * d, 1.0);
    light.direction = vec4(-l, 0.0);
    light.radiance = vec4(1.0);
    light.kind = LIGHT_POINT;
    light.falloff_alpha = a_row.x;
    light.d0 = a_row.y;
    light.falloff_form = FALLOFF_QUADRATIC;
    let quadratic = light_sample(light, vec3(0.0), n);
    light.falloff_form = FALLOFF_LINEAR;
    let linear = light_sample(light, vec3(0.0), n);

    let f = f_fresnel_exact(dot(v, half), v_index);
    let ct = specular_cook_torrance(n, v, l, m, v_index);
    let c_phong = light_contribution(quadratic, n, v, SWEEP_COLOR, 1.0, 1.0, m, h_row.x, mirror, v_index, SPECULAR_PHONG);
    let c_ct = light_contribution(linear, n, v, SWEEP_COLOR, 1.0, 1.0, m, h_row.x, mirror, v_index, SPECULAR_COOK_TORRANCE);

    let base = idx * SWEEP_OUTPUTS;
    outputs[base + 0u] = diffuse_lambert(dot(n, l));
    outputs[base + 1u] = specular_phong(dot(v, r), h_row.x, mirror);
    let n_x_h = cross(n, half);
    outputs[base + 2u] = d_beckmann(dot(n, half), dot(n_x_h, n_x_h), m);
    outputs[base + 3u] = g_cook_torrance(dot(n, half), dot(n, v), dot(n, l), dot(v, half));
    outputs[base + 4u] = f.x;
    outputs[base + 5u] = f.y;
    outputs[base + 6u] = f.z;
    outputs[base + 7u] = ct.x;
    outputs[base + 8u] = ct.y;
    outputs[base + 9u] = ct.z;
    outputs[base + 10u] = falloff_quadratic(d, a_row.x);
    outputs[base + 11u] = falloff_linear(d, a_row.y);
    outputs[base + 12u] = c_phong.x;
    outputs[base + 13u] = c_phong.y;
    outputs[base + 14u] = c_phong.z;
    outputs[base + 15u] = c_ct.x;
    outputs[base + 16u] = c_ct.y;
    outputs[base + 17u] = c_ct.z;
    // The spot cone at the angle between V and L; the range window at distance d with range d0.
    let outer = m * SWEEP_CONE_PER_M;
    let inner = outer * min(a_row.x, 1.0);
    outputs[base + 18u] = spot_cone(dot(v, l), cos(inner), cos(outer));
    outputs[base + 19u] = window_range(d, a_row.y);
}
