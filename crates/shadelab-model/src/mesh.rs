//! Tessellation of the analytic shapes and vertex normals by the chapter's rule (spec §8).
//!
//! A vertex normal is the plain average of the unit normals of the faces around the vertex *that
//! approximate the same surface*: faces whose normals differ by more than the crease angle are on
//! different surfaces (the cylinder's caps, the cube's and the pyramid's faces stay sharp, the
//! sphere is smooth). Zero-area faces have no normal of their own; they never make a NaN.

use crate::brdf::safe_normalize;
use crate::guards::NORMALIZE_MIN_LEN2;
use crate::scene::Shape;
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

/// A vertex of the smooth (indexed) mesh: Gouraud and Phong shading.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct SmoothVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
}

/// A corner of the flat (unindexed) mesh: each face carries its own normal and the centroid where
/// flat shading evaluates the lighting once for the whole face.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FlatVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub centroid: [f32; 3],
}

/// A tessellated shape ready for the GPU, in object space.
#[derive(Clone, Debug, Default)]
pub struct MeshData {
    pub smooth_vertices: Vec<SmoothVertex>,
    pub indices: Vec<u32>,
    pub flat_vertices: Vec<FlatVertex>,
}

impl MeshData {
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }
}

/// Bad geometry in input data.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeshError {
    #[error("triangle {triangle}, corner {corner}: position {position:?} is not finite")]
    NonFinitePosition { triangle: usize, corner: usize, position: [f64; 3] },
}

/// The unit normal of a triangle, or `None` for a zero-area one (guard `NORMALIZE_MIN_LEN2`).
pub fn face_normal(t: &[DVec3; 3]) -> Option<DVec3> {
    let c = (t[1] - t[0]).cross(t[2] - t[0]);
    let len2 = c.length_squared();
    (len2 > NORMALIZE_MIN_LEN2 && len2.is_finite()).then(|| c / len2.sqrt())
}

fn key(p: DVec3) -> [u32; 3] {
    // Positions that round to the same f32 are the same vertex on the GPU.
    p.as_vec3().to_array().map(|c| if c == 0.0 { 0 } else { c.to_bits() })
}

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
    let corner_vertex: Vec<u32> = {
        let mut ids: HashMap<[u32; 3], u32> = HashMap::default();
        triangles
            .iter()
            .flatten()
            .map(|p| {
                let next = ids.len() as u32;
                *ids.entry(key(*p)).or_insert(next)
            })
            .collect()
    };
    let vertices = corner_vertex.iter().map(|&v| v as usize + 1).max().unwrap_or(0);
    // A corner whose vertex an earlier corner of the same triangle already has (a degenerate
    // triangle): its face is listed once around that vertex.
    let repeats = |c: usize| (1..=c % 3).any(|k| corner_vertex[c - k] == corner_vertex[c]);
    // Faces around vertex v: faces[start[v]..start[v + 1]], in triangle order.
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
    drop(cursor);
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
                        data.smooth_vertices.push(SmoothVertex { position, normal: n });
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
        let normal = own.unwrap_or(DVec3::Y).as_vec3().to_array();
        let centroid = ((t[0] + t[1] + t[2]) / 3.0).as_vec3().to_array();
        data.flat_vertices.extend(t.map(|p| FlatVertex { position: p.as_vec3().to_array(), normal, centroid }));
    }
    Ok(data)
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
            smooth.push(SmoothVertex { position: pos, normal: n });
            (smooth.len() - 1) as u32
        });
        self.data.indices.push(idx);
        self.data.flat_vertices.push(FlatVertex {
            position: pos,
            normal: face.as_vec3().to_array(),
            centroid: ((t[0] + t[1] + t[2]) / 3.0).as_vec3().to_array(),
        });
    }
}

/// A triangle mesh read from a scene file (`Shape::Mesh(i)` is `Scene::meshes[i]`), in object
/// space, indexed as files store it: each vertex once, each triangle three vertex indices. (A
/// triangle soup of f64 corners and normals would be 144 bytes a triangle; this is about 36 for
/// a typical closed mesh, which matters at 10⁷ triangles.)
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    pub name: String,
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// A normal per vertex, from the file; `None`: the crease-angle rule makes them.
    pub normals: Option<Vec<DVec3>>,
    /// Triangles as indices into `positions` (and `normals`), counter-clockwise seen from the
    /// front (glTF 2.0 §3.7.2.1). Every index is below `positions.len()` (the loader checks).
    pub indices: Vec<[u32; 3]>,
}

