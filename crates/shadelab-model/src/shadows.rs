//! Cast shadows (docs/model.md §0, §6): each light's shadow settings (whether it casts, the
//! shadow map's resolution, the filter) with their ranges. The GPU answers "is this point seen by
//! the light" from a shadow map (`shaders/shadows.wgsl`, `shadelab_render::shadow_pass`); the f64
//! reference answers it exactly by tracing a ray to the light (`reference`).
//!
//! Also here: the biases and filter constants (twins in `shaders/shadows.wgsl`, held equal by
//! `shadelab_render`'s twin tests), the scene's bounding sphere the maps are fitted to, and the
//! f64 twin of the shadow projection (the light's view-projections, the cube face, the map
//! coordinate) that the render crate packs into the uniforms.

use crate::scene::{Light, Scene, Shape};
use glam::{DMat4, DVec3, DVec4};

mod cascades;
pub use cascades::{
    SHADOW_CASCADE_DEPTH_RATIO, SHADOW_CASCADE_MARGIN_TEXELS, SHADOW_CASCADES_MAX, cascade_count, cascade_layers,
    cascade_projection, cascade_splits, cascades_for_depths, shadow_cascade, shadow_ortho_texel_world,
    view_depth_range,
};

pub use crate::shadow_settings::{
    PCSS_TAPS, SHADOW_PCSS_TAPS, SHADOW_RESOLUTION, SHADOW_RESOLUTION_DEFAULT, ShadowFilter, ShadowSettings,
};

/// The rasterizer's slope-scaled depth bias in the shadow pass (`DepthBiasState::slope_scale`):
/// depth is pushed away from the light by this many times the triangle's depth slope per pixel,
/// so a lit surface tilted towards grazing light does not shadow itself between texel centres
/// (acne). Measured on a lit plane at 5°…90° (`shadow_pass::tests`): with it alone Hard and Pcf
/// are clean but the Poisson taps, 2 texels out, still see the tilted plane in front of them;
/// with the normal offset below as well every filter is clean.
pub const SHADOW_SLOPE_BIAS: f32 = 2.0;
/// The rasterizer's constant depth bias (`DepthBiasState::constant`, in units of the depth
/// format's smallest step at the triangle's depth): absorbs the rounding of a face seen edge-on,
/// whose slope term is unbounded and is clamped by [`SHADOW_DEPTH_BIAS_CLAMP`].
pub const SHADOW_CONSTANT_BIAS: i32 = 4;
/// The most depth bias the rasterizer may add (`DepthBiasState::clamp`, in [0, 1] depth): a face
/// seen edge-on from the light has an unbounded slope; more than 1 % of the map's depth range
/// would let it vanish from the map (peter-panning) rather than only stop acne.
pub const SHADOW_DEPTH_BIAS_CLAMP: f32 = 0.01;
/// The receiver is moved along its normal by this many texels of the light's map at that point
/// before it is compared: a texel covers a patch of surface whose depth varies by up to one
/// texel × tan(angle), and 1.5 texels clears the texel's diagonal (√2). Alone it cleans Hard and
/// Pcf but not Poisson's wider taps; with the slope bias, all three (0 false pixels, 5°…90°).
/// Larger values detach contact shadows (the shadow starts later).
pub const SHADOW_NORMAL_OFFSET_TEXELS: f32 = 1.5;
/// Poisson-disk taps per light (`ShadowFilter::Poisson`): 16 taps of the hardware's 2×2 compare
/// give 64 texels of support, smooth at the default resolution without banding; each doubling
/// doubles the filter's cost.
pub const SHADOW_POISSON_TAPS: u32 = 16;
/// Radius of the Poisson disk in texels: 2 texels widens the edge to about a 5-texel penumbra,
/// visibly softer than `Pcf`, while staying inside the normal offset's margin at contact points.
pub const SHADOW_POISSON_RADIUS_TEXELS: f32 = 2.0;
/// Shadow-map layers: one per directional or spot light, six per point light (its cube faces),
/// six per point source of an area light drawn as points. 24 cubes: 8 point lights, or 7 and an
/// area light as the most points (`AREA_POINTS`, 16). 9 KiB of matrices in the uniform.
pub const MAX_SHADOW_LAYERS: u32 = 24 * 6;
/// Most memory all of a frame's shadow maps may take: 512 MiB. One 2D array holds every layer at
/// one side; when the layers at the largest requested side would need more, the side is halved
/// until they fit (8 point lights × 6 faces × 4096² × 4 bytes would be 3 GiB, and get 1024²).
/// 512 MiB holds a point and a directional light (7 layers, the default scene) at 4096², the
/// top of [`SHADOW_RESOLUTION`], in 448 MiB.
pub const SHADOW_MAP_BUDGET_BYTES: u64 = 512 << 20;
/// Bytes per shadow-map texel (`Depth32Float`).
pub const SHADOW_TEXEL_BYTES: u64 = 4;
/// Near plane of a point or spot light's map as a share of its far plane, at least: keeps 32-bit
/// float depth resolving the far end to about 1e-4 of the range when the light sits inside the
/// scene's bounds (where the geometry gives no near distance).
pub const SHADOW_NEAR_OVER_FAR_MIN: f64 = 1e-3;
/// Widest half-angle a spot light's perspective map covers: a 90° half-angle cone has no finite
/// frustum; beyond 85° the map would spend its texels at its border. A wider cone's rim outside
/// the map is lit, unshadowed.
pub const SPOT_SHADOW_HALF_ANGLE_MAX: f64 = 85.0 * std::f64::consts::PI / 180.0;
/// Smallest radius of the scene's bounding sphere: a scene of one point or one flat plane
/// seen edge-on still gets a map with a finite, non-zero extent.
pub const SHADOW_BOUNDS_RADIUS_MIN: f64 = 1e-3;

