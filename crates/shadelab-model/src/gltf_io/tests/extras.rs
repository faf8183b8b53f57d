//! Tests of `extras.shadelab`: bad values are one error line naming the key.

use super::*;

#[test]
fn extras_out_of_range_are_one_line_errors() {
    let bad = triangle(json!({
        "materials": [{ "name": "x", "extras": { "shadelab": { "m": 5 } } }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "material": 0 }] }],
    }));
    let e = load_scene_from_slice(&bad).unwrap_err().to_string();
    assert!(e.starts_with("<memory>: material 0: extras.shadelab.m = 5 is not a number in [0, 1]"), "{e}");
    assert!(!e.contains('\n'));
    let bad = triangle(json!({ "scenes": [{ "nodes": [0], "extras": { "shadelab": { "shading": "toon" } } }] }));
    let e = load_scene_from_slice(&bad).unwrap_err().to_string();
    assert!(e.contains("scene: extras.shadelab.shading = \"toon\" is not one of flat, gouraud, phong"), "{e}");
}

#[test]
fn extras_null_values_and_several_bad_keys() {
    let material = |extras: Value| {
        triangle(json!({
            "materials": [{ "extras": extras }],
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "material": 0 }] }],
        }))
    };
    let error = |extras: Value| load_scene_from_slice(&material(extras)).unwrap_err().to_string();
    // A key that is there with null is a bad value, not an absent one.
    let e = error(json!({ "shadelab": { "r_d": null } }));
    assert!(e.contains("material 0: extras.shadelab.r_d = null is not a number in [0, 1] (a share or colour)"), "{e}");
    // Several bad keys: the first in the order they are checked (C, m, h, mu, …, a, d).
    let e = error(json!({ "shadelab": { "d": -1, "a": [1, 2], "m": "rough" } }));
    assert!(e.contains("extras.shadelab.m = \"rough\" is not a number in [0, 1]"), "{e}");
    let e = error(json!({ "shadelab": { "a": [1, 2] } }));
    assert!(e.contains("extras.shadelab.a = [1,2] is not 3 numbers in [0, 1000000] (absorption coefficient a per metre (per channel))"), "{e}");
    assert!(error(json!({ "shadelab": 3 })).contains("material 0: extras.shadelab is not an object"));
    // Keys shadelab does not write are ignored; so are extras without `shadelab`.
    let s = load(&material(json!({ "shadelab": { "unknown": true, "m": 0.5 }, "other": 1 })));
    assert_eq!(s.scene.materials[0].m, 0.5);
    assert_eq!(s.scene.materials[0].h, PhongExponent::from_m(1.0), "h stays glTF's, from m = r²");
    let s = load(&material(json!({ "other": { "m": 5 } })));
    assert_eq!(s.scene.materials[0].m, 1.0);
}

#[test]
fn a_plain_gltf_material_opens_with_the_gltf_brdf_and_extras_keep_the_chapters() {
    use crate::lighting::microfacet::{Fresnel, Microfacet};
    let material = |extras: Value| {
        triangle(json!({
            "materials": [{ "extras": extras }],
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "material": 0 }] }],
        }))
    };
    let try_load = |bytes: &[u8]| load_scene_from_slice(bytes);
    let plain = load(&material(json!({ "other": 1 })));
    assert_eq!(plain.scene.materials[0].microfacet, Microfacet::GLTF);
    let mix = plain.scene.materials[0].fresnel_mix;
    assert!((mix.f0 - 0.04).abs() < 1e-15 && mix.weight == 1.0, "{mix:?}");
    // The layer of fresnel_mix is the dielectric's own: ior 2 gives F0 1/9, the specular factor
    // its weight, the colour's largest channel scales F0.
    let layer = load(&triangle(json!({
        "extensionsUsed": ["KHR_materials_ior", "KHR_materials_specular"],
        "materials": [{
            "pbrMetallicRoughness": { "metallicFactor": 0.5 },
            "extensions": {
                "KHR_materials_ior": { "ior": 2.0 },
                "KHR_materials_specular": { "specularFactor": 0.5, "specularColorFactor": [0.5, 2.0, 1.0] }
            }
        }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "material": 0 }] }],
    })));
    let mix = layer.scene.materials[0].fresnel_mix;
    assert!((mix.f0 - 2.0 / 9.0).abs() < 1e-12 && mix.weight == 0.5, "{mix:?}");
    // extras.shadelab without terms: the chapter's; one term named: that one, the others the chapter's.
    let stated = load(&material(json!({ "shadelab": { "m": 0.3 } })));
    assert_eq!(stated.scene.materials[0].microfacet, Microfacet::CHAPTER);
    let one = load(&material(json!({ "shadelab": { "fresnel": "schlick" } })));
    assert_eq!(one.scene.materials[0].microfacet, Microfacet { f: Fresnel::Schlick, ..Microfacet::CHAPTER });
    let bad = try_load(&material(json!({ "shadelab": { "masking": "smiths" } }))).unwrap_err().to_string();
    assert!(bad.contains("masking") && bad.contains("smith-correlated"), "{bad}");
}

