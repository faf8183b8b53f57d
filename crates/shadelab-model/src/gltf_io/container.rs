//! The container and its bytes: the GLB binary container (glTF 2.0 §4.4), buffers (the GLB's
//! BIN chunk, base64 `data:` URIs, external files) and buffer views, read and written. Every
//! declared length is checked against the data that backs it before anything of that size is
//! allocated.

use super::scene_file::{Cx, Reader};
use super::{GltfError, MAX_FILE_BYTES};
use base64::Engine;
use gltf::json;
use serde_json::{Value, json};
use std::borrow::Cow;
use std::io::Read;
use std::path::Path;

/// `bufferView.target` values (glTF 2.0 §5.11).
pub(super) const ARRAY_BUFFER: u32 = 34962;
pub(super) const ELEMENT_ARRAY_BUFFER: u32 = 34963;

/// GLB header: magic, version, total length (glTF 2.0 §4.4.2).
const HEADER: usize = 12;
/// GLB chunk header: length, type (glTF 2.0 §4.4.3).
const CHUNK_HEADER: usize = 8;

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
}

/// The JSON text and the GLB's BIN chunk (glTF 2.0 §4.4: a 12-byte header, then chunks of an
/// 8-byte header and 4-byte-aligned data; the first is JSON, a BIN chunk may follow, others are
/// skipped). Written here rather than with `gltf::binary::Glb::from_slice`, which subtracts 12
/// from the header's length without a check (overflow when it is below 12).
pub(super) fn split_container<'a>(cx: &Cx, bytes: &'a [u8]) -> Result<(&'a [u8], Option<&'a [u8]>), GltfError> {
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

/// A glTF document and its one binary buffer as `.glb` (glTF 2.0 §4.4: header, JSON chunk padded
/// with spaces, BIN chunk padded with zeros); sets `buffers` to that one buffer.
pub(crate) fn glb_container(mut root: Value, mut bin: Vec<u8>) -> Vec<u8> {
    root["buffers"] = json!([{ "byteLength": bin.len() }]);
    let mut json = serde_json::to_vec(&root).expect("a JSON value serializes");
    json.resize(json.len().next_multiple_of(4), b' ');
    bin.resize(bin.len().next_multiple_of(4), 0);
    let total = HEADER + CHUNK_HEADER + json.len() + CHUNK_HEADER + bin.len();
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

/// `buffers` of a `.gltf` file: the one buffer embedded as a base64 data: URI.
pub(super) fn embedded_buffer(bin: &[u8]) -> Value {
    json!([{
        "byteLength": bin.len(),
        "uri": format!("data:application/octet-stream;base64,{}", base64::engine::general_purpose::STANDARD.encode(bin)),
    }])
}

/// Every buffer's bytes, each exactly its `byteLength` long (checked against the data first). A
/// buffer no accessor or image reaches is not read: it is empty, with a warning.
pub(super) fn load_buffers<'a>(
    cx: &mut Cx,
    root: &json::Root,
    bin: Option<&'a [u8]>,
    externals: Externals,
) -> Result<Vec<Cow<'a, [u8]>>, GltfError> {
    let mut out = Vec::with_capacity(root.buffers.len());
    let used = used_buffers(root);
    for (i, b) in root.buffers.iter().enumerate() {
        if !used[i] {
            cx.warn(format!("buffer {i}: no accessor or image uses it: skipped, not read"));
            out.push(Cow::Borrowed(&[][..]));
            continue;
        }
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
                let mut data = data_uri(cx, &format!("buffer {i}"), uri)?;
                if declared > data.len() as u64 {
                    return Err(cx.invalid(format!(
                        "buffer {i}: byteLength {declared} but its data: URI holds {} bytes",
                        data.len()
                    )));
                }
                data.truncate(declared as usize);
                Cow::Owned(data)
            }
            Some(uri) => Cow::Owned(read_external(cx, &format!("buffer {i}"), uri, declared, externals)?),
        };
        out.push(data);
    }
    Ok(out)
}

