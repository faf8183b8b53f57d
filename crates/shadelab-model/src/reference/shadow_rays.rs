//! The reference's cast shadows (docs/model.md §0): a point is hidden from a light when a shadow
//! ray from it to the light crosses a surface. Exact hard shadows of point, spot and directional
//! lights, against the analytic shapes and file meshes.

use super::intersect::{Geometry, occluded, occluded_among};
use crate::guards::LIGHT_DIST_MIN;
use crate::lighting::area::{AreaLight, area_visible_share};
use crate::lighting::lights::Light;
use crate::scene::{Scene, Shape};
use glam::DVec3;
use std::cmp::Ordering;

/// How far a shadow ray's ends are moved off the surfaces they lie on, relative to the scene's
/// scale (its largest coordinate). A computed hit point is off the exact surface by rounding
/// alone: a few f64 ulps (2.2e-16 relative) of its coordinates, times the condition of the
/// object's transform and of the intersection, well under 1e-12 of the scale for the scenes'
/// transforms. At 1e-9 the start is a thousand times beyond that, so a surface never shadows
/// itself at its own start point, and it is 1e5 times under a pixel's footprint at 1280×720
/// (about 6e-4 of the distance for a 40° view), so no shadow edge moves by a visible amount,
/// even at grazing light (1e-9 / tan 1° ≈ 6e-8 of the scale).
pub const SHADOW_RAY_OFFSET_REL: f64 = 1e-9;

/// The scene's scale for [`SHADOW_RAY_OFFSET_REL`]: the largest absolute coordinate of the
/// camera and of the objects' bounding boxes in world space. Hit points lie among these, and
/// their rounding error is relative to them. 1 where nothing is finite and positive.
pub(super) fn scene_scale(scene: &Scene) -> f64 {
    let mut s = scene.camera.eye.abs().max_element();
    for obj in &scene.objects {
        let m = obj.transform.matrix();
        let corners: Vec<DVec3> = match obj.shape {
            Shape::Mesh(i) => match scene.meshes.get(i).filter(|mesh| !mesh.positions.is_empty()) {
                Some(mesh) => {
                    let lo = mesh.positions.iter().fold(DVec3::INFINITY, |a, &p| a.min(p));
                    let hi = mesh.positions.iter().fold(DVec3::NEG_INFINITY, |a, &p| a.max(p));
                    box_corners(lo, hi).to_vec()
                }
                None => Vec::new(),
            },
            // Every analytic shape lies in the unit cube [-1, 1]³.
            _ => box_corners(DVec3::NEG_ONE, DVec3::ONE).to_vec(),
        };
        for c in corners {
            s = s.max(m.transform_point3(c).abs().max_element());
        }
    }
    if s.is_finite() && s > 0.0 { s } else { 1.0 }
}

fn box_corners(lo: DVec3, hi: DVec3) -> [DVec3; 8] {
    std::array::from_fn(|k| {
        DVec3::new(
            if k & 1 == 0 { lo.x } else { hi.x },
            if k & 2 == 0 { lo.y } else { hi.y },
            if k & 4 == 0 { lo.z } else { hi.z },
        )
    })
}

/// The shadow rays of one scene: its objects' inverse transforms and the offset of the rays'
/// ends.
pub(super) struct ShadowRays<'a> {
    scene: &'a Scene,
    geo: &'a Geometry,
    /// `SHADOW_RAY_OFFSET_REL` × the scene's scale, world units.
    offset: f64,
    /// The scene's scale ([`scene_scale`]), measured once for every ray of an image.
    pub scale: f64,
}

impl<'a> ShadowRays<'a> {
    pub fn new(scene: &'a Scene, geo: &'a Geometry) -> Self {
        let scale = scene_scale(scene);
        ShadowRays { scene, geo, offset: SHADOW_RAY_OFFSET_REL * scale, scale }
    }

