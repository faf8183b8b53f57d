//! Ray intersection for the reference: a ray against the exact analytic shapes and a file's
//! triangles, the nearest hit of a camera ray, and whether anything lies on a shadow ray's
//! segment.

use super::bvh::Bvh;
use crate::lighting::common::safe_normalize;
use crate::lighting::transmission::{CUBE_PLANES, PYRAMID_PLANES};
use crate::mesh::{TriangleMesh, face_normal};
use crate::scene::{Scene, Shape};
use glam::{DMat3, DMat4, DVec3};

/// What a ray needs beside the scene: each object's inverse transform, its box in the world and
/// each mesh's hierarchy, made once per image.
pub(crate) struct Geometry {
    pub inverses: Vec<DMat4>,
    /// Each object's transform and the matrix that carries its normals, built once rather than
    /// at every hit.
    pub to_world: Vec<(DMat4, DMat3)>,
    /// Each object's world box, grown by [`BOX_PAD_REL`]: a ray that misses it misses the object,
    /// so [`trace`] and [`occluded`] move it into object space only when it meets the box.
    pub boxes: Vec<(DVec3, DVec3)>,
    pub bvhs: Vec<Bvh>,
}

impl Geometry {
    pub fn new(scene: &Scene) -> Geometry {
        Geometry {
            inverses: scene.objects.iter().map(|o| o.transform.matrix().inverse()).collect(),
            to_world: scene.objects.iter().map(|o| (o.transform.matrix(), o.transform.normal_matrix())).collect(),
            boxes: scene.objects.iter().map(|o| world_box(scene, o)).collect(),
            bvhs: scene.meshes.iter().map(Bvh::build).collect(),
        }
    }
}

/// An object's world box grows by this share of its largest coordinate's size on every side:
/// a ray's crossing computed in object space and the box's in the world differ by rounding
/// (about 1e-15 of those sizes), so 1e-9 keeps every crossing inside the box.
pub const BOX_PAD_REL: f64 = 1e-9;

/// The world box of `obj`: the corners of its object-space box (the unit shapes' [−1, 1]³, a
/// mesh's bounds) through its transform, grown by [`BOX_PAD_REL`]; unbounded for a mesh with no
/// triangles or a transform that is not finite.
fn world_box(scene: &Scene, obj: &crate::scene::Object) -> (DVec3, DVec3) {
    let everywhere = (DVec3::NEG_INFINITY, DVec3::INFINITY);
    let (lo, hi) = match obj.shape {
        Shape::Mesh(m) => match scene.meshes.get(m).and_then(|mesh| mesh.bounds()) {
            Some(b) => b,
            None => return everywhere,
        },
        _ => (DVec3::NEG_ONE, DVec3::ONE),
    };
    let to_world = obj.transform.matrix();
    let corners = (0..8).map(|k| {
        let pick = |bit: usize, a: f64, b: f64| if k & bit == 0 { a } else { b };
        to_world.transform_point3(DVec3::new(pick(1, lo.x, hi.x), pick(2, lo.y, hi.y), pick(4, lo.z, hi.z)))
    });
    let (wlo, whi) = corners.fold((everywhere.1, everywhere.0), |(a, b), c| (a.min(c), b.max(c)));
    let pad = BOX_PAD_REL * wlo.abs().max(whi.abs()).max_element();
    if !pad.is_finite() {
        return everywhere;
    }
    (wlo - DVec3::splat(pad), whi + DVec3::splat(pad))
}

/// Whether the ray `o + t·dir` (`ray`: 1/dir per axis) may meet the box `b` for some `t` in
/// `[0, t_max]`: false only where the slab test proves it apart, so a NaN lets the object's own
/// test decide.
fn may_meet(b: &(DVec3, DVec3), o: DVec3, ray: SlabRay, t_max: f64) -> bool {
    let (a, c) = ((b.0 - o) * ray.inv, (b.1 - o) * ray.inv);
    if ray.finite {
        // No product is NaN: plain comparisons decide as the NaN-aware min and max would.
        let lt = |x: f64, y: f64| if x < y { x } else { y };
        let gt = |x: f64, y: f64| if x > y { x } else { y };
        let t0 = gt(gt(gt(lt(a.x, c.x), lt(a.y, c.y)), lt(a.z, c.z)), 0.0);
        let t1 = lt(lt(lt(gt(a.x, c.x), gt(a.y, c.y)), gt(a.z, c.z)), t_max);
        return !(t0 > t1);
    }
    let (near, far) = (a.min(c), a.max(c));
    let t0 = near.x.max(near.y).max(near.z).max(0.0);
    let t1 = far.x.min(far.y).min(far.z).min(t_max);
    !(t0 > t1)
}

