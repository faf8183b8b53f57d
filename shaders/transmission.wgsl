// Light through a surface (docs/model.md §7, the chapter's 7.5): Snell's law with total internal
// reflection, absorption by Beer–Lambert and by the chapter's rule, the chord through a sphere
// (the Fresnel factor from either side is microfacet.wgsl's fresnel_dielectric). The f64 twin is
// crates/shadelab-model/src/lighting/transmission.rs, with the same names. Only in permutations
// with transparent objects (the glass pass, glass.wgsl) and in the stability sweep.
#if EFFECT_TRANSMISSION

// The chapter's a·d thresholds (the twin's ABSORPTION_NEGLECT_BELOW, ABSORPTION_LINEAR_BELOW).
const ABSORPTION_NEGLECT_BELOW: f32 = 0.2;
const ABSORPTION_LINEAR_BELOW: f32 = 0.5;
// The forms absorption_regime returns (the twin's AbsorptionForm, in its order).
const ABSORPTION_EXACT: u32 = 0u;
const ABSORPTION_LINEAR: u32 = 1u;
const ABSORPTION_NEGLECTED: u32 = 2u;

// The form the chapter's rule picks for optical depth a·d.
fn absorption_regime(ad: f32) -> u32 {
    if (ad < ABSORPTION_NEGLECT_BELOW) {
        return ABSORPTION_NEGLECTED;
    }
    if (ad < ABSORPTION_LINEAR_BELOW) {
        return ABSORPTION_LINEAR;
    }
    return ABSORPTION_EXACT;
}

// e^(−a·d), a·d held at 0 or above; underflows to 0, never NaN.
fn absorption_exact(ad: f32) -> f32 {
    return exp(-max(ad, 0.0));
}

// The chapter's share: 1, 1 − a·d or e^(−a·d) by absorption_regime.
fn absorption_rule(ad: f32) -> f32 {
    return absorption_in_form(ad, absorption_regime(max(ad, 0.0)));
}

// Snell's law: xyz the unit direction refracted from incident `i` at normal `n` (facing the
// incident side), eta = n_i/n_t; w = 1 when refracted, 0 (and xyz 0) under total internal
// reflection.
fn refract_snell(i: vec3<f32>, n: vec3<f32>, eta: f32) -> vec4<f32> {
    let cos_i = clamp(-dot(i, n), 0.0, 1.0);
    // 1 − η²·sin²θ_i, grouped so that η = 1 gives cos²θ_i without cancelling at grazing angles.
    let cos2_t = (1.0 - eta) * (1.0 + eta) + eta * eta * cos_i * cos_i;
    if (cos2_t < 0.0) {
        return vec4(0.0);
    }
    return vec4(i * eta + n * (eta * cos_i - sqrt(cos2_t)), 1.0);
}

// How long the part of the ray from `o` along unit `d` inside a sphere is: the chord ahead, from
// inside or outside; 0 for a miss, a touch, a sphere behind. Each root in the form that does not
// cancel; b² − c as r² less the squared distance from the centre to the line, |oc × d|².
fn sphere_chord(o: vec3<f32>, d: vec3<f32>, centre: vec3<f32>, radius: f32) -> f32 {
    let oc = o - centre;
    let b = dot(oc, d);
    let c = dot(oc, oc) - radius * radius;
    let perp = cross(oc, d);
    let disc = radius * radius - dot(perp, perp);
    if (disc <= 0.0) {
        return 0.0;
    }
    let root = sqrt(disc);
    var far = -b + root;
    var near = c / (-b + root);
    if (b > 0.0) {
        far = -c / (b + root);
        near = -b - root;
    }
    // Behind: nothing; from inside: to the far side; from outside: far − near, as 2√disc.
    if (far <= 0.0) {
        return 0.0;
    }
    return select(2.0 * root, far, near <= 0.0);
}

// An analytic shape's code in shape_exit (the twin's SHAPE_…; Shape::exit_code).
const SHAPE_SPHERE: u32 = 0u;
const SHAPE_CYLINDER: u32 = 1u;
const SHAPE_CUBE: u32 = 2u;
const SHAPE_PLANE: u32 = 3u;
const SHAPE_PYRAMID: u32 = 4u;
const SHAPE_MESH: u32 = 5u;

