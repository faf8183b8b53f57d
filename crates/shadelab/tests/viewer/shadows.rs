//! The viewer's shadow views, driven by egui_kittest on lavapipe: a light's shadow map shown in
//! its panel section, and the difference view's shadow error map with its shares.

use crate::harness::{click, harness, keep_for_a_look, run_until, scroll_click, scroll_to};
use egui_kittest::kittest::Queryable;
use shadelab_model::shadows::SHADOW_RESOLUTION;

/// The most of the default scene's pixels whose lit/shadowed state may disagree with the
/// reference: its shadows' edges, one map texel wide, at the difference view's 480 px width.
const DEFAULT_SCENE_SHADOW_DISAGREEMENT_MAX: f64 = 0.05;

#[test]
fn the_show_shadow_map_box_shows_l1s_map_in_its_section() {
    let mut h = harness();
    assert!(h.query_by_label("show shadow map").is_none(), "collapsed sections show no map controls");
    // The light's header may be below the panel's fold: scroll to it first.
    scroll_click(&mut h, "L1 — directional");
    assert_eq!(h.state().shadow_map_shown(0), None);
    // The box is below the panel's fold: scroll to it first.
    scroll_to(&mut h, "show shadow map");
    h.get_by_label("show shadow map").click();
    let [w, hgt] = run_until(&mut h, "shadow map", 90, |v| v.shadow_map_shown(0));
    let asked = h.state_mut().scene_mut().lights[0].shadow.resolution as usize;
    // Square, a power of two within the declared range, at most what L1 asks for (the memory
    // budget may halve it).
    assert_eq!(w, hgt);
    assert!(w.is_power_of_two() && w <= asked && w >= SHADOW_RESOLUTION.min as usize, "{w} × {hgt} for {asked}");
    let shot = h.render().expect("render");
    keep_for_a_look(&shot, "viewer-shadow-map.png");
    click(&mut h, "show shadow map");
    assert_eq!(h.state().shadow_map_shown(0), None);
}

#[test]
fn the_shadow_error_map_reports_a_small_disagreement_on_the_default_scene() {
    let mut h = harness();
    click(&mut h, "difference from reference");
    h.get_by_label("shadow error").click();
    let s = run_until(&mut h, "shadow comparison", 90, |v| v.shadow_difference());
    assert!(s.share_disagreeing.is_finite(), "{s:?}");
    assert!(s.share_disagreeing < DEFAULT_SCENE_SHADOW_DISAGREEMENT_MAX, "{s:?}");
    assert!(s.share_shadowed_reference > 0.0, "the default scene has cast shadows: {s:?}");
    assert!((s.share_false_shadow + s.share_missed_shadow - s.share_disagreeing).abs() < 1e-12, "{s:?}");
    assert!(h.state().difference().is_some(), "the FLIP numbers stay beside the shadow shares");
    h.run_steps(2);
    let shot = h.render().expect("render");
    keep_for_a_look(&shot, "viewer-shadow-error.png");
    // Back to the FLIP map: no shadow numbers.
    h.get_by_label("FLIP error").click();
    run_until(&mut h, "FLIP map", 90, |v| v.difference());
    assert!(h.state().shadow_difference().is_none());
}

#[test]
fn a_point_lights_map_shows_a_cube_face_with_a_face_menu() {
    let mut h = harness();
    // Below the panel's fold: scroll to it first.
    scroll_click(&mut h, "L2 — point");
    h.state_mut().set_shadow_map_view(1, true);
    let [w, hgt] = run_until(&mut h, "cube face", 90, |v| v.shadow_map_shown(1));
    assert_eq!(w, hgt);
    scroll_to(&mut h, "show shadow map");
    assert!(h.query_by_value("face +x").is_some(), "the point light's map has a face menu");
}

/// On a scene large relative to the view the sun's map has cascades: the panel offers a cascade
/// menu, and the second cascade is read back when chosen.
#[test]
fn a_directional_lights_cascades_have_a_menu() {
    let mut h = harness();
    let field = shadelab_model::Scene::builtin("field").expect("built-in");
    let loaded = shadelab_model::gltf_io::LoadedScene {
        scene: field,
        settings: Default::default(),
        warnings: Vec::new(),
        cameras: Vec::new(),
    };
    h.state_mut().show_loaded(loaded, "field").expect("shown");
    h.run_steps(2);
    // The light's header may be below the panel's fold: scroll to it first.
    scroll_click(&mut h, "L1 — directional");
    h.state_mut().set_shadow_map_view(0, true);
    run_until(&mut h, "first cascade", 90, |v| v.shadow_map_shown(0));
    scroll_to(&mut h, "show shadow map");
    assert!(h.query_by_value("cascade 1").is_some(), "the sun's map has a cascade menu");
    h.get_by_value("cascade 1").click();
    h.run_steps(2);
    click(&mut h, "cascade 2");
    run_until(&mut h, "second cascade", 90, |v| v.shadow_map_shown(0));
    assert!(h.query_by_value("cascade 2").is_some(), "the menu shows the chosen cascade");
}
