//! Tests of what real files bring beside positions and normals: base colour textures (decoded,
//! sampled, saved and read back), vertex colours, sparse accessors, quantized attributes, morph
//! targets at their default weights, and the hostile variants of each.

use super::*;
use crate::reference::render_reference;

/// A public sample from beside the checkout, or `None` (with a note) where it is missing.
fn sample(name: &str) -> Option<LoadedScene> {
    let path = project_root().join("../shared/gltf-samples").join(name);
    if !path.exists() {
        eprintln!("note: {} is missing; skipping", path.display());
        return None;
    }
    Some(load_scene(&path).unwrap_or_else(|e| panic!("{e}")))
}

/// How many distinct colours (to 1/64) the reference image shows on objects.
fn distinct_colors(s: &Scene) -> usize {
    let img = render_reference(s, SpecularModel::CookTorrance, 96, 54);
    let mut seen: Vec<[i64; 3]> = img
        .pixels
        .iter()
        .zip(&img.object)
        .filter(|(_, o)| o.is_some())
        .map(|(p, _)| p.map(|c| (c * 64.0).round() as i64))
        .collect();
    seen.sort();
    seen.dedup();
    seen.len()
}

/// A PNG of `w × h` RGBA pixels.
fn png(w: u32, h: u32, px: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    image::ImageEncoder::write_image(
        image::codecs::png::PngEncoder::new(&mut out),
        px,
        w,
        h,
        image::ExtendedColorType::Rgba8,
    )
    .unwrap();
    out
}

/// One textured triangle: positions, TEXCOORD_0 from `uv_accessor` (merged over a VEC2 FLOAT
/// accessor 1), a material whose base colour texture is image `image` with `sampler`.
fn textured_triangle(image: Value, sampler: Value, uv_accessor: Value) -> Vec<u8> {
    let mut bin = f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    bin.extend(f32s(&[0.0, 0.0, 1.0, 0.0, 0.0, 1.0]));
    let mut uv = json!({ "bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2" });
    if let Value::Object(m) = uv_accessor {
        for (k, v) in m {
            uv[k] = v;
        }
    }
    let doc = json!({
        "asset": { "version": "2.0" },
        "scenes": [{ "nodes": [0] }],
        "nodes": [{ "mesh": 0 }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0, "TEXCOORD_0": 1 }, "material": 0 }] }],
        "materials": [{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 }, "metallicFactor": 0.0 } }],
        "textures": [{ "source": 0, "sampler": 0 }],
        "images": [image],
        "samplers": [sampler],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0] },
            uv,
        ],
        "bufferViews": [{ "buffer": 0, "byteLength": 36 }, { "buffer": 0, "byteOffset": 36, "byteLength": 24 }],
    });
    with_buffer(doc, &bin)
}

fn png_uri(bytes: &[u8]) -> Value {
    json!({ "uri": format!("data:image/png;base64,{}", base64::engine::general_purpose::STANDARD.encode(bytes)) })
}

