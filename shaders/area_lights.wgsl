// Area lights (docs/area-lights.md): rectangle, disk and sphere lights of uniform radiance, lit
// as their centre's point light with N·L replaced by the exact area form and the specular taken
// at a representative point. The f64 twin is crates/shadelab-model/src/lighting/area.rs, with
// the same names and guards. The whole file exists only in permutations with EFFECT_AREA_LIGHTS.

#if EFFECT_AREA_LIGHTS
// Sides of the regular polygon a disk light is drawn as (AREA_DISK_SIDES in area.rs).
const AREA_DISK_SIDES: u32 = 16u;
const AREA_PI: f32 = 3.14159265358979;

// The representative point: the unit direction to it and the scale of the centre's specular.
struct AreaPoint {
    l: vec3<f32>,
    scale: f32,
}

// A walk over a polygon's corners clipped at a horizon, in order, without storing them: the
// first and the previous kept unit direction, how many were kept and clipped, the edge terms' sum.
struct EdgeWalk {
    first: vec3<f32>,
    prev: vec3<f32>,
    kept: u32,
    clipped: u32,
    sum: f32,
}

// The area a point far away sees face-on: a flat light's area, a sphere's disc πr².
fn emitting_area(light: Light) -> f32 {
    if (light.kind == LIGHT_RECT) {
        return 4.0 * light.half_x * light.half_y;
    }
    return AREA_PI * light.half_x * light.half_x;
}

// The radius of the disc the light's farthest point lies on: its half-diagonal, its radius.
fn area_radius(light: Light) -> f32 {
    if (light.kind == LIGHT_RECT) {
        return length(vec2(light.half_x, light.half_y));
    }
    return light.half_x;
}

// How many corners a flat light has: the rectangle's four, the disk's polygon's AREA_DISK_SIDES.
fn area_corner_count(light: Light) -> u32 {
    return select(AREA_DISK_SIDES, 4u, light.kind == LIGHT_RECT);
}

// Corner `i` of a flat light, counter-clockwise seen from the side it emits to: the rectangle's,
// or the disk's equal-area regular polygon's (light.half_y holds its circumradius for a disk,
// LightUniform::new). Computed, not indexed: a CPU rasterizer spills indexed arrays to memory.
fn area_corner(light: Light, i: u32) -> vec3<f32> {
    let t = light.tangent.xyz;
    let b = cross(light.normal.xyz, t);
    if (light.kind == LIGHT_RECT) {
        let sx = select(-1.0, 1.0, i == 1u || i == 2u);
        let sy = select(-1.0, 1.0, i >= 2u);
        return light.position.xyz + t * (sx * light.half_x) + b * (sy * light.half_y);
    }
    let phi = 2.0 * AREA_PI * f32(i) / f32(AREA_DISK_SIDES);
    return light.position.xyz + (t * cos(phi) + b * sin(phi)) * light.half_y;
}

// One edge's term of Lambert's edge formula, θ·n·(a × b)/|a × b| for unit directions a, b, θ as
// atan2(|a × b|, a·b) (precise for small angles in f32); 0 for an edge seen end-on.
fn edge_term(a: vec3<f32>, b: vec3<f32>, n: vec3<f32>) -> f32 {
    let c = cross(a, b);
    let len2 = dot(c, c);
    if (len2 <= EDGE_CROSS_MIN_LEN2) {
        return 0.0;
    }
    let len = sqrt(len2);
    return atan2(len, dot(a, b)) * dot(n, c) / len;
}

// The walk's next corner of the clipped polygon, `v` from the shaded point: counted, and unless
// it touches the point (LIGHT_DIST_MIN, no direction) joined to the previous by its edge term.
fn polygon_step(w_in: EdgeWalk, v: vec3<f32>, n: vec3<f32>) -> EdgeWalk {
    var w = w_in;
    w.clipped++;
    if (length(v) > LIGHT_DIST_MIN) {
        let u = normalize(v);
        if (w.kept == 0u) {
            w.first = u;
        } else {
            w.sum += edge_term(w.prev, u, n);
        }
        w.prev = u;
        w.kept++;
    }
    return w;
}

