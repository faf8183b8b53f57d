//! Cast shadows on lavapipe against the failures users report: a lit gap between an object and
//! its shadow (peter-panning), and setups where the shadow projection degenerates. Acne has its
//! own test beside the shadow pass (`shadow_pass::tests::a_lit_plane_has_no_acne`).

use glam::DVec3;
use shadelab_model::reference::render_reference;
use shadelab_model::scene::{Light, Object, Scene, Shape, Transform, single_shape_scene};
use shadelab_model::shadows::ShadowFilter;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::image_error::{ShadowPixel, shadow_disagreement};
use shadelab_render::{RenderSettings, render_image};
use shadelab_tests::gpu;

/// The widest band of `mask` pixels: for each pixel in the mask, the shortest of its runs through
/// it along the rows, the columns and the two diagonals (a band one pixel wide gives 1 whichever
/// way it runs, a staircase along a slanted edge included).
fn band_width(mask: &[bool], w: usize, h: usize) -> usize {
    let run = |x: usize, y: usize, dx: isize, dy: isize| {
        let mut n = 1;
        for sign in [-1isize, 1] {
            let (mut cx, mut cy) = (x as isize, y as isize);
            loop {
                cx += sign * dx;
                cy += sign * dy;
                if cx < 0 || cy < 0 || cx >= w as isize || cy >= h as isize || !mask[cy as usize * w + cx as usize] {
                    break;
                }
                n += 1;
            }
        }
        n
    };
    let mut widest = 0;
    for y in 0..h {
        for x in 0..w {
            if mask[y * w + x] {
                let shortest = [(1, 0), (0, 1), (1, 1), (1, -1)].map(|(dx, dy)| run(x, y, dx, dy));
                widest = widest.max(shortest.into_iter().min().unwrap_or(0));
            }
        }
    }
    widest
}

/// How close to the object, in pixels, a missed shadow counts as a gap at the contact.
const CONTACT_PX: i64 = 6;

/// Pixels within `radius` (chessboard distance) of a pixel showing `object`.
fn near_object(r: &shadelab_model::reference::ReferenceImage, object: usize, radius: i64) -> Vec<bool> {
    let (w, h) = (r.width as i64, r.height as i64);
    let mut near = vec![false; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            if r.object_at(x as u32, y as u32) == Some(object) {
                for ny in (y - radius).max(0)..(y + radius + 1).min(h) {
                    for nx in (x - radius).max(0)..(x + radius + 1).min(w) {
                        near[(ny * w + nx) as usize] = true;
                    }
                }
            }
        }
    }
    near
}

/// The cube resting on the ground (its base at y = 0), lit by one light of `kind`.
fn cube_on_ground(light: Light, filter: ShadowFilter) -> Scene {
    let mut s = single_shape_scene("cube", Shape::Cube, 1);
    s.lights = vec![light];
    for l in &mut s.lights {
        l.shadow.filter = filter;
    }
    s
}

#[test]
fn an_object_resting_on_the_ground_leaves_at_most_a_one_pixel_lit_gap() {
    let (w, h) = (1280, 720);
    let sun = Light::directional(DVec3::new(-0.6, -0.7, -0.4), [1.0; 3], 1.0);
    let spot = Light::spot(DVec3::new(2.0, 3.0, 2.0), DVec3::new(-0.55, -1.0, -0.5), [1.0; 3], 3.0, 0.05, (0.5, 0.7));
    for (name, light) in [("directional", sun), ("spot", spot)] {
        for filter in [ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Poisson] {
            let scene = cube_on_ground(light.clone(), filter);
            let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
            let on = render_image(gpu(), &scene, w, h, &settings).expect("upload");
            let mut off_scene = scene.clone();
            off_scene.set_shadows(false);
            let off = render_image(gpu(), &off_scene, w, h, &settings).expect("upload");
            let reference = render_reference(&scene, SpecularModel::CookTorrance, w, h);
            let cmp = shadow_disagreement(&on, &off, &reference);
            assert!(cmp.stats.share_shadowed_reference > 0.01, "{name}: the cube's shadow is in view");
            // Lit by the GPU where the exact shadow is, next to the cube: a gap would be a band
            // of such pixels along the contact edge, as wide as the shadow is pushed away. (The
            // shadow's far rim is aliased by the map's texels; that is resolution, not a gap.)
            let near = near_object(&reference, 1, CONTACT_PX);
            let missed: Vec<bool> =
                cmp.map.iter().zip(&near).map(|(p, n)| *n && *p == ShadowPixel::MissedShadow).collect();
            let gap = band_width(&missed, w as usize, h as usize);
            eprintln!(
                "{name} {filter:?}: widest lit band {gap} px, {:.3} % missed, {:.3} % false",
                100.0 * cmp.stats.share_missed_shadow,
                100.0 * cmp.stats.share_false_shadow
            );
            assert!(gap <= 1, "{name} {filter:?}: a lit band {gap} px wide where the exact shadow is");
        }
    }
}

