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
