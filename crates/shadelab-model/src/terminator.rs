//! The self-shadow boundary made visible (docs/model.md §0, "self-shadow boundary"): the mesh
//! edges where the side facing a light changes, i.e. where `N·L` of the faces at an edge changes
//! sign. On the figure-7.3 pyramid these are the edges the chapter labels ABCDEV; projected from
//! the light onto a receiver they outline the cast shadow.
//!
//! The rule, per light and per edge (edges welded by position, so a flat-shaded mesh with split
//! vertices still finds its neighbours; face normals, in world space):
//! - `L` is `−direction` for a directional light, and the vector from the edge's midpoint to the
//!   light for a point or spot light (the midpoint lies in both faces' planes, so the sign of
//!   `N·L` says on which side of each face's plane the light is). A spot's cone is not consulted:
//!   it dims the light, it does not turn a face towards or away from it.
//! - A face faces the light when `N·L > FACING_COS_MIN·|L|`, else it does not.
//! - An edge is on the boundary when one face at it faces the light and another does not; a
//!   non-manifold edge (three or more faces) when its faces disagree.
//! - An edge with one face (the rim of an open mesh, such as the ground plane) is not: there is
//!   no second face whose facing could differ. Counting a lit face's rim would draw the ground's
//!   outline across every picture, and every seam of a file mesh that does not weld.
//!
//! Faces of zero area have no normal and take no part; their edges are skipped.

use crate::Light;
use crate::guards::NORMALIZE_MIN_LEN2;
use crate::lighting::lights::MAX_LIGHTS;
use crate::mesh::{face_normal, key as weld_key};
use crate::scene::{Object, Scene, Shape};
use glam::DVec3;
use std::collections::HashMap;

/// Smallest cosine between `N` and `L` at which a face counts as facing the light. Not 0: a light
/// in the plane of a flat face made of several triangles (a tessellated pyramid side) sits, after
/// rounding, a hair to one side of some triangles and to the other of the rest; at 0 that would
/// draw edges inside the face. 1e-9 is far above the rounding of f64 positions (about 1e-15
/// relative) and far below any light placed on purpose (1e-9 rad of elevation).
pub const FACING_COS_MIN: f64 = 1e-9;

/// One edge of the boundary, its two ends in world space.
pub type Segment = [DVec3; 2];

/// An object's triangle mesh in world space, its edges welded by position, each with the faces
/// that share it: built once, evaluated for any light ([`EdgeMesh::terminator`]).
#[derive(Clone, Debug, Default)]
pub struct EdgeMesh {
    /// Welded world-space positions.
    positions: Vec<DVec3>,
    /// The unit world-space normal of each face with an area.
    normals: Vec<DVec3>,
    /// Each edge's ends (indices into `positions`, lower first).
    edges: Vec<[u32; 2]>,
    /// The faces of edge `e` are `faces[first_face[e]..first_face[e + 1]]` (indices into
    /// `normals`).
    first_face: Vec<u32>,
    faces: Vec<u32>,
}

impl EdgeMesh {
    /// The edges of a world-space triangle soup, normals by its winding (counter-clockwise seen
    /// from the front). Non-finite corners make their triangle take no part.
    pub fn new(triangles: &[[DVec3; 3]]) -> EdgeMesh {
        Self::build(triangles.iter().map(|t| (*t, face_normal(t))))
    }