/// Smallest clip-space w of a point in a perspective map: a point at the map's eye (a receiver at
/// a point light's centre, w = 0) or behind it has no coordinate there and counts as outside the
/// map, lit. 1e-20 keeps `c.xyz / w` finite in f32 for any |c.xyz| below 3e18.
pub const SHADOW_CLIP_W_MIN: f64 = 1e-20;

/// The nearest blocker PCSS searches for, as a share of the receiver's distance from the light:
/// a blocker nearer than a tenth casts a penumbra over 9 light sizes wide, more than 16 search
/// taps resolve, and the search region (the cone from the receiver to the light where it crosses
/// that depth) would cover the whole face. The search's taps are spread as the square of their
/// rank, so near blockers are found as surely as far ones.
pub const SHADOW_PCSS_NEAREST_BLOCKER: f64 = 0.1;

/// The distance along a perspective map's view axis of a point whose stored depth is `depth`
/// (the inverse of the map's depth, far·(z − near)/((far − near)·z)): PCSS averages blockers in
/// this linear depth, not in the stored one.
pub fn shadow_linear_depth(depth: f64, near: f64, far: f64) -> f64 {
    far * near / (far - depth.clamp(0.0, 1.0) * (far - near)).max(near)
}

/// The stored depth of a point at linear depth `z` along a perspective map's axis (the inverse
/// of [`shadow_linear_depth`]): PCSS compares each filter tap with its receiver plane's depth.
/// A map without depth range (far ≤ near) or with its eye at depth 0 stores 0 everywhere.
pub fn shadow_stored_depth(z: f64, near: f64, far: f64) -> f64 {
    let zc = z.max(near);
    if far <= near || zc <= 0.0 {
        return 0.0;
    }
    far * (zc - near) / ((far - near) * zc)
}

/// Largest depth slope PCSS allows a receiver's plane, tan θ (84°): each tap at distance r across
/// the light's view compares with the plane's depth r·tan θ nearer the light, so the receiver
/// does not shadow itself; past 84° the bias would swallow every blocker, and N·L ≤ 0.1 there
/// leaves the light dim anyway.
pub const SHADOW_RECEIVER_SLOPE_MAX: f64 = 10.0;

