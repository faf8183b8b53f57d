// The glass pass (docs/transparency.md): a transparent object drawn over a copy of what is behind
// it. Its surface's own light with C·(1 − τ), and τ of what comes through: split by the exact
// Fresnel factor at the entry (refracted in, mirrored off), bent by Snell's law at the entry and
// the exit, absorbed over the path inside measured from the geometry, reflected back in under
// total internal reflection. The exit is exact for the analytic shapes (transmission.wgsl) and
// read from the back faces for a mesh. What lies along the ray out is found in the opaque scene
// by a march through its depth. The f64 counterpart is the reference's tracer
// (crates/shadelab-model/src/reference/glass.rs), which follows every branch exactly.
#if EFFECT_TRANSMISSION

// Exits the path tries inside an object before it gives up: each total internal reflection
// takes one more. The light of a path still inside after them is lost (the TIR view shows where).
const GLASS_TIR_BOUNCES: u32 = 4u;
// Steps of the march along a ray out, each GLASS_MARCH_GROWTH times the last, the first
// GLASS_MARCH_FIRST of the distance from the eye: 48 steps reach 3.8 times that distance.
const GLASS_MARCH_STEPS: u32 = 48u;
const GLASS_MARCH_GROWTH: f32 = 1.12;
const GLASS_MARCH_FIRST: f32 = 0.002;
// Lookups that walk a mesh's exit along its back faces (back_face_exit).
const BACK_FACE_STEPS: u32 = 4u;
// Halvings that narrow a hit of the march down between its last two steps.
const GLASS_MARCH_REFINE: u32 = 8u;
// The scene's background (scene::BACKGROUND): what a ray that meets nothing sees, where no
// environment is shown as the background.
const GLASS_BACKGROUND: vec3<f32> = vec3(0.03, 0.035, 0.045);
// globals.flags bits 1–2: the glass view (GlassView::code).
const GLASS_VIEW_SHIFT: u32 = 1u;
const GLASS_VIEW_MASK: u32 = 3u;
const GLASS_VIEW_TIR: u32 = 1u;
const GLASS_VIEW_PATH: u32 = 2u;
const GLASS_VIEW_REGIME: u32 = 3u;

// Where a path inside leaves: the point, the outward unit normal, and whether one was found.
struct Exit {
    point: vec3<f32>,
    normal: vec3<f32>,
    found: bool,
}

// One index's path through the object: the light it brings, whether an exit reflected it all
// back (total internal reflection), and the length it ran inside.
struct GlassPath {
    light: vec3<f32>,
    tir: bool,
    length: f32,
}

// World point `p` on the target: pixel xy and the stored depth's z; z < 0 off the view.
fn project_to_pixel(p: vec3<f32>) -> vec3<f32> {
    let clip = globals.view_proj * vec4(p, 1.0);
    if (clip.w <= 0.0) {
        return vec3(0.0, 0.0, -1.0);
    }
    let ndc = clip.xyz / clip.w;
    if (any(abs(ndc.xy) > vec2(1.0)) || ndc.z > 1.0) {
        return vec3(0.0, 0.0, -1.0);
    }
    let size = vec2<f32>(textureDimensions(behind_depth));
    return vec3((ndc.x * 0.5 + 0.5) * size.x, (0.5 - ndc.y * 0.5) * size.y, max(ndc.z, 0.0));
}

fn texel(p: vec3<f32>) -> vec2<i32> {
    let size = vec2<i32>(textureDimensions(behind_depth));
    return clamp(vec2<i32>(p.xy), vec2(0), size - 1);
}

// What is straight behind the pixel.
fn scene_behind(pixel: vec2<f32>) -> vec3<f32> {
    return textureLoad(behind_color, vec2<i32>(pixel), 0).rgb;
}

// What a ray through the glass that meets nothing sees along unit `dir`: the environment where
// it is the background (level 0, as background.wgsl draws it), else the scene's background.
fn glass_miss(dir: vec3<f32>) -> vec3<f32> {
#if EFFECT_ENVIRONMENT_BACKGROUND
    return env_level_sample(0u, dir);
#else
    return GLASS_BACKGROUND;
#endif
}

