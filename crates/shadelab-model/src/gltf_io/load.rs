//! Reading glTF 2.0. Every index is looked up with a check, every byte range is checked against
//! the data that backs it *before* anything of its declared size is allocated, and every limit
//! is a named constant (see the module's parent).

use super::{
    DEFAULT_AMBIENT, DEFAULT_IOR, GltfError, LoadedScene, MAX_FILE_BYTES, MAX_NODE_DEPTH, MAX_OBJECTS, MAX_TRIANGLES,
    POINT_FALLOFF_ALPHA, SceneSettings, dielectric_f0, h_from_m, m_from_roughness,
};
use crate::brdf::safe_normalize;
use crate::mesh::TriangleMesh;
use crate::params::{self, FalloffForm, LightKind, NamedValue, ParamRange, PhongExponent, ShadingMode, SpecularModel};
use crate::scene::{Camera, Light, MAX_LIGHTS, Material, Object, Scene, Shape, Transform};
use base64::Engine;
use glam::{DMat3, DMat4, DQuat, DVec3};
use gltf::json;
use gltf::json::validation::Checked;
use serde_json::{Map, Value};
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
];

/// Field of view of a camera placed by the loader (no camera in the file, or an orthographic one):
/// the built-in scenes'.
const FALLBACK_FOV_Y_DEG: f64 = 40.0;

/// Absorption coefficient `a` read from extras (per unit length): `e^(−a·d)` is 0 in f64 long
/// before 1e6.
const ABSORPTION: ParamRange =
    ParamRange { flag: "a", symbol: "a", meaning: "absorption coefficient a", min: 0.0, max: 1e6 };
/// Thickness `d` read from extras.
const THICKNESS: ParamRange = ParamRange { flag: "d", symbol: "d", meaning: "thickness d", min: 0.0, max: 1e6 };

/// Read a scene file (`.gltf` or `.glb`; external buffers relative to the file's folder).
pub fn load_scene(path: &Path) -> Result<LoadedScene, GltfError> {
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
    load_scene_from_bytes(&bytes, &file, Some(path.parent().unwrap_or(Path::new("."))))
}

/// Read a scene from memory: the fuzzing entry. External buffers are refused (no folder).
pub fn load_scene_from_slice(bytes: &[u8]) -> Result<LoadedScene, GltfError> {
    load_scene_from_bytes(bytes, "<memory>", None)
}

/// Read a scene from memory; `name` starts every error line; external buffer files are read from
/// `base_dir` when given.
pub fn load_scene_from_bytes(bytes: &[u8], name: &str, base_dir: Option<&Path>) -> Result<LoadedScene, GltfError> {
    let mut cx = Cx { file: name.to_string(), warnings: Vec::new(), triangles: 0 };
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
    for (what, n) in
        [("animation", root.animations.len()), ("skin", root.skins.len()), ("texture", root.textures.len())]
    {
        if n > 0 {
            cx.warn(format!("{n} {what}(s) ignored"));
        }
    }
    let buffers = load_buffers(&cx, &root, bin, base_dir)?;
    Reader { cx, root: &root, buffers, prims: HashMap::new(), file_meshes: Vec::new() }.scene()
}

/// Where errors and warnings go: the file's name and what was noticed on the way.
struct Cx {
    file: String,
    warnings: Vec<String>,
    /// Triangles of every object so far (each instance counts), against `MAX_TRIANGLES`.
    triangles: usize,
}

impl Cx {
    fn format(&self, detail: String) -> GltfError {
        GltfError::Format { file: self.file.clone(), detail }
    }
    fn invalid(&self, detail: String) -> GltfError {
        GltfError::Invalid { file: self.file.clone(), detail }
    }
    fn too_large(&self, detail: String) -> GltfError {
        GltfError::TooLarge { file: self.file.clone(), detail }
    }
    fn warn(&mut self, w: String) {
        if !self.warnings.contains(&w) {
            self.warnings.push(w);
        }
    }
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
}

/// The JSON text and the GLB's BIN chunk (glTF 2.0 §4.4: a 12-byte header, then chunks of an
/// 8-byte header and 4-byte-aligned data; the first is JSON, a BIN chunk may follow, others are
/// skipped). Written here rather than with `gltf::binary::Glb::from_slice`, which subtracts 12
/// from the header's length without a check (overflow when it is below 12).
fn split_container<'a>(cx: &Cx, bytes: &'a [u8]) -> Result<(&'a [u8], Option<&'a [u8]>), GltfError> {
    const HEADER: usize = 12;
    const CHUNK_HEADER: usize = 8;
    if !bytes.starts_with(b"glTF") {
        let text = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
        return match text.iter().find(|b| !b.is_ascii_whitespace()) {
            Some(b'{') => Ok((text, None)),
            None => Err(cx.format("empty file: neither a GLB nor a JSON glTF".into())),
            Some(_) => Err(cx.format(format!(
                "not a glTF file: it starts with {:?}, not \"glTF\" (binary .glb) or '{{' (JSON .gltf)",
                String::from_utf8_lossy(&bytes[..bytes.len().min(4)])
            ))),
        };
    }
    if bytes.len() < HEADER {
        return Err(cx.format(format!("truncated GLB: {} bytes, the header alone has {HEADER}", bytes.len())));
    }
    let version = u32_at(bytes, 4);
    if version != 2 {
        return Err(cx.format(format!("GLB version {version} (only 2 is read)")));
    }
    let length = u32_at(bytes, 8) as usize;
    if length > bytes.len() {
        return Err(cx.format(format!("truncated GLB: the header says {length} bytes, the file has {}", bytes.len())));
    }
    let mut rest = &bytes[HEADER.min(length)..length];
    /// A chunk's data and its 4-byte type.
    type Chunk<'c> = Option<(&'c [u8], [u8; 4])>;
    let chunk = |rest: &mut &'a [u8]| -> Result<Chunk<'a>, GltfError> {
        if rest.is_empty() {
            return Ok(None);
        }
        if rest.len() < CHUNK_HEADER {
            return Err(cx.format(format!("truncated GLB: {} bytes where a chunk header needs 8", rest.len())));
        }
        let len = u32_at(rest, 0) as usize;
        let kind = [rest[4], rest[5], rest[6], rest[7]];
        if len > rest.len() - CHUNK_HEADER {
            return Err(cx.format(format!(
                "truncated GLB: a {} chunk of {len} bytes, {} bytes left",
                String::from_utf8_lossy(&kind).trim_end_matches('\0'),
                rest.len() - CHUNK_HEADER
            )));
        }
        let data = &rest[CHUNK_HEADER..CHUNK_HEADER + len];
        *rest = &rest[CHUNK_HEADER + len..];
        Ok(Some((data, kind)))
    };
    let json = match chunk(&mut rest)? {
        Some((data, kind)) if &kind == b"JSON" => data,
        Some((_, kind)) => {
            return Err(cx.format(format!("GLB: the first chunk is {:?}, not JSON", String::from_utf8_lossy(&kind))));
        }
        None => return Err(cx.format("GLB without a JSON chunk".into())),
    };
    let mut bin = None;
    while let Some((data, kind)) = chunk(&mut rest)? {
        if &kind == b"BIN\0" && bin.is_none() {
            bin = Some(data);
        }
    }
    Ok((json, bin))
}