#[test]
fn the_band_width_measure_sees_a_two_pixel_band() {
    // A 2-pixel-high horizontal band, as a shadow pushed 2 pixels away would leave.
    let (w, h) = (20, 10);
    let mut mask = vec![false; w * h];
    for x in 3..17 {
        mask[4 * w + x] = true;
        mask[5 * w + x] = true;
    }
    assert_eq!(band_width(&mask, w, h), 2);
    // A one-pixel staircase (a diagonal edge) is one pixel wide.
    let mut stair = vec![false; w * h];
    for i in 0..9 {
        stair[i * w + i] = true;
        stair[i * w + i + 1] = true;
    }
    assert_eq!(band_width(&stair, w, h), 1);
}

fn finite_everywhere(name: &str, scene: &Scene) {
    for shading in ShadingMode::ALL_MODES {
        for filter in [ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Poisson] {
            let mut s = scene.clone();
            for l in &mut s.lights {
                l.shadow.filter = filter;
            }
            let img = render_image(gpu(), &s, 320, 180, &RenderSettings::new(shading, SpecularModel::CookTorrance))
                .expect("upload");
            assert_eq!(img.nonfinite_count(), 0, "{name}, {shading}, {filter:?}");
            assert!(img.pixels.iter().all(|p| p.iter().all(|c| *c >= 0.0)), "{name}, {shading}, {filter:?}");
        }
    }
}

#[test]
fn degenerate_shadow_setups_give_finite_images() {
    // A point light inside the sphere: the sphere hides it from everything.
    let mut inside = single_shape_scene("sphere", Shape::Sphere, 64);
    inside.lights = vec![Light::point(DVec3::new(0.0, 1.0, 0.0), [1.0; 3], 2.0, 0.05)];
    finite_everywhere("light inside an object", &inside);

    // Point and spot lights exactly on the ground's surface.
    let mut on_surface = single_shape_scene("sphere", Shape::Sphere, 64);
    on_surface.lights = vec![
        Light::point(DVec3::new(1.5, 0.0, 1.0), [1.0; 3], 2.0, 0.05),
        Light::spot(DVec3::new(-1.5, 0.0, 1.0), DVec3::new(0.3, 0.0, -1.0), [1.0; 3], 2.0, 0.05, (0.3, 0.6)),
    ];
    finite_everywhere("light on a surface", &on_surface);

    // All geometry in one plane (two coplanar planes), the light parallel to it.
    let mut flat = single_shape_scene("plane", Shape::Plane, 4);
    flat.objects[1].transform.translation = DVec3::ZERO;
    flat.objects.push(Object {
        name: "second plane".into(),
        shape: Shape::Plane,
        tessellation: 4,
        transform: Transform { translation: DVec3::new(0.5, 0.0, 0.5), rotation_y: 0.7, scale: DVec3::splat(1.0) },
        material: 0,
    });
    flat.lights = vec![
        Light::directional(DVec3::new(1.0, 0.0, 0.3), [1.0; 3], 1.0),
        Light::point(DVec3::new(0.0, 0.0, 3.0), [1.0; 3], 2.0, 0.05),
    ];
    finite_everywhere("coplanar geometry, light in its plane", &flat);

    // A huge scene: the ground a thousand times larger, the light far away.
    let mut huge = single_shape_scene("sphere", Shape::Sphere, 64);
    huge.objects[0].transform.scale *= 1000.0;
    huge.lights = vec![Light::directional(DVec3::new(-0.3, -1.0, -0.2), [1.0; 3], 1.0)];
    finite_everywhere("huge scene", &huge);
}

/// A scene large relative to the view (`field`): with cascades the sun's shadow agrees with the
/// exact shadow rays on more pixels than one map fitted to the whole scene does, at the same map
/// side. Measured at 640×360, 1024 pcf: about 0.5 % of pixels disagree with cascades, 2 % without.
#[test]
fn cascades_bring_a_large_scene_closer_to_the_exact_shadows() {
    let (w, h) = (640, 360);
    let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let mut scene = Scene::builtin("field").expect("built-in");
    for l in &mut scene.lights {
        l.shadow.resolution = 1024;
    }
    assert_eq!(shadelab_model::shadows::cascade_count(&scene), 2);
    let reference = render_reference(&scene, SpecularModel::CookTorrance, w, h);
    let mut off_scene = scene.clone();
    off_scene.set_shadows(false);
    let off = render_image(gpu(), &off_scene, w, h, &settings).expect("upload");
    let share = |cascades: bool| {
        let mut s = scene.clone();
        for l in &mut s.lights {
            l.shadow.cascades = cascades;
        }
        let img = render_image(gpu(), &s, w, h, &settings).expect("upload");
        assert_eq!(img.nonfinite_count(), 0);
        shadow_disagreement(&img, &off, &reference).stats.share_disagreeing
    };
    let (with, without) = (share(true), share(false));
    eprintln!("field 1024 pcf: {:.3} % disagree with cascades, {:.3} % with one map", 100.0 * with, 100.0 * without);
    assert!(with < 0.6 * without, "cascades {with} vs one map {without}");
    assert!(with < 0.01, "{with}");
}