/// A ray's reciprocal direction for [`may_meet`], and whether the start, the direction and its
/// reciprocal are all finite: then a slab product (a finite or infinite bound less the start,
/// times a finite non-zero reciprocal) is never NaN, which only a zero times an infinity makes.
#[derive(Clone, Copy)]
struct SlabRay {
    inv: DVec3,
    finite: bool,
}

impl SlabRay {
    fn new(o: DVec3, dir: DVec3) -> SlabRay {
        let inv = dir.recip();
        SlabRay { inv, finite: o.is_finite() && dir.is_finite() && inv.is_finite() }
    }
}

/// Rays starting closer than this (in object-space ray parameter) do not count as hits: the
/// camera is outside every shape.
pub(super) const RAY_T_MIN: f64 = 1e-9;

/// A ray counts as parallel to a plane, or to a triangle's plane, when the dot product deciding
/// the hit is smaller than this: only an exactly parallel ray gets there, and the division by it
/// would overflow.
const PARALLEL_DENOM_MIN: f64 = 1e-300;

/// A hit: ray parameter and object-space unit normal.
type Hit = (f64, DVec3);

/// The nearest surface a camera ray sees.
pub(crate) struct SurfaceHit {
    pub object: usize,
    pub point: DVec3,
    /// World unit normal the surface is shaded with (a file's interpolated normals).
    pub normal: DVec3,
    /// World unit normal of the surface's geometry (a triangle's face normal; the exact normal of
    /// an analytic shape): the side a shadow ray leaves from.
    pub geometric_normal: DVec3,
    /// The file mesh's texture coordinates and vertex colour at the point, interpolated as the
    /// GPU does (barycentric in object space is perspective-correct); (0, 0) and white elsewhere.
    pub uv: [f64; 2],
    pub vertex_color: [f64; 3],
    /// The mesh triangle hit (file meshes only).
    pub triangle: Option<usize>,
    /// The mesh's tangent at the point in world space (xyz carried by the object's transform, as
    /// the GPU's vertex stage does) and its bitangent sign w; zero without tangents.
    pub tangent: [f64; 4],
}

/// Where a ray meets a file's mesh: ray parameter, shading and face normals, the triangle and the
/// barycentric weights of its corners 1 and 2.
type MeshHit = (f64, DVec3, DVec3, usize, f64, f64);

/// A per-vertex attribute of triangle `k` interpolated at barycentric `(u, v)`.
fn interpolate<const N: usize>(values: &[[f32; N]], tri: [u32; 3], u: f64, v: f64) -> [f64; N] {
    let at = |c: usize| values[tri[c] as usize].map(f64::from);
    let (a, b, c) = (at(0), at(1), at(2));
    std::array::from_fn(|i| a[i] * (1.0 - u - v) + b[i] * u + c[i] * v)
}

/// The ray parameters where a ray enters and leaves a convex polyhedron
/// `{x : n·x ≤ d for all planes}` (`t_in ≤ t_out`), and the entry plane's normal.
fn convex_span(o: DVec3, dir: DVec3, planes: &[(DVec3, f64)]) -> Option<(f64, f64, DVec3)> {
    span_of(planes.iter().map(|&(n, d)| (n, n.dot(dir), d - n.dot(o))))
}

