//! Meshes in object space: the vertex and corner records a shape's meshes are made of, and the
//! rules they share (face normal, weld key, finiteness). Procedural shapes (`procedural.rs`), the
//! crease-angle rule (`crease.rs`) and the triangle mesh of a scene file (`triangle_mesh.rs`)
//! live beside them; the GPU's vertex formats are the render crate's (`shadelab_render::vertex`).

mod crease;
mod procedural;
mod shared;
mod tangents;
mod triangle_mesh;

pub use crease::{CREASE_ANGLE_DEG, CREASE_VALENCE_MAX, build_mesh, build_mesh_with_normals};
pub use procedural::{segments, sphere_rings, tessellate, triangle_count, triangles};
pub use shared::Meshes;
pub use triangle_mesh::TriangleMesh;

use crate::guards::NORMALIZE_MIN_LEN2;
use glam::DVec3;

/// A vertex of the smooth (indexed) mesh, as f32 (what the GPU receives): Gouraud and Phong
/// shading.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
}

/// A corner of the flat (unindexed) mesh, as f32: each face carries its own normal and the
/// centroid where flat shading evaluates the lighting once for the whole face.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatCorner {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub centroid: [f32; 3],
}

impl FlatCorner {
    /// The three corners of triangle `t` with face normal `normal`.
    fn of_triangle(t: &[DVec3; 3], normal: DVec3) -> [FlatCorner; 3] {
        let normal = normal.as_vec3().to_array();
        let centroid = ((t[0] + t[1] + t[2]) / 3.0).as_vec3().to_array();
        t.map(|p| FlatCorner { position: p.as_vec3().to_array(), normal, centroid })
    }
}

/// A shape's smooth and flat meshes, in object space.
#[derive(Clone, Debug, Default)]
pub struct MeshData {
    pub smooth_vertices: Vec<MeshVertex>,
    pub indices: Vec<u32>,
    pub flat_vertices: Vec<FlatCorner>,
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

/// The weld key of a position: positions that round to the same f32 are the same vertex on the
/// GPU (±0 alike).
pub(crate) fn key(p: DVec3) -> [u32; 3] {
    p.as_vec3().to_array().map(|c| if c == 0.0 { 0 } else { c.to_bits() })
}

/// The first non-finite corner of a triangle soup, as an error.
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