/// Every buffer's bytes, each exactly its `byteLength` long (checked against the data first).
fn load_buffers<'a>(
    cx: &Cx,
    root: &json::Root,
    bin: Option<&'a [u8]>,
    base_dir: Option<&Path>,
) -> Result<Vec<Cow<'a, [u8]>>, GltfError> {
    let mut out = Vec::with_capacity(root.buffers.len());
    for (i, b) in root.buffers.iter().enumerate() {
        let declared = b.byte_length.0;
        if declared > MAX_FILE_BYTES {
            return Err(cx.too_large(format!(
                "buffer {i}: byteLength {declared} is more than the limit of {MAX_FILE_BYTES} (MAX_FILE_BYTES)"
            )));
        }
        let data: Cow<[u8]> = match b.uri.as_deref() {
            None => {
                let bin = bin.filter(|_| i == 0).ok_or_else(|| {
                    cx.invalid(format!("buffer {i} has no uri and is not the GLB's BIN chunk (only buffer 0 can be)"))
                })?;
                if declared > bin.len() as u64 {
                    return Err(cx.invalid(format!(
                        "buffer {i}: byteLength {declared} is more than the GLB's BIN chunk ({} bytes)",
                        bin.len()
                    )));
                }
                Cow::Borrowed(&bin[..declared as usize])
            }
            Some(uri) if uri.starts_with("data:") => {
                let (head, payload) = uri.split_once(',').unwrap_or((uri, ""));
                if !head.ends_with(";base64") {
                    return Err(cx.invalid(format!("buffer {i}: only base64 data: URIs are read")));
                }
                let engine = base64::engine::GeneralPurpose::new(
                    &base64::alphabet::STANDARD,
                    base64::engine::GeneralPurposeConfig::new()
                        .with_decode_padding_mode(base64::engine::DecodePaddingMode::Indifferent),
                );
                let mut data =
                    engine.decode(payload).map_err(|e| cx.invalid(format!("buffer {i}: bad base64 data: {e}")))?;
                if declared > data.len() as u64 {
                    return Err(cx.invalid(format!(
                        "buffer {i}: byteLength {declared} but its data: URI holds {} bytes",
                        data.len()
                    )));
                }
                data.truncate(declared as usize);
                Cow::Owned(data)
            }
            Some(uri) => Cow::Owned(read_external(cx, i, uri, declared, base_dir)?),
        };
        out.push(data);
    }
    Ok(out)
}

/// An external buffer file: a relative path (percent-decoded), at least `declared` bytes long;
/// only `declared` bytes are read.
fn read_external(cx: &Cx, i: usize, uri: &str, declared: u64, base_dir: Option<&Path>) -> Result<Vec<u8>, GltfError> {
    if uri.split(['/', '\\']).next().is_some_and(|first| first.contains(':')) {
        return Err(cx.invalid(format!("buffer {i}: '{uri}' is neither a data: URI nor a relative file path")));
    }
    let Some(dir) = base_dir else {
        return Err(cx.invalid(format!("buffer {i}: external file '{uri}' cannot be read from memory")));
    };
    let path = dir.join(percent_decode(uri));
    let file = std::fs::File::open(&path).map_err(|e| cx.invalid(format!("buffer {i}: cannot read '{uri}': {e}")))?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    if len < declared {
        return Err(cx.invalid(format!("buffer {i}: '{uri}' has {len} bytes, byteLength says {declared}")));
    }
    let mut data = Vec::with_capacity(declared as usize);
    file.take(declared)
        .read_to_end(&mut data)
        .map_err(|e| cx.invalid(format!("buffer {i}: cannot read '{uri}': {e}")))?;
    if (data.len() as u64) < declared {
        return Err(cx.invalid(format!("buffer {i}: '{uri}' ended after {} bytes of {declared}", data.len())));
    }
    Ok(data)
}

/// `%20` → space, and so on (URIs in glTF are percent-encoded, RFC 3986); a bad escape stays.
fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        if b[i] == b'%'
            && i + 2 < b.len()
            && let (Some(h), Some(l)) = (hex(b[i + 1]), hex(b[i + 2]))
        {
            out.push((h * 16 + l) as u8);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// One glTF mesh primitive, read once and shared by every node that shows it.
struct Prim {
    /// Index into `Reader::file_meshes`.
    mesh: usize,
    material: Option<usize>,
    /// The analytic shape this primitive is an exact tessellation of (a file shadelab wrote).
    analytic: Option<(Shape, u32)>,
}

struct Reader<'a> {
    cx: Cx,
    root: &'a json::Root,
    buffers: Vec<Cow<'a, [u8]>>,
    /// (mesh, primitive) → what it became (`None`: not triangles, skipped).
    prims: HashMap<(usize, usize), Option<Prim>>,
    /// Meshes read, with the index each got in `Scene::meshes` once an object uses it untransformed.
    file_meshes: Vec<(TriangleMesh, Option<usize>)>,
}

/// A checked view of an accessor's bytes: `count` elements of `elem` bytes, `stride` apart.
struct View<'b> {
    bytes: &'b [u8],
    stride: usize,
    count: usize,
    component: json::accessor::ComponentType,
    ty: json::accessor::Type,
}

fn component_size(c: json::accessor::ComponentType) -> u64 {
    use json::accessor::ComponentType::*;
    match c {
        I8 | U8 => 1,
        I16 | U16 => 2,
        U32 | F32 => 4,
    }
}

fn type_components(t: json::accessor::Type) -> u64 {
    use json::accessor::Type::*;
    match t {
        Scalar => 1,
        Vec2 => 2,
        Vec3 => 3,
        Vec4 | Mat2 => 4,
        Mat3 => 9,
        Mat4 => 16,
    }
}

