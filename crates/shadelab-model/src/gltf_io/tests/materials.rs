//! Tests of the material mapping from glTF's metallic–roughness fields and extensions.

use super::*;

#[test]
fn pbr_materials_map_to_the_model() {
    let doc = |mat: Value| {
        triangle(json!({
            "extensionsUsed": ["KHR_materials_ior", "KHR_materials_specular", "KHR_materials_volume",
                               "KHR_materials_transmission"],
            "materials": [mat],
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "material": 0 }] }],
        }))
    };
    // A rough dielectric: C = baseColor, μ = 0.04, m = roughness².
    let m = &load(&doc(json!({ "pbrMetallicRoughness": {
        "baseColorFactor": [0.5, 0.25, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.5 } })))
    .scene
    .materials[0];
    assert_eq!(m.color, [0.5, 0.25, 1.0]);
    assert!((m.mu[0] - 0.04).abs() < 1e-7 && m.mu[0] == m.mu[2]);
    assert_eq!(m.m, 0.25);
    assert_eq!(m.h, PhongExponent::Finite(2.0 / 0.0625 - 2.0));
    assert_eq!((m.r_s, m.r_d, m.r_a), (1.0, 1.0, 1.0));
    // A metal: μ = baseColor, no diffuse colour; roughness 0 is the mirror.
    let m = &load(&doc(json!({ "pbrMetallicRoughness": {
        "baseColorFactor": [1.0, 0.75, 0.25, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.0 } })))
    .scene
    .materials[0];
    assert_eq!((m.mu, m.color, m.m, m.h), ([1.0, 0.75, 0.25], [0.0; 3], 0.0, PhongExponent::Mirror));
    // ior, specular colour, transmission and volume.
    let m = &load(&doc(json!({
        "pbrMetallicRoughness": { "metallicFactor": 0.0 },
        "extensions": {
            "KHR_materials_ior": { "ior": 2.0 },
            "KHR_materials_specular": { "specularFactor": 0.5, "specularColorFactor": [1.0, 0.5, 0.0] },
            "KHR_materials_transmission": { "transmissionFactor": 0.75 },
            "KHR_materials_volume": { "thicknessFactor": 2.0, "attenuationDistance": 0.5,
                                      "attenuationColor": [1.0, 0.5, 0.25] }
        } })))
    .scene
    .materials[0];
    let f0 = crate::presets::mu_from_ior(2.0);
    for (got, want) in m.mu.iter().zip([f0 * 0.5, f0 * 0.25, 0.0]) {
        assert!((got - want).abs() < 1e-7, "{:?}", m.mu);
    }
    assert_eq!((m.transmission, m.thickness), (0.75, 2.0));
    for (got, c) in m.absorption.iter().zip([1.0f64, 0.5, 0.25]) {
        assert!((got - (-c.ln() / 0.5)).abs() < 1e-6, "{:?}", m.absorption);
    }
    // A primitive without a material gets glTF's default one (metallic 1, roughness 1, white).
    let s = load(&triangle(json!({}))).scene;
    assert_eq!(s.materials.len(), 1);
    assert_eq!((s.materials[0].mu, s.materials[0].m), ([1.0; 3], 1.0));
}
