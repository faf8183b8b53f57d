//! Textured and vertex-coloured glTF files on lavapipe: the public samples drawn as their authors
//! meant (the texture and the colours show, and match the f64 reference that samples them the
//! same way), the same scene saved and read back drawn the same, and a scene without them drawn
//! by a permutation that holds no texture code.

use shadelab_model::effects::Effect;
use shadelab_model::gltf_io::{LoadedScene, load_scene, scene_to_glb};
use shadelab_model::reference::render_reference;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::image_error::compare;
use shadelab_render::{Program, RenderSettings, render_image};
use shadelab_tests::{gpu, workspace_root};

/// Large enough that BoxTextured's 256² texture is not minified much: level 0 only is sampled,
/// and a minified texture aliases, differently for the GPU's f32 coordinates than for f64.
const SIZE: (u32, u32) = (480, 270);

fn sample(name: &str) -> Option<LoadedScene> {
    let path = workspace_root().join("../shared/gltf-samples").join(name);
    if !path.exists() {
        eprintln!("note: {} is missing; skipping", path.display());
        return None;
    }
    Some(load_scene(&path).unwrap_or_else(|e| panic!("{e}")))
}

fn phong() -> RenderSettings {
    RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance)
}

/// RMSE of the GPU's image of `gpu_scene` against the reference of `reference_scene`.
fn rmse(gpu_scene: &shadelab_model::Scene, reference_scene: &shadelab_model::Scene) -> f64 {
    let img = render_image(gpu(), gpu_scene, SIZE.0, SIZE.1, &phong()).unwrap();
    let r = render_reference(reference_scene, SpecularModel::CookTorrance, SIZE.0, SIZE.1);
    compare(&img, &r).stats.rmse
}

/// The GPU draws what the reference draws, and not what it would draw without the texture or
/// the colours: `strip` removes them from the reference's scene.
fn matches_reference_and_needs(s: &shadelab_model::Scene, effect: Effect, strip: impl Fn(&mut shadelab_model::Scene)) {
    let program = Program::for_scene(s, &phong());
    assert!(program.effects().has(effect), "{}", program.label());
    let same = rmse(s, s);
    let mut plain = s.clone();
    strip(&mut plain);
    let without = rmse(s, &plain);
    assert!(same < 2e-3, "RMSE {same} against the reference");
    assert!(without > 20.0 * same, "RMSE {without} against the reference without {effect}, {same} with");
}

#[test]
fn box_textured_matches_the_reference_that_samples_its_texture() {
    let Some(s) = sample("BoxTextured.gltf") else { return };
    matches_reference_and_needs(&s.scene, Effect::BaseColorTexture, |p| p.materials[0].base_color_texture = None);
    // Saved as GLB (the PNG as it was) and read back: the same pixels on the GPU.
    let again = shadelab_model::gltf_io::load_scene_from_slice(&scene_to_glb(&s.scene, &s.settings)).unwrap();
    let (a, b) = (
        render_image(gpu(), &s.scene, SIZE.0, SIZE.1, &phong()).unwrap(),
        render_image(gpu(), &again.scene, SIZE.0, SIZE.1, &phong()).unwrap(),
    );
    let worst = a.pixels.iter().zip(&b.pixels).flat_map(|(p, q)| (0..3).map(move |i| (p[i] - q[i]).abs()));
    assert!(worst.fold(0.0f32, f32::max) < 1e-5);
}

#[test]
fn box_vertex_colors_match_the_reference_that_interpolates_them() {
    let Some(s) = sample("BoxVertexColors.gltf") else { return };
    matches_reference_and_needs(&s.scene, Effect::VertexColors, |p| p.meshes[0].colors = None);
}

#[test]
fn sparse_positions_take_effect_on_the_gpu() {
    let Some(s) = sample("SimpleSparseAccessor.gltf") else { return };
    let same = rmse(&s.scene, &s.scene);
    let mut dense = s.scene.clone();
    // Undo the three substitutions: vertices 8, 10 and 12 back on the row at y = 1.
    for i in [8, 10, 12] {
        dense.meshes[0].positions[i].y = 1.0;
    }
    assert!(same < 2e-3 && rmse(&s.scene, &dense) > 20.0 * same, "{same}");
}