/// Which buffers some accessor (its view or its sparse parts) or image reaches through a view.
fn used_buffers(root: &json::Root) -> Vec<bool> {
    let mut views = vec![false; root.buffer_views.len()];
    let mut mark = |v: usize| {
        if let Some(x) = views.get_mut(v) {
            *x = true;
        }
    };
    for a in &root.accessors {
        if let Some(v) = &a.buffer_view {
            mark(v.value());
        }
        if let Some(s) = &a.sparse {
            mark(s.indices.buffer_view.value());
            mark(s.values.buffer_view.value());
        }
    }
    for image in &root.images {
        if let Some(v) = &image.buffer_view {
            mark(v.value());
        }
    }
    let mut used = vec![false; root.buffers.len()];
    for (view, _) in root.buffer_views.iter().zip(&views).filter(|(_, u)| **u) {
        if let Some(u) = used.get_mut(view.buffer.value()) {
            *u = true;
        }
    }
    used
}

/// The bytes of a base64 `data:` URI (buffers and images).
pub(super) fn data_uri(cx: &Cx, what: &str, uri: &str) -> Result<Vec<u8>, GltfError> {
    let (head, payload) = uri.split_once(',').unwrap_or((uri, ""));
    if !head.ends_with(";base64") {
        return Err(cx.invalid(format!("{what}: only base64 data: URIs are read")));
    }
    let engine = base64::engine::GeneralPurpose::new(
        &base64::alphabet::STANDARD,
        base64::engine::GeneralPurposeConfig::new()
            .with_decode_padding_mode(base64::engine::DecodePaddingMode::Indifferent),
    );
    engine.decode(payload).map_err(|e| cx.invalid(format!("{what}: bad base64 data: {e}")))
}

/// Where a scene's external buffers and images are read from.
#[derive(Clone, Copy, Debug)]
pub enum Externals<'a> {
    /// Nowhere: a scene read from memory alone refuses them.
    None,
    /// The folder the scene file is in; a URI may not lead out of it (`confine.rs`).
    Dir(&'a Path),
    /// The folder the scene file is in, and any path a URI names (`--allow-outside-paths`).
    Anywhere(&'a Path),
    /// Files handed in with the scene, by name (the browser's picked or dropped files, which
    /// carry no folder): a URI is matched by its last path segment.
    Files(&'a [(String, Vec<u8>)]),
}

/// A whole external file named by a relative URI (an image), refused when it is longer than
/// `limit` bytes.
pub(super) fn read_external_whole(
    cx: &Cx,
    what: &str,
    uri: &str,
    limit: u64,
    externals: Externals,
) -> Result<Vec<u8>, GltfError> {
    let len = match externals {
        Externals::Dir(d) | Externals::Anywhere(d) => {
            let path = super::confine::local_path(cx, what, uri, d, matches!(externals, Externals::Dir(_)))?;
            std::fs::metadata(path).map_or(0, |m| m.len())
        }
        Externals::Files(files) => given_file(files, uri).map_or(0, |b| b.len() as u64),
        Externals::None => 0,
    };
    if len > limit {
        return Err(cx.too_large(format!("{what}: '{uri}' has {len} bytes, more than the limit of {limit}")));
    }
    read_external(cx, what, uri, len, externals)
}

/// The file handed in under a URI's last path segment (percent-decoded).
fn given_file<'f>(files: &'f [(String, Vec<u8>)], uri: &str) -> Option<&'f [u8]> {
    let decoded = percent_decode(uri);
    let name = decoded.rsplit(['/', '\\']).next().unwrap_or(&decoded);
    files.iter().find(|(n, _)| n == name).map(|(_, b)| b.as_slice())
}

