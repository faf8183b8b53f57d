//! The node graph: the hierarchy walked from the scene's roots (cycles, nodes with two parents
//! and depth past `MAX_NODE_DEPTH` refused) with each node's world transform, and the objects
//! placed on it. A world transform of the model's form (scale, rotation about y, translation)
//! becomes the object's transform, any other is baked into the mesh; an object is written as a
//! node with its exact f64 transform in `extras.shadelab`.

use super::extras::{self, Number, Vec3, agrees};
use super::materials::{json_default_material, pbr_material};
use super::scene_file::{Reader, quat, vec3};
use super::{GltfError, MAX_NODE_DEPTH, MAX_OBJECTS, MAX_TRIANGLES};
use crate::mesh::TriangleMesh;
use crate::scene::{Material, Object, Scene, Shape, Transform};
use glam::{DMat3, DMat4, DQuat, DVec3};
use gltf::json;
use serde_json::{Value, json};

/// A rotation's x or z component below this is no rotation about x or z: the world transform
/// is of the model's form (a rotation about y).
const ABOUT_Y_ONLY: f64 = 1e-9;

/// A quaternion whose squared length is below this names no rotation.
const QUAT_LENGTH_SQUARED_MIN: f64 = 1e-12;

super::extras_struct! {
    /// `extras.shadelab` of an object's node: its exact f64 transform (the node's own fields are read
    /// as f32), used when it agrees with them (fields in the order they are checked).
    struct NodeExtras {
        rotation_y: Option<Number>,
        translation: Option<Vec3>,
        scale: Option<Vec3>,
    }
}

impl Reader<'_> {
    /// Nodes reachable from `roots`, each with its world matrix, in depth-first order. A node
    /// reached twice (a cycle, or two parents: glTF 2.0 §3.5.3 forbids both) is an error, and so is
    /// a hierarchy deeper than `MAX_NODE_DEPTH`.
    pub(super) fn walk(&self, roots: &[usize]) -> Result<Vec<(usize, DMat4)>, GltfError> {
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
                if !q.is_finite() || q.length_squared() < QUAT_LENGTH_SQUARED_MIN {
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
    pub(super) async fn object(
        &mut self,
        ni: usize,
        mi: usize,
        pi: usize,
        world: &DMat4,
        scene: &mut Scene,
        default_material: &mut Option<usize>,
    ) -> Result<(), GltfError> {
        let Some(prim) = self.prim(mi, pi).await? else { return Ok(()) };
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

    /// The exact transform shadelab wrote in a node's `extras.shadelab`, if all of it is there.
    fn exact_transform(&self, ni: usize) -> Result<Option<Transform>, GltfError> {
        let ex: NodeExtras = extras::read(&self.cx, &self.root.nodes[ni].extras, &format!("node {ni}"))?;
        Ok(match (ex.translation, ex.rotation_y, ex.scale) {
            (Some(translation), Some(rotation_y), Some(scale)) => {
                Some(Transform { translation: translation.0, rotation_y: rotation_y.0, scale: scale.0 })
            }
            _ => None,
        })
    }
}

/// The node of object `o`, showing mesh `mesh`: its transform as glTF's f32 fields, and exactly in
/// `extras.shadelab`.
pub(super) fn object_node(o: &Object, mesh: usize) -> Value {
    let t = &o.transform;
    let ex = NodeExtras {
        rotation_y: Some(Number(t.rotation_y)),
        translation: Some(Vec3(t.translation)),
        scale: Some(Vec3(t.scale)),
    };
    json!({
        "name": o.name,
        "mesh": mesh,
        "translation": vec3(t.translation),
        "rotation": quat(DQuat::from_rotation_y(t.rotation_y)),
        "scale": vec3(t.scale),
        "extras": extras::shadelab(&ex),
    })
}

/// The model's transform (scale, then rotation about y, then translation) equal to `m`, if
/// there is one: positive scales, a rotation about y only, no shear.
fn decompose(m: &DMat4) -> Option<Transform> {
    let (s, r, t) = m.to_scale_rotation_translation();
    if !(s.is_finite() && r.is_finite() && t.is_finite()) || s.min_element() <= 0.0 {
        return None;
    }
    if r.x.abs() > ABOUT_Y_ONLY || r.z.abs() > ABOUT_Y_ONLY {
        return None;
    }
    let tr = Transform { translation: t, rotation_y: 2.0 * r.y.atan2(r.w), scale: s };
    // The same matrix to 1e-9 of its largest entry: f64 rounding of the products, not a shear.
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
        uvs: mesh.uvs.clone(),
        colors: mesh.colors.clone(),
        // Tangents move with the surface; under a mirror the bitangent cross(N, T) turns, so w too.
        tangents: mesh.tangents.as_ref().map(|ts| {
            ts.iter()
                .map(|t| {
                    let v = m.transform_vector3(glam::DVec3::new(t[0] as f64, t[1] as f64, t[2] as f64)).as_vec3();
                    [v.x, v.y, v.z, if flip { -t[3] } else { t[3] }]
                })
                .collect()
        }),
    }
}

/// Centre and radius of a sphere around every object (world space).
pub(super) fn bounds(scene: &Scene) -> (DVec3, f64) {
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for o in &scene.objects {
        let (a, b) = match o.shape {
            Shape::Mesh(i) => scene.meshes.bounds(i).unwrap_or((DVec3::ZERO, DVec3::ZERO)),
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
    // A scene of one point still has a size to frame.
    let radius = ((hi - lo).length() * 0.5).max(1e-3);
    ((lo + hi) * 0.5, radius)
}