/// [`convex_span`] of the unit cube, its planes `CUBE_PLANES` in their order with each plane's
/// dot products read off one axis: `n·dir` is `±dir[a]` and `1 − n·o` is `1 ∓ o[a]`, the same
/// values for a finite ray, without building the planes at every ray.
fn cube_span(o: DVec3, dir: DVec3) -> Option<(f64, f64, DVec3)> {
    span_of(CUBE_PLANES.into_iter().enumerate().map(|(k, n)| {
        let a = k / 2;
        if k % 2 == 0 { (n, dir[a], 1.0 - o[a]) } else { (n, -dir[a], 1.0 + o[a]) }
    }))
}

/// The span of a ray in a convex polyhedron from each plane's normal `n`, `n·dir` and the start's
/// distance inside it `d − n·o`: the latest entry, the earliest exit. Inlined into each caller,
/// where the planes' loop unrolls (called, it cost the Cornell box 6 %).
#[inline(always)]
fn span_of(planes: impl Iterator<Item = (DVec3, f64, f64)>) -> Option<(f64, f64, DVec3)> {
    let (mut t_in, mut t_out, mut n_in) = (f64::NEG_INFINITY, f64::INFINITY, DVec3::ZERO);
    for (n, denom, dist) in planes {
        if denom.abs() < PARALLEL_DENOM_MIN {
            if dist < 0.0 {
                return None;
            }
            continue;
        }
        let t = dist / denom;
        if denom < 0.0 {
            if t > t_in {
                t_in = t;
                n_in = n;
            }
        } else if t < t_out {
            t_out = t;
        }
    }
    (t_in <= t_out).then_some((t_in, t_out, n_in))
}

/// Intersect a ray with a convex polyhedron from outside: its entry point.
fn convex(o: DVec3, dir: DVec3, planes: &[(DVec3, f64)]) -> Option<Hit> {
    entry(convex_span(o, dir, planes)?)
}

/// The entry point of a convex shape's span along a ray, where it lies ahead.
fn entry((t_in, _, n_in): (f64, f64, DVec3)) -> Option<Hit> {
    (t_in > RAY_T_MIN).then(|| (t_in, n_in.normalize()))
}

