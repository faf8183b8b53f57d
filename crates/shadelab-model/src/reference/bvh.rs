//! A bounding volume hierarchy over one mesh's triangles, in the mesh's own (object) space, so
//! that a ray meets O(log n) boxes and a few triangles instead of every triangle. Built once per
//! image: each node splits its triangles by the binned surface-area heuristic (the plane of 16
//! per axis whose children's area × triangles is least), at the median deep in the tree; the walk
//! opens the nearer child first.
//! The project's own, in f64 and glam like the rest of the reference, with no new dependency for
//! the wasm build.

use crate::mesh::TriangleMesh;
use glam::DVec3;

/// Triangles a leaf holds at most: below this a split costs more box tests than it saves.
const LEAF_TRIANGLES: usize = 4;

/// Bins along each axis the surface-area split tries: 16 planes find a split within a few per
/// cent of the best over all of them (Wald 2007, "On fast construction of SAH-based BVHs").
const SAH_BINS: usize = 16;

/// Depth from which nodes split at the median: the surface-area splits may be uneven, and the
/// walk's stack holds 64 nodes; 32 + log2(16·10⁶ / 4) = 54 stays inside it.
const SAH_DEPTH_MAX: usize = 32;

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
            bvh.split(&boxes, 0, n, 0);
        }
        bvh
    }

    /// Bytes the hierarchy holds.
    pub fn bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.order.len() * 4
    }

    /// Builds the node of `order[start..end]` at `depth` and its subtree; returns its index.
    fn split(&mut self, boxes: &[(DVec3, DVec3)], start: usize, end: usize, depth: usize) -> usize {
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
        let centre = |k: &u32, axis: usize| {
            let (a, b) = boxes[*k as usize];
            (a[axis] + b[axis]) * 0.5
        };
        let order = &mut self.order[start..end];
        let sah = (depth < SAH_DEPTH_MAX).then(|| sah_split(boxes, order, clo, extent)).flatten();
        // The binned surface-area split: the triangles left of the best plane first (a plane
        // that rounding leaves with one side empty is not taken).
        let by_plane = sah.map(|(axis, plane)| partition(order, |k| centre(k, axis) < plane));
        let mid = match by_plane.filter(|&m| m > 0 && m < end - start) {
            Some(m) => start + m,
            // Deep in the tree, or no plane: the median along the longest axis, which keeps the
            // depth below SAH_DEPTH_MAX + log2(n).
            None => {
                let axis = longest(extent);
                let mid = (end - start) / 2;
                order.select_nth_unstable_by(mid, |a, b| centre(a, axis).total_cmp(&centre(b, axis)));
                start + mid
            }
        };
        self.nodes[index].count = 0;
        self.split(boxes, start, mid, depth + 1);
        let right = self.split(boxes, mid, end, depth + 1);
        self.nodes[index].right = right as u32;
        index
    }

    /// Visits the triangles whose boxes the ray `o + t·dir` meets for `t` in `(0, t_max)`, the
    /// nearer child's first, so that a near hit shortens `t_max` before the far child is opened;
    /// `visit(k, t_max)` tests triangle `k` and returns the new `t_max` (a nearer hit) or `None`
    /// to stop (an occluder found).
    pub fn walk(&self, o: DVec3, dir: DVec3, mut t_max: f64, mut visit: impl FnMut(usize, f64) -> Option<f64>) {
        let inv = dir.recip();
        let Some(t_root) = self.nodes.first().and_then(|n| entry(n.lo, n.hi, o, inv, t_max)) else { return };
        // Each node with the ray parameter where the ray enters its box.
        let mut stack = [(0u32, 0.0f64); 64];
        stack[0] = (0, t_root);
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (i, t_in) = stack[top];
            // A nearer hit since the node was pushed may put its box past the end.
            if t_in > t_max {
                continue;
            }
            let node = self.nodes[i as usize];
            if node.count > 0 {
                for &k in &self.order[node.start as usize..(node.start + node.count) as usize] {
                    match visit(k as usize, t_max) {
                        Some(t) => t_max = t,
                        None => return,
                    }
                }
                continue;
            }
            // The left child is the next node; a median split keeps the depth near log2(n),
            // far inside the stack for any mesh the loader accepts. The farther child goes first
            // onto the stack, so the nearer is opened first.
            let at = |c: u32| {
                let n = &self.nodes[c as usize];
                entry(n.lo, n.hi, o, inv, t_max).map(|t| (c, t))
            };
            let (left, right) = (at(i + 1), at(node.right));
            let (first, second) = match (left, right) {
                (Some(l), Some(r)) if r.1 < l.1 => (Some(l), Some(r)),
                (l, r) => (r, l),
            };
            for c in [first, second].into_iter().flatten() {
                stack[top] = c;
                top += 1;
            }
        }
    }
}

/// The axis along which `extent` is longest.
fn longest(extent: DVec3) -> usize {
    if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    }
}

