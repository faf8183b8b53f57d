//! The environment's occlusion, precomputed (docs/environment.md, "Occlusion"): a grid of nodes
//! over the scene's box, each holding the share of the environment's cosine-weighted light that
//! reaches it along each of the six axes (an ambient cube), and whether it lies inside a solid.
//! A point looks it up a little off its surface, trilinearly over the nodes that are not inside.
//! Twin of `shaders/occlusion.wgsl`; the grid is baked by `reference::bake_occlusion`, which
//! traces the same rays as the reference's ambient occlusion.

use glam::DVec3;

/// Cells along the longest side of the scene's box: at the default scene's 11 m that is 0.34 m,
/// under the occlusion radius (a tenth of the scene's scale), so a contact is seen by a node.
pub const OCC_GRID_CELLS: u32 = 32;
/// Nodes at most: the GPU buffer holds 8 bytes a node, 64 KiB. A box whose nodes would be more
/// gets larger cells.
pub const OCC_NODES_MAX: usize = 8192;
/// Cosine-distributed rays a node traces about each axis: a face's own noise is at most
/// `√(1/4/48) = 7 %`, and the lookup averages up to eight nodes.
pub const OCC_RAYS: u32 = 48;
/// A node whose rays that meet a surface meet its back more often than this share lies inside a
/// solid or under a one-sided surface (every such ray does; in the open none does) and is left
/// out of the interpolation, so that the dark inside does not bleed out. Half splits the two.
pub const OCC_INSIDE_SHARE: f64 = 0.5;
/// The lookup moves this many cells off the surface along its normal: the point's eight nodes
/// then lie mostly on the open side, where their light is the point's.
pub const OCC_LOOKUP_CELLS: f64 = 0.5;
/// The trilinear weights of the open nodes summing under this mean that no open node is near:
/// the point counts as open (1), not as the quotient of two roundings.
pub const OCC_WEIGHT_MIN: f64 = 1e-4;
/// Grid coordinates beyond this many cells (or not finite) count as open: the lookup's floor and
/// index conversion stay exact in f32.
pub const OCC_COORD_MAX: f64 = 1e6;

/// The six axis directions of a node's ambient cube, in the order of its values.
pub const OCC_AXES: [DVec3; 6] = [DVec3::X, DVec3::NEG_X, DVec3::Y, DVec3::NEG_Y, DVec3::Z, DVec3::NEG_Z];

/// A baked grid: `dims` nodes along each axis (at least 2), `cell` apart from `origin`, x fastest.
#[derive(Clone, Debug, PartialEq)]
pub struct OcclusionGrid {
    pub origin: DVec3,
    pub cell: f64,
    pub dims: [u32; 3],
    /// Per node: the open share about each of [`OCC_AXES`] and whether the node is open (not
    /// inside), each quantized to a byte as the GPU reads it; the eighth byte is zero.
    pub nodes: Vec<[u8; 8]>,
}

