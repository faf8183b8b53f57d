//! The scenes compiled into the binary: the default scene and the single-shape scenes the f64
//! reference knows exactly, with their camera, lights and materials.

use super::{Camera, Light, Material, Object, Scene, Shape, Transform};
use crate::params::PhongExponent;
use glam::DVec3;

/// Names of the scenes compiled into the binary.
pub const BUILTIN_SCENES: &[&str] =
    &["default", "sphere", "cylinder", "pyramid", "cube", "field", "penumbra", "glass", "cornell"];

impl Scene {
    /// A built-in scene by name (see [`BUILTIN_SCENES`]).
    pub fn builtin(name: &str) -> Option<Scene> {
        match name {
            "default" => Some(default_scene()),
            "sphere" => Some(single_shape_scene("sphere", Shape::Sphere, 16)),
            "cylinder" => Some(single_shape_scene("cylinder", Shape::Cylinder, 16)),
            "pyramid" => Some(single_shape_scene("pyramid", Shape::Pyramid, 1)),
            "cube" => Some(single_shape_scene("cube", Shape::Cube, 1)),
            "field" => Some(field_scene()),
            "penumbra" => Some(penumbra_scene(PENUMBRA_PLATE_HEIGHT)),
            "glass" => Some(glass_scene()),
            "cornell" => Some(super::cornell::cornell_scene()),
            _ => None,
        }
    }
}

/// Height of the `penumbra` scene's plate above the ground, m.
pub const PENUMBRA_PLATE_HEIGHT: f64 = 0.5;
/// Height of the `penumbra` scene's light above the ground, m.
pub const PENUMBRA_LIGHT_HEIGHT: f64 = 2.5;
/// Side of the `penumbra` scene's square light, m.
pub const PENUMBRA_LIGHT_SIZE: f64 = 0.5;
/// Half the side of the `penumbra` scene's square plate, m.
pub const PENUMBRA_PLATE_HALF: f64 = 0.5;

/// The `penumbra` scene (docs/area-lights.md): a thin square plate `plate_height` above the
/// ground, under a square light facing down `PENUMBRA_LIGHT_HEIGHT` above it, so the plate's
/// shadow has a penumbra of width `size·h/(H − h)` by similar triangles on every side.
pub fn penumbra_scene(plate_height: f64) -> Scene {
    let (ground_obj, ground_mat) = ground();
    let plate =
        Material { name: "plate".into(), color: [0.6, 0.55, 0.5], m: 0.4, h: h_like_m(0.4), ..Material::default() };
    let half = PENUMBRA_PLATE_HALF;
    let size = PENUMBRA_LIGHT_SIZE;
    let mut light = Light::area(
        crate::params::LightKind::Rect,
        DVec3::new(0.0, PENUMBRA_LIGHT_HEIGHT, 0.0),
        DVec3::NEG_Y,
        [size, size],
        [1.0, 0.97, 0.92],
        1.2,
        0.0,
    );
    light.tangent = DVec3::X;
    Scene {
        absorption: Default::default(),
        name: "penumbra".into(),
        objects: vec![
            ground_obj,
            Object {
                name: "plate".into(),
                shape: Shape::Cube,
                tessellation: 1,
                transform: Transform::new(DVec3::new(0.0, plate_height, 0.0), DVec3::new(half, 0.01, half)),
                material: 1,
            },
        ],
        materials: vec![ground_mat, plate],
        lights: vec![light],
        ambient: [0.08; 3],
        camera: Camera { eye: DVec3::new(1.3, 2.1, 2.6), target: DVec3::new(0.2, 0.15, 0.0), ..default_camera() },
        ..default_scene()
    }
}

