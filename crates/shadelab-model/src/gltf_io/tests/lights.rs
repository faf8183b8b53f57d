//! Tests of lights: `KHR_lights_punctual` kinds, cones, range, the light limit and the default
//! light, the shadow settings, and their round trip.

use super::*;
use crate::shadows::{SHADOW_RESOLUTION, ShadowFilter, ShadowSettings};

#[test]
fn lights_spot_range_limit_and_default() {
    let light = |t: &str| json!({ "type": t, "intensity": std::f64::consts::PI, "color": [1, 0.5, 0.25] });
    let mut lights = vec![light("directional"), json!({ "type": "point", "range": 4.0, "intensity": 1.0 })];
    lights.push(json!({ "type": "spot", "spot": { "outerConeAngle": 0.5 } }));
    lights.extend((0..8).map(|_| light("point")));
    let mut nodes = vec![json!({ "mesh": 0 })];
    nodes.extend((0..lights.len()).map(|i| {
        json!({ "translation": [0, 2, 0], "rotation": [-FRAC_1_SQRT_2, 0, 0, FRAC_1_SQRT_2],
                "extensions": { "KHR_lights_punctual": { "light": i } } })
    }));
    let s = load(&triangle(json!({
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": lights } },
        "nodes": nodes,
        "scenes": [{ "nodes": (0..12).collect::<Vec<_>>() }],
    })));
    assert_eq!(s.scene.lights.len(), MAX_LIGHTS);
    let l = &s.scene.lights[0];
    // I_L = E/π; the node's −z, rotated −90° about x, points down.
    assert_eq!((l.kind, l.color), (LightKind::Directional, [1.0, 0.5, 0.25]));
    assert!((l.intensity - 1.0).abs() < 1e-6);
    near(l.direction, DVec3::NEG_Y, "direction");
    let p = &s.scene.lights[1];
    assert_eq!((p.kind, p.falloff_form, p.falloff_alpha), (LightKind::Point, FalloffForm::Quadratic, 1.0));
    near(p.position, DVec3::new(0.0, 2.0, 0.0), "position");
    assert_eq!(p.range, Some(4.0));
    let spot = &s.scene.lights[2];
    assert_eq!((spot.kind, spot.inner_cone, spot.outer_cone), (LightKind::Spot, 0.0, 0.5f32 as f64));
    near(spot.direction, DVec3::NEG_Y, "spot axis");
    let w = s.warnings.join("\n");
    assert!(w.contains("first 8 are kept"), "{w}");
    assert!(!w.contains("spot") && !w.contains("range"), "spot and range are read, not warned about: {w}");
    // No light at all: a default one, said so.
    let s = load(&triangle(json!({})));
    assert_eq!(s.scene.lights.len(), 1);
    assert!(s.warnings.iter().any(|w| w.contains("no lights")), "{:?}", s.warnings);
    assert!(s.warnings.iter().any(|w| w.contains("no camera")), "{:?}", s.warnings);
}

#[test]
fn light_kinds_and_falloff_round_trip() {
    let mut scene = Scene::builtin("sphere").unwrap();
    scene.lights = vec![
        Light {
            falloff_form: FalloffForm::Linear,
            d0: 0.5,
            ..Light::point(DVec3::new(1.0, 2.0, 3.0), [0.5; 3], 3.0, 0.0)
        },
        Light::point(DVec3::new(-1.0, 2.0, 3.0), [1.0; 3], 2.0, 0.25),
        Light::directional(DVec3::new(0.0, 0.0, 1.0), [1.0, 0.5, 0.0], 0.5),
        Light { range: Some(7.5), ..Light::point(DVec3::new(0.0, 3.0, 0.0), [1.0; 3], 2.0, 0.5) },
        Light {
            range: Some(12.0),
            ..Light::spot(DVec3::new(2.0, 4.0, 1.0), DVec3::new(-0.3, -1.0, 0.1), [1.0; 3], 5.0, 0.1, (0.2, 0.45))
        },
    ];
    let back = load(&scene_to_glb(&scene, &SceneSettings::default())).scene;
    assert_same_scene(&scene, &back);
    assert_eq!(back.lights[4].kind, LightKind::Spot);
}

