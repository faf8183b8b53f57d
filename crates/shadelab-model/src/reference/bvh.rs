//! A bounding volume hierarchy over one mesh's triangles, in the mesh's own (object) space, so
//! that a ray meets O(log n) boxes and a few triangles instead of every triangle. Built once per
//! image: each node splits its triangles at the median centroid along its box's longest axis.
//! The project's own, in f64 and glam like the rest of the reference, with no new dependency for
//! the wasm build.

use crate::mesh::TriangleMesh;
use glam::DVec3;

/// Triangles a leaf holds at most: below this a split costs more box tests than it saves.
const LEAF_TRIANGLES: usize = 4;

/// One node: its box, and either its triangles (`order[start..start + count]`, a leaf) or its
/// children (the next node and `right`, `count` = 0).
#[derive(Clone, Copy, Debug)]
struct Node {
    lo: DVec3,
    hi: DVec3,
    start: u32,
    count: u32,
    right: u32,
}

/// The hierarchy of one mesh.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// Triangle indices, leaves' runs in node order.
    order: Vec<u32>,
}

impl Bvh {
    /// The hierarchy of `mesh`'s triangles.
    pub fn build(mesh: &TriangleMesh) -> Bvh {
        let n = mesh.triangle_count();
        let boxes: Vec<(DVec3, DVec3)> = (0..n)
            .map(|k| {
                let t = mesh.triangle(k);
                (t[0].min(t[1]).min(t[2]), t[0].max(t[1]).max(t[2]))
            })
            .collect();
        let mut bvh = Bvh { nodes: Vec::with_capacity(2 * n / LEAF_TRIANGLES + 1), order: (0..n as u32).collect() };
        if n > 0 {
            bvh.split(&boxes, 0, n);
        }
        bvh
    }

    /// Bytes the hierarchy holds.
    pub fn bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.order.len() * 4
    }

    /// Builds the node of `order[start..end]` and its subtree; returns its index.
    fn split(&mut self, boxes: &[(DVec3, DVec3)], start: usize, end: usize) -> usize {
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        let (mut clo, mut chi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &k in &self.order[start..end] {
            let (a, b) = boxes[k as usize];
            (lo, hi) = (lo.min(a), hi.max(b));
            let c = (a + b) * 0.5;
            (clo, chi) = (clo.min(c), chi.max(c));
        }
        let index = self.nodes.len();
        self.nodes.push(Node { lo, hi, start: start as u32, count: (end - start) as u32, right: 0 });
        let extent = chi - clo;
        // A leaf: few triangles, or centroids that coincide (no split separates them).
        if end - start <= LEAF_TRIANGLES || extent.max_element() <= 0.0 {
            return index;
        }
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let mid = (start + end) / 2;
        let key = |k: &u32| {
            let (a, b) = boxes[*k as usize];
            (a[axis] + b[axis]) * 0.5
        };
        self.order[start..end].select_nth_unstable_by(mid - start, |a, b| key(a).total_cmp(&key(b)));
        self.nodes[index].count = 0;
        self.split(boxes, start, mid);
        let right = self.split(boxes, mid, end);
        self.nodes[index].right = right as u32;
        index
    }

    /// Visits the triangles whose boxes the ray `o + t·dir` meets for `t` in `(0, t_max)`, nearer
    /// boxes not first; `visit(k, t_max)` tests triangle `k` and returns the new `t_max` (a
    /// nearer hit) or `None` to stop (an occluder found).
    pub fn walk(&self, o: DVec3, dir: DVec3, mut t_max: f64, mut visit: impl FnMut(usize, f64) -> Option<f64>) {
        if self.nodes.is_empty() {
            return;
        }
        let inv = dir.recip();
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let i = stack[top] as usize;
            let node = self.nodes[i];
            if !meets(node.lo, node.hi, o, inv, t_max) {
                continue;
            }
            if node.count > 0 {
                for &k in &self.order[node.start as usize..(node.start + node.count) as usize] {
                    match visit(k as usize, t_max) {
                        Some(t) => t_max = t,
                        None => return,
                    }
                }
            } else {
                // The left child is the next node; a median split keeps the depth near log2(n),
                // far inside the stack for any mesh the loader accepts.
                stack[top] = node.right;
                stack[top + 1] = i as u32 + 1;
                top += 2;
            }
        }
    }
}

/// Whether the ray meets the box `[lo, hi]` for some `t` in `[0, t_max]` (the slab test; a
/// zero direction component gives ±∞ there, and a NaN from 0·∞ is passed over by min/max).
fn meets(lo: DVec3, hi: DVec3, o: DVec3, inv: DVec3, t_max: f64) -> bool {
    let (a, b) = ((lo - o) * inv, (hi - o) * inv);
    let (near, far) = (a.min(b), a.max(b));
    let t0 = near.x.max(near.y).max(near.z).max(0.0);
    let t1 = far.x.min(far.y).min(far.z).min(t_max);
    t0 <= t1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::triangles;
    use crate::scene::Shape;

    /// Through the hierarchy a ray finds every triangle a walk over all of them finds: for rays
    /// from all around a fine sphere's mesh, the set of triangles the walk offers contains each
    /// triangle the ray meets, and nothing is offered twice.
    #[test]
    fn the_walk_offers_every_triangle_a_ray_meets() {
        let mesh = TriangleMesh::from_soup("sphere", &triangles(Shape::Sphere, 48), None);
        let bvh = Bvh::build(&mesh);
        assert!(bvh.bytes() > 0 && bvh.order.len() == mesh.triangle_count());
        for k in 0..500 {
            let (u, w) = ((k as f64 * 0.618034).fract(), (k as f64 * 0.414214).fract());
            let (theta, phi) = ((1.0 - 2.0 * u).acos(), std::f64::consts::TAU * w);
            let o = DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin()) * 3.0;
            let dir = DVec3::new((k % 7) as f64 / 7.0 - 0.5, (k % 5) as f64 / 5.0 - 0.5, 0.1) * 0.8 - o;
            let mut offered = Vec::new();
            bvh.walk(o, dir, f64::INFINITY, |k, t| {
                offered.push(k);
                Some(t)
            });
            let mut unique = offered.clone();
            unique.sort_unstable();
            unique.dedup();
            assert_eq!(unique.len(), offered.len(), "ray {k}: a triangle offered twice");
            for (i, t) in mesh.triangles().enumerate() {
                let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
                let p = dir.cross(e2);
                let det = e1.dot(p);
                let s = o - t[0];
                let (a, b) = (s.dot(p) / det, dir.dot(s.cross(e1)) / det);
                let hit = det.abs() > 1e-300 && a >= 0.0 && b >= 0.0 && a + b <= 1.0 && e2.dot(s.cross(e1)) / det > 0.0;
                assert!(!hit || offered.contains(&i), "ray {k} meets triangle {i}, not offered");
            }
        }
        // An empty mesh has nothing to walk.
        Bvh::build(&TriangleMesh::from_soup("empty", &[], None))
            .walk(DVec3::ZERO, DVec3::X, 1.0, |_, _| panic!("offered a triangle of an empty mesh"));
    }
}
