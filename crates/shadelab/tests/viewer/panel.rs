//! The viewer driven by egui_kittest on lavapipe (wgpu): what a person sees and clicks.

use crate::common;
use crate::harness::{
    ViewerHarness, changed_view_pixels, click, harness, keep_for_a_look, orbit, run_until, scroll_click,
    scroll_to_containing, wait_loaded,
};
use egui_kittest::kittest::Queryable;
use shadelab_model::{ShadingMode, SpecularModel};

#[test]
fn snapshot_of_panel_and_view() {
    let mut h = harness();
    h.state_mut().show_live_numbers = false; // they differ every run
    h.run_steps(2);
    // The golden is tests/snapshots/viewer_default.png; UPDATE_SNAPSHOTS=1 regenerates it.
    h.snapshot("viewer_default");
}

#[test]
fn clicking_the_specular_model_changes_the_image() {
    let mut h = harness();
    assert_eq!(h.state().settings().specular, SpecularModel::CookTorrance);
    let before = h.render().expect("render");
    h.get_by_label("Phong (V·R)^h").click();
    h.run_steps(3);
    assert_eq!(h.state().settings().specular, SpecularModel::Phong);
    let after = h.render().expect("render");
    let changed = changed_view_pixels(&before, &after);
    // Phong specular lights up the rough spheres' highlights and whitens the gold's.
    assert!(changed > 2000, "only {changed} pixels of the view changed");
}

/// The Cook–Torrance terms section: "all gltf" gives every material glTF's terms and changes the
/// image; the selected material's D menu switches its D alone, live.
#[test]
fn the_terms_section_switches_each_term_live() {
    use shadelab_model::lighting::microfacet::{Distribution, Microfacet};
    let mut h = harness();
    let before = h.render().expect("render");
    scroll_to_containing(&mut h, "Cook–Torrance terms");
    h.get_by_label_contains("Cook–Torrance terms").click();
    h.run_steps(3);
    click(&mut h, "all gltf");
    let materials = h.state_mut().scene_mut().materials.clone();
    assert!(materials.iter().all(|m| m.microfacet == Microfacet::GLTF));
    // The header names a preset by its name, short enough to keep the panel's width.
    assert!(h.query_by_label("Cook–Torrance terms: gltf").is_some());
    let after = h.render().expect("render");
    let changed = changed_view_pixels(&before, &after);
    assert!(changed > 2000, "only {changed} pixels of the view changed");
    click(&mut h, "all chapter");
    click(&mut h, "D");
    click(&mut h, "ggx");
    let materials = h.state_mut().scene_mut().materials.clone();
    let ggx: Vec<bool> = materials.iter().map(|m| m.microfacet.d == Distribution::Ggx).collect();
    assert_eq!(ggx.iter().filter(|g| **g).count(), 1, "{ggx:?}");
    click(&mut h, "multiple scattering");
    let materials = h.state_mut().scene_mut().materials.clone();
    assert_eq!(materials.iter().filter(|m| m.microfacet.multiple_scattering).count(), 1);
    h.get_by_label("diffuse × (1 − F)").click();
    h.run_steps(3);
    let materials = h.state_mut().scene_mut().materials.clone();
    assert_eq!(materials.iter().filter(|m| m.microfacet.fresnel_mix).count(), 1);
}

/// The h row's "normalized" box scales the selected material's Phong lobe: with Phong specular
/// its highlights brighten.
#[test]
fn the_normalized_box_brightens_phongs_highlights() {
    let mut h = harness();
    h.get_by_label("Phong (V·R)^h").click();
    h.run_steps(3);
    let before = h.render().expect("render");
    click(&mut h, "normalized");
    let materials = h.state_mut().scene_mut().materials.clone();
    assert_eq!(materials.iter().filter(|m| m.phong_normalized).count(), 1);
    let after = h.render().expect("render");
    let changed = changed_view_pixels(&before, &after);
    assert!(changed > 200, "only {changed} pixels of the view changed");
}

