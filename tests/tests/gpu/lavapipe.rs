//! Image tests on lavapipe: goldens of the default scene, and properties of the shading modes
//! measured on pixels.

use glam::DVec3;
use shadelab_model::scene::{Scene, single_shape_scene};
use shadelab_model::{PhongExponent, ShadingMode, Shape, SpecularModel};
use shadelab_render::{RenderSettings, Target, render_image, target};
use shadelab_tests::*;

const GOLDEN_W: u32 = 480;
const GOLDEN_H: u32 = 270;

/// Golden thresholds, measured on lavapipe (Mesa 22.3, LLVM 15, Debian 12) at 480×270:
/// - two renders of the same permutation: FLIP mean 0, p99 0 (lavapipe is deterministic);
/// - the smallest change we want caught, one sphere's m 0.08 → 0.1 (h 300 → 198): mean
///   0.00015–0.0013 and p99 0.04–0.49 across the permutations that show that highlight
///   (Gouraud with Phong specular loses it at 16 segments, so nothing changes there);
/// - the eye moved by 2 mm: mean ≈ 0.003, p99 ≈ 0.35.
///
/// The thresholds sit below the smallest of those, so they catch a one-parameter change, and
/// p99 ignores a handful of edge pixels moved by a different LLVM's rounding.
const GOLDEN: FlipThresholds = FlipThresholds { mean: 0.0001, percentile: (0.99, 0.02) };

fn settings(shading: ShadingMode, specular: SpecularModel) -> RenderSettings {
    RenderSettings::new(shading, specular)
}

#[test]
fn default_scene_goldens_for_all_six_combinations() {
    let scene = Scene::builtin("default").unwrap();
    for shading in ShadingMode::ALL_MODES {
        for specular in SpecularModel::ALL_MODELS {
            let img = render_image(gpu(), &scene, GOLDEN_W, GOLDEN_H, &settings(shading, specular)).expect("upload");
            assert_eq!(img.nonfinite_count(), 0);
            let stats = check_golden(&format!("default-{shading}-{specular}"), &img, GOLDEN);
            eprintln!("default-{shading}-{specular}: FLIP mean {:.5}, p99 {:.5}", stats.mean, stats.percentile);
        }
    }
}

#[test]
fn the_six_combinations_differ_from_each_other() {
    let scene = Scene::builtin("default").unwrap();
    let mut images = Vec::new();
    for shading in ShadingMode::ALL_MODES {
        for specular in SpecularModel::ALL_MODELS {
            images.push((
                (shading, specular),
                render_image(gpu(), &scene, 240, 135, &settings(shading, specular)).expect("upload"),
            ));
        }
    }
    for (i, (ka, a)) in images.iter().enumerate() {
        for (kb, b) in &images[i + 1..] {
            let (s, _) = flip_compare(&a.to_srgb8(), &b.to_srgb8(), 240, 135, 0.99);
            assert!(s.mean > 0.005, "{ka:?} and {kb:?} look alike: FLIP mean {}", s.mean);
        }
    }
}

/// The one-sphere scene with a coarse sphere and a sharp material.
fn coarse_sphere(tessellation: u32, h: f64, m: f64) -> Scene {
    let mut s = single_shape_scene("sphere", Shape::Sphere, tessellation);
    s.materials[1].h = PhongExponent::Finite(h);
    s.materials[1].m = m;
    s
}

/// Pixels inside the sphere's disc where the linear luminance is discontinuous: the second
/// difference across the pixel (horizontally or vertically) exceeds `threshold`. A smooth
/// gradient, however steep, has a small second difference; a step between facets has a large one.
fn discontinuities(img: &shadelab_render::LinearImage, disc: &[(u32, u32)], threshold: f32) -> usize {
    let inside: std::collections::HashSet<_> = disc.iter().copied().collect();
    let l = |x: u32, y: u32| luminance(img.get(x, y));
    disc.iter()
        .filter(|&&(x, y)| x > 0 && y > 0)
        .filter(|&&(x, y)| {
            let horizontal = inside.contains(&(x - 1, y)) && inside.contains(&(x + 1, y));
            let vertical = inside.contains(&(x, y - 1)) && inside.contains(&(x, y + 1));
            let d2x = (l(x - 1, y) - 2.0 * l(x, y) + l(x + 1, y)).abs();
            let d2y = (l(x, y - 1) - 2.0 * l(x, y) + l(x, y + 1)).abs();
            (horizontal && d2x > threshold) || (vertical && d2y > threshold)
        })
        .count()
}

