//! Any JSON value as `extras.shadelab` of the scene, its material and its light (the range-checked
//! fields of `gltf_io/extras.rs`): an `Err` naming the field is fine, a panic is a bug. Bytes that
//! are not JSON are tried as a JSON string.
#![no_main]

use libfuzzer_sys::fuzz_target;

/// One triangle with a material and a point light; EXTRAS is replaced by the input.
const SCENE: &str = r#"{
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "extras": {"shadelab": EXTRAS}}]}},
  "scenes": [{"nodes": [0, 1], "extras": {"shadelab": EXTRAS}}],
  "nodes": [{"mesh": 0}, {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 2, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
  "materials": [{"extras": {"shadelab": EXTRAS}}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]
}"#;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let value: serde_json::Value = serde_json::from_str(&text).unwrap_or(serde_json::Value::String(text.into_owned()));
    let doc = SCENE.replace("EXTRAS", &value.to_string());
    let _ = shadelab_model::gltf_io::load_scene_from_slice(doc.as_bytes());
});
