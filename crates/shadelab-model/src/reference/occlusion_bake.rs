//! The environment's precomputed occlusion (`lighting::occlusion`), baked by the reference's rays:
//! at every node of a grid over the scene's box, the share of cosine-distributed rays about each
//! axis that meet nothing within the ambient occlusion's radius, and the share that meet a back
//! face, which marks the node as inside a solid.

use super::ambient::AO_RADIUS_REL;
use super::intersect::trace;
use super::path::{Rng, cosine_direction};
use super::{Geometry, SECONDARY_RAY_OFFSET};
use crate::lighting::occlusion::{OCC_AXES, OCC_INSIDE_SHARE, OcclusionGrid, occ_layout, occ_quantize};
use crate::scene::Scene;
use glam::DVec3;
use rayon::prelude::*;

/// The scene's occlusion grid with `rays` rays a node and axis, the random numbers from `seed`
/// and the node; `None` for a scene without objects. Its box is the scene's, grown by the
/// radius, so that a point near an edge has nodes on its open side. The radius is
/// `AO_RADIUS_REL` of the objects' largest coordinate: the camera's does not count, so that
/// moving the view keeps the grid.
pub fn bake_occlusion(scene: &Scene, rays: u32, seed: u64) -> Option<OcclusionGrid> {
    let (lo, hi) = crate::shadows::scene_box(scene)?;
    let geo = Geometry::new(scene);
    let scale = lo.abs().max(hi.abs()).max_element().max(f64::MIN_POSITIVE);
    let radius = AO_RADIUS_REL * scale;
    let (origin, cell, dims) = occ_layout(lo - radius, hi + radius);
    let count = dims.iter().map(|&d| d as usize).product::<usize>();
    let [nx, ny, _] = dims;
    let nodes = (0..count)
        .into_par_iter()
        .map(|i| {
            let i = i as u32;
            let at = DVec3::new(f64::from(i % nx), f64::from((i / nx) % ny), f64::from(i / (nx * ny)));
            bake_node(scene, &geo, origin + at * cell, radius, SECONDARY_RAY_OFFSET * scale, rays, Rng::new(seed, i, 0))
        })
        .collect();
    Some(OcclusionGrid { origin, cell, dims, nodes })
}

/// One node at `p`: its open share about each axis, and whether it is open (bytes 0..6, 6).
fn bake_node(scene: &Scene, geo: &Geometry, p: DVec3, radius: f64, offset: f64, rays: u32, mut rng: Rng) -> [u8; 8] {
    let rays = rays.max(1);
    let mut out = [0u8; 8];
    let (mut inside, mut met) = (0u32, 0u32);
    for (a, axis) in OCC_AXES.iter().enumerate() {
        let mut open = 0u32;
        for _ in 0..rays {
            let w = cosine_direction(*axis, rng.uniform(), rng.uniform());
            match trace(scene, geo, p, w).filter(|h| (h.point - p).length() < radius) {
                None => open += 1,
                // A node exactly on a surface does not count the surface it lies on.
                Some(h) if (h.point - p).length() <= offset => open += 1,
                Some(h) => {
                    met += 1;
                    inside += u32::from(h.geometric_normal.dot(w) > 0.0);
                }
            }
        }
        out[a] = occ_quantize(f64::from(open) / f64::from(rays));
    }
    let inside_share = if met == 0 { 0.0 } else { f64::from(inside) / f64::from(met) };
    out[6] = if inside_share > OCC_INSIDE_SHARE { 0 } else { 255 };
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::occlusion::env_occlusion;

    #[test]
    fn the_open_ground_is_open_and_the_contact_is_dark() {
        let scene = Scene::builtin("default").expect("built in");
        let grid = bake_occlusion(&scene, 16, 1).expect("objects");
        // Far from every object the ground is open; the ground below the first sphere's side,
        // where it meets the ground, is darker.
        let open = env_occlusion(&grid, DVec3::new(4.5, 0.0, 3.2), DVec3::Y);
        assert!(open > 0.9, "open ground {open}");
        let sphere = &scene.objects.iter().find(|o| o.shape == crate::scene::Shape::Sphere).expect("a sphere");
        let c = sphere.transform.matrix().transform_point3(DVec3::ZERO);
        let r = sphere.transform.matrix().transform_vector3(DVec3::X).length();
        let contact = env_occlusion(&grid, DVec3::new(c.x + r * 0.8, 0.0, c.z), DVec3::Y);
        assert!(contact < open - 0.15, "contact {contact}, open {open}");
        // The sphere's top sees the sky.
        let top = env_occlusion(&grid, c + DVec3::Y * r, DVec3::Y);
        assert!(top > 0.9, "top {top}");
    }

    #[test]
    fn nodes_inside_solids_and_below_the_ground_are_left_out() {
        let scene = Scene::builtin("default").expect("built in");
        let grid = bake_occlusion(&scene, 16, 1).expect("objects");
        let [nx, ny, _] = grid.dims;
        // Nodes under the ground (10 m by 7.2 m about the origin), within a cell of it and not
        // under an object (whose base, level with the ground, faces down to them): they see the
        // ground's back (the cell is under the radius). Deeper ones see nothing and stay open.
        let boxes = crate::shadows::object_boxes(&scene);
        let under_object = |at: DVec3| {
            boxes.iter().skip(1).any(|(lo, hi)| {
                (lo.x - grid.cell..hi.x + grid.cell).contains(&at.x)
                    && (lo.z - grid.cell..hi.z + grid.cell).contains(&at.z)
            })
        };
        let below = grid.nodes.iter().enumerate().filter(|(i, b)| {
            let i = *i as u32;
            let at = grid.origin
                + DVec3::new(f64::from(i % nx), f64::from((i / nx) % ny), f64::from(i / (nx * ny))) * grid.cell;
            (-grid.cell..-1e-9).contains(&at.y)
                && at.x.abs() < 4.5
                && at.z.abs() < 3.1
                && !under_object(at)
                && b[6] == 255
        });
        assert_eq!(below.count(), 0, "a node within a cell below the ground is open");
        assert!(grid.nodes.iter().any(|b| b[6] == 255));
        // The node nearest each sphere's centre lies inside it.
        for o in scene.objects.iter().filter(|o| o.shape == crate::scene::Shape::Sphere) {
            let c = o.transform.matrix().transform_point3(DVec3::ZERO);
            let i = ((c - grid.origin) / grid.cell).round().as_uvec3();
            assert_eq!(grid.nodes[(i.x + nx * (i.y + ny * i.z)) as usize][6], 0, "{c}");
        }
    }

    #[test]
    fn the_bake_is_the_same_for_the_same_seed() {
        let scene = Scene::builtin("sphere").expect("built in");
        assert_eq!(bake_occlusion(&scene, 4, 7), bake_occlusion(&scene, 4, 7));
        assert!(bake_occlusion(&Scene { objects: vec![], ..scene }, 4, 7).is_none());
    }
}
