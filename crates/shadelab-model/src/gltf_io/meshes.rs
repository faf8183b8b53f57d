//! Meshes and their primitives: triangle lists, strips and fans read into triangle meshes
//! (points and lines are skipped with a warning), each primitive read once however many nodes
//! show it; written as one indexed triangle list with normals per object. An analytic shape is
//! written tessellated with `extras.shadelab` `shape` and `tessellation`, and read back as that
//! shape while the triangles still match.

use super::container::Writer;
use super::extras::{self, Lenient};
use super::scene_file::Reader;
use super::slices::slice_end;
use super::{GltfError, MAX_TRIANGLES};
use crate::mesh::{MeshData, TriangleMesh};
use crate::params;
use crate::scene::{Object, Scene, Shape};
use glam::DVec3;
use gltf::json;
use gltf::json::validation::Checked;
use serde_json::{Value, json};
use std::collections::HashMap;

/// `primitive.mode` of triangle lists.
pub(super) const TRIANGLES: u32 = 4;

/// Positions went through f32: 1e-6 relative is a few f32 ulps.
const ANALYTIC_TOLERANCE: f64 = 1e-6;

super::extras_struct! {
    /// `extras.shadelab` of a mesh that is an analytic shape's tessellation. Both are read leniently:
    /// an unknown shape is a plain mesh, and the tessellation is checked only for a known shape.
    struct MeshExtras {
        /// `Shape::name`.
        shape: Option<Lenient<String>>,
        tessellation: Option<Lenient<u64>>,
    }
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
    pub(super) async fn prim(&mut self, mi: usize, pi: usize) -> Result<Option<&Prim>, GltfError> {
        if !self.prims.contains_key(&(mi, pi)) {
            let p = self.read_prim(mi, pi).await?;
            self.prims.insert((mi, pi), p);
        }
        Ok(self.prims[&(mi, pi)].as_ref())
    }

    async fn read_prim(&mut self, mi: usize, pi: usize) -> Result<Option<Prim>, GltfError> {
        use json::accessor::Type;
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
        let mut positions = self.vec3s(pos.value(), &format!("{what}: POSITION"))?;
        slice_end().await;
        let mut normals = match prim.attributes.get(&Checked::Valid(Semantic::Normals)) {
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
        slice_end().await;
        self.morph(mesh, prim, &what, &mut positions, normals.as_mut())?;
        if let Some(k) = positions.iter().position(|p| !p.is_finite()) {
            return Err(self.cx.invalid(format!("{what}: POSITION {k} is not finite ({})", positions[k])));
        }
        let n = positions.len();
        slice_end().await;
        let uvs = match prim.attributes.get(&Checked::Valid(Semantic::TexCoords(0))) {
            Some(a) => Some(self.per_vertex::<2>(a.value(), &format!("{what}: TEXCOORD_0"), &[Type::Vec2], n)?),
            None => None,
        };
        slice_end().await;
        let colors = self.colors(prim, &what, n)?;
        self.warn_unused_attributes(prim, &what);
        slice_end().await;
        let tangents = self.tangents(prim, &what, n)?;
        slice_end().await;
        let corners = self.corners(prim, positions.len(), &what)?;
        slice_end().await;
        let tris = self.triangles(prim, mode, &corners, &what)?;
        drop(corners);
        slice_end().await;
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
        let mut tm =
            TriangleMesh { name, positions, normals, indices: tris, uvs, colors, tangents }.with_attributes_kept();
        slice_end().await;
        let normal_mapped = material.and_then(|m| root.materials.get(m)).is_some_and(|m| m.normal_texture.is_some());
        if normal_mapped && tm.tangents.is_none() {
            // glTF: without TANGENT, MikkTSpace's frame (and none without normals or coordinates).
            match tm.with_generated_tangents() {
                Some(t) => tm = t,
                None => self.cx.warn(format!(
                    "{what}: normalTexture needs NORMAL and TEXCOORD_0 to frame it: the normal texture is not applied"
                )),
            }
        }
        slice_end().await;
        let analytic = self.analytic_shape(&mesh.extras, &tm, &what)?;
        self.file_meshes.push((tm, None));
        Ok(Some(Prim { mesh: self.file_meshes.len() - 1, material, analytic }))
    }

    /// `COLOR_0`, one linear RGB colour per vertex in [0, 1] (not finite: white), if the primitive has it.
    fn colors(
        &mut self,
        prim: &json::mesh::Primitive,
        what: &str,
        n: usize,
    ) -> Result<Option<Vec<[f32; 3]>>, GltfError> {
        use json::accessor::Type;
        use json::mesh::Semantic;
        Ok(match prim.attributes.get(&Checked::Valid(Semantic::Colors(0))) {
            Some(a) => {
                let c = self.per_vertex::<3>(a.value(), &format!("{what}: COLOR_0"), &[Type::Vec3, Type::Vec4], n)?;
                if c.iter().flatten().any(|x| !x.is_finite()) {
                    self.cx.warn(format!("{what}: a COLOR_0 value is not finite: drawn as white"));
                }
                // Colours are linear RGB in [0, 1] (glTF 2.0 §3.7.2.1); alpha is not used (opaque).
                Some(c.into_iter().map(|c| c.map(|x| if x.is_finite() { x.clamp(0.0, 1.0) } else { 1.0 })).collect())
            }
            None => None,
        })
    }

    /// A warning for each attribute of the primitive that is not read.
    fn warn_unused_attributes(&mut self, prim: &json::mesh::Primitive, what: &str) {
        use json::mesh::Semantic;
        let read: [Semantic; 5] =
            [Semantic::Positions, Semantic::Normals, Semantic::TexCoords(0), Semantic::Colors(0), Semantic::Tangents];
        for name in prim.attributes.keys().filter_map(|k| match k {
            Checked::Valid(s) if !read.contains(s) => Some(s.to_string()),
            Checked::Valid(_) => None,
            Checked::Invalid => Some("an unknown attribute".to_string()),
        }) {
            self.cx.warn(format!("{what}: attribute {name} is not used"));
        }
    }

    /// `TANGENT`, one tangent and bitangent sign per vertex, if the primitive has it.
    fn tangents(
        &mut self,
        prim: &json::mesh::Primitive,
        what: &str,
        n: usize,
    ) -> Result<Option<Vec<[f32; 4]>>, GltfError> {
        use json::accessor::Type;
        use json::mesh::Semantic;
        Ok(match prim.attributes.get(&Checked::Valid(Semantic::Tangents)) {
            Some(a) => {
                let t = self.per_vertex::<4>(a.value(), &format!("{what}: TANGENT"), &[Type::Vec4], n)?;
                if t.iter().flatten().any(|x| !x.is_finite()) {
                    self.cx.warn(format!(
                        "{what}: a TANGENT value is not finite: the normal texture is not applied there"
                    ));
                }
                Some(t)
            }
            None => None,
        })
    }

    /// The triangles of a triangle list, strip or fan (`mode`) from its corner list.
    fn triangles(
        &self,
        prim: &json::mesh::Primitive,
        mode: json::mesh::Mode,
        corners: &[u32],
        what: &str,
    ) -> Result<Vec<[u32; 3]>, GltfError> {
        use json::mesh::Mode;
        Ok(match mode {
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
        })
    }

    /// An attribute with one element per vertex, as f32 (the GPU's precision).
    fn per_vertex<const N: usize>(
        &self,
        index: usize,
        what: &str,
        types: &[json::accessor::Type],
        vertices: usize,
    ) -> Result<Vec<[f32; N]>, GltfError> {
        let v = self.floats::<N>(index, what, types)?;
        if v.len() != vertices {
            return Err(self.cx.invalid(format!("{what}: {} values for {vertices} POSITIONs", v.len())));
        }
        Ok(v.into_iter().map(|e| e.map(|x| x as f32)).collect())
    }

    /// Morph targets at the mesh's default weights (glTF 2.0 §3.7.2.2): each target's POSITION and
    /// NORMAL offsets, times its weight, added to the base. A node's own `weights` are not read.
    fn morph(
        &mut self,
        mesh: &json::Mesh,
        prim: &json::mesh::Primitive,
        what: &str,
        positions: &mut [DVec3],
        mut normals: Option<&mut Vec<DVec3>>,
    ) -> Result<(), GltfError> {
        let Some(targets) = prim.targets.as_ref().filter(|t| !t.is_empty()) else { return Ok(()) };
        let weights = mesh.weights.as_deref().unwrap_or(&[]);
        if weights.len() != targets.len() && !weights.is_empty() {
            return Err(self.cx.invalid(format!(
                "{what}: {} morph targets but {} mesh weights",
                targets.len(),
                weights.len()
            )));
        }
        for (k, t) in targets.iter().enumerate() {
            let w = weights.get(k).copied().unwrap_or(0.0) as f64;
            if !w.is_finite() {
                return Err(self.cx.invalid(format!("{what}: morph weight {k} is not finite")));
            }
            if t.tangents.is_some() {
                self.cx.warn(format!("{what}: morph target {k}: TANGENT offsets are not used"));
            }
            if w == 0.0 {
                continue;
            }
            // The work a weighted target costs is counted before its offsets are read.
            self.cx.morph_offsets = self.cx.morph_offsets.saturating_add(positions.len());
            if self.cx.morph_offsets > super::MAX_MORPH_OFFSETS {
                return Err(self.cx.too_large(format!(
                    "{what}: morph target {k}: the file's weighted targets add more than {} offsets (MAX_MORPH_OFFSETS)",
                    super::MAX_MORPH_OFFSETS
                )));
            }
            let add = |acc: Option<json::Index<json::Accessor>>, to: &mut [DVec3], name: &str| {
                let Some(acc) = acc else { return Ok(()) };
                let d = self.vec3s(acc.value(), &format!("{what}: morph target {k} {name}"))?;
                if d.len() != to.len() {
                    return Err(self.cx.invalid(format!(
                        "{what}: morph target {k} {name}: {} offsets for {} vertices",
                        d.len(),
                        to.len()
                    )));
                }
                to.iter_mut().zip(d).for_each(|(p, d)| *p += w * d);
                Ok(())
            };
            add(t.positions, positions, "POSITION")?;
            if let Some(n) = normals.as_deref_mut() {
                add(t.normals, n, "NORMAL")?;
            }
        }
        Ok(())
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
    let file_mesh = match o.shape {
        Shape::Mesh(i) => scene.meshes.get(i).filter(|m| m.uvs.is_some() || m.colors.is_some()),
        _ => None,
    };
    let mut prim = geometry
        .entry(key)
        .or_insert_with(|| match file_mesh {
            Some(m) => attributed_primitive(w, m),
            None => primitive(w, &scene.mesh_data(o)),
        })
        .clone()?;
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

/// A primitive for a file mesh with texture coordinates or colours: its own vertices, indices and
/// attributes as they are (normals when it has usable ones). `None` for an empty mesh.
fn attributed_primitive(w: &mut Writer, m: &TriangleMesh) -> Option<Value> {
    if m.indices.is_empty() {
        return None;
    }
    let positions: Vec<[f32; 3]> = m.positions.iter().map(|p| p.as_vec3().to_array()).collect();
    let mut attributes = json!({ "POSITION": w.positions(&positions) });
    if m.has_usable_normals() {
        let normals: Vec<[f32; 3]> = (0..m.positions.len()).map(|i| m.smooth_vertex(i).normal).collect();
        attributes["NORMAL"] = json!(w.normals(&normals));
    }
    if let Some(uv) = &m.uvs {
        attributes["TEXCOORD_0"] = json!(w.attribute(uv));
    }
    if let Some(c) = &m.colors {
        attributes["COLOR_0"] = json!(w.attribute(c));
    }
    // Tangents belong to the normals: glTF ignores them without.
    if let Some(t) = &m.tangents
        && m.has_usable_normals()
    {
        attributes["TANGENT"] = json!(w.attribute(t));
    }
    let indices: Vec<u32> = m.indices.iter().flatten().copied().collect();
    Some(json!({ "attributes": attributes, "indices": w.indices(&indices), "mode": TRIANGLES }))
}