#[test]
fn flat_shows_facet_edges_and_gouraud_smooths_them() {
    let (w, h) = (320, 240);
    let scene = coarse_sphere(12, 20.0, 0.3);
    let disc = sphere_disc(&scene.camera, DVec3::new(0.0, 1.0, 0.0), 1.0, w, h, 0.85);
    // Second difference of linear luminance. Measured here on lavapipe: the peak of the h = 20
    // highlight under Phong shading curves by up to 0.01–0.02 per pixel² (145 pixels above 0.01,
    // none above 0.02); facet steps of flat shading put 965 pixels above 0.02, Gouraud none.
    let threshold = 0.02;
    let mut counts = Vec::new();
    for shading in ShadingMode::ALL_MODES {
        let img = render_image(gpu(), &scene, w, h, &settings(shading, SpecularModel::Phong)).expect("upload");
        counts.push(discontinuities(&img, &disc, threshold));
    }
    eprintln!(
        "discontinuous pixels of {} in the disc: flat {}, gouraud {}, phong {}",
        disc.len(),
        counts[0],
        counts[1],
        counts[2]
    );
    assert!(counts[0] > 200, "flat shading should show facet edges: {counts:?}");
    assert!(counts[1] * 10 < counts[0], "Gouraud should smooth facet edges: {counts:?}");
    assert!(counts[2] * 10 < counts[0], "Phong shading should be smooth: {counts:?}");
}

#[test]
fn phong_shading_keeps_the_highlight_that_gouraud_loses() {
    let (w, h) = (320, 240);
    for specular in SpecularModel::ALL_MODELS {
        // A sharp lobe (h = 400, m = 0.07) is narrower than one 8-segment facet (45°).
        let scene = coarse_sphere(8, 400.0, 0.07);
        let disc = sphere_disc(&scene.camera, DVec3::new(0.0, 1.0, 0.0), 1.0, w, h, 0.95);
        let peak = |shading| {
            let img = render_image(gpu(), &scene, w, h, &settings(shading, specular)).expect("upload");
            disc.iter().map(|&(x, y)| luminance(img.get(x, y))).fold(0.0f32, f32::max)
        };
        let (gouraud, phong) = (peak(ShadingMode::Gouraud), peak(ShadingMode::Phong));
        // Without a highlight the brightest diffuse pixel of this blue material is below 0.4.
        eprintln!("{specular}: peak luminance gouraud {gouraud:.3}, phong {phong:.3}");
        assert!(phong > 0.8, "{specular}: Phong shading lost the highlight ({phong})");
        assert!(phong > gouraud + 0.4, "{specular}: Gouraud kept the highlight ({gouraud} vs {phong})");
    }
}

#[test]
fn readback_handles_any_width_with_256_byte_rows() {
    let g = gpu();
    for (w, h) in [(1, 1), (3, 5), (17, 2), (65, 3), (300, 7)] {
        let t = Target::new(&g.device, w, h, target::HDR_FORMAT);
        // Each texel holds its own coordinates, so a misread row shows.
        let texels: Vec<[f32; 4]> = (0..h).flat_map(|y| (0..w).map(move |x| [x as f32, y as f32, 0.5, 1.0])).collect();
        g.queue.write_texture(
            t.color.as_image_copy(),
            bytemuck::cast_slice(&texels),
            wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(w * 16), rows_per_image: Some(h) },
            wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
        );
        let img = target::read_back(&g.device, &g.queue, &t);
        assert_eq!(img.pixels, texels, "{w}×{h}");
    }
}

#[test]
fn extreme_sizes_render() {
    let scene = Scene::builtin("default").unwrap();
    for (w, h) in [(1, 1), (8192, 2), (2, 8192), (333, 77)] {
        let img = render_image(gpu(), &scene, w, h, &RenderSettings::default()).expect("upload");
        assert_eq!((img.width, img.height, img.pixels.len()), (w, h, (w * h) as usize));
        assert_eq!(img.nonfinite_count(), 0);
    }
}