    /// Whether `light` is hidden from surface point `p` (world unit geometric normal `ng`) by
    /// some object; `l` is the unit direction to the light that shading used. The ray starts at
    /// `p` moved off the surface along `ng`, to the side the light is on, and ends at the light:
    /// at its position (point, spot) less the offset there too, so a light sitting on a surface is
    /// not hidden by it; at infinity (directional). A light touching the point
    /// (`d ≤ LIGHT_DIST_MIN`, where shading takes `L = N`) hides nothing.
    pub fn hidden(&self, light: &Light, p: DVec3, ng: DVec3, l: DVec3) -> bool {
        let side = if ng.dot(l) >= 0.0 { 1.0 } else { -1.0 };
        let o = p + ng * (side * self.offset);
        if light.kind.is_directional() {
            occluded(self.scene, self.geo, o, l, f64::INFINITY)
        } else {
            // An area light's hard shadow from its centre; `area_visibility` has its soft one.
            // Also a non-finite distance: no ray to trace.
            let touching = (light.position - p).length().partial_cmp(&LIGHT_DIST_MIN) != Some(Ordering::Greater);
            if touching {
                return false;
            }
            let to_light = light.position - o;
            let d = to_light.length();
            let end_offset = self.offset.max(SHADOW_RAY_OFFSET_REL * light.position.abs().max_element());
            let t_max = d - end_offset;
            t_max > 0.0 && occluded(self.scene, self.geo, o, to_light / d, t_max)
        }
    }

    /// The share of an area light's diffuse light that reaches `p` (unit normal `n`, geometric
    /// normal `ng`): the light's E/L over `k`×`k` equal-area cells with a shadow ray to each
    /// (binary visibility), over the same without shadows; 1 where the light delivers nothing.
    /// The ray to each cell leaves and ends as in [`ShadowRays::hidden`]. `None` for a light
    /// without an area.
    pub fn area_visibility(&self, light: &Light, p: DVec3, n: DVec3, ng: DVec3, k: usize) -> Option<f64> {
        let area = light.area_light()?;
        Some(area_visible_share(&area, p, n, k, &self.cell_visible(ng)))
    }

    /// Whether the segment from a surface point (geometric normal `ng`) to a point on a light is
    /// clear: `visible(from, x)`, the ray leaving and ending as in [`ShadowRays::hidden`].
    pub fn cell_visible(&self, ng: DVec3) -> impl Fn(DVec3, DVec3) -> bool + '_ {
        move |from: DVec3, x: DVec3| {
            let (o, dir, t_max) = self.segment(ng, from, x);
            !(t_max > 0.0 && occluded(self.scene, self.geo, o, dir, t_max))
        }
    }

    /// [`Self::cell_visible`] for segments from `p` to points of `light` alone, testing only the
    /// objects whose world box meets the box that holds `p`, the light and every such segment:
    /// the same answers, and none to test where the light is in the open. Worth it where many
    /// cells are tested from one point (the exact area term).
    pub fn cells_visible_from(&self, ng: DVec3, p: DVec3, light: &AreaLight) -> impl Fn(DVec3, DVec3) -> bool + '_ {
        // Every point of the light lies within its area radius of its centre; a segment's start
        // is off `p` by the offset. One more offset on every side covers their rounding.
        let reach = DVec3::splat(light.area_radius());
        let margin = DVec3::splat(2.0 * self.offset);
        let lo = p.min(light.center - reach) - margin;
        let hi = p.max(light.center + reach) + margin;
        // World boxes are never NaN (an unbounded object's is infinite, and stays); a NaN light
        // leaves the box around `p` alone, and its cells' rays are not traced (NaN length).
        let apart = |b: &(DVec3, DVec3)| b.1.cmplt(lo).any() || b.0.cmpgt(hi).any();
        let among: Vec<usize> = (0..self.geo.boxes.len()).filter(|&i| !apart(&self.geo.boxes[i])).collect();
        move |from: DVec3, x: DVec3| {
            if from != p {
                return self.cell_visible(ng)(from, x);
            }
            if among.is_empty() {
                return true;
            }
            let (o, dir, t_max) = self.segment(ng, from, x);
            !(t_max > 0.0 && occluded_among(self.scene, self.geo, among.iter().copied(), o, dir, t_max))
        }
    }

    /// The shadow ray from `from` (geometric normal `ng`) to `x`: its start off the surface, its
    /// unit direction and its length short of `x` by the offset there.
    fn segment(&self, ng: DVec3, from: DVec3, x: DVec3) -> (DVec3, DVec3, f64) {
        let to = x - from;
        let side = if ng.dot(to) >= 0.0 { 1.0 } else { -1.0 };
        let o = from + ng * (side * self.offset);
        let to = x - o;
        let d = to.length();
        let end_offset = self.offset.max(SHADOW_RAY_OFFSET_REL * x.abs().max_element());
        (o, to / d, d - end_offset)
    }
}
