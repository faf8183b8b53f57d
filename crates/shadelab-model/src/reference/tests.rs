//! Tests of the reference image: it sees the scene, and its cast shadows are exact (a sphere's
//! disk-shaped shadow, a light shut inside a shape, no acne, degenerate setups stay finite).

use super::*;
use crate::lighting::lights::Light;
use crate::mesh::{TriangleMesh, triangles};
use crate::scene::{Camera, Material, Object, Shape, Transform};
use glam::{DVec3, DVec4};

#[test]
fn reference_render_sees_the_scene() {
    let scene = Scene::builtin("default").unwrap();
    let img = render_reference(&scene, SpecularModel::CookTorrance, 64, 36);
    assert!(img.pixels.iter().all(|p| p.iter().all(|c| c.is_finite() && *c >= 0.0)));
    let seen: std::collections::HashSet<_> = img.object.iter().flatten().collect();
    assert!(seen.len() >= 6, "objects seen: {seen:?}");
    assert_eq!(img.get(0, 0), crate::scene::BACKGROUND);
}

const GROUND: usize = 0;
const WHITE: [f64; 3] = [1.0; 3];

pub(super) fn object(name: &str, shape: Shape, translation: DVec3, scale: DVec3) -> Object {
    Object { name: name.into(), shape, tessellation: 16, transform: Transform::new(translation, scale), material: 0 }
}

/// A 4 × 4 ground plane at y = 0 (object 0), the given objects and lights, seen obliquely from
/// the front and above.
pub(super) fn stage(objects: Vec<Object>, lights: Vec<Light>) -> Scene {
    let mut all = vec![object("ground", Shape::Plane, DVec3::ZERO, DVec3::new(4.0, 1.0, 4.0))];
    all.extend(objects);
    Scene {
        objects: all,
        materials: vec![Material::default()],
        lights,
        ..Scene::empty(
            "stage".into(),
            [0.1; 3],
            Camera {
                eye: DVec3::new(0.0, 4.0, 6.0),
                target: DVec3::new(0.0, 0.0, 0.0),
                up: DVec3::Y,
                fov_y_deg: 30.0,
                near: 0.1,
                far: 50.0,
                orthographic: None,
            },
        )
    }
}

pub(super) fn all_finite(img: &ReferenceImage) -> bool {
    img.pixels.iter().chain(&img.unshadowed).all(|p| p.iter().all(|c| c.is_finite() && *c >= 0.0))
}

/// Where the camera ray of pixel `(x, y)` meets the plane y = 0.
pub(super) fn ground_point(cam: &Camera, x: u32, y: u32, w: u32, h: u32) -> Option<DVec3> {
    let (o, d) = cam.ray(x, y, w, h);
    (d.y < 0.0).then(|| o - d * (o.y / d.y))
}

/// Area in pixels of the image of the circle of radius `r` about the origin in the plane
/// y = 0 (its projection sampled at 1440 points, shoelace formula).
fn projected_disk_area(cam: &Camera, r: f64, w: u32, h: u32) -> f64 {
    let m = cam.projection(w as f64 / h as f64) * cam.view();
    let pts: Vec<(f64, f64)> = (0..1440)
        .map(|k| {
            let a = k as f64 / 1440.0 * std::f64::consts::TAU;
            let c = m * DVec4::new(r * a.cos(), 0.0, r * a.sin(), 1.0);
            ((c.x / c.w + 1.0) * 0.5 * w as f64, (1.0 - c.y / c.w) * 0.5 * h as f64)
        })
        .collect();
    let twice: f64 = (0..pts.len())
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum();
    0.5 * twice.abs()
}

