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

/// BoxTextured with its buffer and image moved out of their data: URIs into files of their own,
/// named as a browser hands them over (no folder): the file, and the files beside it.
fn box_textured_split() -> Option<(String, Vec<(String, Vec<u8>)>)> {
    let path = project_root().join("../shared/gltf-samples/BoxTextured.gltf");
    let text = std::fs::read_to_string(&path).ok()?;
    let mut root: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut files = Vec::new();
    let decode = |uri: &str| {
        let payload = uri.split_once(",").unwrap().1;
        base64::engine::general_purpose::STANDARD.decode(payload).unwrap()
    };
    let buffer = &mut root["buffers"][0]["uri"];
    files.push(("box data.bin".to_string(), decode(buffer.as_str().unwrap())));
    *buffer = "sub/box%20data.bin".into();
    let image = &mut root["images"][0]["uri"];
    files.push(("texture.png".to_string(), decode(image.as_str().unwrap())));
    *image = "texture.png".into();
    files.insert(0, ("BoxTextured.gltf".to_string(), serde_json::to_vec(&root).unwrap()));
    Some(("BoxTextured.gltf".into(), files))
}

#[test]
fn files_handed_in_together_read_as_the_folder_does() {
    let Some((main, files)) = box_textured_split() else {
        eprintln!("note: ../shared/gltf-samples is missing; skipping");
        return;
    };
    let given = load_scene_from_files(&main, &files).unwrap_or_else(|e| panic!("{e}"));
    let on_disk = load_scene(&project_root().join("../shared/gltf-samples/BoxTextured.gltf")).unwrap();
    assert_eq!(given.scene, on_disk.scene, "the same scene from files by name as from data: URIs");
    assert_eq!(given.scene.textures.len(), 1);
}

#[test]
fn a_file_not_handed_in_is_one_line_naming_it() {
    let Some((main, mut files)) = box_textured_split() else { return };
    files.retain(|(n, _)| n != "texture.png");
    let e = load_scene_from_files(&main, &files).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("texture.png") && e.contains("not given"), "{e}");
    assert!(!e.contains('\n'), "one line: {e}");
    files.retain(|(n, _)| !n.ends_with(".bin"));
    let e = load_scene_from_files(&main, &files).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("box%20data.bin"), "{e}");
    // Shorter than its byteLength.
    let (main, mut files) = box_textured_split().unwrap();
    files[1].1.truncate(10);
    let e = load_scene_from_files(&main, &files).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("byteLength"), "{e}");
    // No such main file: read as empty bytes, a one-line error.
    assert!(load_scene_from_files("nope.glb", &files).is_err());
}
