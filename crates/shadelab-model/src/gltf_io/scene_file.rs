//! The scene file as a whole: the entry points that read and write one, the glTF scene's own
//! fields (its roots, its name, `extras.shadelab` with the ambient light and the pipeline the
//! file asks for), and the order in which the concepts' readers and writers run.

use super::cameras::FALLBACK_FOV_Y_DEG;
use super::container::{Externals, Writer, embedded_buffer, glb_container, load_buffers, split_container};
use super::extras::{self, Named, Rgb, Unit};
use super::meshes::Prim;
use super::slices::slice_end;
use super::{DEFAULT_AMBIENT, GltfError, LoadedScene, MAX_FILE_BYTES, SceneSettings};
use crate::mesh::TriangleMesh;
use crate::params::{IlluminationModel, ShadingMode, SpecularModel};
use crate::scene::{Camera, Scene};
use glam::{DQuat, DVec3};
use gltf::json;
use serde_json::{Value, json};
use std::borrow::Cow;
use std::collections::HashMap;
use std::io::Read;
use std::path::Path;

/// The extensions this loader reads; any other in `extensionsRequired` is an error, in
/// `extensionsUsed` a warning.
pub const SUPPORTED_EXTENSIONS: &[&str] = &[
    "KHR_lights_punctual",
    "KHR_materials_ior",
    "KHR_materials_specular",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_mesh_quantization",
    "KHR_texture_transform",
];

super::extras_struct! {
    /// `extras.shadelab` of the glTF scene (fields in the order they are checked).
    struct SceneExtras {
        /// `I_amb`.
        ambient: Option<Rgb<Unit>>,
        shading: Option<Named<ShadingMode>>,
        specular: Option<Named<SpecularModel>>,
        /// The illumination model; absent is the Phong model.
        illumination: Option<Named<IlluminationModel>>,
        /// How transparent objects absorb; absent is the chapter's rule.
        absorption: Option<Named<crate::lighting::transmission::AbsorptionChoice>>,
        /// The environment light; absent: none.
        environment: Option<super::environment::EnvironmentExtras>,
    }
}

/// Read a scene file (`.gltf` or `.glb`; external buffers and images inside the file's folder).
pub fn load_scene(path: &Path) -> Result<LoadedScene, GltfError> {
    load_scene_with(path, false)
}

/// [`load_scene`], with `outside` letting its URIs name files outside its folder
/// (`--allow-outside-paths`).
pub fn load_scene_with(path: &Path, outside: bool) -> Result<LoadedScene, GltfError> {
    let (bytes, file) = read_file(path)?;
    let dir = path.parent().unwrap_or(Path::new("."));
    load_scene_from_bytes(&bytes, &file, if outside { Externals::Anywhere(dir) } else { Externals::Dir(dir) })
}

/// The whole file at `path` (at most `MAX_FILE_BYTES`) and the name its errors start with.
pub(super) fn read_file(path: &Path) -> Result<(Vec<u8>, String), GltfError> {
    let file = path.display().to_string();
    let read = |error| GltfError::Read { file: file.clone(), error };
    let f = std::fs::File::open(path).map_err(read)?;
    let len = f.metadata().map_err(read)?.len();
    if len > MAX_FILE_BYTES {
        return Err(GltfError::TooLarge {
            file: file.clone(),
            detail: format!("{len} bytes are more than the limit of {MAX_FILE_BYTES} (MAX_FILE_BYTES)"),
        });
    }
    let mut bytes = Vec::with_capacity(len as usize);
    f.take(MAX_FILE_BYTES).read_to_end(&mut bytes).map_err(read)?;
    Ok((bytes, file))
}

/// Read a scene from memory: the fuzzing entry. External buffers are refused (no folder).
pub fn load_scene_from_slice(bytes: &[u8]) -> Result<LoadedScene, GltfError> {
    load_scene_from_bytes(bytes, "<memory>", Externals::None)
}

/// Read the scene file `main` from files handed in together (the browser's file picker or a
/// drop): its external buffers and images are the others, found by name.
pub fn load_scene_from_files(main: &str, files: &[(String, Vec<u8>)]) -> Result<LoadedScene, GltfError> {
    load_scene_from_bytes(main_file(main, files)?, main, Externals::Files(files))
}

