//! Tests of the path tracer: its one-bounce image is the exact reference's, a closed furnace
//! converges to `L_e/(1 − ρ)`, its images do not depend on the threads, its estimate of the noise
//! holds, and the hard cases stay finite.

use super::tests::{all_finite, object, stage};
use super::*;
use crate::lighting::lights::Light;
use crate::mesh::{TriangleMesh, triangles};
use crate::scene::{Camera, Material, Shape};
use glam::DVec3;

fn path_traced(scene: &Scene, w: u32, h: u32, paths: PathSettings) -> ReferenceImage {
    let mut job = ReferenceJob::with_paths(scene, SpecularModel::CookTorrance, w, h, paths).unwrap();
    job.step(h);
    job.finish()
}

/// At one bounce the path tracer is the exact reference without the constant ambient, bit for bit,
/// with no noise: the same estimator of the direct light.
#[test]
fn one_bounce_is_the_exact_reference_without_ambient() {
    for name in ["default", "glass", "penumbra"] {
        let scene = Scene::builtin(name).unwrap();
        let paths = PathSettings { bounces: 1, spp: 4, seed: 7 };
        let traced = path_traced(&scene, 64, 36, paths);
        let exact =
            render_reference(&Scene { ambient: [0.0; 3], ..scene.clone() }, SpecularModel::CookTorrance, 64, 36);
        assert_eq!(traced.pixels, exact.pixels, "{name}");
        assert!(traced.std_error.iter().all(|e| *e == [0.0; 3]), "{name}");
        assert_eq!(traced.fireflies, 0, "{name}");
    }
}

/// A camera inside a closed sphere whose inside emits `L_e` and reflects ρ diffusely: after `N`
/// bounces every pixel is `L_e·(1 − ρ^N)/(1 − ρ)`, with no noise, since every path sees the same
/// radiance; at 64 bounces that is `L_e/(1 − ρ)`.
#[test]
fn a_white_furnace_converges_to_emission_over_one_minus_albedo() {
    for (rho, le) in [(0.5, 0.2), (0.8, 0.05), (0.95, 0.01)] {
        // A tessellated sphere wound inside out: its face normals point in, toward the camera.
        let inside_out: Vec<[DVec3; 3]> = triangles(Shape::Sphere, 24).into_iter().map(|[a, b, c]| [a, c, b]).collect();
        let mut scene = stage(vec![], vec![]);
        scene.meshes = vec![TriangleMesh::from_soup("furnace", &inside_out, None)].into();
        scene.objects = vec![object("furnace", Shape::Mesh(0), DVec3::ZERO, DVec3::splat(5.0))];
        scene.camera = Camera { eye: DVec3::new(0.3, -0.2, 0.1), target: DVec3::new(1.0, 0.0, 0.5), ..scene.camera };
        scene.materials =
            vec![Material { color: [rho; 3], r_d: 1.0, r_s: 0.0, r_a: 0.0, emission: [le; 3], ..Material::default() }];
        for bounces in [1, 3, 64] {
            let img = path_traced(&scene, 8, 6, PathSettings { bounces, spp: 3, seed: 2 });
            let want = le * (1.0 - rho.powi(bounces as i32)) / (1.0 - rho);
            for p in &img.pixels {
                for c in p {
                    assert!((c - want).abs() <= 1e-12 * want, "ρ {rho}, {bounces} bounces: {c} against {want}");
                }
            }
        }
    }
}

