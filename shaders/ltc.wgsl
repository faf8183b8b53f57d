// An area light's specular by linearly transformed cosines (docs/area-lights.md): the lobe is a
// clamped cosine carried by a matrix M, so its integral over the light is the cosine's over the
// light's corners carried back by M⁻¹ (Lambert's edge formula, clipped at the horizon). The f64
// twin is crates/shadelab-model/src/lighting/ltc.rs; M⁻¹ comes from the table (ms_table.wgsl's
// ltc_matrix). The whole file exists only in permutations with EFFECT_AREA_LTC.

#if EFFECT_AREA_LIGHTS
#if EFFECT_AREA_LTC
// Codes of Light.area_specular (AreaSpecular::code in lights.rs).
const AREA_SPECULAR_REPRESENTATIVE: u32 = 0u;
const AREA_SPECULAR_LTC: u32 = 1u;

// A unit vector perpendicular to unit `n`.
fn any_tangent(n: vec3<f32>) -> vec3<f32> {
    let helper = select(vec3(0.0, 1.0, 0.0), vec3(1.0, 0.0, 0.0), abs(n.x) < 0.9);
    return normalize(cross(n, helper));
}

// A sphere light as the disk covering the same cone seen from `p` (facing p, radius
// r·d/√(d² − r²)); a flat light as it is. Only called off the sphere (SPHERE_DISK_MARGIN).
fn sphere_as_disk(light: Light, p: vec3<f32>) -> Light {
    if (light.kind != LIGHT_SPHERE) {
        return light;
    }
    var disk = light;
    let to_p = p - light.position.xyz;
    let d = length(to_p);
    let r = abs(light.half_x);
    disk.kind = LIGHT_DISK;
    disk.normal = vec4(to_p / d, 0.0);
    disk.tangent = vec4(any_tangent(to_p / d), 0.0);
    disk.half_x = r * d / sqrt(max(d * d - r * r, 0.0));
    disk.half_y = disk.half_x * DISK_POLYGON_SCALE;
    return disk;
}

// The integral over a flat light of the distribution M⁻¹ carries to the clamped cosine, at `p`
// with unit normal `n` and view tangent `t`, in [0, 1]: the corners carried to the cosine's frame
// by `xf` = M⁻¹·(t, n × t, n)ᵀ, Lambert's edge formula clipped at its horizon, over π.
fn ltc_polygon(light: Light, p: vec3<f32>, n: vec3<f32>, t: vec3<f32>, minv: mat3x3<f32>) -> f32 {
    let xf = minv * transpose(mat3x3(t, cross(n, t), n));
    return clamp(polygon_walk(light, p, vec3(0.0, 0.0, 1.0), xf) / AREA_PI, 0.0, 1.0);
}

// The specular of an area light at `p` by LTC, relative to its centre's point light:
// d²/A_emit · π·E · ∫ D_ltc, for M⁻¹ `minv` and the lobe's albedo `e` at N·V; F and the
// compensation are the caller's. −1 where the representative point stands (the point limit,
// AREA_POINT_LIMIT_ANGLE, or a point on the light).
fn area_specular_ltc(light: Light, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, minv: mat3x3<f32>, e: f32) -> f32 {
    let to_c = light.position.xyz - p;
    let d = length(to_c);
    if (d <= LIGHT_DIST_MIN || area_radius(light) < AREA_POINT_LIMIT_ANGLE * d) {
        return -1.0;
    }
    let n_dot_v = dot(n, v);
    if (n_dot_v <= 0.0) {
        return 0.0;
    }
    let scale = d * d / emitting_area(light) * AREA_PI * e;
    if (light.kind == LIGHT_SPHERE && d <= abs(light.half_x) * (1.0 + SPHERE_DISK_MARGIN)) {
        return scale;
    }
    let t = safe_normalize(v - n * n_dot_v, any_tangent(n));
    return scale * ltc_polygon(sphere_as_disk(light, p), p, n, t, minv);
}
#if EFFECT_SPECULAR_COOK_TORRANCE

// docs/area-lights.md: the Cook–Torrance specular of an area light by LTC, F·comp·ltc: F of the
// material at the half vector of v and l (the representative point's direction), the lobe's
// compensation for `ms_e` (1: none), and the light's integral `ltc`; 0 with the view below.
fn specular_ltc(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, v_index: vec3<f32>, terms: u32, ms_e: f32, ltc: f32) -> vec3<f32> {
    if (dot(n, v) <= 0.0) {
        return vec3(0.0);
    }
    let h = safe_normalize(l + v, n);
    var comp = vec3(1.0);
#if EFFECT_MULTIPLE_SCATTERING
    comp = ms_compensation(ms_e, v_index);
#endif
    return microfacet_f(terms, clamp(dot(v, h), 0.0, 1.0), v_index) * comp * ltc;
}
#endif
#endif
#endif
