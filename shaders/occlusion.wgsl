// The environment's occlusion from the grid precomputed over the scene: globals.env_occlusion
// holds its origin and cell, then its node counts; env_occlusion_nodes (bindings.wgsl) two words
// a node, the open share about +x, −x, +y, −y, +z, −z and whether the node is open, a byte each.
// The f64 twin is crates/shadelab-model/src/lighting/occlusion.rs.

#if EFFECT_ENVIRONMENT_OCCLUSION
const OCC_LOOKUP_CELLS: f32 = 0.5;
const OCC_WEIGHT_MIN: f32 = 1e-4;
const OCC_COORD_MAX: f32 = 1e6;

// A node's ambient cube at unit n (its bytes unpacked: lo = +x, −x, +y, −y; hi = +z, −z, open):
// each axis's share weighed by n's squared component along it, the side n faces.
fn occ_cube(lo: vec4<f32>, hi: vec4<f32>, n: vec3<f32>) -> f32 {
    let x = select(lo.y, lo.x, n.x >= 0.0);
    let y = select(lo.w, lo.z, n.y >= 0.0);
    let z = select(hi.y, hi.x, n.z >= 0.0);
    return x * n.x * n.x + y * n.y * n.y + z * n.z * n.z;
}

// The open share at world point p with unit normal n: the open nodes around
// p + n·OCC_LOOKUP_CELLS·cell, trilinearly weighed; 1 where none is near or p is far outside.
fn env_occlusion(p: vec3<f32>, n: vec3<f32>) -> f32 {
    let cell = globals.env_occlusion[0].w;
    let dims = globals.env_occlusion[1].xyz;
    let q = (p + n * (OCC_LOOKUP_CELLS * cell) - globals.env_occlusion[0].xyz) / cell;
    if (!all(abs(q) < vec3(OCC_COORD_MAX))) {
        return 1.0;
    }
    let top = dims - 1.0;
    let qc = clamp(q, vec3(0.0), top);
    // The cell's lower corner, kept one node below the top so that its upper corner exists.
    let base = min(floor(qc), top - 1.0);
    let f = qc - base;
    let b = vec3<u32>(base);
    let d = vec3<u32>(dims);
    var sum = 0.0;
    var weight = 0.0;
    for (var k = 0u; k < 8u; k++) {
        let corner = vec3(k & 1u, (k >> 1u) & 1u, (k >> 2u) & 1u);
        let t = select(1.0 - f, f, corner == vec3(1u));
        let i = b + corner;
        let words = env_occlusion_nodes[i.x + d.x * (i.y + d.y * i.z)];
        let lo = unpack4x8unorm(words.x);
        let hi = unpack4x8unorm(words.y);
        let w = t.x * t.y * t.z * hi.z;
        sum += w * occ_cube(lo, hi, n);
        weight += w;
    }
    return select(sum / weight, 1.0, weight < OCC_WEIGHT_MIN);
}
#endif