/// The viewer's timestamp ring times frames without waiting for them: a frame returns at once,
/// its time arrives on a later collect, and every slot is reused many times over.
#[test]
fn the_timestamp_ring_times_frames_without_waiting() {
    use shadelab_render::timestamp_ring::{RING_SLOTS, TimestampRing};
    let g = gpu();
    let scene = Scene::builtin("default").expect("built-in");
    let mut r = shadelab_render::Renderer::new(&g.device, &g.queue);
    let mut gs = r.upload(&scene).expect("upload");
    let target = Target::new(&g.device, 160, 90, target::HDR_FORMAT);
    let settings = settings(ShadingMode::Phong, SpecularModel::CookTorrance);
    r.write_uniforms(&mut gs, &scene, &target, &settings);
    let program = shadelab_render::Program::for_scene(&scene, &settings);
    let mut ring = TimestampRing::new(&g.device, &g.queue);
    assert!(ring.timed(), "lavapipe has timestamp queries");
    assert_eq!(ring.frame(&mut r, &mut gs, &target, program), None, "nothing has been read back yet");
    let mut times = Vec::new();
    for _ in 0..3 * RING_SLOTS {
        // More frames than slots in flight: the extra ones are drawn untimed, none waits.
        for _ in 0..RING_SLOTS + 1 {
            ring.frame(&mut r, &mut gs, &target, program);
        }
        g.device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
        times.push(ring.collect(&g.device).expect("a time once the GPU is idle"));
    }
    assert!(times.iter().all(|t| t.is_finite() && *t > 0.0), "{times:?}");
}

/// An orthographic camera draws orthographically: the GPU's image is as close to the f64
/// reference (parallel rays, one view direction) as the perspective camera's is to its own, and
/// far from the perspective reference.
#[test]
fn an_orthographic_camera_matches_its_reference() {
    use shadelab_model::reference::render_reference;
    use shadelab_render::image_error::compare;
    let (w, h) = (320, 180);
    let s = settings(ShadingMode::Phong, SpecularModel::CookTorrance);
    let persp = Scene::builtin("default").unwrap();
    let mut ortho = persp.clone();
    ortho.camera.orthographic = Some(2.2);
    let error = |gpu_scene: &Scene, reference_scene: &Scene| {
        let img = render_image(gpu(), gpu_scene, w, h, &s).unwrap();
        compare(&img, &render_reference(reference_scene, SpecularModel::CookTorrance, w, h)).stats.rmse
    };
    let own = error(&persp, &persp);
    let ortho_own = error(&ortho, &ortho);
    assert!(ortho_own <= 2.0 * own, "orthographic RMSE {ortho_own}, perspective {own}");
    assert!(error(&ortho, &persp) > 10.0 * ortho_own);
}

/// A pipeline whose light loop is built for the scene's lights (unrolled, each slot with its
/// kind's code only) draws what the loop reading the lights from the uniforms draws, in every
/// shading mode (flat and Gouraud light in compute passes), with every kind and cast shadows.
#[test]
fn the_light_loop_built_for_the_scene_draws_what_the_uniform_loop_draws() {
    use shadelab_model::LightKind;
    use shadelab_render::program::LightLoop;
    use shadelab_render::{Program, Renderer};
    let mut scene = Scene::builtin("default").unwrap();
    let mut spot = scene.lights[1].clone();
    spot.set_kind(LightKind::Spot);
    scene.lights.push(spot);
    let kinds: Vec<LightKind> = scene.lights.iter().map(|l| l.kind).collect();
    assert_eq!(kinds, [LightKind::Directional, LightKind::Point, LightKind::Spot]);
    let (w, h) = (96, 54);
    let gpu = gpu();
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(&scene).unwrap();
    let target = Target::new(&gpu.device, w, h, target::HDR_FORMAT);
    for shading in ShadingMode::ALL_MODES {
        let settings = settings(shading, SpecularModel::CookTorrance);
        let fixed = Program::for_scene(&scene, &settings);
        let Program::Lit { shading, effects, interpolation, lights } = fixed else { panic!("{fixed:?}") };
        assert_eq!(lights, LightLoop::for_scene(&scene));
        let dynamic = Program::Lit { shading, effects, interpolation, lights: LightLoop::Dynamic };
        let mut draw = |r: &mut Renderer, program: Program| {
            r.write_uniforms(&mut gs, &scene, &target, &settings);
            let mut encoder = r.device.create_command_encoder(&Default::default());
            r.encode(&mut encoder, &mut gs, &target, program, None);
            r.queue.submit([encoder.finish()]);
            target::read_back(&r.device, &r.queue, &target)
        };
        let (a, b) = (draw(&mut r, fixed), draw(&mut r, dynamic));
        let lit = a.pixels.iter().filter(|p| p[..3] != a.pixels[0][..3]).count();
        assert!(lit > (w * h) as usize / 4, "{shading:?}: only {lit} pixels differ from the corner");
        let worst = crate::max_rgb_gap(&a.pixels, &b.pixels);
        assert!(worst <= 1e-5, "{shading:?}: the fixed and the uniform light loops differ by {worst}");
    }
}
