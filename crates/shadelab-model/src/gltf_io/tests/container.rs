//! Tests of the container and its buffers: external buffer files, and truncated or damaged files.

use super::*;

#[test]
fn external_buffers_are_read_beside_the_file() {
    let dir = std::env::temp_dir().join(format!("shadelab-gltf-ext-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut doc: Value = serde_json::from_slice(&triangle(json!({}))).unwrap();
    doc["buffers"][0]["uri"] = json!("tri%20angle.bin");
    std::fs::write(dir.join("tri angle.bin"), f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0])).unwrap();
    std::fs::write(dir.join("t.gltf"), serde_json::to_vec(&doc).unwrap()).unwrap();
    let s = load_scene(&dir.join("t.gltf")).unwrap();
    assert_eq!(s.scene.triangle_count(), 1);
    // From memory there is no folder to read it from.
    let e = load_scene_from_slice(&serde_json::to_vec(&doc).unwrap()).unwrap_err().to_string();
    assert!(e.contains("cannot be read from memory"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Truncating a valid file anywhere never panics (a cheap stand-in for the fuzzer in `fuzz/`).
#[test]
fn every_truncation_of_a_valid_file_is_an_error_not_a_panic() {
    let scene = Scene::builtin("cube").unwrap();
    let glb = scene_to_glb(&scene, &SceneSettings::default());
    for n in (0..glb.len()).step_by(7) {
        assert!(load_scene_from_slice(&glb[..n]).is_err(), "{n}");
    }
    let text = scene_to_gltf_json(&scene, &SceneSettings::default());
    for n in (0..text.len()).step_by(13) {
        assert!(load_scene_from_slice(&text.as_bytes()[..n]).is_err(), "{n}");
    }
    // Every single-byte change of the GLB's header and JSON start.
    for at in 0..64.min(glb.len()) {
        let mut b = glb.clone();
        b[at] ^= 0xFF;
        let _ = load_scene_from_slice(&b);
    }
}
