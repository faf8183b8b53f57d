//! Writing glTF 2.0: every object as an indexed triangle mesh with normals (the analytic shapes
//! tessellated, with `extras.shadelab.shape`/`tessellation` so that they load back as the same
//! analytic shapes), materials as PBR fields that approximate the model plus the exact
//! parameters in `extras.shadelab`, lights as `KHR_lights_punctual`, the camera.

use super::{DEFAULT_IOR, DIELECTRIC_MU_MAX, GltfError, SceneSettings};
use crate::mesh::MeshData;
use crate::params::{FalloffForm, LightKind, NamedValue, PhongExponent};
use crate::scene::{COMPOSED_ASPECT, Light, Material, Scene, Shape};
use base64::Engine;
use glam::{DMat3, DQuat, DVec3};
use serde_json::{Value, json};
use std::collections::HashMap;
use std::path::Path;

/// `bufferView.target` values (glTF 2.0 §5.11).
pub(super) const ARRAY_BUFFER: u32 = 34962;
pub(super) const ELEMENT_ARRAY_BUFFER: u32 = 34963;
/// `accessor.componentType` values (glTF 2.0 §5.1.3).
pub(super) const FLOAT: u32 = 5126;
pub(super) const UNSIGNED_INT: u32 = 5125;
/// `primitive.mode` of triangle lists.
pub(super) const TRIANGLES: u32 = 4;

/// Write the scene as `.glb` when the path ends in `.glb`, else as `.gltf` with the buffer
/// embedded as a base64 data: URI.
pub fn save_scene(scene: &Scene, settings: &SceneSettings, path: &Path) -> Result<(), GltfError> {
    let glb = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("glb"));
    let bytes = if glb { scene_to_glb(scene, settings) } else { scene_to_gltf_json(scene, settings).into_bytes() };
    std::fs::write(path, bytes).map_err(|error| GltfError::Write { file: path.display().to_string(), error })
}

/// The scene as `.gltf` JSON text with an embedded buffer.
pub fn scene_to_gltf_json(scene: &Scene, settings: &SceneSettings) -> String {
    let (mut root, bin) = document(scene, settings);
    root["buffers"] = json!([{
        "byteLength": bin.len(),
        "uri": format!("data:application/octet-stream;base64,{}", base64::engine::general_purpose::STANDARD.encode(&bin)),
    }]);
    let mut text = serde_json::to_string_pretty(&root).expect("a JSON value serializes");
    text.push('\n');
    text
}

/// The scene as a binary `.glb` (glTF 2.0 §4.4: header, JSON chunk padded with spaces, BIN
/// chunk padded with zeros).
pub fn scene_to_glb(scene: &Scene, settings: &SceneSettings) -> Vec<u8> {
    let (root, bin) = document(scene, settings);
    glb_container(root, bin)
}

/// A glTF document and its one binary buffer as `.glb` (glTF 2.0 §4.4: header, JSON chunk padded
/// with spaces, BIN chunk padded with zeros); sets `buffers` to that one buffer.
pub(crate) fn glb_container(mut root: Value, mut bin: Vec<u8>) -> Vec<u8> {
    root["buffers"] = json!([{ "byteLength": bin.len() }]);
    let mut json = serde_json::to_vec(&root).expect("a JSON value serializes");
    json.resize(json.len().next_multiple_of(4), b' ');
    bin.resize(bin.len().next_multiple_of(4), 0);
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}

/// A finite number for JSON (a non-finite one, which validated scenes do not hold, becomes 0:
/// JSON has no NaN).
fn num(x: f64) -> Value {
    json!(if x.is_finite() { x } else { 0.0 })
}

fn vec3(v: DVec3) -> Value {
    json!([num(v.x), num(v.y), num(v.z)])
}

fn rgb(c: [f64; 3]) -> Value {
    json!([num(c[0]), num(c[1]), num(c[2])])
}

fn quat(q: DQuat) -> Value {
    let q = q.normalize();
    json!([num(q.x), num(q.y), num(q.z), num(q.w)])
}