/// The term row shows one term of the model alone; "all" brings the whole model back, and the
/// scene's own coefficients are untouched by the view.
#[test]
fn the_term_row_shows_one_term_alone() {
    let mut h = harness();
    let before = h.render().expect("render");
    let r_s: Vec<f64> = h.state_mut().scene_mut().materials.iter().map(|m| m.r_s).collect();
    click(&mut h, "I_s");
    let specular = h.render().expect("render");
    // Without ambient and diffuse light only the highlights stay: most of the view darkens.
    let changed = changed_view_pixels(&before, &specular);
    assert!(changed > 20000, "only {changed} pixels of the view changed");
    let after: Vec<f64> = h.state_mut().scene_mut().materials.iter().map(|m| m.r_s).collect();
    assert_eq!(r_s, after, "the view's term does not change the scene");
    click(&mut h, "all");
    let back = h.render().expect("render");
    assert_eq!(changed_view_pixels(&before, &back), 0, "all: the whole model again");
}

#[test]
fn keyboard_shortcuts_switch_modes() {
    let mut h = harness();
    let phong = h.render().expect("render");
    h.key_press(egui::Key::Num1);
    h.run_steps(2);
    assert_eq!(h.state().settings().shading, ShadingMode::Flat);
    let flat = h.render().expect("render");
    assert!(changed_view_pixels(&phong, &flat) > 2000);
    h.key_press(egui::Key::Num2);
    h.run_steps(2);
    assert_eq!(h.state().settings().shading, ShadingMode::Gouraud);
    h.key_press(egui::Key::S);
    h.run_steps(2);
    assert_eq!(h.state().settings().specular, SpecularModel::Phong);
}

#[test]
fn parameter_changes_never_rebuild_pipelines() {
    let mut h = harness();
    let builds = h.state().pipeline_builds();
    let first = h.render().expect("render");
    for i in 1..=8 {
        let scene = h.state_mut().scene_mut();
        for mat in &mut scene.materials {
            mat.m = 0.1 * i as f64;
        }
        scene.lights[0].intensity = 0.2 * i as f64;
        h.run_steps(1);
    }
    assert_eq!(h.state().pipeline_builds(), builds, "a parameter change rebuilt a pipeline");
    assert!(changed_view_pixels(&first, &h.render().expect("render")) > 1000, "the parameters had no effect");
}

#[test]
fn a_broken_shader_on_hot_reload_keeps_the_old_pipeline_and_shows_nagas_message() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("hot-reload-shaders");
    std::fs::create_dir_all(&dir).unwrap();
    let shipped = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shaders");
    for (name, _) in shadelab_render::shaders::FILES {
        std::fs::copy(shipped.join(name), dir.join(name)).unwrap();
    }
    let mut h = harness();
    h.state_mut().shader_dir = Some(dir.clone());
    h.run_steps(2);
    assert_eq!(h.state().message().map(|m| m.1), Some(false), "{:?}", h.state().message());
    let good = h.render().expect("render");
    let builds = h.state().pipeline_builds();

    // Break brdf.wgsl: a call to a function that does not exist.
    let brdf = std::fs::read_to_string(dir.join("brdf.wgsl")).unwrap();
    std::thread::sleep(std::time::Duration::from_millis(20));
    std::fs::write(dir.join("brdf.wgsl"), brdf.replace("max(n_dot_l, 0.0)", "maximum(n_dot_l, 0.0)")).unwrap();
    h.state_mut().poll_shaders();
    h.run_steps(2);
    let (msg, is_error) = h.state().message().cloned().expect("a message");
    assert!(is_error && msg.contains("maximum"), "{msg}");
    assert_eq!(h.state().pipeline_builds(), builds, "the old pipeline must stay");
    assert_eq!(changed_view_pixels(&good, &h.render().expect("render")), 0, "the picture must not change");

    // Fixed again: reloaded, pipelines rebuilt once.
    std::thread::sleep(std::time::Duration::from_millis(20));
    std::fs::write(dir.join("brdf.wgsl"), brdf).unwrap();
    h.state_mut().poll_shaders();
    h.run_steps(2);
    assert_eq!(h.state().message().map(|m| m.1), Some(false), "{:?}", h.state().message());
    assert!(h.state().pipeline_builds() > builds);
}