#if EFFECT_REFRACTION
// What the ray from `p` along unit `dir` meets in the scene behind: steps grow until a step lands
// behind the stored depth, halvings then narrow the crossing down; the background when the ray
// leaves the view or meets nothing.
fn scene_along(p: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    var step = GLASS_MARCH_FIRST * max(distance(globals.camera_pos.xyz, p), 1.0);
    var s_prev = 0.0;
    var s = step;
    for (var k = 0u; k < GLASS_MARCH_STEPS; k++) {
        let q = project_to_pixel(p + dir * s);
        if (q.z < 0.0) {
            return glass_miss(dir);
        }
        if (q.z >= textureLoad(behind_depth, texel(q), 0).r) {
            // Narrow the crossing down between the last step in front and this one.
            var lo = s_prev;
            var hi = s;
            for (var r = 0u; r < GLASS_MARCH_REFINE; r++) {
                let mid = 0.5 * (lo + hi);
                let m = project_to_pixel(p + dir * mid);
                if (m.z >= 0.0 && m.z >= textureLoad(behind_depth, texel(m), 0).r) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return textureLoad(behind_color, texel(project_to_pixel(p + dir * hi)), 0).rgb;
        }
        s_prev = s;
        step *= GLASS_MARCH_GROWTH;
        s += step;
    }
    return glass_miss(dir);
}
#endif

// A mesh's exit, from its back faces: the path runs as far as the back face behind `pixel` is
// from `p`; the back face seen where that puts the exit gives the next distance, BACK_FACE_STEPS
// times (the path meeting the back faces as a height field); its normal is the one seen there.
fn back_face_exit(p: vec3<f32>, t: vec3<f32>, pixel: vec2<f32>) -> Exit {
    var out = Exit(p, t, false);
    let here = textureLoad(back_position, vec2<i32>(pixel), 0);
    if (here.w == 0.0) {
        return out;
    }
    var at = vec2<i32>(pixel);
    var d = distance(here.xyz, p);
    for (var k = 0u; k < BACK_FACE_STEPS; k++) {
        let guess = project_to_pixel(p + t * d);
        if (guess.z < 0.0) {
            break;
        }
        let seen = textureLoad(back_position, texel(guess), 0);
        if (seen.w == 0.0) {
            break;
        }
        at = texel(guess);
        d = distance(seen.xyz, p);
    }
    out.point = p + t * d;
    out.normal = safe_normalize(textureLoad(back_normal, at, 0).xyz, t);
    out.found = true;
    return out;
}

// Where the path from world `p` along unit `t` inside the object leaves it.
fn glass_exit(p: vec3<f32>, t: vec3<f32>, pixel: vec2<f32>) -> Exit {
    if (object.exit_shape == SHAPE_MESH) {
        return back_face_exit(p, t, pixel);
    }
    let e = shape_exit(object.exit_shape, (object.inverse_model * vec4(p, 1.0)).xyz,
        (object.inverse_model * vec4(t, 0.0)).xyz);
    if (e.w < 0.0) {
        return Exit(p, t, false);
    }
    // The map to world space is affine: the world exit is at the same ray parameter.
    return Exit(p + t * e.w, safe_normalize(normal_to_world(e.xyz), t), true);
}

// The light index `v` brings through the surface at `p` (outward unit normal `n`) to a ray
// arriving along unit `dir`: the refracted path's, and the mirrored ray's share F.
fn glass_path(p: vec3<f32>, n: vec3<f32>, dir: vec3<f32>, v: f32, pixel: vec2<f32>) -> GlassPath {
    var out = GlassPath(vec3(0.0), false, 0.0);
    var t = dir;
    var f1 = 0.0;
#if EFFECT_REFRACTION
    f1 = fresnel_dielectric(-dot(dir, n), v);
    t = refract_snell(dir, n, 1.0 / v).xyz;
#endif
    var pos = p;
    var weight = vec3(1.0);
#if EFFECT_REFRACTION||EFFECT_ABSORPTION
    var left = false;
    for (var k = 0u; k < GLASS_TIR_BOUNCES; k++) {
        let e = glass_exit(pos, t, pixel);
        if (!e.found) {
            left = true;
            break;
        }
        let d = distance(e.point, pos);
        out.length += d;
#if EFFECT_ABSORPTION
        let ad = object.absorption.rgb * d;
        let form = object.absorption_form;
        weight *= vec3(absorption_in_form(ad.r, form), absorption_in_form(ad.g, form), absorption_in_form(ad.b, form));
#endif
        pos = e.point;
#if EFFECT_REFRACTION
        let out_dir = refract_snell(t, -e.normal, v);
        if (out_dir.w == 0.0) {
            // Total internal reflection: all of it back inside.
            out.tir = true;
            t = reflect_about(t, e.normal);
            continue;
        }
        weight *= 1.0 - fresnel_dielectric(dot(t, e.normal), 1.0 / v);
        t = out_dir.xyz;
#endif
        left = true;
        break;
    }
    if (!left) {
        weight = vec3(0.0);
    }
#endif
#if EFFECT_REFRACTION
    // The ray out of the body and the mirrored one, marched in one loop (its code compiled once).
    let starts = array(pos, p);
    let towards = array(t, reflect_about(dir, n));
    let share = array((1.0 - f1) * weight, vec3(f1));
    for (var r = 0u; r < 2u; r++) {
        out.light += share[r] * scene_along(starts[r], towards[r]);
    }
#else
    out.light = weight * scene_behind(pixel);
#endif
    return out;
}

// A transparent object's colour at world `p` (outward normal `n_in`): its surface's own light
// with C·(1 − τ), and τ of what comes through, each channel along its own index where they differ.
fn glass_color(p: vec3<f32>, n_in: vec3<f32>, surface: Surface, pixel: vec2<f32>) -> vec4<f32> {
    let v = safe_normalize(globals.camera_pos.xyz - p * globals.camera_pos.w, vec3(0.0, 1.0, 0.0));
    let n = safe_normalize(n_in, v);
    let tau = object.transmission;
    var own = surface;
    own.c = surface.c * (1.0 - tau);
    let lit = shade(p, n, own, pixel);
    var v_index = vec3(1.0);
    var disperses = false;
#if EFFECT_REFRACTION
    v_index = object.ior.rgb;
    disperses = object.ior.w != 0.0;
#endif
    // One path for all channels; one per channel where they disperse (a loop, so that the path's
    // code is compiled once).
    var light = vec3(0.0);
    var path = GlassPath(vec3(0.0), false, 0.0);
    let channels = select(1u, 3u, disperses);
    for (var c = 0u; c < channels; c++) {
        let one = glass_path(p, n, -v, v_index[c], pixel);
        if (disperses) {
            light[c] = one.light[c];
        } else {
            light = one.light;
        }
        path.tir = path.tir || one.tir;
        path.length = max(path.length, one.length);
    }
    let color = lit + tau * light;
    switch (globals.flags >> GLASS_VIEW_SHIFT) & GLASS_VIEW_MASK {
        case GLASS_VIEW_TIR: {
            return vec4(select(color * 0.3, vec3(1.0, 0.15, 0.1), path.tir), 1.0);
        }
        case GLASS_VIEW_PATH: {
            return vec4(vec3(path.length / max(object.longest_chord, 1e-6)), 1.0);
        }
        case GLASS_VIEW_REGIME: {
            var form = ABSORPTION_NEGLECTED;
#if EFFECT_ABSORPTION
            form = absorption_regime(max(max(object.absorption.r, object.absorption.g), object.absorption.b) * path.length);
#endif
            var colors = array(vec3(0.9, 0.15, 0.1), vec3(0.95, 0.8, 0.1), vec3(0.15, 0.75, 0.25));
            return vec4(colors[form], 1.0);
        }
        default: {
            return vec4(color, 1.0);
        }
    }
}

@fragment
fn fs_glass(in: PhongOut) -> @location(0) vec4<f32> {
    let px = pixel_inputs(in);
    let c = glass_color(in.world_pos, px.normal, pixel_surface(px.texcoord, px.tint), in.clip.xy);
    // The debug views show their own colours, without the emission.
    if (((globals.flags >> GLASS_VIEW_SHIFT) & GLASS_VIEW_MASK) != 0u) {
        return c;
    }
    return finish(c.rgb + pixel_emission(px.texcoord));
}

// The back-face pass of a mesh: each pixel's nearest back face, its world position and outward
// normal.
struct BackFace {
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
}

@fragment
fn fs_glass_back(in: PhongOut) -> BackFace {
    return BackFace(vec4(in.world_pos, 1.0), vec4(safe_normalize(in.world_normal, vec3(0.0, 1.0, 0.0)), 0.0));
}
#endif