impl TriangleMesh {
    /// A mesh from a triangle soup (each corner its own vertex), with optional corner normals.
    pub fn from_soup(name: &str, triangles: &[[DVec3; 3]], normals: Option<&[[DVec3; 3]]>) -> TriangleMesh {
        TriangleMesh {
            name: name.into(),
            positions: triangles.iter().flatten().copied().collect(),
            normals: normals.map(|n| n.iter().flatten().copied().collect()),
            indices: (0..triangles.len() as u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect(),
        }
    }

    pub fn triangle_count(&self) -> usize {
        self.indices.len()
    }

    /// The corners of triangle `k`.
    pub fn triangle(&self, k: usize) -> [DVec3; 3] {
        self.indices[k].map(|i| self.positions[i as usize])
    }

    /// The file's normals at the corners of triangle `k`, if it has normals (one per vertex; a
    /// list of another length is no normals).
    pub fn corner_normals(&self, k: usize) -> Option<[DVec3; 3]> {
        let n = self.normals.as_ref().filter(|n| n.len() == self.positions.len())?;
        Some(self.indices[k].map(|i| n[i as usize]))
    }

    /// Every triangle's corners.
    pub fn triangles(&self) -> impl ExactSizeIterator<Item = [DVec3; 3]> + '_ {
        (0..self.indices.len()).map(|k| self.triangle(k))
    }

    /// The smooth and flat meshes: the file's normals for the smooth vertices when it has them,
    /// else the crease-angle rule; flat shading always uses the face normal (spec §8).
    ///
    /// With normals, the file's vertices are the smooth vertices as they are (no welding: the
    /// file already shares what it shares). A vertex whose normal is zero or not finite has no
    /// direction of its own: then every corner takes its own face's normal where needed
    /// ([`build_mesh_with_normals`], the triangle-soup path).
    pub fn build(&self) -> Result<MeshData, MeshError> {
        self.check_finite()?;
        match &self.normals {
            Some(_) if self.has_usable_normals() => Ok(MeshData {
                smooth_vertices: (0..self.positions.len()).map(|i| self.smooth_vertex(i)).collect(),
                indices: self.indices.iter().flatten().copied().collect(),
                flat_vertices: (0..self.indices.len()).flat_map(|k| self.flat_corners(k)).collect(),
            }),
            Some(_) => {
                let tris: Vec<[DVec3; 3]> = self.triangles().collect();
                let normals: Vec<[DVec3; 3]> = (0..self.indices.len()).filter_map(|k| self.corner_normals(k)).collect();
                build_mesh_with_normals(&tris, &normals)
            }
            None => build_mesh(&self.triangles().collect::<Vec<_>>(), CREASE_ANGLE_DEG),
        }
    }

    /// True when every vertex has a normal that can be normalized as it is: then the file's
    /// vertices are the smooth vertices ([`Self::smooth_vertex`]) and a GPU buffer can be written
    /// piece by piece, without a whole [`MeshData`] in memory.
    pub fn has_usable_normals(&self) -> bool {
        self.normals.as_ref().is_some_and(|n| n.len() == self.positions.len() && n.iter().all(|v| usable_normal(*v)))
    }

    /// Smooth vertex `i`: the file's position and unit normal (needs [`Self::has_usable_normals`]).
    pub fn smooth_vertex(&self, i: usize) -> SmoothVertex {
        let n = self.normals.as_ref().map_or(DVec3::Y, |n| n[i]);
        SmoothVertex {
            position: self.positions[i].as_vec3().to_array(),
            normal: safe_normalize(n, DVec3::Y).as_vec3().to_array(),
        }
    }

    /// The flat-shading corners of triangle `k`: its face normal and centroid at each corner.
    pub fn flat_corners(&self, k: usize) -> [FlatVertex; 3] {
        let t = self.triangle(k);
        let normal = face_normal(&t).unwrap_or(DVec3::Y).as_vec3().to_array();
        let centroid = ((t[0] + t[1] + t[2]) / 3.0).as_vec3().to_array();
        t.map(|p| FlatVertex { position: p.as_vec3().to_array(), normal, centroid })
    }

    /// The first non-finite position a triangle uses, as an error.
    pub fn check_finite(&self) -> Result<(), MeshError> {
        if self.positions.iter().all(|p| p.is_finite()) {
            return Ok(());
        }
        for (ti, t) in self.indices.iter().enumerate() {
            for (ci, &i) in t.iter().enumerate() {
                let p = self.positions[i as usize];
                if !p.is_finite() {
                    return Err(MeshError::NonFinitePosition { triangle: ti, corner: ci, position: p.to_array() });
                }
            }
        }
        Ok(())
    }

    /// Axis-aligned bounds `(min, max)` of the positions the triangles use, `None` when there are
    /// none.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let mut it = self.indices.iter().flatten().map(|&i| self.positions[i as usize]);
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p))))
    }
}

