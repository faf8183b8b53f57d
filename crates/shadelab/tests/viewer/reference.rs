//! The viewer's difference view while its reference is traced (docs/reference.md): on a worker,
//! on every core, a fiftieth of the rows a step, with the share traced on show.

use crate::common;
use crate::harness::{harness, run_until, wait_loaded};

/// Turned on, the difference view reports the share of its reference traced, within [0, 1],
/// until the error map with its numbers is in.
#[test]
fn the_difference_view_reports_how_far_its_reference_is() {
    let mut h = harness();
    assert_eq!(h.state().reference_progress(), None, "nothing traced before the view is on");
    h.state_mut().set_difference_view(true);
    let (mut seen, start) = (Vec::new(), std::time::Instant::now());
    let stats = loop {
        h.run_steps(1);
        seen.extend(h.state().reference_progress());
        if let Some(s) = h.state().difference() {
            break s;
        }
        assert!(start.elapsed().as_secs() < 60, "no reference after 60 s");
        std::thread::sleep(std::time::Duration::from_millis(5));
    };
    assert!(!seen.is_empty() && seen.iter().all(|p| (0.0..=1.0).contains(p)), "{seen:?}");
    assert!(seen.windows(2).all(|w| w[1] >= w[0]), "the share went back: {seen:?}");
    assert!(stats.rmse.is_finite() && stats.rmse > 0.0, "{stats:?}");
    assert_eq!(h.state().reference_progress(), None, "still tracing after the map is in");
}

/// The ambient error view traces the light between surfaces and shows the chapter's constant
/// ambient against it, with the I_a that fits: on the default scene the fit is dimmer than the
/// scene's grey I_a in green and blue, since the light between its surfaces is mostly the red
/// spheres' (docs/reference.md).
#[test]
fn the_ambient_error_view_fits_i_a() {
    let mut h = harness();
    h.state_mut().set_difference_view(true);
    h.state_mut().set_difference_kind(shadelab::viewer::difference::DifferenceKind::Ambient);
    let fit = run_until(&mut h, "ambient error map", 120, |v| v.ambient_fit());
    let stats = h.state().difference().expect("the map's numbers");
    assert!(stats.rmse.is_finite() && stats.rmse > fit.noise, "{stats:?} against noise {}", fit.noise);
    assert!(fit.scale > 0.0 && fit.noise > 0.0, "{fit:?}");
    assert!(fit.fitted[0] > fit.fitted[1] && fit.fitted[0] > fit.fitted[2], "the bounce is red: {fit:?}");
    assert!(fit.fitted[1] < fit.ambient[1] && fit.fitted[2] < fit.ambient[2], "{fit:?}");
}

/// A textured file has its difference view, and its numbers are the command line's: the map
/// measures the mode's own pipeline, built for it, not the uber pipeline that draws the view
/// while that one compiles (which measured RMSE 0.148 where `render --difference` gives 5.5e-4).
#[test]
fn a_textured_file_has_its_difference_view() {
    let file = common::root().join("../shared/gltf-samples/BoxTextured.gltf");
    let mut h = harness();
    h.state_mut().open_file(&file);
    wait_loaded(&mut h);
    let (msg, is_error) = h.state().message().cloned().expect("the file's message");
    assert!(!is_error && msg.contains("BoxTextured"), "{msg}");
    h.state_mut().set_difference_view(true);
    let stats = run_until(&mut h, "map", 120, |v| v.difference());
    assert!(stats.rmse < 2e-3 && stats.share_off < 0.01, "{stats:?}");
}

/// The FLIP map compares with the f64 twin or, chosen in the panel, with the path-traced truth
/// at the panel's vertices and paths: on the default scene the truth has the light between the
/// surfaces that the chapter's constant I_a stands for, so the GPU's image is further from it
/// than from its twin. The choice and the paths travel in the link.
#[test]
fn the_difference_view_compares_with_the_twin_or_the_truth() {
    use shadelab::viewer::difference::Against;
    let mut h = harness();
    h.state_mut().set_difference_view(true);
    h.run_steps(2);
    let twin = run_until(&mut h, "the map against the twin", 120, |v| v.difference());
    crate::harness::scroll_click(&mut h, "path-traced truth");
    assert_eq!(h.state().difference_view().against, Against::Truth);
    let query = "?scene=default&shading=phong&model=cook-torrance&difference=on&reference=truth&bounces=2&spp=8";
    let mut t = harness();
    t.state_mut().open_link(&shadelab::viewer::parse_query(query));
    let truth = run_until(&mut t, "the map against the truth", 120, |v| v.difference());
    eprintln!(
        "default scene, Phong shading: RMSE {:.3e} against the twin, {:.3e} against the truth",
        twin.rmse, truth.rmse
    );
    assert!(truth.rmse > 2.0 * twin.rmse, "twin {twin:?}, truth {truth:?}");
    assert_eq!(t.state().link("").0, query, "the link names the truth and its paths");
}