// Lambert's edge formula: E/L of a flat light at `p` with unit normal `n`, its polygon clipped at
// the plane through p normal to n, walked corner by corner; 0 seen from behind.
fn polygon_irradiance(p: vec3<f32>, n: vec3<f32>, light: Light) -> f32 {
    return polygon_walk(light, p, n, mat3x3(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0)));
}

// Lambert's edge formula over the light's corners carried by `xf` from `p` (the identity for
// the light itself, ltc.wgsl's M⁻¹ for its LTC), clipped at the plane normal to `n` through the
// origin, 0 seen from behind. The identity changes no bit: each product adds exact zeros.
fn polygon_walk(light: Light, p: vec3<f32>, n: vec3<f32>, xf: mat3x3<f32>) -> f32 {
    let count = area_corner_count(light);
    var w = EdgeWalk(vec3(0.0), vec3(0.0), 0u, 0u, 0.0);
    for (var i = 0u; i < count; i++) {
        let a = xf * (area_corner(light, i) - p);
        let b = xf * (area_corner(light, (i + 1u) % count) - p);
        let sa = dot(a, n);
        let sb = dot(b, n);
        if (sa > 0.0) {
            w = polygon_step(w, a, n);
        }
        if ((sa > 0.0) != (sb > 0.0) && sa != sb) {
            w = polygon_step(w, a + (b - a) * (sa / (sa - sb)), n);
        }
    }
    if (w.clipped < 3u) {
        return 0.0;
    }
    w.sum += edge_term(w.prev, w.first, n);
    return max(-0.5 * w.sum, 0.0);
}

// E/L of a sphere light of radius `radius`, centre at distance `d` and angle θ from the normal:
// the spherical cap, clipped at the horizon; π inside the sphere.
fn sphere_irradiance(radius: f32, d: f32, cos_theta: f32) -> f32 {
    let r = abs(radius);
    let sin2_sigma = (r / d) * (r / d);
    // On or inside the sphere (also where r/d rounds to 1) the light is all round: π.
    if (d <= r || sin2_sigma >= 1.0) {
        return AREA_PI;
    }
    let cos_t = clamp(cos_theta, -1.0, 1.0);
    let sin_t = sqrt(max(1.0 - cos_t * cos_t, 0.0));
    if (cos_t * cos_t >= sin2_sigma || sin2_sigma <= 0.0) {
        return max(AREA_PI * sin2_sigma * cos_t, 0.0);
    }
    // The horizon-clipped cap in the form that keeps f32's precision (area.rs derives it).
    let delta = max(sin2_sigma - cos_t * cos_t, 0.0);
    let sin_sigma = sqrt(sin2_sigma);
    let cos_sigma = sqrt(max(1.0 - sin2_sigma, 0.0));
    let sin_phi = min(sqrt(delta) / (sin_sigma * sin_t), 1.0);
    let cos_phi = clamp(-cos_sigma * cos_t / (sin_sigma * sin_t), -1.0, 1.0);
    let phi = atan2(sin_phi, cos_phi);
    let u = sqrt(delta) / cos_sigma;
    let e = sin2_sigma * sin_t * (sin_sigma / cos_sigma) * sin_minus_phi_cos(phi, sin_phi, cos_phi)
        + atan_minus_u(u);
    return clamp(e, 0.0, AREA_PI);
}

// Below this argument the series replace the direct forms (AREA_SERIES_MAX in area.rs).
const AREA_SERIES_MAX: f32 = 0.25;

// sin φ − φ cos φ, by its series below AREA_SERIES_MAX.
fn sin_minus_phi_cos(phi: f32, sin_phi: f32, cos_phi: f32) -> f32 {
    if (abs(phi) < AREA_SERIES_MAX) {
        let p2 = phi * phi;
        return phi * p2 * (1.0 / 3.0 - p2 * (1.0 / 30.0 - p2 * (1.0 / 840.0 - p2 / 45360.0)));
    }
    return sin_phi - phi * cos_phi;
}

// atan u − u, by its series below AREA_SERIES_MAX.
fn atan_minus_u(u: f32) -> f32 {
    if (abs(u) < AREA_SERIES_MAX) {
        let u2 = u * u;
        return u * u2 * (-1.0 / 3.0 + u2 * (1.0 / 5.0 - u2 * (1.0 / 7.0 - u2 / 9.0)));
    }
    return atan(u) - u;
}

