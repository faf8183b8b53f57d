//! A scene reads only what lies in its own folder: absolute paths, `..` that leaves it, links
//! that point out and remote URIs are refused, each in one line, unless outside paths are
//! allowed; a buffer or image nothing uses is not read at all. Each case plants a file outside
//! the scene's folder and checks that it is refused, or read only when allowed.

use super::*;
use crate::gltf_io::load_scene_with;

/// A fresh folder holding `scene/` and, beside it, `outside/secret.bin`: one triangle's
/// positions, so a scene that reads it loads one triangle.
fn planted(case: &str) -> (std::path::PathBuf, std::path::PathBuf) {
    let root = std::env::temp_dir().join(format!("shadelab-confine-{case}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(root.join("scene")).unwrap();
    std::fs::create_dir_all(root.join("outside")).unwrap();
    let secret = root.join("outside").join("secret.bin");
    std::fs::write(&secret, f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0])).unwrap();
    (root, secret)
}

/// The triangle document with its buffer at `uri`, written as `scene/t.gltf`.
fn scene_with_buffer(root: &std::path::Path, uri: &str) -> std::path::PathBuf {
    let mut doc: Value = serde_json::from_slice(&triangle(json!({}))).unwrap();
    doc["buffers"][0]["uri"] = json!(uri);
    let path = root.join("scene").join("t.gltf");
    std::fs::write(&path, serde_json::to_vec(&doc).unwrap()).unwrap();
    path
}

/// Refused confined with a line containing `needle`; read (one triangle) when allowed.
fn refused_unless_allowed(case: &str, uri_of: impl Fn(&std::path::Path) -> String, needle: &str) {
    let (root, secret) = planted(case);
    let scene = scene_with_buffer(&root, &uri_of(&secret));
    let e = load_scene(&scene).unwrap_err().to_string();
    assert!(e.contains(needle) && e.contains("--allow-outside-paths") && !e.contains('\n'), "{case}: {e}");
    assert_eq!(load_scene_with(&scene, true).unwrap().scene.triangle_count(), 1, "{case}: allowed");
    std::fs::remove_dir_all(&root).unwrap();
}

#[test]
fn an_absolute_path_is_refused_unless_allowed() {
    refused_unless_allowed("absolute", |s| s.display().to_string(), "is an absolute path, outside the scene's folder");
}

#[test]
fn a_path_that_climbs_out_is_refused_unless_allowed() {
    refused_unless_allowed("traversal", |_| "../outside/secret.bin".into(), "leaves the scene's folder through '..'");
    // Percent-encoded dots are decoded first: the same path.
    refused_unless_allowed("encoded", |_| "%2E%2E/outside/secret.bin".into(), "through '..'");
    // A '..' that stays inside is a path like any other.
    let (root, secret) = planted("inside");
    std::fs::create_dir_all(root.join("scene").join("sub")).unwrap();
    std::fs::copy(&secret, root.join("scene").join("inside.bin")).unwrap();
    let scene = scene_with_buffer(&root, "sub/../inside.bin");
    assert_eq!(load_scene(&scene).unwrap().scene.triangle_count(), 1);
    std::fs::remove_dir_all(&root).unwrap();
}

#[cfg(unix)]
#[test]
fn a_link_that_points_out_is_refused_unless_allowed() {
    refused_unless_allowed(
        "link",
        |secret| {
            let link = secret.parent().unwrap().parent().unwrap().join("scene").join("link.bin");
            std::os::unix::fs::symlink(secret, &link).unwrap();
            "link.bin".into()
        },
        "is a link to",
    );
}

#[test]
fn a_remote_uri_is_refused_in_one_line() {
    let (root, _) = planted("remote");
    for uri in ["http://example.com/secret.bin", "https://example.com/a.bin", "file://host/share/a.bin"] {
        let scene = scene_with_buffer(&root, uri);
        for outside in [false, true] {
            let e = load_scene_with(&scene, outside).unwrap_err().to_string();
            assert!(e.contains("is a remote URI; shadelab never opens a network connection"), "{uri}: {e}");
        }
    }
    std::fs::remove_dir_all(&root).unwrap();
}

#[test]
fn an_unused_buffer_or_image_is_skipped_with_a_warning_and_never_read() {
    let (root, secret) = planted("unused");
    let mut doc: Value = serde_json::from_slice(&triangle(json!({}))).unwrap();
    // A second buffer, outside the folder, that no view uses; an image no texture names.
    doc["buffers"].as_array_mut().unwrap().push(json!({ "uri": secret.display().to_string(), "byteLength": 36 }));
    doc["images"] = json!([{ "uri": "../outside/secret.bin" }]);
    let path = root.join("scene").join("t.gltf");
    std::fs::write(&path, serde_json::to_vec(&doc).unwrap()).unwrap();
    let loaded = load_scene(&path).unwrap();
    assert_eq!(loaded.scene.triangle_count(), 1);
    let w = loaded.warnings.join("\n");
    assert!(w.contains("buffer 1: no accessor or image uses it: skipped, not read"), "{w}");
    assert!(w.contains("image 0: no texture uses it: skipped, not read"), "{w}");
    std::fs::remove_dir_all(&root).unwrap();
}
