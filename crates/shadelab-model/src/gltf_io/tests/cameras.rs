//! Tests of cameras: every camera of the file listed, the first the scene's; none: the framing one.

use super::*;

#[test]
fn every_camera_is_listed_the_first_is_the_scenes() {
    let cam = |name: &str, yfov: f64| json!({ "name": name, "type": "perspective", "perspective": { "yfov": yfov, "znear": 0.1 } });
    let s = load(&triangle(json!({
        "scenes": [{ "nodes": [0, 1, 2] }],
        "nodes": [
            { "mesh": 0 },
            { "camera": 1, "translation": [0.0, 0.0, 5.0] },
            { "camera": 0, "translation": [3.0, 1.0, 4.0], "name": "side node" },
        ],
        "cameras": [cam("side", 0.5), cam("front", 0.7)],
    })));
    let names: Vec<&str> = s.cameras.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["front", "side"], "in node order");
    assert_eq!(s.scene.camera, s.cameras[0].1);
    near(s.cameras[0].1.eye, DVec3::new(0.0, 0.0, 5.0), "front eye");
    near(s.cameras[1].1.eye, DVec3::new(3.0, 1.0, 4.0), "side eye");
    near1(s.cameras[1].1.fov_y_deg, 0.5f64.to_degrees(), "side fov");
    // No camera: the framing camera is the one listed.
    let s = load(&triangle(json!({})));
    assert_eq!(s.cameras.len(), 1);
    assert_eq!(s.cameras[0].1, s.scene.camera);
}

/// An orthographic camera is read as one (its half height, near and far), written back as one,
/// and its bad values are one-line errors.
#[test]
fn orthographic_cameras_are_read_and_written() {
    let ortho = |o: Value| {
        triangle(json!({
            "scenes": [{ "nodes": [0, 1] }],
            "nodes": [{ "mesh": 0 }, { "camera": 0, "translation": [0.0, 0.0, 5.0] }],
            "cameras": [{ "type": "orthographic", "orthographic": o }],
        }))
    };
    let s = load(&ortho(json!({ "xmag": 16.0 / 9.0 * 2.5, "ymag": 2.5, "znear": 0.0, "zfar": 20.0 })));
    let c = s.scene.camera;
    assert_eq!((c.orthographic, c.near, c.far), (Some(2.5), 0.0, 20.0));
    assert!(!s.warnings.iter().any(|w| w.contains("orthographic") || w.contains("xmag")), "{:?}", s.warnings);
    let again = load(scene_to_gltf_json(&s.scene, &s.settings).as_bytes()).scene;
    assert_eq!(again.camera.orthographic, Some(2.5));
    near(again.camera.eye, c.eye, "eye");
    // A square xmag/ymag is drawn at the image's aspect, and said.
    let s = load(&ortho(json!({ "xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 20.0 })));
    assert!(s.warnings.iter().any(|w| w.contains("xmag/ymag")), "{:?}", s.warnings);
    for (o, want) in [
        (json!({ "xmag": 1.0, "ymag": 0.0, "znear": 0.1, "zfar": 20.0 }), "camera 0: ymag 0 is not a positive number"),
        (json!({ "xmag": 1.0, "ymag": 1.0, "znear": 5.0, "zfar": 2.0 }), "0 ≤ znear < zfar is required"),
    ] {
        let e = load_scene_from_slice(&ortho(o)).expect_err("an error").to_string();
        assert!(e.contains(want), "{e}");
    }
}
