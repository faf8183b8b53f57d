// The stability sweep's kernel. It evaluates the lighting terms of brdf.wgsl and lights.wgsl —
// the files the renderer uses, concatenated before this one — for one combination of inputs per
// invocation, so that the sweep tests exactly what ships. Its output columns (SWEEP_OUTPUTS,
// COL_…) and the inputs it shares with the f64 side are generated from
// crates/shadelab-render/src/sweep/columns.rs and put before it.

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
    // Shadow projections, 5 rows each after the α rows: the matrix's columns, then
    // (texel_world, perspective).
    shadow: u32,
    // This dispatch's combinations: `chunk` of them from `first` (the outputs are bound from
    // there, so one binding stays within the device's limit).
    first: u32,
    chunk: u32,
    _pad: u32,
}

// SWEEP_COLOR, the material's colour in the per-light contribution, and SWEEP_CONE_PER_M come
// with the columns. Spot cones: the outer half-angle is m·SWEEP_CONE_PER_M (m in [0, 1] spans 0 to
// 90°), the inner one the share min(α, 1) of it (α ≥ 1: inner = outer, the SPOT_COS_SPAN_MIN
// guard's case).

@group(0) @binding(0) var<uniform> counts: SweepCounts;
// Rows: geometry (n, v, l) × count, then m (x), h (x = h, y = 1 for mirror), μ (xyz), d (x),
// α (x = α, y = d0 of the linear falloff), the shadow projections.
@group(0) @binding(1) var<storage, read> table: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> outputs: array<f32>;

// One combination's inputs as the column groups read them: n is n_raw normalized, h_row holds
// (h, mirror), a_row (α, d0), v_index is Fresnel's v of each channel of μ.
struct SweepCombination {
    n_raw: vec3<f32>,
    n: vec3<f32>,
    v: vec3<f32>,
    l: vec3<f32>,
    m: f32,
    h_row: vec4<f32>,
    mu: vec3<f32>,
    v_index: vec3<f32>,
    d: f32,
    a_row: vec4<f32>,
}