fn error_of(bytes: &[u8]) -> String {
    match load_scene_from_slice(bytes) {
        Ok(_) => panic!("loaded"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn box_textured_shows_its_texture_and_round_trips() {
    let Some(s) = sample("BoxTextured.gltf") else { return };
    assert_eq!(s.scene.textures.len(), 1, "{:?}", s.warnings);
    let t = &s.scene.textures[0];
    assert!(t.width > 1 && t.height > 1);
    assert!(s.scene.materials[0].base_color_texture.is_some());
    assert!(s.scene.meshes[0].uvs.is_some());
    // Its sampler asks for NEAREST_MIPMAP_LINEAR, and gets it.
    assert_eq!(
        (t.sampler.min, t.sampler.mipmap),
        (crate::Filter::Nearest, Some(crate::Filter::Linear)),
        "{:?}",
        t.sampler
    );
    assert!(!s.warnings.iter().any(|w| w.contains("minFilter")), "{:?}", s.warnings);
    assert!(!s.warnings.iter().any(|w| w.contains("texture") && w.contains("ignored")), "{:?}", s.warnings);
    // The logo's colours show; the same box without its texture is one colour per face.
    let with = distinct_colors(&s.scene);
    let mut plain = s.scene.clone();
    plain.materials[0].base_color_texture = None;
    let without = distinct_colors(&plain);
    assert!(with > 4 * without, "{with} colours with the texture, {without} without");
    // Saved (the PNG as it was) and read again: the same pixels, the same image.
    for bytes in [scene_to_gltf_json(&s.scene, &s.settings).into_bytes(), scene_to_glb(&s.scene, &s.settings)] {
        let again = load(&bytes);
        assert_eq!(again.scene.textures.len(), 1);
        assert_eq!(again.scene.textures[0].rgba8, t.rgba8);
        assert_eq!(again.scene.textures[0].sampler, t.sampler);
        let (a, b) = (
            render_reference(&s.scene, SpecularModel::CookTorrance, 48, 27),
            render_reference(&again.scene, SpecularModel::CookTorrance, 48, 27),
        );
        let worst = a.pixels.iter().zip(&b.pixels).flat_map(|(p, q)| (0..3).map(move |i| (p[i] - q[i]).abs()));
        assert!(worst.fold(0.0, f64::max) < 1e-5);
    }
}

#[test]
fn box_vertex_colors_show_their_colours() {
    let Some(s) = sample("BoxVertexColors.gltf") else { return };
    let m = &s.scene.meshes[0];
    let colors = m.colors.as_ref().expect("COLOR_0 read");
    assert_eq!(colors.len(), m.positions.len());
    // The file has no material: glTF's default grey, so without the colours every pixel is grey
    // (r = g = b); with them, the pixels take the vertices' hues.
    let chroma = |s: &Scene| {
        let img = render_reference(s, SpecularModel::CookTorrance, 64, 36);
        let on: Vec<&[f64; 3]> =
            img.pixels.iter().zip(&img.object).filter(|(_, o)| o.is_some()).map(|(p, _)| p).collect();
        assert!(on.len() > 100);
        on.iter()
            .map(|p| p.iter().fold(0.0f64, |a, c| a.max(*c)) - p.iter().fold(1e9f64, |a, c| a.min(*c)))
            .fold(0.0, f64::max)
    };
    let mut plain = s.scene.clone();
    plain.meshes[0].colors = None;
    assert!(chroma(&plain) < 1e-12);
    assert!(chroma(&s.scene) > 0.2, "{}", chroma(&s.scene));
    let again = load(scene_to_gltf_json(&s.scene, &s.settings).as_bytes());
    assert_eq!(again.scene.meshes[0].colors.as_ref(), Some(colors));
}

#[test]
fn simple_sparse_accessor_moves_its_positions() {
    let Some(s) = sample("SimpleSparseAccessor.gltf") else { return };
    let p = &s.scene.meshes[0].positions;
    // Two rows of 7 vertices at y = 0 and y = 1; the three sparse values lift vertices 8, 10
    // and 12 to y = 2, 3 and 4 (the accessor's max).
    for (i, v) in p.iter().enumerate() {
        let y = match i {
            0..=6 => 0.0,
            8 => 2.0,
            10 => 3.0,
            12 => 4.0,
            _ => 1.0,
        };
        assert_eq!(v.y, y, "vertex {i}: {p:?}");
    }
}

#[test]
fn a_texture_in_a_file_is_sampled_by_the_reference() {
    // 2×1: red, then blue; nearest filter; u < ½ is red.
    let img = png(2, 1, &[255, 0, 0, 255, 0, 0, 255, 255]);
    let s = load(&textured_triangle(png_uri(&img), json!({ "magFilter": 9728, "minFilter": 9728 }), json!({})));
    assert!(!s.warnings.iter().any(|w| w.contains("minFilter")), "{:?}", s.warnings);
    assert_eq!(s.scene.textures[0].sampler.mipmap, None, "NEAREST: level 0 only");
    let m = &s.scene.materials[0];
    let red = m.surface_at(&s.scene.textures, [0.25, 0.5], None, [1.0; 3]).color;
    let blue = m.surface_at(&s.scene.textures, [0.75, 0.5], None, [1.0; 3]).color;
    assert!(red[0] > 0.9 && red[2] == 0.0 && blue[2] > 0.9 && blue[0] == 0.0, "{red:?} {blue:?}");
}

#[test]
fn quantized_and_normalized_attributes_are_read() {
    // TEXCOORD_0 as normalized UNSIGNED_SHORT (core glTF), 65535 = 1.
    let mut bytes = f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    for v in [0u16, 0, 65535, 0, 0, 65535] {
        bytes.extend(v.to_le_bytes());
    }
    let doc = json!({
        "asset": { "version": "2.0" },
        "extensionsUsed": ["KHR_mesh_quantization"],
        "extensionsRequired": ["KHR_mesh_quantization"],
        "scenes": [{ "nodes": [0] }],
        "nodes": [{ "mesh": 0 }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0, "TEXCOORD_0": 1 } }] }],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3" },
            { "bufferView": 1, "componentType": 5123, "normalized": true, "count": 3, "type": "VEC2" },
        ],
        "bufferViews": [{ "buffer": 0, "byteLength": 36 }, { "buffer": 0, "byteOffset": 36, "byteLength": 12 }],
    });
    let s = load(&with_buffer(doc.clone(), &bytes));
    assert_eq!(s.scene.meshes[0].uvs.as_deref(), Some(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]][..]));
    // Positions as SHORT, not normalized (KHR_mesh_quantization): their integer values.
    let mut q = Vec::new();
    for v in [0i16, 0, 0, 0, 2, 0, 0, 0, 0, 3, 0, 0] {
        q.extend(v.to_le_bytes());
    }
    let mut doc = doc;
    doc["accessors"] = json!([{ "bufferView": 0, "componentType": 5122, "count": 3, "type": "VEC3" }]);
    doc["bufferViews"] = json!([{ "buffer": 0, "byteLength": 24, "byteStride": 8 }]);
    doc["meshes"][0]["primitives"][0]["attributes"] = json!({ "POSITION": 0 });
    let s = load(&with_buffer(doc, &q));
    assert_eq!(s.scene.meshes[0].positions[1], DVec3::new(2.0, 0.0, 0.0));
    assert_eq!(s.scene.meshes[0].positions[2], DVec3::new(0.0, 3.0, 0.0));
}

