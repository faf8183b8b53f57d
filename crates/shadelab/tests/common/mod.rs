//! Helpers shared by the app's test binaries (each uses some of them).
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Run the `shadelab` binary on lavapipe.
pub fn shadelab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_shadelab"))
        .args(args)
        .env("SHADELAB_ADAPTER", "lavapipe")
        .output()
        .expect("run shadelab")
}

/// `shadelab render ARGS --width W --height H --output OUT`, which must succeed (its stderr is the
/// failure's message), and the image it wrote.
pub fn render(args: &[&str], (w, h): (u32, u32), out: &Path) -> image::DynamicImage {
    let (w, h) = (w.to_string(), h.to_string());
    let size = ["--width", w.as_str(), "--height", h.as_str(), "--output", out.to_str().unwrap()];
    let o = shadelab(&[&["render"][..], args, &size].concat());
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    image::open(out).unwrap_or_else(|e| panic!("{}: {e}", out.display()))
}

/// The folder the CLI tests write into.
pub fn out_dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// stderr lines that are shadelab's own (the Vulkan driver may print its own warnings).
pub fn error_lines(o: &Output) -> Vec<String> {
    String::from_utf8_lossy(&o.stderr).lines().filter(|l| l.starts_with("error:")).map(String::from).collect()
}

/// The project's root folder.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The shipped figure 7.3 scene with a second camera, "from above", 8 units up and looking down,
/// written as `dir/name` (its buffers are embedded, so the copy stands alone).
pub fn two_camera_scene(dir: &Path, name: &str) -> PathBuf {
    let text = std::fs::read_to_string(root().join("assets/figure-7-3-pyramid.gltf")).unwrap();
    let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    doc["cameras"].as_array_mut().unwrap().push(serde_json::json!({
        "name": "from above", "type": "perspective", "perspective": { "yfov": 0.8, "znear": 0.1, "zfar": 50.0 }
    }));
    let camera = doc["cameras"].as_array().unwrap().len() - 1;
    // Looking down −Y: rotated −90° about x.
    doc["nodes"].as_array_mut().unwrap().push(serde_json::json!({
        "camera": camera, "translation": [0.0, 8.0, 0.0], "rotation": [-0.70710677, 0.0, 0.0, 0.70710677]
    }));
    let node = doc["nodes"].as_array().unwrap().len() - 1;
    doc["scenes"][0]["nodes"].as_array_mut().unwrap().push(node.into());
    let path = dir.join(name);
    std::fs::write(&path, serde_json::to_string(&doc).unwrap()).unwrap();
    path
}
