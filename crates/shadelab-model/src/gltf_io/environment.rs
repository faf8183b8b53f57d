//! The environment light in `extras.shadelab.environment` of the glTF scene (docs/environment.md):
//! its source (a uniform colour, the sky with its turbidity and sun, or a map file named by a URI
//! beside the scene file, read as buffers and images are), its intensity and its turn.
//! `EXT_lights_image_based` is not read: the loader names it among the ignored extensions.

use super::GltfError;
use super::container::{Externals, data_uri, read_external_whole};
use super::extras::{EnvIntensity, EnvRadiance, EnvRotation, Flag, Named, Num, Rgb, Turbidity, Vec3};
use super::scene_file::Cx;
use crate::lighting::env_file::{MAX_ENV_FILE_BYTES, read_env_image};
use crate::lighting::env_map::{EnvKind, EnvSource, Environment};
use std::sync::Arc;

super::extras_struct! {
    /// `extras.shadelab.environment` (fields in the order they are checked).
    pub(super) struct EnvironmentExtras {
        source: Option<Named<EnvKind>>,
        color: Option<Rgb<EnvRadiance>>,
        turbidity: Option<Num<Turbidity>>,
        /// Toward the sun; absent: the sky follows the first directional light.
        sun: Option<Vec3>,
        /// The map file, relative to the scene file.
        uri: Option<String>,
        intensity: Option<Num<EnvIntensity>>,
        rotation: Option<Num<EnvRotation>>,
        /// False: the GPU leaves out its split-sum specular; absent is true.
        specular: Option<Flag>,
        /// True: the GPU occludes its diffuse light by the precomputed grid; absent is false.
        occlusion: Option<Flag>,
        /// True: drawn where the camera sees nothing, in place of the background; absent is false.
        background: Option<Flag>,
    }
}

/// The environment `ex` describes; its map from a data URI or a file read through `externals`. A source without what it
/// needs (a map without its URI) is one error line.
pub(super) fn read_environment(
    cx: &mut Cx,
    ex: EnvironmentExtras,
    externals: Externals,
) -> Result<Environment, GltfError> {
    let what = "scene: extras.shadelab.environment";
    let source = match ex.source.map(|s| s.0) {
        None | Some(EnvKind::Uniform) => EnvSource::Uniform(ex.color.map_or([0.0; 3], |c| c.0)),
        Some(EnvKind::Sky) => EnvSource::Sky {
            turbidity: ex.turbidity.map_or(crate::lighting::sky::TURBIDITY.min + 1.0, |t| t.0),
            sun: ex.sun.map(|s| s.0),
        },
        Some(EnvKind::Image) => {
            let Some(uri) = ex.uri else {
                return Err(cx.invalid(format!("{what}: source \"image\" needs a uri (an .hdr or .exr file)")));
            };
            let bytes = if uri.starts_with("data:") {
                data_uri(cx, what, &uri)?
            } else {
                read_external_whole(cx, what, &uri, MAX_ENV_FILE_BYTES, externals)?
            };
            let name = if uri.starts_with("data:") { "(a data URI)" } else { uri.as_str() };
            let (img, warnings) = read_env_image(&bytes, name).map_err(|e| cx.invalid(format!("{what}: {e}")))?;
            for w in warnings {
                cx.warn(w);
            }
            EnvSource::Image(Arc::new(img))
        }
    };
    Ok(Environment {
        source,
        intensity: ex.intensity.map_or(1.0, |v| v.0),
        rotation_deg: ex.rotation.map_or(0.0, |v| v.0),
        specular: ex.specular.is_none_or(|f| f.0),
        occlusion: ex.occlusion.is_some_and(|f| f.0),
        background: ex.background.is_some_and(|f| f.0),
    })
}

/// `env` as extras: a map is written as its file name (`EnvImage::name`), which must lie beside
/// the saved scene for it to load again.
pub(super) fn write_environment(env: &Environment) -> EnvironmentExtras {
    let mut ex = EnvironmentExtras {
        intensity: Some(env.intensity.into()),
        rotation: Some(env.rotation_deg.into()),
        specular: (!env.specular).then_some(Flag(false)),
        occlusion: env.occlusion.then_some(Flag(true)),
        background: env.background.then_some(Flag(true)),
        ..Default::default()
    };
    match &env.source {
        EnvSource::Uniform(c) => {
            ex.source = Some(Named(EnvKind::Uniform));
            ex.color = Some((*c).into());
        }
        EnvSource::Sky { turbidity, sun } => {
            ex.source = Some(Named(EnvKind::Sky));
            ex.turbidity = Some((*turbidity).into());
            ex.sun = sun.map(Vec3);
        }
        EnvSource::Image(img) => {
            ex.source = Some(Named(EnvKind::Image));
            let file = std::path::Path::new(&img.name).file_name().map(|f| f.to_string_lossy().into_owned());
            ex.uri = Some(file.unwrap_or_else(|| img.name.clone()));
        }
    }
    ex
}