/// A share in [0, 1] as the byte the GPU unpacks (`unpack4x8unorm`): round(255·v).
pub fn occ_quantize(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The byte back as the share the GPU reads.
pub fn occ_dequantize(b: u8) -> f64 {
    f64::from(b) / 255.0
}

impl OcclusionGrid {
    /// The nodes as the GPU's buffer holds them: two little-endian words a node.
    pub fn gpu_words(&self) -> Vec<[u32; 2]> {
        self.nodes
            .iter()
            .map(|b| [u32::from_le_bytes([b[0], b[1], b[2], b[3]]), u32::from_le_bytes([b[4], b[5], b[6], b[7]])])
            .collect()
    }

    /// The grid's placement as the GPU's globals hold it: origin and cell, then the node counts.
    pub fn gpu_placement(&self) -> [[f32; 4]; 2] {
        let o = self.origin.as_vec3();
        let d = self.dims.map(|n| n as f32);
        [[o.x, o.y, o.z, self.cell as f32], [d[0], d[1], d[2], 0.0]]
    }

    fn node(&self, i: [u32; 3]) -> &[u8; 8] {
        let [nx, ny, _] = self.dims;
        &self.nodes[(i[0] + nx * (i[1] + ny * i[2])) as usize]
    }
}

/// A node's ambient cube at unit `n`: each axis's share weighed by the normal's squared
/// component along it, the side `n` faces.
pub fn occ_cube(node: &[u8; 8], n: DVec3) -> f64 {
    let pick = |c: f64, pos: usize| occ_dequantize(if c >= 0.0 { node[pos] } else { node[pos + 1] }) * c * c;
    pick(n.x, 0) + pick(n.y, 2) + pick(n.z, 4)
}

/// The environment's open share at world point `p` with unit normal `n`: the grid's open nodes
/// around `p + n·OCC_LOOKUP_CELLS·cell`, trilinearly weighed; 1 where none is near.
pub fn env_occlusion(grid: &OcclusionGrid, p: DVec3, n: DVec3) -> f64 {
    let q = (p + n * (OCC_LOOKUP_CELLS * grid.cell) - grid.origin) / grid.cell;
    if !(q.abs().max_element() < OCC_COORD_MAX) {
        return 1.0;
    }
    let top = DVec3::new(f64::from(grid.dims[0]), f64::from(grid.dims[1]), f64::from(grid.dims[2])) - 1.0;
    let q = q.clamp(DVec3::ZERO, top);
    // The cell's lower corner, kept one node below the top so that its upper corner exists.
    let base = q.floor().min(top - 1.0);
    let f = q - base;
    let (mut sum, mut weight) = (0.0, 0.0);
    for k in 0..8u32 {
        let corner = [k & 1, (k >> 1) & 1, (k >> 2) & 1];
        let w = (0..3).fold(1.0, |w, a| w * if corner[a] == 1 { f[a] } else { 1.0 - f[a] });
        let node = grid.node([0, 1, 2].map(|a| base[a] as u32 + corner[a]));
        let w = w * occ_dequantize(node[6]);
        sum += w * occ_cube(node, n);
        weight += w;
    }
    if weight < OCC_WEIGHT_MIN { 1.0 } else { sum / weight }
}

/// The grid's placement over the box `(lo, hi)`: `OCC_GRID_CELLS` along its longest side, larger
/// cells where that would pass `OCC_NODES_MAX` nodes; `(origin, cell, dims)`.
pub fn occ_layout(lo: DVec3, hi: DVec3) -> (DVec3, f64, [u32; 3]) {
    let extent = (hi - lo).max(DVec3::splat(1e-6));
    let mut cell = extent.max_element() / f64::from(OCC_GRID_CELLS);
    loop {
        let dims = [extent.x, extent.y, extent.z].map(|e| ((e / cell).ceil() as u32 + 1).max(2));
        if dims.iter().map(|&d| d as usize).product::<usize>() <= OCC_NODES_MAX {
            return (lo, cell, dims);
        }
        cell *= 1.05;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(dims: [u32; 3], node: [u8; 8]) -> OcclusionGrid {
        let count = dims.iter().product::<u32>() as usize;
        OcclusionGrid { origin: DVec3::ZERO, cell: 1.0, dims, nodes: vec![node; count] }
    }

    #[test]
    fn the_cube_is_exact_on_its_axes_and_weighs_between() {
        let node = [255, 0, 51, 102, 153, 204, 255, 0];
        assert_eq!(occ_cube(&node, DVec3::X), 1.0);
        assert_eq!(occ_cube(&node, DVec3::NEG_Y), 0.4);
        let d = DVec3::new(1.0, 0.0, -1.0).normalize();
        assert!((occ_cube(&node, d) - 0.5 * (1.0 + 0.8)).abs() < 1e-12);
    }

    #[test]
    fn inside_nodes_are_left_out_and_none_open_is_open() {
        let mut g = grid([2, 2, 2], [128; 8]);
        g.nodes.iter_mut().for_each(|b| b[6] = 255);
        // Every open node at 128/255: the lookup is theirs, wherever the point is.
        let v = env_occlusion(&g, DVec3::splat(0.3), DVec3::Y);
        assert!((v - 128.0 / 255.0).abs() < 1e-12, "{v}");
        // Half the nodes inside and dark: they do not count.
        for (i, b) in g.nodes.iter_mut().enumerate() {
            if i % 2 == 1 {
                *b = [0; 8];
            }
        }
        assert!((env_occlusion(&g, DVec3::splat(0.3), DVec3::Y) - 128.0 / 255.0).abs() < 1e-12);
        // No node open: the point counts as open.
        g.nodes.iter_mut().for_each(|b| b[6] = 0);
        assert_eq!(env_occlusion(&g, DVec3::splat(0.3), DVec3::Y), 1.0);
    }

    #[test]
    fn points_far_outside_or_not_finite_stay_in_range() {
        let mut g = grid([3, 2, 2], [200, 200, 200, 200, 200, 200, 255, 0]);
        g.nodes[0] = [0, 0, 0, 0, 0, 0, 255, 0];
        for p in [DVec3::splat(-1e9), DVec3::splat(1e9), DVec3::NAN, DVec3::new(f64::INFINITY, 0.0, 0.0)] {
            let v = env_occlusion(&g, p, DVec3::Y);
            assert!((0.0..=1.0).contains(&v), "{p}: {v}");
        }
        // Beyond the grid the edge's nodes hold: the corner node is dark.
        assert_eq!(env_occlusion(&g, DVec3::new(-50.0, -50.0, -50.0), DVec3::Y), 0.0);
    }

    #[test]
    fn the_layout_keeps_the_node_bound() {
        for hi in [DVec3::new(10.0, 2.0, 7.0), DVec3::splat(5.0), DVec3::new(1.0, 0.0, 0.0), DVec3::splat(1e-12)] {
            let (_, cell, dims) = occ_layout(DVec3::ZERO, hi);
            assert!(dims.iter().map(|&d| d as usize).product::<usize>() <= OCC_NODES_MAX, "{hi}");
            for a in 0..3 {
                assert!(f64::from(dims[a] - 1) * cell >= hi[a] - 1e-9, "{hi}: the grid covers the box");
            }
        }
    }
}
