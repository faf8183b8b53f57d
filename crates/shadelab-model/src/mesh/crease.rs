//! The chapter's rule for vertex normals (docs/model.md §8): a vertex normal is the plain average
//! of the unit normals of the faces around the vertex *that approximate the same surface*. Faces
//! whose normals differ by more than the crease angle are on different surfaces (the cylinder's
//! caps, the cube's and the pyramid's faces stay sharp, the sphere is smooth). Zero-area faces
//! have no normal of their own; they never make a NaN. Also the welding of given corner normals.

use super::{FlatCorner, MeshData, MeshError, MeshVertex, check_finite, face_normal, key};
use crate::brdf::safe_normalize;
use glam::DVec3;
// FxHash: welding hashes every corner (3 per triangle), and SipHash's resistance to chosen keys
// buys nothing for positions.
use rustc_hash::FxHashMap as HashMap;

/// Faces whose normals differ by more than this belong to different surfaces (not averaged).
/// 60° keeps the cube's 90° and the pyramid's 78° edges sharp and smooths a sphere or cylinder of
/// 8 or more segments (45° between neighbours).
pub const CREASE_ANGLE_DEG: f64 = 60.0;

/// Most faces around one vertex for which the crease-angle rule is evaluated pair by pair (each
/// corner's face against every other face there: work quadratic in the count). A vertex whose
/// faces all lie within half the crease angle of their mean (a smooth vertex, such as a sphere's
/// pole of thousands of faces) needs no pairs and has no limit. Beyond it, at a crease, each
/// corner keeps its own face's normal. Real meshes meet at a crease with a few faces (a cube's
/// corner: 3 to 6, a 64-segment cone's apex: 64); a hostile file can put millions on one vertex,
/// which would take hours pair by pair. With the limit the work is at most
/// `3·triangles·CREASE_VALENCE_MAX` steps.
pub const CREASE_VALENCE_MAX: usize = 64;

/// Build the smooth and flat meshes of a triangle soup with the crease-angle rule.
///
/// Corners that round to the same f32 position are one vertex; the faces around each vertex are
/// kept as compressed rows (one array for all vertices, no list per vertex), and a vertex's
/// corners with the same smooth normal share one smooth vertex. At 10⁷ triangles this is a few
/// flat arrays instead of millions of small allocations. The work is linear in the triangles
/// (see `CREASE_VALENCE_MAX`).
pub fn build_mesh(triangles: &[[DVec3; 3]], crease_angle_deg: f64) -> Result<MeshData, MeshError> {
    check_finite(triangles)?;
    let cos_crease = crease_angle_deg.to_radians().cos();
    let normals: Vec<Option<DVec3>> = triangles.iter().map(face_normal).collect();
    // The vertex of each corner (corner c of triangle t is 3t + c).
    let corner_vertex = corner_vertices(triangles);
    let vertices = corner_vertex.iter().map(|&v| v as usize + 1).max().unwrap_or(0);
    // Faces around vertex v: faces[start[v]..start[v + 1]], in triangle order.
    let (start, faces) = faces_around(&corner_vertex, vertices);
    let mut data = MeshData {
        smooth_vertices: Vec::with_capacity(vertices),
        indices: vec![0; corner_vertex.len()],
        flat_vertices: Vec::with_capacity(corner_vertex.len()),
    };
    // Per vertex: each of its corners' smooth normal; corners with the same normal (as f32, what
    // the GPU sees) share a smooth vertex.
    let cos_half_crease = (crease_angle_deg.to_radians() * 0.5).cos();
    let mut made: Vec<([u32; 3], u32)> = Vec::new();
    for v in 0..vertices {
        let around = &faces[start[v]..start[v + 1]];
        let face_normals = || around.iter().filter_map(|&g| normals[g as usize]);
        // When every face here is within half the crease angle of their mean, every pair is within
        // the crease angle, so every corner sums all of them: once for the vertex, in the same
        // order as the pairwise sum below (the same bits), instead of once per corner.
        let all = face_normals().fold(DVec3::ZERO, |s, n| s + n);
        let mean = safe_normalize(all, DVec3::Y);
        let one_surface = face_normals().all(|n| n.dot(mean) >= cos_half_crease);
        let pairwise = !one_surface && around.len() <= CREASE_VALENCE_MAX;
        made.clear();
        for &t in around {
            let t = t as usize;
            let own = normals[t];
            let fallback = own.unwrap_or(DVec3::Y);
            for c in (0..3).filter(|&c| corner_vertex[3 * t + c] as usize == v) {
                let sum = if one_surface {
                    all
                } else if pairwise {
                    pairwise_sum(around, &normals, own, cos_crease)
                } else {
                    // More faces than CREASE_VALENCE_MAX meeting at a crease: the corner keeps its
                    // own face's normal, and its own vertex (no search among the others).
                    fallback
                };
                let n = safe_normalize(sum, fallback).as_vec3().to_array();
                let bits = n.map(f32::to_bits);
                let found = if one_surface || pairwise { made.iter().find(|(b, _)| *b == bits) } else { None };
                let idx = match found {
                    Some(&(_, i)) => i,
                    None => {
                        let position = triangles[t][c].as_vec3().to_array();
                        data.smooth_vertices.push(MeshVertex { position, normal: n });
                        let i = (data.smooth_vertices.len() - 1) as u32;
                        made.push((bits, i));
                        i
                    }
                };
                data.indices[3 * t + c] = idx;
            }
        }
    }
    for (t, own) in triangles.iter().zip(&normals) {
        data.flat_vertices.extend(FlatCorner::of_triangle(t, own.unwrap_or(DVec3::Y)));
    }
    Ok(data)
}

