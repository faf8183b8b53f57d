use super::*;
use crate::assets::ASSET_SCENES;
use crate::mesh::TriangleMesh;
use crate::params::{FalloffForm, LightKind};
use crate::scene::{Light, MAX_LIGHTS, Object, Shape, Transform};
use base64::Engine;
use glam::DVec3;
use serde_json::{Value, json};
use std::f64::consts::FRAC_1_SQRT_2;
use std::path::{Path, PathBuf};

/// Values that pass through glTF's f32 fields (transforms, camera) come back within this.
const F32_TOL: f64 = 1e-5;

fn near(a: DVec3, b: DVec3, what: &str) {
    assert!((a - b).abs().max_element() <= F32_TOL * (1.0 + a.abs().max_element()), "{what}: {a} vs {b}");
}

fn near1(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() <= F32_TOL * (1.0 + a.abs()), "{what}: {a} vs {b}");
}

fn object_triangles(s: &Scene, o: &Object) -> Vec<[DVec3; 3]> {
    match o.shape {
        Shape::Mesh(i) => s.meshes[i].triangles().collect(),
        shape => crate::mesh::triangles(shape, o.tessellation),
    }
}

/// Same parameters: materials, ambient, lights' parameters exactly (they travel in extras);
/// shapes and tessellations exactly; transforms, light placement and camera within f32.
pub(crate) fn assert_same_scene(a: &Scene, b: &Scene) {
    assert_eq!(a.name, b.name);
    assert_eq!(a.materials, b.materials);
    assert_eq!(a.ambient, b.ambient);
    assert_eq!(a.objects.len(), b.objects.len());
    for (x, y) in a.objects.iter().zip(&b.objects) {
        assert_eq!((&x.name, x.material), (&y.name, y.material));
        match (x.shape, y.shape) {
            (Shape::Mesh(_), Shape::Mesh(_)) => {
                let (tx, ty) = (object_triangles(a, x), object_triangles(b, y));
                assert_eq!(tx.len(), ty.len(), "{}", x.name);
                for (p, q) in tx.iter().flatten().zip(ty.iter().flatten()) {
                    near(*p, *q, &x.name);
                }
            }
            _ => assert_eq!((x.shape, x.tessellation), (y.shape, y.tessellation), "{}", x.name),
        }
        near(x.transform.translation, y.transform.translation, &x.name);
        near(x.transform.scale, y.transform.scale, &x.name);
        near1(x.transform.rotation_y, y.transform.rotation_y, &x.name);
    }
    assert_eq!(a.lights.len(), b.lights.len());
    for (x, y) in a.lights.iter().zip(&b.lights) {
        assert_eq!(
            (x.kind, x.color, x.intensity, x.falloff_form, x.falloff_alpha, x.d0),
            (y.kind, y.color, y.intensity, y.falloff_form, y.falloff_alpha, y.d0)
        );
        assert_eq!((x.inner_cone, x.outer_cone, x.range), (y.inner_cone, y.outer_cone, y.range));
        near(x.position, y.position, "light position");
        near(x.direction, y.direction, "light direction");
    }
    let (c, d) = (&a.camera, &b.camera);
    near(c.eye, d.eye, "eye");
    near(c.target, d.target, "target");
    near(c.up, d.up, "up");
    near1(c.fov_y_deg, d.fov_y_deg, "fov");
    near1(c.near, d.near, "near");
    near1(c.far, d.far, "far");
    assert!(c.view().abs_diff_eq(d.view(), 1e-5));
    assert_eq!(a.triangle_count(), b.triangle_count());
}

fn project_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn data_uri(bin: &[u8]) -> String {
    format!("data:application/octet-stream;base64,{}", base64::engine::general_purpose::STANDARD.encode(bin))
}

/// A document around one buffer embedded as a data: URI.
fn with_buffer(mut doc: Value, bin: &[u8]) -> Vec<u8> {
    doc["buffers"] = json!([{ "byteLength": bin.len(), "uri": data_uri(bin) }]);
    serde_json::to_vec(&doc).unwrap()
}

