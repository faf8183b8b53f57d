//! Any bytes as the image of a material's base colour texture, through the loader's texture path
//! (format sniffing, the declared size against MAX_TEXTURE_SIDE and MAX_TEXTURE_BYTES, decoding):
//! an `Err` or a warning is fine, a panic, an abort or an allocation the bytes cannot back is a bug.
#![no_main]

use base64::Engine;
use libfuzzer_sys::fuzz_target;

/// One triangle with texture coordinates and a material whose base colour texture is image 0.
const SCENE: &str = r#"{
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [{"uri": "data:image/png;base64,IMAGE"}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/"}]
}"#;

fuzz_target!(|data: &[u8]| {
    let image = base64::engine::general_purpose::STANDARD.encode(data);
    let doc = SCENE.replace("IMAGE", &image);
    let _ = shadelab_model::gltf_io::load_scene_from_slice(doc.as_bytes());
});
