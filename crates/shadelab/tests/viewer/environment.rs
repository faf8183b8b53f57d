//! The viewer's environment section (docs/environment.md), driven by egui_kittest on lavapipe:
//! the sky takes I_amb's place and changes the image, its occlusion and split sum are switched,
//! its specular is shown alone, and "none" gives I_amb back.

use crate::harness::{ViewerHarness, changed_view_pixels, click, harness, scroll_click, scroll_to};
use egui_kittest::kittest::Queryable;
use shadelab_model::lighting::env_map::EnvSource;

/// Open the environment menu and pick `item`.
fn choose(h: &mut ViewerHarness, item: &str) {
    scroll_click(h, "environment");
    click(h, item);
}

#[test]
fn the_sky_replaces_the_ambient_and_none_gives_it_back() {
    let mut h = harness();
    let ambient = h.state_mut().scene_mut().ambient;
    scroll_click(&mut h, "environment light");
    let before = h.render().expect("render");
    choose(&mut h, "sky (Preetham)");
    let scene = h.state_mut().scene_mut().clone();
    assert!(matches!(scene.environment.as_ref().map(|e| &e.source), Some(EnvSource::Sky { .. })));
    assert_eq!(scene.ambient, [0.0; 3]);
    let after = h.render().expect("render");
    if let Ok(dir) = std::env::var("SHADELAB_VIEWER_SHOTS") {
        after.save(std::path::Path::new(&dir).join("viewer-environment.png")).unwrap();
    }
    let changed = changed_view_pixels(&before, &after);
    assert!(changed > 2000, "only {changed} pixels of the view changed");
    // The occlusion darkens the contacts; the split sum's checkbox takes the specular away.
    scroll_to(&mut h, "occlusion (precomputed grid)");
    h.get_by_label("occlusion (precomputed grid)").click();
    h.run_steps(3);
    assert!(h.state_mut().scene_mut().environment.as_ref().is_some_and(|e| e.occlusion));
    let occluded = h.render().expect("render");
    let changed = changed_view_pixels(&after, &occluded);
    assert!(changed > 200, "the occlusion changed only {changed} pixels of the view");
    // The term row offers the environment's specular alone: only its reflections stay.
    scroll_click(&mut h, "I_env,s");
    let env_specular = h.render().expect("render");
    let changed = changed_view_pixels(&occluded, &env_specular);
    assert!(changed > 20000, "the environment's specular alone changed only {changed} pixels");
    click(&mut h, "all");
    scroll_to(&mut h, "specular (split sum)");
    h.get_by_label("specular (split sum)").click();
    h.run_steps(3);
    assert!(h.state_mut().scene_mut().environment.as_ref().is_some_and(|e| !e.specular));
    // As the background, the sky fills the view's empty top.
    let plain = h.render().expect("render");
    click(&mut h, "show as the background");
    assert!(h.state_mut().scene_mut().environment.as_ref().is_some_and(|e| e.background));
    let behind = h.render().expect("render");
    let changed = changed_view_pixels(&plain, &behind);
    assert!(changed > 5000, "the background changed only {changed} pixels of the view");
    choose(&mut h, "none (the constant I_amb)");
    let scene = h.state_mut().scene_mut().clone();
    assert_eq!((scene.environment, scene.ambient), (None, ambient));
    assert!(h.query_by_label("I_env,s").is_none(), "no environment, no term of its own");
}

/// An `.hdr` or `.exr` opened from the files row lights the scene on show by that map, in place
/// of I_amb; a broken one is one line on the panel and the scene keeps its light.
#[test]
fn a_map_file_opens_as_the_environment() {
    use shadelab_model::lighting::env_map::EnvImage;
    let dir = std::env::temp_dir().join(format!("shadelab-viewer-map-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let img = EnvImage { name: "sky".into(), width: 8, height: 4, texels: vec![[0.5, 0.6, 0.9]; 32] };
    let map = dir.join("sky.exr");
    std::fs::write(&map, shadelab_model::lighting::env_file::write_env_exr(&img).unwrap()).unwrap();
    let mut h = harness();
    let objects = h.state_mut().scene_mut().objects.len();
    h.state_mut().open_file(&map);
    h.run_steps(3);
    let scene = h.state_mut().scene_mut().clone();
    let Some(EnvSource::Image(read)) = scene.environment.as_ref().map(|e| &e.source) else {
        panic!("no map: {:?}", scene.environment)
    };
    assert_eq!((read.width, read.height, scene.ambient, scene.objects.len()), (8, 4, [0.0; 3], objects));
    let broken = dir.join("broken.hdr");
    std::fs::write(&broken, b"not a map").unwrap();
    h.state_mut().open_file(&broken);
    h.run_steps(3);
    let (said, error) = h.state().message().cloned().expect("a message");
    assert!(error && said.contains("broken.hdr") && !said.contains('\n'), "{said}");
    assert!(matches!(h.state_mut().scene_mut().environment.as_ref().map(|e| &e.source), Some(EnvSource::Image(_))));
    std::fs::remove_dir_all(&dir).unwrap();
}
