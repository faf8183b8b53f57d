//! Tests of the environment light in `extras.shadelab.environment`: each source round-trips,
//! a map file is read beside the scene file, a bad one is one line, and
//! `EXT_lights_image_based` is named among the ignored extensions.

use super::*;
use crate::lighting::env_file::write_env_exr;
use crate::lighting::env_map::{EnvImage, EnvSource, Environment};
use std::sync::Arc;

fn with_env(source: EnvSource) -> Scene {
    let mut s = Scene::builtin("default").unwrap();
    s.environment = Some(Environment {
        source,
        intensity: 2.5,
        rotation_deg: -30.0,
        specular: false,
        occlusion: true,
        background: true,
    });
    s
}

#[test]
fn uniform_and_sky_round_trip() {
    for source in [
        EnvSource::Uniform([0.1, 0.2, 0.3]),
        EnvSource::Sky { turbidity: 4.5, sun: Some(DVec3::new(0.3, 0.8, -0.1)) },
        EnvSource::Sky { turbidity: 2.0, sun: None },
    ] {
        let scene = with_env(source);
        let back = load(scene_to_gltf_json(&scene, &SceneSettings::default()).as_bytes());
        assert_eq!(back.scene.environment, scene.environment);
    }
}

#[test]
fn a_map_is_read_beside_the_scene_file() {
    let dir = std::env::temp_dir().join(format!("shadelab-gltf-env-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let texels = (0..32).map(|i| [i as f32, 0.5, 2.0]).collect();
    let img = EnvImage { name: dir.join("sky.exr").display().to_string(), width: 8, height: 4, texels };
    std::fs::write(dir.join("sky.exr"), write_env_exr(&img).unwrap()).unwrap();
    let scene = with_env(EnvSource::Image(Arc::new(img.clone())));
    let path = dir.join("s.gltf");
    save_scene(&scene, &SceneSettings::default(), &path).unwrap();
    let back = load_scene(&path).unwrap();
    let Some(Environment { source: EnvSource::Image(read), intensity, rotation_deg, .. }) = back.scene.environment
    else {
        panic!("no map: {:?}", back.scene.environment)
    };
    assert_eq!((read.texels.clone(), intensity, rotation_deg), (img.texels, 2.5, -30.0));
    // A broken map is one line naming the field and the file.
    std::fs::write(dir.join("sky.exr"), b"not a map").unwrap();
    let e = load_scene(&path).unwrap_err().to_string();
    assert!(e.contains("extras.shadelab.environment") && e.contains("sky.exr") && !e.contains('\n'), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_map_without_a_uri_or_outside_the_folder_is_refused() {
    for (env, says) in [
        (json!({ "source": "image" }), "needs a uri"),
        (json!({ "source": "image", "uri": "/etc/passwd" }), "environment"),
        (json!({ "source": "sky", "turbidity": 40 }), "turbidity"),
        (json!({ "source": "moon" }), "source"),
    ] {
        let doc = triangle(json!({ "scenes": [{ "nodes": [0], "extras": { "shadelab": { "environment": env } } }] }));
        let e = load_scene_from_slice(&doc).unwrap_err().to_string();
        assert!(e.contains(says) && !e.contains('\n'), "{env}: {e}");
    }
}

#[test]
fn ext_lights_image_based_is_named_as_ignored() {
    let s = load(&triangle(json!({ "extensionsUsed": ["EXT_lights_image_based"] })));
    assert!(s.warnings.iter().any(|w| w.contains("ignored: EXT_lights_image_based")), "{:?}", s.warnings);
    assert_eq!(s.scene.environment, None);
}