/// The `glass` scene (docs/transparency.md): three transparent solids in front of a wall of
/// coloured stripes, so that refraction shows as the stripes bent and flipped. A clear glass
/// sphere (v = 1.5); a slab turned 50° about y, through which a view entering its face meets a
/// side beyond the critical angle (total internal reflection); and an absorbing cylinder that
/// takes blue and green more than red, with a·d near 1 across it (the rule's exact regime). One
/// point light; no cast shadows (glass casts a full shadow, which would hide the stripes).
pub fn glass_scene() -> Scene {
    let (ground_obj, ground_mat) = ground();
    let mut objects = vec![ground_obj];
    let mut materials = vec![ground_mat];
    let stripe = |name: &str, color: [f64; 3]| Material {
        name: name.into(),
        color,
        r_s: 0.2,
        r_d: 0.9,
        r_a: 0.9,
        m: 0.6,
        h: h_like_m(0.6),
        ..Material::default()
    };
    materials.push(stripe("stripe light", [0.85, 0.82, 0.72]));
    materials.push(stripe("stripe dark", [0.12, 0.22, 0.55]));
    // Twelve stripes 0.3 m wide, 1.6 m tall, on a wall 1.2 m behind the solids.
    for i in 0..12 {
        objects.push(Object {
            name: format!("stripe {}", i + 1),
            shape: Shape::Cube,
            tessellation: 1,
            transform: Transform::new(DVec3::new(-1.65 + 0.3 * i as f64, 0.8, -1.3), DVec3::new(0.15, 0.8, 0.05)),
            material: 1 + i % 2,
        });
    }
    let glass = |name: &str, color: [f64; 3], absorption: [f64; 3]| Material {
        name: name.into(),
        color,
        r_s: 1.0,
        r_d: 0.8,
        r_a: 0.8,
        m: 0.08,
        h: h_like_m(0.08),
        mu: [0.04; 3],
        transmission: 0.95,
        absorption,
        ..Material::default()
    };
    let solids = [
        ("glass sphere", Shape::Sphere, DVec3::new(-1.1, 0.5, 0.0), DVec3::splat(0.5), 0.0, [0.0; 3]),
        ("slab", Shape::Cube, DVec3::new(0.15, 0.55, 0.1), DVec3::new(0.4, 0.55, 0.12), 50f64.to_radians(), [0.0; 3]),
        (
            "absorbing cylinder",
            Shape::Cylinder,
            DVec3::new(1.2, 0.5, 0.0),
            DVec3::new(0.35, 0.5, 0.35),
            0.0,
            [0.4, 1.2, 2.0],
        ),
    ];
    for (name, shape, at, size, turn, absorption) in solids {
        materials.push(glass(name, [0.9; 3], absorption));
        objects.push(Object {
            name: name.into(),
            shape,
            tessellation: 32,
            transform: Transform { translation: at, rotation_y: turn, scale: size },
            material: materials.len() - 1,
        });
    }
    let mut light = Light::point(DVec3::new(-1.5, 3.0, 2.5), [1.0, 0.98, 0.95], 1.3, 0.04);
    light.shadow.casts = false;
    Scene {
        name: "glass".into(),
        objects,
        materials,
        lights: vec![light],
        ambient: [0.25; 3],
        camera: Camera { eye: DVec3::new(0.0, 1.3, 4.2), target: DVec3::new(0.0, 0.55, 0.0), ..default_camera() },
        ..default_scene()
    }
}

/// The Phong exponent that gives a lobe about as wide as Beckmann roughness `m`
/// (`h = 2/m² − 2`, the usual Beckmann–Phong correspondence), rounded.
fn h_like_m(m: f64) -> PhongExponent {
    PhongExponent::from_m(m).rounded()
}

pub(super) fn default_camera() -> Camera {
    Camera {
        eye: DVec3::new(0.0, 2.1, 5.2),
        target: DVec3::new(0.0, 0.35, -0.4),
        up: DVec3::Y,
        fov_y_deg: 40.0,
        near: 0.1,
        far: 50.0,
        orthographic: None,
    }
}

fn default_lights() -> Vec<Light> {
    vec![
        Light::directional(DVec3::new(-0.55, -1.0, -0.7), [1.0, 0.97, 0.92], 0.75),
        Light::point(DVec3::new(-2.2, 2.4, 2.4), [0.92, 0.96, 1.0], 1.1, 0.06),
    ]
}

fn ground() -> (Object, Material) {
    (
        Object {
            name: "ground".into(),
            shape: Shape::Plane,
            tessellation: 16,
            transform: Transform::new(DVec3::ZERO, DVec3::new(5.0, 1.0, 3.6)),
            material: 0,
        },
        Material {
            name: "ground".into(),
            color: [0.32, 0.32, 0.3],
            r_s: 0.25,
            r_d: 0.8,
            r_a: 0.8,
            m: 0.5,
            h: PhongExponent::Finite(6.0),
            mu: [0.04; 3],
            ..Material::default()
        },
    )
}