/// tan θ of the receiver's plane against the light, from the cosine `n_dot_l`, at most
/// [`SHADOW_RECEIVER_SLOPE_MAX`].
pub fn receiver_slope(n_dot_l: f64) -> f64 {
    let c = n_dot_l.clamp(0.0, 1.0);
    ((1.0 - c * c).sqrt() / c.max(1.0 / SHADOW_RECEIVER_SLOPE_MAX)).min(SHADOW_RECEIVER_SLOPE_MAX)
}

/// PCSS's blocker search radius on a perspective map, in units of the map's tangent (a cube face
/// spans −1 to 1): the cone from the receiver at `d_receiver` to a light of size `w_light`,
/// where it crosses the nearest depth a blocker can have (`near`, at least `BLOCKER_DIST_MIN`):
/// ½·w_light·(1/near − 1/d_r), 0 for a receiver nearer than that.
pub fn pcss_search_radius(w_light: f64, d_receiver: f64, near: f64) -> f64 {
    let near = near.max(crate::guards::BLOCKER_DIST_MIN);
    (0.5 * w_light.abs() * (1.0 / near - 1.0 / d_receiver.max(near))).max(0.0)
}

/// The penumbra's width on a receiver at distance `d_receiver` from a light of size `w_light`
/// whose blocker is at `d_blocker` (both measured from the light, in linear depth): similar
/// triangles, w = w_light·(d_r − d_b)/d_b; 0 where the receiver is not behind the blocker.
pub fn penumbra_width(w_light: f64, d_receiver: f64, d_blocker: f64) -> f64 {
    let d_b = d_blocker.max(crate::guards::BLOCKER_DIST_MIN);
    (w_light.abs() * (d_receiver - d_b) / d_b).max(0.0)
}

/// The constants `shaders/shadows.wgsl` and `shaders/shadow_math.wgsl` repeat, by their WGSL name: the twin test holds them
/// equal, and every `f32`/`u32` constant of that file (other than the filter codes) is here.
pub const WGSL_TWINS: [(&str, f64); 8] = [
    ("SHADOW_NORMAL_OFFSET_TEXELS", SHADOW_NORMAL_OFFSET_TEXELS as f64),
    ("SHADOW_POISSON_TAPS", SHADOW_POISSON_TAPS as f64),
    ("SHADOW_POISSON_RADIUS_TEXELS", SHADOW_POISSON_RADIUS_TEXELS as f64),
    ("MAX_SHADOW_LAYERS", MAX_SHADOW_LAYERS as f64),
    ("SHADOW_CASCADE_MARGIN_TEXELS", SHADOW_CASCADE_MARGIN_TEXELS),
    ("SHADOW_CLIP_W_MIN", SHADOW_CLIP_W_MIN),
    ("SHADOW_RECEIVER_SLOPE_MAX", SHADOW_RECEIVER_SLOPE_MAX),
    ("SHADOW_PCSS_NEAREST_BLOCKER", SHADOW_PCSS_NEAREST_BLOCKER),
];

/// The bounding sphere `(centre, radius)` of every object in world space (the corners of each
/// shape's box carried by its transform); `None` for a scene without objects.
pub fn scene_bounds(scene: &Scene) -> Option<(DVec3, f64)> {
    let (lo, hi) = scene_box(scene)?;
    let centre = (lo + hi) * 0.5;
    Some((centre, ((hi - lo).length() * 0.5).max(SHADOW_BOUNDS_RADIUS_MIN)))
}

