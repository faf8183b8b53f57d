//! Command-line arguments. Values arrive as text and are validated by the model's ranges, so a
//! mistake gets one line naming the flag and its allowed range (exit code 2).

use crate::Failure;
use clap::{Args, Parser, Subcommand};
use shadelab_model::gltf_io::{self, LoadedScene, SceneSettings};
use shadelab_model::params::{self, NamedValue, ParamError};
use shadelab_model::{FalloffForm, LightKind, Overrides, Scene, ShadingMode, SpecularModel};
use shadelab_render::RenderSettings;
use std::path::PathBuf;

#[derive(Parser, Debug)]
#[command(
    name = "shadelab",
    version,
    about = "Flat, Gouraud and Phong shading with Phong or Cook–Torrance specular: a viewer, headless renders and benchmarks."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Viewer: save the window's content (panel included) to this PNG, then exit (with
    /// --exit-after-frames).
    #[arg(long, value_name = "PATH")]
    pub screenshot: Option<PathBuf>,
    /// Viewer: render this many frames, then exit 0.
    #[arg(long, value_name = "N")]
    pub exit_after_frames: Option<String>,
    /// Viewer: the scene to start on and its overrides, as `render` takes them.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Viewer: the shading mode and specular model to start in.
    #[command(flatten)]
    pub mode: ModeArgs,
    /// Viewer, for developers: reload the WGSL from this folder (e.g. `shaders`) when a file
    /// changes; a shader error is shown in the panel and the previous pipelines are kept.
    #[arg(long, value_name = "DIR")]
    pub shaders: Option<std::path::PathBuf>,
    /// Viewer: start with the "difference from reference" view on (FLIP error map of the mode
    /// against the f64 reference, with its numbers and the GPU time).
    #[arg(long)]
    pub difference: bool,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render a scene headless to a PNG (sRGB) or an EXR (linear float).
    Render(RenderArgs),
    /// Measure: frame time per shading mode × specular model, what accuracy costs, what
    /// specialization saves, what a (large) scene file costs to open.
    #[command(subcommand)]
    Bench(BenchCommand),
    /// Evaluate every lighting term of the shipped WGSL over >10⁶ hard input combinations on the
    /// GPU and compare with the f64 reference: non-finite values, bounds, relative errors.
    Sweep,
}

