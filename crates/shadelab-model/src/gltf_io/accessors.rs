//! Accessors: typed element arrays over a buffer view (glTF 2.0 §3.6.2), read with every count,
//! offset and stride checked before an element is read: vertex attributes as floats from FLOAT
//! or from 8- and 16-bit integers (normalized or not, glTF 2.0 §3.11 and `KHR_mesh_quantization`),
//! sparse substitutions applied (§3.6.2.3), and indices as SCALAR of unsigned integers; written as
//! FLOAT and UNSIGNED_INT.

use super::container::{ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, Writer};
use super::scene_file::Reader;
use super::{GltfError, MAX_TRIANGLES};
use glam::DVec3;
use gltf::json;
use gltf::json::accessor::ComponentType;
use gltf::json::validation::Checked;
use serde_json::{Value, json};

/// `accessor.componentType` values (glTF 2.0 §5.1.3).
pub(super) const FLOAT: u32 = 5126;
pub(super) const UNSIGNED_INT: u32 = 5125;

/// A checked view of an accessor's bytes: `count` elements of `elem` bytes, `stride` apart
/// (`bytes` empty for an accessor without a buffer view: all zeros, glTF 2.0 §3.6.2.3).
pub(super) struct View<'b> {
    bytes: &'b [u8],
    stride: usize,
    count: usize,
    component: ComponentType,
    ty: json::accessor::Type,
    normalized: bool,
}

