//! The flags of `shadelab bench …`, one struct a command.

use super::{FRAMES, MESH_TRIANGLES, ModeArgs, SceneArgs, SizeArgs, WARMUP, values, within};
use clap::Args;
use shadelab_model::params;
use shadelab_model::{AreaSpecular, LightKind, ModelChoice, ShadingMode};
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct BenchGlassArgs {
    #[arg(long, default_value = "640", value_parser = values::count(params::WIDTH),
          help = within("Width in pixels", params::WIDTH))]
    pub width: u32,
    #[arg(long, default_value = "360", value_parser = values::count(params::HEIGHT),
          help = within("Height in pixels", params::HEIGHT))]
    pub height: u32,
    #[command(flatten)]
    pub frames: RowFrames,
    /// Folder for glass.md, glass-methods.csv, glass-rule.csv and the rule's error maps.
    #[arg(long, default_value = "bench-glass", value_name = "DIR")]
    pub output: PathBuf,
}

#[derive(Args, Debug)]
pub struct BenchMicrofacetArgs {
    #[arg(long, default_value = "480", value_parser = values::count(params::WIDTH),
          help = within("Width in pixels", params::WIDTH))]
    pub width: u32,
    #[arg(long, default_value = "270", value_parser = values::count(params::HEIGHT),
          help = within("Height in pixels", params::HEIGHT))]
    pub height: u32,
    #[command(flatten)]
    pub frames: RowFrames,
    /// Folder for microfacet.md, microfacet-combos.csv, microfacet-schlick.csv and the maps.
    #[arg(long, default_value = "bench-microfacet", value_name = "DIR")]
    pub output: PathBuf,
}

/// The frames a study times for each of its rows: `--frames` measured after `--warmup`.
#[derive(Args, Debug)]
pub struct RowFrames {
    #[arg(long, default_value = "20", value_parser = values::count(FRAMES),
          help = within("Measured frames per row (after warm-up)", FRAMES))]
    pub frames: u32,
    #[arg(long, default_value = "2", value_parser = values::count(WARMUP),
          help = within("Warm-up frames per row (not measured)", WARMUP))]
    pub warmup: u32,
}

impl RowFrames {
    /// Measured and warm-up frames as counts.
    pub fn counts(&self) -> (usize, usize) {
        (self.frames as usize, self.warmup as usize)
    }
}