#[test]
fn extras_are_written_and_read_by_the_same_types() {
    // Every key of the module's `extras.shadelab` table is written, and read back exactly.
    let mut scene = Scene::builtin("sphere").unwrap();
    scene.lights[0] = Light {
        range: Some(9.0),
        ..Light::spot(DVec3::new(0.5, 3.0, 1.0), DVec3::new(0.1, -1.0, 0.2), [1.0, 0.9, 0.8], 4.0, 0.3, (0.1, 0.4))
    };
    scene.materials[1].h = PhongExponent::Mirror;
    scene.materials[0].emission = [0.25, 0.5, 1.0];
    scene.materials[0].phong_normalized = true;
    scene.materials[1].microfacet = crate::lighting::microfacet::Microfacet {
        d: crate::lighting::microfacet::Distribution::Ggx,
        multiple_scattering: true,
        fresnel_mix: true,
        ..crate::lighting::microfacet::Microfacet::CHAPTER
    };
    scene.materials[1].fresnel_mix = crate::scene::FresnelMix { f0: 0.0625, weight: 0.75 };
    scene.lights[0].shadow = crate::shadows::ShadowSettings {
        casts: false,
        resolution: 300,
        filter: crate::shadows::ShadowFilter::Poisson,
        cascades: false,
        pcss_taps: 16,
    };
    let settings = SceneSettings { shading: Some(ShadingMode::Flat), specular: Some(SpecularModel::CookTorrance) };
    let doc: Value = serde_json::from_str(&scene_to_gltf_json(&scene, &settings)).unwrap();
    let keys = |v: &Value| v["extras"]["shadelab"].as_object().unwrap().keys().cloned().collect::<Vec<_>>().join(" ");
    // I_e only where the material emits, mf0 only with a metallic–roughness texture (tests/textures.rs).
    assert_eq!(
        keys(&doc["materials"][0]),
        "C I_e a d distribution fresnel h m masking mu mu_t phong_normalized r_a r_d r_s t"
    );
    assert_eq!(
        keys(&doc["materials"][1]),
        "C a d distribution fresnel fresnel_mix h m masking mix_f0 mix_weight mu mu_t multiple_scattering r_a r_d r_s t"
    );
    assert_eq!(doc["materials"][1]["extras"]["shadelab"]["h"], json!("mirror"));
    assert_eq!(doc["materials"][1]["extras"]["shadelab"]["distribution"], json!("ggx"));
    assert_eq!(doc["materials"][1]["extras"]["shadelab"]["masking"], json!("v-groove"));
    assert_eq!(
        keys(&doc["extensions"]["KHR_lights_punctual"]["lights"][0]),
        "I_L alpha casts_shadows color d0 direction falloff_form inner_cone outer_cone pcss_taps position range \
         shadow_cascades shadow_filter shadow_resolution"
    );
    assert_eq!(keys(&doc["scenes"][0]), "ambient shading specular");
    assert_eq!(keys(&doc["cameras"][0]), "eye far fov_y_deg near target up");
    assert_eq!(keys(&doc["nodes"][0]), "rotation_y scale translation");
    let mesh = doc["meshes"].as_array().unwrap().iter().find(|m| m.get("extras").is_some()).unwrap();
    assert_eq!(keys(mesh), "shape tessellation");
    let back = load(&serde_json::to_vec(&doc).unwrap());
    assert_eq!(back.scene, scene);
    assert_eq!(back.settings, settings);
}
