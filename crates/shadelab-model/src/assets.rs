//! The scenes shipped in `assets/` as glTF, made here so that they can be regenerated and
//! checked: `UPDATE_ASSETS=1 cargo test --release -p shadelab-model shipped_assets` writes them,
//! and a normal test loads each file and compares it with its constructor.

use crate::gltf_io::SceneSettings;
use crate::params::{PhongExponent, ShadingMode, SpecularModel};
use crate::presets::{MaterialPreset, PRESETS};
use crate::scene::{Camera, Light, Material, Object, Scene, Shape, Transform};
use glam::DVec3;

/// A scene file in `assets/` and how to make it.
pub struct AssetScene {
    /// File name under `assets/`.
    pub file: &'static str,
    pub scene: fn() -> Scene,
    pub settings: SceneSettings,
}

/// Every generated asset.
pub const ASSET_SCENES: [AssetScene; 4] = [
    AssetScene {
        file: "figure-7-3-pyramid.gltf",
        scene: figure_7_3_pyramid,
        settings: SceneSettings { shading: Some(ShadingMode::Flat), specular: Some(SpecularModel::Phong) },
    },
    AssetScene {
        file: "gouraud-vs-phong.gltf",
        scene: gouraud_vs_phong,
        settings: SceneSettings { shading: Some(ShadingMode::Gouraud), specular: Some(SpecularModel::Phong) },
    },
    AssetScene {
        file: "material-board.gltf",
        scene: material_board,
        settings: SceneSettings { shading: Some(ShadingMode::Phong), specular: Some(SpecularModel::CookTorrance) },
    },
    AssetScene {
        file: "textured-floor.gltf",
        scene: textured_floor,
        settings: SceneSettings { shading: Some(ShadingMode::Phong), specular: Some(SpecularModel::CookTorrance) },
    },
];

/// The default scene on a floor with every glTF texture the renderer draws, made in code
/// (`scene_variants::with_material_maps`): base colour, metallic–roughness, occlusion, emissive.
pub fn textured_floor() -> Scene {
    let mut s = crate::scene_variants::with_material_maps(&Scene::builtin("default").expect("built in"), 64);
    s.name = "textured-floor".into();
    s
}

fn camera(eye: DVec3, target: DVec3) -> Camera {
    Camera { eye, target, up: DVec3::Y, fov_y_deg: 40.0, near: 0.1, far: 50.0, orthographic: None }
}

fn ground(tessellation: u32, color: [f64; 3]) -> (Object, Material) {
    (
        Object {
            name: "ground".into(),
            shape: Shape::Plane,
            tessellation,
            transform: Transform::new(DVec3::ZERO, DVec3::new(5.0, 1.0, 3.6)),
            material: 0,
        },
        Material {
            name: "ground".into(),
            color,
            r_s: 0.25,
            r_d: 0.8,
            r_a: 0.8,
            m: 0.5,
            h: PhongExponent::from_m(0.5),
            mu: [0.04; 3],
            ..Material::default()
        },
    )
}

/// The chapter's figure 7.3: a pyramid lit by parallel light. The light comes from behind on the
/// right, so the faces towards the viewer on the left are in the pyramid's own shadow and the
/// self-shadow boundary runs along its edges; the ground is the receiver of the cast shadow.
pub fn figure_7_3_pyramid() -> Scene {
    let (ground, ground_mat) = ground(16, [0.55, 0.55, 0.52]);
    Scene {
        objects: vec![
            ground,
            Object {
                name: "pyramid".into(),
                shape: Shape::Pyramid,
                tessellation: 1,
                transform: Transform {
                    translation: DVec3::new(0.0, 0.9, 0.0),
                    rotation_y: 20f64.to_radians(),
                    scale: DVec3::splat(0.9),
                },
                material: 1,
            },
        ],
        materials: vec![
            ground_mat,
            Material {
                name: "stone".into(),
                color: [0.82, 0.8, 0.74],
                r_s: 0.3,
                r_d: 0.9,
                r_a: 0.8,
                m: 0.35,
                h: PhongExponent::from_m(0.35),
                mu: [0.05; 3],
                ..Material::default()
            },
        ],
        lights: vec![Light::directional(DVec3::new(-0.75, -0.8, 0.45), [1.0, 0.98, 0.94], 1.0)],
        ..Scene::empty(
            "figure 7.3: pyramid in parallel light".into(),
            [0.1; 3],
            camera(DVec3::new(0.6, 2.4, 4.6), DVec3::new(0.0, 0.7, 0.0)),
        )
    }
}

