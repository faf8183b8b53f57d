//! Scene variants for the accuracy study (`shadelab bench accuracy`) and the viewer's difference
//! view: which scenes the f64 reference knows exactly, and a scene remade at one level of detail
//! or with a chosen number of lights.

use crate::scene::{Light, MAX_LIGHTS, Scene, Shape};
use glam::DVec3;

/// Scenes whose exact geometry the reference ray-caster knows (every object is an analytic shape).
pub const ANALYTIC_SCENES: [&str; 4] = ["sphere", "cylinder", "pyramid", "default"];

/// Whether the f64 reference knows the scene's exact geometry: every object is an analytic shape
/// (not a triangle mesh from a file).
#[allow(unreachable_patterns)]
pub fn is_analytic(scene: &Scene) -> bool {
    scene
        .objects
        .iter()
        .all(|o| matches!(o.shape, Shape::Sphere | Shape::Cylinder | Shape::Cube | Shape::Plane | Shape::Pyramid))
}

/// Most file-mesh triangles a scene may have for the reference to render it: the loader's own
/// limit (`gltf_io::MAX_TRIANGLES`). A ray meets a mesh through its hierarchy (`reference/bvh.rs`,
/// about 36 bytes a triangle, 0.6 GB at this limit), so its cost grows with log n, not n.
pub const REFERENCE_MESH_TRIANGLES: usize = crate::gltf_io::MAX_TRIANGLES;

/// Whether the f64 reference renders the scene: analytic shapes exactly, and file meshes (their
/// triangles are the file's exact surface) of at most `REFERENCE_MESH_TRIANGLES` in all.
pub fn reference_covers(scene: &Scene) -> bool {
    let mesh_triangles: usize = scene
        .objects
        .iter()
        .filter_map(|o| match o.shape {
            Shape::Mesh(i) => Some(scene.meshes.get(i).map_or(0, |m| m.triangle_count())),
            _ => None,
        })
        .sum();
    mesh_triangles <= REFERENCE_MESH_TRIANGLES
}

/// A planar face gets `level / PLANAR_CELLS_PER_LEVEL` cells per side, so that the coarsest
/// level (8 segments around a sphere) is one quad per face and the finest (512) is 64 × 64: a
/// face under a point light needs vertices inside it for Gouraud shading to see the falloff, but
/// far fewer than a curved surface needs to follow its curvature.
pub const PLANAR_CELLS_PER_LEVEL: u32 = 8;

/// The scene with every object at one level of detail: `level` segments around spheres and
/// cylinders, `level / PLANAR_CELLS_PER_LEVEL` (at least 1) cells per side of planar faces.
pub fn at_level(scene: &Scene, level: u32) -> Scene {
    let mut s = scene.clone();
    for o in &mut s.objects {
        o.tessellation = tessellation_at_level(o.shape, level, o.tessellation);
    }
    s
}

/// The tessellation parameter of one shape at a level of detail (`keep` for shapes the levels
/// do not apply to).
#[allow(unreachable_patterns)]
pub fn tessellation_at_level(shape: Shape, level: u32, keep: u32) -> u32 {
    match shape {
        Shape::Sphere | Shape::Cylinder => level.max(3),
        Shape::Cube | Shape::Plane | Shape::Pyramid => (level / PLANAR_CELLS_PER_LEVEL).max(1),
        _ => keep,
    }
}

/// The scene lit by `n` (1 ..= MAX_LIGHTS) point lights instead of its own, spread on a ring
/// above it, their total intensity that of the scene's lights (so the image stays exposed alike
/// while the work per pixel grows with `n`).
pub fn with_point_lights(scene: &Scene, n: usize) -> Scene {
    let n = n.clamp(1, MAX_LIGHTS);
    let total: f64 = scene.lights.iter().map(|l| l.intensity).sum::<f64>().max(1.0);
    let mut s = scene.clone();
    s.lights = (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * (i as f64 + 0.125) / n as f64;
            let p = DVec3::new(3.0 * a.cos(), 3.0, 3.0 * a.sin() + 1.0);
            Light::point(p, [1.0, 0.98, 0.95], total / n as f64, 0.05)
        })
        .collect();
    s
}

/// Side of the checker texture of [`with_textured_floor`], in texels, and of its squares.
pub const CHECKER_TEXELS: u32 = 64;
pub const CHECKER_SQUARE_TEXELS: u32 = 8;
/// Times the checker repeats across the floor.
pub const CHECKER_REPEATS: f64 = 4.0;

