//! The environment light on lavapipe (docs/environment.md): its nine SH terms drawn by the GPU
//! against their f64 twin on a sky, and a 1×1 map against the uniform ambient it stands for.

use shadelab_model::lighting::env_map::{EnvImage, EnvSource, Environment};
use shadelab_model::reference::render_reference;
use shadelab_model::scene::Scene;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::{LinearImage, RenderSettings, render_image};
use shadelab_tests::{error, gpu, interior};
use std::sync::Arc;

const W: u32 = 240;
const H: u32 = 135;

fn draw(scene: &Scene) -> LinearImage {
    render_image(gpu(), scene, W, H, &RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance)).unwrap()
}

fn lit_by(scene: &Scene, source: EnvSource) -> Scene {
    Scene { ambient: [0.0; 3], environment: Some(Environment::new(source)), ..scene.clone() }
}

/// A 1×1 map of `I_a`'s colour draws the default scene as `I_a` does, to f32 rounding: the
/// environment's SH term replaces the ambient's and gives the same light (its split-sum
/// specular, which `I_a` has no counterpart of, left out).
#[test]
fn a_one_texel_map_draws_the_uniform_ambient() {
    let scene = Scene::builtin("default").unwrap();
    let a = scene.ambient;
    let one = EnvImage { name: "1×1".into(), width: 1, height: 1, texels: vec![a.map(|v| v as f32)] };
    let mut lit = lit_by(&scene, EnvSource::Image(Arc::new(one)));
    lit.environment.as_mut().unwrap().specular = false;
    let env = draw(&lit);
    let constant = draw(&scene);
    let worst = crate::max_rgb_gap(&env.pixels, &constant.pixels);
    eprintln!("1×1 map against I_a: max |difference| {worst:.2e}");
    assert!(worst < 1e-5, "{worst}");
}

/// Under the sky alone (no other light) the GPU's SH diffuse matches the f64 reference (the same
/// nine terms) on every object's interior pixels as closely as a point light does on a fine
/// sphere, and the sky changes the image by far more than that. The shapes are tessellated
/// finely: the sky's light turns with the normal, and a coarse mesh's normals are not the
/// reference's exact ones.
#[test]
fn the_sky_on_the_gpu_matches_its_f64_twin() {
    // Without cast shadows, whose map edges are not what this compares.
    let mut scene = Scene::builtin("default").unwrap();
    scene.set_shadows(false);
    let sun = glam::DVec3::new(0.5, 0.5, 0.3);
    scene.lights.clear();
    for o in &mut scene.objects {
        o.tessellation = 256;
    }
    let sky = lit_by(&scene, EnvSource::Sky { turbidity: 3.0, sun: Some(sun) });
    let img = draw(&sky);
    let reference = render_reference(&sky, SpecularModel::CookTorrance, W, H);
    let plain = draw(&Scene { ambient: [0.0; 3], ..scene.clone() });
    // The ground and the spheres: the shapes whose meshes stability.rs bounds against the exact
    // surfaces (the cylinder's side meets its caps in a crease the mesh rounds off).
    let bounded = |name: &str| name == "ground" || name.starts_with("sphere");
    for object in (0..scene.objects.len()).filter(|&o| bounded(&scene.objects[o].name)) {
        let pixels = interior(&reference, object);
        assert!(!pixels.is_empty(), "{}", scene.objects[object].name);
        let (mean, max, worst) = error(&img, &reference, &pixels);
        let apart = pixels
            .iter()
            .map(|&(x, y)| (0..3).map(|c| (img.get(x, y)[c] - plain.get(x, y)[c]).abs()).fold(0.0, f32::max))
            .fold(0.0, f32::max);
        let name = &scene.objects[object].name;
        eprintln!("{name}: mean |error| {mean:.2e}, max {max:.2e} at {worst:?}; the sky adds up to {apart:.2e}");
        // A point light's thresholds on a fine sphere (stability.rs).
        assert!(mean < 1e-4 && max < 4e-3, "{name}: mean {mean}, max {max}");
        assert!(apart > 0.02, "{name}: the sky adds only {apart}");
    }
}

