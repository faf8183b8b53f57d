//! Area lights on lavapipe (docs/area-lights.md): each kind drawn by the GPU against its f64
//! twin, the representative point against the exact integral, and the zero-size limit against
//! the point light. The penumbra's width is measured
//! by `bench penumbra` (crates/shadelab/tests/app/penumbra_widths.rs).

use shadelab_model::reference::{ReferenceImage, render_drawn, render_reference};
use shadelab_model::scene::{Overrides, Scene, single_shape_scene};
use shadelab_model::{AreaSpecular, LightKind, ShadingMode, Shape, SpecularModel};
use shadelab_render::{LinearImage, RenderSettings, render_image};
use shadelab_tests::{error, gpu, interior};

const W: u32 = 240;
const H: u32 = 135;

/// The default scene, unshadowed, with every light turned into `kind` of width `size`.
fn scene_with(kind: LightKind, size: f64) -> Scene {
    let mut s = Scene::builtin("default").unwrap();
    s.apply(&Overrides { light: Some(kind), light_size: Some(size), shadows: Some(false), ..Default::default() });
    s
}

fn draw(scene: &Scene, specular: SpecularModel) -> LinearImage {
    render_image(gpu(), scene, W, H, &RenderSettings::new(ShadingMode::Phong, specular)).unwrap()
}

/// Each area kind, 1.5 m wide above a fine sphere on the ground, drawn by the GPU matches its
/// f64 twin (`render_drawn`: the exact edge formula or cap and the same representative point or
/// LTC, in f64) on every interior pixel as closely as a point light does there, with either specular
/// model; and it differs from the point light's image by far more than that.
#[test]
fn every_area_kind_matches_its_f64_twin() {
    let (w, h) = (320, 180);
    for specular in SpecularModel::ALL_MODELS {
        let settings = RenderSettings::new(ShadingMode::Phong, specular);
        let mut point = single_shape_scene("sphere", Shape::Sphere, 256);
        point.set_shadows(false);
        let point_img = render_image(gpu(), &point, w, h, &settings).unwrap();
        // The LTC draws Cook–Torrance's lobe only.
        let methods: &[AreaSpecular] = match specular {
            SpecularModel::CookTorrance => &[AreaSpecular::Representative, AreaSpecular::Ltc],
            SpecularModel::Phong => &[AreaSpecular::Representative],
        };
        let kinds = [LightKind::Rect, LightKind::Disk, LightKind::Sphere];
        for (kind, method) in kinds.into_iter().flat_map(|k| methods.iter().map(move |&m| (k, m))) {
            let mut scene = point.clone();
            let area_specular = Some(method);
            scene.apply(&Overrides { light: Some(kind), light_size: Some(1.5), area_specular, ..Default::default() });
            let img = render_image(gpu(), &scene, w, h, &settings).unwrap();
            let reference = render_drawn(&scene, specular, w, h);
            for (object, pixels) in [("ground", interior(&reference, 0)), ("sphere", interior(&reference, 1))] {
                let (mean, max, worst) = error(&img, &reference, &pixels);
                let apart = pixels
                    .iter()
                    .map(|&(x, y)| {
                        (0..3).map(|c| (img.get(x, y)[c] - point_img.get(x, y)[c]).abs()).fold(0.0, f32::max)
                    })
                    .fold(0.0, f32::max);
                eprintln!(
                    "{kind:?} ({method:?}), {specular}, {object}: {} pixels, mean |error| {mean:.2e}, max {max:.2e} at {worst:?}; up to {apart:.2e} from the point light",
                    pixels.len()
                );
                // The point light's thresholds on this scene (stability.rs); an area form or
                // representative point that differs between the WGSL and the twin moves whole
                // regions by far more.
                assert!(mean < 1e-4, "{kind:?} {specular} {object}: mean |error| {mean}");
                assert!(max < 4e-3, "{kind:?} {specular} {object}: max |error| {max} at {worst:?}");
                assert!(
                    apart as f64 > 10.0 * max.max(1e-3),
                    "{kind:?} {specular} {object}: only {apart} from the point light"
                );
            }
        }
    }
}

/// A zero-size sphere light is the point light, pixel for pixel within 1e-3; a zero-size
/// rectangle or disk is a Lambertian point, so it darkens wherever it is seen obliquely and adds
/// nothing behind its face.
#[test]
fn a_zero_size_area_light_draws_the_point_light() {
    let specular = SpecularModel::CookTorrance;
    let point = draw(&scene_with(LightKind::Point, 0.0), specular);
    let sphere = draw(&scene_with(LightKind::Sphere, 0.0), specular);
    let diff = crate::max_rgb_gap(&point.pixels, &sphere.pixels);
    assert!(diff <= 1e-3, "zero-size sphere vs point light: {diff}");
    let rect = draw(&scene_with(LightKind::Rect, 0.0), specular);
    let darker = point.pixels.iter().zip(&rect.pixels).all(|(p, r)| (0..3).all(|c| r[c] <= p[c] + 1e-5));
    assert!(darker, "a Lambertian point never adds to the isotropic one");
    assert!(crate::max_rgb_gap(&point.pixels, &rect.pixels) > 1e-2, "the rectangle's cos θ_l must show");
}

