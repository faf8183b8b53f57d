//! The scene the flags ask for: a built-in scene or a glTF file, seen through the chosen camera,
//! with the flags' overrides applied.

use super::SceneArgs;
use crate::Failure;
use shadelab_model::gltf_io::{self, LoadedScene, SceneSettings};
use shadelab_model::params::{self, ParamError};
use shadelab_model::{Overrides, Scene};

/// Build the scene the arguments ask for.
pub fn scene(args: &SceneArgs) -> Result<Scene, Failure> {
    load(args).map(|l| l.scene)
}

/// Build the scene the arguments ask for: a built-in scene, or a glTF file (a name that is not
/// built in and ends in .gltf/.glb or names a file), seen through the camera `--camera` picks,
/// with the overrides applied. A bad file is the user's mistake (exit 2); its warnings are
/// logged. A built-in scene lists its one camera.
pub fn load(args: &SceneArgs) -> Result<LoadedScene, Failure> {
    let mut loaded = load_unchanged(args)?;
    apply_flags(args, &mut loaded.scene)?;
    Ok(loaded)
}

/// The scene `--scene` names, through the camera `--camera` picks, before the overrides.
pub fn load_unchanged(args: &SceneArgs) -> Result<LoadedScene, Failure> {
    let name = &args.scene;
    let is_file = {
        let lower = name.to_ascii_lowercase();
        lower.ends_with(".gltf") || lower.ends_with(".glb") || std::path::Path::new(name).is_file()
    };
    let mut loaded = match Scene::builtin(name) {
        Some(s) => LoadedScene {
            cameras: vec![("the scene's camera".into(), s.camera)],
            scene: s,
            settings: SceneSettings::default(),
            warnings: Vec::new(),
        },
        None if is_file && std::path::Path::new(name).exists() => {
            let loaded = gltf_io::load_scene_with(std::path::Path::new(name), args.allow_outside_paths)
                .map_err(|e| Failure::Usage(e.to_string()))?;
            for w in &loaded.warnings {
                log::warn!("{name}: {w}");
            }
            loaded
        }
        None => {
            return Err(ParamError::Unknown {
                flag: "--scene".into(),
                value: name.clone(),
                allowed: format!(
                    "{}, or an existing .gltf/.glb file",
                    shadelab_model::scene::BUILTIN_SCENES.join(", ")
                ),
            }
            .into());
        }
    };
    pick_camera(args, &mut loaded)?;
    Ok(loaded)
}

/// Look through the camera `--camera` picks among the loaded scene's (none given: its first).
pub fn pick_camera(args: &SceneArgs, loaded: &mut LoadedScene) -> Result<(), Failure> {
    // The camera's range is the file's camera count, known only now (so not a clap parser).
    if let Some(text) = &args.camera {
        let n = loaded.cameras.len();
        let range = params::ParamRange {
            flag: "--camera",
            symbol: "N",
            meaning: "camera number (the scene's cameras, counted from 0)",
            min: 0.0,
            max: (n - 1) as f64,
        };
        loaded.scene.camera = loaded.cameras[range.parse_u32(text)? as usize].1;
    }
    Ok(())
}

/// The flags' overrides and environment applied to `scene`.
pub fn apply_flags(args: &SceneArgs, scene: &mut Scene) -> Result<(), Failure> {
    scene.apply(&overrides(args));
    environment(args, scene)
}

/// The environment the flags ask for, in place of the scene's: `--environment` picks its source,
/// the others set its intensity, turn and turbidity. An adjustment without an environment to
/// adjust is the user's mistake.
fn environment(args: &SceneArgs, scene: &mut Scene) -> Result<(), Failure> {
    use shadelab_model::lighting::env_map::{EnvSource, Environment};
    let sky = EnvSource::Sky {
        turbidity: args.turbidity.unwrap_or(shadelab_model::lighting::sky::TURBIDITY_DEFAULT),
        sun: None,
    };
    match args.environment.as_deref() {
        None => {}
        Some("none") => scene.environment = None,
        Some("uniform") => scene.environment = Some(Environment::new(EnvSource::Uniform(scene.ambient))),
        Some("sky") => scene.environment = Some(Environment::new(sky)),
        Some(path) => {
            let (img, warnings) = shadelab_model::lighting::env_file::load_env_image(std::path::Path::new(path))
                .map_err(|e| Failure::Usage(format!("--environment: {e}")))?;
            for w in warnings {
                log::warn!("{w}");
            }
            scene.environment = Some(Environment::new(EnvSource::Image(std::sync::Arc::new(img))));
        }
    }
    // The environment takes the place of the constant ambient it stands for.
    if args.environment.as_deref().is_some_and(|e| e != "none") {
        scene.ambient = [0.0; 3];
    }
    let adjusts = [
        ("--env-intensity", args.env_intensity.is_some()),
        ("--env-rotation", args.env_rotation.is_some()),
        ("--turbidity", args.turbidity.is_some()),
        ("--env-occlusion", args.env_occlusion.is_some()),
        ("--env-background", args.env_background.is_some()),
    ];
    let Some(env) = scene.environment.as_mut() else {
        if let Some((flag, _)) = adjusts.iter().find(|(_, given)| *given) {
            return Err(Failure::Usage(format!(
                "{flag}: the scene has no environment; add --environment uniform, sky or a map file"
            )));
        }
        return Ok(());
    };
    if let Some(v) = args.env_intensity {
        env.intensity = v;
    }
    if let Some(v) = args.env_rotation {
        env.rotation_deg = v;
    }
    if let Some(on) = args.env_specular {
        env.specular = on;
    }
    if let Some(on) = args.env_occlusion {
        env.occlusion = on;
    }
    if let Some(on) = args.env_background {
        env.background = on;
    }
    if let Some(t) = args.turbidity {
        match &mut env.source {
            EnvSource::Sky { turbidity, .. } => *turbidity = t,
            _ => return Err(Failure::Usage("--turbidity: only for --environment sky".into())),
        }
    }
    Ok(())
}

/// The parameters the flags override (each checked by its value parser).
pub fn overrides(a: &SceneArgs) -> Overrides {
    Overrides {
        m: a.m,
        h: a.h,
        mu: a.mu,
        transmission: a.transmission,
        ior: a.ior,
        absorption_coef: a.absorption_coef,
        absorption: a.absorption,
        falloff_alpha: a.falloff,
        falloff_form: a.falloff_form,
        d0: a.d0,
        light: a.light,
        light_size: a.light_size,
        area_points: a.area_points,
        area_specular: a.area_specular,
        shadows: a.shadows,
        shadow_resolution: a.shadow_resolution,
        shadow_filter: a.shadow_filter,
        pcss_taps: a.pcss_taps,
        shadow_cascades: a.shadow_cascades,
        // `--model` is a mode flag (ModeArgs::settle).
        illumination: None,
        microfacet: a.microfacet,
        distribution: a.distribution,
        masking: a.masking,
        fresnel: a.fresnel,
        phong_normalized: a.phong_normalized,
        multiple_scattering: a.multiple_scattering,
        fresnel_mix: a.fresnel_mix,
    }
}
