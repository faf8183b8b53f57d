//! Tests of the scene file as a whole: every built-in scene and shipped asset round trips, saving by
//! extension, extensions the loader does not read, and a public sample file.

use super::*;

#[test]
fn every_builtin_scene_round_trips_through_gltf_and_glb() {
    for name in crate::scene::BUILTIN_SCENES {
        let scene = Scene::builtin(name).unwrap();
        let settings = SceneSettings { shading: Some(ShadingMode::Gouraud), specular: Some(SpecularModel::Phong) };
        for bytes in [scene_to_gltf_json(&scene, &settings).into_bytes(), scene_to_glb(&scene, &settings)] {
            let back = load(&bytes);
            assert_same_scene(&scene, &back.scene);
            // The extras carry every f64 exactly, so the scene comes back equal, bit for bit.
            assert_eq!(back.scene, scene, "{name}");
            assert_eq!(back.settings, settings);
            assert!(back.warnings.is_empty(), "{name}: {:?}", back.warnings);
            // Analytic shapes come back analytic: the same tessellation, no stored mesh.
            assert!(back.scene.meshes.is_empty(), "{name}");
            // Saving what was loaded is a fixed point (the first save rounds transforms to f32).
            let again = scene_to_gltf_json(&back.scene, &back.settings);
            let twice = load(again.as_bytes());
            assert!(again == scene_to_gltf_json(&twice.scene, &twice.settings), "{name}: second save differs");
        }
    }
}

/// A transparent material's given index per channel and the scene's absorption choice come back
/// exactly; without a given index none comes back (it follows μ).
#[test]
fn glass_parameters_round_trip() {
    let mut scene = Scene::builtin("glass").unwrap();
    scene.absorption = crate::lighting::transmission::AbsorptionChoice::Exact;
    scene.materials[3].ior = Some([1.45, 1.5, 1.6]);
    let settings = SceneSettings::default();
    let back = load(scene_to_gltf_json(&scene, &settings).as_bytes()).scene;
    assert_eq!(back, scene);
    assert_eq!(back.materials[4].ior, None);
}

#[test]
fn save_scene_writes_gltf_or_glb_by_extension() {
    let dir = std::env::temp_dir().join(format!("shadelab-gltf-save-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = Scene::builtin("cube").unwrap();
    for file in ["s.gltf", "s.glb"] {
        let path = dir.join(file);
        save_scene(&scene, &SceneSettings::default(), &path).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        assert_eq!(bytes.starts_with(b"glTF"), file.ends_with(".glb"));
        let back = load_scene(&path).unwrap();
        assert_same_scene(&scene, &back.scene);
        assert_eq!(back.settings, SceneSettings::default());
    }
    let e = save_scene(&scene, &SceneSettings::default(), &dir.join("no/such/dir/s.gltf")).unwrap_err();
    assert!(e.to_string().contains("s.gltf: cannot write"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn shipped_assets_match_their_generators() {
    // `UPDATE_ASSETS=1` rewrites the files from their constructors first (look at the renders
    // of every file it changes before committing it), like `UPDATE_GOLDENS`.
    let update = std::env::var("UPDATE_ASSETS").as_deref() == Ok("1");
    for a in &ASSET_SCENES {
        let path = project_root().join("assets").join(a.file);
        if update {
            save_scene(&(a.scene)(), &a.settings, &path).unwrap();
            eprintln!("wrote {}", path.display());
        }
        let mut loaded = load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
        // A loaded texture keeps the PNG it came from; the constructor's have none yet.
        for t in &mut loaded.scene.textures {
            t.encoded = None;
        }
        let want = (a.scene)();
        assert_same_scene(&want, &loaded.scene);
        assert_eq!(loaded.scene.camera, want.camera, "{}", a.file);
        assert_eq!(loaded.scene.lights, want.lights, "{}", a.file);
        assert_eq!(loaded.scene.objects, want.objects, "{}", a.file);
        assert_eq!(loaded.scene.materials, want.materials, "{}", a.file);
        assert_eq!(loaded.scene.meshes, want.meshes, "{}", a.file);
        assert_eq!(loaded.scene.textures, want.textures, "{}", a.file);
        assert_eq!(loaded.scene, want, "{}", a.file);
        assert_eq!(loaded.settings, a.settings, "{}", a.file);
        assert!(loaded.warnings.is_empty(), "{}: {:?}", a.file, loaded.warnings);
        let size = std::fs::metadata(&path).unwrap().len();
        assert!(size < 1_000_000, "{}: {size} bytes", a.file);
    }
}

#[test]
fn unsupported_optional_extensions_are_warnings() {
    let s = load(&triangle(json!({
        "extensionsUsed": ["KHR_texture_transform", "EXT_meshopt_compression", "KHR_lights_punctual"],
    })));
    let w = s.warnings.join("\n");
    assert!(w.contains("optional extension(s) not supported, ignored: EXT_meshopt_compression"), "{w}");
}

/// The public sample `Box.gltf` (Khronos sample models, CC-BY 4.0), read from beside the checkout.
#[test]
fn khronos_box_sample_loads() {
    let path = project_root().join("../shared/gltf-samples/Box.gltf");
    if !path.exists() {
        eprintln!("note: {} is missing; skipping the Box.gltf test", path.display());
        return;
    }
    let s = load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.scene.objects.len(), 1);
    assert_eq!(s.scene.triangle_count(), 12);
    assert_eq!(s.scene.materials.len(), 1);
    // The root node turns y up into −z; turned back, the unit box's bounds are ±0.5 on every axis.
    let (lo, hi) = s.scene.meshes[0].bounds().unwrap();
    near(lo, DVec3::splat(-0.5), "min");
    near(hi, DVec3::splat(0.5), "max");
    // Its file normals are used: 24 vertices, one normal per face corner.
    let m = s.scene.mesh_data(&s.scene.objects[0]);
    assert_eq!(m.smooth_vertices.len(), 24);
    assert!(s.warnings.iter().any(|w| w.contains("no lights")));
    // Its material gives only a base colour: metallic and roughness default to 1 (glTF 2.0
    // §5.22), a rough red metal: μ = base colour, no diffuse colour, m = 1.
    let mat = &s.scene.materials[0];
    assert_eq!((mat.mu, mat.color, mat.m), ([0.8f32 as f64, 0.0, 0.0], [0.0; 3], 1.0), "{mat:?}");
    // And it survives a round trip.
    let again = load(scene_to_gltf_json(&s.scene, &s.settings).as_bytes()).scene;
    assert_same_scene(&s.scene, &again);
}
