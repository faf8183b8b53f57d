//! Tests of reading and writing glTF, one file per concept (as the code is split); the helpers
//! they share (scene comparison, small hand-made files) and the malformed-file corpus are here.

mod cameras;
mod confine;
mod container;
mod environment;
mod extras;
mod lights;
mod materials;
mod meshes;
mod nodes;
mod scene_file;
mod slices;
mod textures;

use super::*;
use crate::assets::ASSET_SCENES;
use crate::mesh::TriangleMesh;
use crate::params::{FalloffForm, LightKind, PhongExponent, ShadingMode, SpecularModel};
use crate::scene::{Light, MAX_LIGHTS, Object, Scene, Shape, Transform};
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
        assert_eq!(x.shadow, y.shadow);
        near(x.position, y.position, "light position");
        near(x.direction, y.direction, "light direction");
        assert_eq!(x.size, y.size, "area light size");
        if x.kind.is_area() {
            near(x.area_tangent(), y.area_tangent(), "area light tangent");
        }
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

/// A GLB around a document and its BIN chunk.
fn glb(doc: Value, bin: &[u8]) -> Vec<u8> {
    glb_container(doc, bin.to_vec())
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
        // A file that loads, with a warning: the rest of the cell is in one of its warnings.
        if let Some(warning) = expected.strip_prefix("warning: ") {
            match load_scene(&path) {
                Ok(l) if l.warnings.iter().any(|w| w.contains(warning)) => {}
                Ok(l) => failures.push(format!("{file}: no warning '{warning}' in {:?}", l.warnings)),
                Err(e) => failures.push(format!("{file}: expected a warning, got {e}")),
            }
            listed.push(file.to_string());
            continue;
        }
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