#[test]
fn spot_lights_and_range_are_read_from_khr_lights_punctual() {
    let light = |l: Value| {
        triangle(json!({
            "extensionsUsed": ["KHR_lights_punctual"],
            "extensions": { "KHR_lights_punctual": { "lights": [l] } },
            "scenes": [{ "nodes": [0, 1] }],
            "nodes": [
                { "mesh": 0 },
                // Rotated 90° about x: the light's −Z points down −Y.
                { "translation": [0.0, 3.0, 0.0], "rotation": [-0.70710677, 0.0, 0.0, 0.70710677],
                  "extensions": { "KHR_lights_punctual": { "light": 0 } } },
            ],
        }))
    };
    let s = load_scene_from_slice(&light(json!({
        "type": "spot", "intensity": 10.0, "range": 5.0, "spot": { "innerConeAngle": 0.1, "outerConeAngle": 0.6 }
    })))
    .unwrap();
    let l = &s.scene.lights[0];
    assert_eq!(l.kind, LightKind::Spot);
    assert_eq!((l.inner_cone, l.outer_cone, l.range), (0.1f32 as f64, 0.6f32 as f64, Some(5.0)));
    near(l.direction, DVec3::NEG_Y, "spot axis");
    assert!(s.warnings.iter().all(|w| !w.contains("spot") && !w.contains("range")), "{:?}", s.warnings);
    // glTF's default cones, and an outer cone of exactly π/2 as f32.
    let s = load_scene_from_slice(&light(json!({ "type": "spot", "spot": {} }))).unwrap();
    assert_eq!((s.scene.lights[0].inner_cone, s.scene.lights[0].outer_cone), (0.0, std::f32::consts::FRAC_PI_4 as f64));
    let s = load_scene_from_slice(&light(
        json!({ "type": "spot", "spot": { "outerConeAngle": std::f32::consts::FRAC_PI_2 } }),
    ))
    .unwrap();
    assert_eq!(s.scene.lights[0].outer_cone, std::f64::consts::FRAC_PI_2);
    for (bad, says) in [
        (
            json!({ "type": "spot", "spot": { "innerConeAngle": 0.5, "outerConeAngle": 0.5 } }),
            "must be 0 ≤ inner < outer ≤ π/2",
        ),
        (json!({ "type": "spot", "spot": { "outerConeAngle": 2.0 } }), "must be 0 ≤ inner < outer ≤ π/2"),
        (json!({ "type": "spot" }), "a spot light without `spot`"),
        (json!({ "type": "point", "range": 0.0 }), "range 0 is not in [0.000001, 1000000000]"),
    ] {
        let e = load_scene_from_slice(&light(bad)).unwrap_err().to_string();
        assert!(e.contains(says), "{e}");
    }
    let s = load_scene_from_slice(&light(json!({ "type": "directional", "range": 3.0 }))).unwrap();
    assert_eq!(s.scene.lights[0].range, None);
    assert!(s.warnings.iter().any(|w| w.contains("range 3 ignored")), "{:?}", s.warnings);
}

/// One light with `extras` in a file of one triangle.
fn light_with_extras(extras: Value) -> Vec<u8> {
    triangle(json!({
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": [{ "type": "point", "extras": extras }] } },
        "scenes": [{ "nodes": [0, 1] }],
        "nodes": [{ "mesh": 0 }, { "translation": [0, 2, 0], "extensions": { "KHR_lights_punctual": { "light": 0 } } }],
    }))
}

