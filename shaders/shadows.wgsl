// Cast shadows from shadow maps (docs/model.md §0, §6): the visibility of a light from a surface
// point, by comparing the point's depth seen from the light with the depth the light's shadow
// pass stored (crates/shadelab-render/src/shadow_pass.rs). The projection math is in
// shadow_math.wgsl, the uniform structs in types.wgsl and the maps' bindings in bindings.wgsl; the
// f64 reference traces exact shadow rays instead of sampling maps. Everything here exists only in
// the permutations with EFFECT_CAST_SHADOWS.

#if EFFECT_CAST_SHADOWS
// Codes Rust writes into `ShadowLight.shadow_filter` (ShadowFilter::code in
// crates/shadelab-model/src/shadows.rs).
const SHADOW_FILTER_HARD: u32 = 0u;
const SHADOW_FILTER_PCF: u32 = 1u;
const SHADOW_FILTER_POISSON: u32 = 2u;
const SHADOW_FILTER_PCSS: u32 = 3u;

// Twins of crates/shadelab-model/src/shadows.rs (shadows::WGSL_TWINS), reasons there.
const MAX_SHADOW_LAYERS: u32 = 144u;
const SHADOW_POISSON_TAPS: u32 = 16u;
const SHADOW_POISSON_RADIUS_TEXELS: f32 = 2.0;
const SHADOW_CASCADE_MARGIN_TEXELS: f32 = 3.0;
const SHADOW_PCSS_NEAREST_BLOCKER: f32 = 0.1;

#if EFFECT_SHADOW_POISSON||EFFECT_SHADOW_PCSS
// A per-pixel angle in [0, 2π) (interleaved gradient noise of the screen position): rotates the
// Poisson disk so its pattern turns into fine noise instead of banding.
fn shadow_rotation(pixel: vec2<f32>) -> f32 {
    return 6.2831853 * fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}
#endif

#if EFFECT_SHADOW_POISSON
// Point `i` of the 16-point Poisson disk of unit radius the soft filters tap.
fn poisson_tap(i: u32) -> vec2<f32> {
    var disk = array<vec2<f32>, 16>(
        vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725),
        vec2(-0.09418410, -0.92938870), vec2(0.34495938, 0.29387760),
        vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
        vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379),
        vec2(0.44323325, -0.97511554), vec2(0.53742981, -0.47373420),
        vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
        vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590),
        vec2(0.19984126, 0.78641367), vec2(0.14383161, -0.14100790),
    );
    return disk[i % 16u];
}

// SHADOW_FILTER_POISSON: the mean of SHADOW_POISSON_TAPS bilinear compares on a disk of
// SHADOW_POISSON_RADIUS_TEXELS texels, rotated per pixel.
fn shadow_compare_poisson(sl: ShadowLight, uv: vec2<f32>, layer: u32, depth: f32, pixel: vec2<f32>) -> f32 {
    let a = shadow_rotation(pixel);
    let rot = mat2x2(cos(a), sin(a), -sin(a), cos(a)) * (SHADOW_POISSON_RADIUS_TEXELS * sl.texel_uv);
    // The taps stay inside the light's part of the layer (the rest is another size's border).
    let hi = vec2(sl.uv_scale - 0.5 * sl.texel_uv);
    var sum = 0.0;
    for (var i = 0u; i < SHADOW_POISSON_TAPS; i++) {
        let q = clamp(uv + rot * poisson_tap(i), vec2(0.5 * sl.texel_uv), hi);
        sum += textureSampleCompareLevel(shadow_maps, shadow_linear, q, layer, depth);
    }
    return sum / f32(SHADOW_POISSON_TAPS);
}
#endif

#if EFFECT_SHADOW_PCSS
// Search tap `i` of `n`: a golden-angle spiral whose radius grows as the square of its rank, so
// near blockers (small cones) are sampled as densely as far ones.
fn pcss_search_tap(i: u32, n: u32) -> vec2<f32> {
    let r = (f32(i) + 0.5) / f32(n);
    let angle = 2.3999632 * f32(i);
    return r * r * vec2(cos(angle), sin(angle));
}

// Filter tap `i` of `n` on the unit disk: the golden-angle spiral with radius √((i + ½)/n), as
// even a cover of the disk as a Poisson disk for any n (Vogel's).
fn pcss_filter_tap(i: u32, n: u32) -> vec2<f32> {
    let r = sqrt((f32(i) + 0.5) / f32(n));
    let angle = 2.3999632 * f32(i);
    return r * vec2(cos(angle), sin(angle));
}

