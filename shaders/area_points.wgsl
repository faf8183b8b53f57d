// The chapter's approximation of an area light by k point sources (docs/area-lights.md): the
// points lie on the light in a stratified pattern, each a Lambertian emitter with 1/k of its
// power and its own hard shadow (shadows.wgsl's cube j). The f64 twin is
// crates/shadelab-model/src/lighting/area_points.rs. The whole file exists only in permutations
// with EFFECT_AREA_POINTS.

#if EFFECT_AREA_POINTS
// Twins of AREA_GOLDEN_FRACTION (1/φ) and AREA_GOLDEN_ANGLE (2π/φ²) in area_points.rs.
const AREA_GOLDEN_FRACTION: f32 = 0.618033988749895;
const AREA_GOLDEN_ANGLE: f32 = 2.399963229728653;
const AREA_QUARTER_PI: f32 = 0.785398163397448;

// One point source: where it is, the normal it emits around (zero: every way alike), and its
// share of the light's power relative to the centre's point light.
struct AreaEmitter {
    position: vec3<f32>,
    normal: vec3<f32>,
    gain: f32,
}

// How many samples the light loop takes of a light: its k where drawn as points, else 1.
fn area_point_count(light: Light) -> u32 {
    return select(1u, light.area_points, drawn_as_points(light));
}

// Point `j` of `k` of the Fibonacci lattice on the unit square; one point is its centre.
fn area_lattice(j: u32, k: u32) -> vec2<f32> {
    let x = (f32(j) + 0.5) / f32(max(k, 1u));
    let y = fract(0.5 + f32(j) * AREA_GOLDEN_FRACTION);
    return vec2(x, y);
}

// The unit square onto the unit disk, area-preserving (the concentric map); centre to centre.
fn concentric_disk(u: vec2<f32>) -> vec2<f32> {
    let a = 2.0 * u.x - 1.0;
    let b = 2.0 * u.y - 1.0;
    if (a == 0.0 && b == 0.0) {
        return vec2(0.0);
    }
    var r = b;
    var phi = 2.0 * AREA_QUARTER_PI - AREA_QUARTER_PI * (a / b);
    if (abs(a) > abs(b)) {
        r = a;
        phi = AREA_QUARTER_PI * (b / a);
    }
    return vec2(r * cos(phi), r * sin(phi));
}

// Point `j` of `k` of the Fibonacci sphere, pole along y.
fn fibonacci_sphere(j: u32, k: u32) -> vec3<f32> {
    let y = 1.0 - 2.0 * (f32(j) + 0.5) / f32(max(k, 1u));
    let r = sqrt(max(1.0 - y * y, 0.0));
    let phi = AREA_GOLDEN_ANGLE * f32(j);
    return vec3(r * cos(phi), y, r * sin(phi));
}

// Point source `j` of a light drawn as its area_points points (area_points.rs says why each
// shape's points and gains).
fn area_emitter(light: Light, j: u32) -> AreaEmitter {
    let k = max(light.area_points, 1u);
    let t = light.tangent.xyz;
    let b = cross(light.normal.xyz, t);
    let u = area_lattice(j, k);
    if (light.kind == LIGHT_RECT) {
        let q = t * ((2.0 * u.x - 1.0) * light.half_x) + b * ((2.0 * u.y - 1.0) * light.half_y);
        return AreaEmitter(light.position.xyz + q, light.normal.xyz, 1.0 / f32(k));
    }
    if (light.kind == LIGHT_DISK) {
        let q = concentric_disk(u) * light.half_x;
        return AreaEmitter(light.position.xyz + t * q.x + b * q.y, light.normal.xyz, 1.0 / f32(k));
    }
    if (k > 1u) {
        let s = fibonacci_sphere(j, k);
        return AreaEmitter(light.position.xyz + s * light.half_x, s, 4.0 / f32(k));
    }
    return AreaEmitter(light.position.xyz, vec3(0.0), 1.0);
}

// Point source `e` (area_emitter) at `p` with unit normal `n`: the centre's sample `base` with the
// direction to the source and its factor gain·cos θ_e·d²/r² (r² at least LIGHT_DIST_MIN²).
fn area_point_sample(base: LightSample, light: Light, e: AreaEmitter, p: vec3<f32>, n: vec3<f32>) -> LightSample {
    let to_c = light.position.xyz - p;
    let d2 = dot(to_c, to_c);
    let to = e.position - p;
    let r = length(to);
    let l = select(n, to / r, r > LIGHT_DIST_MIN);
    let cos_e = select(max(-dot(e.normal, l), 0.0), 1.0, all(e.normal == vec3(0.0)));
    let scale = e.gain * cos_e * d2 / max(r * r, LIGHT_DIST_MIN * LIGHT_DIST_MIN);
    return LightSample(l, base.radiance, scale * dot(n, l), scale, -1.0);
}
#endif