// E/L of the light at `p`: the sphere's cap, or the flat light's edge formula.
fn area_irradiance(light: Light, p: vec3<f32>, n: vec3<f32>) -> f32 {
    if (light.kind == LIGHT_SPHERE) {
        let to = light.position.xyz - p;
        let d = length(to);
        return sphere_irradiance(light.half_x, d, select(1.0, dot(n, to) / d, d > 0.0));
    }
    return polygon_irradiance(p, n, light);
}

// The diffuse factor relative to the centre's point light, d²·(E/L)/A_emit; under
// AREA_POINT_LIMIT_ANGLE the point limit cos θ_p (sphere) or cos θ_p·cos θ_l (flat lights).
fn area_form(light: Light, p: vec3<f32>, n: vec3<f32>) -> f32 {
    let to = light.position.xyz - p;
    let d = length(to);
    if (d <= LIGHT_DIST_MIN) {
        return 0.0;
    }
    let l = to / d;
    if (area_radius(light) < AREA_POINT_LIMIT_ANGLE * d) {
        let cos_l = select(max(-dot(light.normal.xyz, l), 0.0), 1.0, light.kind == LIGHT_SPHERE);
        return max(dot(n, l), 0.0) * cos_l;
    }
    return d * d * area_irradiance(light, p, n) / emitting_area(light);
}

// A vector in a flat light's plane (from its centre) moved onto the shape: clamped to the
// rectangle's half-sizes, or in length to the disk's radius.
fn clamp_to_shape(light: Light, local: vec3<f32>) -> vec3<f32> {
    let t = light.tangent.xyz;
    let b = cross(light.normal.xyz, t);
    let x = dot(local, t);
    let y = dot(local, b);
    if (light.kind == LIGHT_RECT) {
        return t * clamp(x, -light.half_x, light.half_x) + b * clamp(y, -light.half_y, light.half_y);
    }
    let len = length(vec2(x, y));
    let k = select(1.0, light.half_x / len, len > light.half_x);
    return (t * x + b * y) * k;
}

// The representative point for the specular term (area.rs explains the choice and the lobe's
// widening m²/(m² + σ²/8)).
fn area_specular_point(light: Light, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, m_in: f32) -> AreaPoint {
    let to_c = light.position.xyz - p;
    let d = length(to_c);
    if (d <= LIGHT_DIST_MIN) {
        return AreaPoint(n, 0.0);
    }
    let flat = light.kind != LIGHT_SPHERE;
    let axis = light.normal.xyz;
    if (area_radius(light) < AREA_POINT_LIMIT_ANGLE * d) {
        return AreaPoint(to_c / d, select(1.0, max(-dot(axis, to_c / d), 0.0), flat));
    }
    let r_dir = safe_normalize(2.0 * dot(n, v) * n - v, n);
    var q = vec3(0.0);
    var scale = 1.0;
    if (flat) {
        let denom = dot(r_dir, axis);
        var local = safe_normalize(r_dir - axis * denom, vec3(0.0)) * (2.0 * area_radius(light));
        if (denom < 0.0) {
            local = p + r_dir * max(dot(to_c, axis) / denom, 0.0) - light.position.xyz;
        }
        q = light.position.xyz + clamp_to_shape(light, local);
        let to_q = q - p;
        let r2 = max(dot(to_q, to_q), LIGHT_DIST_MIN * LIGHT_DIST_MIN);
        scale = max(-dot(axis, safe_normalize(to_q, vec3(0.0))), 0.0) * d * d / r2;
    } else {
        let along = dot(to_c, r_dir) * r_dir - to_c;
        let len = length(along);
        let reach = select(0.0, min(light.half_x / len, 1.0), len > 0.0);
        q = light.position.xyz + along * reach;
    }
    let m = max(m_in, M_MIN);
    let sigma = sqrt(emitting_area(light) / AREA_PI) / d;
    let norm = m * m / (m * m + sigma * sigma / 8.0);
    return AreaPoint(safe_normalize(q - p, to_c / d), scale * norm);
}
#endif