/// The world-space box `(lo, hi)` around every object; `None` for a scene without objects.
pub fn scene_box(scene: &Scene) -> Option<(DVec3, DVec3)> {
    let boxes = object_boxes(scene);
    let lo = boxes.iter().fold(DVec3::splat(f64::INFINITY), |a, b| a.min(b.0));
    let hi = boxes.iter().fold(DVec3::splat(f64::NEG_INFINITY), |a, b| a.max(b.1));
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

/// An object's box `(lo, hi)` in its own space: its shape's, or its mesh's bounds (`None` for a
/// mesh without any).
pub fn object_local_box(scene: &Scene, o: &crate::scene::Object) -> Option<(DVec3, DVec3)> {
    match o.shape {
        Shape::Mesh(i) => scene.meshes.bounds(i),
        Shape::Plane => Some((DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 0.0, 1.0))),
        _ => Some((DVec3::splat(-1.0), DVec3::splat(1.0))),
    }
}

/// Each object's world-space box `(lo, hi)`: the corners of its shape's box carried by its
/// transform, non-finite corners left out (an object with none is left out).
pub fn object_boxes(scene: &Scene) -> Vec<(DVec3, DVec3)> {
    let mut out = Vec::new();
    for o in &scene.objects {
        let Some((a, b)) = object_local_box(scene, o) else { continue };
        let m = o.transform.matrix();
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for k in 0..8 {
            let c = DVec3::new(
                if k & 1 == 0 { a.x } else { b.x },
                if k & 2 == 0 { a.y } else { b.y },
                if k & 4 == 0 { a.z } else { b.z },
            );
            let w = m.transform_point3(c);
            if w.is_finite() {
                lo = lo.min(w);
                hi = hi.max(w);
            }
        }
        if lo.is_finite() && hi.is_finite() {
            out.push((lo, hi));
        }
    }
    out
}

/// One light's shadow projection: a view-projection per layer (1, or 6 cube faces in the order
/// of [`shadow_face`]), and the world size of one texel (at unit distance along the view axis
/// for a perspective map).
#[derive(Clone, Debug, PartialEq)]
pub struct ShadowProjection {
    pub matrices: Vec<DMat4>,
    pub texel_world: f64,
    pub perspective: bool,
    /// The depth range along the view axis (a perspective map's planes; PCSS linearizes with it).
    pub near: f64,
    pub far: f64,
}

/// The faces' view directions and up vectors, in [`shadow_face`]'s order: +x, −x, +y, −y, +z, −z.
const FACES: [(DVec3, DVec3); 6] = [
    (DVec3::X, DVec3::NEG_Y),
    (DVec3::NEG_X, DVec3::NEG_Y),
    (DVec3::Y, DVec3::Z),
    (DVec3::NEG_Y, DVec3::NEG_Z),
    (DVec3::Z, DVec3::NEG_Y),
    (DVec3::NEG_Z, DVec3::NEG_Y),
];

/// An up vector not parallel to `dir`.
fn up_for(dir: DVec3) -> DVec3 {
    if dir.y.abs() > 0.99 { DVec3::Z } else { DVec3::Y }
}