/// A sphere of radius 0.5 centred 1.5 above the ground, lit from straight above, casts a disk of
/// radius `radius` about the origin. The shadowed ground pixels are exactly those whose ground
/// point lies in the disk (at most 2 differ: centres within the ray offset of the edge), and
/// their count is the disk's projected area within 1 %: the edge crosses about 400 pixels, each
/// counted whole or not at all, and those errors (each under ±0.5 pixel) mostly cancel.
fn assert_disk_shadow(light: Light, radius: f64) {
    let (w, h) = (640, 360);
    let sphere = object("ball", Shape::Sphere, DVec3::new(0.0, 1.5, 0.0), DVec3::splat(0.5));
    let scene = stage(vec![sphere], vec![light]);
    let img = render_reference(&scene, SpecularModel::CookTorrance, w, h);
    assert!(all_finite(&img));
    let (mut shadowed, mut in_disk, mut differ) = (0usize, 0usize, 0usize);
    for y in 0..h {
        for x in 0..w {
            if img.object_at(x, y) != Some(GROUND) {
                continue;
            }
            let p = ground_point(&scene.camera, x, y, w, h).unwrap();
            let (s, d) = (img.hidden_at(x, y) & 1 != 0, p.x * p.x + p.z * p.z < radius * radius);
            shadowed += s as usize;
            in_disk += d as usize;
            differ += (s != d) as usize;
        }
    }
    let area = projected_disk_area(&scene.camera, radius, w, h);
    assert!(differ <= 2, "{differ} ground pixels disagree with the disk ({shadowed} shadowed, {in_disk} in the disk)");
    assert!(
        (shadowed as f64 - area).abs() <= 0.01 * area,
        "{shadowed} shadowed pixels vs the disk's projected area {area:.1}"
    );
    assert!(area > 3000.0, "the disk is too small in the image to test: {area:.1} pixels");
}

#[test]
fn a_sphere_lit_from_above_casts_a_disk_of_its_radius() {
    assert_disk_shadow(Light::directional(DVec3::NEG_Y, WHITE, 1.0), 0.5);
}

/// From a point or spot light at height 3 straight above the centre (1.5 above it), the tangent
/// cone has sin θ = 0.5 / 1.5, and the shadow is a disk of radius 3 tan θ on the ground.
#[test]
fn a_sphere_under_a_point_or_spot_light_casts_the_tangent_cone_disk() {
    let radius = 3.0 * (0.5f64 / 1.5).asin().tan();
    let at = DVec3::new(0.0, 3.0, 0.0);
    assert_disk_shadow(Light::point(at, WHITE, 1.0, 0.0), radius);
    let cones = (60f64.to_radians(), 80f64.to_radians());
    assert_disk_shadow(Light::spot(at, DVec3::NEG_Y, WHITE, 1.0, 0.0, cones), radius);
}

/// The shapes that close a volume, as analytic shapes and as a file's mesh.
fn closed_shapes() -> Vec<(Shape, Vec<TriangleMesh>)> {
    let ball = TriangleMesh::from_soup("ball", &triangles(Shape::Sphere, 24), None);
    vec![
        (Shape::Sphere, vec![]),
        (Shape::Cube, vec![]),
        (Shape::Cylinder, vec![]),
        (Shape::Pyramid, vec![]),
        (Shape::Mesh(0), vec![ball]),
    ]
}

/// A point light at the centre of a closed shape lights nothing: outside, every ray to it
/// crosses the shape (cast shadow); the shape's own outside faces away from it (N·L < 0). The
/// image equals the same scene with no lights, bit for bit, while without shadows the light
/// reaches the ground and the other object.
#[test]
fn a_light_inside_a_closed_shape_shadows_everything_outside_it() {
    for (shape, meshes) in closed_shapes() {
        let centre = DVec3::new(0.3, 1.0, 0.2);
        let shell = object("shell", shape, centre, DVec3::new(0.6, 0.5, 0.7));
        let other = object("box", Shape::Cube, DVec3::new(-1.6, 0.4, -0.5), DVec3::splat(0.4));
        let mut scene = stage(vec![shell, other], vec![Light::point(centre, WHITE, 2.0, 0.1)]);
        scene.meshes = meshes.into();
        let img = render_reference(&scene, SpecularModel::CookTorrance, 320, 180);
        assert!(all_finite(&img), "{shape:?}");
        let mut dark = scene.clone();
        dark.lights.clear();
        let unlit = render_reference(&dark, SpecularModel::CookTorrance, 320, 180);
        let wrong = img.pixels.iter().zip(&unlit.pixels).filter(|(a, b)| a != b).count();
        assert_eq!(wrong, 0, "{shape:?}: {wrong} pixels get light from inside the shape");
        let hidden = img.hidden.iter().filter(|&&b| b != 0).count();
        let reached = img.unshadowed.iter().zip(&unlit.pixels).filter(|(a, b)| a != b).count();
        assert_eq!(hidden, reached, "{shape:?}: hidden pixels vs pixels the light reaches without shadows");
        assert!(hidden > 10_000, "{shape:?}: only {hidden} pixels would be lit without shadows");
    }
}