/// Half the surface area of a box: what the heuristic weighs a child's triangles by.
fn half_area(lo: DVec3, hi: DVec3) -> f64 {
    let d = (hi - lo).max(DVec3::ZERO);
    d.x * d.y + d.y * d.z + d.z * d.x
}

/// The binned surface-area split of `order`'s triangles (centroids within `clo + extent`): the
/// axis and plane whose children's `area × count` is least; `None` where no plane has
/// triangles on both sides.
fn sah_split(boxes: &[(DVec3, DVec3)], order: &[u32], clo: DVec3, extent: DVec3) -> Option<(usize, f64)> {
    let empty = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    let mut best: Option<(f64, usize, f64)> = None;
    for axis in 0..3 {
        if extent[axis] <= 0.0 {
            continue;
        }
        let scale = SAH_BINS as f64 / extent[axis];
        let mut bins = [(empty, 0usize); SAH_BINS];
        for &k in order {
            let (a, b) = boxes[k as usize];
            let c = (a[axis] + b[axis]) * 0.5;
            let bin = (((c - clo[axis]) * scale) as usize).min(SAH_BINS - 1);
            let (bx, n) = &mut bins[bin];
            *bx = (bx.0.min(a), bx.1.max(b));
            *n += 1;
        }
        // Areas and counts left of each plane, then right of it, summed from the ends.
        let mut left = [(0.0, 0usize); SAH_BINS];
        let (mut bx, mut n) = (empty, 0);
        for i in 0..SAH_BINS - 1 {
            (bx, n) = ((bx.0.min(bins[i].0.0), bx.1.max(bins[i].0.1)), n + bins[i].1);
            left[i] = (half_area(bx.0, bx.1), n);
        }
        let (mut bx, mut n) = (empty, 0);
        for i in (1..SAH_BINS).rev() {
            (bx, n) = ((bx.0.min(bins[i].0.0), bx.1.max(bins[i].0.1)), n + bins[i].1);
            let (la, ln) = left[i - 1];
            if ln == 0 || n == 0 {
                continue;
            }
            let cost = la * ln as f64 + half_area(bx.0, bx.1) * n as f64;
            if best.is_none_or(|b| cost < b.0) {
                best = Some((cost, axis, clo[axis] + i as f64 / scale));
            }
        }
    }
    best.map(|(_, axis, plane)| (axis, plane))
}

/// Reorders `order` so that the keys `left` holds come first; returns how many.
fn partition(order: &mut [u32], left: impl Fn(&u32) -> bool) -> usize {
    let mut i = 0;
    for j in 0..order.len() {
        if left(&order[j]) {
            order.swap(i, j);
            i += 1;
        }
    }
    i
}

/// Where the ray enters the box `[lo, hi]` if it meets it for some `t` in `[0, t_max]` (the
/// slab test; a zero direction component gives ±∞ there, and a NaN from 0·∞ is passed over by
/// min/max).
fn entry(lo: DVec3, hi: DVec3, o: DVec3, inv: DVec3, t_max: f64) -> Option<f64> {
    let (a, b) = ((lo - o) * inv, (hi - o) * inv);
    let (near, far) = (a.min(b), a.max(b));
    let t0 = near.x.max(near.y).max(near.z).max(0.0);
    let t1 = far.x.min(far.y).min(far.z).min(t_max);
    (t0 <= t1).then_some(t0)
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

    /// Triangles spaced ever wider apart (each twice as far out as the one before) make the
    /// surface-area splits peel one triangle at a time; from `SAH_DEPTH_MAX` on the median split
    /// takes over, so the tree stays within the walk's 64-node stack and every triangle is found.
    #[test]
    fn uneven_splits_stay_within_the_walks_stack() {
        let soup: Vec<[DVec3; 3]> = (0..300)
            .map(|k| {
                let x = 2f64.powi(k);
                [DVec3::new(x, 0.0, 0.0), DVec3::new(x, 1.0, 0.0), DVec3::new(x, 0.0, 1.0)]
            })
            .collect();
        let mesh = TriangleMesh::from_soup("spread", &soup, None);
        let bvh = Bvh::build(&mesh);
        fn depth(b: &Bvh, i: usize) -> usize {
            let n = b.nodes[i];
            if n.count > 0 { 1 } else { 1 + depth(b, i + 1).max(depth(b, n.right as usize)) }
        }
        // 32 surface-area levels, then log2(300/4) + 1 median ones; unbounded, the chain is 65 deep.
        let d = depth(&bvh, 0);
        assert!(d <= 40, "depth {d}");
        for k in [0, 1, 150, 299] {
            let x = 2f64.powi(k);
            let mut offered = Vec::new();
            bvh.walk(DVec3::new(x * 1.5, 0.2, 0.2), DVec3::NEG_X, f64::INFINITY, |i, t| {
                offered.push(i);
                Some(t)
            });
            assert!(offered.contains(&(k as usize)), "triangle {k} not offered");
        }
    }
}
