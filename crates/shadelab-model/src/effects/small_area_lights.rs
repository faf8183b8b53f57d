//! Area lights too small on screen for their area to show (docs/area-lights.md): where, in an
//! image that frames the whole scene, an area light's penumbra and its highlight would both be
//! under a pixel wide and its diffuse light within an 8-bit step of its centre's, it is drawn as
//! one point source (its centre, with a flat light's emitter cosine) and the reason is printed.
//! The camera takes no part, so orbiting and zooming never change the lights drawn (nor the
//! pipeline). One pure function decides ([`small_area_light`]); the CLI, the viewer and `bench
//! effects` apply it the same way ([`draw_small_area_lights_as_points`]), so the analysis, the
//! uniforms and the shadow maps all see the same lights.

use crate::params::NamedValue;
use crate::scene::{Light, MAX_LIGHTS, Scene};
use crate::shadows::object_boxes;
use glam::DVec3;

/// Largest penumbra or highlight, in pixels, that still counts as not showing: one pixel.
pub const SMALL_AREA_MAX_PX: f64 = 1.0;
/// Largest light radius over its nearest object's distance r/d for which its diffuse light is
/// its centre's: the area form differs from the point form by about (r/d)², and (1/16)² is
/// 1/256, under one step of an 8-bit image.
pub const SMALL_AREA_MAX_RADIUS_OVER_DISTANCE: f64 = 1.0 / 16.0;

/// The bounds that decide: the largest penumbra and highlight the light can draw, in pixels of
/// the framing image, and its radius over the distance to the nearest object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmallAreaLight {
    pub penumbra_px: f64,
    pub highlight_px: f64,
    pub radius_over_distance: f64,
    /// The distance from the light's centre to the nearest object's box.
    pub nearest: f64,
}

impl SmallAreaLight {
    /// Whether all three bounds are under their limits.
    pub fn is_small(&self) -> bool {
        self.penumbra_px <= SMALL_AREA_MAX_PX
            && self.highlight_px <= SMALL_AREA_MAX_PX
            && self.radius_over_distance <= SMALL_AREA_MAX_RADIUS_OVER_DISTANCE
    }
}

/// Distance from `p` to the box `(lo, hi)` (0 inside) and to its farthest corner.
fn box_distances(p: DVec3, (lo, hi): (DVec3, DVec3)) -> (f64, f64) {
    let near = (lo - p).max(p - hi).max(DVec3::ZERO).length();
    let far = (p - lo).abs().max((p - hi).abs()).length();
    (near, far)
}

/// The bounds for area light `light` of `scene` in an image `height` pixels high that frames the
/// scene: its objects' bounding sphere just spans the height, so a pixel is the sphere's diameter
/// over `height`, whatever the lens (a perspective camera at the framing distance, or an
/// orthographic one as tall as the sphere). The camera itself is not read: the rule holds for
/// every view at least that far out, and a view zoomed closer may show an area the rule dropped.
/// `None` for a light without an area or a scene without objects. Bounds, not estimates:
/// - the penumbra: the similar triangles' w·(d_r − d_b)/d_b ≤ w·d_r/d_b, with w the light's full
///   extent, the blocker no nearer than the nearest object less the light's radius, and the
///   receiver d_r within each object's box (0 if shadows are off: no penumbra);
/// - the highlight: a flat or convex mirror shows the light no larger than the light itself,
///   w, seen from at least the mirror's distance to the camera (a rough surface blurs point and
///   area alike);
/// - an object within the light's radius: no bound (infinite), so the light keeps its area.
pub fn small_area_light(scene: &Scene, light: &Light, height: u32) -> Option<SmallAreaLight> {
    bounds_of(&object_boxes(scene), light, height)
}

/// [`small_area_light`] with the scene's object boxes already made (they walk every mesh).
fn bounds_of(boxes: &[(DVec3, DVec3)], light: &Light, height: u32) -> Option<SmallAreaLight> {
    let area = light.area_light()?;
    if boxes.is_empty() {
        return None;
    }
    let r = area.area_radius();
    let w = 2.0 * r;
    // One pixel of the framing image, in world units: the scene's diameter over the height.
    let lo = boxes.iter().fold(DVec3::splat(f64::INFINITY), |a, b| a.min(b.0));
    let hi = boxes.iter().fold(DVec3::splat(f64::NEG_INFINITY), |a, b| a.max(b.1));
    let pixel = (hi - lo).length() / height.max(1) as f64;
    let pixels = |world: f64| {
        if world == 0.0 {
            0.0
        } else if pixel > 0.0 {
            world / pixel
        } else {
            f64::INFINITY
        }
    };
    let d_near = boxes.iter().map(|b| box_distances(area.center, *b).0).fold(f64::INFINITY, f64::min);
    // On a receiver at x, d(x) from the light, the penumbra is at most w·d(x)/(d_near − r), with
    // d(x) at most each box's farthest corner from the light.
    let penumbra = if !light.shadow.casts {
        0.0
    } else if d_near > r {
        boxes.iter().map(|b| pixels(w * (box_distances(area.center, *b).1 + r) / (d_near - r))).fold(0.0, f64::max)
    } else {
        f64::INFINITY
    };
    Some(SmallAreaLight {
        penumbra_px: penumbra,
        highlight_px: pixels(w),
        radius_over_distance: if d_near > 0.0 { r / d_near } else { f64::INFINITY },
        nearest: d_near,
    })
}