/// The scene with its floor (its first plane) made a file mesh at `level`'s tessellation whose
/// texture coordinates carry a bilinear checker texture (made here, no file), repeating
/// `CHECKER_REPEATS` times: a textured scene for the accuracy study that the reference renders.
pub fn with_textured_floor(scene: &Scene, level: u32) -> Scene {
    use crate::scene::{Texture, TextureRef};
    let mut s = scene.clone();
    let Some(i) = s.objects.iter().position(|o| o.shape == Shape::Plane) else { return s };
    let n = tessellation_at_level(Shape::Plane, level, 1);
    let tris = crate::mesh::triangles(Shape::Plane, n);
    let normals: Vec<[DVec3; 3]> = tris.iter().map(|_| [DVec3::Y; 3]).collect();
    let mut mesh = crate::mesh::TriangleMesh::from_soup(&s.objects[i].name, &tris, Some(&normals));
    let uv = |p: &DVec3| [((p.x + 1.0) * 0.5 * CHECKER_REPEATS) as f32, ((p.z + 1.0) * 0.5 * CHECKER_REPEATS) as f32];
    mesh.uvs = Some(mesh.positions.iter().map(uv).collect());
    s.meshes.push(mesh);
    let side = CHECKER_TEXELS;
    let rgba8: Vec<u8> = (0..side * side)
        .flat_map(|k| {
            let (x, y) = (k % side / CHECKER_SQUARE_TEXELS, k / side / CHECKER_SQUARE_TEXELS);
            let v = if (x + y) % 2 == 0 { 230 } else { 40 };
            [v, v, v, 255]
        })
        .collect();
    s.textures.push(Texture { width: side, height: side, rgba8: rgba8.into(), ..Texture::solid("checker", [0; 4]) });
    let mut material = s.materials[s.objects[i].material].clone();
    material.name = format!("textured {}", material.name);
    material.base_color_texture = Some(TextureRef { texture: s.textures.len() - 1, ..Default::default() });
    s.materials.push(material);
    s.objects[i].material = s.materials.len() - 1;
    s.objects[i].shape = Shape::Mesh(s.meshes.len() - 1);
    // A mesh has no tessellation of its own (1, as a loaded file's).
    s.objects[i].tessellation = 1;
    s
}

/// An image of `side`² texels, each `f(x, y)` as RGBA8.
fn image(name: &str, side: u32, f: impl Fn(u32, u32) -> [u8; 4]) -> crate::scene::Texture {
    let rgba8: Vec<u8> = (0..side * side).flat_map(|k| f(k % side, k / side)).collect();
    crate::scene::Texture {
        width: side,
        height: side,
        rgba8: rgba8.into(),
        ..crate::scene::Texture::solid(name, [0; 4])
    }
}

/// glTF's F0 of a dielectric of index 1.5, which the textured floor's metal falls back to.
const FLOOR_F0: f64 = 0.04;
/// The textured floor's emission I_e where its emissive texture is white.
pub const FLOOR_EMISSION: [f64; 3] = [0.3, 0.15, 0.05];