/// Convex shapes never shadow themselves, and a bare plane is never shadowed, for light down to
/// grazing elevations: the ray offset keeps every start point off its own surface (no acne).
#[test]
fn nothing_shadows_itself_down_to_grazing_light() {
    for shape in [Shape::Sphere, Shape::Cube, Shape::Cylinder, Shape::Pyramid] {
        for elevation_deg in [90.0, 45.0, 20.0, 5.0, 1.0, 0.1f64] {
            for azimuth_deg in [0.0, 35.0, 120.0f64] {
                let (e, a) = (elevation_deg.to_radians(), azimuth_deg.to_radians());
                let dir = -DVec3::new(e.cos() * a.cos(), e.sin(), e.cos() * a.sin());
                let solid = object("solid", shape, DVec3::new(0.2, 0.8, -0.1), DVec3::new(0.7, 0.55, 0.6));
                let mut scene = stage(vec![solid], vec![Light::directional(dir, WHITE, 1.0)]);
                scene.objects[GROUND].transform.translation.y = -100.0; // out of the way
                let img = render_reference(&scene, SpecularModel::CookTorrance, 160, 90);
                let hidden = img.hidden.iter().filter(|&&b| b != 0).count();
                assert_eq!(hidden, 0, "{shape:?} at elevation {elevation_deg}°, azimuth {azimuth_deg}°");
                let plane = stage(vec![], vec![Light::directional(dir, WHITE, 1.0)]);
                let img = render_reference(&plane, SpecularModel::CookTorrance, 160, 90);
                assert!(img.hidden.iter().all(|&b| b == 0), "plane at elevation {elevation_deg}°");
            }
        }
    }
}

/// A light exactly on a surface, and all geometry in one plane with the light in or parallel to
/// it: finite, non-negative output, both with and without shadows.
#[test]
fn degenerate_shadow_setups_stay_finite() {
    let ball = || object("ball", Shape::Sphere, DVec3::new(0.0, 0.5, 0.0), DVec3::splat(0.5));
    let cones = (0.3, 0.6);
    let on_surface = [
        Light::point(DVec3::ZERO, WHITE, 1.0, 0.0),
        Light::point(DVec3::new(0.0, 1.0, 0.0), WHITE, 1.0, 0.0),
        Light::spot(DVec3::new(0.5, 0.5, 0.0), DVec3::X, WHITE, 1.0, 0.0, cones),
        Light::spot(DVec3::new(1.0, 0.0, 0.0), DVec3::NEG_Y, WHITE, 1.0, 0.0, cones),
    ];
    for light in on_surface {
        let img = render_reference(&stage(vec![ball()], vec![light.clone()]), SpecularModel::Phong, 160, 90);
        assert!(all_finite(&img), "light on a surface: {light:?}");
    }
    let flat = TriangleMesh::from_soup(
        "flat",
        &[[DVec3::new(-1.0, 0.0, 1.0), DVec3::new(1.0, 0.0, 1.0), DVec3::new(0.0, 0.0, -1.0)]],
        None,
    );
    let parallel = [
        Light::directional(DVec3::X, WHITE, 1.0),
        Light::directional(DVec3::new(1.0, -1e-12, 0.3), WHITE, 1.0),
        Light::point(DVec3::new(0.0, 0.0, -3.0), WHITE, 1.0, 0.0),
        Light::spot(DVec3::new(3.0, 0.0, 0.0), DVec3::NEG_X, WHITE, 1.0, 0.0, cones),
    ];
    for light in parallel {
        let coplanar = vec![
            object("sheet", Shape::Plane, DVec3::new(0.5, 0.0, 0.5), DVec3::splat(1.0)),
            object("flat", Shape::Mesh(0), DVec3::ZERO, DVec3::ONE),
        ];
        let mut scene = stage(coplanar, vec![light.clone()]);
        scene.meshes = vec![flat.clone()].into();
        for casts in [true, false] {
            scene.set_shadows(casts);
            let img = render_reference(&scene, SpecularModel::CookTorrance, 160, 90);
            assert!(all_finite(&img), "geometry in one plane, light {light:?}, shadows {casts}");
        }
    }
}