/// The default scene: a row of red plastic spheres going from sharp to rough (m increasing, h
/// decreasing alike), a gold cylinder and a stone pyramid on a ground plane, with a directional
/// key light and a point light.
pub fn default_scene() -> Scene {
    let (ground_obj, ground_mat) = ground();
    let mut objects = vec![ground_obj];
    let mut materials = vec![ground_mat];
    for (i, m) in [0.08, 0.15, 0.25, 0.4, 0.7].into_iter().enumerate() {
        materials.push(Material {
            name: format!("plastic m={m}"),
            color: [0.75, 0.12, 0.08],
            r_s: 1.0,
            r_d: 0.8,
            r_a: 0.8,
            m,
            h: h_like_m(m),
            mu: [0.04; 3],
            ..Material::default()
        });
        objects.push(Object {
            name: format!("sphere {}", i + 1),
            shape: Shape::Sphere,
            tessellation: 16,
            transform: Transform::new(DVec3::new(-2.0 + i as f64, 0.42, 0.7), DVec3::splat(0.42)),
            material: materials.len() - 1,
        });
    }
    materials.push(Material {
        name: "gold".into(),
        color: [1.0, 0.766, 0.336],
        r_s: 1.0,
        r_d: 0.25,
        r_a: 0.5,
        m: 0.2,
        h: h_like_m(0.2),
        // Gold's reflectance at normal incidence (linear sRGB), Filament's material table.
        mu: [1.0, 0.766, 0.336],
        ..Material::default()
    });
    objects.push(Object {
        name: "cylinder".into(),
        shape: Shape::Cylinder,
        tessellation: 16,
        transform: Transform::new(DVec3::new(-1.5, 0.7, -1.1), DVec3::new(0.45, 0.7, 0.45)),
        material: materials.len() - 1,
    });
    materials.push(Material {
        name: "stone".into(),
        color: [0.82, 0.8, 0.74],
        r_s: 0.4,
        r_d: 0.85,
        r_a: 0.8,
        m: 0.3,
        h: h_like_m(0.3),
        mu: [0.05; 3],
        ..Material::default()
    });
    objects.push(Object {
        name: "pyramid".into(),
        shape: Shape::Pyramid,
        tessellation: 1,
        transform: Transform {
            translation: DVec3::new(1.5, 0.65, -1.1),
            rotation_y: 30f64.to_radians(),
            scale: DVec3::splat(0.65),
        },
        material: materials.len() - 1,
    });
    Scene {
        objects,
        materials,
        lights: default_lights(),
        ..Scene::empty("default".into(), [0.12; 3], default_camera())
    }
}

/// A scene large relative to the view: the default scene's objects on an 80 m field, with two
/// rows of stone posts going 36 m away, under a low sun alone. The objects in view span depths
/// 3.3 m to 40 m, a ratio over 8 (docs/model.md §6), so the sun's shadow gets two cascades.
pub fn field_scene() -> Scene {
    let mut s = default_scene();
    s.name = "field".into();
    s.objects[0].transform.scale = DVec3::new(40.0, 1.0, 40.0);
    s.objects[0].tessellation = 32;
    let stone = s.materials.iter().position(|m| m.name == "stone").unwrap_or(0);
    for i in 0..9 {
        for x in [-3.0, 3.0] {
            s.objects.push(Object {
                name: format!("post {}{}", if x < 0.0 { "L" } else { "R" }, i + 1),
                shape: Shape::Cube,
                tessellation: 1,
                transform: Transform::new(DVec3::new(x, 1.2, -4.0 - 4.0 * i as f64), DVec3::new(0.3, 1.2, 0.3)),
                material: stone,
            });
        }
    }
    s.lights = vec![Light::directional(DVec3::new(-0.6, -0.45, -0.65), [1.0, 0.95, 0.88], 0.9)];
    s
}

/// One shape on the ground, lit by the default lights: the scenes the reference knows exactly.
pub fn single_shape_scene(name: &str, shape: Shape, tessellation: u32) -> Scene {
    let (ground_obj, ground_mat) = ground();
    let material = Material {
        name: "blue plastic".into(),
        color: [0.15, 0.3, 0.8],
        m: 0.2,
        h: h_like_m(0.2),
        ..Material::default()
    };
    let (translation, scale, rotation_y) = match shape {
        Shape::Cylinder => (DVec3::new(0.0, 0.9, 0.0), DVec3::new(0.7, 0.9, 0.7), 0.0),
        Shape::Pyramid => (DVec3::new(0.0, 0.9, 0.0), DVec3::splat(0.9), 30f64.to_radians()),
        Shape::Cube => (DVec3::new(0.0, 0.7, 0.0), DVec3::splat(0.7), 30f64.to_radians()),
        _ => (DVec3::new(0.0, 1.0, 0.0), DVec3::splat(1.0), 0.0),
    };
    Scene {
        objects: vec![
            ground_obj,
            Object {
                name: name.into(),
                shape,
                tessellation,
                transform: Transform { translation, rotation_y, scale },
                material: 1,
            },
        ],
        materials: vec![ground_mat, material],
        lights: default_lights(),
        ..Scene::empty(
            name.into(),
            [0.12; 3],
            Camera { eye: DVec3::new(0.0, 2.2, 4.6), target: DVec3::new(0.0, 0.8, 0.0), ..default_camera() },
        )
    }
}
