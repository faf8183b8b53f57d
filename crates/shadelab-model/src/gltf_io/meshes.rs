//! Meshes and their primitives: triangle lists, strips and fans read into triangle meshes
//! (points and lines are skipped with a warning), each primitive read once however many nodes
//! show it; written as one indexed triangle list with normals per object. An analytic shape is
//! written tessellated with `extras.shadelab` `shape` and `tessellation`, and read back as that
//! shape while the triangles still match.

use super::container::Writer;
use super::extras::{self, Lenient};
use super::scene_file::Reader;
use super::{GltfError, MAX_TRIANGLES};
use crate::mesh::{MeshData, TriangleMesh};
use crate::params;
use crate::scene::{Object, Scene, Shape};
use gltf::json;
use gltf::json::validation::Checked;
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};
use std::collections::HashMap;

/// `primitive.mode` of triangle lists.
pub(super) const TRIANGLES: u32 = 4;

/// Positions went through f32: 1e-6 relative is a few f32 ulps.
const ANALYTIC_TOLERANCE: f64 = 1e-6;

/// `extras.shadelab` of a mesh that is an analytic shape's tessellation. Both are read leniently:
/// an unknown shape is a plain mesh, and the tessellation is checked only for a known shape.
#[derive(Default, Serialize, Deserialize)]
#[serde(default)]
struct MeshExtras {
    /// `Shape::name`.
    shape: Option<Lenient<String>>,
    tessellation: Option<Lenient<u64>>,
}

/// One glTF mesh primitive, read once and shared by every node that shows it.
pub(super) struct Prim {
    /// Index into `Reader::file_meshes`.
    pub(super) mesh: usize,
    pub(super) material: Option<usize>,
    /// The analytic shape this primitive is an exact tessellation of (a file shadelab wrote).
    pub(super) analytic: Option<(Shape, u32)>,
}

impl Reader<'_> {
    /// The error line for `more` triangles past the running total.
    pub(super) fn too_many(&self, more: usize) -> GltfError {
        self.cx.too_large(format!(
            "{} triangles are more than the limit of {MAX_TRIANGLES} (MAX_TRIANGLES)",
            self.cx.triangles.saturating_add(more)
        ))
    }

    /// Read primitive `pi` of mesh `mi` (once).
    pub(super) fn prim(&mut self, mi: usize, pi: usize) -> Result<Option<&Prim>, GltfError> {
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
        let ex: MeshExtras = extras::read(&self.cx, extras, what)?;
        let (Some(Lenient(Ok(shape))), Some(Lenient(tess))) = (ex.shape, ex.tessellation) else { return Ok(None) };
        let Some(shape) = Shape::ALL.into_iter().find(|s| s.name() == shape) else { return Ok(None) };
        let tess = tess.as_ref().ok().and_then(|&t| params::TESSELLATION.check(t as f64).ok()).ok_or_else(|| {
            let written = tess.as_ref().map_or_else(Value::to_string, u64::to_string);
            self.cx.invalid(format!("{what}: extras.shadelab.tessellation {written} is not in [1, 4096]"))
        })? as u32;
        if crate::mesh::triangle_count(shape, tess) != mesh.triangle_count() {
            return Ok(None);
        }
        let exact = crate::mesh::triangles(shape, tess);
        let same = exact.iter().zip(mesh.triangles()).all(|(a, b)| {
            a.iter()
                .zip(b)
                .all(|(p, q)| (*p - q).abs().max_element() <= ANALYTIC_TOLERANCE * (1.0 + p.abs().max_element()))
        });
        Ok(same.then_some((shape, tess)))
    }
}

/// The glTF mesh of object `o` (its primitive written once per shape and tessellation, in
/// `geometry`), without its material's index set; `None` for an empty mesh (glTF accessors hold
/// at least one element).
pub(super) fn write_mesh(
    w: &mut Writer,
    geometry: &mut HashMap<(Shape, u32), Option<Value>>,
    scene: &Scene,
    o: &Object,
) -> Option<Value> {
    let key = (o.shape, if matches!(o.shape, Shape::Mesh(_)) { 0 } else { o.tessellation });
    let mut prim = geometry.entry(key).or_insert_with(|| primitive(w, &scene.mesh_data(o))).clone()?;
    prim["material"] = json!(o.material);
    let mut mesh = json!({ "name": o.name, "primitives": [prim] });
    if !matches!(o.shape, Shape::Mesh(_)) {
        let ex = MeshExtras {
            shape: Some(Lenient(Ok(o.shape.name().to_string()))),
            tessellation: Some(Lenient(Ok(u64::from(o.tessellation)))),
        };
        mesh["extras"] = extras::shadelab(&ex);
    }
    Some(mesh)
}

/// A primitive (without its material) for a built mesh: the smooth vertices with their
/// normals, and the indices. `None` for an empty mesh.
fn primitive(w: &mut Writer, m: &MeshData) -> Option<Value> {
    if m.indices.is_empty() {
        return None;
    }
    let positions: Vec<[f32; 3]> = m.smooth_vertices.iter().map(|v| v.position).collect();
    let normals: Vec<[f32; 3]> = m.smooth_vertices.iter().map(|v| v.normal).collect();
    let pos = w.positions(&positions);
    let nrm = w.normals(&normals);
    let idx = w.indices(&m.indices);
    Some(json!({ "attributes": { "POSITION": pos, "NORMAL": nrm }, "indices": idx, "mode": TRIANGLES }))
}
