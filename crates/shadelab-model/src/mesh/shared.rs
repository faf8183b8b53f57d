//! A scene's meshes, shared between the scene and its copies: cloning a scene (the viewer's scene
//! as drawn, a reference's key) does not copy 10⁷ triangles, and two copies compare equal at once
//! when they share their meshes. Writing through it copies them first if they are shared, and
//! forgets their bounds, which are otherwise computed once for every copy.

use super::TriangleMesh;
use glam::DVec3;
use std::ops::{Deref, DerefMut};
use std::sync::{Arc, OnceLock};

/// Each mesh's bounds (`TriangleMesh::bounds`), in mesh order.
type Bounds = Vec<Option<(DVec3, DVec3)>>;

#[derive(Clone, Default)]
pub struct Meshes {
    meshes: Arc<Vec<TriangleMesh>>,
    bounds: Arc<OnceLock<Bounds>>,
}

impl Deref for Meshes {
    type Target = Vec<TriangleMesh>;
    fn deref(&self) -> &Vec<TriangleMesh> {
        &self.meshes
    }
}

impl DerefMut for Meshes {
    /// Copy-on-write: the meshes are copied first when another scene shares them.
    fn deref_mut(&mut self) -> &mut Vec<TriangleMesh> {
        self.bounds = Default::default();
        Arc::make_mut(&mut self.meshes)
    }
}

impl PartialEq for Meshes {
    /// The same meshes when shared; otherwise compared mesh by mesh.
    fn eq(&self, other: &Meshes) -> bool {
        Arc::ptr_eq(&self.meshes, &other.meshes) || *self.meshes == *other.meshes
    }
}

impl std::fmt::Debug for Meshes {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.meshes.fmt(f)
    }
}

impl From<Vec<TriangleMesh>> for Meshes {
    fn from(meshes: Vec<TriangleMesh>) -> Meshes {
        Meshes { meshes: Arc::new(meshes), bounds: Default::default() }
    }
}

impl FromIterator<TriangleMesh> for Meshes {
    fn from_iter<I: IntoIterator<Item = TriangleMesh>>(iter: I) -> Meshes {
        iter.into_iter().collect::<Vec<_>>().into()
    }
}

impl Meshes {
    /// Whether `self` and `other` are the same shared meshes (not a copy).
    pub fn same(&self, other: &Meshes) -> bool {
        Arc::ptr_eq(&self.meshes, &other.meshes)
    }

    /// Mesh `i`'s bounds, `None` for no such mesh or one without triangles. Every mesh's bounds
    /// are computed on the first call, once for the scene and its copies (a pass over every
    /// index); the effect analysis and the shadow maps ask for them every time they are derived.
    pub fn bounds(&self, i: usize) -> Option<(DVec3, DVec3)> {
        let all = self.bounds.get_or_init(|| self.meshes.iter().map(TriangleMesh::bounds).collect());
        all.get(i).copied().flatten()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn copies_share_until_written() {
        let tri = TriangleMesh::from_soup("t", &[[DVec3::ZERO, DVec3::X, DVec3::Y]], None);
        let a: Meshes = vec![tri.clone()].into();
        let mut b = a.clone();
        assert!(a.same(&b) && a == b);
        b.push(tri);
        assert!(!a.same(&b) && a != b && a.len() == 1 && b.len() == 2, "written: copied first");
        let c: Meshes = a.iter().cloned().collect();
        assert!(!a.same(&c) && a == c, "a copy equals by value");
    }

    #[test]
    fn bounds_are_kept_until_a_mesh_changes() {
        let tri = TriangleMesh::from_soup("t", &[[DVec3::ZERO, DVec3::X, DVec3::Y]], None);
        let mut m: Meshes = vec![tri].into();
        assert_eq!(m.bounds(0), Some((DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0))));
        assert_eq!(m.bounds(1), None);
        let copy = m.clone();
        m[0].positions.iter_mut().for_each(|p| *p *= 2.0);
        assert_eq!(m.bounds(0), Some((DVec3::ZERO, DVec3::new(2.0, 2.0, 0.0))), "written: bounds again");
        assert_eq!(copy.bounds(0), Some((DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0))), "the copy keeps its own");
    }
}