/// The vertex of each corner (3t + c): corners that round to the same f32 position share one.
fn corner_vertices(triangles: &[[DVec3; 3]]) -> Vec<u32> {
    let mut ids: HashMap<[u32; 3], u32> = HashMap::default();
    triangles
        .iter()
        .flatten()
        .map(|p| {
            let next = ids.len() as u32;
            *ids.entry(key(*p)).or_insert(next)
        })
        .collect()
}

/// The faces around each vertex as compressed rows: vertex v's are `faces[start[v]..start[v + 1]]`.
fn faces_around(corner_vertex: &[u32], vertices: usize) -> (Vec<usize>, Vec<u32>) {
    // A corner whose vertex an earlier corner of the same triangle already has (a degenerate
    // triangle): its face is listed once around that vertex.
    let repeats = |c: usize| (1..=c % 3).any(|k| corner_vertex[c - k] == corner_vertex[c]);
    let mut start = vec![0usize; vertices + 1];
    for (c, &v) in corner_vertex.iter().enumerate() {
        if !repeats(c) {
            start[v as usize + 1] += 1;
        }
    }
    for v in 0..vertices {
        start[v + 1] += start[v];
    }
    let mut faces = vec![0u32; start[vertices]];
    let mut cursor = start.clone();
    for (c, &v) in corner_vertex.iter().enumerate() {
        if !repeats(c) {
            faces[cursor[v as usize]] = (c / 3) as u32;
            cursor[v as usize] += 1;
        }
    }
    (start, faces)
}

/// The sum of the normals of the faces `around` a vertex within the crease angle of `own`'s.
fn pairwise_sum(around: &[u32], normals: &[Option<DVec3>], own: Option<DVec3>, cos_crease: f64) -> DVec3 {
    let mut sum = DVec3::ZERO;
    for &g in around {
        if let Some(ng) = normals[g as usize] {
            // A zero-area face has no surface of its own: it takes every neighbour.
            if own.is_none_or(|nf| nf.dot(ng) >= cos_crease) {
                sum += ng;
            }
        }
    }
    sum
}

/// Builds a [`MeshData`] corner by corner: smooth vertices welded by position and normal (as
/// f32, what the GPU sees), one flat vertex per corner.
#[derive(Default)]
struct Assembler {
    data: MeshData,
    welded: HashMap<([u32; 3], [u32; 3]), u32>,
}

impl Assembler {
    /// Corner `p` of triangle `t` with its smooth normal and its face's normal.
    fn corner(&mut self, t: &[DVec3; 3], p: DVec3, normal: DVec3, face: DVec3) {
        let (pos, n) = (p.as_vec3().to_array(), normal.as_vec3().to_array());
        let smooth = &mut self.data.smooth_vertices;
        let idx = *self.welded.entry((key(p), n.map(f32::to_bits))).or_insert_with(|| {
            smooth.push(MeshVertex { position: pos, normal: n });
            (smooth.len() - 1) as u32
        });
        self.data.indices.push(idx);
        self.data.flat_vertices.push(FlatCorner {
            position: pos,
            normal: face.as_vec3().to_array(),
            centroid: ((t[0] + t[1] + t[2]) / 3.0).as_vec3().to_array(),
        });
    }
}