#[test]
fn resizing_to_nothing_and_back_does_not_crash() {
    let mut h = harness();
    for size in [egui::vec2(0.0, 0.0), egui::vec2(1.0, 1.0), egui::vec2(300.0, 0.0), egui::vec2(1100.0, 640.0)] {
        h.set_size(size);
        h.run_steps(2);
    }
    let img = h.render().expect("render");
    assert!(changed_view_pixels(&img, &image::RgbaImage::new(img.width(), img.height())) > 10_000);
}

/// The "difference from reference" view: once the f64 reference is in, the view shows the FLIP
/// map with its numbers; switching to flat shading (same reference, new render) raises the error.
#[test]
fn difference_from_reference_view() {
    let mut h = harness();
    let normal = h.render().expect("render");
    h.get_by_label("difference from reference").click();
    let wait = |h: &mut ViewerHarness| run_until(h, "reference", 60, |v| v.difference());
    let phong = wait(&mut h);
    assert!(phong.flip_mean > 0.0 && phong.rmse > 0.0 && phong.rmse.is_finite(), "{phong:?}");
    let map = h.render().expect("render");
    assert!(changed_view_pixels(&normal, &map) > 20_000, "the error map replaces the render");
    h.key_press(egui::Key::Num1);
    let flat = wait(&mut h);
    assert_eq!(h.state().settings().shading, ShadingMode::Flat);
    assert!(flat.rmse > phong.rmse * 1.5, "flat {flat:?} vs phong {phong:?}");
}

/// Opening glTF files in the viewer: a broken file shows the loader's one-line error and keeps
/// the scene; a good one replaces it; "save scene" writes a file that opens to the same scene.
#[test]
fn open_and_save_scene_files() {
    let mut h = harness();
    let before = h.state_mut().scene_mut().clone();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    h.state_mut().open_file(&root.join("tests/gltf-corpus/index-past-vertex-count.gltf"));
    wait_loaded(&mut h);
    let (msg, is_error) = h.state().message().cloned().expect("a message");
    assert!(is_error && msg.contains("index-past-vertex-count.gltf") && !msg.contains('\n'), "{msg}");
    assert_eq!(*h.state_mut().scene_mut(), before, "a bad file leaves the scene as it was");
    h.state_mut().open_file(&root.join("assets/material-board.gltf"));
    wait_loaded(&mut h);
    assert!(!h.state().message().unwrap().1, "{:?}", h.state().message());
    let board = h.state_mut().scene_mut().clone();
    assert_ne!(board, before);
    let out = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("viewer-saved.gltf");
    h.state_mut().save_scene(&out);
    let saved = shadelab_model::gltf_io::load_scene(&out).expect("saved scene loads");
    assert_eq!(saved.scene.objects, board.objects);
    assert_eq!(saved.scene.materials, board.materials);
    assert_eq!(saved.scene.lights, board.lights);
}