#[derive(Subcommand, Debug)]
pub enum BenchCommand {
    /// Frame time of a scene for each shading × specular combination, interleaved in one run.
    Render(BenchRenderArgs),
    /// What accuracy costs in time: every shading mode × specular model × level of detail ×
    /// resolution of the analytic scenes, timed against a null-shader baseline and compared
    /// with the f64 reference; also the cost per light and per resolution. Writes a CSV, a
    /// Markdown report and plots.
    Accuracy(BenchAccuracyArgs),
    /// What specialization saves: each scene drawn by its specialized pipeline (only the effects
    /// it calls for), by the uber pipeline (every effect, switched off at run time) and, per
    /// effect, by the specialized pipeline without it (the floor), interleaved in one run.
    Effects(BenchEffectsArgs),
    /// What a scene file costs to open: load (read, check, triangles), build + upload (normals,
    /// GPU buffers), first frame (pipeline + draw), the next frame, and the process's peak
    /// memory. One scene per process, so the peak is this scene's.
    Load(BenchLoadArgs),
    /// Large meshes: generate spheres of about the given triangle counts as .glb and run
    /// `bench load` on each in a fresh process (under /usr/bin/time -v when installed).
    Mesh(BenchMeshArgs),
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchLoadArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub mode: ModeArgs,
    #[command(flatten)]
    pub size: SizeArgs,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchMeshArgs {
    /// Triangle counts, comma-separated, each in [1, MAX_TRIANGLES].
    #[arg(long, default_value = "1000000,10000000", value_name = "N,N,...")]
    pub triangles: String,
    /// Leave NORMAL out of the files: the loader makes normals by the crease-angle rule.
    #[arg(long)]
    pub without_normals: bool,
    /// Folder for the generated .glb files (kept, so that they can be opened in the viewer).
    #[arg(long, default_value = "bench-mesh", value_name = "DIR")]
    pub out: PathBuf,
    /// flat | gouraud | phong
    #[arg(long, default_value = "phong")]
    pub shading: String,
    #[command(flatten)]
    pub size: SizeArgs,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchEffectsArgs {
    /// Scenes: built-in names or glTF files (repeat the flag for several).
    #[arg(long = "scene", default_value = "default", value_name = "NAME|PATH")]
    pub scenes: Vec<String>,
    #[command(flatten)]
    pub size: SizeArgs,
    /// Measured frames per pipeline (after warm-up).
    #[arg(long, default_value = "50")]
    pub frames: String,
    /// Warm-up frames per pipeline (not measured).
    #[arg(long, default_value = "3")]
    pub warmup: String,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchAccuracyArgs {
    /// A small subset (2 scenes, 3 levels, small sizes, 10 frames): well under a minute.
    #[arg(long)]
    pub quick: bool,
    /// Folder for accuracy.csv, accuracy.md, error-vs-time.png and scaling.png.
    #[arg(long, default_value = "bench-accuracy", value_name = "DIR")]
    pub out: PathBuf,
    /// Measured frames per configuration (default 50; 10 with --quick).
    #[arg(long, value_name = "N")]
    pub frames: Option<String>,
    /// Warm-up frames per configuration (default 5; 2 with --quick).
    #[arg(long, value_name = "N")]
    pub warmup: Option<String>,
}

/// The scene and the parameters that override it (shared by `render` and `bench`).
#[derive(Args, Debug, Clone, Default)]
#[command(allow_negative_numbers = true)]
pub struct SceneArgs {
    /// A built-in scene (default, sphere, cylinder, pyramid, cube) or a glTF 2.0 file (.gltf, .glb).
    #[arg(long, default_value = "default", value_name = "NAME|PATH")]
    pub scene: String,
    /// Roughness m of every material, in [0, 1].
    #[arg(long)]
    pub m: Option<String>,
    /// Phong exponent h of every material, in [1, 1e9], or 'mirror'.
    #[arg(long)]
    pub h: Option<String>,
    /// Normal-incidence reflectance μ of every material: R,G,B or one value, each in [0, 1].
    #[arg(long, value_name = "R,G,B")]
    pub mu: Option<String>,
    /// Falloff factor α of every point and spot light, I0/(1 + α d²), in [0, 1e6].
    #[arg(long, value_name = "ALPHA")]
    pub falloff: Option<String>,
    /// Falloff form of every point and spot light: quadratic (1/(1 + α d²)) or linear (the
    /// chapter's 1/(d + d0)).
    #[arg(long, value_name = "FORM")]
    pub falloff_form: Option<String>,
    /// d0 of the linear falloff 1/(d + d0), in [0.001, 1000].
    #[arg(long)]
    pub d0: Option<String>,
    /// Which of a scene file's cameras to look through: 0 (the first, the default) to the number
    /// of cameras − 1, in the file's node order. A built-in scene has one.
    #[arg(long, value_name = "N")]
    pub camera: Option<String>,
    /// Make every light directional, point or spot (a spot gets glTF's default cone, 45°, aimed
    /// at the origin).
    #[arg(long, value_name = "directional|point|spot")]
    pub light: Option<String>,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct RenderArgs {
    #[command(flatten)]
    pub mode: ModeArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Also write the scene, after the overrides, as glTF 2.0 (.gltf with an embedded buffer, or
    /// .glb), with the shading mode and specular model in its extras.
    #[arg(long, value_name = "PATH")]
    pub save_scene: Option<PathBuf>,
    #[command(flatten)]
    pub size: SizeArgs,
    /// Output file: .png (8-bit sRGB) or .exr (linear 32-bit float).
    #[arg(long, default_value = "shadelab.png", value_name = "PATH")]
    pub output: PathBuf,
    /// Paint pixels whose colour is NaN or infinite magenta.
    #[arg(long)]
    pub debug_nonfinite: bool,
    /// Print the effects the scene calls for (the shader holds only those), each with its reason.
    #[arg(long)]
    pub explain: bool,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchRenderArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub size: SizeArgs,
    /// Measured frames per combination (after warm-up).
    #[arg(long, default_value = "30")]
    pub frames: String,
    /// Warm-up frames per combination (not measured).
    #[arg(long, default_value = "3")]
    pub warmup: String,
}

/// The image size (`render` and every `bench`).
#[derive(Args, Debug, Clone)]
pub struct SizeArgs {
    /// Width in pixels, 1 to 8192.
    #[arg(long, default_value = "1280")]
    pub width: String,
    /// Height in pixels, 1 to 8192.
    #[arg(long, default_value = "720")]
    pub height: String,
}

impl SizeArgs {
    /// The size, each side checked against its range.
    pub fn parse(&self) -> Result<(u32, u32), ParamError> {
        size(&self.width, &self.height)
    }
}

/// The shading mode and specular model (`render`, `bench load`, the viewer).
#[derive(Args, Debug, Clone, Default)]
pub struct ModeArgs {
    /// flat | gouraud | phong [default: the scene file's, else phong]
    #[arg(long)]
    pub shading: Option<String>,
    /// phong | cook-torrance [default: the scene file's, else cook-torrance]
    #[arg(long)]
    pub specular: Option<String>,
}

impl ModeArgs {
    /// Each flag when given, else what the scene file records, else Phong shading with
    /// Cook–Torrance specular.
    pub fn resolve(&self, file: SceneSettings) -> Result<RenderSettings, ParamError> {
        Ok(RenderSettings::new(
            flag_or_file(self.shading.as_deref(), file.shading, ShadingMode::Phong)?,
            flag_or_file(self.specular.as_deref(), file.specular, SpecularModel::CookTorrance)?,
        ))
    }
}

/// Warm-up frames of a benchmark (at least one is always drawn, to build the pipelines).
pub const WARMUP: params::ParamRange =
    params::ParamRange { flag: "--warmup", symbol: "N", meaning: "number of warm-up frames", min: 0.0, max: 1e6 };

/// Frames for benchmarks and the viewer's --exit-after-frames.
pub const FRAMES: params::ParamRange =
    params::ParamRange { flag: "--frames", symbol: "N", meaning: "number of frames", min: 1.0, max: 1e6 };

/// Build the scene the arguments ask for.
pub fn scene(args: &SceneArgs) -> Result<Scene, Failure> {
    load(args).map(|l| l.scene)
}

/// Build the scene the arguments ask for: a built-in scene, or a glTF file (a name that is not
/// built in and ends in .gltf/.glb or names a file), seen through the camera `--camera` picks,
/// with the overrides applied. A bad file is the user's mistake (exit 2); its warnings are
/// logged. A built-in scene lists its one camera.
pub fn load(args: &SceneArgs) -> Result<LoadedScene, Failure> {
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
            let loaded = gltf_io::load_scene(std::path::Path::new(name)).map_err(|e| Failure::Usage(e.to_string()))?;
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
    loaded.scene.apply(&overrides(args)?);
    Ok(loaded)
}

/// `--shading`/`--specular`: the flag when given, else the scene file's choice, else `default`.
fn flag_or_file<T: NamedValue + PartialEq>(flag: Option<&str>, file: Option<T>, default: T) -> Result<T, ParamError> {
    flag.map_or(Ok(file.unwrap_or(default)), T::parse_named)
}

pub fn overrides(a: &SceneArgs) -> Result<Overrides, ParamError> {
    Ok(Overrides {
        m: a.m.as_deref().map(|t| params::M.parse(t)).transpose()?,
        h: a.h.as_deref().map(params::parse_h).transpose()?,
        mu: a.mu.as_deref().map(params::parse_mu).transpose()?,
        falloff_alpha: a.falloff.as_deref().map(|t| params::FALLOFF.parse(t)).transpose()?,
        falloff_form: a.falloff_form.as_deref().map(FalloffForm::parse_named).transpose()?,
        d0: a.d0.as_deref().map(|t| params::D0.parse(t)).transpose()?,
        light: a.light.as_deref().map(LightKind::parse_named).transpose()?,
    })
}

pub fn size(width: &str, height: &str) -> Result<(u32, u32), ParamError> {
    Ok((params::WIDTH.parse_u32(width)?, params::HEIGHT.parse_u32(height)?))
}