fn component_size(c: ComponentType) -> u64 {
    use ComponentType::*;
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

/// Component `k` of the element at byte `at` as f64: FLOAT as it is, an integer normalized to
/// [0, 1] or [−1, 1] when `normalized` (glTF 2.0 §3.11: `max(c/127, −1)` and so on), else its value.
fn component(bytes: &[u8], at: usize, c: ComponentType, normalized: bool) -> f64 {
    use ComponentType::*;
    let b = &bytes[at..];
    let (v, scale) = match c {
        F32 => return f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
        U32 => (u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64, u32::MAX as f64),
        I8 => (b[0] as i8 as f64, 127.0),
        U8 => (b[0] as f64, 255.0),
        I16 => (i16::from_le_bytes([b[0], b[1]]) as f64, 32767.0),
        U16 => (u16::from_le_bytes([b[0], b[1]]) as f64, 65535.0),
    };
    if normalized { (v / scale).max(-1.0) } else { v }
}

/// An unsigned index of `size` bytes (UNSIGNED_BYTE, _SHORT or _INT) at byte `at`.
fn unsigned_at(bytes: &[u8], at: usize, size: usize) -> u64 {
    let b = &bytes[at..];
    match size {
        1 => b[0] as u64,
        2 => u16::from_le_bytes([b[0], b[1]]) as u64,
        _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64,
    }
}

/// The component types a vertex attribute may have: FLOAT, or 8- and 16-bit integers
/// (`KHR_mesh_quantization` and the core's normalized colours and texture coordinates).
fn attribute_component(c: ComponentType) -> bool {
    !matches!(c, ComponentType::U32)
}

impl Reader<'_> {
    /// The bytes of accessor `index`, checked: `byteOffset + (count − 1)·stride + element size`
    /// must lie inside its buffer view, and the view inside its buffer, before anything is read.
    /// A sparse accessor's substitutions are not applied here ([`Self::floats`] does).
    pub(super) fn accessor(&self, index: usize, what: &str) -> Result<View<'_>, GltfError> {
        let acc = self.get(&self.root.accessors, index, "accessor", &format!("{what}: "))?;
        let name = format!("{what}: accessor {index}");
        let component = match acc.component_type {
            Checked::Valid(c) => c.0,
            Checked::Invalid => return Err(self.cx.invalid(format!("{name} has an unknown componentType"))),
        };
        let ty = match acc.type_ {
            Checked::Valid(t) => t,
            Checked::Invalid => return Err(self.cx.invalid(format!("{name} has an unknown type"))),
        };
        let elem = component_size(component) * type_components(ty);
        let count = acc.count.0;
        let normalized = acc.normalized;
        let Some(view_index) = acc.buffer_view.map(|v| v.value()) else {
            if acc.sparse.is_none() {
                return Err(self.cx.invalid(format!("{name} has no bufferView and is not sparse")));
            }
            // All zeros but for the substitutions: more elements than the corners of
            // MAX_TRIANGLES triangles cannot all be used, and none of that size is made.
            if count / 3 > MAX_TRIANGLES as u64 {
                return Err(self.too_many((count / 3) as usize));
            }
            return Ok(View { bytes: &[], stride: elem as usize, count: count as usize, component, ty, normalized });
        };
        let view = self.buffer_view(view_index, &format!("{name}: "))?;
        let view_len = view.bytes.len() as u64;
        let stride = match view.stride {
            Some(s) if s < elem => {
                return Err(self.cx.invalid(format!(
                    "buffer view {view_index}: byteStride {s} is less than the {elem}-byte elements of {name}"
                )));
            }
            Some(s) => s,
            None => elem,
        };
        let offset = acc.byte_offset.map_or(0, |o| o.0);
        let needed =
            if count == 0 { Some(0) } else { (count - 1).checked_mul(stride).and_then(|n| n.checked_add(elem)) };
        if needed.and_then(|n| n.checked_add(offset)).is_none_or(|end| end > view_len) {
            return Err(self.cx.invalid(format!(
                "{name}: {count} elements of {elem} bytes from offset {offset} need {} bytes, buffer view {view_index} has {view_len}",
                needed.map_or("more than 2^64".to_string(), |n| n.to_string())
            )));
        }
        Ok(View {
            bytes: &view.bytes[offset as usize..],
            stride: stride as usize,
            count: count as usize,
            component,
            ty,
            normalized,
        })
    }

    /// Accessor `index` as `N`-component float elements of one of `types` (a vertex attribute):
    /// FLOAT or an 8- or 16-bit integer type, normalized when the accessor says so, with its
    /// sparse substitutions applied.
    pub(super) fn floats<const N: usize>(
        &self,
        index: usize,
        what: &str,
        types: &[json::accessor::Type],
    ) -> Result<Vec<[f64; N]>, GltfError> {
        let v = self.accessor(index, what)?;
        if v.count / 3 > MAX_TRIANGLES {
            return Err(self.too_many(v.count / 3));
        }
        if !types.contains(&v.ty) || !attribute_component(v.component) {
            let names: Vec<String> = types.iter().map(|t| format!("{t:?}")).collect();
            return Err(self.cx.invalid(format!(
                "{what}: accessor {index} is {:?} of {:?}; {} of FLOAT or of 8/16-bit integers is read",
                v.ty,
                v.component,
                names.join(" or ")
            )));
        }
        let n = (type_components(v.ty) as usize).min(N);
        let size = component_size(v.component) as usize;
        let read = |bytes: &[u8], at: usize| -> [f64; N] {
            let mut e = [0.0; N];
            for (k, x) in e.iter_mut().enumerate().take(n) {
                *x = component(bytes, at + k * size, v.component, v.normalized);
            }
            e
        };
        let mut out: Vec<[f64; N]> = if v.bytes.is_empty() {
            vec![[0.0; N]; v.count]
        } else {
            (0..v.count).map(|k| read(v.bytes, k * v.stride)).collect()
        };
        self.apply_sparse(index, what, &mut out, |bytes, k| read(bytes, k * n * size), (n * size) as u64)?;
        Ok(out)
    }

    /// Overwrite the elements a sparse accessor names (glTF 2.0 §3.6.2.3): `count` indices,
    /// strictly increasing and below the accessor's count, and as many tightly packed values of
    /// `elem` bytes; every range is checked before it is read.
    fn apply_sparse<T>(
        &self,
        index: usize,
        what: &str,
        out: &mut [T],
        read: impl Fn(&[u8], usize) -> T,
        elem: u64,
    ) -> Result<(), GltfError> {
        let Some(sparse) = &self.root.accessors[index].sparse else { return Ok(()) };
        let name = format!("{what}: accessor {index}: sparse");
        let count = sparse.count.0;
        if count > out.len() as u64 {
            return Err(self.cx.invalid(format!("{name} count {count} is more than the accessor's {}", out.len())));
        }
        let size = match sparse.indices.component_type {
            Checked::Valid(json::accessor::IndexComponentType(c)) => component_size(c),
            Checked::Invalid => return Err(self.cx.invalid(format!("{name} indices have an unknown componentType"))),
        };
        let range = |view: usize, offset: u64, bytes: u64, part: &str| -> Result<&[u8], GltfError> {
            let v = self.buffer_view(view, &format!("{name} {part}: "))?;
            let end = offset.checked_add(bytes).filter(|&e| e <= v.bytes.len() as u64).ok_or_else(|| {
                self.cx.invalid(format!(
                    "{name} {part}: {count} elements need {bytes} bytes from offset {offset}, buffer view {view} has {}",
                    v.bytes.len()
                ))
            })?;
            Ok(&v.bytes[offset as usize..end as usize])
        };
        let idx = &sparse.indices;
        let indices = range(idx.buffer_view.value(), idx.byte_offset.0, count * size, "indices")?;
        let vals = &sparse.values;
        let values = range(vals.buffer_view.value(), vals.byte_offset.0, count * elem, "values")?;
        let mut previous: Option<u64> = None;
        for k in 0..count as usize {
            let i = unsigned_at(indices, k * size as usize, size as usize);
            if i >= out.len() as u64 || previous.is_some_and(|p| i <= p) {
                return Err(self.cx.invalid(format!(
                    "{name} index {i} (entry {k}) is not increasing or not below the count {}",
                    out.len()
                )));
            }
            previous = Some(i);
            out[i as usize] = read(values, k);
        }
        Ok(())
    }

    /// Accessor `index` as 3-vectors (positions, normals, morph target offsets).
    pub(super) fn vec3s(&self, index: usize, what: &str) -> Result<Vec<DVec3>, GltfError> {
        let v = self.floats::<3>(index, what, &[json::accessor::Type::Vec3])?;
        Ok(v.into_iter().map(DVec3::from_array).collect())
    }

    /// The primitive's corner list (its indices, or 0..n), each checked against `vertices`.
    pub(super) fn corners(
        &self,
        prim: &json::mesh::Primitive,
        vertices: usize,
        what: &str,
    ) -> Result<Vec<u32>, GltfError> {
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
        let read = |bytes: &[u8], at: usize| unsigned_at(bytes, at, size) as u32;
        let mut out: Vec<u32> = if v.bytes.is_empty() {
            vec![0; v.count]
        } else {
            (0..v.count).map(|k| read(v.bytes, k * v.stride)).collect()
        };
        self.apply_sparse(index.value(), what, &mut out, |b, k| read(b, k * size), size as u64)?;
        if let Some(&i) = out.iter().find(|&&i| i as usize >= vertices) {
            return Err(self.cx.invalid(format!("{what}: index {i} is past the vertex count {vertices}")));
        }
        Ok(out)
    }
}