#[test]
fn morph_targets_apply_at_the_default_weights() {
    let mut bin = f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    bin.extend(f32s(&[0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
    let doc = json!({
        "asset": { "version": "2.0" },
        "scenes": [{ "nodes": [0] }],
        "nodes": [{ "mesh": 0 }],
        "meshes": [{ "weights": [0.5], "primitives": [{ "attributes": { "POSITION": 0 }, "targets": [{ "POSITION": 1 }] }] }],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3" },
            { "bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3" },
        ],
        "bufferViews": [{ "buffer": 0, "byteLength": 36 }, { "buffer": 0, "byteOffset": 36, "byteLength": 36 }],
    });
    let s = load(&with_buffer(doc.clone(), &bin));
    assert_eq!(s.scene.meshes[0].positions[0], DVec3::new(0.0, 0.0, 1.0));
    let mut bad = doc;
    bad["meshes"][0]["weights"] = json!([0.5, 0.5]);
    assert!(error_of(&with_buffer(bad, &bin)).contains("1 morph targets but 2 mesh weights"));
}

#[test]
fn sparse_accessors_without_a_view_and_broken_ones() {
    // Positions all zero but for the substituted vertices 1 and 2.
    let mut bin = Vec::new();
    for i in [1u16, 2] {
        bin.extend(i.to_le_bytes());
    }
    bin.extend(f32s(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0]));
    let doc = |indices: [u16; 2]| {
        let mut b = Vec::new();
        for i in indices {
            b.extend(i.to_le_bytes());
        }
        b.extend(&bin[4..]);
        with_buffer(
            json!({
                "asset": { "version": "2.0" },
                "scenes": [{ "nodes": [0] }],
                "nodes": [{ "mesh": 0 }],
                "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 } }] }],
                "accessors": [{ "componentType": 5126, "count": 3, "type": "VEC3", "sparse": {
                    "count": 2, "indices": { "bufferView": 0, "componentType": 5123 }, "values": { "bufferView": 1 } } }],
                "bufferViews": [{ "buffer": 0, "byteLength": 4 }, { "buffer": 0, "byteOffset": 4, "byteLength": 24 }],
            }),
            &b,
        )
    };
    let s = load(&doc([1, 2]));
    assert_eq!(s.scene.meshes[0].positions, vec![DVec3::ZERO, DVec3::X, DVec3::Y]);
    assert!(error_of(&doc([2, 1])).contains("is not increasing or not below the count 3"));
    assert!(error_of(&doc([1, 7])).contains("index 7 (entry 1)"));
}

#[test]
fn hostile_textures_get_one_line_and_no_panic() {
    let ok_png = png(1, 1, &[255; 4]);
    let tri = |image: Value, sampler: Value| load_scene_from_slice(&textured_triangle(image, sampler, json!({})));
    // Bytes that are not an image: a warning, drawn without the texture.
    let s = tri(json!({ "uri": "data:image/png;base64,aGVsbG8=" }), json!({})).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("image 0: not a PNG or JPEG image")), "{:?}", s.warnings);
    assert!(s.scene.materials[0].base_color_texture.is_none());
    // A PNG header that declares 100000 × 100000 pixels: refused before decoding.
    let mut huge = ok_png.clone();
    huge[16..20].copy_from_slice(&100_000u32.to_be_bytes());
    huge[20..24].copy_from_slice(&100_000u32.to_be_bytes());
    let e = tri(png_uri(&huge), json!({})).err().map(|e| e.to_string()).unwrap_or_default();
    let warned = tri(png_uri(&huge), json!({})).ok().map(|s| s.warnings.join("; ")).unwrap_or_default();
    assert!(e.contains("MAX_TEXTURE_SIDE") || warned.contains("image 0"), "{e} / {warned}");
    // An image in a buffer view past the end of its buffer.
    let mut doc: Value = serde_json::from_slice(&textured_triangle(
        json!({ "bufferView": 2, "mimeType": "image/png" }),
        json!({}),
        json!({}),
    ))
    .unwrap();
    doc["bufferViews"].as_array_mut().unwrap().push(json!({ "buffer": 0, "byteOffset": 40, "byteLength": 1000 }));
    assert!(error_of(&serde_json::to_vec(&doc).unwrap()).contains("buffer view 2: bytes 40..1040 are past the end"));
    // A sampler with values glTF does not define: its defaults, with a warning.
    let s = tri(png_uri(&ok_png), json!({ "wrapS": 1234, "magFilter": 7 })).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("sampler 0: wrapS is not a glTF wrap mode")), "{:?}", s.warnings);
    assert_eq!(s.scene.textures[0].sampler, crate::scene::Sampler::default());
    // A texture index out of range.
    let mut doc: Value = serde_json::from_slice(&textured_triangle(png_uri(&ok_png), json!({}), json!({}))).unwrap();
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = json!(5);
    assert!(
        error_of(&serde_json::to_vec(&doc).unwrap()).contains("material 0: baseColorTexture: texture 5 does not exist")
    );
    // Texture coordinates that are NaN or far out of range: the reference stays finite.
    let mut bin = f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    bin.extend(f32s(&[f32::NAN, 0.0, 1e30, -1e30, f32::INFINITY, 0.5]));
    let mut doc: Value = serde_json::from_slice(&textured_triangle(png_uri(&ok_png), json!({}), json!({}))).unwrap();
    doc["buffers"] = json!([{ "byteLength": bin.len(), "uri": data_uri(&bin) }]);
    let s = load(&serde_json::to_vec(&doc).unwrap()).scene;
    let img = render_reference(&s, SpecularModel::CookTorrance, 32, 18);
    assert!(img.pixels.iter().flatten().all(|c| c.is_finite()));
}