#[test]
fn shadow_settings_round_trip_exactly() {
    let mut scene = Scene::builtin("default").unwrap();
    let settings = [
        ShadowSettings { casts: false, resolution: 256, filter: ShadowFilter::Hard, cascades: true, pcss_taps: 16 },
        ShadowSettings { casts: true, resolution: 4096, filter: ShadowFilter::Poisson, cascades: false, pcss_taps: 16 },
        ShadowSettings { casts: true, resolution: 1000, filter: ShadowFilter::Pcf, cascades: true, pcss_taps: 16 },
        ShadowSettings { casts: true, resolution: 512, filter: ShadowFilter::Pcss, cascades: true, pcss_taps: 32 },
    ];
    scene.lights.push(Light::spot(DVec3::new(1.0, 3.0, 0.0), DVec3::NEG_Y, [1.0; 3], 2.0, 0.1, (0.2, 0.5)));
    let mut area =
        Light::area(LightKind::Rect, DVec3::new(0.0, 2.0, 0.0), DVec3::NEG_Y, [0.4, 0.3], [1.0; 3], 1.0, 0.0);
    area.area_points = 9;
    scene.lights.push(area);
    for (l, s) in scene.lights.iter_mut().zip(settings) {
        l.shadow = s;
    }
    let none = SceneSettings::default();
    for bytes in [scene_to_glb(&scene, &none), scene_to_gltf_json(&scene, &none).into_bytes()] {
        let back = load(&bytes).scene;
        assert_same_scene(&scene, &back);
        assert_eq!(back.lights.iter().map(|l| l.shadow).collect::<Vec<_>>(), settings);
        assert_eq!(back.lights[3].area_points, 9, "the area light's point sources");
    }
    // A file without the keys gets the model's defaults; each key alone changes only itself.
    let s = load(&light_with_extras(json!({}))).scene;
    assert_eq!(s.lights[0].shadow, ShadowSettings::default());
    let s = load(&light_with_extras(json!({ "shadelab": { "shadow_filter": "hard", "shadow_resolution": 512.0 } })));
    let want = ShadowSettings { resolution: 512, filter: ShadowFilter::Hard, ..Default::default() };
    assert_eq!(s.scene.lights[0].shadow, want);
    let s = load(&light_with_extras(json!({ "shadelab": { "shadow_cascades": false } })));
    assert_eq!(s.scene.lights[0].shadow, ShadowSettings { cascades: false, ..Default::default() });
}

#[test]
fn a_bad_shadow_setting_is_one_error_line_naming_the_key() {
    let (lo, hi) = (SHADOW_RESOLUTION.min, SHADOW_RESOLUTION.max);
    for (bad, says) in [
        (
            json!({ "shadow_resolution": 128 }),
            format!("extras.shadelab.shadow_resolution = 128 is not an integer in [{lo}, {hi}]"),
        ),
        (json!({ "shadow_resolution": 8192 }), format!("shadow_resolution = 8192 is not an integer in [{lo}, {hi}]")),
        (json!({ "shadow_resolution": 1024.5 }), "shadow_resolution = 1024.5 is not an integer".into()),
        (json!({ "shadow_resolution": "high" }), "shadow_resolution = \"high\" is not an integer".into()),
        (
            json!({ "shadow_filter": "vsm" }),
            "extras.shadelab.shadow_filter = \"vsm\" is not one of hard, pcf, poisson".into(),
        ),
        (json!({ "casts_shadows": "yes" }), "extras.shadelab.casts_shadows = \"yes\" is not true or false".into()),
        (json!({ "casts_shadows": null }), "extras.shadelab.casts_shadows = null is not true or false".into()),
        (json!({ "pcss_taps": 2 }), "extras.shadelab.pcss_taps = 2 is not an integer in [4, 64]".into()),
        (json!({ "points": 17 }), "extras.shadelab.points = 17 is not an integer in [0, 16]".into()),
    ] {
        let e = load_scene_from_slice(&light_with_extras(json!({ "shadelab": bad }))).unwrap_err().to_string();
        assert!(e.starts_with("<memory>: light 0: ") && e.contains(&says) && !e.contains('\n'), "{e}\nlacks: {says}");
    }
}

