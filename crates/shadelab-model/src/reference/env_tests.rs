//! Tests of the environment light in the reference: its nine SH terms stand in for `I_a` exactly
//! where the environment is uniform, and the path tracer's sampling of it (the environment's own
//! density and the bounce's, weighed by multiple importance sampling) meets the closed forms of
//! an open plane under a uniform sky and under one bright texel.

use super::tests::{all_finite, object, stage};
use super::*;
use crate::lighting::env_map::{EnvImage, EnvSource, Environment};
use crate::scene::{Object, Shape};
use glam::DVec3;
use std::sync::Arc;

fn image(w: u32, h: u32, f: impl Fn(u32, u32) -> [f32; 3]) -> EnvSource {
    let texels = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| f(x, y)).collect();
    EnvSource::Image(Arc::new(EnvImage { name: "test".into(), width: w, height: h, texels }))
}

fn lit_by(scene: &Scene, source: EnvSource) -> Scene {
    Scene { ambient: [0.0; 3], environment: Some(Environment::new(source)), ..scene.clone() }
}

/// A 1×1 environment, or a uniform one, is the uniform ambient it stands for: the exact
/// reference's SH terms (its split-sum specular left out, which `I_a` has no counterpart of)
/// give the image of `I_a` = its colour, to rounding.
#[test]
fn a_one_texel_environment_is_the_uniform_ambient() {
    let scene = Scene::builtin("default").unwrap();
    let l = [0.12, 0.09, 0.05];
    let want = render_reference(&Scene { ambient: l, ..scene.clone() }, SpecularModel::CookTorrance, 48, 27);
    for source in [EnvSource::Uniform(l), image(1, 1, |_, _| l.map(|v| v as f32))] {
        let name = source.name();
        let mut lit = lit_by(&scene, source);
        lit.environment.as_mut().unwrap().specular = false;
        let got = render_reference(&lit, SpecularModel::CookTorrance, 48, 27);
        for (g, w) in got.pixels.iter().zip(&want.pixels) {
            for c in 0..3 {
                assert!((g[c] - w[c]).abs() <= 1e-7 * w[c].max(1.0), "{name}: {g:?} against {w:?}");
            }
        }
    }
}

/// A black environment adds nothing to the exact reference.
#[test]
fn a_black_environment_adds_nothing() {
    let scene = Scene { ambient: [0.0; 3], ..Scene::builtin("default").unwrap() };
    let want = render_reference(&scene, SpecularModel::Phong, 32, 18);
    let got = render_reference(&lit_by(&scene, EnvSource::Uniform([0.0; 3])), SpecularModel::Phong, 32, 18);
    assert_eq!(got.pixels, want.pixels);
}

/// An open diffuse plane with no lights: every pixel on it is `r_d·C·E/π` for the environment's
/// irradiance `E`, the mean of `spp` paths within four standard errors.
fn plane_under(source: EnvSource, spp: u32) -> (Vec<[f64; 3]>, ReferenceImage) {
    let mut scene = stage(vec![], vec![]);
    scene.objects = vec![object("ground", Shape::Plane, DVec3::ZERO, DVec3::new(40.0, 1.0, 40.0))];
    scene.materials = vec![Material { color: [0.6, 0.5, 0.4], r_d: 1.0, r_a: 1.0, r_s: 0.0, ..Material::default() }];
    let scene = lit_by(&scene, source);
    let paths = PathSettings { bounces: 1, spp, seed: 3 };
    let mut job = ReferenceJob::with_paths(&scene, SpecularModel::Phong, 16, 9, paths).unwrap();
    job.step(9);
    let img = job.finish();
    let on_plane = img.pixels.iter().zip(&img.object).filter(|(_, o)| o.is_some()).map(|(p, _)| *p).collect();
    (on_plane, img)
}

fn assert_mean(pixels: &[[f64; 3]], want: [f64; 3], img: &ReferenceImage, what: &str) {
    assert!(!pixels.is_empty() && all_finite(img), "{what}");
    let k = pixels.len() as f64;
    for c in 0..3 {
        let mean = pixels.iter().map(|p| p[c]).sum::<f64>() / k;
        let se = (img.std_error.iter().map(|e| e[c] * e[c]).sum::<f64>() / k).sqrt() / k.sqrt();
        assert!((mean - want[c]).abs() <= 4.0 * se + 1e-12, "{what} channel {c}: {mean} against {want:?} (σ {se})");
    }
}

