//! The viewer's "self-shadow boundary" switch, driven by egui_kittest on lavapipe: ticking it
//! draws the boundary edges over the view in the overlay colour.

use crate::harness::{click, harness, keep_for_a_look, view_pixels_where};
use egui_kittest::kittest::Queryable;

/// Pixels of the scene area (left of the panel) in the boundary's colour, saturated cyan.
fn boundary_pixels(image: &image::RgbaImage) -> usize {
    view_pixels_where(image, |[r, g, b]| r < 30 && g > 230 && b > 230)
}

#[test]
fn the_boundary_switch_draws_the_edges_over_the_view() {
    let mut h = harness();
    assert_eq!(h.state().self_shadow_boundary_edges(), 0);
    let off = h.render().expect("render");
    click(&mut h, "self-shadow boundary");
    let edges = h.state().self_shadow_boundary_edges();
    // The default scene's two lights: a loop round each sphere, the cylinder's and the pyramid's.
    assert!(edges > 100, "{edges} edges");
    let on = h.render().expect("render");
    keep_for_a_look(&on, "viewer-boundary.png");
    let (before, after) = (boundary_pixels(&off), boundary_pixels(&on));
    assert!(before == 0 && after > 500, "boundary-coloured pixels: {before} off, {after} on");
    click(&mut h, "self-shadow boundary");
    assert_eq!(h.state().self_shadow_boundary_edges(), 0);
}

/// Pixels of the scene area in saturated yellow (the vertex normals' colour).
fn normal_pixels(image: &image::RgbaImage) -> usize {
    view_pixels_where(image, |[r, g, b]| r > 230 && g > 230 && b < 30)
}

/// The "vertex normals" and "creases" switches draw their lines over the view, and stop.
#[test]
fn the_normals_and_creases_switches_draw_their_lines() {
    let mut h = harness();
    assert_eq!(h.state().mesh_line_counts(), (0, 0));
    let off = h.render().expect("render");
    h.get_by_label("vertex normals").click();
    click(&mut h, "creases");
    let (normals, creases) = h.state().mesh_line_counts();
    // Every smooth vertex of the default scene (941), the cylinder's rims and the pyramid's
    // edges (40).
    assert!(normals > 500 && creases > 30, "{normals} normals, {creases} creases");
    let on = h.render().expect("render");
    let (before, after) = (normal_pixels(&off), normal_pixels(&on));
    assert!(before == 0 && after > 1000, "normal-coloured pixels: {before} off, {after} on");
    h.get_by_label("vertex normals").click();
    click(&mut h, "creases");
    assert_eq!(h.state().mesh_line_counts(), (0, 0));
}
