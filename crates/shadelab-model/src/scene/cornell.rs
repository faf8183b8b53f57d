//! The `cornell` scene (docs/reference.md, "Checks against published renders"): the Cornell box
//! with its published dimensions (Cornell University Program of Computer Graphics, "Cornell Box
//! Data"), in metres, so that the path-traced reference can be compared with other renderers.
//!
//! The room is 556 × 548.8 × 559.2 mm, open at the front; the light is a 130 × 105 mm rectangle
//! just under the ceiling; the two blocks are 165 mm and 330 mm tall boxes turned about the
//! vertical. The published walls are up to 3 mm off square and the blocks' sides 165–167 mm; here
//! they are square and 166 mm, so that every surface is an analytic shape the reference meets
//! exactly. Every surface is Lambertian (`r_d = 1`, no specular), with the usual RGB albedos.

use super::{Camera, Light, Material, Object, Scene, Shape, Transform};
use crate::params::LightKind;
use glam::DVec3;

/// The room's inside: width (x), height (y) and depth (z), m.
pub const CORNELL_ROOM: [f64; 3] = [0.556, 0.5488, 0.5592];
/// The light's sides along x and z, m, and its centre.
pub const CORNELL_LIGHT_SIZE: [f64; 2] = [0.130, 0.105];
pub const CORNELL_LIGHT_CENTER: [f64; 3] = [0.278, 0.5487, 0.2795];
/// The light's radiance in physical units, W/(m²·sr) per channel. The chapter's light carries no
/// 1/π, so the scene's light has intensity `I = α·A·L/π` (docs/reference.md, "Units", and
/// [`CORNELL_FALLOFF`]).
pub const CORNELL_RADIANCE: [f64; 3] = [17.0, 12.0, 4.0];
/// The light's falloff α. An area light is drawn as its centre's point light spread over its
/// area, and the chapter's point light falls off as `1/(1 + α d²)`, not `1/d²`: its radiance at a
/// point `d` from its centre is `I·d²/(A·(1 + α d²))`. With α = 10⁴ that is `I/(α A)` within
/// `1/(α d²)`, under 0.25 % at the 0.2 m from the light's centre to the nearest lit surface, so
/// the light has the constant radiance a physical emitter has.
pub const CORNELL_FALLOFF: f64 = 1e4;
/// The albedos of the white, red and green surfaces.
pub const CORNELL_WHITE: [f64; 3] = [0.73, 0.73, 0.73];
pub const CORNELL_RED: [f64; 3] = [0.65, 0.05, 0.05];
pub const CORNELL_GREEN: [f64; 3] = [0.12, 0.45, 0.15];
/// The walls' thickness outside the room, m: the cubes they are made of need one.
const WALL: f64 = 0.01;

fn lambertian(name: &str, color: [f64; 3]) -> Material {
    Material { name: name.into(), color, r_d: 1.0, r_s: 0.0, r_a: 1.0, mu: [0.0; 3], ..Material::default() }
}

/// An axis-aligned box from corner `lo` to `hi`, turned by `turn` about its vertical axis.
fn block(name: &str, lo: [f64; 3], hi: [f64; 3], turn: f64, material: usize) -> Object {
    let (lo, hi) = (DVec3::from(lo), DVec3::from(hi));
    Object {
        name: name.into(),
        shape: Shape::Cube,
        tessellation: 1,
        transform: Transform { translation: (lo + hi) * 0.5, rotation_y: turn, scale: (hi - lo) * 0.5 },
        material,
    }
}

/// The Cornell box, seen from the published camera: at (278, 273, −800) mm, looking along +z,
/// 39.3° vertical field of view (its 35 mm lens on a 25 mm film).
pub fn cornell_scene() -> Scene {
    let [w, h, d] = CORNELL_ROOM;
    let materials =
        vec![lambertian("white", CORNELL_WHITE), lambertian("red", CORNELL_RED), lambertian("green", CORNELL_GREEN)];
    let (white, red, green) = (0, 1, 2);
    let t = WALL;
    let objects = vec![
        block("floor", [-t, -t, -t], [w + t, 0.0, d + t], 0.0, white),
        block("ceiling", [-t, h, -t], [w + t, h + t, d + t], 0.0, white),
        block("back wall", [-t, -t, d], [w + t, h + t, d + t], 0.0, white),
        // +x is on the camera's left: the red wall.
        block("left wall", [w, -t, -t], [w + t, h + t, d + t], 0.0, red),
        block("right wall", [-t, -t, -t], [0.0, h + t, d + t], 0.0, green),
        // The published blocks' centres and turns: the short one 16.6° one way, the tall 17.2°
        // the other.
        block("short block", [0.1025, 0.0, 0.0860], [0.2685, 0.165, 0.2520], (-16.6f64).to_radians(), white),
        block("tall block", [0.2855, 0.0, 0.2683], [0.4515, 0.330, 0.4343], 17.2f64.to_radians(), white),
    ];
    let [lx, lz] = CORNELL_LIGHT_SIZE;
    let peak = CORNELL_RADIANCE.iter().copied().fold(0.0, f64::max);
    let color = CORNELL_RADIANCE.map(|c| c / peak);
    let intensity = CORNELL_FALLOFF * lx * lz * peak / std::f64::consts::PI;
    let center = DVec3::from(CORNELL_LIGHT_CENTER);
    let mut light = Light::area(LightKind::Rect, center, DVec3::NEG_Y, [lx, lz], color, intensity, CORNELL_FALLOFF);
    light.tangent = DVec3::X;
    Scene {
        objects,
        materials,
        lights: vec![light],
        ..Scene::empty(
            "cornell".into(),
            [0.1; 3],
            Camera {
                eye: DVec3::new(0.278, 0.273, -0.8),
                target: DVec3::new(0.278, 0.273, 0.0),
                up: DVec3::Y,
                fov_y_deg: 39.3,
                near: 0.01,
                far: 5.0,
                orthographic: None,
            },
        )
    }
}
