//! Cascaded shadow maps for directional lights (docs/model.md §6): when the part of the scene in
//! view spans a large depth ratio, one orthographic map fitted to the whole scene spends as many
//! texels on the far end as on the near end, where a screen pixel covers far less ground. The view
//! is then split along its depth into cascades, each with its own map fitted to its slice, finest
//! first; a point is shadowed by the first cascade whose map holds it.
//!
//! The f64 twins of `shadow_cascade` and `shadow_ortho_texel_world` in `shaders/shadows.wgsl`.

use super::{SHADOW_BOUNDS_RADIUS_MIN, SHADOW_NORMAL_OFFSET_TEXELS, SHADOW_POISSON_RADIUS_TEXELS, shadow_map_coord};
use super::{ShadowProjection, up_for};
use crate::scene::{Camera, Light, Scene};
use glam::{DMat4, DVec3};

/// Most cascades a directional light gets: at [`SHADOW_CASCADE_DEPTH_RATIO`] per cascade, four
/// cover a view depth ratio of 8⁴ = 4096 (a 0.1 m near plane to 400 m); each one costs another
/// depth pass over the scene and one more layer of memory.
pub const SHADOW_CASCADES_MAX: u32 = 4;
/// The view depth ratio (far / near of the scene in view) one map may cover. A screen pixel's
/// footprint grows linearly with depth while an orthographic map's texel does not, so across a
/// ratio of 8 the near end gets 8× fewer texels per pixel than the far end: about the step from a
/// 2048 map to a 256 one, which `bench shadows` shows as the visible loss.
pub const SHADOW_CASCADE_DEPTH_RATIO: f64 = 8.0;
/// The filter's reach in texels beyond the point itself (the Poisson disk's radius and the
/// bilinear footprint's one texel): a point counts as inside a cascade only that far from the
/// map's edge, so no tap of its filter falls off the map.
pub const SHADOW_CASCADE_MARGIN_TEXELS: f64 = SHADOW_POISSON_RADIUS_TEXELS as f64 + 1.0;

// A point light's six faces are told from cascades by their count.
const _: () = assert!(SHADOW_CASCADES_MAX < 6);

/// Rays per side of the grid across the image that measures the depths in view.
const VIEW_RAYS_PER_SIDE: u32 = 33;

/// The depths `(near, far)` along the camera's view axis at which the objects are in view: where
/// a 33 × 33 grid of rays across a 16:9 image enters and leaves the objects' boxes, clipped to the
/// camera's near and far planes. The grid is fixed so the effect analysis, which knows no image
/// size, decides as the renderer does. `None` when no ray meets an object.
pub fn view_depth_range(scene: &Scene) -> Option<(f64, f64)> {
    let cam = &scene.camera;
    let forward = (cam.target - cam.eye).try_normalize()?;
    let right = forward.cross(cam.up).try_normalize()?;
    let up = right.cross(forward);
    let ty = (cam.fov_y_deg.to_radians() * 0.5).tan();
    let tx = ty * crate::scene::COMPOSED_ASPECT;
    let boxes = super::object_boxes(scene);
    let (mut near, mut far) = (f64::INFINITY, f64::NEG_INFINITY);
    let n = VIEW_RAYS_PER_SIDE;
    for i in 0..n {
        for j in 0..n {
            let sx = 2.0 * i as f64 / (n - 1) as f64 - 1.0;
            let sy = 2.0 * j as f64 / (n - 1) as f64 - 1.0;
            // Depth per unit of ray length is 1 along this ray's un-normalized direction.
            let d = forward + right * (sx * tx) + up * (sy * ty);
            for (lo, hi) in &boxes {
                if let Some((t0, t1)) = ray_box(cam.eye, d, *lo, *hi) {
                    near = near.min(t0.max(cam.near));
                    far = far.max(t1.min(cam.far));
                }
            }
        }
    }
    (near.is_finite() && far.is_finite() && far > near).then_some((near, far))
}

/// Where the ray `o + t·d`, t ≥ 0, is inside the box `[lo, hi]` (slabs; a flat box is a plane's
/// rectangle): `(t_enter, t_exit)`, or `None` if it misses.
fn ray_box(o: DVec3, d: DVec3, lo: DVec3, hi: DVec3) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (0.0f64, f64::INFINITY);
    for a in 0..3 {
        if d[a].abs() < 1e-300 {
            if o[a] < lo[a] || o[a] > hi[a] {
                return None;
            }
            continue;
        }
        let (u, v) = ((lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]);
        t0 = t0.max(u.min(v));
        t1 = t1.min(u.max(v));
    }
    (t0 <= t1 && t1.is_finite()).then_some((t0, t1))
}

/// The layers a directional light that casts shadows holds, whatever the view: with its cascades
/// allowed and a perspective camera [`SHADOW_CASCADES_MAX`], else 1. Fixed by the light and the
/// projection, so orbiting, panning and zooming never reallocate the maps or change the program;
/// [`cascade_count`] says how many of them a frame draws.
pub fn cascade_layers(scene: &Scene, light: &Light) -> u32 {
    if light.shadow.cascades && scene.camera.orthographic.is_none() { SHADOW_CASCADES_MAX } else { 1 }
}

