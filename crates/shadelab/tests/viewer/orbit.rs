//! Orbiting the view, driven by egui_kittest on lavapipe: the camera alone changes, so nothing is
//! derived, no pipeline is built and no shadow map is drawn again; a light moved redraws its maps.

use crate::harness::{ViewerHarness, changed_view_pixels, harness, orbit, run_until};

/// Frames of the orbit.
const ORBIT_FRAMES: u32 = 30;

/// The default scene with cast shadows from both lights (the sun's single map fitted to the
/// scene, not cascades fitted to the view), every pipeline built and the first frames drawn.
fn settled() -> ViewerHarness {
    let mut h = harness();
    h.state_mut().scene_mut().lights[0].shadow.cascades = false;
    h.run_steps(2);
    run_until(&mut h, "pipelines built", 120, |v| (!v.pipelines_building()).then_some(()));
    h.run_steps(3);
    assert!(h.state_mut().scene_mut().lights.iter().all(|l| l.shadow.casts), "both lights cast shadows");
    h
}

/// What the viewer has done so far: derivations, pipeline builds, shadow-map layers drawn.
fn counts(h: &ViewerHarness) -> (u64, u32, u64) {
    let v = h.state();
    (v.derivations(), v.pipeline_builds(), v.shadow_layer_draws())
}

#[test]
fn orbiting_derives_builds_and_draws_no_shadow_map() {
    let mut h = settled();
    let before_image = h.render().expect("render");
    let before = counts(&h);
    assert!(before.2 > 0, "the first frames drew the shadow maps");
    orbit(&mut h, ORBIT_FRAMES);
    let after = counts(&h);
    let changed = changed_view_pixels(&before_image, &h.render().expect("render"));
    assert!(changed > 1000, "the orbit turned the view: {changed} pixels changed");
    assert_eq!(after.0 - before.0, 0, "derivations while orbiting");
    assert_eq!(after.1 - before.1, 0, "pipeline builds while orbiting");
    assert_eq!(after.2 - before.2, 0, "shadow-map layers drawn while orbiting");
}

#[test]
fn moving_a_light_redraws_its_maps_and_a_material_none() {
    let mut h = settled();
    let before = counts(&h).2;
    // A material's roughness: the maps hold depths only, nothing to draw again.
    h.state_mut().scene_mut().materials[0].m = 0.123;
    h.run_steps(2);
    assert_eq!(counts(&h).2, before, "a material change redrew shadow maps");
    // The point light (L2) moved: its six cube faces, and not the sun's map.
    h.state_mut().scene_mut().lights[1].position.x += 0.5;
    h.run_steps(2);
    assert_eq!(counts(&h).2 - before, 6, "moving the point light redraws its six faces alone");
}