/// The light the sphere of `scene` reflects to the camera, summed over its pixels, and the same
/// with diffuse only.
fn sphere_light(img: &shadelab_model::reference::ReferenceImage) -> f64 {
    (0..img.height)
        .flat_map(|y| (0..img.width).map(move |x| (x, y)))
        .filter(|&(x, y)| img.object_at(x, y) == Some(1))
        .map(|(x, y)| img.get(x, y).iter().sum::<f64>())
        .sum()
}

/// How the drawn specular (`drawn`) compares with the exact integral on the sphere's pixels: the
/// light on the sphere drawn over exact, the per-pixel relative error where the highlight is at
/// least a tenth of its peak (lowest, highest) and the largest absolute difference.
fn against_exact(drawn: &ReferenceImage, exact: &ReferenceImage) -> (f64, f64, f64, f64) {
    let ratio = sphere_light(drawn) / sphere_light(exact);
    let pixels = interior(exact, 1);
    let worst = pixels
        .iter()
        .map(|&(x, y)| (0..3).map(|c| (drawn.get(x, y)[c] - exact.get(x, y)[c]).abs()).fold(0.0, f64::max))
        .fold(0.0, f64::max);
    let peak = pixels.iter().map(|&(x, y)| exact.get(x, y)[0]).fold(0.0, f64::max);
    let (lo, hi) = pixels
        .iter()
        .filter(|&&(x, y)| exact.get(x, y)[0] > 0.1 * peak)
        .map(|&(x, y)| drawn.get(x, y)[0] / exact.get(x, y)[0] - 1.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| (a.min(r), b.max(r)));
    (ratio, lo, hi, worst)
}

/// The GPU's two specular methods against the exact integral the reference takes, on a glossy
/// sphere under a 1.2 × 0.8 m rectangle and a disk of the same area: the representative point's
/// highlight carries far more light than the light delivers, and less as the lobe widens; the
/// LTC's is within 5 % of the exact light at every m. The diffuse alone is the same in all. The
/// figures are docs/area-lights.md's.
#[test]
fn the_specular_methods_against_the_exact_integral() {
    let (w, h) = (160, 90);
    for (kind, size) in [(LightKind::Rect, [1.2, 0.8]), (LightKind::Disk, [1.1055; 2])] {
        let mut base = single_shape_scene("sphere", Shape::Sphere, 256);
        base.set_shadows(false);
        base.apply(&Overrides { light: Some(kind), ..Default::default() });
        base.lights[0].size = size;
        let mut ratios = Vec::new();
        let roughness: &[f64] =
            if kind == LightKind::Rect { &[0.05, 0.1, 0.2, 0.5, 0.7] } else { &[0.05, 0.2, 0.5, 0.7] };
        for &m in roughness {
            let mut glossy = base.clone();
            glossy.materials.iter_mut().for_each(|mat| {
                mat.m = m;
                mat.r_d = 0.0;
            });
            let exact = render_reference(&glossy, SpecularModel::CookTorrance, w, h);
            assert!(exact.area_error < 1e-2, "m {m}: the integral did not converge: {}", exact.area_error);
            let point = render_drawn(&glossy, SpecularModel::CookTorrance, w, h);
            let mut ltc = glossy.clone();
            ltc.apply(&Overrides { area_specular: Some(AreaSpecular::Ltc), ..Default::default() });
            let ltc = render_drawn(&ltc, SpecularModel::CookTorrance, w, h);
            let (ratio, lo, hi, worst) = against_exact(&point, &exact);
            let (ltc_ratio, ltc_lo, ltc_hi, ltc_worst) = against_exact(&ltc, &exact);
            eprintln!(
                "AREA-EXACT | {kind:?} | {m} | {ratio:.3} | {:+.0} % to {:+.0} % | {worst:.3} | {ltc_ratio:.3} | {:+.0} % to {:+.0} % | {ltc_worst:.3} | {:.1e} |",
                100.0 * lo,
                100.0 * hi,
                100.0 * ltc_lo,
                100.0 * ltc_hi,
                exact.area_error
            );
            assert!(
                (ltc_ratio - 1.0).abs() <= 0.05,
                "{kind:?} m {m}: LTC's light on the sphere is {ltc_ratio} of the exact"
            );
            ratios.push(ratio);
        }
        // The representative point gives the sphere more light than the light delivers at every
        // roughness, the more the narrower the lobe (under the rectangle: 1.48× at m = 0.05,
        // 1.16× at 0.2, 1.05× at 0.7).
        assert!(ratios.iter().all(|r| *r > 1.02) && ratios.windows(2).all(|p| p[1] < p[0]), "{kind:?}: {ratios:?}");
        let mut matte = base.clone();
        matte.materials.iter_mut().for_each(|mat| mat.r_s = 0.0);
        let (exact, drawn) = (
            render_reference(&matte, SpecularModel::CookTorrance, w, h),
            render_drawn(&matte, SpecularModel::CookTorrance, w, h),
        );
        let diffuse_gap = crate::max_rgb_gap(&exact.pixels, &drawn.pixels);
        // The disk's E/L is its equal-area 16-gon's when drawn, the quadrature's in the reference.
        let bound = if kind == LightKind::Rect { 1e-12 } else { 1e-2 };
        assert!(diffuse_gap < bound, "{kind:?}: the diffuse moved by {diffuse_gap}");
    }
}