/// With `casts` off the reference is the unshadowed image bit for bit, and on the default scene
/// shadows do fall (the objects' contact shadows on the ground).
#[test]
fn shadows_off_is_the_unshadowed_image() {
    let mut scene = Scene::builtin("default").unwrap();
    let on = render_reference(&scene, SpecularModel::CookTorrance, 160, 90);
    scene.set_shadows(false);
    let off = render_reference(&scene, SpecularModel::CookTorrance, 160, 90);
    assert!(off.hidden.iter().all(|&b| b == 0));
    assert_eq!(off.pixels, off.unshadowed);
    assert_eq!(on.unshadowed, off.pixels);
    let shadowed_ground = (0..on.pixels.len()).filter(|&i| on.object[i] == Some(GROUND) && on.hidden[i] != 0).count();
    assert!(shadowed_ground > 100, "only {shadowed_ground} shadowed ground pixels in the default scene");
    for (i, (a, b)) in on.pixels.iter().zip(&off.pixels).enumerate() {
        assert_eq!(on.hidden[i] == 0, a == b, "pixel {i}: hidden {} but {a:?} vs {b:?}", on.hidden[i]);
    }
}

/// Each light's bit is its own: a light that does not cast never hides, one that does still
/// hides where the other one's shadow would fall too.
#[test]
fn the_hidden_bits_are_per_light() {
    let sphere = object("ball", Shape::Sphere, DVec3::new(0.0, 1.5, 0.0), DVec3::splat(0.5));
    let mut lights =
        vec![Light::directional(DVec3::NEG_Y, WHITE, 1.0), Light::point(DVec3::new(0.0, 3.0, 0.0), WHITE, 1.0, 0.0)];
    lights[0].shadow.casts = false;
    let img = render_reference(&stage(vec![sphere], lights), SpecularModel::CookTorrance, 160, 90);
    assert!(img.hidden.iter().all(|&b| b & 1 == 0));
    assert!(img.hidden.iter().filter(|&&b| b == 2).count() > 100);
}

#[test]
fn a_reference_traced_in_steps_is_the_same_image() {
    let scene = Scene::builtin("default").unwrap();
    // The default scene has no area light, so the scene as drawn is the reference.
    let whole = render_drawn(&scene, SpecularModel::CookTorrance, 48, 27);
    let mut job = ReferenceJob::new(&scene, SpecularModel::CookTorrance, 48, 27);
    let mut steps = 0;
    while !job.step(4) {
        steps += 1;
        assert!(job.progress() < 1.0);
    }
    assert_eq!(steps, 6, "27 rows in steps of 4: 6 steps before the last");
    assert_eq!(job.progress(), 1.0);
    let stepped = job.finish();
    assert_eq!(stepped.pixels, whole.pixels);
    assert_eq!(stepped.object, whole.object);
    assert_eq!(stepped.hidden, whole.hidden);
    assert_eq!(stepped.unshadowed, whole.unshadowed);
}

