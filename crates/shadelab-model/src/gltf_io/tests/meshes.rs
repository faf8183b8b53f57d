//! Tests of meshes, primitives and accessors: file meshes with and without normals, analytic
//! shapes, strips and fans, the triangle and object limits, and file meshes in the reference.

use super::*;

#[test]
fn mesh_objects_round_trip_with_and_without_normals() {
    let mut scene = Scene::builtin("sphere").unwrap();
    let tris = crate::mesh::triangles(Shape::Cube, 2);
    let normals: Vec<[DVec3; 3]> = tris.iter().map(|t| [crate::mesh::face_normal(t).unwrap(); 3]).collect();
    scene.meshes =
        vec![TriangleMesh::from_soup("soup", &tris, None), TriangleMesh::from_soup("faceted", &tris, Some(&normals))]
            .into();
    for (i, x) in [-2.0, 2.0].into_iter().enumerate() {
        scene.objects.push(Object {
            name: format!("mesh {i}"),
            shape: Shape::Mesh(i),
            tessellation: 1,
            transform: Transform { translation: DVec3::new(x, 1.0, 0.0), rotation_y: 0.4, scale: DVec3::splat(0.5) },
            material: 1,
        });
    }
    let back = load(scene_to_gltf_json(&scene, &SceneSettings::default()).as_bytes()).scene;
    assert_same_scene(&scene, &back);
    // Both render as before: the same smooth (crease-angle) and flat meshes.
    for (o, p) in scene.objects.iter().zip(&back.objects).skip(2) {
        let (m, n) = (scene.mesh_data(o), back.mesh_data(p));
        assert_eq!(m.indices, n.indices);
        assert_eq!(m.smooth_vertices, n.smooth_vertices);
        assert_eq!(m.flat_vertices, n.flat_vertices);
    }
}

#[test]
fn an_edited_analytic_mesh_loads_as_a_mesh() {
    let scene = Scene::builtin("pyramid").unwrap();
    let mut doc: Value = serde_json::from_str(&scene_to_gltf_json(&scene, &SceneSettings::default())).unwrap();
    // Claim another tessellation than the triangles have.
    doc["meshes"][1]["extras"]["shadelab"]["tessellation"] = json!(3);
    let back = load(&serde_json::to_vec(&doc).unwrap()).scene;
    assert_eq!(back.objects[1].shape, Shape::Mesh(0));
    assert_eq!(back.triangle_count(), scene.triangle_count());
}

#[test]
fn strips_and_fans_become_triangles() {
    let bin = f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0]);
    for (mode, want) in [(5, [[0, 1, 2], [1, 3, 2]]), (6, [[1, 2, 0], [2, 3, 0]])] {
        let doc = json!({
            "asset": { "version": "2.0" },
            "nodes": [{ "mesh": 0 }],
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "mode": mode }] }],
            "accessors": [{ "bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3" }],
            "bufferViews": [{ "buffer": 0, "byteLength": 48 }],
        });
        let s = load(&with_buffer(doc, &bin)).scene;
        let p = |i: usize| DVec3::new((i % 2) as f64, (i / 2) as f64, 0.0);
        let want: Vec<[DVec3; 3]> = want.iter().map(|t| t.map(p)).collect();
        assert_eq!(s.meshes[0].triangles().collect::<Vec<_>>(), want, "mode {mode}");
    }
}