/// Inside a furnace of glossy surfaces every bounce sees the same radiance `L_e`, so two bounces
/// give `L_e·(1 + A)`, with `A = ∫ term(ω) dω/π` the model's albedo toward the camera: the
/// mixture of lobe and cosine sampling converges to the quadrature of `A`, within 4 standard
/// errors.
#[test]
fn glossy_bounces_converge_to_the_albedo_integral() {
    let inside_out: Vec<[DVec3; 3]> = triangles(Shape::Sphere, 24).into_iter().map(|[a, b, c]| [a, c, b]).collect();
    for (specular, m) in [(SpecularModel::CookTorrance, 0.15), (SpecularModel::Phong, 0.3)] {
        let mut scene = stage(vec![], vec![]);
        scene.meshes = vec![TriangleMesh::from_soup("furnace", &inside_out, None)].into();
        scene.objects = vec![object("furnace", Shape::Mesh(0), DVec3::ZERO, DVec3::splat(5.0))];
        scene.camera = Camera { eye: DVec3::new(0.3, -0.2, 0.1), target: DVec3::new(1.0, 0.0, 0.5), ..scene.camera };
        let le = 0.1;
        let material = Material {
            color: [0.6; 3],
            r_d: 0.5,
            r_s: 0.5,
            m,
            h: crate::params::PhongExponent::from_m(m),
            emission: [le; 3],
            ..Material::default()
        };
        scene.materials = vec![material.clone()];
        let paths = PathSettings { bounces: 2, spp: 20_000, seed: 8 };
        let mut job = ReferenceJob::with_paths(&scene, specular, 1, 1, paths).unwrap();
        job.step(1);
        let img = job.finish();
        // The albedo by a midpoint quadrature over the hemisphere, the same probe the tracer uses.
        let (o, dir) = scene.camera.ray(0, 0, 1, 1);
        let geo = Geometry::new(&scene);
        let hit = trace_ray(&scene, &geo, o, dir).unwrap();
        let (n, steps) = (hit.normal, 600);
        let (t, b) = n.any_orthonormal_pair();
        let mut albedo = 0.0;
        for i in 0..steps {
            let theta = (i as f64 + 0.5) / steps as f64 * std::f64::consts::FRAC_PI_2;
            for j in 0..2 * steps {
                let phi = (j as f64 + 0.5) / (2 * steps) as f64 * std::f64::consts::TAU;
                let w = t * (theta.sin() * phi.cos()) + b * (theta.sin() * phi.sin()) + n * theta.cos();
                let probe = Light::directional(-w, [1.0; 3], 1.0);
                let at = crate::lighting::shading::ShadePoint {
                    p: hit.point,
                    n_in: n,
                    eye: o.extend(1.0),
                    mat: &material,
                    ambient: [0.0; 3],
                    env_sh: None,
                    env_prefiltered: None,
                    env_occlusion: None,
                    specular,
                    model: scene.illumination,
                };
                let term = crate::lighting::shading::shade_exact(&at, &[probe], |_, _, _, _| 1.0, &mut |_| None)[1];
                let dw = theta.sin()
                    * (std::f64::consts::FRAC_PI_2 / steps as f64)
                    * (std::f64::consts::TAU / (2 * steps) as f64);
                albedo += term * dw / std::f64::consts::PI;
            }
        }
        let want = le * (1.0 + albedo);
        let (got, sigma) = (img.pixels[0][1], img.std_error[0][1]);
        assert!(sigma < 0.01 * want, "{specular:?}: noise {sigma} too large to test");
        assert!((got - want).abs() < 4.0 * sigma, "{specular:?}: {got} against {want} (σ {sigma}, albedo {albedo})");
    }
}

/// The same seed gives the same image on one thread and on several, and in steps; another seed
/// gives another image.
#[test]
fn the_seed_alone_decides_the_image() {
    let scene = Scene::builtin("default").unwrap();
    let paths = PathSettings { bounces: 3, spp: 2, seed: 11 };
    let one =
        rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap().install(|| path_traced(&scene, 48, 27, paths));
    let many = path_traced(&scene, 48, 27, paths);
    assert_eq!(one.pixels, many.pixels);
    let mut job = ReferenceJob::with_paths(&scene, SpecularModel::CookTorrance, 48, 27, paths).unwrap();
    while !job.step(5) {}
    assert_eq!(job.finish().pixels, many.pixels);
    let other = path_traced(&scene, 48, 27, PathSettings { seed: 12, ..paths });
    assert_ne!(other.pixels, many.pixels);
}

/// The estimated standard error is honest: two images with different seeds differ by about
/// √2 times it, and more paths shrink it by about √(ratio). On the default scene made diffuse,
/// whose paths' light is bounded; a glossy lobe's rare bright paths are the fireflies' count.
#[test]
fn the_noise_estimate_matches_the_noise() {
    let mut scene = Scene::builtin("default").unwrap();
    for m in &mut scene.materials {
        m.r_s = 0.0;
    }
    let paths = PathSettings { bounces: 2, spp: 16, seed: 3 };
    let (w, h) = (40, 24);
    let a = path_traced(&scene, w, h, paths);
    let b = path_traced(&scene, w, h, PathSettings { seed: 4, ..paths });
    let (mut diff_sq, mut var, mut n) = (0.0, 0.0, 0);
    for i in 0..a.pixels.len() {
        for c in 0..3 {
            diff_sq += (a.pixels[i][c] - b.pixels[i][c]).powi(2);
            var += a.std_error[i][c].powi(2) + b.std_error[i][c].powi(2);
            n += 1;
        }
    }
    assert!(var > 0.0, "the default scene has indirect light");
    let ratio = (diff_sq / var).sqrt();
    assert!((0.8..1.25).contains(&ratio), "measured over estimated noise: {ratio} ({n} values)");
    let more = path_traced(&scene, w, h, PathSettings { spp: 64, ..paths });
    let mean = |img: &ReferenceImage| img.std_error.iter().map(|e| e[1]).sum::<f64>();
    let shrink = mean(&a) / mean(&more);
    assert!((1.6..2.5).contains(&shrink), "16 → 64 paths: the error shrinks {shrink}×, about 2 expected");
}