@compute @workgroup_size(64)
fn sweep(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let local = gid.x + gid.y * groups.x * 64u;
    let idx = counts.first + local;
    if (local >= counts.chunk || idx >= counts.total) {
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

    var inp: SweepCombination;
    inp.n_raw = table[gi * 3u].xyz;
    inp.v = table[gi * 3u + 1u].xyz;
    inp.l = table[gi * 3u + 2u].xyz;
    let o = counts.m_offset;
    inp.m = table[o + mi].x;
    inp.h_row = table[o + counts.m + hi];
    inp.mu = table[o + counts.m + counts.h + ui].xyz;
    inp.d = table[o + counts.m + counts.h + counts.mu + di].x;
    inp.a_row = table[o + counts.m + counts.h + counts.mu + counts.d + ai];
    inp.n = safe_normalize(inp.n_raw, inp.v);
    inp.v_index = fresnel_v_from_mu(inp.mu);
    // The shadow case: (geometry + m index) of the projections, 5 rows each.
    let so = o + counts.m + counts.h + counts.mu + counts.d + counts.alpha + ((gi + mi) % counts.shadow) * 5u;

    // The column groups in column order, as the f64 reference writes them.
    let base = local * SWEEP_OUTPUTS;
    light_columns(base, inp);
    microfacet_columns(base, inp);
    shadow_map_columns(base, inp, so);
    surface_map_columns(base, inp);
    area_columns(base, inp);
    transmission_columns(base, inp);
    pcss_columns(base, inp);
}

// The microfacet terms beyond the chapter's: every D and Smith's G on each D's Λ, Schlick's F and
// the glTF preset's whole specular.
fn microfacet_columns(base: u32, inp: SweepCombination) {
    let n = inp.n;
    let v = inp.v;
    let l = inp.l;
    let m = inp.m;
    let half = safe_normalize(l + v, n);
    let n_x_h = cross(n, half);
    let nv = dot(n, v);
    let nl = dot(n, l);
    // Every D of the term table and its Smith G, each at its code's channel.
    for (var d = 0u; d < DISTRIBUTION_COUNT; d++) {
        outputs[base + COL_MICROFACET_D + d] = microfacet_d(d, dot(n, half), dot(n_x_h, n_x_h), m);
        outputs[base + COL_G_SMITH_SEPARABLE + d] = g_smith_separable(d, nv, nl, m);
        outputs[base + COL_G_SMITH_CORRELATED + d] = g_smith_correlated(d, nv, nl, m);
    }
    put_rgb(base + COL_MICROFACET_F_SCHLICK, microfacet_f(MICROFACET_GLTF, dot(v, half), inp.v_index));
    put_rgb(base + COL_SPECULAR_MICROFACET_GLTF, specular_microfacet(n, v, l, m, inp.v_index, MICROFACET_GLTF, 1.0));
    // The compensation over E = m (0 to 1, the floor at 0 included).
    put_rgb(base + COL_MS_COMPENSATION, ms_compensation(m, inp.v_index));
    outputs[base + COL_FRESNEL_MIX_WEIGHT] = fresnel_mix_weight(MICROFACET_GLTF, n, v, l, inp.mu.x, 1.0);
    outputs[base + COL_FRESNEL_MIX_WEIGHT + 1u] = fresnel_mix_weight(MICROFACET_CHAPTER, n, v, l, inp.mu.x, 1.0);
}

// The BRDF, falloff, per-light contribution, other-model and spot-and-window columns.
fn light_columns(base: u32, inp: SweepCombination) {
    let n = inp.n;
    let v = inp.v;
    let l = inp.l;
    let m = inp.m;
    let h_row = inp.h_row;
    let v_index = inp.v_index;
    let d = inp.d;
    let a_row = inp.a_row;
    let half = safe_normalize(l + v, n);
    let r = 2.0 * dot(n, l) * n - l;
    let mirror = h_row.y > 0.5;

    var light: Light;
    light.position = vec4(l * d, 1.0);
    light.direction = vec4(-l, 0.0);
    light.radiance = vec4(1.0);
    light.kind = LIGHT_POINT;
    light.falloff_alpha = a_row.x;
    light.d0 = a_row.y;
    light.falloff_form = FALLOFF_QUADRATIC;
    let quadratic = light_sample(light, vec3(0.0), n, v, m);
    light.falloff_form = FALLOFF_LINEAR;
    let linear = light_sample(light, vec3(0.0), n, v, m);

    let f = microfacet_f(MICROFACET_CHAPTER, dot(v, half), v_index);
    let ct = specular_cook_torrance(n, v, l, m, v_index);
    let c_phong = light_contribution(
        quadratic, n, v, SWEEP_COLOR, 1.0, 1.0, m, h_row.x, mirror, v_index, SPECULAR_PHONG, MICROFACET_CHAPTER, false, 1.0, vec2(0.0),
    );
    let c_ct = light_contribution(
        linear, n, v, SWEEP_COLOR, 1.0, 1.0, m, h_row.x, mirror, v_index,
        SPECULAR_COOK_TORRANCE, MICROFACET_CHAPTER, false, 1.0, vec2(0.0),
    );

    outputs[base + COL_DIFFUSE_LAMBERT] = diffuse_lambert(dot(n, l));
    outputs[base + COL_SPECULAR_PHONG] = specular_phong(dot(v, r), h_row.x, mirror);
    outputs[base + COL_PHONG_NORMALIZED] = phong_normalization(h_row.x, mirror) * specular_phong(dot(v, r), h_row.x, mirror);
    let n_x_h = cross(n, half);
    outputs[base + COL_D_BECKMANN] = d_beckmann(dot(n, half), dot(n_x_h, n_x_h), m);
    outputs[base + COL_G_COOK_TORRANCE] = g_cook_torrance(dot(n, half), dot(n, v), dot(n, l), dot(v, half));
    put_rgb(base + COL_MICROFACET_F, f);
    put_rgb(base + COL_SPECULAR_COOK_TORRANCE, ct);
    outputs[base + COL_FALLOFF_QUADRATIC] = falloff_quadratic(d, a_row.x);
    outputs[base + COL_FALLOFF_LINEAR] = falloff_linear(d, a_row.y);
    put_rgb(base + COL_CONTRIBUTION_PHONG, c_phong);
    put_rgb(base + COL_CONTRIBUTION_COOK_TORRANCE, c_ct);
    // The other models at the linear falloff's sample; m in [0, 1] doubles as the share 1 − t.
    let nl = linear.form;
    let nv = dot(n, v);
    put_rgb(base + COL_LAMBERT_RULE_LIT, lambert_rule_lit(SWEEP_COLOR, linear.radiance, nl));
    put_rgb(base + COL_LAMBERT_RULE_FILL, lambert_rule_fill(SWEEP_COLOR, linear.radiance));
    outputs[base + COL_REFLECTED_COS_PHI] = reflected_cos_phi(nl, nv);
    put_rgb(base + COL_SUM_CONTRIBUTION, sum_contribution(linear.radiance, nl, nv, SWEEP_COLOR, 1.0, 1.0));
    put_rgb(base + COL_TRANSMITTED_TERM, transmitted_term(linear.radiance, SWEEP_COLOR, m));
    // The spot cone at the angle between V and L; the range window at distance d with range d0.
    let outer = m * SWEEP_CONE_PER_M;
    let inner = outer * min(a_row.x, 1.0);
    outputs[base + COL_SPOT_CONE] = spot_cone(dot(v, l), cos(inner), cos(outer));
    outputs[base + COL_WINDOW_RANGE] = window_range(d, a_row.y);
}

// The shadow-map columns for the projection at table row `so`: the receiver at l·d with normal
// n moved by the normal offset, as shadow_visibility does (docs/model.md §6).
fn shadow_map_columns(base: u32, inp: SweepCombination, so: u32) {
    let n = inp.n;
    let l = inp.l;
    let d = inp.d;
    let sm = mat4x4(table[so], table[so + 1u], table[so + 2u], table[so + 3u]);
    let s_row = table[so + 4u];
    let to_p = l * d;
    let texel = shadow_texel_world(s_row.x, s_row.y > 0.5, d * dot(n, l));
    outputs[base + COL_SHADOW_FACE] = f32(shadow_face(to_p));
    outputs[base + COL_SHADOW_TEXEL_WORLD] = texel;
    put_rgb(base + COL_SHADOW_MAP_COORD, shadow_map_coord(sm, to_p + n * (SHADOW_NORMAL_OFFSET_TEXELS * texel)));
    outputs[base + COL_SHADOW_ORTHO_TEXEL_WORLD] = shadow_ortho_texel_world(sm, SWEEP_SHADOW_RESOLUTION);
}

// The surface columns: tint, vertex colour, texture coordinates and the material maps.
fn surface_map_columns(base: u32, inp: SweepCombination) {
    let n_raw = inp.n_raw;
    let n = inp.n;
    let v = inp.v;
    let l = inp.l;
    let m = inp.m;
    let h_row = inp.h_row;
    let mu = inp.mu;
    let d = inp.d;
    let a_row = inp.a_row;
    // The surface at a tint of m in every channel, μ's tinted part μ itself (a metal); the raw
    // normal as a vertex colour (outside [0, 1]); d and α as texture coordinates, transformed by
    // the offset (d0, d), a rotation of 4m right angles and the scale (h, d).
    let s = tinted_surface(SWEEP_COLOR, mu, mu, vec3(m));
    put_rgb(base + COL_TINTED_SURFACE_C, s.c);
    put_rgb(base + COL_TINTED_SURFACE_MU, s.mu);
    put_rgb(base + COL_VERTEX_TINT, vertex_tint(n_raw));
    let uv = texture_uv(vec2(d, a_row.x), vec2(a_row.y, d), 4.0 * m * SWEEP_CONE_PER_M, vec2(h_row.x, d));
    put_rgb(base + COL_TEXTURE_UV, vec3(uv, 0.0));
    // The material maps with the raw normal's channels as texels (outside [0, 1]): a metal
    // (μ_t = μ, M·F0 = 0.04·μ) at metal scale x, the roughness m at scale y, r_a = 0.8 occluded by
    // z at strength m, and I_e = μ times the normal as an emissive texel.
    let k = metallic_scaled(SWEEP_COLOR, mu, mu, 0.04 * mu, n_raw.x);
    put_rgb(base + COL_METALLIC_SCALED_C, k.c);
    put_rgb(base + COL_METALLIC_SCALED_MU, k.mu);
    outputs[base + COL_ROUGHNESS_SCALED] = roughness_scaled(m, n_raw.y);
    outputs[base + COL_PHONG_H_FROM_M] = phong_h_from_m(m);
    outputs[base + COL_OCCLUDED] = occluded(0.8, n_raw.z, m);
    put_rgb(base + COL_EMITTED, emitted(mu, n_raw));
    // N turned by the raw normal as a texel in the frame of L as tangent (along N at normal
    // incidence: no frame), its sign from V·L, scale h.
    let w = select(1.0, -1.0, dot(v, l) < 0.0);
    put_rgb(base + COL_NORMAL_MAPPED, normal_mapped(n, vec4(l, w), n_raw, h_row.x));
}

// The area-light columns: each shape's diffuse form, specular scale and point-source form.
fn area_columns(base: u32, inp: SweepCombination) {
    let n = inp.n;
    let v = inp.v;
    let l = inp.l;
    let m = inp.m;
    let d = inp.d;
    let a_row = inp.a_row;
    // Area lights at l·d facing −v, α as their size (0 to 1e6 m): the diffuse form and the
    // specular point's scale of each shape.
    var area: Light;
    area.position = vec4(l * d, 1.0);
    area.normal = vec4(-v, 0.0);
    area.tangent = vec4(safe_normalize(cross(-v, vec3(0.0, 0.0, 1.0)), vec3(1.0, 0.0, 0.0)), 0.0);
    area.half_x = 0.5 * a_row.x;
    // The same light as k = 1 + ⌊7m⌋ point sources: their forms, each clipped at 0 as the diffuse
    // term takes it, summed.
    area.area_points = 1u + u32(m * 7.0);
    let centre_sample = LightSample(l, vec3(1.0), 0.0, 1.0, -1.0);
    for (var k = 0u; k < 3u; k++) {
        area.kind = LIGHT_RECT + k;
        area.half_y = select(area.half_x, area.half_x * DISK_POLYGON_SCALE, area.kind == LIGHT_DISK);
        outputs[base + COL_AREA_FORM + k] = area_form(area, vec3(0.0), n);
        outputs[base + COL_AREA_SPEC_SCALE + k] = area_specular_point(area, vec3(0.0), n, v, m).scale;
        var form_sum = 0.0;
        for (var j = 0u; j < area.area_points; j++) {
            form_sum += diffuse_lambert(area_point_sample(centre_sample, area, area_emitter(area, j), vec3(0.0), n).form);
        }
        outputs[base + COL_AREA_POINTS_FORM + k] = form_sum;
    }
}

// The transmission columns: Fresnel, refraction, absorption, the sphere's chord and shape exits.
fn transmission_columns(base: u32, inp: SweepCombination) {
    let n = inp.n;
    let v = inp.v;
    let l = inp.l;
    let m = inp.m;
    let v_index = inp.v_index;
    let d = inp.d;
    let a_row = inp.a_row;
    // Light through a surface at N, met along −V: into v (μ's red channel) and out of it; absorption
    // over a·d = α·d; the chord from l·d·m towards V through a sphere of radius α at the origin.
    let c = dot(n, v);
    outputs[base + COL_FRESNEL_DIELECTRIC] = fresnel_dielectric(c, v_index.x);
    outputs[base + COL_FRESNEL_DIELECTRIC + 1u] = fresnel_dielectric(c, 1.0 / v_index.x);
    let refracted = refract_snell(-v, n, 1.0 / v_index.x);
    outputs[base + COL_REFRACT_SNELL] = refracted.x;
    outputs[base + COL_REFRACT_SNELL + 1u] = refracted.y;
    outputs[base + COL_REFRACT_SNELL + 2u] = refracted.z;
    outputs[base + COL_REFRACT_SNELL + 3u] = refracted.w;
    outputs[base + COL_ABSORPTION] = absorption_exact(a_row.x * d);
    outputs[base + COL_ABSORPTION + 1u] = absorption_rule(a_row.x * d);
    outputs[base + COL_SPHERE_CHORD] = sphere_chord(l * (d * m), v, vec3(0.0), a_row.x);
    for (var form = 0u; form < 3u; form++) {
        outputs[base + COL_ABSORPTION_IN_FORM + form] = absorption_in_form(a_row.x * d, form);
    }
    // The exit from m·N inside each unit shape along V (m = 1: on the surface).
    let shapes = array(SHAPE_SPHERE, SHAPE_CYLINDER, SHAPE_CUBE, SHAPE_PYRAMID);
    for (var k = 0u; k < 4u; k++) {
        outputs[base + COL_SHAPE_EXIT + k] = shape_exit(shapes[k], n * m, v).w;
    }
}

// The PCSS and shadow-depth columns.
fn pcss_columns(base: u32, inp: SweepCombination) {
    let n = inp.n;
    let l = inp.l;
    let m = inp.m;
    let d = inp.d;
    let a_row = inp.a_row;
    outputs[base + COL_PENUMBRA_WIDTH] = penumbra_width(a_row.x, d, a_row.y);
    outputs[base + COL_PCSS_SEARCH_RADIUS] = pcss_search_radius(a_row.x, d, a_row.y);
    outputs[base + COL_SHADOW_LINEAR_DEPTH] = shadow_linear_depth(m, a_row.y, a_row.y + d);
    outputs[base + COL_SHADOW_STORED_DEPTH] = shadow_stored_depth(d, a_row.y, a_row.y + d);
    outputs[base + COL_RECEIVER_SLOPE] = receiver_slope(dot(n, l));
}

// A colour's three channels into consecutive outputs from `at`.
fn put_rgb(at: u32, c: vec3<f32>) {
    outputs[at] = c.x;
    outputs[at + 1u] = c.y;
    outputs[at + 2u] = c.z;
}
