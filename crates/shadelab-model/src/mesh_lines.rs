//! The meshes' normals and creases made visible (docs/model.md §8): the vertex normals the smooth
//! mesh carries, as short lines from each vertex, and the edges the crease-angle rule kept sharp
//! (the two faces' normals differ by more than `CREASE_ANGLE_DEG`). On the cylinder the rim's
//! vertices show two normals, the side's (the mean of the side faces only) and the cap's: the
//! chapter's rule of 7.6.1, which leaves the cap's face out of the side's normal.

use crate::mesh::{CREASE_ANGLE_DEG, MeshData};
use crate::scene::{Object, Scene, Shape};
use crate::terminator::{EdgeMesh, Segment};
use glam::DVec3;

/// Length of a normal's line as a share of the scene's bounding radius: 3 % is long enough to
/// read the direction at 1280×720 and short enough that a 16-segment sphere's normals do not
/// cross.
pub const NORMAL_LINE_SHARE: f64 = 0.03;

/// Most normals drawn for one scene: a 10⁷-triangle file has millions of vertices, whose lines
/// would fill the image; past this every k-th vertex is drawn (k the smallest that fits).
pub const NORMAL_LINES_MAX: usize = 200_000;

/// An object's smooth mesh in object space: its shape's tessellation or its file mesh (`None`
/// for a mesh index past `Scene::meshes` or a mesh that does not build).
fn smooth_mesh(scene: &Scene, o: &Object) -> Option<MeshData> {
    match o.shape {
        Shape::Mesh(i) => scene.meshes.get(i)?.build().ok(),
        shape => Some(crate::mesh::tessellate(shape, o.tessellation)),
    }
}

/// Every vertex normal of the smooth meshes (Gouraud's and Phong's), in world space: a line from
/// the vertex along its unit normal, [`NORMAL_LINE_SHARE`] of the scene's radius long. A vertex
/// shared by faces on two sides of a crease has one line per side.
pub fn normal_segments(scene: &Scene) -> Vec<Segment> {
    let Some((_, radius)) = crate::shadows::scene_bounds(scene) else { return Vec::new() };
    let length = NORMAL_LINE_SHARE * radius;
    let meshes: Vec<(&Object, MeshData)> =
        scene.objects.iter().filter_map(|o| smooth_mesh(scene, o).map(|m| (o, m))).collect();
    let total: usize = meshes.iter().map(|(_, m)| m.smooth_vertices.len()).sum();
    let step = total.div_ceil(NORMAL_LINES_MAX).max(1);
    let mut out = Vec::with_capacity(total / step + 1);
    for (o, mesh) in meshes {
        let m = o.transform.matrix();
        let nm = o.transform.normal_matrix();
        for v in mesh.smooth_vertices.iter().step_by(step) {
            let p = m.transform_point3(DVec3::from(v.position.map(f64::from)));
            let Some(n) = (nm * DVec3::from(v.normal.map(f64::from))).try_normalize() else { continue };
            if p.is_finite() {
                out.push([p, p + n * length]);
            }
        }
    }
    out
}

/// The edges the crease-angle rule keeps sharp, in world space: where two faces' normals differ
/// by more than `CREASE_ANGLE_DEG` (the cube's twelve edges, the cylinder's rims, the pyramid's
/// edges; none on the sphere).
pub fn crease_segments(scene: &Scene) -> Vec<Segment> {
    let cos_crease = CREASE_ANGLE_DEG.to_radians().cos();
    scene.objects.iter().flat_map(|o| EdgeMesh::of_object(scene, o).creases(cos_crease)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::single_shape_scene;

    fn object_only(shape: Shape, tessellation: u32) -> Scene {
        let mut s = single_shape_scene("x", shape, tessellation);
        s.objects.retain(|o| o.name != "ground");
        s
    }

    #[test]
    fn creases_are_the_sharp_edges_of_each_shape() {
        assert_eq!(crease_segments(&object_only(Shape::Cube, 1)).len(), 12, "a cube's edges");
        assert_eq!(crease_segments(&object_only(Shape::Sphere, 16)).len(), 0, "a sphere is smooth");
        // A cylinder of 16 segments: two rims of 16 edges each; its side's seams are smooth.
        assert_eq!(crease_segments(&object_only(Shape::Cylinder, 16)).len(), 32);
        // The pyramid: four base edges and four lateral edges.
        assert_eq!(crease_segments(&object_only(Shape::Pyramid, 1)).len(), 8);
    }

    #[test]
    fn the_cylinders_rim_has_a_side_normal_and_a_cap_normal() {
        let s = object_only(Shape::Cylinder, 16);
        let lines = normal_segments(&s);
        let (_, radius) = crate::shadows::scene_bounds(&s).unwrap();
        assert!(lines.iter().all(|l| ((l[1] - l[0]).length() - NORMAL_LINE_SHARE * radius).abs() < 1e-9));
        // A point of the top rim: one line straight up (the cap's), one horizontal (the side's,
        // the mean of the two side faces at it, the cap left out).
        let top = lines.iter().map(|l| l[0].y).fold(f64::NEG_INFINITY, f64::max);
        let rim: Vec<DVec3> = lines
            .iter()
            .filter(|l| (l[0].y - top).abs() < 1e-9 && DVec3::new(l[0].x, 0.0, l[0].z).length() > 0.1)
            .map(|l| (l[1] - l[0]).normalize())
            .collect();
        assert!(rim.iter().any(|d| (d.y - 1.0).abs() < 1e-6), "a cap normal on the rim");
        assert!(rim.iter().any(|d| d.y.abs() < 1e-6), "a side normal on the rim, horizontal");
        assert!(rim.iter().all(|d| (d.y - 1.0).abs() < 1e-6 || d.y.abs() < 1e-6), "nothing in between");
    }

    #[test]
    fn a_huge_mesh_is_thinned_to_the_limit() {
        let mut s = object_only(Shape::Sphere, 16);
        s.objects[0].tessellation = 1024;
        let n = normal_segments(&s).len();
        assert!(n <= NORMAL_LINES_MAX && n > NORMAL_LINES_MAX / 4, "{n}");
    }
}