/// [`with_textured_floor`] whose floor also has the other glTF textures, made here: a glTF metal
/// (metallic factor 1, F0 0.04) whose metallic–roughness texture turns bands of it into a rough
/// dielectric, an occlusion texture darkening its ambient towards each checker square's edges,
/// an emissive texture of diagonal stripes (I_e = `FLOOR_EMISSION`), and a normal texture of
/// ridges across each checker square (with the floor's MikkTSpace tangents).
pub fn with_material_maps(scene: &Scene, level: u32) -> Scene {
    use crate::scene::{MetalRoughnessMap, OcclusionMap, TextureRef};
    let mut s = with_textured_floor(scene, level);
    let Some(mi) = s.objects.iter().find(|o| matches!(o.shape, Shape::Mesh(_))).map(|o| o.material) else { return s };
    let side = CHECKER_TEXELS;
    let band = 2 * CHECKER_SQUARE_TEXELS;
    let next = s.textures.len();
    // Green: roughness scale, blue: metal scale (bands of polished metal and rough dielectric).
    s.textures.push(image("metal bands", side, |x, _| {
        if (x / band).is_multiple_of(2) { [0, 90, 255, 255] } else { [0, 255, 0, 255] }
    }));
    // Red: occlusion, 1 at each square's centre and 0.25 at its edges.
    let square = CHECKER_SQUARE_TEXELS as f64;
    s.textures.push(image("occlusion", side, |x, y| {
        let d = |c: u32| ((c as f64 % square) + 0.5 - square / 2.0).abs() / (square / 2.0);
        let occ = 1.0 - 0.75 * d(x).max(d(y));
        [(occ * 255.0).round() as u8, 0, 0, 255]
    }));
    // Ridges along v: the normal tilts ±0.5 towards u across each square (x = ½ + ½·sin).
    s.textures.push(image("ridges", side, |x, _| {
        let a = (x as f64 + 0.5) / square * std::f64::consts::TAU;
        let tilt = 0.5 * a.sin();
        let z = (1.0 - tilt * tilt).sqrt();
        let enc = |c: f64| ((c * 0.5 + 0.5) * 255.0).round() as u8;
        [enc(tilt), enc(0.0), enc(z), 255]
    }));
    s.textures.push(image("emissive stripes", side, |x, y| {
        if ((x + y) / 6).is_multiple_of(4) { [255; 4] } else { [0, 0, 0, 255] }
    }));
    let m = &mut s.materials[mi];
    let base = m.color;
    (m.color, m.mu, m.mu_tinted) = ([0.0; 3], base, base);
    m.r_a = 1.0;
    m.emission = FLOOR_EMISSION;
    let r = |texture| TextureRef { texture, ..Default::default() };
    m.maps.metal_roughness = Some(MetalRoughnessMap { texture: r(next), metallic_f0: [FLOOR_F0; 3] });
    m.maps.occlusion = Some(OcclusionMap { texture: r(next + 1), strength: 1.0 });
    // In the order the loader meets them (metallic–roughness, occlusion, normal, emissive), so
    // that a saved scene reads back with the same indices.
    m.maps.normal = Some(crate::scene::NormalMap { texture: r(next + 2), scale: 1.0 });
    m.maps.emissive = Some(r(next + 3));
    // The floor's tangents, as the loader makes them for a file without any.
    if let Some(Shape::Mesh(k)) = s.objects.iter().find(|o| o.material == mi).map(|o| o.shape)
        && let Some(t) = s.meshes[k].with_generated_tangents()
    {
        s.meshes[k] = t;
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_textured_floor_is_a_textured_mesh_the_reference_renders() {
        let s = with_textured_floor(&Scene::builtin("default").unwrap(), 64);
        let floor = s.objects.iter().find(|o| matches!(o.shape, Shape::Mesh(_))).expect("a mesh floor");
        assert!(s.materials[floor.material].base_color_texture.is_some());
        assert!(reference_covers(&s) && !is_analytic(&s));
        let a = crate::effects::analyze(&s, crate::SpecularModel::CookTorrance);
        assert!(a.key.has(crate::effects::Effect::BaseColorTexture));
    }

    #[test]
    fn the_material_maps_floor_calls_for_every_texture_effect() {
        use crate::effects::Effect;
        let s = with_material_maps(&Scene::builtin("default").unwrap(), 32);
        let a = crate::effects::analyze(&s, crate::SpecularModel::CookTorrance);
        for e in [
            Effect::BaseColorTexture,
            Effect::MetalRoughnessTexture,
            Effect::OcclusionTexture,
            Effect::Emission,
            Effect::EmissiveTexture,
        ] {
            assert!(a.key.has(e), "{e}");
        }
        // Without them the scene needs none of them.
        let plain = Scene::builtin("default").unwrap();
        let a = crate::effects::analyze(&plain, crate::SpecularModel::CookTorrance);
        assert!(!a.key.samples_textures() && !a.key.has(Effect::Emission));
    }

    #[test]
    fn analytic_scenes_exist() {
        for name in ANALYTIC_SCENES {
            assert!(is_analytic(&Scene::builtin(name).expect(name)), "{name}");
        }
    }

    #[test]
    fn levels_change_triangle_counts_monotonically() {
        for name in ANALYTIC_SCENES {
            let base = Scene::builtin(name).unwrap();
            let counts: Vec<usize> = [8, 32, 128, 512].iter().map(|&l| at_level(&base, l).triangle_count()).collect();
            assert!(counts.windows(2).all(|w| w[0] < w[1]), "{name}: {counts:?}");
        }
    }

    #[test]
    fn light_count_and_total_intensity() {
        let base = Scene::builtin("sphere").unwrap();
        let total: f64 = base.lights.iter().map(|l| l.intensity).sum();
        for n in [1, 2, 4, 8] {
            let s = with_point_lights(&base, n);
            assert_eq!(s.lights.len(), n);
            let t: f64 = s.lights.iter().map(|l| l.intensity).sum();
            assert!((t - total.max(1.0)).abs() < 1e-12);
        }
        assert_eq!(with_point_lights(&base, 99).lights.len(), MAX_LIGHTS);
    }
}