impl<'a> Reader<'a> {
    fn get<'r, T>(&self, list: &'r [T], index: usize, what: &str, owner: &str) -> Result<&'r T, GltfError> {
        list.get(index).ok_or_else(|| {
            self.cx.invalid(format!("{owner}{what} {index} does not exist (the file has {})", list.len()))
        })
    }

    /// The bytes of accessor `index`, checked: `byteOffset + (count − 1)·stride + element size`
    /// must lie inside its buffer view, and the view inside its buffer, before anything is read.
    fn accessor(&self, index: usize, what: &str) -> Result<View<'_>, GltfError> {
        let acc = self.get(&self.root.accessors, index, "accessor", &format!("{what}: "))?;
        let name = format!("{what}: accessor {index}");
        if acc.sparse.is_some() {
            return Err(self.cx.invalid(format!("{name} is sparse (not supported)")));
        }
        let component = match acc.component_type {
            Checked::Valid(c) => c.0,
            Checked::Invalid => return Err(self.cx.invalid(format!("{name} has an unknown componentType"))),
        };
        let ty = match acc.type_ {
            Checked::Valid(t) => t,
            Checked::Invalid => return Err(self.cx.invalid(format!("{name} has an unknown type"))),
        };
        let elem = component_size(component) * type_components(ty);
        let view_index = acc.buffer_view.ok_or_else(|| self.cx.invalid(format!("{name} has no bufferView")))?.value();
        let view = self.get(&self.root.buffer_views, view_index, "buffer view", &format!("{name}: "))?;
        let buffer_index = view.buffer.value();
        let buffer = self.get(&self.buffers, buffer_index, "buffer", &format!("buffer view {view_index}: "))?;
        let view_offset = view.byte_offset.map_or(0, |o| o.0);
        let view_len = view.byte_length.0;
        let view_end = view_offset.checked_add(view_len).filter(|&e| e <= buffer.len() as u64).ok_or_else(|| {
            self.cx.invalid(format!(
                "buffer view {view_index}: bytes {view_offset}..{} are past the end of buffer {buffer_index} ({} bytes)",
                view_offset as u128 + view_len as u128,
                buffer.len()
            ))
        })?;
        let stride = match view.byte_stride {
            Some(s) if (s.0 as u64) < elem => {
                return Err(self.cx.invalid(format!(
                    "buffer view {view_index}: byteStride {} is less than the {elem}-byte elements of {name}",
                    s.0
                )));
            }
            Some(s) => s.0 as u64,
            None => elem,
        };
        let count = acc.count.0;
        let offset = acc.byte_offset.map_or(0, |o| o.0);
        let needed =
            if count == 0 { Some(0) } else { (count - 1).checked_mul(stride).and_then(|n| n.checked_add(elem)) };
        if needed.and_then(|n| n.checked_add(offset)).is_none_or(|end| end > view_len) {
            return Err(self.cx.invalid(format!(
                "{name}: {count} elements of {elem} bytes from offset {offset} need {} bytes, buffer view {view_index} has {view_len}",
                needed.map_or("more than 2^64".to_string(), |n| n.to_string())
            )));
        }
        let start = (view_offset + offset) as usize;
        Ok(View {
            bytes: &buffer[start..view_end as usize],
            stride: stride as usize,
            count: count as usize,
            component,
            ty,
        })
    }

    fn vec3s(&self, index: usize, what: &str) -> Result<Vec<DVec3>, GltfError> {
        let v = self.accessor(index, what)?;
        if v.ty != json::accessor::Type::Vec3 || v.component != json::accessor::ComponentType::F32 {
            return Err(self.cx.invalid(format!(
                "{what}: accessor {index} is {:?} of {:?}; VEC3 of FLOAT is read",
                v.ty, v.component
            )));
        }
        // More vertices than the corners of MAX_TRIANGLES triangles cannot all be used.
        if v.count / 3 > MAX_TRIANGLES {
            return Err(self.too_many(v.count / 3));
        }
        let f = |at: usize| f32::from_le_bytes([v.bytes[at], v.bytes[at + 1], v.bytes[at + 2], v.bytes[at + 3]]) as f64;
        Ok((0..v.count).map(|k| k * v.stride).map(|at| DVec3::new(f(at), f(at + 4), f(at + 8))).collect())
    }

    /// The primitive's corner list (its indices, or 0..n), each checked against `vertices`.
    fn corners(&self, prim: &json::mesh::Primitive, vertices: usize, what: &str) -> Result<Vec<u32>, GltfError> {
        let Some(index) = prim.indices else {
            return Ok((0..vertices as u32).collect());
        };
        let v = self.accessor(index.value(), what)?;
        use json::accessor::ComponentType::*;
        let size = match (v.ty, v.component) {
            (json::accessor::Type::Scalar, U8) => 1,
            (json::accessor::Type::Scalar, U16) => 2,
            (json::accessor::Type::Scalar, U32) => 4,
            (t, c) => {
                return Err(self.cx.invalid(format!(
                    "{what}: indices accessor {} is {t:?} of {c:?}; SCALAR of UNSIGNED_BYTE/SHORT/INT is read",
                    index.value()
                )));
            }
        };
        if v.count / 3 > MAX_TRIANGLES {
            return Err(self.too_many(v.count / 3));
        }
        let mut out = Vec::with_capacity(v.count);
        for k in 0..v.count {
            let b = &v.bytes[k * v.stride..];
            let i = match size {
                1 => b[0] as u32,
                2 => u16::from_le_bytes([b[0], b[1]]) as u32,
                _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            };
            if i as usize >= vertices {
                return Err(self.cx.invalid(format!("{what}: index {i} is past the vertex count {vertices}")));
            }
            out.push(i);
        }
        Ok(out)
    }

    fn too_many(&self, more: usize) -> GltfError {
        self.cx.too_large(format!(
            "{} triangles are more than the limit of {MAX_TRIANGLES} (MAX_TRIANGLES)",
            self.cx.triangles.saturating_add(more)
        ))
    }

    /// Read primitive `pi` of mesh `mi` (once).
    fn prim(&mut self, mi: usize, pi: usize) -> Result<Option<&Prim>, GltfError> {
        if !self.prims.contains_key(&(mi, pi)) {
            let p = self.read_prim(mi, pi)?;
            self.prims.insert((mi, pi), p);
        }
        Ok(self.prims[&(mi, pi)].as_ref())
    }

    fn read_prim(&mut self, mi: usize, pi: usize) -> Result<Option<Prim>, GltfError> {
        use json::mesh::{Mode, Semantic};
        let root = self.root;
        let mesh = &root.meshes[mi];
        let prim = &mesh.primitives[pi];
        let what = format!("mesh {mi} primitive {pi}");
        let mode = match prim.mode {
            Checked::Valid(m) => m,
            Checked::Invalid => return Err(self.cx.invalid(format!("{what}: unknown mode"))),
        };
        if !matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan) {
            self.cx.warn(format!("{what}: {mode:?} are not triangles, skipped"));
            return Ok(None);
        }
        let pos = prim
            .attributes
            .get(&Checked::Valid(Semantic::Positions))
            .ok_or_else(|| self.cx.invalid(format!("{what}: no POSITION attribute")))?;
        let positions = self.vec3s(pos.value(), &format!("{what}: POSITION"))?;
        if let Some(k) = positions.iter().position(|p| !p.is_finite()) {
            return Err(self.cx.invalid(format!("{what}: POSITION {k} is not finite ({})", positions[k])));
        }
        let normals = match prim.attributes.get(&Checked::Valid(Semantic::Normals)) {
            Some(n) => {
                let n = self.vec3s(n.value(), &format!("{what}: NORMAL"))?;
                if n.len() != positions.len() {
                    return Err(self.cx.invalid(format!(
                        "{what}: {} NORMALs for {} POSITIONs",
                        n.len(),
                        positions.len()
                    )));
                }
                Some(n)
            }
            None => None,
        };
        let corners = self.corners(prim, positions.len(), &what)?;
        let tris: Vec<[u32; 3]> = match mode {
            Mode::Triangles => {
                if corners.len() % 3 != 0 {
                    return Err(self.cx.invalid(format!(
                        "{what}: {} {} is not a multiple of 3",
                        corners.len(),
                        if prim.indices.is_some() { "indices" } else { "vertices" }
                    )));
                }
                corners.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
            }
            // glTF 2.0 §3.7.2.1: strip triangle i is {v_i, v_(i+1+i%2), v_(i+2−i%2)}; fan
            // triangle i is {v_(i+1), v_(i+2), v_0}.
            Mode::TriangleStrip => (0..corners.len().saturating_sub(2))
                .map(|i| [corners[i], corners[i + 1 + i % 2], corners[i + 2 - i % 2]])
                .collect(),
            _ => (0..corners.len().saturating_sub(2)).map(|i| [corners[i + 1], corners[i + 2], corners[0]]).collect(),
        };
        if tris.len() > MAX_TRIANGLES {
            return Err(self.too_many(tris.len()));
        }
        let material = prim.material.map(|m| m.value());
        if let Some(m) = material
            && m >= root.materials.len()
        {
            return Err(self
                .cx
                .invalid(format!("{what}: material {m} does not exist (the file has {})", root.materials.len())));
        }
        let name = mesh.name.clone().unwrap_or_else(|| format!("mesh {mi}"));
        let name = if mesh.primitives.len() > 1 { format!("{name} #{pi}") } else { name };
        let tm = TriangleMesh { name, positions, normals, indices: tris };
        let analytic = self.analytic_shape(&mesh.extras, &tm, &what)?;
        self.file_meshes.push((tm, None));
        Ok(Some(Prim { mesh: self.file_meshes.len() - 1, material, analytic }))
    }

    /// `extras.shadelab.shape`/`tessellation` of a mesh shadelab wrote: the analytic shape it
    /// tessellates, when the triangles still match that tessellation (an edited mesh does not).
    fn analytic_shape(
        &self,
        extras: &json::Extras,
        mesh: &TriangleMesh,
        what: &str,
    ) -> Result<Option<(Shape, u32)>, GltfError> {
        let Some(ex) = shadelab_extras(&self.cx, extras, what)? else { return Ok(None) };
        let (Some(shape), Some(tess)) = (ex.get("shape").and_then(Value::as_str), ex.get("tessellation")) else {
            return Ok(None);
        };
        let Some(shape) = Shape::ALL.into_iter().find(|s| s.name() == shape) else { return Ok(None) };
        let tess = tess.as_u64().and_then(|t| params::TESSELLATION.check(t as f64).ok()).ok_or_else(|| {
            self.cx.invalid(format!("{what}: extras.shadelab.tessellation {tess} is not in [1, 4096]"))
        })? as u32;
        if crate::mesh::triangle_count(shape, tess) != mesh.triangle_count() {
            return Ok(None);
        }
        let exact = crate::mesh::triangles(shape, tess);
        // Positions went through f32: 1e-6 relative is a few f32 ulps.
        let same = exact.iter().zip(mesh.triangles()).all(|(a, b)| {
            a.iter().zip(b).all(|(p, q)| (*p - q).abs().max_element() <= 1e-6 * (1.0 + p.abs().max_element()))
        });
        Ok(same.then_some((shape, tess)))
    }

    fn scene(mut self) -> Result<LoadedScene, GltfError> {
        let root = self.root;
        let scene_index = root.scene.map(|s| s.value()).or((!root.scenes.is_empty()).then_some(0));
        let (roots, scene_json) = match scene_index {
            Some(s) => {
                let sc = self.get(&root.scenes, s, "scene", "")?;
                (sc.nodes.iter().map(|n| n.value()).collect::<Vec<_>>(), Some(sc))
            }
            // No scene: glTF 2.0 §3.5.1 lets a viewer show nothing; we show every root node.
            None => {
                let mut has_parent = vec![false; root.nodes.len()];
                for n in &root.nodes {
                    for c in n.children.iter().flatten() {
                        if let Some(p) = has_parent.get_mut(c.value()) {
                            *p = true;
                        }
                    }
                }
                ((0..root.nodes.len()).filter(|&i| !has_parent[i]).collect(), None)
            }
        };
        let instances = self.walk(&roots)?;

        let mut scene = Scene {
            name: scene_json.and_then(|s| s.name.clone()).unwrap_or_else(|| "glTF scene".into()),
            objects: Vec::new(),
            materials: Vec::new(),
            lights: Vec::new(),
            ambient: DEFAULT_AMBIENT,
            camera: Camera {
                eye: DVec3::Z,
                target: DVec3::ZERO,
                up: DVec3::Y,
                fov_y_deg: FALLBACK_FOV_Y_DEG,
                near: 0.1,
                far: 100.0,
            },
            meshes: Vec::new(),
        };
        let mut textured = 0;
        for (i, m) in root.materials.iter().enumerate() {
            textured += usize::from(m.pbr_metallic_roughness.base_color_texture.is_some());
            scene.materials.push(self.material(i, m)?);
        }
        if textured > 0 {
            self.cx.warn(format!("{textured} material(s) have a base colour texture: only the factor is used"));
        }
        let mut default_material = None;
        let mut settings = SceneSettings::default();
        if let Some(sc) = scene_json {
            self.scene_extras(sc, &mut scene, &mut settings)?;
        }

        let mut camera_nodes = Vec::new();
        let mut light_nodes = Vec::new();
        for &(ni, world) in &instances {
            let node = &root.nodes[ni];
            if let Some(mi) = node.mesh.map(|m| m.value()) {
                let mesh = self.get(&root.meshes, mi, "mesh", &format!("node {ni}: "))?;
                for pi in 0..mesh.primitives.len() {
                    self.object(ni, mi, pi, &world, &mut scene, &mut default_material)?;
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
        let (center, radius) = bounds(&scene);
        for (ni, li, world) in light_nodes {
            let lights = root.extensions.as_ref().and_then(|e| e.khr_lights_punctual.as_ref());
            let all = lights.map_or(&[][..], |l| &l.lights[..]);
            let light = self.get(all, li, "light", &format!("node {ni}: "))?;
            let l = self.light(li, light, &world)?;
            scene.lights.push(l);
        }
        if scene.lights.len() > MAX_LIGHTS {
            self.cx.warn(format!(
                "{} lights: the first {MAX_LIGHTS} are kept (MAX_LIGHTS, the GPU's light slots)",
                scene.lights.len()
            ));
            scene.lights.truncate(MAX_LIGHTS);
        }
        if scene.lights.is_empty() {
            log::info!("{}: no lights; a default directional light is added", self.cx.file);
            self.cx.warn("no lights: a default directional light is added".into());
            scene.lights.push(Light::directional(DVec3::new(-0.55, -1.0, -0.7), [1.0; 3], 1.0));
        }
        let mut cameras = Vec::with_capacity(camera_nodes.len());
        for (ni, ci, world) in camera_nodes {
            let name = root.cameras[ci].name.clone().or_else(|| root.nodes[ni].name.clone());
            cameras.push((name.unwrap_or_else(|| format!("camera {ci}")), self.camera(ci, &world, center, radius)?));
        }
        if cameras.is_empty() {
            self.cx.warn("no camera: one is placed to frame the scene".into());
            cameras.push(("framing the scene".into(), framing_camera(center, radius)));
        }
        scene.camera = cameras[0].1;
        Ok(LoadedScene { scene, settings, warnings: self.cx.warnings, cameras })
    }

    /// Nodes reachable from `roots`, each with its world matrix, in depth-first order. A node
    /// reached twice (a cycle, or two parents: glTF 2.0 §3.5.3 forbids both) is an error, and so is
    /// a hierarchy deeper than `MAX_NODE_DEPTH`.
    fn walk(&self, roots: &[usize]) -> Result<Vec<(usize, DMat4)>, GltfError> {
        let nodes = &self.root.nodes;
        let mut seen = vec![false; nodes.len()];
        let mut out = Vec::new();
        let mut stack: Vec<(usize, DMat4, usize, String)> =
            roots.iter().rev().map(|&n| (n, DMat4::IDENTITY, 0, "scene: ".to_string())).collect();
        while let Some((ni, parent, depth, owner)) = stack.pop() {
            let node = self.get(nodes, ni, "node", &owner)?;
            if seen[ni] {
                return Err(self.cx.invalid(format!("node {ni} is reached twice: a cycle or a node with two parents")));
            }
            seen[ni] = true;
            if depth >= MAX_NODE_DEPTH {
                return Err(self
                    .cx
                    .too_large(format!("node {ni}: the hierarchy is deeper than {MAX_NODE_DEPTH} (MAX_NODE_DEPTH)")));
            }
            let world = parent * self.node_matrix(ni, node)?;
            if !world.is_finite() {
                return Err(self.cx.invalid(format!("node {ni}: its world transform is not finite")));
            }
            out.push((ni, world));
            for c in node.children.iter().flatten().rev() {
                stack.push((c.value(), world, depth + 1, format!("node {ni}: child ")));
            }
        }
        Ok(out)
    }

    fn node_matrix(&self, ni: usize, node: &json::scene::Node) -> Result<DMat4, GltfError> {
        let m = match node.matrix {
            // Column-major, as glam's.
            Some(m) => DMat4::from_cols_array(&m.map(f64::from)),
            None => {
                let t = node.translation.map_or(DVec3::ZERO, |t| DVec3::from_array(t.map(f64::from)));
                let s = node.scale.map_or(DVec3::ONE, |s| DVec3::from_array(s.map(f64::from)));
                let q = node.rotation.map_or(DQuat::IDENTITY, |r| DQuat::from_array(r.0.map(f64::from)));
                if !q.is_finite() || q.length_squared() < 1e-12 {
                    return Err(self.cx.invalid(format!("node {ni}: rotation {q} is not a unit quaternion")));
                }
                DMat4::from_scale_rotation_translation(s, q.normalize(), t)
            }
        };
        if !m.is_finite() {
            return Err(self.cx.invalid(format!("node {ni}: transform is not finite")));
        }
        Ok(m)
    }

    /// Add the object for primitive `pi` of mesh `mi` at node `ni`: an analytic shape or a mesh
    /// under a transform of the model's form (scale, rotation about y, translation), or else the
    /// mesh with the node's whole transform baked into its positions.
    fn object(
        &mut self,
        ni: usize,
        mi: usize,
        pi: usize,
        world: &DMat4,
        scene: &mut Scene,
        default_material: &mut Option<usize>,
    ) -> Result<(), GltfError> {
        let Some(prim) = self.prim(mi, pi)? else { return Ok(()) };
        let (mesh_i, material, analytic) = (prim.mesh, prim.material, prim.analytic);
        let count = self.file_meshes[mesh_i].0.triangle_count();
        if self.cx.triangles.saturating_add(count) > MAX_TRIANGLES {
            return Err(self.too_many(count));
        }
        self.cx.triangles += count;
        if scene.objects.len() >= MAX_OBJECTS {
            return Err(self.cx.too_large(format!("more than {MAX_OBJECTS} objects (MAX_OBJECTS)")));
        }
        let material = match material {
            Some(m) => m,
            None => *default_material.get_or_insert_with(|| {
                // glTF 2.0 §3.9.6: the default material is one with every property at its default.
                scene
                    .materials
                    .push(Material { name: "glTF default".into(), ..pbr_material(&json_default_material()) });
                scene.materials.len() - 1
            }),
        };
        let node = &self.root.nodes[ni];
        let name = node.name.clone().unwrap_or_else(|| self.file_meshes[mesh_i].0.name.clone());
        let name = if self.root.meshes[mi].primitives.len() > 1 { format!("{name} #{pi}") } else { name };
        let exact = self.exact_transform(ni)?;
        let decomposed = decompose(world).map(|t| match exact {
            Some(e)
                if agrees(e.translation, t.translation)
                    && agrees(e.scale, t.scale)
                    && agrees(DVec3::splat(e.rotation_y.sin()), DVec3::splat(t.rotation_y.sin()))
                    && agrees(DVec3::splat(e.rotation_y.cos()), DVec3::splat(t.rotation_y.cos())) =>
            {
                e
            }
            _ => t,
        });
        let (shape, tessellation, transform) = match (decomposed, analytic) {
            (Some(t), Some((shape, tess))) => (shape, tess, t),
            (Some(t), None) => {
                // A slot now; the file mesh moves into it once every object is placed (in
                // `scene`): a large mesh is never held twice.
                let idx = *self.file_meshes[mesh_i].1.get_or_insert_with(|| {
                    scene.meshes.push(TriangleMesh::default());
                    scene.meshes.len() - 1
                });
                (Shape::Mesh(idx), 1, t)
            }
            (None, _) => {
                let baked = bake(&self.file_meshes[mesh_i].0, world);
                if baked.positions.iter().any(|p| !p.is_finite()) {
                    return Err(self.cx.invalid(format!("node {ni}: a transformed position is not finite")));
                }
                scene.meshes.push(baked);
                (Shape::Mesh(scene.meshes.len() - 1), 1, Transform::new(DVec3::ZERO, DVec3::ONE))
            }
        };
        scene.objects.push(Object { name, shape, tessellation, transform, material });
        Ok(())
    }

    /// The exact transform shadelab wrote in a node's `extras.shadelab`, if any.
    fn exact_transform(&self, ni: usize) -> Result<Option<Transform>, GltfError> {
        let what = format!("node {ni}");
        let Some(ex) = shadelab_extras(&self.cx, &self.root.nodes[ni].extras, &what)? else { return Ok(None) };
        let e = Extras { cx: &self.cx, what: &what, ex: &ex };
        let rotation_y = match ex.get("rotation_y") {
            Some(v) => Some(v.as_f64().ok_or_else(|| e.bad("rotation_y", v, "a number"))?),
            None => None,
        };
        Ok(match (e.vec3("translation")?, rotation_y, e.vec3("scale")?) {
            (Some(translation), Some(rotation_y), Some(scale)) => Some(Transform { translation, rotation_y, scale }),
            _ => None,
        })
    }

    fn material(&self, i: usize, m: &json::Material) -> Result<Material, GltfError> {
        let what = format!("material {i}");
        let pbr = &m.pbr_metallic_roughness;
        let finite = pbr.base_color_factor.0.iter().all(|c| c.is_finite())
            && pbr.metallic_factor.0.is_finite()
            && pbr.roughness_factor.0.is_finite();
        if !finite {
            return Err(self.cx.invalid(format!("{what}: a pbrMetallicRoughness factor is not finite")));
        }
        let mut mat = pbr_material(m);
        mat.name = m.name.clone().unwrap_or(what.clone());
        if let Some(ex) = shadelab_extras(&self.cx, &m.extras, &what)? {
            let e = Extras { cx: &self.cx, what: &what, ex: &ex };
            if let Some(c) = e.rgb("C", &params::UNIT)? {
                mat.color = c;
            }
            if let Some(v) = e.num("m", &params::M)? {
                mat.m = v;
            }
            if let Some(h) = ex.get("h") {
                mat.h = match h.as_str() {
                    Some("mirror") => PhongExponent::Mirror,
                    _ => PhongExponent::Finite(e.num("h", &params::H)?.unwrap_or(0.0)),
                };
            }
            if let Some(v) = e.rgb("mu", &params::MU)? {
                mat.mu = v;
            }
            for (key, field) in
                [("r_s", &mut mat.r_s), ("r_d", &mut mat.r_d), ("r_a", &mut mat.r_a), ("t", &mut mat.transmission)]
            {
                if let Some(v) = e.num(key, &params::UNIT)? {
                    *field = v;
                }
            }
            if let Some(v) = e.rgb("a", &ABSORPTION)? {
                mat.absorption = v;
            }
            if let Some(v) = e.num("d", &THICKNESS)? {
                mat.thickness = v;
            }
        }
        Ok(mat)
    }

    fn light(
        &mut self,
        li: usize,
        l: &json::extensions::scene::khr_lights_punctual::Light,
        world: &DMat4,
    ) -> Result<Light, GltfError> {
        use json::extensions::scene::khr_lights_punctual::Type;
        let what = format!("light {li}");
        let intensity = l.intensity as f64;
        if !intensity.is_finite() || intensity < 0.0 || !l.color.iter().all(|c| c.is_finite()) {
            return Err(self
                .cx
                .invalid(format!("{what}: intensity {intensity} or colour {:?} is not finite and ≥ 0", l.color)));
        }
        let position = world.transform_point3(DVec3::ZERO);
        let direction = safe_normalize(world.transform_vector3(DVec3::NEG_Z), DVec3::NEG_Y);
        let color = l.color.map(|c| (c as f64).clamp(0.0, 1.0));
        // glTF: lux (directional) or candela (point, spot); `I_L = E/π` (see the module's docs).
        let mut i_l = intensity / std::f64::consts::PI;
        if i_l > params::INTENSITY.max {
            self.cx.warn(format!("{what}: I_L = intensity/π = {i_l} is clamped to {}", params::INTENSITY.max));
            i_l = params::INTENSITY.max;
        }
        let kind = match l.type_ {
            Checked::Valid(Type::Directional) => LightKind::Directional,
            Checked::Valid(Type::Point) => LightKind::Point,
            Checked::Valid(Type::Spot) => LightKind::Spot,
            Checked::Invalid => return Err(self.cx.invalid(format!("{what}: unknown light type"))),
        };
        let (inner_cone, outer_cone) = match (&l.spot, kind) {
            (Some(s), LightKind::Spot) => (s.inner_cone_angle as f64, s.outer_cone_angle as f64),
            (None, LightKind::Spot) => return Err(self.cx.invalid(format!("{what}: a spot light without `spot`"))),
            _ => (0.0, crate::scene::SPOT_OUTER_CONE_DEFAULT),
        };
        let range = match l.range {
            Some(r) if kind == LightKind::Directional => {
                self.cx.warn(format!("{what}: range {r} ignored: a directional light has no distance"));
                None
            }
            Some(r) => Some(params::RANGE.check(r as f64).map_err(|_| {
                self.cx.invalid(format!("{what}: range {r} is not in [{}, {}]", params::RANGE.min, params::RANGE.max))
            })?),
            None => None,
        };
        let mut light = Light {
            kind,
            position,
            direction,
            color,
            intensity: i_l,
            falloff_form: FalloffForm::Quadratic,
            falloff_alpha: if kind == LightKind::Directional { 0.0 } else { POINT_FALLOFF_ALPHA },
            d0: 1.0,
            inner_cone,
            outer_cone,
            range,
        };
        if let Some(ex) = shadelab_extras(&self.cx, &l.extras, &what)? {
            let e = Extras { cx: &self.cx, what: &what, ex: &ex };
            if let Some(v) = e.num("I_L", &params::INTENSITY)? {
                light.intensity = v;
            }
            if let Some(v) = e.rgb("color", &params::UNIT)? {
                light.color = v;
            }
            if let Some(v) = e.num("alpha", &params::FALLOFF)? {
                light.falloff_alpha = v;
            }
            if let Some(v) = e.num("d0", &params::D0)? {
                light.d0 = v;
            }
            if let Some(f) = e.named::<FalloffForm>("falloff_form")? {
                light.falloff_form = f;
            }
            if let Some(p) = e.vec3("position")?
                && agrees(p, light.position)
            {
                light.position = p;
            }
            if let Some(d) = e.vec3("direction")?
                && agrees(d, light.direction)
            {
                light.direction = d;
            }
            if let Some(v) = e.num("inner_cone", &params::CONE_ANGLE_F32)? {
                light.inner_cone = v;
            }
            if let Some(v) = e.num("outer_cone", &params::CONE_ANGLE_F32)? {
                light.outer_cone = v;
            }
            if let Some(v) = e.num("range", &params::RANGE)? {
                light.range = Some(v);
            }
        }
        // glTF's f32 π/2 is a little above f64's: the cones are held to [0, π/2] after the check.
        let (inner, outer) = (light.inner_cone, light.outer_cone);
        let span = params::CONE_ANGLE_F32;
        if kind == LightKind::Spot && !(span.min <= inner && inner < outer && outer <= span.max) {
            return Err(self.cx.invalid(format!(
                "{what}: spot cone angles inner {}, outer {} must be 0 ≤ inner < outer ≤ π/2 (radians)",
                // As the file wrote them (f32), not widened to f64's digits.
                inner as f32,
                outer as f32
            )));
        }
        light.inner_cone = inner.min(params::CONE_ANGLE.max);
        light.outer_cone = outer.min(params::CONE_ANGLE.max);
        Ok(light)
    }

    fn camera(&mut self, ci: usize, world: &DMat4, center: DVec3, radius: f64) -> Result<Camera, GltfError> {
        let c = &self.root.cameras[ci];
        let what = format!("camera {ci}");
        let eye = world.transform_point3(DVec3::ZERO);
        let forward = world.transform_vector3(DVec3::NEG_Z);
        let up_node = world.transform_vector3(DVec3::Y);
        if forward.length_squared() < 1e-20 || forward.cross(up_node).length_squared() < 1e-20 {
            return Err(self.cx.invalid(format!("{what}: its node's transform is degenerate")));
        }
        let forward = forward.normalize();
        let far_auto = ((eye - center).length() + radius) * 2.0;
        let (fov, near, far) = match (&c.perspective, &c.orthographic) {
            (Some(p), _) => {
                let yfov = p.yfov as f64;
                if !(yfov > 0.0 && yfov < std::f64::consts::PI) {
                    return Err(self.cx.invalid(format!("{what}: yfov {yfov} is not in (0, π)")));
                }
                let near = p.znear as f64;
                if !(near > 0.0 && near.is_finite()) {
                    return Err(self.cx.invalid(format!("{what}: znear {near} is not a positive number")));
                }
                let far = match p.zfar {
                    Some(f) if (f as f64) > near && f.is_finite() => f as f64,
                    Some(f) => return Err(self.cx.invalid(format!("{what}: zfar {f} is not beyond znear {near}"))),
                    // Infinite projection: far enough for the whole scene.
                    None => far_auto.max(near * 10.0),
                };
                (yfov.to_degrees(), near, far)
            }
            _ => {
                self.cx.warn(format!("{what} is orthographic: shown in perspective ({FALLBACK_FOV_Y_DEG}°)"));
                let near = (far_auto * 1e-3).max(1e-3);
                (FALLBACK_FOV_Y_DEG, near, far_auto.max(near * 10.0))
            }
        };
        let depth = (center - eye).dot(forward).max(radius * 0.1).max(1e-3);
        let mut camera =
            Camera { eye, target: eye + forward * depth, up: up_node.normalize(), fov_y_deg: fov, near, far };
        // The exact eye, the orbit pivot and the up vector shadelab wrote, when they still agree
        // with the node.
        if let Some(ex) = shadelab_extras(&self.cx, &c.extras, &what)? {
            let e = Extras { cx: &self.cx, what: &what, ex: &ex };
            if let Some(eye) = e.vec3("eye")?
                && agrees(eye, camera.eye)
            {
                camera.eye = eye;
            }
            for (key, field) in
                [("fov_y_deg", &mut camera.fov_y_deg), ("near", &mut camera.near), ("far", &mut camera.far)]
            {
                if let Some(v) = ex.get(key) {
                    let v = v.as_f64().ok_or_else(|| e.bad(key, v, "a number"))?;
                    if agrees(DVec3::splat(v), DVec3::splat(*field)) {
                        *field = v;
                    }
                }
            }
            let (eye, forward) = (camera.eye, forward);
            if let Some(t) = e.vec3("target")?
                && (t - eye).length_squared() > 0.0
                && (t - eye).normalize().dot(forward) > 1.0 - 1e-9
            {
                camera.target = t;
            }
            if let Some(up) = e.vec3("up")? {
                let with = Camera { up, ..camera };
                if up.cross(forward).length_squared() > 1e-12 && with.view().abs_diff_eq(camera.view(), 1e-6) {
                    camera.up = up;
                }
            }
        }
        Ok(camera)
    }

    fn scene_extras(&self, sc: &json::Scene, scene: &mut Scene, settings: &mut SceneSettings) -> Result<(), GltfError> {
        let Some(ex) = shadelab_extras(&self.cx, &sc.extras, "scene")? else { return Ok(()) };
        let e = Extras { cx: &self.cx, what: "scene", ex: &ex };
        if let Some(a) = e.rgb("ambient", &params::UNIT)? {
            scene.ambient = a;
        }
        settings.shading = e.named::<ShadingMode>("shading")?;
        settings.specular = e.named::<SpecularModel>("specular")?;
        Ok(())
    }
}

/// glTF's default material: every property at its default (glTF 2.0 §3.9.6).
fn json_default_material() -> json::Material {
    json::deserialize::from_str("{}").expect("every material property has a default")
}

/// The model's material from glTF's metallic–roughness fields and extensions (the mapping and
/// its reasons: the module's parent).
fn pbr_material(m: &json::Material) -> Material {
    let pbr = &m.pbr_metallic_roughness;
    let base = [0, 1, 2].map(|c| (pbr.base_color_factor.0[c] as f64).clamp(0.0, 1.0));
    let metallic = (pbr.metallic_factor.0 as f64).clamp(0.0, 1.0);
    let roughness = (pbr.roughness_factor.0 as f64).clamp(0.0, 1.0);
    let ext = m.extensions.as_ref();
    let ior = ext.and_then(|e| e.ior.as_ref()).map_or(DEFAULT_IOR, |i| i.ior.0 as f64);
    // KHR_materials_ior: ior ≥ 1, or 0 (F0 = 1); anything else is read as the default.
    let ior = if ior == 0.0 || (ior >= 1.0 && ior.is_finite()) { ior } else { DEFAULT_IOR };
    let (spec, spec_color) = ext
        .and_then(|e| e.specular.as_ref())
        .map_or((1.0, [1.0; 3]), |s| (s.specular_factor.0 as f64, s.specular_color_factor.0.map(f64::from)));
    let sane = |x: f64| if x.is_finite() { x.max(0.0) } else { 1.0 };
    let f0 = dielectric_f0(ior, sane(spec), spec_color.map(sane));
    let mu = [0, 1, 2].map(|c| (f0[c] * (1.0 - metallic) + base[c] * metallic).clamp(0.0, 1.0));
    let m_rough = m_from_roughness(roughness);
    let transmission =
        ext.and_then(|e| e.transmission.as_ref()).map_or(0.0, |t| (t.transmission_factor.0 as f64).clamp(0.0, 1.0));
    let (absorption, thickness) = ext.and_then(|e| e.volume.as_ref()).map_or(([0.0; 3], 0.0), |v| {
        let dist = v.attenuation_distance.0 as f64;
        let a = v.attenuation_color.0.map(|c| {
            let c = (c as f64).clamp(super::ATTENUATION_COLOR_MIN, 1.0);
            // Beer's law: c^(x/D) = e^(−a·x) with a = −ln(c)/D (spec §7); D = ∞ (the default): none.
            if dist > 0.0 && dist.is_finite() { (-c.ln() / dist).min(ABSORPTION.max) } else { 0.0 }
        });
        let d = v.thickness_factor.0 as f64;
        (a, if d.is_finite() { d.clamp(0.0, THICKNESS.max) } else { 0.0 })
    });
    Material {
        name: String::new(),
        color: base.map(|c| c * (1.0 - metallic)),
        r_s: 1.0,
        r_d: 1.0,
        r_a: 1.0,
        m: m_rough,
        h: h_from_m(m_rough),
        mu,
        transmission,
        absorption,
        thickness,
    }
}

/// The `shadelab` object of an `extras`, if there is one.
fn shadelab_extras(cx: &Cx, extras: &json::Extras, what: &str) -> Result<Option<Map<String, Value>>, GltfError> {
    let Some(raw) = extras else { return Ok(None) };
    let v: Value =
        serde_json::from_str(raw.get()).map_err(|e| cx.invalid(format!("{what}: extras are not JSON: {e}")))?;
    match v.get("shadelab") {
        None => Ok(None),
        Some(Value::Object(o)) => Ok(Some(o.clone())),
        Some(_) => Err(cx.invalid(format!("{what}: extras.shadelab is not an object"))),
    }
}

/// Typed, range-checked fields of an `extras.shadelab` object.
struct Extras<'e> {
    cx: &'e Cx,
    what: &'e str,
    ex: &'e Map<String, Value>,
}

impl Extras<'_> {
    fn bad(&self, key: &str, v: &Value, allowed: &str) -> GltfError {
        self.cx.invalid(format!("{}: extras.shadelab.{key} = {v} is not {allowed}", self.what))
    }
    fn num(&self, key: &str, range: &ParamRange) -> Result<Option<f64>, GltfError> {
        let Some(v) = self.ex.get(key) else { return Ok(None) };
        let allowed = || format!("a number in [{}, {}] ({})", range.min, range.max, range.meaning);
        let x = v.as_f64().ok_or_else(|| self.bad(key, v, &allowed()))?;
        range.check(x).map(Some).map_err(|_| self.bad(key, v, &allowed()))
    }
    fn rgb(&self, key: &str, range: &ParamRange) -> Result<Option<[f64; 3]>, GltfError> {
        let Some(v) = self.ex.get(key) else { return Ok(None) };
        let allowed = || format!("3 numbers in [{}, {}] ({})", range.min, range.max, range.meaning);
        let a = v.as_array().filter(|a| a.len() == 3).ok_or_else(|| self.bad(key, v, &allowed()))?;
        let mut out = [0.0; 3];
        for (o, x) in out.iter_mut().zip(a) {
            *o = x.as_f64().and_then(|x| range.check(x).ok()).ok_or_else(|| self.bad(key, v, &allowed()))?;
        }
        Ok(Some(out))
    }
    fn vec3(&self, key: &str) -> Result<Option<DVec3>, GltfError> {
        let Some(v) = self.ex.get(key) else { return Ok(None) };
        let a = v
            .as_array()
            .filter(|a| a.len() == 3)
            .and_then(|a| a.iter().map(Value::as_f64).collect::<Option<Vec<f64>>>())
            .ok_or_else(|| self.bad(key, v, "3 numbers"))?;
        Ok(Some(DVec3::new(a[0], a[1], a[2])))
    }
    fn named<T: NamedValue + PartialEq>(&self, key: &str) -> Result<Option<T>, GltfError> {
        let Some(v) = self.ex.get(key) else { return Ok(None) };
        let allowed = T::ALL.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ");
        let s = v.as_str().ok_or_else(|| self.bad(key, v, &format!("one of {allowed}")))?;
        T::parse_named(s).map(Some).map_err(|_| self.bad(key, v, &format!("one of {allowed}")))
    }
}