#[derive(Args, Debug)]
pub struct BenchPenumbraArgs {
    /// Folder for penumbra.csv, penumbra.md and penumbra.png.
    #[arg(long, default_value = "bench-penumbra", value_name = "DIR")]
    pub output: PathBuf,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchShadowsArgs {
    /// A built-in scene or a glTF file.
    #[arg(long, default_value = "default", value_name = "NAME|PATH")]
    pub scene: String,
    #[command(flatten)]
    pub size: SizeArgs,
    #[arg(long, value_name = "N", value_parser = values::count(FRAMES),
          help = within("Measured frames per row (default 30; 5 with --quick)", FRAMES))]
    pub frames: Option<u32>,
    #[arg(long, value_name = "N", value_parser = values::count(WARMUP),
          help = within("Warm-up frames per row (default 3; 1 with --quick)", WARMUP))]
    pub warmup: Option<u32>,
    /// Folder for shadows.csv, shadows.md and shadows.png.
    #[arg(long, default_value = "bench-shadows", value_name = "DIR")]
    pub output: PathBuf,
    /// Resolutions 256, 1024 and 4096 only, 5 frames.
    #[arg(long)]
    pub quick: bool,
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
    #[arg(
        long,
        default_value = "1000000,10000000",
        value_name = "N,N,...",
        value_delimiter = ',',
        value_parser = values::count(MESH_TRIANGLES),
        help = format!("Triangle counts, comma-separated, each in [{}, {}]", MESH_TRIANGLES.min, MESH_TRIANGLES.max)
    )]
    pub triangles: Vec<u32>,
    /// Leave NORMAL out of the files: the loader makes normals by the crease-angle rule.
    #[arg(long)]
    pub without_normals: bool,
    /// Folder for the generated .glb files (kept, so that they can be opened in the viewer).
    #[arg(long, default_value = "bench-mesh", value_name = "DIR")]
    pub out: PathBuf,
    /// The shading mode.
    #[arg(long, default_value = "phong", value_parser = values::named::<ShadingMode>())]
    pub shading: ShadingMode,
    #[command(flatten)]
    pub size: SizeArgs,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchEffectsArgs {
    /// Scenes: built-in names or glTF files (repeat the flag for several).
    #[arg(long = "scene", default_value = "default", value_name = "NAME|PATH")]
    pub scenes: Vec<String>,
    /// Light every scene with this illumination model (lambert, sum, phong, cook-torrance)
    /// [default: each scene's, with Cook–Torrance specular].
    #[arg(long, value_parser = values::named::<ModelChoice>())]
    pub model: Option<ModelChoice>,
    /// Make every light of every scene this kind (directional, point, spot, rect, disk, sphere).
    #[arg(long, value_name = "KIND", value_parser = values::named::<LightKind>())]
    pub light: Option<LightKind>,
    #[arg(long, value_name = "METRES", value_parser = values::real(params::LIGHT_SIZE),
          help = within("Width of every area light", params::LIGHT_SIZE))]
    pub light_size: Option<f64>,
    /// How every area light draws its specular (representative, ltc) [default: each light's own].
    #[arg(long, value_name = "representative|ltc", value_parser = values::named::<AreaSpecular>())]
    pub area_specular: Option<AreaSpecular>,
    #[command(flatten)]
    pub size: SizeArgs,
    #[arg(long, default_value = "50", value_parser = values::count(FRAMES),
          help = within("Measured frames per pipeline (after warm-up)", FRAMES))]
    pub frames: u32,
    #[arg(long, default_value = "3", value_parser = values::count(WARMUP),
          help = within("Warm-up frames per pipeline (not measured)", WARMUP))]
    pub warmup: u32,
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
    #[arg(long, value_name = "N", value_parser = values::count(FRAMES),
          help = within("Measured frames per configuration (default 50; 10 with --quick)", FRAMES))]
    pub frames: Option<u32>,
    #[arg(long, value_name = "N", value_parser = values::count(WARMUP),
          help = within("Warm-up frames per configuration (default 5; 2 with --quick)", WARMUP))]
    pub warmup: Option<u32>,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchRenderArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub size: SizeArgs,
    #[arg(long, default_value = "30", value_parser = values::count(FRAMES),
          help = within("Measured frames per combination (after warm-up)", FRAMES))]
    pub frames: u32,
    #[arg(long, default_value = "3", value_parser = values::count(WARMUP),
          help = within("Warm-up frames per combination (not measured)", WARMUP))]
    pub warmup: u32,
    #[arg(long, value_parser = values::count(values::POINT_LIGHTS),
          help = within("Light the scene with this many point lights on a ring above it instead of its own (the accuracy study's light-count variant)", values::POINT_LIGHTS))]
    pub point_lights: Option<u32>,
}

shadelab_model::param_ranges! {
    /// Runs of each timing: the table gives their median.
    pub const REFERENCE_RUNS = "--runs", "runs", "timed runs of each row", [1.0, 100.0];
}

#[derive(Args, Debug)]
pub struct BenchReferenceArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub size: SizeArgs,
    #[arg(long, default_value = "3", value_parser = values::count(REFERENCE_RUNS),
          help = within("Timed runs of each row (the median is reported)", REFERENCE_RUNS))]
    pub runs: u32,
}

#[derive(Args, Debug)]
pub struct BenchAmbientArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The image size [default: 320×180].
    #[arg(long, default_value = "320", value_parser = values::count(params::WIDTH), help = within("Width in pixels", params::WIDTH))]
    pub width: u32,
    #[arg(long, default_value = "180", value_parser = values::count(params::HEIGHT), help = within("Height in pixels", params::HEIGHT))]
    pub height: u32,
    #[arg(long, default_value = "4", value_parser = values::count(params::BOUNCES),
          help = within("Surface vertices a path has", params::BOUNCES))]
    pub bounces: u32,
    /// Paths a pixel of the truth every row is measured against; the path-traced rows take 1, 4,
    /// 16, … paths, up to a quarter of it.
    #[arg(long, default_value = "1024", value_parser = values::count(params::SPP),
          help = within("Paths a pixel of the truth", params::SPP))]
    pub truth_spp: u32,
}
