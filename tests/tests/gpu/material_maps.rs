//! glTF's other material textures on lavapipe: the metallic–roughness, occlusion and emissive
//! textures and the emission I_e, on a floor made in code (`scene_variants::with_material_maps`),
//! drawn as the f64 reference draws them and not as it would without each; saved and read back
//! the same; and the per-vertex modes drawing the emission exactly and leaving the lighting
//! textures to Phong shading.

use shadelab_model::effects::Effect;
use shadelab_model::gltf_io::{SceneSettings, load_scene_from_slice, scene_to_glb};
use shadelab_model::reference::render_reference;
use shadelab_model::scene_variants::with_material_maps;
use shadelab_model::{Scene, ShadingMode, SpecularModel};
use shadelab_render::image_error::compare;
use shadelab_render::{Program, RenderSettings, render_image};
use shadelab_tests::gpu;

const SIZE: (u32, u32) = (320, 180);
/// The floor's tessellation level (as the accuracy study's quick run).
const LEVEL: u32 = 32;

fn scene() -> Scene {
    let mut s = with_material_maps(&Scene::builtin("default").unwrap(), LEVEL);
    // The floor alone (the spheres are tessellated on the GPU and exact in the reference), seen
    // from close by so that its textures are magnified (level 0 only is sampled: a minified
    // texture aliases, differently in f32 and f64).
    s.objects.retain(|o| matches!(o.shape, shadelab_model::Shape::Mesh(_)));
    s.camera.eye = glam::DVec3::new(0.0, 1.4, 1.4);
    s.camera.target = glam::DVec3::new(0.0, 0.0, 0.0);
    s
}

fn rmse(gpu_scene: &Scene, reference_scene: &Scene, settings: &RenderSettings) -> f64 {
    let img = render_image(gpu(), gpu_scene, SIZE.0, SIZE.1, settings).unwrap();
    let r = render_reference(reference_scene, settings.specular, SIZE.0, SIZE.1);
    compare(&img, &r).stats.rmse
}

/// Takes one map (or the emission) out of a material.
type Strip = fn(&mut shadelab_model::Material);

fn floor(s: &mut Scene) -> &mut shadelab_model::Material {
    let i = s.objects.iter().find(|o| matches!(o.shape, shadelab_model::Shape::Mesh(_))).unwrap().material;
    &mut s.materials[i]
}

/// Phong shading draws each map as the reference does, and the reference without the map is far
/// from it: each map is drawn, and drawn as the model says.
#[test]
fn each_map_matches_the_reference_and_is_needed() {
    let s = scene();
    for specular in [SpecularModel::CookTorrance, SpecularModel::Phong] {
        let settings = RenderSettings::new(ShadingMode::Phong, specular);
        let fx = Program::for_scene(&s, &settings).effects();
        // The floor is a glTF metal (C = 0) whose texture makes bands of it diffuse: the
        // analysis keeps the diffuse term for them.
        for e in [
            Effect::Diffuse,
            Effect::MetalRoughnessTexture,
            Effect::OcclusionTexture,
            Effect::Emission,
            Effect::EmissiveTexture,
        ] {
            assert!(fx.has(e), "{e}: {}", fx.label());
        }
        let same = rmse(&s, &s, &settings);
        eprintln!("{specular:?}: RMSE {same:.2e} against the reference");
        assert!(same < 3e-3, "{specular:?}: RMSE {same}");
        let strip: [(&str, Strip); 5] = [
            ("normal texture", |m| m.maps.normal = None),
            ("metallic–roughness", |m| m.maps.metal_roughness = None),
            ("occlusion", |m| m.maps.occlusion = None),
            ("emissive texture", |m| m.maps.emissive = None),
            ("emission", |m| m.emission = [0.0; 3]),
        ];
        for (what, f) in strip {
            let mut plain = s.clone();
            f(floor(&mut plain));
            let without = rmse(&s, &plain, &settings);
            eprintln!("{specular:?}: without the {what}: RMSE {without:.2e}");
            assert!(without > 5.0 * same, "{specular:?}: without the {what}: {without}, with: {same}");
        }
    }
}