/// Figures 7.9–7.12: a sphere and a cylinder with few segments (8), shiny, so that Gouraud
/// shading's lost and smeared highlights and Phong shading's kept ones show.
pub fn gouraud_vs_phong() -> Scene {
    let (ground, ground_mat) = ground(8, [0.32, 0.32, 0.3]);
    let shiny = Material {
        name: "shiny blue plastic".into(),
        color: [0.15, 0.3, 0.8],
        r_s: 1.0,
        r_d: 0.8,
        r_a: 0.8,
        m: 0.12,
        h: PhongExponent::from_m(0.12),
        mu: [0.04; 3],
        ..Material::default()
    };
    Scene {
        objects: vec![
            ground,
            Object {
                name: "sphere".into(),
                shape: Shape::Sphere,
                tessellation: 8,
                transform: Transform::new(DVec3::new(-1.1, 0.9, 0.0), DVec3::splat(0.9)),
                material: 1,
            },
            Object {
                name: "cylinder".into(),
                shape: Shape::Cylinder,
                tessellation: 8,
                transform: Transform {
                    translation: DVec3::new(1.1, 0.9, 0.0),
                    rotation_y: 10f64.to_radians(),
                    scale: DVec3::new(0.7, 0.9, 0.7),
                },
                material: 1,
            },
        ],
        materials: vec![ground_mat, shiny],
        lights: vec![
            Light::directional(DVec3::new(-0.55, -1.0, -0.7), [1.0, 0.97, 0.92], 0.75),
            Light::point(DVec3::new(-2.2, 2.4, 2.4), [0.92, 0.96, 1.0], 1.1, 0.06),
        ],
        ..Scene::empty(
            "Gouraud vs Phong shading".into(),
            [0.12; 3],
            camera(DVec3::new(0.0, 2.2, 4.6), DVec3::new(0.0, 0.8, 0.0)),
        )
    }
}

/// Rows of spheres: the metal presets (μ per channel, Filament's table), the dielectric presets
/// (μ from their index; glass and water carry the chapter's transmission and absorption,
/// stored for later), and one plastic from sharp to rough (m up, h = 2/m² − 2 down).
pub fn material_board() -> Scene {
    let (ground, ground_mat) = ground(8, [0.3, 0.3, 0.3]);
    let mut objects = vec![ground];
    let mut materials = vec![ground_mat];
    let mut sphere = |name: String, material: Material, x: f64, z: f64| {
        materials.push(material);
        objects.push(Object {
            name,
            shape: Shape::Sphere,
            tessellation: 24,
            transform: Transform::new(DVec3::new(x, 0.38, z), DVec3::splat(0.38)),
            material: materials.len() - 1,
        });
    };
    let row_x = |i: usize, n: usize| (i as f64 - (n as f64 - 1.0) / 2.0) * 0.95;
    let metals: Vec<_> = PRESETS.iter().filter(|p| p.metal).collect();
    for (i, p) in metals.iter().enumerate() {
        let mat = metal_material(p);
        sphere(p.name.into(), mat, row_x(i, metals.len()), -1.3);
    }
    let dielectrics: Vec<_> = PRESETS.iter().filter(|p| !p.metal).collect();
    for (i, p) in dielectrics.iter().enumerate() {
        let mat = dielectric_material(p);
        sphere(p.name.into(), mat, row_x(i, dielectrics.len()), 0.0);
    }
    let roughness = [0.05, 0.1, 0.2, 0.35, 0.6];
    for (i, m) in roughness.into_iter().enumerate() {
        let mat = plastic_material(m);
        sphere(format!("plastic m={m}"), mat, row_x(i, roughness.len()), 1.3);
    }
    Scene {
        objects,
        materials,
        lights: vec![
            Light::directional(DVec3::new(-0.45, -1.0, -0.8), [1.0, 0.97, 0.92], 0.8),
            Light::point(DVec3::new(2.5, 2.5, 2.8), [0.92, 0.96, 1.0], 1.0, 0.05),
        ],
        ..Scene::empty("material board".into(), [0.1; 3], camera(DVec3::new(0.0, 3.6, 4.4), DVec3::new(0.0, 0.2, 0.1)))
    }
}

/// A metal preset's material on the board: μ from the preset, fairly sharp, little diffuse.
fn metal_material(p: &MaterialPreset) -> Material {
    Material {
        name: p.name.into(),
        color: p.color,
        r_s: 1.0,
        r_d: 0.25,
        r_a: 0.5,
        m: 0.2,
        h: PhongExponent::from_m(0.2),
        mu: p.mu,
        ..Material::default()
    }
}

/// A dielectric preset's material on the board; glass and water transmit and absorb.
fn dielectric_material(p: &MaterialPreset) -> Material {
    // Transmission t and absorption a per unit length (docs/model.md §7): clear glass barely absorbs;
    // water absorbs red most (about 0.45 per metre, here per unit).
    let (transmission, absorption) = match p.name {
        "glass" => (0.9, [0.02, 0.01, 0.015]),
        "water" => (0.85, [0.45, 0.06, 0.03]),
        _ => (0.0, [0.0; 3]),
    };
    Material {
        name: p.name.into(),
        color: p.color,
        r_s: 1.0,
        r_d: 0.8,
        r_a: 0.8,
        m: 0.15,
        h: PhongExponent::from_m(0.15),
        mu: p.mu,
        transmission,
        ior: None,
        absorption,
        thickness: if transmission > 0.0 { 0.76 } else { 0.0 },
        base_color_texture: None,
        mu_tinted: [0.0; 3],
        emission: [0.0; 3],
        maps: Default::default(),
        microfacet: Default::default(),
        phong_normalized: false,
        fresnel_mix: Default::default(),
    }
}

/// The board's red plastic with roughness `m` (h = 2/m² − 2).
fn plastic_material(m: f64) -> Material {
    Material {
        name: format!("plastic m={m}"),
        color: [0.75, 0.12, 0.08],
        r_s: 1.0,
        r_d: 0.8,
        r_a: 0.8,
        m,
        h: PhongExponent::from_m(m),
        mu: [0.04; 3],
        ..Material::default()
    }
}