/// The glTF document without `buffers`, and the one buffer's bytes.
fn document(scene: &Scene, settings: &SceneSettings) -> (Value, Vec<u8>) {
    let mut w = Writer::default();
    let mut nodes = Vec::new();
    let mut meshes = Vec::new();
    let mut geometry: HashMap<(Shape, u32), Option<Value>> = HashMap::new();
    for o in &scene.objects {
        let key = (o.shape, if matches!(o.shape, Shape::Mesh(_)) { 0 } else { o.tessellation });
        let prim = geometry.entry(key).or_insert_with(|| w.geometry(&scene.mesh_data(o))).clone();
        // An empty mesh has nothing to write (glTF accessors hold at least one element).
        let Some(mut prim) = prim else { continue };
        prim["material"] = json!(o.material);
        let mut mesh = json!({ "name": o.name, "primitives": [prim] });
        if !matches!(o.shape, Shape::Mesh(_)) {
            mesh["extras"] = json!({ "shadelab": { "shape": o.shape.name(), "tessellation": o.tessellation } });
        }
        meshes.push(mesh);
        let t = &o.transform;
        nodes.push(json!({
            "name": o.name,
            "mesh": meshes.len() - 1,
            "translation": vec3(t.translation),
            "rotation": quat(DQuat::from_rotation_y(t.rotation_y)),
            "scale": vec3(t.scale),
            // The exact f64 transform (the node's fields are read as f32); used when it agrees.
            "extras": { "shadelab": {
                "translation": vec3(t.translation), "rotation_y": num(t.rotation_y), "scale": vec3(t.scale),
            } },
        }));
    }
    let mut extensions_used = Vec::new();
    let materials: Vec<Value> = scene.materials.iter().map(|m| material(m, &mut extensions_used)).collect();

    let c = &scene.camera;
    let to_world = c.view().inverse();
    nodes.push(json!({
        "name": "camera",
        "camera": 0,
        "translation": vec3(c.eye),
        "rotation": quat(DQuat::from_mat3(&DMat3::from_mat4(to_world))),
    }));
    let cameras = json!([{
        "name": "camera",
        "type": "perspective",
        "perspective": {
            "yfov": num(c.fov_y_deg.to_radians()),
            "znear": num(c.near),
            "zfar": num(c.far),
            "aspectRatio": num(COMPOSED_ASPECT),
        },
        // The orbit pivot and the up vector: the node's rotation alone does not keep them.
        // and the exact eye (the node's fields are read as f32).
        "extras": { "shadelab": {
            "eye": vec3(c.eye), "target": vec3(c.target), "up": vec3(c.up),
            "fov_y_deg": num(c.fov_y_deg), "near": num(c.near), "far": num(c.far),
        } },
    }]);

    let mut lights = Vec::new();
    for (i, l) in scene.lights.iter().enumerate() {
        lights.push(light(l));
        nodes.push(json!({
            "name": format!("light {i}"),
            "translation": vec3(l.position),
            "rotation": quat(DQuat::from_rotation_arc(DVec3::NEG_Z, l.direction.normalize_or(DVec3::NEG_Y))),
            "extensions": { "KHR_lights_punctual": { "light": i } },
        }));
    }
    if !lights.is_empty() {
        extensions_used.push("KHR_lights_punctual");
    }
    extensions_used.sort();
    extensions_used.dedup();

    let mut scene_extras = json!({ "ambient": rgb(scene.ambient) });
    if let Some(s) = settings.shading {
        scene_extras["shading"] = json!(s.name());
    }
    if let Some(s) = settings.specular {
        scene_extras["specular"] = json!(s.name());
    }
    let mut root = json!({
        "asset": { "version": "2.0", "generator": concat!("shadelab ", env!("CARGO_PKG_VERSION")) },
        "scene": 0,
        "scenes": [{
            "name": scene.name,
            "nodes": (0..nodes.len()).collect::<Vec<_>>(),
            "extras": { "shadelab": scene_extras },
        }],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": cameras,
        "accessors": w.accessors,
        "bufferViews": w.views,
    });
    if !extensions_used.is_empty() {
        root["extensionsUsed"] = json!(extensions_used);
    }
    if !lights.is_empty() {
        root["extensions"] = json!({ "KHR_lights_punctual": { "lights": lights } });
    }
    (root, w.bin)
}

#[derive(Default)]
struct Writer {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl Writer {
    /// Append a buffer view over `bytes` and an accessor on it; returns the accessor's index.
    fn accessor(&mut self, bytes: &[u8], target: u32, mut accessor: Value) -> usize {
        // Every element here is 4-byte aligned (f32 and u32), as glTF 2.0 §3.6.2.4 asks.
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.views.push(json!({ "buffer": 0, "byteOffset": offset, "byteLength": bytes.len(), "target": target }));
        accessor["bufferView"] = json!(self.views.len() - 1);
        self.accessors.push(accessor);
        self.accessors.len() - 1
    }