/// "open…" and "save as…" ask the file picker (the native dialog in the real viewer, a stand-in
/// here) on a worker thread, then open or save what it answers; no answer changes nothing.
#[test]
fn file_dialog_buttons_open_and_save_the_chosen_file() {
    use shadelab::viewer::FileRequest;
    use std::sync::{Arc, Mutex};
    let mut h = harness();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let out = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("viewer-dialog-saved.glb");
    let _ = std::fs::remove_file(&out);
    let asked: Arc<Mutex<Vec<FileRequest>>> = Arc::default();
    let answer: Arc<Mutex<Option<std::path::PathBuf>>> = Arc::default();
    let (a, b) = (asked.clone(), answer.clone());
    h.state_mut().file_picker = Arc::new(move |req| {
        a.lock().unwrap().push(req);
        b.lock().unwrap().clone()
    });
    // Frames until the panel's message changes (the picker answers on a worker thread).
    let wait = |h: &mut ViewerHarness| {
        let before = h.state().message().cloned();
        for _ in 0..100 {
            h.run_steps(1);
            if h.state().message().cloned() != before {
                return;
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
    };
    // Closing the dialog: nothing changes, and the panel says so.
    let before = h.state_mut().scene_mut().clone();
    h.get_by_label("open…").click();
    wait(&mut h);
    let (msg, is_error) = h.state().message().cloned().expect("a message");
    assert!(!is_error && msg.contains("no file chosen"), "{msg}");
    assert_eq!(*h.state_mut().scene_mut(), before);
    // Choosing a file opens it.
    *answer.lock().unwrap() = Some(root.join("assets/figure-7-3-pyramid.gltf"));
    h.get_by_label("open…").click();
    wait(&mut h);
    let (msg, is_error) = h.state().message().cloned().expect("a message");
    assert!(!is_error && msg.contains("opened") && msg.contains("figure-7-3-pyramid.gltf"), "{msg}");
    let pyramid = h.state_mut().scene_mut().clone();
    assert_ne!(pyramid, before);
    assert!(h.state().file_field.ends_with("figure-7-3-pyramid.gltf"));
    // "save as…" writes where the dialog says.
    *answer.lock().unwrap() = Some(out.clone());
    h.get_by_label("save as…").click();
    wait(&mut h);
    let (msg, is_error) = h.state().message().cloned().expect("a message");
    assert!(!is_error && msg.starts_with("saved"), "{msg}");
    let saved = shadelab_model::gltf_io::load_scene(&out).expect("the saved scene loads");
    assert_eq!(saved.scene.objects, pyramid.objects);
    assert_eq!(*asked.lock().unwrap(), [FileRequest::Open, FileRequest::Open, FileRequest::Save]);
}

/// A file with several cameras gets a camera menu; choosing one looks through it.
#[test]
fn a_files_cameras_are_offered_in_a_menu() {
    let mut h = harness();
    let path = common::two_camera_scene(std::path::Path::new(env!("CARGO_TARGET_TMPDIR")), "viewer-two-cameras.gltf");
    // The built-in scene has one camera: no menu.
    assert!(h.query_by_label("from above").is_none());
    h.state_mut().open_file(&path);
    wait_loaded(&mut h);
    h.run_steps(3);
    let before = h.render().expect("render");
    let eye = h.state_mut().scene_mut().camera.eye;
    click(&mut h, "camera");
    click(&mut h, "from above");
    let after_eye = h.state_mut().scene_mut().camera.eye;
    assert!((after_eye - glam::DVec3::new(0.0, 8.0, 0.0)).length() < 1e-5, "{eye} -> {after_eye}");
    let after = h.render().expect("render");
    assert!(changed_view_pixels(&before, &after) > 5000);
}

/// A light made a spot light in the panel lights only its cone, and the panel offers its cones.
#[test]
fn a_light_can_become_a_spot_light_in_the_panel() {
    let mut h = harness();
    let before = h.render().expect("render");
    // Below the panel's fold: scroll to it first.
    scroll_click(&mut h, "L2 — point");
    let shown = |h: &ViewerHarness, label: &str| h.query_all_by_label(label).next().is_some();
    assert!(!shown(&h, "outer cone °"));
    scroll_click(&mut h, "spot");
    let l = h.state_mut().scene_mut().lights[1].clone();
    assert_eq!(l.kind, shadelab_model::LightKind::Spot);
    assert_eq!(l.outer_cone, shadelab_model::scene::SPOT_OUTER_CONE_DEFAULT);
    assert!(shown(&h, "outer cone °") && shown(&h, "inner cone °"));
    let after = h.render().expect("render");
    // Outside its 45° cone the point light's share is gone: the ground's edges darken.
    assert!(changed_view_pixels(&before, &after) > 2000, "{}", changed_view_pixels(&before, &after));
}

/// A light's "casts shadows" box in its panel section switches that light's shadows, and only its.
#[test]
fn a_lights_casts_shadows_box_switches_its_shadows() {
    let mut h = harness();
    let before = h.state_mut().scene_mut().lights.clone();
    assert!(before.iter().all(|l| l.shadow.casts));
    // Collapsed sections show no shadow controls.
    assert!(h.query_by_label("casts shadows").is_none());
    scroll_click(&mut h, "L1 — directional");
    // The box may be below the panel's fold: scroll to it first.
    scroll_click(&mut h, "casts shadows");
    let after = h.state_mut().scene_mut().lights.clone();
    assert!(!after[0].shadow.casts, "the box did not switch L1's shadows off");
    assert_eq!(
        (after[0].shadow.resolution, after[0].shadow.filter),
        (before[0].shadow.resolution, before[0].shadow.filter)
    );
    assert_eq!(after[1..], before[1..], "another light changed");
    click(&mut h, "casts shadows");
    assert!(h.state_mut().scene_mut().lights[0].shadow.casts);
}

/// The model row switches among the chapter's four models: the Lambert rule changes the image,
/// leaves the specular row for the Phong model, and the four-term sum puts the chapter's
/// 1/(d + d0) on the point light; the term row offers the model's own terms, and V shows the
/// cast-shadow factor in place of the frame.
#[test]
fn the_model_row_switches_models_and_v_shows_the_shadow_factor() {
    use shadelab_model::{FalloffForm, IlluminationModel, LightKind};
    let mut h = harness();
    let before = h.render().expect("render");
    let pick = |h: &mut ViewerHarness, label: &str| {
        click(h, "model");
        click(h, label);
    };
    pick(&mut h, "Lambert rule");
    h.run_steps(3);
    assert_eq!(h.state_mut().scene_mut().illumination, IlluminationModel::Lambert);
    let lambert = h.render().expect("render");
    let changed = changed_view_pixels(&before, &lambert);
    assert!(changed > 20000, "only {changed} pixels of the view changed");
    assert!(h.query_by_label("I_s").is_none(), "the Lambert rule has no specular term");
    pick(&mut h, "four-term sum");
    let scene = h.state_mut().scene_mut().clone();
    assert_eq!(scene.illumination, IlluminationModel::Sum);
    assert!(
        scene.lights.iter().filter(|l| l.kind != LightKind::Directional).all(|l| l.falloff_form == FalloffForm::Linear)
    );
    click(&mut h, "I_r");
    pick(&mut h, "Cook–Torrance model");
    assert_eq!(h.state().settings().specular, SpecularModel::CookTorrance);
    assert_eq!(h.state_mut().scene_mut().illumination, IlluminationModel::Phong);
    assert!(h.query_by_label("I_r").is_none() && h.query_by_label("I_t").is_none());
    click(&mut h, "V");
    assert!(h.state().shadow_factor_size().is_some(), "the factor image is drawn");
    let v = h.render().expect("render");
    // Grey: the view's pixels have equal channels where the factor image is shown.
    let view_width = v.width() * 6 / 10;
    let (mut grey, mut all) = (0, 0);
    for y in (0..v.height()).step_by(7) {
        for x in (0..view_width).step_by(7) {
            let p = v.get_pixel(x, y).0;
            all += 1;
            grey += (p[0].abs_diff(p[1]) <= 1 && p[1].abs_diff(p[2]) <= 1) as usize;
        }
    }
    assert!(grey * 2 > all, "{grey} of {all} view pixels are grey");
}

/// A click on the view picks the pixel: the lobe window shows that pixel's N, V and each light's
/// angles, the f64 model's values for the point it sees, and its plots.
#[test]
fn clicking_a_pixel_shows_its_lobe_and_angles() {
    let mut h = harness();
    assert!(h.state().picked().is_none() && h.query_by_label("lobe of the picked pixel").is_none());
    // On the middle sphere of the default scene.
    let at = egui::pos2(300.0, 350.0);
    h.input_mut().events.push(egui::Event::PointerMoved(at));
    h.run_steps(1);
    for pressed in [true, false] {
        h.input_mut().events.push(egui::Event::PointerButton {
            pos: at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Default::default(),
        });
        h.run_steps(1);
    }
    h.run_steps(3);
    let picked = h.state().picked().cloned().expect("a pixel is picked");
    let size = h.state().view_size().expect("the view is drawn");
    let scene = h.state_mut().scene_mut().clone();
    let expected = shadelab_model::lobe::pick(&scene, picked.pixel, size).expect("an object");
    assert_eq!(picked, expected, "the pick is the f64 model's point of that pixel");
    assert!(
        scene.objects[picked.object].shape == shadelab_model::Shape::Sphere,
        "{}",
        scene.objects[picked.object].name
    );
    // The window shows that pixel and its angles for each light.
    assert!(h.query_by_label_contains(&format!("pixel ({}, {})", picked.pixel.0, picked.pixel.1)).is_some());
    for (l, _) in &picked.lights {
        let a = shadelab_model::lobe::Angles::of(picked.n, picked.v, *l);
        let text = format!(
            "θ_i = {:.1}°, θ_v = {:.1}°, θ_h = {:.1}°, θ_d = {:.1}°",
            a.theta_i, a.theta_v, a.theta_h, a.theta_d
        );
        assert!(h.query_by_label_contains(&text).is_some(), "{text} is not shown");
    }
    // The polar plot's legend names each curve with its maximum, and the other terms beside it.
    assert!(h.query_by_label_contains("Cook–Torrance (max").is_some());
    assert!(h.query_by_label_contains("CT ggx/smith-correlated/schlick").is_some());
    keep_for_a_look(&h.render().expect("render"), "lobe-window.png");
}

/// A large file opens on a worker thread: the panel shows a progress bar and a cancel button,
/// frames keep coming and the old scene stays on show until the new one is ready; cancelling
/// keeps the old scene.
#[test]
fn a_large_file_opens_with_progress_and_can_be_cancelled() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join("viewer-large-sphere.glb");
    let (bytes, triangles) = shadelab_model::gltf_io::synthetic::sphere_glb(2_000_000, false);
    std::fs::write(&path, bytes).unwrap();
    let mut h = harness();
    let before = h.state_mut().scene_mut().clone();
    // Cancelled (the first load, the slowest: nothing cached): the scene on show stays.
    h.state_mut().open_file(&path);
    h.run_steps(1);
    assert!(h.state().loading());
    assert!(h.query_by_label_contains("viewer-large-sphere.glb").is_some(), "the bar names the file");
    click(&mut h, "cancel");
    assert!(!h.state().loading());
    assert!(h.state().message().unwrap().0.contains("cancelled opening"), "{:?}", h.state().message());
    assert_eq!(*h.state_mut().scene_mut(), before);
    // Opened: the old scene is drawn, frame after frame, until the new one is ready.
    h.state_mut().open_file(&path);
    let start = std::time::Instant::now();
    let frames = wait_loaded(&mut h);
    eprintln!("{frames} frames drawn while {triangles} triangles loaded in {:.2} s", start.elapsed().as_secs_f64());
    assert!(frames >= 3, "{frames} frames while loading");
    assert!(!h.state().message().unwrap().1, "{:?}", h.state().message());
    assert_eq!(h.state_mut().scene_mut().triangle_count(), triangles);
}

/// A textured file in the viewer: it opens without an error, and the panel names the textures of
/// the material picked.
#[test]
fn the_panel_names_a_materials_textures() {
    let mut h = harness();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    h.state_mut().open_file(&root.join("assets/textured-floor.gltf"));
    wait_loaded(&mut h);
    assert!(!h.state().message().unwrap().1, "{:?}", h.state().message());
    h.run_steps(2);
    assert!(h.query_by_label_contains("textures:").is_none(), "the first sphere has none");
    click(&mut h, "material");
    click(&mut h, "textured ground");
    let line = "textures: base colour, metallic–roughness, occlusion, emissive, normal; emits I_e = (0.30, 0.15, 0.05)";
    h.get_by_label(line).scroll_to_me();
}

#[test]
fn a_link_written_by_the_viewer_opens_the_same_view() {
    let mut h = harness();
    click(&mut h, "gouraud");
    h.state_mut().set_term(shadelab_model::terms::Term::Diffuse);
    h.state_mut().set_difference_view(true);
    h.run_steps(1);
    let (link, note) = h.state().link("http://127.0.0.1:8000/");
    assert!(note.is_none(), "a built-in scene travels in the link");
    assert!(link.starts_with("http://127.0.0.1:8000/?scene=default&shading=gouraud"), "{link}");
    let query = link.split_once('?').unwrap().1;
    let parsed = shadelab::viewer::parse_query(query);
    assert!(parsed.errors.is_empty(), "{:?}", parsed.errors);
    let mut fresh = harness();
    fresh.state_mut().open_link(&parsed);
    fresh.run_steps(1);
    assert_eq!(fresh.state().settings().shading, ShadingMode::Gouraud);
    assert_eq!(fresh.state().link("http://127.0.0.1:8000/").0, link, "the same view, so the same link");
    assert!(fresh.state().message().is_none());
    // A bad parameter is named and the others still apply.
    let mut bad = harness();
    bad.state_mut().open_link(&shadelab::viewer::parse_query("scene=glass&shading=toon&term=shadow"));
    bad.run_steps(1);
    let (msg, is_error) = bad.state().message().cloned().expect("a message");
    assert!(is_error && msg.contains("shading=toon") && msg.contains("flat, gouraud, phong"), "{msg}");
    assert_eq!(bad.state().link("").0, "?scene=glass&shading=phong&model=cook-torrance&term=shadow");
}

/// A link copied from a view with edited materials, lights, camera and environment opens the same
/// picture in a fresh viewer, to the pixel, and writes the same link again.
#[test]
fn a_link_carries_edited_materials_lights_camera_and_environment() {
    use shadelab_model::lighting::env_map::{EnvSource, Environment};
    let mut h = harness();
    orbit(&mut h, 10);
    let s = h.state_mut().scene_mut();
    s.materials[0].m = 0.123_456_789;
    s.materials[1].mu = [0.9, 0.5, 0.25];
    s.lights[0].intensity = 0.7;
    s.lights[1].shadow.filter = shadelab_model::shadow_settings::ShadowFilter::Pcss;
    s.lights.push(shadelab_model::Light::point(glam::DVec3::new(-2.0, 3.0, 1.0), [0.2, 0.4, 1.0], 0.8, 0.1));
    s.environment = Some(Environment::new(EnvSource::Sky { turbidity: 4.0, sun: None }));
    s.ambient = [0.0; 3];
    h.run_steps(3);
    let (link, note) = h.state().link("");
    assert!(note.is_none(), "{note:?}");
    eprintln!("the edited view's link: {link} ({} characters)", link.len());
    for key in ["orbit=", "mat0.m=0.123456789", "mat1.mu=0.9,0.5,0.25", "lights=3", "light2.pos=-2,3,1", "env=sky"] {
        assert!(link.contains(key), "{key} in {link}");
    }
    let parsed = shadelab::viewer::parse_query(&link);
    assert!(parsed.errors.is_empty(), "{:?}", parsed.errors);
    let mut fresh = harness();
    fresh.state_mut().open_link(&parsed);
    fresh.run_steps(3);
    assert!(fresh.state().message().is_none(), "{:?}", fresh.state().message());
    assert_eq!(fresh.state().link("").0, link, "the same view, so the same link");
    let (a, b) = (h.render().expect("render"), fresh.render().expect("render"));
    keep_for_a_look(&a, "viewer-link-copied.png");
    keep_for_a_look(&b, "viewer-link-opened.png");
    assert_eq!(changed_view_pixels(&a, &b), 0, "the link opens the same picture");
}

#[test]
fn the_frame_is_derived_once_per_change() {
    let mut h = harness();
    h.run_steps(3);
    let before = h.state().derivations();
    assert!(before >= 1, "the first frame derives");
    h.run_steps(10);
    assert_eq!(h.state().derivations(), before, "frames that change nothing derive nothing");
    h.state_mut().scene_mut().materials[1].m = 0.3;
    h.run_steps(3);
    assert_eq!(h.state().derivations(), before + 1, "one change: one derivation, whatever the frames after it");
    h.state_mut().set_term(shadelab_model::terms::Term::Diffuse);
    h.run_steps(3);
    assert_eq!(h.state().derivations(), before + 2, "a term is a change");
    assert!(h.state_mut().scene_mut().ambient.iter().all(|&a| a > 0.0), "the term view leaves the scene as it is");
}