// SHADOW_FILTER_PCSS: percentage-closer soft shadows (docs/area-lights.md). The blocker search
// takes sl.pcss_taps stored depths over the cone from the receiver to the light, where it
// crosses the nearest blocker depth searched (SHADOW_PCSS_NEAREST_BLOCKER), and keeps those
// inside the cone at their own depth; the blockers' mean linear depth d_b gives the penumbra
// w = w_light·(d_r − d_b)/d_b at the receiver, and the filter's disk has radius w/2 there (its
// ramp spans its diameter), at least one texel. Both patterns turn per pixel. Every tap compares
// with the receiver's own plane there: a tap r away at the receiver may see that plane nearer the
// light by r·tan θ (θ between N and L, `n_dot_l`), which must not shadow it. A light without an
// area (w_light = 0) gets the hardware's 2×2 compare.
fn shadow_compare_pcss(sl: ShadowLight, uv: vec2<f32>, layer: u32, depth: f32, n_dot_l: f32, pixel: vec2<f32>) -> f32 {
    if (sl.light_size <= 0.0 || sl.perspective == 0u) {
        return textureSampleCompareLevel(shadow_maps, shadow_linear, uv, layer, depth);
    }
    let a = shadow_rotation(pixel);
    let rot = mat2x2(cos(a), sin(a), -sin(a), cos(a));
    let lo = vec2(0.5 * sl.texel_uv);
    let hi = vec2(sl.uv_scale - 0.5 * sl.texel_uv);
    let d_r = shadow_linear_depth(depth, sl.near, sl.far);
    let slope = receiver_slope(n_dot_l);
    // Map tangent units to layer coordinates: a face spans 2 in tangent and uv_scale in uv.
    let per_tan = 0.5 * sl.uv_scale;
    let nearest = max(sl.near, SHADOW_PCSS_NEAREST_BLOCKER * d_r);
    let search = min(pcss_search_radius(sl.light_size, d_r, nearest), 1.0);
    let taps = max(sl.pcss_taps, 1u);
    var blockers = 0.0;
    var depth_sum = 0.0;
    for (var i = 0u; i < taps; i++) {
        let off = rot * pcss_search_tap(i, taps) * search;
        let q = clamp(uv + off * per_tan, lo, hi);
        let z = shadow_linear_depth(textureLoad(shadow_maps, vec2<i32>(q / sl.texel_uv), i32(layer), 0), sl.near, sl.far);
        // A blocker: nearer than the receiver's own plane there, and inside the cone from the
        // receiver to the light at its own depth (the search region is that cone's widest part).
        let r = length(off);
        if (z < d_r - r * d_r * slope && r <= pcss_search_radius(sl.light_size, d_r, z)) {
            blockers += 1.0;
            depth_sum += z;
        }
    }
    if (blockers == 0.0) {
        return 1.0;
    }
    let w = penumbra_width(sl.light_size, d_r, depth_sum / blockers);
    let radius = max(0.5 * w / max(d_r, BLOCKER_DIST_MIN), sl.texel_uv / per_tan);
    var lit = 0.0;
    for (var i = 0u; i < taps; i++) {
        let off = rot * pcss_filter_tap(i, taps) * radius;
        let q = clamp(uv + off * per_tan, lo, hi);
        let own = shadow_stored_depth(d_r - length(off) * d_r * slope, sl.near, sl.far);
        lit += textureSampleCompareLevel(shadow_maps, shadow_linear, q, layer, own);
    }
    return lit / f32(taps);
}
#endif

#if EFFECT_SHADOW_HARD
// SHADOW_FILTER_HARD: one compare at the nearest texel.
fn shadow_compare_hard(uv: vec2<f32>, layer: u32, depth: f32) -> f32 {
    return textureSampleCompareLevel(shadow_maps, shadow_nearest, uv, layer, depth);
}
#endif

#if EFFECT_SHADOW_PCF
// SHADOW_FILTER_PCF: the hardware's bilinear 2×2 compare.
fn shadow_compare_pcf(uv: vec2<f32>, layer: u32, depth: f32) -> f32 {
    return textureSampleCompareLevel(shadow_maps, shadow_linear, uv, layer, depth);
}
#endif

// 1 where the point at map coordinate `t` (layer `layer`) is lit, 0 where shadowed, between at
// filtered edges. Outside the map's square or depth range nothing is known: lit. Each filter is
// its own effect, in the permutation only when some light uses it: a CPU rasterizer runs the
// code of branches no pixel takes. A filter the permutation lacks leaves the light unshadowed.
// `n_dot_l` is the cosine between the point's normal and its light (PCSS's receiver plane).
fn shadow_compare(sl: ShadowLight, layer: u32, t: vec3<f32>, n_dot_l: f32, pixel: vec2<f32>) -> f32 {
    if (any(t.xy < vec2(0.0)) || any(t.xy > vec2(1.0)) || t.z < 0.0 || t.z > 1.0) {
        return 1.0;
    }
    let uv = t.xy * sl.uv_scale;
#if EFFECT_SHADOW_HARD
    if (sl.shadow_filter == SHADOW_FILTER_HARD) {
        return shadow_compare_hard(uv, layer, t.z);
    }
#endif
#if EFFECT_SHADOW_POISSON
    if (sl.shadow_filter == SHADOW_FILTER_POISSON) {
        return shadow_compare_poisson(sl, uv, layer, t.z, pixel);
    }
#endif
#if EFFECT_SHADOW_PCF
    if (sl.shadow_filter == SHADOW_FILTER_PCF) {
        return shadow_compare_pcf(uv, layer, t.z);
    }
#endif
#if EFFECT_SHADOW_PCSS
    if (sl.shadow_filter == SHADOW_FILTER_PCSS) {
        return shadow_compare_pcss(sl, uv, layer, t.z, n_dot_l, pixel);
    }
#endif
    return 1.0;
}