    /// The edges of an object of `scene` in world space: its analytic shape's tessellation (the
    /// triangles the rasterizer draws, `mesh::triangles`) or its file mesh, transformed. A mesh
    /// index past `Scene::meshes` gives no edges.
    pub fn of_object(scene: &Scene, object: &Object) -> EdgeMesh {
        let local: Vec<[DVec3; 3]> = match object.shape {
            Shape::Mesh(i) => scene.meshes.get(i).map(|m| m.triangles().collect()).unwrap_or_default(),
            shape => crate::mesh::triangles(shape, object.tessellation),
        };
        let m = object.transform.matrix();
        // A mirroring transform (negative scale) flips the winding; the normal matrix
        // (`Transform::normal_matrix`, what the renderer uses) does not, so neither do we.
        let mirrored = object.transform.scale.x * object.transform.scale.y * object.transform.scale.z < 0.0;
        Self::build(local.iter().map(|t| {
            let w = t.map(|p| m.transform_point3(p));
            (w, face_normal(&w).map(|n| if mirrored { -n } else { n }))
        }))
    }

    fn build(triangles: impl Iterator<Item = ([DVec3; 3], Option<DVec3>)>) -> EdgeMesh {
        let mut mesh = EdgeMesh::default();
        let mut index: HashMap<[u32; 3], u32> = HashMap::new();
        // (lower end, upper end, face) for every edge of every face, grouped below by sorting.
        let mut corners: Vec<(u32, u32, u32)> = Vec::new();
        for (t, normal) in triangles {
            let Some(normal) = normal.filter(|_| t.iter().all(|p| p.is_finite())) else { continue };
            let face = mesh.normals.len() as u32;
            mesh.normals.push(normal);
            let ids = t.map(|p| {
                *index.entry(weld_key(p)).or_insert_with(|| {
                    mesh.positions.push(p);
                    (mesh.positions.len() - 1) as u32
                })
            });
            for k in 0..3 {
                let (a, b) = (ids[k], ids[(k + 1) % 3]);
                if a != b {
                    corners.push((a.min(b), a.max(b), face));
                }
            }
        }
        corners.sort_unstable();
        for (i, &(a, b, face)) in corners.iter().enumerate() {
            if i == 0 || (corners[i - 1].0, corners[i - 1].1) != (a, b) {
                mesh.edges.push([a, b]);
                mesh.first_face.push(mesh.faces.len() as u32);
            }
            mesh.faces.push(face);
        }
        mesh.first_face.push(mesh.faces.len() as u32);
        mesh
    }

    /// How many distinct edges the mesh has.
    pub fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// The edges whose faces' normals differ by more than the angle whose cosine is
    /// `cos_crease` (any two of a non-manifold edge's faces): the creases the mesh builder keeps
    /// sharp (`mesh_lines`). An edge with one face is no crease.
    pub fn creases(&self, cos_crease: f64) -> Vec<Segment> {
        let mut out = Vec::new();
        for (e, &[a, b]) in self.edges.iter().enumerate() {
            let faces = &self.faces[self.first_face[e] as usize..self.first_face[e + 1] as usize];
            let n = |f: &u32| self.normals[*f as usize];
            let sharp =
                faces.iter().enumerate().any(|(i, f)| faces[i + 1..].iter().any(|g| n(f).dot(n(g)) < cos_crease));
            if sharp {
                out.push([self.positions[a as usize], self.positions[b as usize]]);
            }
        }
        out
    }

    /// The edges on the self-shadow boundary of `light` (the rule in the module's comment). A
    /// directional light with a zero direction has no `L`: nothing faces it, nothing is drawn.
    pub fn terminator(&self, light: &Light) -> Vec<Segment> {
        let mut out = Vec::new();
        for (e, &[a, b]) in self.edges.iter().enumerate() {
            let (pa, pb) = (self.positions[a as usize], self.positions[b as usize]);
            let l = if light.kind.is_directional() { -light.direction } else { light.position - (pa + pb) * 0.5 };
            let len2 = l.length_squared();
            if !(len2 > NORMALIZE_MIN_LEN2 && len2.is_finite()) {
                // The light on the edge, or no direction: no face at this edge faces it.
                continue;
            }
            let threshold = FACING_COS_MIN * len2.sqrt();
            let faces = &self.faces[self.first_face[e] as usize..self.first_face[e + 1] as usize];
            let facing = |f: &u32| self.normals[*f as usize].dot(l) > threshold;
            let lit = faces.iter().any(facing);
            let unlit = !faces.iter().all(facing);
            if lit && unlit {
                out.push([pa, pb]);
            }
        }
        out
    }
}