/// The hard cases stay finite and non-negative: grazing light, a light on a surface, a
/// zero-area triangle, the camera inside glass, glossy surfaces that make fireflies, area lights
/// on a surface, edge-on to it and inside an object.
#[test]
fn hard_cases_stay_finite() {
    let ball = || object("ball", Shape::Sphere, DVec3::new(0.0, 0.5, 0.0), DVec3::splat(0.5));
    let lights = [
        Light::directional(DVec3::new(1.0, -1e-12, 0.3), [1.0; 3], 1.0),
        Light::point(DVec3::new(0.0, 1.0, 0.0), [1.0; 3], 1.0, 0.0),
        Light::point(DVec3::ZERO, [1.0; 3], 1.0, 0.0),
        // An area light lying on the ground, and one edge-on to it: the bounces' one-point
        // estimate meets points on and beside its plane.
        Light::area(crate::params::LightKind::Rect, DVec3::ZERO, DVec3::Y, [1.0, 1.0], [1.0; 3], 1.0, 0.0),
        Light::area(
            crate::params::LightKind::Disk,
            DVec3::new(1.0, 0.5, 0.0),
            DVec3::X,
            [0.5, 0.5],
            [1.0; 3],
            1.0,
            0.0,
        ),
        Light::area(
            crate::params::LightKind::Sphere,
            DVec3::new(0.0, 0.5, 0.0),
            DVec3::Y,
            [0.4, 0.4],
            [1.0; 3],
            1.0,
            0.0,
        ),
    ];
    let paths = PathSettings { bounces: 4, spp: 4, seed: 5 };
    for light in lights {
        let mut scene = stage(vec![ball()], vec![light.clone()]);
        scene.materials[0].m = 0.02;
        assert!(all_finite(&path_traced(&scene, 32, 18, paths)), "{light:?}");
    }
    let flat = crate::mesh::TriangleMesh::from_soup("flat", &[[DVec3::ZERO, DVec3::X, DVec3::X * 2.0]], None);
    let mut scene = stage(vec![object("flat", Shape::Mesh(0), DVec3::new(0.0, 0.5, 0.0), DVec3::ONE)], vec![]);
    scene.lights = vec![Light::point(DVec3::new(0.0, 2.0, 0.0), [1.0; 3], 1.0, 0.0)];
    scene.meshes = vec![flat].into();
    assert!(all_finite(&path_traced(&scene, 32, 18, paths)), "zero-area triangle");
    let mut glass = Scene::builtin("glass").unwrap();
    if let Some(o) = glass
        .objects
        .iter()
        .find(|o| glass.drawn_as_glass(glass.objects.iter().position(|p| p.name == o.name).unwrap()))
    {
        glass.camera.eye = o.transform.translation;
    }
    assert!(all_finite(&path_traced(&glass, 32, 18, paths)), "camera inside glass");
}

/// The ladder's constant rung is the exact reference with the scene's `I_a`; the fitted `I_a`
/// recovers a scale the indirect light was made with, and fits the real indirect light at least
/// as well as the scene's own `I_a`.
#[test]
fn the_ambient_ladder_rebuilds_the_reference_and_fits_i_a() {
    let scene = Scene::builtin("default").unwrap();
    let (w, h) = (48, 27);
    let traced = path_traced(&scene, w, h, PathSettings { bounces: 3, spp: 8, seed: 9 });
    let mut ladder = AmbientLadder::new(&traced, scene.ambient).unwrap();
    let exact = render_reference(&scene, SpecularModel::CookTorrance, w, h);
    for (a, b) in ladder.constant().iter().zip(&exact.pixels) {
        for c in 0..3 {
            assert!((a[c] - b[c]).abs() <= 1e-12, "{a:?} against {b:?}");
        }
    }
    let fitted = ladder.fitted_ambient();
    assert!(ladder.rmse(&ladder.fitted()) <= ladder.rmse(&ladder.constant()) + 1e-15);
    assert!(fitted.iter().all(|k| k.is_finite() && *k > 0.0), "{fitted:?}");
    ladder.indirect = ladder.per_ambient.iter().map(|a| [0.3 * a[0], 0.5 * a[1], 0.7 * a[2]]).collect();
    let k = ladder.fitted_ambient();
    for (c, want) in [0.3, 0.5, 0.7].into_iter().enumerate() {
        assert!((k[c] - want).abs() < 1e-12, "channel {c}: {} against {want}", k[c]);
    }
    assert!(ladder.rmse(&ladder.fitted()) < 1e-12);
}