/// How many cascades a directional light needs in this scene's view: enough that each covers a
/// depth ratio of at most [`SHADOW_CASCADE_DEPTH_RATIO`], at most [`SHADOW_CASCADES_MAX`]; 1
/// (one map fitted to the scene) when the view's ratio is within it.
pub fn cascade_count(scene: &Scene) -> u32 {
    // An orthographic view's pixels cover the same area at every depth: one map serves it.
    if scene.camera.orthographic.is_some() {
        return 1;
    }
    view_depth_range(scene).map_or(1, |(near, far)| cascades_for_depths(near, far))
}

/// The cascades a view of depths `near` to `far` ([`view_depth_range`]) needs (see
/// [`cascade_count`]).
pub fn cascades_for_depths(near: f64, far: f64) -> u32 {
    let k = ((far / near).ln() / SHADOW_CASCADE_DEPTH_RATIO.ln()).ceil();
    if k.is_finite() { (k as u32).clamp(1, SHADOW_CASCADES_MAX) } else { SHADOW_CASCADES_MAX }
}

/// The `count + 1` split depths from `near` to `far`, geometric: each cascade covers the same
/// depth ratio, as a pixel's footprint grows in proportion to depth.
pub fn cascade_splits(near: f64, far: f64, count: u32) -> Vec<f64> {
    let n = count.max(1);
    (0..=n).map(|i| near * (far / near).powf(i as f64 / n as f64)).collect()
}

/// The bounding sphere of the view frustum's slice between depths `a` and `b` (its eight
/// corners) for an image of aspect ratio `aspect`.
fn slice_sphere(cam: &Camera, aspect: f64, a: f64, b: f64) -> (DVec3, f64) {
    let forward = (cam.target - cam.eye).try_normalize().unwrap_or(DVec3::NEG_Z);
    let right = forward.cross(cam.up).try_normalize().unwrap_or(DVec3::X);
    let up = right.cross(forward);
    let ty = (cam.fov_y_deg.to_radians() * 0.5).tan();
    let tx = ty * aspect;
    let mut corners = Vec::with_capacity(8);
    for d in [a, b] {
        for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
            corners.push(cam.eye + forward * d + right * (sx * tx * d) + up * (sy * ty * d));
        }
    }
    let centre = corners.iter().sum::<DVec3>() / 8.0;
    let radius = corners.iter().map(|c| (*c - centre).length()).fold(0.0, f64::max);
    (centre, radius)
}

/// A directional light's cascaded projection: one orthographic map per slice of the view
/// (`cascade_splits`), each fitted to its slice's bounding sphere (or to the scene's sphere
/// `(centre, radius)` when that is smaller), its centre snapped to the map's texel grid so the
/// shadows do not crawl as the camera moves. Depth spans the whole scene sphere, so casters
/// outside a slice still shadow it.
pub fn cascade_projection(
    light: &Light,
    scene: &Scene,
    aspect: f64,
    (centre, radius): (DVec3, f64),
    resolution: u32,
    count: u32,
) -> ShadowProjection {
    let radius = if radius.is_finite() { radius.max(SHADOW_BOUNDS_RADIUS_MIN) } else { SHADOW_BOUNDS_RADIUS_MIN };
    let dir = light.direction.try_normalize().unwrap_or(DVec3::NEG_Y);
    let n = resolution.max(1) as f64;
    let Some((near, far)) = view_depth_range(scene) else {
        return super::shadow_projection(light, centre, radius, resolution);
    };
    let basis = DMat4::look_to_rh(DVec3::ZERO, dir, up_for(dir));
    let splits = cascade_splits(near, far, count);
    let aspect = if aspect.is_finite() && aspect > 0.0 { aspect } else { 1.0 };
    let matrices = splits
        .windows(2)
        .map(|w| {
            let (c, r) = slice_sphere(&scene.camera, aspect, w[0], w[1]);
            let (c, r) =
                if r.is_finite() && r < radius { (c, r.max(SHADOW_BOUNDS_RADIUS_MIN)) } else { (centre, radius) };
            // Snap the centre across the light's view to whole texels of this cascade.
            let texel = 2.0 * r / n;
            let local = basis.transform_point3(c);
            let snapped = DVec3::new((local.x / texel).round() * texel, (local.y / texel).round() * texel, local.z);
            let c = basis.inverse().transform_point3(snapped);
            // The eye stands where the scene sphere begins along the light, a radius back.
            let behind = (c - centre).dot(dir) + 2.0 * radius;
            let view = DMat4::look_to_rh(c - dir * behind, dir, up_for(dir));
            let proj = DMat4::orthographic_rh(-r, r, -r, r, radius * 0.5, radius * 3.5);
            proj * view
        })
        .collect::<Vec<_>>();
    let texel_world = shadow_ortho_texel_world(matrices[0], n);
    ShadowProjection { matrices, texel_world, perspective: false, near: radius * 0.5, far: radius * 3.5 }
}