impl Writer {
    /// Append a buffer view over `bytes` and an accessor on it; returns the accessor's index.
    fn accessor(&mut self, bytes: &[u8], target: u32, mut accessor: Value) -> usize {
        accessor["bufferView"] = json!(self.view(bytes, target));
        self.accessors.push(accessor);
        self.accessors.len() - 1
    }

    /// Positions as VEC3 of FLOAT with their bounds (glTF 2.0 §3.7.2.1 asks `min` and `max`).
    pub(super) fn positions(&mut self, positions: &[[f32; 3]]) -> usize {
        let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        self.accessor(
            bytemuck::cast_slice(positions),
            ARRAY_BUFFER,
            json!({ "componentType": FLOAT, "count": positions.len(), "type": "VEC3", "min": lo, "max": hi }),
        )
    }

    /// Normals as VEC3 of FLOAT.
    pub(super) fn normals(&mut self, normals: &[[f32; 3]]) -> usize {
        self.accessor(
            bytemuck::cast_slice(normals),
            ARRAY_BUFFER,
            json!({ "componentType": FLOAT, "count": normals.len(), "type": "VEC3" }),
        )
    }

    /// Per-vertex attributes (texture coordinates as VEC2, colours as VEC3) of FLOAT.
    pub(super) fn attribute<const N: usize>(&mut self, values: &[[f32; N]]) -> usize {
        let ty = match N {
            2 => "VEC2",
            3 => "VEC3",
            _ => "VEC4",
        };
        self.accessor(
            bytemuck::cast_slice(values.as_flattened()),
            ARRAY_BUFFER,
            json!({ "componentType": FLOAT, "count": values.len(), "type": ty }),
        )
    }

    /// Triangle-list indices as SCALAR of UNSIGNED_INT.
    pub(super) fn indices(&mut self, indices: &[u32]) -> usize {
        self.accessor(
            bytemuck::cast_slice(indices),
            ELEMENT_ARRAY_BUFFER,
            json!({ "componentType": UNSIGNED_INT, "count": indices.len(), "type": "SCALAR" }),
        )
    }
}