/// Ambient occlusion is 1 on open ground beyond its radius from the sphere resting on it, and
/// well under 1 beside the sphere's contact.
#[test]
fn ambient_occlusion_darkens_contact_only() {
    let ball = object("ball", Shape::Sphere, DVec3::new(0.0, 0.5, 0.0), DVec3::splat(0.5));
    let scene = stage(vec![ball], vec![Light::point(DVec3::new(0.0, 3.0, 0.0), [1.0; 3], 1.0, 0.0)]);
    let (w, h) = (96, 54);
    let ao = ambient_occlusion(&scene, w, h, 64, 3);
    let seen = render_reference(&scene, SpecularModel::Phong, w, h);
    // The scene's size is the camera's 6 m: occluders count within 0.6 m.
    let radius = AO_RADIUS_REL * 6.0;
    let (mut open, mut contact) = (0, 0);
    for y in 0..h {
        for x in 0..w {
            let Some(p) = (seen.object_at(x, y) == Some(0))
                .then(|| super::tests::ground_point(&scene.camera, x, y, w, h))
                .flatten()
            else {
                continue;
            };
            let (d, a) = (DVec3::new(p.x, 0.0, p.z).length(), ao[(y * w + x) as usize]);
            if d > 0.5 + radius + 0.05 {
                assert_eq!(a, 1.0, "open ground {d:.2} m from the axis");
                open += 1;
            } else if d < 0.55 {
                assert!(a < 0.9, "beside the contact, {d:.2} m from the axis: {a}");
                contact += 1;
            }
        }
    }
    assert!(open > 100 && contact > 3, "{open} open and {contact} contact pixels");
}

/// One bright pixel in a smooth image is the one outlier; a smooth ramp and a sharp edge have none.
#[test]
fn an_outlier_is_a_pixel_far_above_its_neighbourhoods_median() {
    let (w, h) = (8, 6);
    let mut img: Vec<[f64; 3]> = (0..w * h).map(|i| [0.1 + 0.01 * (i % w) as f64; 3]).collect();
    for y in 0..h {
        for x in 4..w {
            img[y * w + x] = [0.9; 3];
        }
    }
    assert_eq!(outlier_pixels(&img, w), 0, "a ramp and an edge");
    img[2 * w + 1] = [1.5; 3];
    assert_eq!(outlier_pixels(&img, w), 1);
    img[2 * w + 1] = [0.95; 3];
    assert_eq!(outlier_pixels(&img, w), 0, "under 10× the median");
}

/// The constant ambient per unit of `I_a` that a path-traced image carries (traced without the
/// lights) is the difference of the exact lit images at `I_a = 1` and `I_a = 0`, through glass
/// and under an area light too.
#[test]
fn the_ambient_per_unit_is_the_lit_images_difference() {
    for name in ["default", "glass"] {
        let mut scene = Scene::builtin(name).unwrap();
        let at = DVec3::new(1.0, 3.0, 2.0);
        scene.lights[0] = Light::area(crate::params::LightKind::Rect, at, -at, [0.6, 0.4], [1.0; 3], 1.2, 0.05);
        let paths = PathSettings { bounces: 2, spp: 1, seed: 1 };
        let mut job = ReferenceJob::with_paths(&scene, SpecularModel::CookTorrance, 24, 16, paths).unwrap();
        job.step(16);
        let traced = job.finish();
        let lit = |a: f64| {
            let s = Scene { ambient: [a; 3], ..scene.clone() };
            let mut job = ReferenceJob::new(&s, SpecularModel::CookTorrance, 24, 16);
            job.step(16);
            job.finish().pixels
        };
        let (one, zero) = (lit(1.0), lit(0.0));
        for (k, a) in traced.per_ambient.iter().enumerate() {
            for c in 0..3 {
                let want = one[k][c] - zero[k][c];
                assert!((a[c] - want).abs() <= 1e-12 * (1.0 + want.abs()), "{name} pixel {k}: {} vs {want}", a[c]);
            }
        }
    }
}
