// Light sources and distance falloff (docs/model.md §2, §6); the f64 twin is
// crates/shadelab-model/src/lighting/lights.rs, which also declares the light kinds and parameters.

// Codes Rust writes into `Light.kind` and `Light.falloff_form` (LightKind::code and
// FalloffForm::code in crates/shadelab-model/src/lighting/lights.rs), held equal by the test
// `wgsl_codes_equal_rust_codes`.
const LIGHT_DIRECTIONAL: u32 = 0u;
const LIGHT_POINT: u32 = 1u;
const LIGHT_SPOT: u32 = 2u;
const LIGHT_RECT: u32 = 3u;
const LIGHT_DISK: u32 = 4u;
const LIGHT_SPHERE: u32 = 5u;
const FALLOFF_QUADRATIC: u32 = 0u;
const FALLOFF_LINEAR: u32 = 1u;

struct Light {
    // xyz: position of a point or spot light.
    position: vec4<f32>,
    // xyz: direction a directional light travels (L = −direction).
    direction: vec4<f32>,
    // rgb: colour × intensity I_L.
    radiance: vec4<f32>,
    kind: u32,
    falloff_form: u32,
    falloff_alpha: f32,
    d0: f32,
    // xyz: unit axis of a spot light, the way it shines (kept apart from `direction`, so that a
    // permutation without directional lights reads nothing of theirs).
    spot_axis: vec4<f32>,
    // Spot cones: cos of the inner and outer half-angles.
    cos_inner: f32,
    cos_outer: f32,
    // Point and spot lights: where the light ends; 0 = never.
    range: f32,
    _pad: f32,
    // xyz: unit normal of a flat area light, the way it emits (kept apart from spot_axis, so that
    // a permutation without spot lights reads nothing of theirs).
    normal: vec4<f32>,
    // xyz: unit tangent of a flat area light (the rectangle's width), perpendicular to its normal.
    tangent: vec4<f32>,
    // A rectangle's half-sizes; a disk's radius and its equal-area polygon's circumradius; a
    // sphere's radius (in half_x).
    half_x: f32,
    half_y: f32,
    // An area light: 0 for its exact area form, k for k point sources on it (area_points.wgsl).
    area_points: u32,
    // An area light in its exact form: its specular at the representative point or by LTC
    // (AREA_SPECULAR_* in ltc.wgsl).
    area_specular: u32,
}

// Whether an area light is drawn as k point sources (only permutations with EFFECT_AREA_POINTS
// draw any that way).
fn drawn_as_points(light: Light) -> bool {
#if EFFECT_AREA_POINTS
    return light.kind >= LIGHT_RECT && light.area_points > 0u;
#else
    return false;
#endif
}

// docs/model.md §6: I(d) = I0/(1 + α d²); in (0, 1] for α ≥ 0.
fn falloff_quadratic(d: f32, alpha: f32) -> f32 {
    return 1.0 / (1.0 + max(alpha, 0.0) * d * d);
}

// docs/model.md §2: the chapter's 1/(d + d0), d0 kept at or above D0_MIN.
fn falloff_linear(d: f32, d0: f32) -> f32 {
    return 1.0 / (max(d, 0.0) + max(d0, D0_MIN));
}

// KHR_lights_punctual's spot cone: 1 inside the inner cone, 0 outside the outer one, the square
// of a ramp linear in cos between; the span cos_inner − cos_outer at least SPOT_COS_SPAN_MIN.
fn spot_cone(cos_angle: f32, cos_inner: f32, cos_outer: f32) -> f32 {
    let t = clamp((cos_angle - cos_outer) / max(cos_inner - cos_outer, SPOT_COS_SPAN_MIN), 0.0, 1.0);
    return t * t;
}

// KHR_lights_punctual's range window clamp(1 − (d/range)⁴, 0, 1): 0 at d = range; range ≤ 0 is none.
fn window_range(d: f32, range: f32) -> f32 {
    if (range <= 0.0) {
        return 1.0;
    }
    let x = min(max(d, 0.0) / range, 1.0);
    let x2 = x * x;
    return 1.0 - x2 * x2;
}

struct LightSample {
    // Unit vector from the surface towards the light (an area light's representative point).
    l: vec3<f32>,
    // Incident intensity I_L after falloff, per channel.
    radiance: vec3<f32>,
    // The diffuse term's cosine factor: N·L, or an area light's area_form.
    form: f32,
    // What the specular term at l is scaled by: 1, or an area light's representative-point scale.
    spec_scale: f32,
    // An area light's specular by LTC relative to its centre's point light (ltc.wgsl), which
    // replaces the lobe at l under Cook–Torrance; negative: none.
    ltc: f32,
}

// Direction, intensity and the diffuse and specular factors of one light at surface point `p`
// with normal `n`, seen along `v`, roughness `m` (read by area lights only). A light with a
// position closer than LIGHT_DIST_MIN touches the surface: its direction is undefined, so L = N.
// An area light is its centre's point light with N·L replaced by its exact area form and the
// specular taken at its representative point (area_lights.wgsl).
// The `#if EFFECT_…` blocks are kept only in permutations whose scene calls for the effect
// (crates/shadelab-model/src/effects/declared.rs decides; crates/shadelab-render/src/shaders.rs cuts).
fn light_sample(light: Light, p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, m: f32) -> LightSample {
    var s: LightSample;
    s.spec_scale = 1.0;
    s.ltc = -1.0;
#if EFFECT_POINT_LIGHTS
    // Point, spot and area lights (a spot is a point light with a cone).
    if (light.kind != LIGHT_DIRECTIONAL) {
        let to_light = light.position.xyz - p;
        let d = length(to_light);
        s.l = select(n, to_light / max(d, LIGHT_DIST_MIN), d > LIGHT_DIST_MIN);
        var f = 1.0;
#if EFFECT_FALLOFF_QUADRATIC
        if (light.falloff_form == FALLOFF_QUADRATIC) {
            f = falloff_quadratic(d, light.falloff_alpha);
        }
#endif
#if EFFECT_FALLOFF_LINEAR
        if (light.falloff_form == FALLOFF_LINEAR) {
            f = falloff_linear(d, light.d0);
        }
#endif
#if EFFECT_LIGHT_RANGE
        f *= window_range(d, light.range);
#endif
#if EFFECT_SPOT_LIGHTS
        if (light.kind == LIGHT_SPOT) {
            f *= spot_cone(dot(-s.l, light.spot_axis.xyz), light.cos_inner, light.cos_outer);
        }
#endif
        s.radiance = light.radiance.rgb * f;
        s.form = dot(n, s.l);
#if EFFECT_AREA_LIGHTS
        if (light.kind >= LIGHT_RECT && !drawn_as_points(light)) {
            let a = area_specular_point(light, p, n, v, m);
            s.l = a.l;
            s.spec_scale = a.scale;
            s.form = area_form(light, p, n);
        }
#endif
        return s;
    }
#endif
#if EFFECT_DIRECTIONAL_LIGHTS
    s.l = safe_normalize(-light.direction.xyz, n);
    s.radiance = light.radiance.rgb;
    s.form = dot(n, s.l);
#endif
    return s;
}