/// Flat and Gouraud shading light per face and per vertex and tint C per pixel: BoxTextured's
/// faces are flat, so both draw the texture almost as the reference does, far closer than the
/// factor alone. The chapter's screen-space interpolation draws it too, with texture coordinates
/// linear on the screen: the affine warp across each triangle's diagonal, far from the
/// perspective-correct image.
#[test]
fn per_vertex_modes_tint_per_pixel() {
    let Some(s) = sample("BoxTextured.gltf") else { return };
    let reference = render_reference(&s.scene, SpecularModel::CookTorrance, SIZE.0, SIZE.1);
    let mut plain = s.scene.clone();
    plain.materials[0].base_color_texture = None;
    let rmse = |shading, interpolation, scene: &shadelab_model::Scene| {
        let settings = RenderSettings { interpolation, ..RenderSettings::new(shading, SpecularModel::CookTorrance) };
        assert!(Program::for_scene(&s.scene, &settings).effects().has(Effect::BaseColorTexture));
        let img = render_image(gpu(), scene, SIZE.0, SIZE.1, &settings).unwrap();
        compare(&img, &reference).stats.rmse
    };
    use shadelab_model::Interpolation::{Perspective, Screen};
    for shading in [ShadingMode::Flat, ShadingMode::Gouraud] {
        let (with, without) = (rmse(shading, Perspective, &s.scene), rmse(shading, Perspective, &plain));
        eprintln!("{shading:?}: RMSE {with:.2e} with the texture, {without:.2e} without");
        assert!(with * 10.0 < without, "{shading:?}: {with} with, {without} without");
    }
    let perspective = rmse(ShadingMode::Gouraud, Perspective, &s.scene);
    let (screen, without) = (rmse(ShadingMode::Gouraud, Screen, &s.scene), rmse(ShadingMode::Gouraud, Screen, &plain));
    eprintln!("Gouraud, screen-space: RMSE {screen:.2e} with the texture, {without:.2e} without");
    assert!(screen * 2.0 < without && screen > 10.0 * perspective, "{screen} vs {without}, {perspective}");
}

/// A scene without texture coordinates or colours has no surface code, and the uber program
/// draws it too (with nothing to bind).
#[test]
fn untextured_scenes_carry_no_texture_code() {
    let plain = shadelab_model::Scene::builtin("default").unwrap();
    let p = Program::for_scene(&plain, &phong());
    assert!(!p.effects().has(Effect::BaseColorTexture) && !p.effects().has(Effect::VertexColors));
    for shading in ShadingMode::ALL_MODES {
        let uber = RenderSettings {
            specialization: shadelab_render::Specialization::Uber,
            ..RenderSettings::new(shading, SpecularModel::CookTorrance)
        };
        let img = render_image(gpu(), &plain, 64, 36, &uber).unwrap();
        assert!(img.pixels.iter().flatten().all(|c| c.is_finite()), "{shading:?}");
    }
}

/// A checker seen far and at a grazing angle, minified many times: the GPU's mipmapped trilinear
/// sampling matches the reference that builds the same chain and picks levels by the pixel's
/// footprint, and is far from what level 0 alone gives (the aliasing mipmaps are there to stop).
#[test]
fn minified_textures_use_the_same_mipmaps_as_the_reference() {
    let mut s =
        shadelab_model::scene_variants::with_textured_floor(&shadelab_model::Scene::builtin("default").unwrap(), 32);
    s.objects.retain(|o| matches!(o.shape, shadelab_model::Shape::Mesh(_)));
    let t = s.materials[s.objects[0].material].base_color_texture.unwrap().texture;
    s.textures[t].rgba8 = (0..64 * 64u32)
        .flat_map(|k| if (k % 64 + k / 64) % 2 == 0 { [255; 4] } else { [0, 0, 0, 255] })
        .collect::<Vec<u8>>()
        .into();
    s.camera.eye = glam::DVec3::new(0.0, 0.35, 4.0);
    s.camera.target = glam::DVec3::new(0.0, 0.0, 0.0);
    let (w, h) = (160, 90);
    let img = render_image(gpu(), &s, w, h, &phong()).unwrap();
    let same = compare(&img, &render_reference(&s, SpecularModel::CookTorrance, w, h)).stats.rmse;
    let mut level0 = s.clone();
    level0.textures[t].sampler.mipmap = None;
    level0.textures[t].levels = Default::default();
    let without = compare(&img, &render_reference(&level0, SpecularModel::CookTorrance, w, h)).stats.rmse;
    eprintln!("minified checker: RMSE {same:.2e} against the mipmapped reference, {without:.2e} against level 0");
    assert!(same < 1e-2 && without > 4.0 * same, "{same} vs {without}");
}

/// A textured file lit by the sky in place of its ambient (docs/environment.md): the GPU draws
/// what the reference draws, and not what it would draw without the environment.
#[test]
fn box_textured_under_the_sky_matches_the_reference() {
    use shadelab_model::lighting::env_map::{EnvSource, Environment};
    let Some(mut s) = sample("BoxTextured.gltf") else { return };
    s.scene.ambient = [0.0; 3];
    s.scene.environment = Some(Environment::new(EnvSource::Sky { turbidity: 3.0, sun: None }));
    matches_reference_and_needs(&s.scene, Effect::EnvironmentSh, |p| p.environment = None);
}
