//! Accessors: typed element arrays over a buffer view (glTF 2.0 §3.6.2), read with every count,
//! offset and stride checked before an element is read (VEC3 of FLOAT for positions and
//! normals, SCALAR of unsigned integers for indices), and written as FLOAT and UNSIGNED_INT.

use super::container::{ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, Writer};
use super::scene_file::Reader;
use super::{GltfError, MAX_TRIANGLES};
use glam::DVec3;
use gltf::json;
use gltf::json::validation::Checked;
use serde_json::{Value, json};

/// `accessor.componentType` values (glTF 2.0 §5.1.3).
pub(super) const FLOAT: u32 = 5126;
pub(super) const UNSIGNED_INT: u32 = 5125;

/// A checked view of an accessor's bytes: `count` elements of `elem` bytes, `stride` apart.
pub(super) struct View<'b> {
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

impl Reader<'_> {
    /// The bytes of accessor `index`, checked: `byteOffset + (count − 1)·stride + element size`
    /// must lie inside its buffer view, and the view inside its buffer, before anything is read.
    pub(super) fn accessor(&self, index: usize, what: &str) -> Result<View<'_>, GltfError> {
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
        Ok(View {
            bytes: &view.bytes[offset as usize..],
            stride: stride as usize,
            count: count as usize,
            component,
            ty,
        })
    }

    /// Accessor `index` as VEC3 of FLOAT (positions, normals).
    pub(super) fn vec3s(&self, index: usize, what: &str) -> Result<Vec<DVec3>, GltfError> {
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

    /// Triangle-list indices as SCALAR of UNSIGNED_INT.
    pub(super) fn indices(&mut self, indices: &[u32]) -> usize {
        self.accessor(
            bytemuck::cast_slice(indices),
            ELEMENT_ARRAY_BUFFER,
            json!({ "componentType": UNSIGNED_INT, "count": indices.len(), "type": "SCALAR" }),
        )
    }
}
