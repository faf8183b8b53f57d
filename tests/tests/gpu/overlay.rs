//! The self-shadow boundary drawn over a render on lavapipe (`render --overlay terminator`): the
//! overlay changes the image only near the projected boundary edges, and an edge behind an
//! object is hidden.

use glam::DVec3;
use shadelab_model::scene::single_shape_scene;
use shadelab_model::terminator::scene_terminator;
use shadelab_model::{Camera, Shape};
use shadelab_render::overlay_pass::{TERMINATOR_COLOR, render_image_with_lines};
use shadelab_render::{LinearImage, RenderSettings, render_image};
use shadelab_tests::*;

const W: u32 = 480;
const H: u32 = 270;
/// How far (pixels) a changed pixel may lie from a projected edge: the lines are two pixels wide
/// (shifted by one pixel right and up) and rasterized within half a pixel of the exact line.
const NEAR_EDGE_PX: f64 = 2.5;

fn is_overlay(p: [f32; 4]) -> bool {
    (0..3).all(|c| p[c] == TERMINATOR_COLOR[c])
}

/// Distance from pixel centre `(x, y)` to the segment `a`–`b` in pixels.
fn distance_to_segment(x: f64, y: f64, a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((x - a.0) * dx + (y - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    ((x - a.0 - t * dx).powi(2) + (y - a.1 - t * dy).powi(2)).sqrt()
}

/// The segments `lines` projected to pixels: a pixel centre's distance to the nearest of them.
fn nearest_line_px(camera: &Camera, lines: &[[DVec3; 2]]) -> impl Fn(u32, u32) -> f64 {
    let projected: Vec<_> = lines.iter().map(|s| (project(camera, s[0], W, H), project(camera, s[1], W, H))).collect();
    move |x, y| {
        let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
        projected.iter().map(|&(a, b)| distance_to_segment(px, py, a, b)).fold(f64::MAX, f64::min)
    }
}

/// The pixels `(x, y, index)` where `drawn` differs from `plain`.
fn changed_pixels<'a>(plain: &'a LinearImage, drawn: &'a LinearImage) -> impl Iterator<Item = (u32, u32, usize)> + 'a {
    (0..H)
        .flat_map(|y| (0..W).map(move |x| (x, y, (y * W + x) as usize)))
        .filter(|&(_, _, i)| plain.pixels[i] != drawn.pixels[i])
}

fn overlay_pixels(image: &LinearImage) -> usize {
    image.pixels.iter().filter(|p| is_overlay(**p)).count()
}

#[test]
fn the_overlay_changes_only_pixels_near_the_projected_boundary() {
    let scenes = [shadelab_model::assets::figure_7_3_pyramid(), shadelab_model::scene::default_scene()];
    for scene in scenes {
        let settings = RenderSettings::default();
        let edges = scene_terminator(&scene);
        assert!(!edges.is_empty(), "{}", scene.name);
        let plain = render_image(gpu(), &scene, W, H, &settings).unwrap();
        let drawn = render_image_with_lines(gpu(), &scene, (W, H), &settings, &edges, TERMINATOR_COLOR).unwrap();
        let nearest = nearest_line_px(&scene.camera, &edges);
        let mut changed = 0;
        for (x, y, i) in changed_pixels(&plain, &drawn) {
            changed += 1;
            assert!(is_overlay(drawn.pixels[i]), "{}: ({x}, {y}) changed to another colour", scene.name);
            let near = nearest(x, y);
            assert!(near <= NEAR_EDGE_PX, "{}: ({x}, {y}) is {near:.1} px from every edge", scene.name);
        }
        assert!(changed > 0 && overlay_pixels(&drawn) >= changed, "{}: {changed} pixels changed", scene.name);
        assert_eq!(overlay_pixels(&plain), 0, "{}: the shading itself made the overlay colour", scene.name);
    }
}

#[test]
fn an_edge_behind_an_object_is_hidden() {
    // A line across the view behind the sphere (radius 1 at (0, 1, 0)), from one side to the other.
    let scene = single_shape_scene("sphere", Shape::Sphere, 32);
    let (a, b) = (DVec3::new(-3.0, 1.0, -2.0), DVec3::new(3.0, 1.0, -2.0));
    let image = render_image_with_lines(gpu(), &scene, (W, H), &RenderSettings::default(), &[[a, b]], TERMINATOR_COLOR)
        .unwrap();
    let cam: &Camera = &scene.camera;
    let count_near = |p: DVec3| {
        let (cx, cy) = project(cam, p, W, H);
        let mut n = 0;
        for y in (cy as i64 - 4).max(0)..(cy as i64 + 5).min(H as i64) {
            for x in (cx as i64 - 4).max(0)..(cx as i64 + 5).min(W as i64) {
                n += is_overlay(image.pixels[(y as u32 * W + x as u32) as usize]) as usize;
            }
        }
        n
    };
    assert_eq!(count_near(DVec3::new(0.0, 1.0, -2.0)), 0, "the line shows through the sphere");
    assert!(count_near(DVec3::new(-2.5, 1.0, -2.0)) > 0 && count_near(DVec3::new(2.5, 1.0, -2.0)) > 0);
}

/// Normals and creases over the cylinder (`render --overlay normals,creases`): both colours are
/// drawn, each only near its own lines, and the second set is depth-tested like the first (the
/// overlay passes keep the scene's depth).
#[test]
fn normals_and_creases_are_drawn_each_near_its_lines() {
    use shadelab_model::mesh_lines::{crease_segments, normal_segments};
    use shadelab_render::overlay_pass::{CREASES_COLOR, NORMALS_COLOR, render_image_with_line_sets};
    let scene = single_shape_scene("cylinder", Shape::Cylinder, 16);
    let settings = RenderSettings::default();
    let (normals, creases) = (normal_segments(&scene), crease_segments(&scene));
    assert_eq!(creases.len(), 32, "the cylinder's two rims");
    let plain = render_image(gpu(), &scene, W, H, &settings).unwrap();
    let sets = [(normals.as_slice(), NORMALS_COLOR), (creases.as_slice(), CREASES_COLOR)];
    let drawn = render_image_with_line_sets(gpu(), &scene, (W, H), &settings, &sets).unwrap();
    for (lines, color) in sets {
        let nearest = nearest_line_px(&scene.camera, lines);
        let mut count = 0;
        for (x, y, i) in changed_pixels(&plain, &drawn) {
            if (0..3).any(|c| drawn.pixels[i][c] != color[c]) {
                continue;
            }
            count += 1;
            let near = nearest(x, y);
            assert!(near <= NEAR_EDGE_PX, "{color:?}: ({x}, {y}) is {near:.1} px from its lines");
        }
        assert!(count > 200, "{color:?}: only {count} pixels drawn");
    }
}