#[test]
fn limits_on_triangles_and_objects_are_errors_before_allocation() {
    // 3·(MAX_TRIANGLES + 1) one-byte indices, all naming the one vertex: refused from the
    // accessor's count, before the indices are read.
    let n = 3 * (MAX_TRIANGLES + 1);
    let mut bin = f32s(&[0.0, 0.0, 0.0]);
    bin.resize(12 + n.next_multiple_of(4), 0);
    let doc = json!({
        "asset": { "version": "2.0" },
        "nodes": [{ "mesh": 0 }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "indices": 1 }] }],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 1, "type": "VEC3" },
            { "bufferView": 1, "componentType": 5121, "count": n, "type": "SCALAR" },
        ],
        "bufferViews": [{ "buffer": 0, "byteLength": 12 }, { "buffer": 0, "byteOffset": 12, "byteLength": n }],
    });
    let e = load_scene_from_slice(&glb(doc, &bin)).unwrap_err();
    assert!(matches!(e, GltfError::TooLarge { .. }), "{e}");
    let want = format!("{} triangles are more than the limit of {MAX_TRIANGLES} (MAX_TRIANGLES)", MAX_TRIANGLES + 1);
    assert!(e.to_string().contains(&want), "{e}");
    // Instances count: a 10⁴-triangle mesh shown by one node more than the limit allows.
    let per_mesh = 10_000;
    let instances = MAX_TRIANGLES / per_mesh + 1;
    assert!(instances <= MAX_OBJECTS, "the triangle limit must be reached before the object limit");
    let corners: Vec<f32> = (0..3 * per_mesh).flat_map(|i| [i as f32, (i % 3) as f32, 0.0]).collect();
    let nodes: Vec<Value> = (0..instances).map(|_| json!({ "mesh": 0 })).collect();
    let doc = json!({
        "asset": { "version": "2.0" },
        "scenes": [{ "nodes": (0..instances).collect::<Vec<_>>() }],
        "nodes": nodes,
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 } }] }],
        "accessors": [{ "bufferView": 0, "componentType": 5126, "count": 3 * per_mesh, "type": "VEC3" }],
        "bufferViews": [{ "buffer": 0, "byteLength": 36 * per_mesh }],
    });
    let e = load_scene_from_slice(&glb(doc, &f32s(&corners))).unwrap_err().to_string();
    assert!(e.contains(&format!("{} triangles are more than the limit", instances * per_mesh)), "{e}");
    // Objects: one more node than MAX_OBJECTS.
    let doc = json!({
        "asset": { "version": "2.0" },
        "scenes": [{ "nodes": (0..=MAX_OBJECTS).collect::<Vec<_>>() }],
        "nodes": (0..=MAX_OBJECTS).map(|_| json!({ "mesh": 0 })).collect::<Vec<_>>(),
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 } }] }],
        "accessors": [{ "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3" }],
        "bufferViews": [{ "buffer": 0, "byteLength": 36 }],
    });
    let e = load_scene_from_slice(&glb(doc, &f32s(&[0.0; 9]))).unwrap_err().to_string();
    assert!(e.contains("more than 16384 objects (MAX_OBJECTS)"), "{e}");
}

#[test]
fn reference_ray_caster_sees_file_meshes() {
    // A cube as a file mesh (baked under a tilt, so it is a `Shape::Mesh`), framed by the loader.
    let mut scene = Scene::builtin("cube").unwrap();
    scene.objects[1].transform.rotation_y = 0.3;
    let mut doc: Value = serde_json::from_str(&scene_to_gltf_json(&scene, &SceneSettings::default())).unwrap();
    doc["nodes"][1]["rotation"] = json!([0.2, 0.0, 0.0, 0.98]);
    let s = load(&serde_json::to_vec(&doc).unwrap()).scene;
    assert!(matches!(s.objects[1].shape, Shape::Mesh(_)));
    let img = crate::reference::render_reference(&s, SpecularModel::CookTorrance, 64, 36);
    let seen = img.object.iter().filter(|o| **o == Some(1)).count();
    assert!(seen > 50, "the mesh covers {seen} pixels");
    assert!(img.pixels.iter().all(|p| p.iter().all(|c| c.is_finite() && *c >= 0.0)));
}

/// Thousands of weighted morph targets naming one large accessor stop at `MAX_MORPH_OFFSETS`,
/// in one line, before their offsets are added; a few targets still apply.
#[test]
fn morph_targets_past_the_offset_limit_are_an_error() {
    // 65535 vertices (21845 triangles), every target the positions accessor itself.
    let n = 65_535usize;
    let bin = f32s(&(0..n).flat_map(|i| [(i % 256) as f32, (i / 256) as f32, 0.0]).collect::<Vec<f32>>());
    let doc_with = |targets: usize| {
        let doc = json!({
            "asset": { "version": "2.0" },
            "scenes": [{ "nodes": [0] }],
            "nodes": [{ "mesh": 0 }],
            "meshes": [{
                "primitives": [{ "attributes": { "POSITION": 0 }, "targets": vec![json!({ "POSITION": 0 }); targets] }],
                "weights": vec![0.001; targets],
            }],
            "accessors": [{ "bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
                            "min": [0, 0, 0], "max": [255, 255, 0] }],
            "bufferViews": [{ "buffer": 0, "byteLength": bin.len() }],
        });
        with_buffer(doc, &bin)
    };
    assert_eq!(load(&doc_with(3)).scene.triangle_count(), n / 3);
    let targets = MAX_MORPH_OFFSETS / n + 1;
    let e = load_scene_from_slice(&doc_with(targets)).unwrap_err().to_string();
    assert!(e.contains("MAX_MORPH_OFFSETS") && !e.contains('\n'), "{e}");
}