/// Under a uniform environment `L` the plane's truth is `r_d·C·L`: the environment's samples and
/// the bounces' escapes add up to it, neither counted twice.
#[test]
fn a_uniform_sky_over_a_plane_gives_its_ambient() {
    let l = [0.3, 0.2, 0.1];
    let (pixels, img) = plane_under(EnvSource::Uniform(l), 64);
    assert_mean(&pixels, [0.6 * l[0], 0.5 * l[1], 0.4 * l[2]], &img, "uniform");
}

/// One bright texel in a black map: the plane's truth is `r_d·C·L·∫cos dω/π` over the texel's
/// cell, found by the environment's own samples (a bounce hardly ever meets so small a cell).
#[test]
fn a_single_bright_texel_is_found() {
    let (w, h, hot) = (16u32, 8u32, (5u32, 2u32));
    let l = 40.0f32;
    let (pixels, img) = plane_under(image(w, h, |x, y| if (x, y) == hot { [l; 3] } else { [0.0; 3] }), 32);
    let t = |r: u32| std::f64::consts::PI * f64::from(r) / f64::from(h);
    let (m0, m1) = (t(hot.1 + 1).cos(), t(hot.1).cos());
    let cos_integral = (m1 * m1 - m0 * m0) / 2.0 * std::f64::consts::TAU / f64::from(w);
    let e = f64::from(l) * cos_integral / std::f64::consts::PI;
    assert_mean(&pixels, [0.6 * e, 0.5 * e, 0.4 * e], &img, "one texel");
}

/// Hard cases stay finite: a sun at the horizon, a black map, a single texel of 10⁶, each over
/// the default scene with its shadows and glass-free objects, three bounces.
#[test]
fn hard_environments_stay_finite() {
    let scene = Scene::builtin("default").unwrap();
    for source in [
        EnvSource::Sky { turbidity: 2.0, sun: Some(DVec3::X) },
        EnvSource::Sky { turbidity: 10.0, sun: Some(DVec3::new(0.0, -1.0, 0.2)) },
        image(8, 4, |_, _| [0.0; 3]),
        image(8, 4, |x, y| if (x, y) == (3, 1) { [1e6; 3] } else { [0.0; 3] }),
    ] {
        let name = format!("{source:?}").chars().take(60).collect::<String>();
        let lit = lit_by(&scene, source);
        let exact = render_reference(&lit, SpecularModel::CookTorrance, 24, 14);
        assert!(all_finite(&exact), "{name}");
        let paths = PathSettings { bounces: 3, spp: 2, seed: 5 };
        let mut job = ReferenceJob::with_paths(&lit, SpecularModel::CookTorrance, 24, 14, paths).unwrap();
        job.step(14);
        assert!(all_finite(&job.finish()), "{name}");
    }
}

/// The split sum's units and terms: a specular-only plane under a uniform environment, where the
/// prefiltered map is the radiance itself, so the only approximation left is Schlick's form of F
/// in `F0·(E − B) + B`: the exact reference's split sum meets the path-traced truth's mean within
/// four standard errors and 3 %, for a metal with the chapter's terms (its exact F near 1
/// everywhere) and dielectrics with glTF's (Schlick's F itself), glossy and rough. A dielectric
/// with the chapter's exact F falls further from Schlick's form toward grazing (docs/environment.md).
#[test]
fn the_split_sum_meets_the_truth_under_a_uniform_sky() {
    use crate::lighting::microfacet::Microfacet;
    for (m, mu, terms) in
        [(0.3, 0.9, Microfacet::CHAPTER), (1.0, 0.04, Microfacet::GLTF), (0.6, 0.04, Microfacet::GLTF)]
    {
        split_sum_case(m, mu, terms);
    }
}