/// A file normal that can be normalized as it is (guard `NORMALIZE_MIN_LEN2`).
fn usable_normal(n: DVec3) -> bool {
    let len2 = n.length_squared();
    len2.is_finite() && len2 > NORMALIZE_MIN_LEN2
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

fn check_finite(triangles: &[[DVec3; 3]]) -> Result<(), MeshError> {
    for (ti, t) in triangles.iter().enumerate() {
        for (ci, p) in t.iter().enumerate() {
            if !p.is_finite() {
                return Err(MeshError::NonFinitePosition { triangle: ti, corner: ci, position: p.to_array() });
            }
        }
    }
    Ok(())
}

/// Tessellate a shape (see [`Shape`] for its object-space extent) and build its meshes. A
/// `Shape::Mesh` has no analytic form: build it from `Scene::meshes` ([`TriangleMesh::build`]
/// or `Scene::mesh_data`); here it gives an empty mesh.
pub fn tessellate(shape: Shape, tessellation: u32) -> MeshData {
    build_mesh(&triangles(shape, tessellation), CREASE_ANGLE_DEG).expect("procedural shapes are finite")
}

/// Segments around a sphere or cylinder for a tessellation parameter (at least 3).
pub fn segments(tessellation: u32) -> u32 {
    tessellation.max(3)
}

/// Rings of a sphere with `segments` segments.
pub fn sphere_rings(segments: u32) -> u32 {
    (segments / 2).max(2)
}

/// Triangles a shape has at a tessellation, without building it.
pub fn triangle_count(shape: Shape, tessellation: u32) -> usize {
    let n = tessellation.max(1) as usize;
    let s = segments(tessellation) as usize;
    match shape {
        Shape::Sphere => s * 2 * (sphere_rings(s as u32) as usize - 1),
        Shape::Cylinder => 4 * s,
        Shape::Cube => 12 * n * n,
        Shape::Plane => 2 * n * n,
        Shape::Pyramid => 6 * n * n,
        // Counted from `Scene::meshes` by `Scene::triangle_count`.
        Shape::Mesh(_) => 0,
    }
}

/// The triangles of an analytic shape (empty for `Shape::Mesh`), oriented so that each face's normal points out of the shape.
pub fn triangles(shape: Shape, tessellation: u32) -> Vec<[DVec3; 3]> {
    let n = tessellation.max(1);
    let (tris, inside) = match shape {
        Shape::Sphere => (sphere(segments(n)), DVec3::ZERO),
        Shape::Cylinder => (cylinder(segments(n)), DVec3::ZERO),
        Shape::Cube => (cube(n), DVec3::ZERO),
        Shape::Plane => (plane(n), DVec3::NEG_Y),
        Shape::Pyramid => (pyramid(n), DVec3::new(0.0, -0.5, 0.0)),
        // A file's mesh has no analytic form: its triangles are `Scene::meshes[i]`.
        Shape::Mesh(_) => return Vec::new(),
    };
    // Every shape is convex (the plane is one face of one), so a face is oriented outwards when
    // its normal points away from a point inside.
    tris.into_iter()
        .map(|t| match face_normal(&t) {
            Some(nrm) if nrm.dot((t[0] + t[1] + t[2]) / 3.0 - inside) < 0.0 => [t[0], t[2], t[1]],
            _ => t,
        })
        .collect()
}

fn quad(out: &mut Vec<[DVec3; 3]>, a: DVec3, b: DVec3, c: DVec3, d: DVec3) {
    // a b
    // c d
    out.push([a, c, d]);
    out.push([a, d, b]);
}

fn sphere(seg: u32) -> Vec<[DVec3; 3]> {
    let rings = sphere_rings(seg);
    let v = |i: u32, j: u32| -> DVec3 {
        if i == 0 {
            return DVec3::Y;
        }
        if i == rings {
            return DVec3::NEG_Y;
        }
        let theta = std::f64::consts::PI * i as f64 / rings as f64;
        let phi = std::f64::consts::TAU * (j % seg) as f64 / seg as f64;
        DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin())
    };
    let mut out = Vec::new();
    for i in 0..rings {
        for j in 0..seg {
            let (a, b, c, d) = (v(i, j), v(i, j + 1), v(i + 1, j), v(i + 1, j + 1));
            if i == 0 {
                out.push([a, c, d]);
            } else if i == rings - 1 {
                out.push([a, c, b]);
            } else {
                quad(&mut out, a, b, c, d);
            }
        }
    }
    out
}