/// Draw every area light of `scene` (the first `MAX_LIGHTS`) that is drawn with its exact form
/// but too small to show it in an image `height` pixels high framing the scene as one point
/// source (`area_points` = 1), and say why, one line each, e.g. "rect light L2: 0.02 × 0.02 m,
/// 40.000 m from the nearest object, penumbra ≤ 0.4 px, highlight ≤ 0.3 px, r/d 0.001: drawn as
/// a point light".
pub fn draw_small_area_lights_as_points(scene: &mut Scene, height: u32) -> Vec<String> {
    let mut lines = Vec::new();
    let exact = |l: &Light| l.kind.is_area() && l.area_points == 0;
    if !scene.lights.iter().take(MAX_LIGHTS).any(exact) {
        return lines;
    }
    let boxes = object_boxes(scene);
    for i in 0..scene.lights.len().min(MAX_LIGHTS) {
        let light = &scene.lights[i];
        if !exact(light) {
            continue;
        }
        let Some(b) = bounds_of(&boxes, light, height).filter(SmallAreaLight::is_small) else { continue };
        let size = match light.kind.size_names() {
            Some((_, Some(_))) => format!("{} × {} m", light.size[0], light.size[1]),
            Some((_, None)) => format!("{} m across", light.size[0]),
            None => continue,
        };
        lines.push(format!(
            "{} light L{}: {size}, {:.3} m from the nearest object, penumbra ≤ {:.2} px, highlight ≤ {:.2} px, r/d {:.2e}: drawn as a point light",
            light.kind.name(),
            i + 1,
            b.nearest,
            b.penumbra_px,
            b.highlight_px,
            b.radius_over_distance
        ));
        scene.lights[i].area_points = 1;
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Overrides;

    fn penumbra_with(size: f64) -> Scene {
        let mut s = crate::scene::penumbra_scene(0.5);
        s.apply(&Overrides { light_size: Some(size), ..Default::default() });
        s
    }

    #[test]
    fn a_tiny_light_is_drawn_as_a_point_and_says_why() {
        let mut s = penumbra_with(1e-4);
        let lines = draw_small_area_lights_as_points(&mut s, 720);
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert!(lines[0].starts_with("rect light L1: 0.0001 × 0.0001 m, ") && lines[0].ends_with("point light"));
        assert_eq!(s.lights[0].area_points, 1);
    }

    #[test]
    fn a_visible_light_keeps_its_area() {
        let mut s = penumbra_with(0.5);
        assert!(draw_small_area_lights_as_points(&mut s, 720).is_empty());
        assert_eq!(s.lights[0].area_points, 0);
        let b = small_area_light(&s, &s.lights[0], 720).unwrap();
        assert!(b.penumbra_px > 10.0 && b.highlight_px > 10.0, "{b:?}");
    }

    #[test]
    fn the_bounds_scale_with_size_and_resolution() {
        let s = penumbra_with(0.01);
        let at = |h| small_area_light(&s, &s.lights[0], h).unwrap();
        let (a, b) = (at(360), at(720));
        assert!(
            (b.penumbra_px / a.penumbra_px - 2.0).abs() < 1e-9 && (b.highlight_px / a.highlight_px - 2.0).abs() < 1e-9
        );
        let big = penumbra_with(0.02);
        let c = small_area_light(&big, &big.lights[0], 360).unwrap();
        assert!(c.highlight_px > 1.99 * a.highlight_px && c.penumbra_px > 2.0 * a.penumbra_px);
        // Without shadows there is no penumbra to show.
        let mut off = s.clone();
        off.set_shadows(false);
        assert_eq!(small_area_light(&off, &off.lights[0], 720).unwrap().penumbra_px, 0.0);
    }

    /// The camera decides nothing: near, far or orthographic, the bounds and the lights drawn
    /// stay; the image's height still scales them.
    #[test]
    fn the_camera_decides_nothing() {
        let s = penumbra_with(0.001);
        let at = |s: &Scene| small_area_light(s, &s.lights[0], 720).unwrap();
        let mut moved = s.clone();
        moved.camera.eye = moved.camera.target + (s.camera.eye - s.camera.target) * 0.05;
        let mut ortho = s.clone();
        ortho.camera.orthographic = Some(0.01);
        assert_eq!(at(&moved), at(&s));
        assert_eq!(at(&ortho), at(&s));
        let small = |s: &Scene, h| draw_small_area_lights_as_points(&mut s.clone(), h).len();
        assert_eq!((small(&s, 720), small(&moved, 720), small(&ortho, 720)), (1, 1, 1), "{:?}", at(&s));
        assert_eq!(small(&s, 100_000), 0, "at a height of 10⁵ pixels the light shows its area");
    }

    #[test]
    fn no_bound_when_an_object_touches_the_light() {
        let mut s = penumbra_with(0.01);
        s.lights[0].position = DVec3::new(0.0, 0.5, 0.0);
        let b = small_area_light(&s, &s.lights[0], 720).unwrap();
        assert!(b.penumbra_px.is_infinite() && !b.is_small());
    }
}