fn split_sum_case(m: f64, mu: f64, terms: crate::lighting::microfacet::Microfacet) {
    let mut scene = stage(vec![], vec![]);
    scene.objects = vec![object("ground", Shape::Plane, DVec3::ZERO, DVec3::new(40.0, 1.0, 40.0))];
    let mat = Material {
        color: [1.0; 3],
        r_d: 0.0,
        r_a: 0.0,
        r_s: 1.0,
        m,
        mu: [mu; 3],
        microfacet: terms,
        ..Material::default()
    };
    scene.materials = vec![mat];
    let scene = lit_by(&scene, EnvSource::Uniform([1.0; 3]));
    let split = render_reference(&scene, SpecularModel::CookTorrance, 16, 9);
    let paths = PathSettings { bounces: 1, spp: 256, seed: 4 };
    let mut job = ReferenceJob::with_paths(&scene, SpecularModel::CookTorrance, 16, 9, paths).unwrap();
    job.step(9);
    let truth = job.finish();
    let on: Vec<usize> = (0..truth.object.len()).filter(|&i| truth.object[i].is_some()).collect();
    let k = on.len() as f64;
    let mean = |img: &ReferenceImage| on.iter().map(|&i| img.pixels[i][1]).sum::<f64>() / k;
    let se = (on.iter().map(|&i| truth.std_error[i][1].powi(2)).sum::<f64>()).sqrt() / k;
    let (s, t) = (mean(&split), mean(&truth));
    assert!(t > 0.01, "m {m}, μ {mu}: the plane reflects the sky: {t}");
    assert!((s - t).abs() <= 4.0 * se + 0.03 * t, "m {m}, μ {mu}: split sum {s} against the truth {t} (σ {se})");
}

/// Light through glass: under a uniform environment a clear (non-absorbing) glass sphere over an
/// open diffuse plane passes the sky it hides on to the plane, less what its surface reflects back
/// down (the plane's own, dimmer light), so the plane near it stays within 5 % of the open plane's
/// `r_d·C·L`. A black sphere in its place, the light a path through glass brought before it
/// carried the environment, takes over a fifth of it.
#[test]
fn a_clear_glass_sphere_passes_the_sky_on() {
    let l = [0.3, 0.3, 0.3];
    let open = 0.6 * l[0];
    let glass = Material { transmission: 1.0, ior: Some([1.5; 3]), r_s: 0.0, ..Material::default() };
    let black = Material { color: [0.0; 3], r_s: 0.0, ..Material::default() };
    let near = |sphere: Material| {
        let mut scene = stage(vec![], vec![]);
        scene.objects = vec![
            object("ground", Shape::Plane, DVec3::ZERO, DVec3::new(40.0, 1.0, 40.0)),
            Object { material: 1, ..object("ball", Shape::Sphere, DVec3::new(0.0, 0.9, 0.0), DVec3::splat(0.8)) },
        ];
        let ground = Material { color: [0.6, 0.5, 0.4], r_d: 1.0, r_a: 1.0, r_s: 0.0, ..Material::default() };
        scene.materials = vec![ground, sphere];
        let scene = lit_by(&scene, EnvSource::Uniform(l));
        let (w, h) = (32, 18);
        let paths = PathSettings { bounces: 3, spp: 48, seed: 6 };
        let mut job = ReferenceJob::with_paths(&scene, SpecularModel::Phong, w, h, paths).unwrap();
        job.step(h);
        let img = job.finish();
        assert!(all_finite(&img));
        // The ground's pixels within 1.2 of the sphere's foot, seen beside it.
        let on: Vec<usize> = (0..w * h)
            .filter(|&i| img.object[i as usize] == Some(0))
            .filter(|&i| {
                super::tests::ground_point(&scene.camera, i % w, i / w, w, h).is_some_and(|p| p.length() < 1.2)
            })
            .map(|i| i as usize)
            .collect();
        assert!(on.len() > 20, "{} ground pixels near the sphere", on.len());
        on.iter().map(|&i| img.pixels[i][0]).sum::<f64>() / on.len() as f64
    };
    let (through_glass, behind_black) = (near(glass), near(black));
    eprintln!("plane near the sphere: {through_glass:.4} (glass), {behind_black:.4} (black), open {open:.4}");
    assert!((through_glass - open).abs() < 0.05 * open, "glass: {through_glass} against {open}");
    assert!(behind_black < 0.8 * open, "a black sphere darkens the plane: {behind_black}");
}
