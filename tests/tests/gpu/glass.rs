//! Transparent objects on lavapipe (docs/transparency.md): the glass pass against the reference's
//! Whitted tracer, the total-internal-reflection mask, the chapter's absorption rule against the
//! exact form, and the back-face exit against the analytic one.

use shadelab_model::lighting::transmission::{AbsorptionChoice, GlassExit, GlassView};
use shadelab_model::reference::render_reference;
use shadelab_model::scene::Scene;
use shadelab_model::{ShadingMode, Shape, SpecularModel};
use shadelab_render::{LinearImage, RenderSettings, render_image};
use shadelab_tests::{error, gpu, interior};

const W: u32 = 320;
const H: u32 = 180;

fn settings() -> RenderSettings {
    RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance)
}

fn glass() -> Scene {
    Scene::builtin("glass").unwrap()
}

fn object(scene: &Scene, name: &str) -> usize {
    scene.objects.iter().position(|o| o.name == name).unwrap()
}

/// Share of `pixels` where any channel of `a` and `b` differs by more than `by`.
fn share_off(a: &LinearImage, b: &shadelab_model::reference::ReferenceImage, pixels: &[(u32, u32)], by: f64) -> f64 {
    let off =
        pixels.iter().filter(|&&(x, y)| (0..3).any(|c| (a.get(x, y)[c] as f64 - b.get(x, y)[c]).abs() > by)).count();
    off as f64 / pixels.len().max(1) as f64
}

/// The glass scene's transparent solids match the reference's exact tracer on their inside
/// pixels: the sphere, whose exit is exact and whose paths never reflect totally, closely; the
/// slab and the cylinder, where the pass follows one path per exit and the tracer every branch,
/// within the light of the branches it drops. The opaque scene around them is unchanged.
#[test]
fn glass_matches_the_whitted_reference() {
    let scene = glass();
    let img = render_image(gpu(), &scene, W, H, &settings()).unwrap();
    let reference = render_reference(&scene, SpecularModel::CookTorrance, W, H);
    for (name, mean_max, share_max) in
        [("glass sphere", 0.02, 0.1), ("slab", 0.04, 0.2), ("absorbing cylinder", 0.04, 0.2)]
    {
        let pixels = interior(&reference, object(&scene, name));
        assert!(pixels.len() > 500, "{name}: {} pixels", pixels.len());
        let (mean, max, worst) = error(&img, &reference, &pixels);
        let off = share_off(&img, &reference, &pixels, 0.1);
        eprintln!("{name}: mean |error| {mean:.4}, max {max:.3} at {worst:?}, {:.1} % off by 0.1", off * 100.0);
        assert!(mean < mean_max, "{name}: mean |error| {mean}");
        assert!(off < share_max, "{name}: {:.1} % of pixels off by more than 0.1", off * 100.0);
    }
    let stripe = interior(&reference, object(&scene, "stripe 1"));
    let (mean, _, _) = error(&img, &reference, &stripe);
    assert!(mean < 2e-3, "the opaque wall: mean |error| {mean}");
}

/// Total internal reflection shows where it must: never in a sphere (a path leaves at the angle
/// it entered at), along the turned slab's sides, which the paths through its face meet beyond
/// the critical angle. And a slab of index 1 (no interface) has none.
#[test]
fn total_internal_reflection_shows_in_the_slab_not_in_the_sphere() {
    let mut scene = glass();
    let s = RenderSettings { glass_view: GlassView::Tir, ..settings() };
    let reference = render_reference(&scene, SpecularModel::CookTorrance, W, H);
    let red = |img: &LinearImage, pixels: &[(u32, u32)]| {
        pixels.iter().filter(|&&(x, y)| img.get(x, y) == [1.0, 0.15, 0.1, 1.0]).count()
    };
    let img = render_image(gpu(), &scene, W, H, &s).unwrap();
    let sphere = interior(&reference, object(&scene, "glass sphere"));
    let slab = interior(&reference, object(&scene, "slab"));
    assert_eq!(red(&img, &sphere), 0, "a sphere reflects no path totally");
    let n = red(&img, &slab);
    assert!(n > slab.len() / 10, "{n} of {} slab pixels reflect totally", slab.len());
    let i = scene.objects[object(&scene, "slab")].material;
    scene.materials[i].ior = Some([1.0; 3]);
    let img = render_image(gpu(), &scene, W, H, &s).unwrap();
    assert_eq!(red(&img, &slab), 0, "index 1: no interface to reflect at");
}