/// Build the meshes of a triangle soup whose corner normals are given (a scene file's): smooth
/// vertices are welded by position and normal, so a file's hard edges stay hard. A zero or
/// non-finite normal is replaced by the face's (guard `NORMALIZE_MIN_LEN2`).
pub fn build_mesh_with_normals(triangles: &[[DVec3; 3]], normals: &[[DVec3; 3]]) -> Result<MeshData, MeshError> {
    check_finite(triangles)?;
    let mut mesh = Assembler::default();
    for (t, tn) in triangles.iter().zip(normals.iter().chain(std::iter::repeat(&[DVec3::ZERO; 3]))) {
        let face = face_normal(t).unwrap_or(DVec3::Y);
        for (p, n) in t.iter().zip(tn) {
            let n = if n.is_finite() { safe_normalize(*n, face) } else { face };
            mesh.corner(t, *p, n, face);
        }
    }
    Ok(mesh.data)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::mesh::{tessellate, triangles};
    use crate::scene::Shape;

    pub(in crate::mesh) fn unit_normals(m: &MeshData) -> bool {
        m.smooth_vertices.iter().all(|v| {
            let n = glam::Vec3::from(v.normal);
            n.is_finite() && (n.length() - 1.0).abs() < 1e-5
        })
    }

    #[test]
    fn sphere_is_smooth_and_close_to_exact_normals() {
        let m = tessellate(Shape::Sphere, 32);
        // Smooth: one vertex per position (no creases), and the averaged normal is near the radius.
        for v in &m.smooth_vertices {
            let p = glam::Vec3::from(v.position);
            assert!(p.normalize().dot(glam::Vec3::from(v.normal)) > 0.999, "{v:?}");
        }
        let positions: std::collections::HashSet<_> =
            m.smooth_vertices.iter().map(|v| v.position.map(f32::to_bits)).collect();
        assert_eq!(positions.len(), m.smooth_vertices.len());
    }

    #[test]
    fn crease_keeps_cylinder_caps_and_cube_faces_sharp() {
        let m = tessellate(Shape::Cylinder, 16);
        for v in &m.smooth_vertices {
            let n = glam::Vec3::from(v.normal);
            // Either a cap normal (±y) or a side normal (horizontal): never a blend of the two.
            assert!(n.y.abs() > 0.9999 || n.y.abs() < 1e-6, "{v:?}");
        }
        let c = tessellate(Shape::Cube, 2);
        for v in &c.smooth_vertices {
            let n = glam::Vec3::from(v.normal);
            assert!((n.abs().max_element() - 1.0).abs() < 1e-6, "{v:?}");
        }
        let p = tessellate(Shape::Pyramid, 1);
        assert_eq!(p.smooth_vertices.len(), 4 + 4 * 3, "pyramid faces stay separate");
    }

    #[test]
    fn degenerate_and_duplicate_vertex_triangles_get_finite_normals() {
        let a = DVec3::new(0.0, 0.0, 0.0);
        let b = DVec3::new(1.0, 0.0, 0.0);
        let c = DVec3::new(0.0, 0.0, -1.0);
        let tris = [[a, b, c], [a, a, b], [a, b, b * 2.0], [c, c, c]];
        let m = build_mesh(&tris, CREASE_ANGLE_DEG).unwrap();
        assert!(unit_normals(&m));
        for v in &m.flat_vertices {
            assert!(glam::Vec3::from(v.normal).is_finite() && glam::Vec3::from(v.centroid).is_finite());
        }
        // The degenerate triangles touching the good one take its normal (+y here).
        assert!(m.smooth_vertices.iter().all(|v| v.normal[1] > 0.999));
    }

    #[test]
    fn non_finite_positions_are_an_error() {
        let t = [[DVec3::ZERO, DVec3::X, DVec3::new(f64::NAN, 0.0, 1.0)]];
        let e = build_mesh(&t, CREASE_ANGLE_DEG).unwrap_err();
        assert!(e.to_string().contains("triangle 0, corner 2"), "{e}");
        let t = [[DVec3::ZERO, DVec3::splat(f64::INFINITY), DVec3::Z]];
        assert!(build_mesh(&t, CREASE_ANGLE_DEG).is_err());
    }

    /// The crease-angle rule stated directly: the normal at a corner is the normalized sum of the
    /// normals of every face touching its position that lies within the crease angle of its own
    /// face (all of them for a zero-area face), each face once.
    fn rule(tris: &[[DVec3; 3]], t: usize, c: usize) -> [f32; 3] {
        let cos = CREASE_ANGLE_DEG.to_radians().cos();
        let own = face_normal(&tris[t]);
        let mut sum = DVec3::ZERO;
        for g in tris.iter().filter(|g| g.iter().any(|q| key(*q) == key(tris[t][c]))) {
            if let Some(ng) = face_normal(g)
                && own.is_none_or(|nf| nf.dot(ng) >= cos)
            {
                sum += ng;
            }
        }
        safe_normalize(sum, own.unwrap_or(DVec3::Y)).as_vec3().to_array()
    }

    #[test]
    fn build_mesh_follows_the_rule_and_shares_each_distinct_vertex_once() {
        let mut cases: Vec<Vec<[DVec3; 3]>> = Shape::ALL.iter().map(|&s| triangles(s, 6)).collect();
        // A zero-area triangle with two corners at one position, beside a normal one.
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::Y);
        cases.push(vec![[a, b, c], [a, a, b]]);
        for tris in cases {
            let m = build_mesh(&tris, CREASE_ANGLE_DEG).unwrap();
            assert_eq!(m.indices.len(), 3 * tris.len());
            let mut distinct = std::collections::HashSet::new();
            for (t, tri) in tris.iter().enumerate() {
                for (c, p) in tri.iter().enumerate() {
                    let v = m.smooth_vertices[m.indices[3 * t + c] as usize];
                    assert_eq!(v.position, p.as_vec3().to_array(), "triangle {t} corner {c}");
                    assert_eq!(v.normal, rule(&tris, t, c), "triangle {t} corner {c}");
                    distinct.insert((key(*p), v.normal.map(f32::to_bits)));
                }
            }
            assert_eq!(m.smooth_vertices.len(), distinct.len(), "each (position, normal) once");
            assert_eq!(m.flat_vertices.len(), 3 * tris.len());
        }
    }

    #[test]
    fn many_faces_at_one_vertex_take_linear_work() {
        // A sphere's pole: 200 faces, all on one surface, so the rule holds exactly beyond
        // CREASE_VALENCE_MAX.
        let tris = triangles(Shape::Sphere, 200);
        let m = build_mesh(&tris, CREASE_ANGLE_DEG).unwrap();
        let mut pole = 0;
        for (t, tri) in tris.iter().enumerate() {
            for (c, p) in tri.iter().enumerate().filter(|(_, p)| p.y > 1.0 - 1e-12) {
                assert_eq!(m.smooth_vertices[m.indices[3 * t + c] as usize].normal, rule(&tris, t, c), "{p}");
                pole += 1;
            }
        }
        assert!(pole >= 200, "{pole} corners at the pole");
        // A cone's apex: 100 faces 45° off the axis, opposite ones 90° apart (a crease), more than
        // CREASE_VALENCE_MAX: each corner keeps its own face's normal.
        let n = 100;
        assert!(n > CREASE_VALENCE_MAX);
        let rim = |k: usize| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            DVec3::new(a.cos(), 0.0, -a.sin())
        };
        let cone: Vec<[DVec3; 3]> = (0..n).map(|k| [DVec3::Y, rim(k), rim(k + 1)]).collect();
        let m = build_mesh(&cone, CREASE_ANGLE_DEG).unwrap();
        for (t, tri) in cone.iter().enumerate() {
            let own = face_normal(tri).unwrap().as_vec3().to_array();
            assert_eq!(m.smooth_vertices[m.indices[3 * t] as usize].normal, own, "apex corner of face {t}");
        }
        // A hostile file's million zero-area triangles on one vertex: no surface, one vertex.
        let degenerate = vec![[DVec3::ZERO; 3]; 1_000_000];
        let m = build_mesh(&degenerate, CREASE_ANGLE_DEG).unwrap();
        assert_eq!((m.smooth_vertices.len(), m.indices.len()), (1, 3_000_000));
    }
}