/// One triangle facing +z with a normal texture: POSITION, NORMAL (unless `normals` is false),
/// TEXCOORD_0 (unless `uvs` is false) and, with `tangent`, that TANGENT at every vertex.
fn normal_mapped_triangle(normals: bool, uvs: bool, tangent: Option<[f32; 4]>) -> Vec<u8> {
    let mut bin = f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    bin.extend(f32s(&[0.0, 0.0, 1.0, 0.0, 0.0, 1.0]));
    bin.extend(f32s(&[0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0]));
    let t = tangent.unwrap_or([0.0; 4]);
    bin.extend(f32s(&[t, t, t].concat()));
    let mut attributes = json!({ "POSITION": 0 });
    if uvs {
        attributes["TEXCOORD_0"] = json!(1);
    }
    if normals {
        attributes["NORMAL"] = json!(2);
    }
    if tangent.is_some() {
        attributes["TANGENT"] = json!(3);
    }
    let flat = png(1, 1, &[128, 128, 255, 255]);
    let doc = json!({
        "asset": { "version": "2.0" },
        "scenes": [{ "nodes": [0] }],
        "nodes": [{ "mesh": 0 }],
        "meshes": [{ "primitives": [{ "attributes": attributes, "material": 0 }] }],
        "materials": [{ "normalTexture": { "index": 0, "scale": 0.5 } }],
        "textures": [{ "source": 0 }],
        "images": [png_uri(&flat)],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0] },
            { "bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2" },
            { "bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC3" },
            { "bufferView": 3, "componentType": 5126, "count": 3, "type": "VEC4" },
        ],
        "bufferViews": [
            { "buffer": 0, "byteLength": 36 },
            { "buffer": 0, "byteOffset": 36, "byteLength": 24 },
            { "buffer": 0, "byteOffset": 60, "byteLength": 36 },
            { "buffer": 0, "byteOffset": 96, "byteLength": 48 },
        ],
    });
    with_buffer(doc, &bin)
}