/// The bytes of `main` among files handed in together (none: empty, which the parse refuses).
pub(super) fn main_file<'f>(main: &str, files: &'f [(String, Vec<u8>)]) -> Result<&'f [u8], GltfError> {
    let bytes = files.iter().find(|(n, _)| n == main).map(|(_, b)| b.as_slice()).unwrap_or_default();
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(GltfError::TooLarge {
            file: main.to_string(),
            detail: format!("{} bytes are more than the limit of {MAX_FILE_BYTES} (MAX_FILE_BYTES)", bytes.len()),
        });
    }
    Ok(bytes)
}

/// Read a scene from memory; `name` starts every error line; external buffers and images come
/// from `externals`.
pub fn load_scene_from_bytes(bytes: &[u8], name: &str, externals: Externals) -> Result<LoadedScene, GltfError> {
    super::slices::run_to_end(parse(bytes, name, externals))
}

/// [`load_scene_from_bytes`] in slices (`slices.rs`): the container and the JSON first, then
/// the buffers, then the scene.
pub(super) async fn parse(bytes: &[u8], name: &str, externals: Externals<'_>) -> Result<LoadedScene, GltfError> {
    let mut cx = Cx { file: name.to_string(), warnings: Vec::new(), triangles: 0, morph_offsets: 0 };
    let (json_bytes, bin) = split_container(&cx, bytes)?;
    let root: json::Root =
        json::deserialize::from_slice(json_bytes).map_err(|e| cx.format(format!("invalid glTF JSON: {e}")))?;
    if !root.asset.version.starts_with("2.") {
        return Err(cx.format(format!("glTF version {} (only 2.x is read)", root.asset.version)));
    }
    let unsupported: Vec<&str> =
        root.extensions_required.iter().map(String::as_str).filter(|e| !SUPPORTED_EXTENSIONS.contains(e)).collect();
    if !unsupported.is_empty() {
        return Err(GltfError::UnsupportedRequired { file: cx.file.clone(), extensions: unsupported.join(", ") });
    }
    let ignored: Vec<&str> =
        root.extensions_used.iter().map(String::as_str).filter(|e| !SUPPORTED_EXTENSIONS.contains(e)).collect();
    if !ignored.is_empty() {
        cx.warn(format!("optional extension(s) not supported, ignored: {}", ignored.join(", ")));
    }
    for (what, n) in [("animation", root.animations.len()), ("skin", root.skins.len())] {
        if n > 0 {
            cx.warn(format!("{n} {what}(s) ignored"));
        }
    }
    slice_end().await;
    let buffers = load_buffers(&mut cx, &root, bin, externals)?;
    // Images are read when a material's texture needs them; one no texture names never is.
    for i in 0..root.images.len() {
        if !root.textures.iter().any(|t| t.source.value() == i) {
            cx.warn(format!("image {i}: no texture uses it: skipped, not read"));
        }
    }
    slice_end().await;
    Reader {
        cx,
        root: &root,
        buffers,
        externals,
        prims: HashMap::new(),
        file_meshes: Vec::new(),
        textures: HashMap::new(),
        texture_bytes: 0,
    }
    .scene()
    .await
}

/// Where errors and warnings go: the file's name and what was noticed on the way.
pub(super) struct Cx {
    pub(super) file: String,
    pub(super) warnings: Vec<String>,
    /// Triangles of every object so far (each instance counts), against `MAX_TRIANGLES`.
    pub(super) triangles: usize,
    /// Morph offsets applied so far (targets × vertices), against `MAX_MORPH_OFFSETS`.
    pub(super) morph_offsets: usize,
}

impl Cx {
    pub(super) fn format(&self, detail: String) -> GltfError {
        GltfError::Format { file: self.file.clone(), detail }
    }
    pub(super) fn invalid(&self, detail: String) -> GltfError {
        GltfError::Invalid { file: self.file.clone(), detail }
    }
    pub(super) fn too_large(&self, detail: String) -> GltfError {
        GltfError::TooLarge { file: self.file.clone(), detail }
    }
    pub(super) fn warn(&mut self, w: String) {
        if !self.warnings.contains(&w) {
            self.warnings.push(w);
        }
    }
}