    /// A primitive (without its material) for a built mesh: the smooth vertices with their
    /// normals, and the indices. `None` for an empty mesh.
    fn geometry(&mut self, m: &MeshData) -> Option<Value> {
        if m.indices.is_empty() {
            return None;
        }
        let positions: Vec<[f32; 3]> = m.smooth_vertices.iter().map(|v| v.position).collect();
        let normals: Vec<[f32; 3]> = m.smooth_vertices.iter().map(|v| v.normal).collect();
        let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in &positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let n = positions.len();
        let pos = self.accessor(
            bytemuck::cast_slice(&positions),
            ARRAY_BUFFER,
            json!({ "componentType": FLOAT, "count": n, "type": "VEC3", "min": lo, "max": hi }),
        );
        let nrm = self.accessor(
            bytemuck::cast_slice(&normals),
            ARRAY_BUFFER,
            json!({ "componentType": FLOAT, "count": n, "type": "VEC3" }),
        );
        let idx = self.accessor(
            bytemuck::cast_slice(&m.indices),
            ELEMENT_ARRAY_BUFFER,
            json!({ "componentType": UNSIGNED_INT, "count": m.indices.len(), "type": "SCALAR" }),
        );
        Some(json!({ "attributes": { "POSITION": pos, "NORMAL": nrm }, "indices": idx, "mode": TRIANGLES }))
    }
}

/// A material: PBR fields that approximate the model (the loader's mapping run backwards), and
/// the model's exact parameters in `extras.shadelab`.
fn material(m: &Material, extensions_used: &mut Vec<&'static str>) -> Value {
    let mu_max = m.mu.iter().fold(0.0f64, |a, b| a.max(*b));
    let mut ext = serde_json::Map::new();
    let (base, metallic) = if mu_max <= DIELECTRIC_MU_MAX {
        // A dielectric: μ through the index of refraction v = (1 + √μ)/(1 − √μ) (spec §5) of its
        // largest channel, the others by KHR_materials_specular's colour.
        let v = crate::brdf::fresnel_v_from_mu(mu_max);
        if (v - DEFAULT_IOR).abs() > 1e-9 {
            ext.insert("KHR_materials_ior".into(), json!({ "ior": num(v) }));
            extensions_used.push("KHR_materials_ior");
        }
        if m.mu.iter().any(|c| (c - mu_max).abs() > 1e-12) && mu_max > 0.0 {
            ext.insert(
                "KHR_materials_specular".into(),
                json!({ "specularColorFactor": rgb(m.mu.map(|c| c / mu_max)) }),
            );
            extensions_used.push("KHR_materials_specular");
        }
        (m.color, 0.0)
    } else {
        // A metal: glTF's F0 is the base colour.
        (m.mu, 1.0)
    };
    if m.transmission > 0.0 {
        ext.insert("KHR_materials_transmission".into(), json!({ "transmissionFactor": num(m.transmission) }));
        extensions_used.push("KHR_materials_transmission");
    }
    if m.thickness > 0.0 || m.absorption.iter().any(|a| *a > 0.0) {
        // e^(−a·x) = c^(x/D) with D = 1: c = e^(−a) (spec §7).
        ext.insert(
            "KHR_materials_volume".into(),
            json!({
                "thicknessFactor": num(m.thickness),
                "attenuationDistance": 1.0,
                "attenuationColor": rgb(m.absorption.map(|a| (-a).exp())),
            }),
        );
        extensions_used.push("KHR_materials_volume");
    }
    let h = match m.h {
        PhongExponent::Mirror => json!("mirror"),
        PhongExponent::Finite(h) => num(h),
    };
    let mut out = json!({
        "name": m.name,
        "pbrMetallicRoughness": {
            "baseColorFactor": [num(base[0]), num(base[1]), num(base[2]), 1.0],
            "metallicFactor": metallic,
            "roughnessFactor": num(m.m.clamp(0.0, 1.0).sqrt()),
        },
        "extras": { "shadelab": {
            "C": rgb(m.color), "m": num(m.m), "h": h, "mu": rgb(m.mu),
            "r_s": num(m.r_s), "r_d": num(m.r_d), "r_a": num(m.r_a),
            "t": num(m.transmission), "a": rgb(m.absorption), "d": num(m.thickness),
        } },
    });
    if !ext.is_empty() {
        out["extensions"] = Value::Object(ext);
    }
    out
}

/// A `KHR_lights_punctual` light. `intensity = I_L·π` (the loader's `I_L = E/π` backwards); a
/// quadratic point light's is divided by α, so that `I_L/(1 + αd²)` and glTF's `intensity/(π d²)`
/// agree far from the light. The exact parameters go in `extras.shadelab`.
fn light(l: &Light) -> Value {
    let pi = std::f64::consts::PI;
    let (kind, intensity) = match l.kind {
        LightKind::Directional => ("directional", l.intensity * pi),
        LightKind::Point | LightKind::Spot => {
            let far =
                if l.falloff_form == FalloffForm::Quadratic && l.falloff_alpha > 0.0 { l.falloff_alpha } else { 1.0 };
            (l.kind.name(), l.intensity * pi / far)
        }
    };
    let mut v = json!({
        "type": kind,
        "color": rgb(l.color),
        "intensity": num(intensity),
        "extras": { "shadelab": {
            "I_L": num(l.intensity),
            "color": rgb(l.color),
            "alpha": num(l.falloff_alpha),
            "falloff_form": l.falloff_form.name(),
            "d0": num(l.d0),
            // Exact placement (the node's fields are read as f32); used when it agrees.
            "position": vec3(l.position),
            "direction": vec3(l.direction),
        } },
    });
    if l.kind == LightKind::Spot {
        v["spot"] = json!({ "innerConeAngle": num(l.inner_cone), "outerConeAngle": num(l.outer_cone) });
        v["extras"]["shadelab"]["inner_cone"] = num(l.inner_cone);
        v["extras"]["shadelab"]["outer_cone"] = num(l.outer_cone);
    }
    if let Some(r) = l.range.filter(|_| l.kind != LightKind::Directional) {
        v["range"] = num(r);
        v["extras"]["shadelab"]["range"] = num(r);
    }
    v
}