/// Whether a value shadelab wrote exactly in extras still agrees with what the file's f32
/// fields say (1e-5 relative: f32 rounding and a few products, not an edit).
fn agrees(exact: DVec3, from_node: DVec3) -> bool {
    let scale = 1.0 + exact.abs().max_element().max(from_node.abs().max_element());
    (exact - from_node).abs().max_element() <= 1e-5 * scale && exact.is_finite()
}

/// The model's transform (scale, then rotation about y, then translation) equal to `m`, if
/// there is one: positive scales, a rotation about y only, no shear.
fn decompose(m: &DMat4) -> Option<Transform> {
    let (s, r, t) = m.to_scale_rotation_translation();
    if !(s.is_finite() && r.is_finite() && t.is_finite()) || s.min_element() <= 0.0 {
        return None;
    }
    if r.x.abs() > 1e-9 || r.z.abs() > 1e-9 {
        return None;
    }
    let tr = Transform { translation: t, rotation_y: 2.0 * r.y.atan2(r.w), scale: s };
    let tol = 1e-9 * m.to_cols_array().iter().fold(1.0f64, |a, b| a.max(b.abs()));
    tr.matrix().abs_diff_eq(*m, tol).then_some(tr)
}

/// The mesh with `m` applied to its positions (and `m`'s inverse transpose to its normals), the
/// winding reversed when `m` mirrors so that faces keep pointing out.
fn bake(mesh: &TriangleMesh, m: &DMat4) -> TriangleMesh {
    let flip = m.determinant() < 0.0;
    let nm = DMat3::from_mat4(*m).inverse().transpose();
    TriangleMesh {
        name: mesh.name.clone(),
        positions: mesh.positions.iter().map(|&p| m.transform_point3(p)).collect(),
        normals: mesh.normals.as_ref().map(|ns| ns.iter().map(|&n| nm * n).collect()),
        // A mirror reverses the winding.
        indices: mesh.indices.iter().map(|t| if flip { [t[0], t[2], t[1]] } else { *t }).collect(),
    }
}