/// A file being read: its JSON, its buffers and what has been read of its meshes.
pub(super) struct Reader<'a> {
    pub(super) cx: Cx,
    pub(super) root: &'a json::Root,
    pub(super) buffers: Vec<Cow<'a, [u8]>>,
    /// (mesh, primitive) → what it became (`None`: not triangles, skipped).
    pub(super) prims: HashMap<(usize, usize), Option<Prim>>,
    /// Meshes read, with the index each got in `Scene::meshes` once an object uses it untransformed.
    pub(super) file_meshes: Vec<(TriangleMesh, Option<usize>)>,
    /// Where external buffer and image files are read from.
    pub(super) externals: Externals<'a>,
    /// glTF texture → its index in `Scene::textures` (`None`: not usable, warned about).
    pub(super) textures: HashMap<usize, Option<usize>>,
    /// Decoded texture bytes so far, against `MAX_TEXTURE_BYTES`.
    pub(super) texture_bytes: u64,
}

impl Reader<'_> {
    /// `list[index]`, or the error line "{owner}{what} {index} does not exist".
    pub(super) fn get<'r, T>(&self, list: &'r [T], index: usize, what: &str, owner: &str) -> Result<&'r T, GltfError> {
        list.get(index).ok_or_else(|| {
            self.cx.invalid(format!("{owner}{what} {index} does not exist (the file has {})", list.len()))
        })
    }

    /// The whole scene: the node graph first (it says which meshes, lights and cameras are
    /// shown), then the materials, the objects, the lights and the cameras.
    async fn scene(mut self) -> Result<LoadedScene, GltfError> {
        let root = self.root;
        let scene_index = root.scene.map(|s| s.value()).or((!root.scenes.is_empty()).then_some(0));
        let (roots, scene_json) = match scene_index {
            Some(s) => {
                let sc = self.get(&root.scenes, s, "scene", "")?;
                (sc.nodes.iter().map(|n| n.value()).collect::<Vec<_>>(), Some(sc))
            }
            // No scene: glTF 2.0 §3.5.1 lets a viewer show nothing; we show every root node.
            None => (parentless_nodes(root), None),
        };
        let instances = self.walk(&roots)?;

        let mut scene = empty_scene(scene_json.and_then(|s| s.name.clone()).unwrap_or_else(|| "glTF scene".into()));
        self.materials(&mut scene).await?;
        let mut default_material = None;
        let mut settings = SceneSettings::default();
        if let Some(sc) = scene_json {
            let ex: SceneExtras = extras::read(&self.cx, &sc.extras, "scene")?;
            if let Some(a) = ex.ambient {
                scene.ambient = a.0;
            }
            settings.shading = ex.shading.map(|s| s.0);
            settings.specular = ex.specular.map(|s| s.0);
            if let Some(m) = ex.illumination {
                scene.illumination = m.0;
            }
            if let Some(a) = ex.absorption {
                scene.absorption = a.0;
            }
            if let Some(e) = ex.environment {
                scene.environment = Some(super::environment::read_environment(&mut self.cx, e, self.externals)?);
            }
        }

        let mut camera_nodes = Vec::new();
        let mut light_nodes = Vec::new();
        for &(ni, world) in &instances {
            let node = &root.nodes[ni];
            if let Some(mi) = node.mesh.map(|m| m.value()) {
                let mesh = self.get(&root.meshes, mi, "mesh", &format!("node {ni}: "))?;
                for pi in 0..mesh.primitives.len() {
                    self.object(ni, mi, pi, &world, &mut scene, &mut default_material).await?;
                    slice_end().await;
                }
            }
            if let Some(ci) = node.camera.map(|c| c.value()) {
                self.get(&root.cameras, ci, "camera", &format!("node {ni}: "))?;
                camera_nodes.push((ni, ci, world));
            }
            if let Some(li) =
                node.extensions.as_ref().and_then(|e| e.khr_lights_punctual.as_ref()).map(|k| k.light.value())
            {
                light_nodes.push((ni, li, world));
            }
        }
        if scene.objects.is_empty() {
            return Err(self.cx.invalid("the scene has no triangle meshes to show".into()));
        }
        for (mesh, slot) in std::mem::take(&mut self.file_meshes) {
            if let Some(i) = slot {
                scene.meshes[i] = mesh;
            }
        }
        let (center, radius) = super::nodes::bounds(&scene);
        self.lights(light_nodes, &mut scene)?;
        let cameras = self.cameras(camera_nodes, center, radius)?;
        scene.camera = cameras[0].1;
        Ok(LoadedScene { scene, settings, warnings: self.cx.warnings, cameras })
    }
}