fn f32s(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

/// One triangle (positions only, no indices) at node 0; `extra` is merged into the root.
fn triangle(extra: Value) -> Vec<u8> {
    let bin = f32s(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    let mut doc = json!({
        "asset": { "version": "2.0" },
        "scenes": [{ "nodes": [0] }],
        "nodes": [{ "mesh": 0 }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 } }] }],
        "accessors": [{ "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                        "min": [0, 0, 0], "max": [1, 1, 0] }],
        "bufferViews": [{ "buffer": 0, "byteLength": 36 }],
    });
    if let Value::Object(extra) = extra {
        for (k, v) in extra {
            doc[k] = v;
        }
    }
    with_buffer(doc, &bin)
}

fn load(bytes: &[u8]) -> LoadedScene {
    load_scene_from_slice(bytes).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn every_builtin_scene_round_trips_through_gltf_and_glb() {
    for name in crate::scene::BUILTIN_SCENES {
        let scene = Scene::builtin(name).unwrap();
        let settings = SceneSettings { shading: Some(ShadingMode::Gouraud), specular: Some(SpecularModel::Phong) };
        for bytes in [scene_to_gltf_json(&scene, &settings).into_bytes(), scene_to_glb(&scene, &settings)] {
            let back = load(&bytes);
            assert_same_scene(&scene, &back.scene);
            // The extras carry every f64 exactly, so the scene comes back equal, bit for bit.
            assert_eq!(back.scene, scene, "{name}");
            assert_eq!(back.settings, settings);
            assert!(back.warnings.is_empty(), "{name}: {:?}", back.warnings);
            // Analytic shapes come back analytic: the same tessellation, no stored mesh.
            assert!(back.scene.meshes.is_empty(), "{name}");
            // Saving what was loaded is a fixed point (the first save rounds transforms to f32).
            let again = scene_to_gltf_json(&back.scene, &back.settings);
            let twice = load(again.as_bytes());
            assert!(again == scene_to_gltf_json(&twice.scene, &twice.settings), "{name}: second save differs");
        }
    }
}

#[test]
fn save_scene_writes_gltf_or_glb_by_extension() {
    let dir = std::env::temp_dir().join(format!("shadelab-gltf-save-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = Scene::builtin("cube").unwrap();
    for file in ["s.gltf", "s.glb"] {
        let path = dir.join(file);
        save_scene(&scene, &SceneSettings::default(), &path).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        assert_eq!(bytes.starts_with(b"glTF"), file.ends_with(".glb"));
        let back = load_scene(&path).unwrap();
        assert_same_scene(&scene, &back.scene);
        assert_eq!(back.settings, SceneSettings::default());
    }
    let e = save_scene(&scene, &SceneSettings::default(), &dir.join("no/such/dir/s.gltf")).unwrap_err();
    assert!(e.to_string().contains("s.gltf: cannot write"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn mesh_objects_round_trip_with_and_without_normals() {
    let mut scene = Scene::builtin("sphere").unwrap();
    let tris = crate::mesh::triangles(Shape::Cube, 2);
    let normals: Vec<[DVec3; 3]> = tris.iter().map(|t| [crate::mesh::face_normal(t).unwrap(); 3]).collect();
    scene.meshes =
        vec![TriangleMesh::from_soup("soup", &tris, None), TriangleMesh::from_soup("faceted", &tris, Some(&normals))];
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
fn pbr_materials_map_to_the_model() {
    let doc = |mat: Value| {
        triangle(json!({
            "extensionsUsed": ["KHR_materials_ior", "KHR_materials_specular", "KHR_materials_volume",
                               "KHR_materials_transmission"],
            "materials": [mat],
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "material": 0 }] }],
        }))
    };
    // A rough dielectric: C = baseColor, μ = 0.04, m = roughness².
    let m = &load(&doc(json!({ "pbrMetallicRoughness": {
        "baseColorFactor": [0.5, 0.25, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.5 } })))
    .scene
    .materials[0];
    assert_eq!(m.color, [0.5, 0.25, 1.0]);
    assert!((m.mu[0] - 0.04).abs() < 1e-7 && m.mu[0] == m.mu[2]);
    assert_eq!(m.m, 0.25);
    assert_eq!(m.h, PhongExponent::Finite(2.0 / 0.0625 - 2.0));
    assert_eq!((m.r_s, m.r_d, m.r_a), (1.0, 1.0, 1.0));
    // A metal: μ = baseColor, no diffuse colour; roughness 0 is the mirror.
    let m = &load(&doc(json!({ "pbrMetallicRoughness": {
        "baseColorFactor": [1.0, 0.75, 0.25, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.0 } })))
    .scene
    .materials[0];
    assert_eq!((m.mu, m.color, m.m, m.h), ([1.0, 0.75, 0.25], [0.0; 3], 0.0, PhongExponent::Mirror));
    // ior, specular colour, transmission and volume.
    let m = &load(&doc(json!({
        "pbrMetallicRoughness": { "metallicFactor": 0.0 },
        "extensions": {
            "KHR_materials_ior": { "ior": 2.0 },
            "KHR_materials_specular": { "specularFactor": 0.5, "specularColorFactor": [1.0, 0.5, 0.0] },
            "KHR_materials_transmission": { "transmissionFactor": 0.75 },
            "KHR_materials_volume": { "thicknessFactor": 2.0, "attenuationDistance": 0.5,
                                      "attenuationColor": [1.0, 0.5, 0.25] }
        } })))
    .scene
    .materials[0];
    let f0 = crate::presets::mu_from_ior(2.0);
    for (got, want) in m.mu.iter().zip([f0 * 0.5, f0 * 0.25, 0.0]) {
        assert!((got - want).abs() < 1e-7, "{:?}", m.mu);
    }
    assert_eq!((m.transmission, m.thickness), (0.75, 2.0));
    for (got, c) in m.absorption.iter().zip([1.0f64, 0.5, 0.25]) {
        assert!((got - (-c.ln() / 0.5)).abs() < 1e-6, "{:?}", m.absorption);
    }
    // A primitive without a material gets glTF's default one (metallic 1, roughness 1, white).
    let s = load(&triangle(json!({}))).scene;
    assert_eq!(s.materials.len(), 1);
    assert_eq!((s.materials[0].mu, s.materials[0].m), ([1.0; 3], 1.0));
}

#[test]
fn extras_out_of_range_are_one_line_errors() {
    let bad = triangle(json!({
        "materials": [{ "name": "x", "extras": { "shadelab": { "m": 5 } } }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "material": 0 }] }],
    }));
    let e = load_scene_from_slice(&bad).unwrap_err().to_string();
    assert!(e.starts_with("<memory>: material 0: extras.shadelab.m = 5 is not a number in [0, 1]"), "{e}");
    assert!(!e.contains('\n'));
    let bad = triangle(json!({ "scenes": [{ "nodes": [0], "extras": { "shadelab": { "shading": "toon" } } }] }));
    let e = load_scene_from_slice(&bad).unwrap_err().to_string();
    assert!(e.contains("scene: extras.shadelab.shading = \"toon\" is not one of flat, gouraud, phong"), "{e}");
}

#[test]
fn lights_spot_range_limit_and_default() {
    let light = |t: &str| json!({ "type": t, "intensity": std::f64::consts::PI, "color": [1, 0.5, 0.25] });
    let mut lights = vec![light("directional"), json!({ "type": "point", "range": 4.0, "intensity": 1.0 })];
    lights.push(json!({ "type": "spot", "spot": { "outerConeAngle": 0.5 } }));
    lights.extend((0..8).map(|_| light("point")));
    let mut nodes = vec![json!({ "mesh": 0 })];
    nodes.extend((0..lights.len()).map(|i| {
        json!({ "translation": [0, 2, 0], "rotation": [-FRAC_1_SQRT_2, 0, 0, FRAC_1_SQRT_2],
                "extensions": { "KHR_lights_punctual": { "light": i } } })
    }));
    let s = load(&triangle(json!({
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": lights } },
        "nodes": nodes,
        "scenes": [{ "nodes": (0..12).collect::<Vec<_>>() }],
    })));
    assert_eq!(s.scene.lights.len(), MAX_LIGHTS);
    let l = &s.scene.lights[0];
    // I_L = E/π; the node's −z, rotated −90° about x, points down.
    assert_eq!((l.kind, l.color), (LightKind::Directional, [1.0, 0.5, 0.25]));
    assert!((l.intensity - 1.0).abs() < 1e-6);
    near(l.direction, DVec3::NEG_Y, "direction");
    let p = &s.scene.lights[1];
    assert_eq!((p.kind, p.falloff_form, p.falloff_alpha), (LightKind::Point, FalloffForm::Quadratic, 1.0));
    near(p.position, DVec3::new(0.0, 2.0, 0.0), "position");
    assert_eq!(p.range, Some(4.0));
    let spot = &s.scene.lights[2];
    assert_eq!((spot.kind, spot.inner_cone, spot.outer_cone), (LightKind::Spot, 0.0, 0.5f32 as f64));
    near(spot.direction, DVec3::NEG_Y, "spot axis");
    let w = s.warnings.join("\n");
    assert!(w.contains("first 8 are kept"), "{w}");
    assert!(!w.contains("spot") && !w.contains("range"), "spot and range are read, not warned about: {w}");
    // No light at all: a default one, said so.
    let s = load(&triangle(json!({})));
    assert_eq!(s.scene.lights.len(), 1);
    assert!(s.warnings.iter().any(|w| w.contains("no lights")), "{:?}", s.warnings);
    assert!(s.warnings.iter().any(|w| w.contains("no camera")), "{:?}", s.warnings);
}

#[test]
fn hierarchy_transforms_decompose_or_bake() {
    let s = load(&triangle(json!({
        "nodes": [
            { "translation": [1, 0, 0], "children": [1, 2, 3] },
            // Rotation about y and uniform scale: the model's transform form.
            { "mesh": 0, "rotation": [0, 0.3826834, 0, 0.9238795], "scale": [2, 2, 2] },
            // Rotation about x: baked into the positions.
            { "mesh": 0, "rotation": [FRAC_1_SQRT_2, 0, 0, FRAC_1_SQRT_2] },
            // A mirror: baked, winding reversed so the face still points the same way.
            { "mesh": 0, "scale": [-1, 1, 1] },
        ],
    })))
    .scene;
    assert_eq!(s.objects.len(), 3);
    let t = &s.objects[0].transform;
    assert_eq!(s.objects[0].shape, Shape::Mesh(0));
    near(t.translation, DVec3::X, "translation");
    near1(t.rotation_y, 45f64.to_radians(), "rotation_y");
    near(t.scale, DVec3::splat(2.0), "scale");
    let baked = &s.meshes[1].triangle(0);
    near(baked[2], DVec3::new(1.0, 0.0, 1.0), "rotated corner");
    let mirrored = &s.meshes[2].triangle(0);
    let n = crate::mesh::face_normal(mirrored).unwrap();
    near(n, DVec3::Z, "mirrored face normal");
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

/// The public sample `Box.gltf` (Khronos sample models, CC-BY 4.0), read from beside the checkout.
#[test]
fn khronos_box_sample_loads() {
    let path = project_root().join("../shared/gltf-samples/Box.gltf");
    if !path.exists() {
        eprintln!("note: {} is missing; skipping the Box.gltf test", path.display());
        return;
    }
    let s = load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.scene.objects.len(), 1);
    assert_eq!(s.scene.triangle_count(), 12);
    assert_eq!(s.scene.materials.len(), 1);
    // The root node turns y up into −z; turned back, the unit box's bounds are ±0.5 on every axis.
    let (lo, hi) = s.scene.meshes[0].bounds().unwrap();
    near(lo, DVec3::splat(-0.5), "min");
    near(hi, DVec3::splat(0.5), "max");
    // Its file normals are used: 24 vertices, one normal per face corner.
    let m = s.scene.mesh_data(&s.scene.objects[0]);
    assert_eq!(m.smooth_vertices.len(), 24);
    assert!(s.warnings.iter().any(|w| w.contains("no lights")));
    // Its material gives only a base colour: metallic and roughness default to 1 (glTF 2.0
    // §5.22), a rough red metal: μ = base colour, no diffuse colour, m = 1.
    let mat = &s.scene.materials[0];
    assert_eq!((mat.mu, mat.color, mat.m), ([0.8f32 as f64, 0.0, 0.0], [0.0; 3], 1.0), "{mat:?}");
    // And it survives a round trip.
    let again = load(scene_to_gltf_json(&s.scene, &s.settings).as_bytes()).scene;
    assert_same_scene(&s.scene, &again);
}

#[test]
fn shipped_assets_match_their_generators() {
    // `UPDATE_ASSETS=1` rewrites the files from their constructors first (look at the renders
    // of every file it changes before committing it), like `UPDATE_GOLDENS`.
    let update = std::env::var("UPDATE_ASSETS").as_deref() == Ok("1");
    for a in &ASSET_SCENES {
        let path = project_root().join("assets").join(a.file);
        if update {
            save_scene(&(a.scene)(), &a.settings, &path).unwrap();
            eprintln!("wrote {}", path.display());
        }
        let loaded = load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
        let want = (a.scene)();
        assert_same_scene(&want, &loaded.scene);
        assert_eq!(loaded.scene.camera, want.camera, "{}", a.file);
        assert_eq!(loaded.scene.lights, want.lights, "{}", a.file);
        assert_eq!(loaded.scene.objects, want.objects, "{}", a.file);
        assert_eq!(loaded.scene, want, "{}", a.file);
        assert_eq!(loaded.settings, a.settings, "{}", a.file);
        assert!(loaded.warnings.is_empty(), "{}: {:?}", a.file, loaded.warnings);
        let size = std::fs::metadata(&path).unwrap().len();
        assert!(size < 1_000_000, "{}: {size} bytes", a.file);
    }
}

/// The malformed files of `tests/gltf-corpus/`, each with the error its README promises.
#[test]
fn malformed_corpus_gives_the_expected_errors() {
    let dir = project_root().join("tests/gltf-corpus");
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
    // Table rows: | `file` | what | `expected substring` |
    let (mut listed, mut failures) = (Vec::new(), Vec::new());
    for line in readme.lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let file = cells[1].trim_matches('`');
        let expected = cells[3].trim_matches('`');
        let path = dir.join(file);
        let Some(e) = load_scene(&path).err() else {
            failures.push(format!("{file} loaded without an error"));
            continue;
        };
        let msg = e.to_string();
        println!("{msg}");
        if !(msg.starts_with(&path.display().to_string()) && msg.contains(expected) && !msg.contains('\n')) {
            failures.push(format!("{file}: expected '{expected}' in: {msg}"));
        }
        // From memory, the same (but external files).
        let bytes = std::fs::read(&path).unwrap();
        assert!(load_scene_from_slice(&bytes).is_err(), "{file}");
        listed.push(file.to_string());
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| f.ends_with(".gltf") || f.ends_with(".glb"))
        .collect();
    files.sort();
    listed.sort();
    assert_eq!(files, listed, "every corpus file is listed in its README, and only those");
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

#[test]
fn light_kinds_and_falloff_round_trip() {
    let mut scene = Scene::builtin("sphere").unwrap();
    scene.lights = vec![
        Light {
            falloff_form: FalloffForm::Linear,
            d0: 0.5,
            ..Light::point(DVec3::new(1.0, 2.0, 3.0), [0.5; 3], 3.0, 0.0)
        },
        Light::point(DVec3::new(-1.0, 2.0, 3.0), [1.0; 3], 2.0, 0.25),
        Light::directional(DVec3::new(0.0, 0.0, 1.0), [1.0, 0.5, 0.0], 0.5),
        Light { range: Some(7.5), ..Light::point(DVec3::new(0.0, 3.0, 0.0), [1.0; 3], 2.0, 0.5) },
        Light {
            range: Some(12.0),
            ..Light::spot(DVec3::new(2.0, 4.0, 1.0), DVec3::new(-0.3, -1.0, 0.1), [1.0; 3], 5.0, 0.1, (0.2, 0.45))
        },
    ];
    let back = load(&scene_to_glb(&scene, &SceneSettings::default())).scene;
    assert_same_scene(&scene, &back);
    assert_eq!(back.lights[4].kind, LightKind::Spot);
}

#[test]
fn spot_lights_and_range_are_read_from_khr_lights_punctual() {
    let light = |l: Value| {
        triangle(json!({
            "extensionsUsed": ["KHR_lights_punctual"],
            "extensions": { "KHR_lights_punctual": { "lights": [l] } },
            "scenes": [{ "nodes": [0, 1] }],
            "nodes": [
                { "mesh": 0 },
                // Rotated 90° about x: the light's −Z points down −Y.
                { "translation": [0.0, 3.0, 0.0], "rotation": [-0.70710677, 0.0, 0.0, 0.70710677],
                  "extensions": { "KHR_lights_punctual": { "light": 0 } } },
            ],
        }))
    };
    let s = load_scene_from_slice(&light(json!({
        "type": "spot", "intensity": 10.0, "range": 5.0, "spot": { "innerConeAngle": 0.1, "outerConeAngle": 0.6 }
    })))
    .unwrap();
    let l = &s.scene.lights[0];
    assert_eq!(l.kind, LightKind::Spot);
    assert_eq!((l.inner_cone, l.outer_cone, l.range), (0.1f32 as f64, 0.6f32 as f64, Some(5.0)));
    near(l.direction, DVec3::NEG_Y, "spot axis");
    assert!(s.warnings.iter().all(|w| !w.contains("spot") && !w.contains("range")), "{:?}", s.warnings);
    // glTF's default cones, and an outer cone of exactly π/2 as f32.
    let s = load_scene_from_slice(&light(json!({ "type": "spot", "spot": {} }))).unwrap();
    assert_eq!((s.scene.lights[0].inner_cone, s.scene.lights[0].outer_cone), (0.0, std::f32::consts::FRAC_PI_4 as f64));
    let s = load_scene_from_slice(&light(
        json!({ "type": "spot", "spot": { "outerConeAngle": std::f32::consts::FRAC_PI_2 } }),
    ))
    .unwrap();
    assert_eq!(s.scene.lights[0].outer_cone, std::f64::consts::FRAC_PI_2);
    for (bad, says) in [
        (
            json!({ "type": "spot", "spot": { "innerConeAngle": 0.5, "outerConeAngle": 0.5 } }),
            "must be 0 ≤ inner < outer ≤ π/2",
        ),
        (json!({ "type": "spot", "spot": { "outerConeAngle": 2.0 } }), "must be 0 ≤ inner < outer ≤ π/2"),
        (json!({ "type": "spot" }), "a spot light without `spot`"),
        (json!({ "type": "point", "range": 0.0 }), "range 0 is not in [0.000001, 1000000000]"),
    ] {
        let e = load_scene_from_slice(&light(bad)).unwrap_err().to_string();
        assert!(e.contains(says), "{e}");
    }
    let s = load_scene_from_slice(&light(json!({ "type": "directional", "range": 3.0 }))).unwrap();
    assert_eq!(s.scene.lights[0].range, None);
    assert!(s.warnings.iter().any(|w| w.contains("range 3 ignored")), "{:?}", s.warnings);
}

/// A GLB around a document and its BIN chunk.
fn glb(doc: Value, bin: &[u8]) -> Vec<u8> {
    super::save::glb_container(doc, bin.to_vec())
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
fn unsupported_optional_extensions_and_textures_are_warnings() {
    let s = load(&triangle(json!({
        "extensionsUsed": ["KHR_texture_transform", "EXT_meshopt_compression", "KHR_lights_punctual"],
    })));
    let w = s.warnings.join("\n");
    assert!(
        w.contains("optional extension(s) not supported, ignored: KHR_texture_transform, EXT_meshopt_compression"),
        "{w}"
    );
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