/// The shadow projection of `light` fitted to the bounding sphere `(centre, radius)` with a map
/// `resolution` texels wide. Directional: orthographic, the sphere's silhouette square, depth
/// across its diameter. Spot: perspective with the outer cone (at most
/// [`SPOT_SHADOW_HALF_ANGLE_MAX`]). Point: six 90° faces. Near and far enclose the sphere.
pub fn shadow_projection(light: &Light, centre: DVec3, radius: f64, resolution: u32) -> ShadowProjection {
    let radius = if radius.is_finite() { radius.max(SHADOW_BOUNDS_RADIUS_MIN) } else { SHADOW_BOUNDS_RADIUS_MIN };
    let n = resolution.max(1) as f64;
    if light.kind.is_directional() {
        let dir = light.direction.try_normalize().unwrap_or(DVec3::NEG_Y);
        // The eye stands a radius back from the sphere; depth spans the diameter, plus a
        // margin so the nearest caster is not clipped at the near plane.
        let eye = centre - dir * (radius * 2.0);
        let view = DMat4::look_to_rh(eye, dir, up_for(dir));
        let proj = DMat4::orthographic_rh(-radius, radius, -radius, radius, radius * 0.5, radius * 3.5);
        ShadowProjection {
            matrices: vec![proj * view],
            texel_world: 2.0 * radius / n,
            perspective: false,
            near: radius * 0.5,
            far: radius * 3.5,
        }
    } else {
        // An area light's map is a point light's six faces from its centre (PCSS widens it).
        let d = (centre - light.position).length();
        let far = if (d + radius).is_finite() { (d + radius).max(SHADOW_BOUNDS_RADIUS_MIN) } else { radius };
        let near = (d - radius).max(far * SHADOW_NEAR_OVER_FAR_MIN);
        if light.kind.has_cone() {
            let axis = light.spot_axis();
            let half = light.outer_cone.clamp(1e-3, SPOT_SHADOW_HALF_ANGLE_MAX);
            let view = DMat4::look_to_rh(light.position, axis, up_for(axis));
            let proj = DMat4::perspective_rh(2.0 * half, 1.0, near, far);
            ShadowProjection {
                matrices: vec![proj * view],
                texel_world: 2.0 * half.tan() / n,
                perspective: true,
                near,
                far,
            }
        } else {
            let proj = DMat4::perspective_rh(std::f64::consts::FRAC_PI_2, 1.0, near, far);
            let matrices = FACES.iter().map(|(f, up)| proj * DMat4::look_to_rh(light.position, *f, *up)).collect();
            ShadowProjection { matrices, texel_world: 2.0 / n, perspective: true, near, far }
        }
    }
}

/// The layers `light` holds in the frame's array of maps, per cube, whatever the view: 0 when it
/// casts no shadow, 6 for a point or area light's cube, [`cascade_layers`] for a directional
/// light, 1 for a spot's map. The one place a kind's layers are decided: [`shadow_cubes`], the
/// renderer's shadow plan and the viewer's map menu read it.
pub fn light_layers(scene: &Scene, light: &Light) -> u32 {
    if !light.shadow.casts {
        0
    } else if light.kind.is_directional() {
        cascade_layers(scene, light)
    } else if light.kind.has_cube_map() {
        6
    } else {
        1
    }
}

/// The layers of `light`'s map (per cube) a frame draws and reads: a directional light's
/// [`cascade_count`] for this view when it holds cascades, otherwise all of [`light_layers`].
pub fn drawn_layers(scene: &Scene, light: &Light) -> u32 {
    let layers = light_layers(scene, light);
    if light.kind.is_directional() && layers > 1 { cascade_count(scene).min(layers) } else { layers }
}

/// How many shadow cubes each light slot of `scene` gets (the first `MAX_LIGHTS`): 0 for a light
/// that casts none or has no cube (directional, spot), 1 for a point or area light, its k for an
/// area light drawn as k points, as many as `MAX_SHADOW_LAYERS` leaves once every other casting
/// light has its layers (then point source j uses cube j mod the count). `ShadowPlan` lays the
/// layers out from this; the effect analysis reports a light that got fewer than its k.
pub fn shadow_cubes(scene: &Scene) -> Vec<u32> {
    let lights: Vec<&Light> = scene.lights.iter().take(crate::scene::MAX_LIGHTS).collect();
    let own: Vec<u32> = lights.iter().map(|l| light_layers(scene, l)).collect();
    let mut spare = MAX_SHADOW_LAYERS.saturating_sub(own.iter().sum());
    lights
        .iter()
        .zip(own)
        .map(|(l, own)| {
            if own != 6 {
                return 0;
            }
            let want = crate::lighting::area_points::area_point_count(l);
            let extra = (want - 1).min(spare / 6);
            spare -= 6 * extra;
            1 + extra
        })
        .collect()
}