/// The nodes no node has as a child: what is shown when the file has no scene.
fn parentless_nodes(root: &json::Root) -> Vec<usize> {
    let mut has_parent = vec![false; root.nodes.len()];
    for n in &root.nodes {
        for c in n.children.iter().flatten() {
            if let Some(p) = has_parent.get_mut(c.value()) {
                *p = true;
            }
        }
    }
    (0..root.nodes.len()).filter(|&i| !has_parent[i]).collect()
}

/// A scene named `name` with nothing in it yet: the default ambient and a fallback camera.
fn empty_scene(name: String) -> Scene {
    let camera = Camera {
        eye: DVec3::Z,
        target: DVec3::ZERO,
        up: DVec3::Y,
        fov_y_deg: FALLBACK_FOV_Y_DEG,
        near: 0.1,
        far: 100.0,
        orthographic: None,
    };
    Scene::empty(name, DEFAULT_AMBIENT, camera)
}

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
    root["buffers"] = embedded_buffer(&bin);
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

/// The glTF document without `buffers`, and the one buffer's bytes: every object a node with
/// its mesh, then the camera's node, then one node per light, all roots of the one scene.
fn document(scene: &Scene, settings: &SceneSettings) -> (Value, Vec<u8>) {
    let mut w = Writer::default();
    let mut nodes = Vec::new();
    let mut meshes = Vec::new();
    let mut geometry = HashMap::new();
    for o in &scene.objects {
        let Some(mesh) = super::meshes::write_mesh(&mut w, &mut geometry, scene, o) else { continue };
        meshes.push(mesh);
        nodes.push(super::nodes::object_node(o, meshes.len() - 1));
    }
    let mut extensions_used = Vec::new();
    let materials: Vec<Value> =
        scene.materials.iter().map(|m| super::materials::write_material(m, &mut extensions_used)).collect();

    let (camera_node, camera) = super::cameras::write_camera(&scene.camera);
    nodes.push(camera_node);

    let mut lights = Vec::new();
    for (i, l) in scene.lights.iter().enumerate() {
        let (light, node) = super::lights::write_light(i, l);
        lights.push(light);
        nodes.push(node);
    }
    if !lights.is_empty() {
        extensions_used.push("KHR_lights_punctual");
    }
    extensions_used.sort();
    extensions_used.dedup();

    let scene_extras = SceneExtras {
        ambient: Some(scene.ambient.into()),
        shading: settings.shading.map(Named),
        specular: settings.specular.map(Named),
        illumination: (scene.illumination != IlluminationModel::Phong).then_some(Named(scene.illumination)),
        absorption: (scene.absorption != Default::default()).then_some(Named(scene.absorption)),
        environment: scene.environment.as_ref().map(super::environment::write_environment),
    };
    let mut root = json!({
        "asset": { "version": "2.0", "generator": concat!("shadelab ", env!("CARGO_PKG_VERSION")) },
        "scene": 0,
        "scenes": [{
            "name": scene.name,
            "nodes": (0..nodes.len()).collect::<Vec<_>>(),
            "extras": extras::shadelab(&scene_extras),
        }],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [camera],
    });
    if !scene.textures.is_empty() {
        let (images, samplers, textures) = super::textures::write_textures(scene, |b| w.image_view(b));
        root["images"] = images;
        root["samplers"] = samplers;
        root["textures"] = textures;
    }
    root["accessors"] = json!(w.accessors);
    root["bufferViews"] = json!(w.views);
    if !extensions_used.is_empty() {
        root["extensionsUsed"] = json!(extensions_used);
    }
    if !lights.is_empty() {
        root["extensions"] = json!({ "KHR_lights_punctual": { "lights": lights } });
    }
    (root, w.bin)
}

/// A finite number for one of glTF's own fields (see [`extras::finite`]).
pub(super) fn num(x: f64) -> Value {
    json!(extras::finite(x))
}

pub(super) fn vec3(v: DVec3) -> Value {
    json!([num(v.x), num(v.y), num(v.z)])
}

pub(super) fn rgb(c: [f64; 3]) -> Value {
    json!([num(c[0]), num(c[1]), num(c[2])])
}

/// A node's `rotation` (x, y, z, w), normalized.
pub(super) fn quat(q: DQuat) -> Value {
    let q = q.normalize();
    json!([num(q.x), num(q.y), num(q.z), num(q.w)])
}