#if EFFECT_SHADOW_CASCADES
// Which of directional light `sl`'s cascades (finest first) shadows world point `p` with unit
// normal `n`: the first whose map holds the normal-offset point SHADOW_CASCADE_MARGIN_TEXELS from
// its edge (so the filter's taps stay on it) and inside its depth range; the last otherwise.
fn shadow_cascade(sl: ShadowLight, p: vec3<f32>, n: vec3<f32>) -> u32 {
    let resolution = sl.uv_scale / sl.texel_uv;
    let margin = SHADOW_CASCADE_MARGIN_TEXELS / resolution;
    for (var k = 0u; k + 1u < sl.layers; k++) {
        let m = shadows.matrices[min(sl.first_layer + k, MAX_SHADOW_LAYERS - 1u)];
        let q = p + n * (SHADOW_NORMAL_OFFSET_TEXELS * shadow_ortho_texel_world(m, resolution));
        let t = shadow_map_coord(m, q);
        if (all(t.xy >= vec2(margin)) && all(t.xy <= vec2(1.0 - margin)) && t.z >= 0.0 && t.z <= 1.0) {
            return k;
        }
    }
    return sl.layers - 1u;
}
#endif

// How much of light `i` reaches world point `p` with unit normal `n`: 1 lit, 0 in a cast shadow.
// `origin` is where the light (or its point source `j`, drawn as points) sits; a cube light's
// j-th cube holds that source's map. The receiver is first moved along its normal by
// SHADOW_NORMAL_OFFSET_TEXELS texels of the light's map at that point (the normal offset; the
// slope-scaled bias is the shadow pass's).
fn shadow_visibility(i: u32, light: Light, origin: vec3<f32>, j: u32, p: vec3<f32>, n: vec3<f32>, pixel: vec2<f32>) -> f32 {
    let sl = shadows.lights[i];
    if (sl.layers == 0u) {
        return 1.0;
    }
    var layer = sl.first_layer;
    var dist = 0.0;
    // Cube lights have 6 layers a cube; a directional light at most 4 cascades, a spot 1.
    let cube_light = sl.layers >= 6u;
#if EFFECT_POINT_LIGHTS
    // Point and spot lights only: a directional light's position is not read.
    let to_p = p - origin;
    if (cube_light) {
        dist = max(max(abs(to_p.x), abs(to_p.y)), abs(to_p.z));
    }
#if EFFECT_SPOT_LIGHTS
    if (sl.layers == 1u && sl.perspective != 0u) {
        dist = dot(to_p, light.spot_axis.xyz);
    }
#endif
#endif
    var texel = shadow_texel_world(sl.texel_world, sl.perspective != 0u, dist);
#if EFFECT_SHADOW_CASCADES
    // A directional light's cascades: the finest that holds the point, with its own texel size.
    if (sl.perspective == 0u && sl.layers > 1u) {
        layer += shadow_cascade(sl, p, n);
        texel = shadow_ortho_texel_world(shadows.matrices[min(layer, MAX_SHADOW_LAYERS - 1u)], sl.uv_scale / sl.texel_uv);
    }
#endif
    let q = p + n * (SHADOW_NORMAL_OFFSET_TEXELS * texel);
#if EFFECT_POINT_LIGHTS
    // A cube's face is chosen after the offset (the offset point may cross into the next).
    if (cube_light) {
        var cube = 0u;
#if EFFECT_AREA_POINTS
        cube = j % max(sl.cubes, 1u);
#endif
        layer += 6u * cube + shadow_face(q - origin);
    }
#endif
    let t = shadow_map_coord(shadows.matrices[min(layer, MAX_SHADOW_LAYERS - 1u)], q);
    // PCSS's receiver plane: the cosine to the light's centre (it has one only as a point light).
    var n_dot_l = 1.0;
#if EFFECT_SHADOW_PCSS
#if EFFECT_POINT_LIGHTS
    n_dot_l = dot(n, safe_normalize(origin - p, n));
#endif
#endif
    return shadow_compare(sl, layer, t, n_dot_l, pixel);
}

#endif