/// The absorbing cylinder alone with a·d up to just under 0.2 and just under 0.5: the rule's image
/// (neglected, then 1 − a·d) differs from the exact one by no more than the chapter's bounds allow,
/// 1 − e^(−0.2) = 18.1 % and e^(−0.5) − 0.5 = 0.107 of the light through, and by something.
#[test]
fn the_absorption_rule_errs_within_the_chapters_bounds() {
    let mut scene = glass();
    let cyl = object(&scene, "absorbing cylinder");
    let chord = shadelab_model::effects::longest_chord(&scene, cyl);
    let mi = scene.objects[cyl].material;
    let pixels = interior(&render_reference(&scene, SpecularModel::CookTorrance, W, H), cyl);
    for (ad, bound) in [(0.19, 1.0 - (-0.2f64).exp()), (0.49, (-0.5f64).exp() - 0.5)] {
        scene.materials[mi].absorption = [ad / chord; 3];
        let mut at = |choice| {
            scene.absorption = choice;
            render_image(gpu(), &scene, W, H, &settings()).unwrap()
        };
        let (rule, exact) = (at(AbsorptionChoice::Rule), at(AbsorptionChoice::Exact));
        scene.materials[mi].absorption = [0.0; 3];
        let clear = render_image(gpu(), &scene, W, H, &settings()).unwrap();
        let mut worst = 0.0f64;
        let mut total = 0.0;
        for &(x, y) in &pixels {
            for c in 0..3 {
                let d = (rule.get(x, y)[c] - exact.get(x, y)[c]).abs() as f64;
                // What comes through is at most the unabsorbed image.
                worst = worst.max(d - bound * clear.get(x, y)[c] as f64);
                total += d;
            }
        }
        eprintln!("a·d ≤ {ad}: rule − exact mean {:.4}", total / (3 * pixels.len()) as f64);
        assert!(worst <= 1e-4, "a·d ≤ {ad}: the rule errs past the chapter's bound by {worst}");
        assert!(total > 0.0, "a·d ≤ {ad}: the rule changed nothing");
    }
}

/// The back-face exit draws the same solids as the analytic one, less exactly: a path's exit is
/// looked up where the view's depth through the object puts it.
#[test]
fn back_faces_approach_the_analytic_exit() {
    let scene = glass();
    let reference = render_reference(&scene, SpecularModel::CookTorrance, W, H);
    let analytic = render_image(gpu(), &scene, W, H, &settings()).unwrap();
    let back =
        render_image(gpu(), &scene, W, H, &RenderSettings { glass_exit: GlassExit::BackFaces, ..settings() }).unwrap();
    let pixels = interior(&reference, object(&scene, "glass sphere"));
    let (a, _, _) = error(&analytic, &reference, &pixels);
    let (b, _, _) = error(&back, &reference, &pixels);
    eprintln!("sphere mean |error|: analytic {a:.4}, back faces {b:.4}");
    assert!(b < 0.04, "back faces: mean |error| {b}");
    assert!(a <= b, "the analytic exit is the exact one");
}