/// Centre and radius of a sphere around every object (world space).
fn bounds(scene: &Scene) -> (DVec3, f64) {
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for o in &scene.objects {
        let (a, b) = match o.shape {
            Shape::Mesh(i) => scene.meshes[i].bounds().unwrap_or((DVec3::ZERO, DVec3::ZERO)),
            _ => (DVec3::NEG_ONE, DVec3::ONE),
        };
        let m = o.transform.matrix();
        for k in 0..8 {
            let c = DVec3::new(
                if k & 1 == 0 { a.x } else { b.x },
                if k & 2 == 0 { a.y } else { b.y },
                if k & 4 == 0 { a.z } else { b.z },
            );
            let p = m.transform_point3(c);
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    let radius = ((hi - lo).length() * 0.5).max(1e-3);
    ((lo + hi) * 0.5, radius)
}

/// A camera that shows a sphere of `radius` about `center`, from the front and a little above.
fn framing_camera(center: DVec3, radius: f64) -> Camera {
    let fov = FALLBACK_FOV_Y_DEG;
    let dist = radius / (fov.to_radians() * 0.5).sin() * 1.05;
    let eye = center + DVec3::new(0.0, 0.35, 1.0).normalize() * dist;
    Camera {
        eye,
        target: center,
        up: DVec3::Y,
        fov_y_deg: fov,
        near: (dist - radius).max(dist * 1e-3) * 0.5,
        far: (dist + radius) * 2.0,
    }
}