/// Area lights round-trip through `extras.shadelab` (kind, width, height, tangent, PCSS), while
/// the file's KHR light is what other viewers draw: a point light for a sphere, a spot light
/// lighting the half-space in front for a rectangle or disk. A bad width is one error line, and
/// area extras on a directional light are dropped with a warning.
#[test]
fn area_lights_round_trip_as_extras_on_punctual_lights() {
    let mut scene = Scene::builtin("sphere").unwrap();
    let mut rect = Light::area(
        LightKind::Rect,
        DVec3::new(0.5, 2.5, 0.0),
        DVec3::new(0.1, -1.0, 0.0),
        [0.8, 0.3],
        [1.0; 3],
        2.0,
        0.1,
    );
    rect.tangent = DVec3::new(0.0, 0.0, 1.0);
    let disk = Light::area(LightKind::Disk, DVec3::new(-1.0, 2.0, 1.0), DVec3::NEG_Y, [0.4; 2], [1.0; 3], 1.0, 0.0);
    let sphere =
        Light::area(LightKind::Sphere, DVec3::new(1.0, 1.5, -1.0), DVec3::NEG_Y, [0.25; 2], [1.0; 3], 1.0, 0.2);
    scene.lights = vec![rect, disk, sphere];
    assert!(scene.lights.iter().all(|l| l.shadow.filter == ShadowFilter::Pcss), "area lights take PCSS");
    let none = SceneSettings::default();
    let json = scene_to_gltf_json(&scene, &none);
    let file: Value = serde_json::from_str(&json).unwrap();
    let types: Vec<&str> = file["extensions"]["KHR_lights_punctual"]["lights"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["type"].as_str().unwrap())
        .collect();
    assert_eq!(types, ["spot", "spot", "point"]);
    let outer = &file["extensions"]["KHR_lights_punctual"]["lights"][0]["spot"]["outerConeAngle"];
    assert!((outer.as_f64().unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-6, "{outer}");
    for bytes in [scene_to_glb(&scene, &none), json.into_bytes()] {
        let back = load(&bytes);
        assert_same_scene(&scene, &back.scene);
        assert_eq!(
            back.scene.lights.iter().map(|l| l.kind).collect::<Vec<_>>(),
            [LightKind::Rect, LightKind::Disk, LightKind::Sphere]
        );
        assert!(back.scene.lights.iter().all(|l| l.shadow.filter == ShadowFilter::Pcss));
        assert!(back.warnings.iter().all(|w| !w.contains("area")), "{:?}", back.warnings);
    }
    let e = load_scene_from_slice(&light_with_extras(json!({ "shadelab": { "area": "rect", "width": -1.0 } })))
        .unwrap_err()
        .to_string();
    assert!(e.contains("extras.shadelab.width = -1") && e.contains("[0, 1000000]") && !e.contains('\n'), "{e}");
    let e =
        load_scene_from_slice(&light_with_extras(json!({ "shadelab": { "area": "tube" } }))).unwrap_err().to_string();
    assert!(e.contains("extras.shadelab.area = \"tube\"") && e.contains("rect, disk, sphere"), "{e}");
    // A directional light cannot have an area: kept directional, said so.
    let dir = triangle(json!({
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": [{ "type": "directional", "extras": { "shadelab": { "area": "disk" } } }] } },
        "scenes": [{ "nodes": [0, 1] }],
        "nodes": [{ "mesh": 0 }, { "extensions": { "KHR_lights_punctual": { "light": 0 } } }],
    }));
    let s = load(&dir);
    assert_eq!(s.scene.lights[0].kind, LightKind::Directional);
    assert!(s.warnings.iter().any(|w| w.contains("area \"disk\" ignored")), "{:?}", s.warnings);
}
