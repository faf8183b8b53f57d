//! The viewer's "self-shadow boundary" switch, driven by egui_kittest on lavapipe: ticking it
//! draws the boundary edges over the view in the overlay colour.

use crate::harness::harness;
use egui_kittest::kittest::Queryable;

/// Pixels of the scene area (left of the panel) in the boundary's colour, saturated cyan.
fn boundary_pixels(image: &image::RgbaImage) -> usize {
    let view_width = image.width() * 6 / 10;
    (0..image.height())
        .flat_map(|y| (0..view_width).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let [r, g, b, _] = image.get_pixel(x, y).0;
            r < 30 && g > 230 && b > 230
        })
        .count()
}

#[test]
fn the_boundary_switch_draws_the_edges_over_the_view() {
    let mut h = harness();
    assert_eq!(h.state().self_shadow_boundary_edges(), 0);
    let off = h.render().expect("render");
    h.get_by_label("self-shadow boundary").click();
    h.run_steps(3);
    let edges = h.state().self_shadow_boundary_edges();
    // The default scene's two lights: a loop round each sphere, the cylinder's and the pyramid's.
    assert!(edges > 100, "{edges} edges");
    let on = h.render().expect("render");
    // Kept for a look: target/tmp/viewer-boundary.png.
    on.save(std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("viewer-boundary.png")).unwrap();
    let (before, after) = (boundary_pixels(&off), boundary_pixels(&on));
    assert!(before == 0 && after > 500, "boundary-coloured pixels: {before} off, {after} on");
    h.get_by_label("self-shadow boundary").click();
    h.run_steps(3);
    assert_eq!(h.state().self_shadow_boundary_edges(), 0);
}

/// Pixels of the scene area in saturated yellow (the vertex normals' colour).
fn normal_pixels(image: &image::RgbaImage) -> usize {
    let view_width = image.width() * 6 / 10;
    (0..image.height())
        .flat_map(|y| (0..view_width).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let [r, g, b, _] = image.get_pixel(x, y).0;
            r > 230 && g > 230 && b < 30
        })
        .count()
}

/// The "vertex normals" and "creases" switches draw their lines over the view, and stop.
#[test]
fn the_normals_and_creases_switches_draw_their_lines() {
    let mut h = harness();
    assert_eq!(h.state().mesh_line_counts(), (0, 0));
    let off = h.render().expect("render");
    h.get_by_label("vertex normals").click();
    h.get_by_label("creases").click();
    h.run_steps(3);
    let (normals, creases) = h.state().mesh_line_counts();
    // Every smooth vertex of the default scene (941), the cylinder's rims and the pyramid's
    // edges (40).
    assert!(normals > 500 && creases > 30, "{normals} normals, {creases} creases");
    let on = h.render().expect("render");
    let (before, after) = (normal_pixels(&off), normal_pixels(&on));
    assert!(before == 0 && after > 1000, "normal-coloured pixels: {before} off, {after} on");
    h.get_by_label("vertex normals").click();
    h.get_by_label("creases").click();
    h.run_steps(3);
    assert_eq!(h.state().mesh_line_counts(), (0, 0));
}
