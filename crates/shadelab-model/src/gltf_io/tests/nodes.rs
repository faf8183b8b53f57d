//! Tests of the node graph: transforms decomposed into the model's form or baked into the mesh.

use super::*;

#[test]
fn hierarchy_transforms_decompose_or_bake() {
    let s = load(&triangle(json!({
        "nodes": [
            { "translation": [1, 0, 0], "children": [1, 2, 3] },
            // Rotation about y and uniform scale: the model's transform form.
            { "mesh": 0, "rotation": [0, 0.3826834, 0, 0.9238795], "scale": [2, 2, 2] },
            // Rotation about x: baked into the positions.
            { "mesh": 0, "rotation": [FRAC_1_SQRT_2, 0, 0, FRAC_1_SQRT_2] },
            // A mirror: baked, winding reversed so the face still points the same way.
            { "mesh": 0, "scale": [-1, 1, 1] },
        ],
    })))
    .scene;
    assert_eq!(s.objects.len(), 3);
    let t = &s.objects[0].transform;
    assert_eq!(s.objects[0].shape, Shape::Mesh(0));
    near(t.translation, DVec3::X, "translation");
    near1(t.rotation_y, 45f64.to_radians(), "rotation_y");
    near(t.scale, DVec3::splat(2.0), "scale");
    let baked = &s.meshes[1].triangle(0);
    near(baked[2], DVec3::new(1.0, 0.0, 1.0), "rotated corner");
    let mirrored = &s.meshes[2].triangle(0);
    let n = crate::mesh::face_normal(mirrored).unwrap();
    near(n, DVec3::Z, "mirrored face normal");
}