/// Saved as GLB and read back: the same maps, the same M·F0 and I_e, the same pixels.
#[test]
fn a_saved_scene_keeps_its_maps() {
    let s = scene();
    let again = load_scene_from_slice(&scene_to_glb(&s, &SceneSettings::default())).unwrap().scene;
    let (a, b) = (floor(&mut s.clone()).clone(), floor(&mut again.clone()).clone());
    assert_eq!(a.maps.metal_roughness.map(|m| m.metallic_f0), b.maps.metal_roughness.map(|m| m.metallic_f0));
    assert_eq!(a.maps.occlusion.map(|m| m.strength), b.maps.occlusion.map(|m| m.strength));
    assert!(b.maps.emissive.is_some());
    assert_eq!(a.maps.normal.map(|m| m.scale), b.maps.normal.map(|m| m.scale));
    assert_eq!(a.emission, b.emission);
    let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let (x, y) = (
        render_image(gpu(), &s, SIZE.0, SIZE.1, &settings).unwrap(),
        render_image(gpu(), &again, SIZE.0, SIZE.1, &settings).unwrap(),
    );
    let worst = x.pixels.iter().zip(&y.pixels).flat_map(|(p, q)| (0..3).map(move |i| (p[i] - q[i]).abs()));
    assert!(worst.fold(0.0f32, f32::max) < 1e-5);
}

/// Flat and Gouraud shading add the emission per pixel (it is not lit, so exactly), and hold no
/// metallic–roughness or occlusion code: those vary the lighting per pixel, which these modes
/// compute per face or vertex.
#[test]
fn per_vertex_modes_draw_the_emission_and_leave_the_lighting_maps() {
    let s = scene();
    let mut dark = s.clone();
    floor(&mut dark).emission = [0.0; 3];
    for shading in [ShadingMode::Flat, ShadingMode::Gouraud] {
        let settings = RenderSettings::new(shading, SpecularModel::CookTorrance);
        let fx = Program::for_scene(&s, &settings).effects();
        assert!(fx.has(Effect::Emission) && fx.has(Effect::EmissiveTexture), "{}", fx.label());
        for e in shadelab_render::program::PER_PIXEL_LIGHTING {
            assert!(!fx.has(e), "{e}: {}", fx.label());
        }
        let (a, b) = (
            render_image(gpu(), &s, SIZE.0, SIZE.1, &settings).unwrap(),
            render_image(gpu(), &dark, SIZE.0, SIZE.1, &settings).unwrap(),
        );
        // The emitted light is the difference, exactly where the stripes are.
        let lit = a.pixels.iter().zip(&b.pixels).filter(|(p, q)| (p[0] - q[0]) > 0.2).count();
        assert!(lit > (SIZE.0 * SIZE.1 / 50) as usize, "{shading:?}: {lit} pixels emit");
        let brighter = a.pixels.iter().zip(&b.pixels).all(|(p, q)| (0..3).all(|i| p[i] >= q[i] - 1e-6));
        assert!(brighter, "{shading:?}: emission only adds");
    }
}

/// Writes the test scene's image and reference, and the default scene with the material-mapped
/// floor as a GLB (for `shadelab bench effects --scene`), to `$SHADELAB_DUMP` (a folder).
#[test]
fn dump_when_asked() {
    let Ok(dir) = std::env::var("SHADELAB_DUMP") else { return };
    let s = scene();
    let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let img = render_image(gpu(), &s, SIZE.0, SIZE.1, &settings).unwrap();
    let r = shadelab_render::image_error::reference_image(&render_reference(&s, settings.specular, SIZE.0, SIZE.1));
    let full = with_material_maps(&Scene::builtin("default").unwrap(), 64);
    std::fs::write(format!("{dir}/material-maps.glb"), scene_to_glb(&full, &SceneSettings::default())).unwrap();
    for (name, i) in [("maps-gpu.png", &img), ("maps-reference.png", &r)] {
        image::RgbImage::from_raw(SIZE.0, SIZE.1, i.to_srgb8()).unwrap().save(format!("{dir}/{name}")).unwrap();
    }
}