/// The objects' world boxes lose no hit: every shape, turned and stretched, and a mesh, met by
/// rays from all around and from inside, give the same nearest hit and the same occlusion with
/// the boxes as with boxes that admit every ray.
#[test]
fn the_objects_boxes_lose_no_hit() {
    let shapes = [Shape::Sphere, Shape::Cube, Shape::Cylinder, Shape::Pyramid, Shape::Plane, Shape::Mesh(0)];
    let mut objects = Vec::new();
    for (k, &shape) in shapes.iter().enumerate() {
        let at = DVec3::new(k as f64 - 2.5, 0.6 + 0.1 * k as f64, 0.3 * (k % 2) as f64);
        let mut o = object("shape", shape, at, DVec3::new(0.4, 0.7, 0.25));
        o.transform.rotation_y = 0.4 * k as f64;
        objects.push(o);
    }
    let mut scene = stage(objects, vec![]);
    scene.meshes = vec![TriangleMesh::from_soup("ball", &triangles(Shape::Sphere, 12), None)].into();
    let geo = Geometry::new(&scene);
    let open =
        Geometry { boxes: vec![(DVec3::NEG_INFINITY, DVec3::INFINITY); geo.boxes.len()], ..Geometry::new(&scene) };
    let mut rng = path::Rng::new(7, 0, 0);
    let mut unit = || 2.0 * rng.uniform() - 1.0;
    let (mut hits, mut blocked) = (0, 0);
    for _ in 0..20_000 {
        let o = DVec3::new(4.0 * unit(), 1.0 + 1.5 * unit(), 2.0 * unit());
        let dir = DVec3::new(unit(), unit(), unit());
        let t_max = 3.0 * (unit() + 1.0);
        let (a, b) = (intersect::trace(&scene, &geo, o, dir), intersect::trace(&scene, &open, o, dir));
        assert_eq!(a.as_ref().map(|h| (h.object, h.point)), b.as_ref().map(|h| (h.object, h.point)), "{o} {dir}");
        hits += usize::from(a.is_some());
        let occluded = intersect::occluded(&scene, &geo, o, dir, t_max);
        assert_eq!(occluded, intersect::occluded(&scene, &open, o, dir, t_max), "{o} {dir} {t_max}");
        blocked += usize::from(occluded);
    }
    // The rays must meet things for the comparison to mean anything.
    assert!(hits > 5_000 && blocked > 5_000, "{hits} hits, {blocked} blocked");
}

/// The shadow rays from one point to an area light's cells answer the same testing only the
/// objects near them (`cells_visible_from`) as testing every object (`cell_visible`), for each
/// area kind, from points on the ground and on a ball under it; some cells are hidden, some not.
#[test]
fn cell_rays_near_the_light_answer_as_rays_to_every_object() {
    use crate::lighting::area::front_cells;
    use crate::lighting::lights::LightKind;
    let objects = vec![
        object("ball", Shape::Sphere, DVec3::new(0.0, 0.6, 0.0), DVec3::splat(0.5)),
        object("box", Shape::Cube, DVec3::new(1.2, 0.3, -0.4), DVec3::new(0.3, 0.3, 0.5)),
        object("post", Shape::Cylinder, DVec3::new(-1.3, 0.8, 0.5), DVec3::new(0.2, 0.8, 0.2)),
    ];
    let spread = |i: u32, k: f64| (f64::from(i) * k).fract();
    let points: Vec<(DVec3, DVec3)> = (0..300)
        .map(|i| (DVec3::new(4.0 * spread(i, 0.618) - 2.0, 0.0, 4.0 * spread(i, 0.414) - 2.0), DVec3::Y))
        .chain((0..100).map(|i| {
            let n = DVec3::new(spread(i, 0.618) - 0.5, 0.3 + spread(i, 0.271), spread(i, 0.414) - 0.5).normalize();
            (DVec3::new(0.0, 0.6, 0.0) + n * 0.5, n)
        }))
        .collect();
    for kind in [LightKind::Rect, LightKind::Disk, LightKind::Sphere] {
        let light = Light::area(kind, DVec3::new(0.3, 2.5, 0.2), DVec3::NEG_Y, [1.2, 0.6], [1.0; 3], 1.0, 0.0);
        let area = light.area_light().unwrap();
        let scene = stage(objects.clone(), vec![light]);
        let geo = intersect::Geometry::new(&scene);
        let rays = shadow_rays::ShadowRays::new(&scene, &geo);
        let (mut hidden, mut cells) = (0, 0);
        for &(p, ng) in &points {
            let (near, every) = (rays.cells_visible_from(ng, p, &area), rays.cell_visible(ng));
            for (x, _, _) in front_cells(&area, p, 8) {
                let seen = near(p, x);
                assert_eq!(seen, every(p, x), "{kind:?}: from {p} to {x}");
                (hidden, cells) = (hidden + usize::from(!seen), cells + 1);
            }
        }
        assert!(hidden > 0 && hidden < cells, "{kind:?}: {hidden} of {cells} cells hidden");
    }
}