fn solve_quadratic(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 || a == 0.0 {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (t0, t1) = (q / a, c / q);
    Some((t0.min(t1), t0.max(t1)))
}

/// A unit shape's faces `n·p ≤ 1` (`transmission::CUBE_PLANES`, `PYRAMID_PLANES`) as the
/// `(n, d)` pairs of `convex_span`.
fn faces<const N: usize>(planes: [DVec3; N]) -> [(DVec3, f64); N] {
    planes.map(|n| (n, 1.0))
}

/// Intersect a ray (object space, `dir` not necessarily unit) with a unit shape. A
/// `Shape::Mesh` has no analytic form and is not hit here: [`trace`] intersects its triangles.
pub(super) fn intersect_shape(shape: Shape, o: DVec3, dir: DVec3) -> Option<Hit> {
    match shape {
        Shape::Mesh(_) => None,
        Shape::Sphere => {
            let (t0, t1) = solve_quadratic(dir.dot(dir), 2.0 * o.dot(dir), o.dot(o) - 1.0)?;
            let t = if t0 > RAY_T_MIN { t0 } else { t1 };
            (t > RAY_T_MIN).then(|| (t, (o + dir * t).normalize()))
        }
        Shape::Cylinder => {
            let mut best: Option<Hit> = None;
            let mut consider = |h: Hit| {
                if h.0 > RAY_T_MIN && best.is_none_or(|b| h.0 < b.0) {
                    best = Some(h);
                }
            };
            let (a, b, c) =
                (dir.x * dir.x + dir.z * dir.z, 2.0 * (o.x * dir.x + o.z * dir.z), o.x * o.x + o.z * o.z - 1.0);
            if let Some((t0, t1)) = solve_quadratic(a, b, c) {
                for t in [t0, t1] {
                    let p = o + dir * t;
                    if p.y.abs() <= 1.0 {
                        consider((t, DVec3::new(p.x, 0.0, p.z).normalize()));
                    }
                }
            }
            if dir.y != 0.0 {
                for y in [-1.0, 1.0] {
                    let t = (y - o.y) / dir.y;
                    let p = o + dir * t;
                    if p.x * p.x + p.z * p.z <= 1.0 {
                        consider((t, DVec3::new(0.0, y, 0.0)));
                    }
                }
            }
            best
        }
        Shape::Cube => entry(cube_span(o, dir)?),
        Shape::Plane => {
            if dir.y == 0.0 {
                return None;
            }
            let t = -o.y / dir.y;
            let p = o + dir * t;
            (t > RAY_T_MIN && p.x.abs() <= 1.0 && p.z.abs() <= 1.0).then_some((t, DVec3::Y))
        }
        Shape::Pyramid => convex(o, dir, &faces(PYRAMID_PLANES)),
    }
}

/// The first ray parameter after `RAY_T_MIN` where a ray (object space) crosses a unit shape's
/// surface, entering or leaving it: a shadow ray may start inside a closed shape.
fn first_crossing(shape: Shape, o: DVec3, dir: DVec3) -> Option<f64> {
    // A convex shape's span: its entry where that lies ahead, else its exit.
    let crossing = |(t_in, t_out, _): (f64, f64, DVec3)| [t_in, t_out].into_iter().find(|&t| t > RAY_T_MIN);
    match shape {
        Shape::Cube => crossing(cube_span(o, dir)?),
        Shape::Pyramid => crossing(convex_span(o, dir, &faces(PYRAMID_PLANES))?),
        // The sphere and cylinder tests take the exit when the entry is behind; the plane and
        // meshes have one crossing per surface.
        shape => intersect_shape(shape, o, dir).map(|h| h.0),
    }
}

/// Möller–Trumbore: the ray parameter and barycentric `(u, v)` where a ray crosses triangle `t`
/// from either side.
fn intersect_triangle(t: &[DVec3; 3], o: DVec3, dir: DVec3) -> Option<(f64, f64, f64)> {
    let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
    let p = dir.cross(e2);
    let det = e1.dot(p);
    if det.abs() < PARALLEL_DENOM_MIN {
        return None;
    }
    let s = o - t[0];
    let u = s.dot(p) / det;
    let q = s.cross(e1);
    let v = dir.dot(q) / det;
    let tt = e2.dot(q) / det;
    ((0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && tt > RAY_T_MIN).then_some((tt, u, v))
}

/// Intersect a ray (object space) with a file's triangle mesh through its hierarchy: ray
/// parameter, shading normal (the file's corner normals interpolated, or the face normal; it faces
/// the ray's origin side as the face's winding says, no flipping) and face normal. Of triangles
/// hit at the same parameter, the lowest index wins, as a walk over every triangle in order would.
fn intersect_mesh(mesh: &TriangleMesh, bvh: &Bvh, o: DVec3, dir: DVec3) -> Option<MeshHit> {
    let mut best: Option<(f64, usize, f64, f64)> = None;
    bvh.walk(o, dir, f64::INFINITY, |k, t_max| {
        if let Some((tt, u, v)) = intersect_triangle(&mesh.triangle(k), o, dir)
            && tt <= t_max
            && best.is_none_or(|b| tt < b.0 || (tt == b.0 && k < b.1))
        {
            best = Some((tt, k, u, v));
            return Some(tt);
        }
        Some(t_max)
    });
    let (tt, k, u, v) = best?;
    let face = face_normal(&mesh.triangle(k)).unwrap_or(DVec3::Y);
    let n = match mesh.corner_normals(k) {
        Some(c) => safe_normalize(c[0] * (1.0 - u - v) + c[1] * u + c[2] * v, face),
        None => face,
    };
    Some((tt, n, face, k, u, v))
}

/// The nearest hit of a world ray among the scene's objects (`inverses`: each object's inverse
/// transform).
pub(super) fn trace(scene: &Scene, geo: &Geometry, o: DVec3, dir: DVec3) -> Option<SurfaceHit> {
    // Ray parameter, object, shading and face normals, texture coordinates, vertex colour,
    // object-space tangent, mesh triangle.
    type Best = (f64, usize, DVec3, DVec3, [f64; 2], [f64; 3], [f64; 4], Option<usize>);
    let mut best: Option<Best> = None;
    let slab = SlabRay::new(o, dir);
    for (i, (obj, inv)) in scene.objects.iter().zip(&geo.inverses).enumerate() {
        if !may_meet(&geo.boxes[i], o, slab, best.map_or(f64::INFINITY, |b| b.0)) {
            continue;
        }
        let (lo, ld) = (inv.transform_point3(o), inv.transform_vector3(dir));
        let hit = match obj.shape {
            Shape::Mesh(m) => scene.meshes.get(m).and_then(|mesh| {
                let (t, n, face, k, u, v) = intersect_mesh(mesh, geo.bvhs.get(m)?, lo, ld)?;
                let tri = mesh.indices[k];
                let uv = mesh
                    .uvs
                    .as_ref()
                    .filter(|a| a.len() == mesh.positions.len())
                    .map_or([0.0; 2], |uvs| interpolate(uvs, tri, u, v));
                let color = mesh
                    .colors
                    .as_ref()
                    .filter(|a| a.len() == mesh.positions.len())
                    .map_or([1.0; 3], |c| interpolate(c, tri, u, v));
                let tangent = mesh
                    .tangents
                    .as_ref()
                    .filter(|a| a.len() == mesh.positions.len())
                    .map_or([0.0; 4], |ts| interpolate(ts, tri, u, v));
                Some((t, n, face, uv, color, tangent, Some(k)))
            }),
            shape => intersect_shape(shape, lo, ld).map(|(t, n)| (t, n, n, [0.0; 2], [1.0; 3], [0.0; 4], None)),
        };
        if let Some((t, n, face, uv, color, tangent, k)) = hit
            && best.is_none_or(|b| t < b.0)
        {
            best = Some((t, i, n, face, uv, color, tangent, k));
        }
    }
    best.map(|(t, i, n, face, uv, vertex_color, tangent, triangle)| {
        let (matrix, to_world) = geo.to_world[i];
        let tw = matrix.transform_vector3(DVec3::new(tangent[0], tangent[1], tangent[2]));
        SurfaceHit {
            object: i,
            point: o + dir * t,
            normal: (to_world * n).normalize(),
            geometric_normal: safe_normalize(to_world * face, DVec3::Y),
            uv,
            vertex_color,
            tangent: [tw.x, tw.y, tw.z, tangent[3]],
            triangle,
        }
    })
}

/// Where a world ray from `o` inside object `i` along `dir` leaves it: the point and the outward
/// world unit normal there. An analytic shape's exit is exact (`shape_exit`); a mesh's is its
/// nearest triangle ahead, its face normal turned along the ray. `None` when nothing is ahead.
pub(super) fn glass_exit(scene: &Scene, geo: &Geometry, i: usize, o: DVec3, dir: DVec3) -> Option<(DVec3, DVec3)> {
    let obj = &scene.objects[i];
    let inv = geo.inverses[i];
    let (lo, ld) = (inv.transform_point3(o), inv.transform_vector3(dir));
    let (t, n) = match obj.shape {
        Shape::Mesh(m) => {
            let (t, _, face, ..) = intersect_mesh(scene.meshes.get(m)?, geo.bvhs.get(m)?, lo, ld)?;
            (t, if face.dot(ld) < 0.0 { -face } else { face })
        }
        shape => crate::lighting::transmission::shape_exit(shape.exit_code(), lo, ld)?,
    };
    let normal = safe_normalize(geo.to_world[i].1 * n, dir);
    Some((o + dir * t, normal))
}

/// The texture coordinates where the world ray `o + t·dir` meets the plane of triangle `k` of
/// object `object`'s mesh, its barycentric weights extended past the edges: a neighbouring
/// pixel's coordinates on the same surface, as the GPU's derivatives difference them. `None`
/// without coordinates or for a ray along the plane.
pub(super) fn uv_on_triangle_plane(
    scene: &Scene,
    inverses: &[DMat4],
    object: usize,
    k: usize,
    o: DVec3,
    dir: DVec3,
) -> Option<[f64; 2]> {
    let Shape::Mesh(m) = scene.objects.get(object)?.shape else { return None };
    let mesh = scene.meshes.get(m)?;
    let uvs = mesh.uvs.as_ref().filter(|a| a.len() == mesh.positions.len())?;
    let [p0, p1, p2] = mesh.triangle(k);
    let inv = inverses.get(object)?;
    let (lo, ld) = (inv.transform_point3(o), inv.transform_vector3(dir));
    let (e1, e2) = (p1 - p0, p2 - p0);
    let nf = e1.cross(e2);
    let denom = nf.dot(ld);
    if denom.abs() <= RAY_PLANE_DENOM_MIN * nf.length() * ld.length() {
        return None;
    }
    let w = lo + ld * (nf.dot(p0 - lo) / denom) - p0;
    let (d00, d01, d11, d20, d21) = (e1.dot(e1), e1.dot(e2), e2.dot(e2), w.dot(e1), w.dot(e2));
    let den = d00 * d11 - d01 * d01;
    if den.abs() <= f64::MIN_POSITIVE {
        return None;
    }
    let (u, v) = ((d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den);
    Some(interpolate(uvs, mesh.indices[k], u, v))
}

/// A ray this close to a triangle's plane (the sine of the angle between them) meets it nowhere
/// useful: the footprint there is unbounded, and the GPU would pick the coarsest level anyway.
const RAY_PLANE_DENOM_MIN: f64 = 1e-12;

/// Whether any object's surface crosses the world ray `o + t·dir` for `t` in (`RAY_T_MIN`,
/// `t_max`): the shadow ray's test, stopping at the first occluder found.
pub(super) fn occluded(scene: &Scene, geo: &Geometry, o: DVec3, dir: DVec3, t_max: f64) -> bool {
    occluded_among(scene, geo, 0..scene.objects.len(), o, dir, t_max)
}

/// [`occluded`] among the objects `among` only (indices into the scene's objects): the same
/// answer wherever the others cannot meet the segment.
pub(super) fn occluded_among(
    scene: &Scene,
    geo: &Geometry,
    among: impl IntoIterator<Item = usize>,
    o: DVec3,
    dir: DVec3,
    t_max: f64,
) -> bool {
    let slab = SlabRay::new(o, dir);
    among.into_iter().any(|i| {
        let (obj, inv, b) = (&scene.objects[i], &geo.inverses[i], &geo.boxes[i]);
        if !may_meet(b, o, slab, t_max) {
            return false;
        }
        let (lo, ld) = (inv.transform_point3(o), inv.transform_vector3(dir));
        match obj.shape {
            Shape::Mesh(m) => scene.meshes.get(m).zip(geo.bvhs.get(m)).is_some_and(|(mesh, bvh)| {
                let mut hit = false;
                bvh.walk(lo, ld, t_max, |k, t| {
                    hit = intersect_triangle(&mesh.triangle(k), lo, ld).is_some_and(|(tt, _, _)| tt < t_max);
                    (!hit).then_some(t)
                });
                hit
            }),
            shape => first_crossing(shape, lo, ld).is_some_and(|t| t < t_max),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::triangles;

    /// Every analytic shape agrees with its own tessellation: rays that hit a fine mesh's
    /// triangle hit the shape at nearly the same distance.
    #[test]
    fn analytic_shapes_match_their_tessellation() {
        for shape in Shape::ALL {
            let tris = triangles(shape, 64);
            for (k, t) in tris.iter().enumerate().step_by(97) {
                let c = (t[0] + t[1] + t[2]) / 3.0;
                let from = c * 3.0 + DVec3::new(0.1, 2.5, 0.2) * if shape == Shape::Plane { 1.0 } else { 0.0 };
                let dir = c - from;
                let hit = intersect_shape(shape, from, dir);
                let (t_hit, _) = hit.unwrap_or_else(|| panic!("{shape:?} triangle {k} missed"));
                assert!((t_hit - 1.0).abs() < 0.01, "{shape:?} triangle {k}: t = {t_hit}");
            }
        }
    }

    /// The cube's own span is the general convex span of its planes, bit for bit, for rays from
    /// everywhere, those along an axis and those in a face's plane included.
    #[test]
    fn the_cubes_span_is_the_convex_span_of_its_planes() {
        let mut seed = 7u64;
        let mut next = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 6.0 - 3.0
        };
        let mut rays: Vec<(DVec3, DVec3)> =
            (0..20_000).map(|_| (DVec3::new(next(), next(), next()), DVec3::new(next(), next(), next()))).collect();
        rays.extend([
            (DVec3::new(0.2, 3.0, -0.1), DVec3::NEG_Y),
            (DVec3::new(1.0, 0.5, 3.0), DVec3::NEG_Z),
            (DVec3::new(-2.0, 1.0, 1.0), DVec3::X),
            (DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.0, 1.0, 0.0)),
        ]);
        for (o, dir) in rays {
            let general = convex_span(o, dir, &faces(CUBE_PLANES));
            let own = cube_span(o, dir);
            let bits = |s: Option<(f64, f64, DVec3)>| {
                s.map(|(a, b, n)| (a.to_bits(), b.to_bits(), n.to_array().map(f64::to_bits)))
            };
            assert_eq!(bits(own), bits(general), "from {o} along {dir}");
        }
    }

    #[test]
    fn normals_point_out() {
        for shape in [Shape::Sphere, Shape::Cylinder, Shape::Cube, Shape::Pyramid] {
            for dir in [DVec3::X, DVec3::NEG_Y, DVec3::new(0.3, -0.2, -1.0)] {
                let o = -dir * 10.0 + DVec3::new(0.0, -0.3, 0.0);
                let (t, n) = intersect_shape(shape, o, dir).unwrap();
                assert!(n.dot(dir) < 0.0, "{shape:?} {dir}: normal {n} at t {t}");
            }
        }
    }

    /// A ray from inside a closed shape crosses its surface once, on the way out; from outside
    /// it crosses first on the way in.
    #[test]
    fn a_ray_from_inside_crosses_on_the_way_out() {
        for shape in [Shape::Sphere, Shape::Cylinder, Shape::Cube, Shape::Pyramid] {
            for dir in [DVec3::X, DVec3::NEG_Y, DVec3::Y, DVec3::new(0.3, -0.2, -1.0).normalize()] {
                let inside = DVec3::new(0.05, -0.3, 0.02);
                let t = first_crossing(shape, inside, dir).unwrap_or_else(|| panic!("{shape:?} {dir}: no exit"));
                assert!(t > 0.0 && t < 3.0, "{shape:?} {dir}: exit at {t}");
                let outside = inside - dir * 10.0;
                let t_in = first_crossing(shape, outside, dir).unwrap();
                assert!(t_in < 10.0, "{shape:?} {dir}: first crossing {t_in} is not the entry");
            }
        }
    }
}

/// One mesh's hierarchy on its own, for measuring it against another (`studies/bvh`): the same
/// build and the same nearest-hit walk the reference's rays take.
pub struct MeshHierarchy<'m> {
    mesh: &'m TriangleMesh,
    bvh: Bvh,
}

impl<'m> MeshHierarchy<'m> {
    pub fn build(mesh: &'m TriangleMesh) -> MeshHierarchy<'m> {
        MeshHierarchy { mesh, bvh: Bvh::build(mesh) }
    }

    /// Bytes the hierarchy holds (the mesh's own triangles not counted).
    pub fn bytes(&self) -> usize {
        self.bvh.bytes()
    }

    /// Where a ray from `o` along `dir` meets triangle `k` alone: its ray parameter.
    pub fn triangle_hit(&self, k: usize, o: DVec3, dir: DVec3) -> Option<f64> {
        intersect_triangle(&self.mesh.triangle(k), o, dir).map(|(t, _, _)| t)
    }

    /// The nearest triangle a ray from `o` along `dir` meets: its ray parameter and index.
    pub fn nearest(&self, o: DVec3, dir: DVec3) -> Option<(f64, usize)> {
        intersect_mesh(self.mesh, &self.bvh, o, dir).map(|(t, _, _, k, _, _)| (t, k))
    }
}