/// With the precomputed occlusion on, the GPU's occluded diffuse matches its f64 twin (the same
/// grid, baked once for each) as closely as the unoccluded one does, and the occlusion darkens
/// the ground where the objects meet it by far more than that.
#[test]
fn the_occluded_sky_on_the_gpu_matches_its_f64_twin() {
    let mut scene = Scene::builtin("default").unwrap();
    scene.set_shadows(false);
    scene.lights.clear();
    for o in &mut scene.objects {
        o.tessellation = 256;
    }
    let sky = lit_by(&scene, EnvSource::Sky { turbidity: 3.0, sun: Some(glam::DVec3::new(0.5, 0.5, 0.3)) });
    let mut occluded = sky.clone();
    occluded.environment.as_mut().unwrap().occlusion = true;
    let img = draw(&occluded);
    let open = draw(&sky);
    let reference = render_reference(&occluded, SpecularModel::CookTorrance, W, H);
    let bounded = |name: &str| name == "ground" || name.starts_with("sphere");
    for object in (0..scene.objects.len()).filter(|&o| bounded(&scene.objects[o].name)) {
        let pixels = interior(&reference, object);
        let (mean, max, worst) = error(&img, &reference, &pixels);
        let darker = pixels
            .iter()
            .map(|&(x, y)| (0..3).map(|c| open.get(x, y)[c] - img.get(x, y)[c]).fold(0.0, f32::max))
            .fold(0.0, f32::max);
        let name = &scene.objects[object].name;
        eprintln!("{name}: mean |error| {mean:.2e}, max {max:.2e} at {worst:?}; occlusion darkens up to {darker:.2e}");
        assert!(mean < 1e-4 && max < 4e-3, "{name}: mean {mean}, max {max}");
        if name == "ground" {
            assert!(darker > 0.02, "the occlusion darkens the ground only by {darker}");
        }
    }
}

/// As the background, the sky fills every pixel where the camera sees nothing with level 0 of its
/// prefiltered levels toward the pixel's ray, as the f64 reference's miss does; the objects'
/// pixels are the same as without it, and a term alone has no background.
#[test]
fn the_sky_as_the_background_matches_its_f64_twin() {
    let scene = Scene::builtin("default").unwrap();
    let mut sky = lit_by(&scene, EnvSource::Sky { turbidity: 3.0, sun: Some(glam::DVec3::new(0.5, 0.5, 0.3)) });
    let without = draw(&sky);
    sky.environment.as_mut().unwrap().background = true;
    let img = draw(&sky);
    let reference = render_reference(&sky, SpecularModel::CookTorrance, W, H);
    let (mut worst, mut sum, mut empty, mut apart) = (0.0f32, 0.0f64, 0, 0.0f32);
    for y in 0..H {
        for x in 0..W {
            let i = (y * W + x) as usize;
            let (p, q) = (img.get(x, y), without.get(x, y));
            // The empty pixels, off the silhouettes (where the mesh and the exact shape may
            // disagree): those whose neighbours see nothing either.
            let open = |dx: i32, dy: i32| {
                let (u, v) = (x as i32 + dx, y as i32 + dy);
                u < 0
                    || v < 0
                    || u >= W as i32
                    || v >= H as i32
                    || reference.object[(v as u32 * W + u as u32) as usize].is_none()
            };
            if reference.object[i].is_some() || ![(1, 0), (-1, 0), (0, 1), (0, -1)].iter().all(|&(dx, dy)| open(dx, dy))
            {
                continue;
            }
            empty += 1;
            let r = reference.pixels[i];
            let e = (0..3).map(|c| (p[c] - r[c] as f32).abs()).fold(0.0, f32::max);
            (worst, sum) = (worst.max(e), sum + f64::from(e));
            apart = (0..3).map(|c| (p[c] - q[c]).abs()).fold(apart, f32::max);
        }
    }
    let mean = sum / empty.max(1) as f64;
    eprintln!(
        "background: {empty} pixels, mean |error| {mean:.2e}, max {worst:.2e}; the sky differs from the colour by up to {apart:.2e}"
    );
    assert!(empty > (W * H / 5) as usize, "{empty} empty pixels");
    // The surfaces' thresholds: Vulkan lets atan and acos, which find the texel, err by 4096 ulp.
    assert!(mean < 1e-4 && worst < 4e-3, "the background differs from its twin by {mean} (mean), {worst} (max)");
    assert!(apart > 0.1, "the sky differs from the background colour only by {apart}");
    // The objects are drawn as before: the background only fills what the scene leaves.
    for (x, y) in interior(&reference, 0) {
        assert_eq!(img.get(x, y), without.get(x, y), "the ground changed at ({x}, {y})");
    }
    // A term alone drops the background, the environment's too.
    let ambient = shadelab_model::terms::Term::Ambient.scene(&sky);
    assert!(!ambient.environment.as_ref().unwrap().background);
}