/// The warnings about the normal texture and the tangents (the file has no light or camera).
fn tangent_warnings(s: &LoadedScene) -> Vec<&String> {
    s.warnings.iter().filter(|w| w.contains("TANGENT") || w.contains("normal")).collect()
}

#[test]
fn a_normal_texture_gets_the_files_tangents_or_mikktspace() {
    // The file's own TANGENT is used as it is.
    let s = load(&normal_mapped_triangle(true, true, Some([0.0, 1.0, 0.0, -1.0])));
    assert_eq!(s.scene.materials[0].maps.normal.map(|n| n.scale), Some(0.5));
    assert_eq!(s.scene.meshes[0].tangents.as_deref(), Some(&[[0.0, 1.0, 0.0, -1.0]; 3][..]));
    assert!(tangent_warnings(&s).is_empty(), "{:?}", s.warnings);
    // None in the file: MikkTSpace's, u along +x here.
    let s = load(&normal_mapped_triangle(true, true, None));
    let t = s.scene.meshes[0].tangents.as_ref().expect("generated tangents");
    assert!(t.iter().all(|t| (t[0] - 1.0).abs() < 1e-5 && t[1].abs() < 1e-5 && t[3].abs() == 1.0), "{t:?}");
    assert!(tangent_warnings(&s).is_empty(), "{:?}", s.warnings);
    // No normals: glTF's flat ones, and MikkTSpace's tangents in them.
    let s = load(&normal_mapped_triangle(false, true, None));
    assert!(s.scene.meshes[0].tangents.is_some(), "{:?}", s.warnings);
    // No texture coordinates: no frame, and the loader says so.
    let s = load(&normal_mapped_triangle(true, false, None));
    assert!(s.scene.meshes[0].tangents.is_none());
    assert!(s.warnings.iter().any(|w| w.contains("normalTexture needs NORMAL and TEXCOORD_0")), "{:?}", s.warnings);
    // A tangent that is not finite: warned about, and the texture leaves the normal there.
    let s = load(&normal_mapped_triangle(true, true, Some([f32::NAN, 0.0, 0.0, 1.0])));
    assert!(s.warnings.iter().any(|w| w.contains("TANGENT value is not finite")), "{:?}", s.warnings);
}

#[test]
fn the_normal_and_occlusion_slots_read_their_texture_transform() {
    let mut doc: Value = serde_json::from_slice(&normal_mapped_triangle(true, true, None)).unwrap();
    let transform = json!({ "KHR_texture_transform": { "offset": [0.5, 0.0], "scale": [2.0, 2.0] } });
    doc["materials"][0]["normalTexture"]["extensions"] = transform.clone();
    doc["materials"][0]["occlusionTexture"] = json!({ "index": 0, "strength": 0.5, "extensions": transform });
    doc["extensionsUsed"] = json!(["KHR_texture_transform"]);
    let s = load(&serde_json::to_vec(&doc).unwrap());
    let m = &s.scene.materials[0];
    let (n, o) = (m.maps.normal.unwrap(), m.maps.occlusion.unwrap());
    for t in [n.texture.transform, o.texture.transform] {
        assert_eq!((t.offset, t.scale), ([0.5, 0.0], [2.0, 2.0]), "{:?}", s.warnings);
    }
    assert_eq!(o.strength, 0.5);
    // Saved and read back: the same transforms.
    let again = load(&crate::gltf_io::scene_to_glb(&s.scene, &s.settings));
    assert_eq!(again.scene.materials[0].maps, m.maps);
    // A malformed one is an error naming its slot.
    doc["materials"][0]["normalTexture"]["extensions"] = json!({ "KHR_texture_transform": { "scale": "big" } });
    let e = error_of(&serde_json::to_vec(&doc).unwrap());
    assert!(e.contains("material 0: normalTexture: KHR_texture_transform"), "{e}");
}