/// The cube face that sees direction `d` from a point light (its largest axis; ties go to x,
/// then y): 0 +x, 1 −x, 2 +y, 3 −y, 4 +z, 5 −z. Twin of `shadow_face` in `shaders/shadows.wgsl`.
pub fn shadow_face(d: DVec3) -> u32 {
    let a = d.abs();
    if a.x >= a.y && a.x >= a.z {
        if d.x >= 0.0 { 0 } else { 1 }
    } else if a.y >= a.z {
        if d.y >= 0.0 { 2 } else { 3 }
    } else if d.z >= 0.0 {
        4
    } else {
        5
    }
}

/// Where world point `p` falls in the map of view-projection `m`: `(u, v, depth)`, u and v in
/// [0, 1] across the map (v down, as textures are addressed), depth in [0, 1] from near to far.
/// A point with clip w below [`SHADOW_CLIP_W_MIN`] is outside: `(−1, −1, −1)`.
/// Twin of `shadow_map_coord` in `shaders/shadow_math.wgsl`.
pub fn shadow_map_coord(m: DMat4, p: DVec3) -> DVec3 {
    let c = m * DVec4::new(p.x, p.y, p.z, 1.0);
    if c.w < SHADOW_CLIP_W_MIN {
        return DVec3::splat(-1.0);
    }
    let ndc = c.truncate() / c.w;
    DVec3::new(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5, ndc.z)
}

/// The world size of one texel of a light's map at a receiver `dist` along the map's view axis:
/// constant for an orthographic map, growing with distance for a perspective one. Twin of
/// `shadow_texel_world` in `shaders/shadows.wgsl`.
pub fn shadow_texel_world(texel_world: f64, perspective: bool, dist: f64) -> f64 {
    if perspective { texel_world * dist.max(0.0) } else { texel_world }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::LightKind;

    #[test]
    fn every_layer_sees_the_bounds_inside_its_depth_range() {
        let s = Scene::builtin("default").unwrap();
        let (c, r) = scene_bounds(&s).unwrap();
        assert!(r > 1.0 && r.is_finite());
        for l in &s.lights {
            let p = shadow_projection(l, c, r, 2048);
            assert_eq!(p.matrices.len(), if l.kind == LightKind::Point { 6 } else { 1 });
            // The object centres fall inside the map of the face that sees them, depth in (0, 1).
            for o in &s.objects {
                let q = o.transform.translation;
                let m = if l.kind == LightKind::Point {
                    p.matrices[shadow_face(q - l.position) as usize]
                } else {
                    p.matrices[0]
                };
                let t = shadow_map_coord(m, q);
                // A point on a face's edge (a tie of two axes) lands on 0 or 1 up to rounding.
                let inside = |x: f64| (-1e-9..=1.0 + 1e-9).contains(&x);
                assert!(inside(t.x) && inside(t.y), "{}: {t}", o.name);
                assert!(t.z > 0.0 && t.z < 1.0, "{}: depth {}", o.name, t.z);
            }
        }
    }

    #[test]
    fn faces_follow_the_major_axis() {
        let dirs = [DVec3::X, DVec3::NEG_X, DVec3::Y, DVec3::NEG_Y, DVec3::Z, DVec3::NEG_Z];
        for (i, d) in dirs.iter().enumerate() {
            assert_eq!(shadow_face(*d + DVec3::splat(0.1)) as usize, i);
            assert_eq!(FACES[i].0, *d);
        }
    }

    #[test]
    fn degenerate_inputs_give_finite_matrices() {
        let mut l = Light::point(DVec3::ZERO, [1.0; 3], 1.0, 0.0);
        for (c, r) in [(DVec3::ZERO, 0.0), (DVec3::ZERO, f64::INFINITY), (DVec3::splat(1e9), 1e9)] {
            for kind in [LightKind::Point, LightKind::Spot, LightKind::Directional] {
                l.set_kind(kind);
                let p = shadow_projection(&l, c, r, 256);
                assert!(p.matrices.iter().all(|m| m.is_finite()) && p.texel_world.is_finite(), "{kind:?} {c} {r}");
            }
        }
    }
}