/// A scene without transparent objects has no glass pass: its program holds none of the glass
/// effects, and the pass has nothing to draw.
#[test]
fn an_opaque_scene_has_no_glass_pass() {
    use shadelab_model::effects::Effect;
    use shadelab_render::Program;
    for name in ["default", "sphere", "penumbra"] {
        let scene = Scene::builtin(name).unwrap();
        let fx = Program::for_scene(&scene, &settings()).effects();
        assert!(!fx.has(Effect::Transmission) && !fx.has(Effect::Refraction) && !fx.has(Effect::Absorption));
        assert!(shadelab_render::glass_pass::glass_order(&scene).is_empty());
    }
    let scene = glass();
    assert_eq!(shadelab_render::glass_pass::glass_order(&scene).len(), 3);
    assert!(Program::for_scene(&scene, &settings()).effects().has(Effect::Transmission));
    // Far to near: the slab (nearest the eye's line) after the two farther solids.
    let order = shadelab_render::glass_pass::glass_order(&scene);
    let eye = scene.camera.eye;
    let dist = |i: usize| scene.objects[i].transform.translation.distance(eye);
    assert!(order.windows(2).all(|w| dist(w[0]) >= dist(w[1])));
    assert!(order.iter().all(|&i| scene.objects[i].shape != Shape::Plane));
}

/// A file's mesh has no analytic exit: the glass pass finds it from the mesh's back faces, the
/// reference by meeting its triangles from inside. The slab and the sphere as meshes match the
/// reference about as the back-face exit of the analytic shapes does.
#[test]
fn a_glass_mesh_exits_through_its_back_faces() {
    use shadelab_model::mesh::{TriangleMesh, triangles};
    let mut scene = glass();
    for (name, shape, tessellation) in [("slab", Shape::Cube, 1), ("glass sphere", Shape::Sphere, 48)] {
        let i = object(&scene, name);
        let tris = triangles(shape, tessellation);
        scene.meshes.push(TriangleMesh::from_soup(name, &tris, None));
        scene.objects[i].shape = Shape::Mesh(scene.meshes.len() - 1);
    }
    let img = render_image(gpu(), &scene, W, H, &settings()).unwrap();
    let reference = render_reference(&scene, SpecularModel::CookTorrance, W, H);
    for (name, mean_max) in [("slab", 0.06), ("glass sphere", 0.06)] {
        let pixels = interior(&reference, object(&scene, name));
        let (mean, _, _) = error(&img, &reference, &pixels);
        eprintln!("{name} as a mesh: mean |error| {mean:.4}");
        assert!(pixels.len() > 500 && mean < mean_max, "{name} as a mesh: mean |error| {mean}");
    }
}

/// Rays through glass that meet nothing see the environment where it is the background, on the
/// GPU as in its f64 twin: the glass sphere alone before the sky, within the sphere's bound of
/// the whole scene's comparison above. Against the constant background the sky through it is
/// far off.
#[test]
fn glass_shows_the_environment_behind_it() {
    use shadelab_model::lighting::env_map::{EnvSource, Environment};
    let mut scene = glass();
    scene.objects = vec![scene.objects[object(&scene, "glass sphere")].clone()];
    let sky = Environment { background: true, ..Environment::new(EnvSource::Sky { turbidity: 3.0, sun: None }) };
    scene.environment = Some(sky);
    let img = render_image(gpu(), &scene, W, H, &settings()).unwrap();
    let reference = render_reference(&scene, SpecularModel::CookTorrance, W, H);
    let pixels = interior(&reference, 0);
    assert!(pixels.len() > 500, "{} sphere pixels", pixels.len());
    let (mean, max, worst) = error(&img, &reference, &pixels);
    eprintln!("glass sphere before the sky: mean |error| {mean:.4}, max {max:.3} at {worst:?}");
    assert!(mean < 0.02, "mean |error| {mean}");
    scene.environment.as_mut().unwrap().background = false;
    let plain = render_reference(&scene, SpecularModel::CookTorrance, W, H);
    let (apart, _, _) = error(&img, &plain, &pixels);
    assert!(apart > 0.05, "the sky shows through the glass: {apart} from the constant background");
}
