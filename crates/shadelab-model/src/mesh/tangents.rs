//! Tangents for normal textures: the MikkTSpace frame glTF requires when a file gives none
//! (glTF 2.0 §3.7.2.1), made by the `bevy_mikktspace` crate, per triangle corner. A vertex whose
//! corners get different tangents (a seam in the texture coordinates, a mirrored half) is split
//! so that each copy carries one.

use super::TriangleMesh;

/// Corners of one vertex whose tangents differ by less than this (per component) keep sharing it.
const TANGENT_WELD: f32 = 1e-5;

/// The mesh's vertices as MikkTSpace reads them: positions, normals and texture coordinates by
/// (face, corner), and the tangent written back for each corner.
struct Corners<'a> {
    mesh: &'a TriangleMesh,
    normals: &'a [glam::DVec3],
    uvs: &'a [[f32; 2]],
    out: Vec<[f32; 4]>,
}

impl bevy_mikktspace::Geometry for Corners<'_> {
    fn num_faces(&self) -> usize {
        self.mesh.indices.len()
    }

    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }

    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.mesh.positions[self.mesh.indices[face][vert] as usize].as_vec3().to_array()
    }

    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.normals[self.mesh.indices[face][vert] as usize].as_vec3().to_array()
    }

    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        self.uvs[self.mesh.indices[face][vert] as usize]
    }

    fn set_tangent(&mut self, tangent: Option<bevy_mikktspace::TangentSpace>, face: usize, vert: usize) {
        // A corner the algorithm cannot frame (a degenerate face alone) gets none: a zero
        // tangent, which `normal_mapped` answers with the unperturbed normal.
        self.out[3 * face + vert] = tangent.map_or([0.0; 4], |t| t.tangent_encoded());
    }
}

impl TriangleMesh {
    /// This mesh with MikkTSpace tangents (`tangents`), splitting the vertices whose corners
    /// disagree; `None` when it has no usable normals or no texture coordinates to frame.
    pub fn with_generated_tangents(&self) -> Option<TriangleMesh> {
        let normals = self.normals.as_ref().filter(|n| n.len() == self.positions.len())?;
        let uvs = self.uvs.as_ref().filter(|u| u.len() == self.positions.len())?;
        if !self.has_usable_normals() {
            return None;
        }
        let mut corners = Corners { mesh: self, normals, uvs, out: vec![[0.0; 4]; 3 * self.indices.len()] };
        // The crate's error type has no values yet; should it gain one, no tangents.
        bevy_mikktspace::generate_tangents(&mut corners).ok()?;
        let corner_tangents = corners.out;
        let mut m = self.clone();
        let mut tangents: Vec<Option<[f32; 4]>> = vec![None; m.positions.len()];
        for (k, tri) in m.indices.iter_mut().enumerate() {
            for (c, index) in tri.iter_mut().enumerate() {
                let t = corner_tangents[3 * k + c];
                let v = *index as usize;
                match tangents[v] {
                    None => tangents[v] = Some(t),
                    Some(have) if (0..4).all(|i| (have[i] - t[i]).abs() < TANGENT_WELD) => {}
                    Some(_) => {
                        // A copy of vertex v for this corner's tangent.
                        m.positions.push(m.positions[v]);
                        if let Some(n) = &mut m.normals {
                            n.push(n[v]);
                        }
                        if let Some(u) = &mut m.uvs {
                            u.push(u[v]);
                        }
                        if let Some(col) = &mut m.colors {
                            col.push(col[v]);
                        }
                        tangents.push(Some(t));
                        *index = (m.positions.len() - 1) as u32;
                    }
                }
            }
        }
        m.tangents = Some(tangents.into_iter().map(|t| t.unwrap_or([0.0; 4])).collect());
        Some(m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A unit quad in the xz plane facing +y, u along +x and v along +z.
    fn quad() -> TriangleMesh {
        let p = [DVec3::ZERO, DVec3::Z, DVec3::new(1.0, 0.0, 1.0), DVec3::X];
        TriangleMesh {
            name: "quad".into(),
            positions: p.to_vec(),
            normals: Some(vec![DVec3::Y; 4]),
            indices: vec![[0, 1, 2], [0, 2, 3]],
            uvs: Some(p.iter().map(|q| [q.x as f32, q.z as f32]).collect()),
            colors: None,
            tangents: None,
        }
    }

    #[test]
    fn a_flat_quad_gets_its_u_direction_as_tangent() {
        let m = quad().with_generated_tangents().unwrap();
        let t = m.tangents.as_ref().unwrap();
        assert_eq!(m.positions.len(), 4, "one frame for the whole quad: nothing split");
        for t in t {
            assert!((t[0] - 1.0).abs() < 1e-5 && t[1].abs() < 1e-5 && t[2].abs() < 1e-5, "{t:?}");
            assert_eq!(t[3].abs(), 1.0);
        }
    }

    #[test]
    fn a_mirrored_half_splits_its_shared_vertices() {
        let mut q = quad();
        // The second triangle's u runs the other way: its shared corners need another frame.
        let uvs = q.uvs.as_mut().unwrap();
        uvs[3] = [-1.0, 0.0];
        let m = q.with_generated_tangents().unwrap();
        assert!(m.positions.len() > 4, "{}", m.positions.len());
        assert_eq!(m.tangents.as_ref().unwrap().len(), m.positions.len());
        assert!(m.indices.iter().flatten().all(|&i| (i as usize) < m.positions.len()));
    }

    #[test]
    fn no_uvs_or_normals_no_tangents() {
        let mut q = quad();
        q.uvs = None;
        assert!(q.with_generated_tangents().is_none());
        let mut q = quad();
        q.normals = None;
        assert!(q.with_generated_tangents().is_none());
    }
}
