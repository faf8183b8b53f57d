//! The triangle mesh of a scene file (`Shape::Mesh(i)` is `Scene::meshes[i]`): indexed as files
//! store it, with the file's normals or none, and its smooth and flat meshes.

use super::{
    CREASE_ANGLE_DEG, FlatCorner, MeshData, MeshError, MeshVertex, build_mesh, build_mesh_with_normals, face_normal,
};
use crate::brdf::safe_normalize;
use crate::guards::NORMALIZE_MIN_LEN2;
use glam::DVec3;

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
    /// Texture coordinates per vertex (glTF `TEXCOORD_0`), if the file has them.
    pub uvs: Option<Vec<[f32; 2]>>,
    /// Linear RGB colour per vertex that multiplies `C` (glTF `COLOR_0`), if the file has one.
    pub colors: Option<Vec<[f32; 3]>>,
    /// Tangent per vertex, xyz and the bitangent's sign w (glTF `TANGENT`, or MikkTSpace's):
    /// the frame a normal texture perturbs the normal in.
    pub tangents: Option<Vec<[f32; 4]>>,
}

impl TriangleMesh {
    /// A mesh from a triangle soup (each corner its own vertex), with optional corner normals.
    pub fn from_soup(name: &str, triangles: &[[DVec3; 3]], normals: Option<&[[DVec3; 3]]>) -> TriangleMesh {
        TriangleMesh {
            name: name.into(),
            positions: triangles.iter().flatten().copied().collect(),
            normals: normals.map(|n| n.iter().flatten().copied().collect()),
            indices: (0..triangles.len() as u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect(),
            uvs: None,
            colors: None,
            tangents: None,
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

    /// This mesh with its vertex attributes (texture coordinates, colours) kept at every corner:
    /// as it is when its normals can be used as they are; else a triangle soup whose corners
    /// carry the normals [`Self::build`] gives them (the crease-angle rule, or the face normal for
    /// an unusable file normal), which re-indexes vertices and would lose the attributes.
    pub fn with_attributes_kept(self) -> TriangleMesh {
        if (self.uvs.is_none() && self.colors.is_none()) || self.has_usable_normals() {
            return self;
        }
        let Ok(built) = self.build() else { return self };
        if built.indices.len() != 3 * self.indices.len() {
            return self;
        }
        let corners = || self.indices.iter().flatten().map(|&i| i as usize);
        TriangleMesh {
            name: self.name.clone(),
            positions: corners().map(|i| self.positions[i]).collect(),
            normals: Some(
                built
                    .indices
                    .iter()
                    .map(|&v| DVec3::from(built.smooth_vertices[v as usize].normal.map(f64::from)))
                    .collect(),
            ),
            indices: (0..self.indices.len() as u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect(),
            uvs: self.uvs.as_ref().map(|u| corners().map(|i| u[i]).collect()),
            colors: self.colors.as_ref().map(|c| corners().map(|i| c[i]).collect()),
            // The file's tangents belong to normals it did not have usably: glTF ignores them.
            tangents: None,
        }
    }

    /// The smooth and flat meshes: the file's normals for the smooth vertices when it has them,
    /// else the crease-angle rule; flat shading always uses the face normal (docs/model.md §8).
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
    pub fn smooth_vertex(&self, i: usize) -> MeshVertex {
        let n = self.normals.as_ref().map_or(DVec3::Y, |n| n[i]);
        MeshVertex {
            position: self.positions[i].as_vec3().to_array(),
            normal: safe_normalize(n, DVec3::Y).as_vec3().to_array(),
        }
    }

    /// The flat-shading corners of triangle `k`: its face normal and centroid at each corner.
    pub fn flat_corners(&self, k: usize) -> [FlatCorner; 3] {
        let t = self.triangle(k);
        FlatCorner::of_triangle(&t, face_normal(&t).unwrap_or(DVec3::Y))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::triangles;
    use crate::scene::Shape;

    #[test]
    fn attributes_stay_at_their_corners_when_the_normals_come_from_the_crease_rule() {
        let tris = triangles(Shape::Cube, 1);
        let mut m = TriangleMesh::from_soup("cube", &tris, None);
        // Weld the soup: 8 vertices, as a file stores a cube, each with its own colour.
        let mut ids: Vec<DVec3> = Vec::new();
        for t in m.indices.iter_mut() {
            for c in t.iter_mut() {
                let p = m.positions[*c as usize];
                *c = ids.iter().position(|q| *q == p).unwrap_or_else(|| {
                    ids.push(p);
                    ids.len() - 1
                }) as u32;
            }
        }
        m.positions = ids;
        m.colors = Some((0..m.positions.len()).map(|i| [i as f32, 0.0, 0.0]).collect());
        let before = m.clone();
        let kept = m.with_attributes_kept();
        assert!(kept.has_usable_normals());
        for k in 0..before.triangle_count() {
            assert_eq!(kept.triangle(k), before.triangle(k));
            for c in 0..3 {
                let (a, b) = (kept.indices[k][c] as usize, before.indices[k][c] as usize);
                assert_eq!(kept.colors.as_ref().unwrap()[a], before.colors.as_ref().unwrap()[b]);
            }
            // A cube's faces meet at 90°: past the crease angle, each corner has its face's normal.
            let face = face_normal(&before.triangle(k)).unwrap();
            assert!(kept.corner_normals(k).unwrap().iter().all(|n| (*n - face).length() < 1e-6));
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
}