/// Every object's edges of one scene, built once (welding is the costly part) and evaluated for
/// any set of lights.
#[derive(Clone, Debug, Default)]
pub struct SceneEdges {
    pub objects: Vec<EdgeMesh>,
}

impl SceneEdges {
    pub fn new(scene: &Scene) -> SceneEdges {
        SceneEdges { objects: scene.objects.iter().map(|o| EdgeMesh::of_object(scene, o)).collect() }
    }

    /// The boundary of every object for each of `lights` that the renderer draws (the first
    /// `MAX_LIGHTS`), all in one list.
    pub fn terminator(&self, lights: &[Light]) -> Vec<Segment> {
        let lights = &lights[..lights.len().min(MAX_LIGHTS)];
        self.objects.iter().flat_map(|m| lights.iter().flat_map(|l| m.terminator(l))).collect()
    }
}

/// The self-shadow boundary of a whole scene: every object, every light, world space.
pub fn scene_terminator(scene: &Scene) -> Vec<Segment> {
    SceneEdges::new(scene).terminator(&scene.lights)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{TriangleMesh, triangles};
    use crate::scene::{Transform, single_shape_scene};

    fn dir_light(to_light: DVec3) -> Light {
        Light::directional(-to_light, [1.0; 3], 1.0)
    }

    /// A segment as an order-free pair, rounded to 1e-9, for comparing sets of segments.
    fn key(s: &Segment) -> [[i64; 3]; 2] {
        let r = |p: DVec3| (p * 1e9).round().as_i64vec3().to_array();
        let (a, b) = (r(s[0]), r(s[1]));
        if a <= b { [a, b] } else { [b, a] }
    }

    fn sorted(segments: &[Segment]) -> Vec<[[i64; 3]; 2]> {
        let mut k: Vec<_> = segments.iter().map(key).collect();
        k.sort();
        k
    }

    fn total_length(segments: &[Segment]) -> f64 {
        segments.iter().map(|s| (s[1] - s[0]).length()).sum()
    }

    /// Apex V, and base corners in the pyramid's object space (docs: `Shape::Pyramid`).
    const V: DVec3 = DVec3::new(0.0, 1.0, 0.0);
    fn base(x: f64, z: f64) -> DVec3 {
        DVec3::new(x, -1.0, z)
    }

    fn pyramid_index(scene: &Scene) -> usize {
        scene.objects.iter().position(|o| o.shape == Shape::Pyramid).expect("a pyramid")
    }

    #[test]
    fn pyramid_lit_from_above_side_has_its_four_outline_edges() {
        // L towards +x, up and −z: the +x and −z sides face it; −x, +z and the base do not.
        let light = dir_light(DVec3::new(1.0, 1.0, -1.0));
        let expected = sorted(&[
            [V, base(1.0, 1.0)],
            [V, base(-1.0, -1.0)],
            [base(1.0, -1.0), base(1.0, 1.0)],
            [base(-1.0, -1.0), base(1.0, -1.0)],
        ]);
        let got = EdgeMesh::new(&triangles(Shape::Pyramid, 1)).terminator(&light);
        assert_eq!(got.len(), 4);
        assert_eq!(sorted(&got), expected);
        // The same with split vertices (a flat-shaded file mesh: each triangle its own corners).
        let mut scene = single_shape_scene("pyramid", Shape::Pyramid, 1);
        scene.meshes = vec![TriangleMesh::from_soup("pyramid", &triangles(Shape::Pyramid, 1), None)].into();
        let k = pyramid_index(&scene);
        scene.objects[k].shape = Shape::Mesh(0);
        scene.objects[k].transform = Transform::new(DVec3::ZERO, DVec3::ONE);
        let split = EdgeMesh::of_object(&scene, &scene.objects[k]);
        assert_eq!(sorted(&split.terminator(&light)), expected);
        // Tessellated, the flat faces' inner edges stay off it: the same outline, in pieces.
        let fine = EdgeMesh::new(&triangles(Shape::Pyramid, 4)).terminator(&light);
        assert_eq!(fine.len(), 4 * 4);
        assert!((total_length(&fine) - total_length(&got)).abs() < 1e-9);
    }

    #[test]
    fn point_light_and_transform_are_taken_in_world_space() {
        // The pyramid moved, turned and scaled; a point light far along the same direction as
        // above lights the same sides.
        let mut scene = single_shape_scene("pyramid", Shape::Pyramid, 1);
        let t =
            Transform { translation: DVec3::new(2.0, 0.5, -1.0), rotation_y: 0.0, scale: DVec3::new(0.5, 2.0, 0.5) };
        let k = pyramid_index(&scene);
        scene.objects[k].transform = t;
        let light = Light::point(t.translation + DVec3::new(100.0, 100.0, -100.0), [1.0; 3], 1.0, 0.0);
        let got = EdgeMesh::of_object(&scene, &scene.objects[k]).terminator(&light);
        let w = |p: DVec3| t.matrix().transform_point3(p);
        let expected = sorted(&[
            [w(V), w(base(1.0, 1.0))],
            [w(V), w(base(-1.0, -1.0))],
            [w(base(1.0, -1.0)), w(base(1.0, 1.0))],
            [w(base(-1.0, -1.0)), w(base(1.0, -1.0))],
        ]);
        assert_eq!(sorted(&got), expected);
        // A mirroring scale keeps the outward normals: the mirrored sides are lit.
        scene.objects[k].transform = Transform::new(DVec3::ZERO, DVec3::new(-1.0, 1.0, 1.0));
        let mirrored =
            EdgeMesh::of_object(&scene, &scene.objects[k]).terminator(&dir_light(DVec3::new(-1.0, 1.0, -1.0)));
        let m = |p: DVec3| p * DVec3::new(-1.0, 1.0, 1.0);
        let expected = sorted(&[
            [m(V), m(base(1.0, 1.0))],
            [m(V), m(base(-1.0, -1.0))],
            [m(base(1.0, -1.0)), m(base(1.0, 1.0))],
            [m(base(-1.0, -1.0)), m(base(1.0, -1.0))],
        ]);
        assert_eq!(sorted(&mirrored), expected);
    }

    #[test]
    fn figure_7_3_pyramid_shows_its_outline_and_the_ground_none() {
        let scene = crate::assets::figure_7_3_pyramid();
        let edges = SceneEdges::new(&scene);
        let pyramid = pyramid_index(&scene);
        let ground = scene.objects.iter().position(|o| o.shape == Shape::Plane).unwrap();
        let light = &scene.lights[0];
        // The light comes from above, behind on the right: three sides face it and the base
        // does not, so the outline is two side edges to the apex and three base edges, the
        // closed path V A B C D V around the lit part.
        let outline = edges.objects[pyramid].terminator(light);
        assert_eq!(outline.len(), 5);
        let apex = scene.objects[pyramid].transform.matrix().transform_point3(V);
        assert_eq!(outline.iter().filter(|s| s.contains(&apex)).count(), 2);
        let base_y = scene.objects[pyramid].transform.matrix().transform_point3(base(1.0, 1.0)).y;
        assert_eq!(outline.iter().filter(|s| s.iter().all(|p| (p.y - base_y).abs() < 1e-12)).count(), 3);
        // The ground faces the light everywhere, and its rim has one face each: nothing.
        assert!(edges.objects[ground].edge_count() > 0);
        assert!(edges.objects[ground].terminator(light).is_empty());
        assert_eq!(scene_terminator(&scene).len(), 5);
    }

    #[test]
    fn sphere_terminator_is_one_closed_loop_near_the_great_circle_across_l() {
        let segments_around = 32;
        let l = DVec3::new(0.3, 0.8, -0.52).normalize();
        let got = EdgeMesh::new(&triangles(Shape::Sphere, segments_around)).terminator(&dir_light(l));
        assert!(got.len() >= segments_around as usize, "{}", got.len());
        // Every end is shared by exactly two segments, and they chain into one loop.
        let mut next: HashMap<[i64; 3], Vec<[i64; 3]>> = HashMap::new();
        for s in &got {
            let [a, b] = key(s);
            next.entry(a).or_default().push(b);
            next.entry(b).or_default().push(a);
        }
        assert!(next.values().all(|n| n.len() == 2), "not a simple closed curve");
        let start = *next.keys().next().unwrap();
        let (mut prev, mut at, mut steps) = (start, next[&start][0], 1);
        while at != start {
            let n = &next[&at];
            let to = if n[0] == prev { n[1] } else { n[0] };
            (prev, at, steps) = (at, to, steps + 1);
        }
        assert_eq!(steps, got.len(), "more than one loop");
        // Each vertex is within about one ring's angle (π/16 here) of the great circle.
        let ring = std::f64::consts::PI / crate::mesh::sphere_rings(segments_around) as f64;
        for s in &got {
            for p in s {
                let off = p.normalize().dot(l).asin().abs();
                assert!(off <= 1.5 * ring, "{p:?} is {off} rad off the great circle");
            }
        }
    }

    #[test]
    fn a_light_in_a_faces_plane_is_finite_and_draws_nothing_inside_the_face() {
        // The +x side lies in the plane 2x + y = 1; this point light is in it, off the face.
        let in_plane = Light::point(DVec3::new(0.5, 0.0, 7.0), [1.0; 3], 1.0, 0.0);
        assert!((2.0 * in_plane.position.x + in_plane.position.y - 1.0).abs() < 1e-15);
        let coarse = EdgeMesh::new(&triangles(Shape::Pyramid, 1)).terminator(&in_plane);
        let fine = EdgeMesh::new(&triangles(Shape::Pyramid, 5)).terminator(&in_plane);
        for s in coarse.iter().chain(&fine) {
            assert!(s[0].is_finite() && s[1].is_finite());
        }
        assert!(!coarse.is_empty());
        assert!((total_length(&fine) - total_length(&coarse)).abs() < 1e-9);
        // A directional light parallel to the base, a light on an edge, a light at the apex and a
        // zero direction: all finite, none panics.
        let mesh = EdgeMesh::new(&triangles(Shape::Pyramid, 3));
        let lights = [
            dir_light(DVec3::X),
            Light::point(DVec3::new(0.0, -1.0, 1.0), [1.0; 3], 1.0, 0.0),
            Light::point(V, [1.0; 3], 1.0, 0.0),
            Light::directional(DVec3::ZERO, [1.0; 3], 1.0),
        ];
        for light in &lights {
            assert!(mesh.terminator(light).iter().flatten().all(|p| p.is_finite()));
        }
        assert!(mesh.terminator(&lights[3]).is_empty());
    }

    #[test]
    fn an_open_planes_rim_is_no_boundary_and_degenerate_faces_take_no_part() {
        let plane = EdgeMesh::new(&triangles(Shape::Plane, 2));
        assert!(plane.terminator(&dir_light(DVec3::NEG_Y)).is_empty());
        assert!(plane.terminator(&dir_light(DVec3::Y)).is_empty());
        let sliver = [[DVec3::ZERO, DVec3::X, DVec3::X * 2.0], [DVec3::ZERO, DVec3::X, DVec3::NAN]];
        let m = EdgeMesh::new(&sliver);
        assert_eq!(m.edge_count(), 0);
    }
}