fn cylinder(seg: u32) -> Vec<[DVec3; 3]> {
    let rim = |j: u32, y: f64| {
        let phi = std::f64::consts::TAU * (j % seg) as f64 / seg as f64;
        DVec3::new(phi.cos(), y, phi.sin())
    };
    let mut out = Vec::new();
    for j in 0..seg {
        quad(&mut out, rim(j, 1.0), rim(j + 1, 1.0), rim(j, -1.0), rim(j + 1, -1.0));
        out.push([DVec3::Y, rim(j, 1.0), rim(j + 1, 1.0)]);
        out.push([DVec3::NEG_Y, rim(j, -1.0), rim(j + 1, -1.0)]);
    }
    out
}

fn grid(out: &mut Vec<[DVec3; 3]>, n: u32, point: impl Fn(f64, f64) -> DVec3) {
    let t = |i: u32| -1.0 + 2.0 * i as f64 / n as f64;
    for i in 0..n {
        for j in 0..n {
            quad(out, point(t(i), t(j)), point(t(i + 1), t(j)), point(t(i), t(j + 1)), point(t(i + 1), t(j + 1)));
        }
    }
}

fn cube(n: u32) -> Vec<[DVec3; 3]> {
    let mut out = Vec::new();
    for axis in 0..3 {
        for s in [-1.0, 1.0] {
            grid(&mut out, n, |u, v| {
                let mut p = [0.0; 3];
                p[axis] = s;
                p[(axis + 1) % 3] = u;
                p[(axis + 2) % 3] = v;
                DVec3::from_array(p)
            });
        }
    }
    out
}

fn plane(n: u32) -> Vec<[DVec3; 3]> {
    let mut out = Vec::new();
    grid(&mut out, n, |u, v| DVec3::new(u, 0.0, v));
    out
}

fn pyramid(n: u32) -> Vec<[DVec3; 3]> {
    let mut out = Vec::new();
    grid(&mut out, n, |u, v| DVec3::new(u, -1.0, v));
    let apex = DVec3::Y;
    let base = [
        DVec3::new(-1.0, -1.0, -1.0),
        DVec3::new(1.0, -1.0, -1.0),
        DVec3::new(1.0, -1.0, 1.0),
        DVec3::new(-1.0, -1.0, 1.0),
    ];
    let nf = n as f64;
    for k in 0..4 {
        let (b0, b1) = (base[k], base[(k + 1) % 4]);
        let p = |i: u32, j: u32| b0 + (b1 - b0) * (i as f64 / nf) + (apex - b0) * (j as f64 / nf);
        for j in 0..n {
            for i in 0..n - j {
                out.push([p(i, j), p(i + 1, j), p(i, j + 1)]);
                if i + 1 < n - j {
                    out.push([p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_normals(m: &MeshData) -> bool {
        m.smooth_vertices.iter().all(|v| {
            let n = glam::Vec3::from(v.normal);
            n.is_finite() && (n.length() - 1.0).abs() < 1e-5
        })
    }

    #[test]
    fn counts_match_and_normals_are_unit() {
        for shape in Shape::ALL {
            for t in [1, 3, 8, 17] {
                let m = tessellate(shape, t);
                assert_eq!(m.triangle_count(), triangle_count(shape, t), "{shape:?} {t}");
                assert_eq!(m.flat_vertices.len(), 3 * m.triangle_count());
                assert!(unit_normals(&m), "{shape:?} {t}");
            }
        }
    }

    #[test]
    fn faces_point_outwards() {
        for shape in [Shape::Sphere, Shape::Cylinder, Shape::Cube, Shape::Pyramid] {
            for t in triangles(shape, 8) {
                let n = face_normal(&t).unwrap();
                let c = (t[0] + t[1] + t[2]) / 3.0;
                let inside = if shape == Shape::Pyramid { DVec3::new(0.0, -0.5, 0.0) } else { DVec3::ZERO };
                assert!(n.dot(c - inside) > 0.0, "{shape:?}");
            }
        }
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
}

#[cfg(test)]
mod rule_tests {
    use super::*;

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
    fn normals_of_another_length_than_the_positions_are_no_normals() {
        let tris = triangles(Shape::Cube, 1);
        let mut m = TriangleMesh::from_soup("cube", &tris, None);
        m.normals = Some(vec![DVec3::Y; 5]);
        assert!(!m.has_usable_normals() && m.corner_normals(0).is_none());
        let built = m.build().unwrap();
        // Every corner falls back to its own face's normal.
        for (t, tri) in tris.iter().enumerate() {
            let own = face_normal(tri).unwrap().as_vec3().to_array();
            assert_eq!(built.smooth_vertices[built.indices[3 * t] as usize].normal, own);
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