/// The world size of one texel of orthographic map `m` with `resolution` texels across: the map
/// spans 2 / |first row| in world units. Twin of `shadow_ortho_texel_world` in `shadows.wgsl`.
pub fn shadow_ortho_texel_world(m: DMat4, resolution: f64) -> f64 {
    2.0 / (DVec3::new(m.x_axis.x, m.y_axis.x, m.z_axis.x).length() * resolution)
}

/// Which of a directional light's `matrices` (its cascades, finest first) shadows world point
/// `p` with unit normal `n`: the first whose map holds the normal-offset point at least
/// [`SHADOW_CASCADE_MARGIN_TEXELS`] from its edge and inside its depth range; the last otherwise.
/// Twin of `shadow_cascade` in `shaders/shadows.wgsl`.
pub fn shadow_cascade(matrices: &[DMat4], resolution: f64, p: DVec3, n: DVec3) -> usize {
    let margin = SHADOW_CASCADE_MARGIN_TEXELS / resolution;
    for (k, m) in matrices.iter().enumerate().take(matrices.len().saturating_sub(1)) {
        let q = p + n * (SHADOW_NORMAL_OFFSET_TEXELS as f64 * shadow_ortho_texel_world(*m, resolution));
        let t = shadow_map_coord(*m, q);
        let inside = |x: f64| x >= margin && x <= 1.0 - margin;
        if inside(t.x) && inside(t.y) && (0.0..=1.0).contains(&t.z) {
            return k;
        }
    }
    matrices.len().saturating_sub(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_scene_needs_one_map_and_the_field_several() {
        let s = Scene::builtin("default").unwrap();
        let (near, far) = view_depth_range(&s).unwrap();
        assert!(far / near < SHADOW_CASCADE_DEPTH_RATIO, "{near} … {far}");
        assert_eq!(cascade_count(&s), 1);
        let f = Scene::builtin("field").unwrap();
        let (near, far) = view_depth_range(&f).unwrap();
        assert!(far / near > SHADOW_CASCADE_DEPTH_RATIO, "{near} … {far}");
        assert_eq!(cascade_count(&f), 2, "{near} … {far}");
    }

    #[test]
    fn splits_are_geometric_and_cover_the_range() {
        let s = cascade_splits(0.5, 256.0, 3);
        assert_eq!(s.len(), 4);
        assert!((s[0] - 0.5).abs() < 1e-12 && (s[3] - 256.0).abs() < 1e-9);
        assert!((s[1] / s[0] - s[2] / s[1]).abs() < 1e-9 && (s[1] / s[0] - 8.0).abs() < 1e-9);
    }

    #[test]
    fn cascades_are_finest_near_the_camera_and_each_holds_its_slice() {
        let s = Scene::builtin("field").unwrap();
        let l = s.lights.iter().find(|l| l.kind == crate::params::LightKind::Directional).unwrap();
        let bounds = super::super::scene_bounds(&s).unwrap();
        let k = cascade_count(&s);
        let p = cascade_projection(l, &s, 16.0 / 9.0, bounds, 2048, k);
        assert_eq!(p.matrices.len(), k as usize);
        let texels: Vec<f64> = p.matrices.iter().map(|m| shadow_ortho_texel_world(*m, 2048.0)).collect();
        let one =
            shadow_ortho_texel_world(super::super::shadow_projection(l, bounds.0, bounds.1, 2048).matrices[0], 2048.0);
        assert!(texels.windows(2).all(|w| w[0] < w[1]), "finest first: {texels:?}");
        assert!(texels[0] * 4.0 < one, "the first cascade is much finer than one map: {texels:?} vs {one}");
        // A ground point on the view axis at each slice's middle depth picks that slice's cascade.
        let (near, far) = view_depth_range(&s).unwrap();
        let splits = cascade_splits(near, far, k);
        let cam = &s.camera;
        let forward = (cam.target - cam.eye).normalize();
        for (i, w) in splits.windows(2).enumerate().skip(1) {
            let d = (w[0] * w[1]).sqrt();
            let q = cam.eye + forward * d;
            let chosen = shadow_cascade(&p.matrices, 2048.0, q, DVec3::Y);
            assert!(chosen <= i, "depth {d}: cascade {chosen}, slice {i}");
        }
    }

    #[test]
    fn degenerate_views_give_finite_cascades() {
        let mut s = Scene::builtin("field").unwrap();
        let bounds = super::super::scene_bounds(&s).unwrap();
        let l = s.lights[0].clone();
        for (near, far) in [(0.1, 0.1), (1e-9, 1e9), (5.0, 1.0)] {
            s.camera.near = near;
            s.camera.far = far;
            for aspect in [1e-6, 16.0 / 9.0, 1e6, f64::NAN] {
                let p = cascade_projection(&l, &s, aspect, bounds, 256, SHADOW_CASCADES_MAX);
                assert!(p.matrices.iter().all(|m| m.is_finite()) && p.texel_world.is_finite(), "{near} {far} {aspect}");
                assert!(cascade_count(&s) >= 1);
            }
        }
    }
}