// The share of light left after optical depth a·d in `form` (ABSORPTION_…): 1 − a·d held at 0.
fn absorption_in_form(ad_in: f32, form: u32) -> f32 {
    let ad = max(ad_in, 0.0);
    if (form == ABSORPTION_NEGLECTED) {
        return 1.0;
    }
    if (form == ABSORPTION_LINEAR) {
        return max(1.0 - ad, 0.0);
    }
    return absorption_exact(ad);
}

// The mirror direction of `i` about unit normal `n`.
fn reflect_about(i: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    return i - n * (2.0 * dot(i, n));
}

// The far root of a·t² + 2b·t + c = 0 for a point inside (c held at 0 or below), in the form
// that does not cancel; at least 0.
fn quadric_exit(a: f32, b: f32, c_in: f32) -> f32 {
    let c = min(c_in, 0.0);
    let root = sqrt(max(b * b - a * c, 0.0));
    if (b > 0.0) {
        return -c / (b + root);
    }
    return (root - b) / max(a, QUADRIC_A_MIN);
}

// The exit through the first `count` convex planes n·p ≤ 1 that the ray runs towards: xyz the
// plane's n, w = t (at least 0); w < 0 when the ray runs towards none.
fn planes_exit(o: vec3<f32>, d: vec3<f32>, planes: array<vec3<f32>, 6>, count: u32) -> vec4<f32> {
    var best = vec4(0.0, 0.0, 0.0, -1.0);
    for (var k = 0u; k < count; k++) {
        let n = planes[k];
        let towards = dot(n, d);
        if (towards <= 0.0) {
            continue;
        }
        let t = max((1.0 - dot(n, o)) / towards, 0.0);
        if (best.w < 0.0 || t < best.w) {
            best = vec4(n, t);
        }
    }
    return best;
}

// Where the ray from `o` inside unit shape `shape` (object space) along `d` leaves it: xyz the
// outward normal there (not unit), w = t (the exit at o + t·d); w < 0 for a mesh or a zero
// direction. A point a rounding outside counts as on the surface; the plane's exit is its entry.
fn shape_exit(shape: u32, o: vec3<f32>, d: vec3<f32>) -> vec4<f32> {
    if (all(d == vec3(0.0))) {
        return vec4(0.0, 0.0, 0.0, -1.0);
    }
    switch shape {
        case SHAPE_SPHERE: {
            let t = quadric_exit(dot(d, d), dot(o, d), dot(o, o) - 1.0);
            return vec4(o + d * t, t);
        }
        case SHAPE_CYLINDER: {
            let a = d.x * d.x + d.z * d.z;
            var side = 3.4e38;
            if (a > 0.0) {
                side = quadric_exit(a, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - 1.0);
            }
            var cap = 3.4e38;
            if (d.y != 0.0) {
                cap = max((sign(d.y) - o.y) / d.y, 0.0);
            }
            if (cap < side) {
                return vec4(0.0, sign(d.y), 0.0, cap);
            }
            let p = o + d * side;
            return vec4(p.x, 0.0, p.z, side);
        }
        case SHAPE_CUBE: {
            let planes = array(vec3(1.0, 0.0, 0.0), vec3(-1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0),
                vec3(0.0, -1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, -1.0));
            return planes_exit(o, d, planes, 6u);
        }
        case SHAPE_PLANE: {
            return vec4(0.0, select(1.0, -1.0, d.y < 0.0), 0.0, 0.0);
        }
        case SHAPE_PYRAMID: {
            let planes = array(vec3(2.0, 1.0, 0.0), vec3(-2.0, 1.0, 0.0), vec3(0.0, 1.0, 2.0),
                vec3(0.0, 1.0, -2.0), vec3(0.0, -1.0, 0.0), vec3(0.0));
            return planes_exit(o, d, planes, 5u);
        }
        default: {
            return vec4(0.0, 0.0, 0.0, -1.0);
        }
    }
}
#endif
