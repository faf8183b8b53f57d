//! The viewer's area lights, driven by egui_kittest on lavapipe: a light too small on screen is
//! drawn as a point light and the panel says why; a light as k point sources draws with its slider;
//! the light's specular choice switches to the LTC.

use crate::harness::{click, harness_of_height, keep_for_a_look, scroll_click};
use egui_kittest::kittest::Queryable;
use shadelab_model::{AreaSpecular, LightKind, Overrides};

#[test]
fn a_small_area_light_is_a_point_light_and_the_panel_says_why() {
    let mut h = harness_of_height(900.0);
    let tiny = Overrides { light: Some(LightKind::Rect), light_size: Some(0.001), ..Default::default() };
    h.state_mut().scene_mut().apply(&tiny);
    h.run_steps(3);
    let lines = h.state().small_area_lights().to_vec();
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(lines.iter().all(|l| l.starts_with("rect light L") && l.ends_with("drawn as a point light")));
    assert!(h.query_by_label(&lines[0]).is_some(), "the panel shows '{}'", lines[0]);
    // The scene itself keeps its area lights: the rule applies to each frame, not to the edits.
    assert!(h.state_mut().scene_mut().lights.iter().all(|l| l.area_points == 0));
    // A light large enough to show its area keeps it, and the lines go.
    let large = Overrides { light_size: Some(0.5), ..Default::default() };
    h.state_mut().scene_mut().apply(&large);
    h.run_steps(3);
    assert!(h.state().small_area_lights().is_empty());
    assert!(h.query_by_label(&lines[0]).is_none());
}

/// The viewer with `overrides` applied to its scene and the first light's section (`label`)
/// opened in the panel.
fn with_first_light_open(overrides: &Overrides, label: &str) -> crate::harness::ViewerHarness {
    let mut h = harness_of_height(900.0);
    h.state_mut().scene_mut().apply(overrides);
    h.run_steps(2);
    click(&mut h, label);
    h
}

#[test]
fn a_light_as_point_sources_has_its_slider_and_draws() {
    let points = Overrides { light: Some(LightKind::Disk), area_points: Some(4), ..Default::default() };
    let mut h = with_first_light_open(&points, "L1 — disk");
    assert!(h.query_all_by_label("points k (0 = exact)").next().is_some(), "the light's section has the k slider");
    assert!(h.state().message().is_none_or(|(_, error)| !error), "{:?}", h.state().message());
    let shot = h.render().expect("render");
    keep_for_a_look(&shot, "viewer-area-points.png");
}

#[test]
fn the_light_panels_ltc_choice_redraws_the_highlight() {
    let rect = Overrides { light: Some(LightKind::Rect), light_size: Some(1.0), ..Default::default() };
    let mut h = with_first_light_open(&rect, "L1 — rect");
    let before = h.render().expect("render");
    click(&mut h, "LTC");
    h.run_steps(2);
    assert_eq!(h.state_mut().scene_mut().lights[0].area_specular, AreaSpecular::Ltc);
    assert!(h.state().message().is_none_or(|(_, error)| !error), "{:?}", h.state().message());
    // Under Cook–Torrance (the viewer's default) the effect is on, and the list of effects says so.
    scroll_click(&mut h, "effects called for");
    assert!(
        h.query_by_label_contains("specular by LTC: on — rect light L1").is_some(),
        "the effects list names the LTC and the light that asks for it"
    );
    let after = h.render().expect("render");
    assert!(before.as_raw() != after.as_raw(), "the highlight is drawn another way");
    keep_for_a_look(&after, "viewer-area-ltc.png");
}