/// An external buffer file: a relative path (percent-decoded), at least `declared` bytes long;
/// only `declared` bytes are read.
fn read_external(cx: &Cx, what: &str, uri: &str, declared: u64, externals: Externals) -> Result<Vec<u8>, GltfError> {
    super::confine::relative_uri(cx, what, uri)?;
    let path = match externals {
        Externals::Dir(dir) => super::confine::local_path(cx, what, uri, dir, true)?,
        Externals::Anywhere(dir) => super::confine::local_path(cx, what, uri, dir, false)?,
        Externals::Files(files) => {
            let data = given_file(files, uri).ok_or_else(|| {
                cx.invalid(format!("{what}: external file '{uri}' was not given with the scene (pick or drop it too)"))
            })?;
            if (data.len() as u64) < declared {
                return Err(cx.invalid(format!("{what}: '{uri}' has {} bytes, byteLength says {declared}", data.len())));
            }
            return Ok(data[..declared as usize].to_vec());
        }
        Externals::None => {
            return Err(cx.invalid(format!("{what}: external file '{uri}' cannot be read from memory")));
        }
    };
    let file = std::fs::File::open(&path).map_err(|e| cx.invalid(format!("{what}: cannot read '{uri}': {e}")))?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    if len < declared {
        return Err(cx.invalid(format!("{what}: '{uri}' has {len} bytes, byteLength says {declared}")));
    }
    let mut data = Vec::with_capacity(declared as usize);
    file.take(declared).read_to_end(&mut data).map_err(|e| cx.invalid(format!("{what}: cannot read '{uri}': {e}")))?;
    if (data.len() as u64) < declared {
        return Err(cx.invalid(format!("{what}: '{uri}' ended after {} bytes of {declared}", data.len())));
    }
    Ok(data)
}

/// `%20` → space, and so on (URIs in glTF are percent-encoded, RFC 3986); a bad escape stays.
pub fn percent_decode(s: &str) -> String {
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

/// A buffer view's bytes, checked to lie inside its buffer, and its declared stride.
pub(super) struct BufferView<'b> {
    pub(super) bytes: &'b [u8],
    pub(super) stride: Option<u64>,
}

impl Reader<'_> {
    /// Buffer view `index` (named by `owner`, which starts the error line of a missing view).
    pub(super) fn buffer_view(&self, index: usize, owner: &str) -> Result<BufferView<'_>, GltfError> {
        let view = self.get(&self.root.buffer_views, index, "buffer view", owner)?;
        let buffer_index = view.buffer.value();
        let buffer = self.get(&self.buffers, buffer_index, "buffer", &format!("buffer view {index}: "))?;
        let offset = view.byte_offset.map_or(0, |o| o.0);
        let len = view.byte_length.0;
        let end = offset.checked_add(len).filter(|&e| e <= buffer.len() as u64).ok_or_else(|| {
            self.cx.invalid(format!(
                "buffer view {index}: bytes {offset}..{} are past the end of buffer {buffer_index} ({} bytes)",
                offset as u128 + len as u128,
                buffer.len()
            ))
        })?;
        Ok(BufferView { bytes: &buffer[offset as usize..end as usize], stride: view.byte_stride.map(|s| s.0 as u64) })
    }
}

/// The one binary buffer of a file being written, with its buffer views and accessors.
#[derive(Default)]
pub(super) struct Writer {
    pub(super) bin: Vec<u8>,
    pub(super) views: Vec<Value>,
    pub(super) accessors: Vec<Value>,
}

impl Writer {
    /// Append `bytes` as a buffer view for `target`; returns the view's index.
    pub(super) fn view(&mut self, bytes: &[u8], target: u32) -> usize {
        // Every element here is 4-byte aligned (f32 and u32), as glTF 2.0 §3.6.2.4 asks.
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.views.push(json!({ "buffer": 0, "byteOffset": offset, "byteLength": bytes.len(), "target": target }));
        self.views.len() - 1
    }

    /// Append an image's bytes as a buffer view (no target), padded so that what follows stays
    /// 4-byte aligned; returns the view's index.
    pub(super) fn image_view(&mut self, bytes: &[u8]) -> usize {
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.bin.resize(self.bin.len().next_multiple_of(4), 0);
        self.views.push(json!({ "buffer": 0, "byteOffset": offset, "byteLength": bytes.len() }));
        self.views.len() - 1
    }
}
