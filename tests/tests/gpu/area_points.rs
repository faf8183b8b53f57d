//! Area lights drawn as the chapter's k point sources on lavapipe (docs/area-lights.md): the GPU
//! against its f64 twin, and the approximation converging to the exact area light as k grows.

use shadelab_model::reference::{render_drawn, render_reference};
use shadelab_model::scene::{Overrides, Scene, penumbra_scene, single_shape_scene};
use shadelab_model::{LightKind, ShadingMode, Shape, SpecularModel};
use shadelab_render::{LinearImage, RenderSettings, render_image};
use shadelab_tests::{error, gpu, interior};

const W: u32 = 320;
const H: u32 = 180;

fn settings(specular: SpecularModel) -> RenderSettings {
    RenderSettings::new(ShadingMode::Phong, specular)
}

/// Mean |a − b| over every pixel and channel.
fn mean_abs(a: &LinearImage, b: &[[f64; 3]]) -> f64 {
    let sum: f64 = a.pixels.iter().zip(b).map(|(p, q)| (0..3).map(|c| (p[c] as f64 - q[c]).abs()).sum::<f64>()).sum();
    sum / (3 * b.len()) as f64
}

/// Each area kind as 1 and 5 point sources, unshadowed, drawn by the GPU matches the f64 twin of
/// the same approximation on every interior pixel, as closely as the exact area light does.
#[test]
fn points_match_their_f64_twin() {
    for specular in SpecularModel::ALL_MODELS {
        let mut base = single_shape_scene("sphere", Shape::Sphere, 256);
        base.set_shadows(false);
        for kind in [LightKind::Rect, LightKind::Disk, LightKind::Sphere] {
            for k in [1, 5] {
                let mut scene = base.clone();
                scene.apply(&Overrides {
                    light: Some(kind),
                    light_size: Some(1.5),
                    area_points: Some(k),
                    ..Default::default()
                });
                let img = render_image(gpu(), &scene, W, H, &settings(specular)).unwrap();
                let twin = render_drawn(&scene, specular, W, H);
                for (object, pixels) in [("ground", interior(&twin, 0)), ("sphere", interior(&twin, 1))] {
                    let (mean, max, worst) = error(&img, &twin, &pixels);
                    eprintln!(
                        "{kind:?} k = {k}, {specular}, {object}: mean |error| {mean:.2e}, max {max:.2e} at {worst:?}"
                    );
                    // The exact area light's thresholds (area_lights.rs).
                    assert!(mean < 1e-4, "{kind:?} k = {k} {specular} {object}: mean |error| {mean}");
                    assert!(max < 4e-3, "{kind:?} k = {k} {specular} {object}: max |error| {max} at {worst:?}");
                }
            }
        }
    }
}

/// The penumbra scene's square light as k = 1, 4 and 16 point sources, each with its own hard
/// shadow: at 16 the GPU's image is nearer the exact reference (the light's integral with binary
/// visibility) than at 1 or 4, and at every k it stays close to the f64 twin of the same k points
/// (what is left is the shadow maps' texels along the hard edges). The error need not fall at
/// every step: 4 points draw four distinct shadow edges and highlights, which on this scene
/// are further from the exact light in mean than the one centre's (docs/area-lights.md).
#[test]
fn points_converge_to_the_exact_area_light() {
    let specular = SpecularModel::CookTorrance;
    let exact_scene = penumbra_scene(0.5);
    let exact = render_reference(&exact_scene, specular, W, H);
    let mut errors = Vec::new();
    for k in [1, 4, 16] {
        let mut scene: Scene = exact_scene.clone();
        scene.apply(&Overrides { area_points: Some(k), ..Default::default() });
        let img = render_image(gpu(), &scene, W, H, &settings(specular)).unwrap();
        let twin = render_drawn(&scene, specular, W, H);
        let (to_exact, to_twin) = (mean_abs(&img, &exact.pixels), mean_abs(&img, &twin.pixels));
        eprintln!("k = {k}: mean |GPU − exact| {to_exact:.3e}, mean |GPU − f64 twin| {to_twin:.3e}");
        assert!(to_twin < 0.25 * to_exact.max(4e-3), "k = {k}: {to_twin} from its twin, {to_exact} from exact");
        errors.push(to_exact);
    }
    assert!(errors[2] < errors[0] && errors[2] < errors[1], "16 points must beat 1 and 4: {errors:?}");
}
