//! The surface's effects (docs/textures.md): the base colour, metallic–roughness, occlusion,
//! normal and emissive textures, vertex colours and emission, each on where some drawn object's
//! material or mesh has it, with the reason naming the first.

use super::analyze::Analysis;
use super::declared::Effect;
use crate::scene::Scene;

/// The surface's textures, vertex colours and emission.
pub(super) fn decide_textures(a: &mut Analysis, scene: &Scene) {
    let (textured, why) = base_color_texture(scene);
    a.decide(Effect::BaseColorTexture, textured, why);
    let (colored, why) = vertex_colors(scene);
    a.decide(Effect::VertexColors, colored, why);
    let (on, why) = texture_map(scene, "metallic–roughness texture", |m| m.maps.metal_roughness.map(|t| t.texture));
    a.decide(Effect::MetalRoughnessTexture, on, why);
    let (on, why) = texture_map(scene, "occlusion texture", |m| m.maps.occlusion.map(|t| t.texture));
    a.decide(Effect::OcclusionTexture, on, why);
    let (on, why) = normal_texture(scene);
    a.decide(Effect::NormalTexture, on, why);
    let (on, why) = emission(scene);
    a.decide(Effect::Emission, on, why);
    let (on, why) = emissive_texture(scene);
    a.decide(Effect::EmissiveTexture, on, why);
}

/// The file mesh object `o` shows, if it is one.
fn file_mesh<'s>(scene: &'s Scene, o: &crate::scene::Object) -> Option<&'s crate::mesh::TriangleMesh> {
    match o.shape {
        crate::scene::Shape::Mesh(i) => scene.meshes.get(i),
        _ => None,
    }
}

/// The base colour texture is sampled when some object's material has one and its mesh has the
/// texture coordinates to sample it with (without them the loader has said so; the factor alone
/// is drawn).
fn base_color_texture(scene: &Scene) -> (bool, String) {
    texture_map(scene, "base colour texture", |m| m.base_color_texture)
}

/// A material texture (`what`, found by `slot`) is sampled when some object's material has one
/// that exists and its mesh has texture coordinates to sample it with (without them the loader has
/// said so; the material's own parameter is drawn).
fn texture_map(
    scene: &Scene,
    what: &str,
    slot: impl Fn(&crate::scene::Material) -> Option<crate::scene::TextureRef>,
) -> (bool, String) {
    let has = |o: &&crate::scene::Object| {
        scene.materials.get(o.material).and_then(&slot).is_some_and(|r| r.texture < scene.textures.len())
    };
    let textured: Vec<_> = scene.objects.iter().filter(has).collect();
    let sampled = textured.iter().filter(|o| file_mesh(scene, o).is_some_and(|m| m.uvs.is_some())).count();
    if textured.is_empty() {
        (false, format!("no material has one ({what})"))
    } else if sampled == 0 {
        (false, format!("{} object(s) have a material with one ({what}) but no texture coordinates", textured.len()))
    } else {
        (true, format!("{sampled} object(s) have one ({what}) and texture coordinates"))
    }
}

/// The normal texture is sampled where a textured mesh has tangents to turn the normal in (the
/// loader gives every such mesh MikkTSpace's when its file has none, or says why not).
fn normal_texture(scene: &Scene) -> (bool, String) {
    let (on, why) = texture_map(scene, "normal texture", |m| m.maps.normal.map(|n| n.texture));
    let framed = scene.objects.iter().any(|o| {
        scene.materials.get(o.material).is_some_and(|m| m.maps.normal.is_some())
            && file_mesh(scene, o).is_some_and(|m| m.uvs.is_some() && m.tangents.is_some())
    });
    if on && !framed {
        return (false, "no mesh with a normal texture has tangents to frame it".into());
    }
    (on, why)
}

/// Emission is added when some object's material emits (I_e > 0 in some channel).
fn emission(scene: &Scene) -> (bool, String) {
    let n = scene.objects.iter().filter(|o| emits(scene, o)).count();
    if n == 0 {
        (false, "no material emits (I_e = 0)".into())
    } else {
        (true, format!("{n} object(s) emit light I_e > 0"))
    }
}

fn emits(scene: &Scene, o: &crate::scene::Object) -> bool {
    scene.materials.get(o.material).is_some_and(|m| m.emission.iter().any(|e| *e > 0.0))
}

/// The emissive texture is sampled where it can change something: on an emitting material.
fn emissive_texture(scene: &Scene) -> (bool, String) {
    let (on, why) = texture_map(scene, "emissive texture", |m| m.maps.emissive);
    if on && !scene.objects.iter().any(|o| emits(scene, o) && scene.materials[o.material].maps.emissive.is_some()) {
        return (false, "every material with an emissive texture has I_e = 0: the texture scales nothing".into());
    }
    (on, why)
}

/// Vertex colours are interpolated when some object's mesh has them.
fn vertex_colors(scene: &Scene) -> (bool, String) {
    let n = scene.objects.iter().filter(|o| file_mesh(scene, o).is_some_and(|m| m.colors.is_some())).count();
    if n == 0 {
        (false, "no mesh has vertex colours".into())
    } else {
        (true, format!("{n} object(s) have vertex colours"))
    }
}
