//! Command-line arguments: the subcommands and their flags. Every numeric and named flag goes
//! through a value parser built from the model's declared ranges and names ([`values`]), so
//! `--help` shows what each allows and a mistake is one line naming the flag (exit code 2). The
//! scene the flags ask for is built in [`load`].

mod bench_args;
mod load;
pub mod values;

pub use bench_args::*;
pub use load::{apply_flags, load, load_unchanged, overrides, pick_camera, scene};
pub use values::{FRAMES, MESH_TRIANGLES, WARMUP, one_line, within};

use crate::Failure;
use clap::{Args, Parser, Subcommand};
use shadelab_model::gltf_io::{LoadedScene, SceneSettings};
use shadelab_model::lighting::microfacet::{Distribution, Fresnel, Masking, Microfacet};
use shadelab_model::params::{self, AreaSpecular, PhongExponent};
use shadelab_model::scene::BUILTIN_SCENES;
use shadelab_model::shadows::{PCSS_TAPS, SHADOW_RESOLUTION, ShadowFilter};
use shadelab_model::{
    FalloffForm, IlluminationModel, Interpolation, LightKind, ModelChoice, Overrides, ShadingMode, SpecularModel,
};
use shadelab_render::RenderSettings;
use std::path::PathBuf;

/// Parse `args` (the program's name first) as the command line: [`Cli::try_parse_from`] with
/// the command built once. clap otherwise builds every flag's definition, help and range on each
/// parse, which a link pays once per parameter (`viewer/link.rs`).
pub fn parse_args<I, T>(args: I) -> Result<Cli, clap::Error>
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    use clap::{CommandFactory, FromArgMatches};
    static COMMAND: std::sync::OnceLock<std::sync::Mutex<clap::Command>> = std::sync::OnceLock::new();
    let command = COMMAND.get_or_init(|| {
        let mut c = Cli::command();
        c.build();
        std::sync::Mutex::new(c)
    });
    // A panic while parsing leaves the command as it was: the poison is only the flag.
    let mut cmd = command.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let mut matches = cmd.try_get_matches_from_mut(args)?;
    Cli::from_arg_matches_mut(&mut matches).map_err(|e| e.format(&mut cmd))
}

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
    #[arg(long, value_name = "N", value_parser = values::count(FRAMES))]
    pub exit_after_frames: Option<u32>,
    /// Viewer: open the view a link's query describes, as the page's "copy link" writes it
    /// (`'?scene=glass&mat0.m=0.3&orbit=…'`); a bad key is named in the panel and the others apply.
    #[arg(long, value_name = "QUERY")]
    pub link: Option<String>,
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
    /// Write the chapter's figures as PNGs, with commands.txt listing the render command of each
    /// (and the scene files they use), to remake or change any of them.
    Figures(FiguresArgs),
    /// The lobe of one pixel of a render (the viewer's click): print its point's N, V and each
    /// light's angles, from the f64 model, and write the polar plot and the θh/θd slice as PNG.
    Lobe(LobeArgs),
    /// Compare two PNG images of the same size (a screenshot against a render, two renders):
    /// print the FLIP mean, RMSE, max error and the share of pixels off by more than 1/255.
    Compare(CompareArgs),
    /// Fit the LTC tables of the area lights' specular (docs/area-lights.md) for every D, print
    /// each one's distance to its lobes, and with --write replace the table the renderer reads.
    FitLtc(FitLtcArgs),
}

#[derive(Args, Debug)]
pub struct FitLtcArgs {
    /// Write the tables as Rust source here (the renderer's is
    /// crates/shadelab-model/src/lighting/ltc_table.rs).
    #[arg(long, value_name = "PATH")]
    pub write: Option<PathBuf>,
    /// Print every node's distance, a row of N·V from normal view to grazing per m.
    #[arg(long)]
    pub rows: bool,
}

#[derive(Args, Debug)]
pub struct CompareArgs {
    /// The image taken as right (PNG, 8-bit sRGB).
    #[arg(value_name = "REFERENCE")]
    pub reference: PathBuf,
    /// The image compared with it.
    #[arg(value_name = "TEST")]
    pub test: PathBuf,
    /// Write the FLIP error map (magma scale) to this PNG.
    #[arg(long, value_name = "PATH")]
    pub map: Option<PathBuf>,
    /// Exit 1 when the FLIP mean is above this.
    #[arg(long, value_name = "FLIP", value_parser = values::real(FLIP_MEAN))]
    pub max_flip: Option<f64>,
}

shadelab_model::param_ranges! {
    /// `compare --max-flip`: a FLIP error lies in [0, 1].
    pub const FLIP_MEAN = "--max-flip", "FLIP", "largest FLIP mean accepted", [0.0, 1.0];
}

#[derive(Args, Debug)]
pub struct LobeArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub size: SizeArgs,
    /// The pixel, X,Y from the top left of a render of --width × --height.
    #[arg(long, value_name = "X,Y", value_parser = values::pixel())]
    pub pixel: (u32, u32),
    /// Which light's plane of incidence to plot, counted from 1.
    #[arg(long, default_value = "1", value_name = "N")]
    pub plane_of: usize,
    /// The plots' PNG.
    #[arg(long, default_value = "lobe.png", value_name = "PATH")]
    pub output: PathBuf,
}

#[derive(Args, Debug)]
pub struct FiguresArgs {
    /// Folder for the figures, their scene files and commands.txt.
    #[arg(long, default_value = "figures", value_name = "DIR")]
    pub out: PathBuf,
    #[arg(long, default_value = "640", value_parser = values::count(params::WIDTH),
          help = within("Each figure's width in pixels (smaller for a quick look)", params::WIDTH))]
    pub width: u32,
    #[arg(long, default_value = "360", value_parser = values::count(params::HEIGHT),
          help = within("Each figure's height in pixels", params::HEIGHT))]
    pub height: u32,
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
    /// What shadow accuracy costs: every light's shadow map at each resolution × filter, the same
    /// frame without shadows and the null-shader baseline, interleaved, each against the f64
    /// reference's exact shadows. Writes a CSV, a Markdown table and a plot.
    Shadows(BenchShadowsArgs),
    /// The 10–90 % width of the `penumbra` scene's soft shadow as its plate rises, against the
    /// similar-triangles prediction: the f64 reference, PCSS, 16 point sources and PCF. Writes a
    /// CSV, a Markdown table and a plot.
    Penumbra(BenchPenumbraArgs),
    /// What transparency costs against its accuracy: the `glass` scene opaque, straight through,
    /// with the analytic and the back-face exit, timed side by side and compared with the f64
    /// Whitted reference; the chapter's absorption rule against the exact form at a range of a·d,
    /// its error beside the time it saves. Writes a Markdown report, CSVs and error maps.
    Glass(BenchGlassArgs),
    /// What each Cook–Torrance term costs against what it changes: the default scene with each
    /// of the combinations of D, G and F and with glTF's whole set, timed side by side against
    /// the null shader; each combination's f64 reference against the chapter's and the GPU
    /// against its own; maps of where a term's change lies; Schlick's F against the exact factor
    /// per μ. Writes a Markdown report, CSVs and the maps.
    Microfacet(BenchMicrofacetArgs),
    /// What the f64 reference costs on a scene: its meshes' hierarchy (build time, memory) and
    /// the image on every core and on one.
    Reference(BenchReferenceArgs),
    /// The chapter's constant ambient against the path-traced light between surfaces: the error
    /// against a high-sample truth and the time of the constant I_a, the fitted I_a, ambient
    /// occlusion and path tracing at 1, 4, 16, … paths a pixel.
    Ambient(BenchAmbientArgs),
    /// The environment light's approximations against the path-traced truth: the constant I_a
    /// of its mean radiance, the nine SH terms, and those terms times ambient occlusion, with
    /// the GPU's frame time of each it draws (the sky unless --environment says otherwise).
    Environment(BenchAmbientArgs),
}

/// The scene and the parameters that override it (shared by `render` and `bench`).
#[derive(Args, Debug, Clone, Default)]
#[command(allow_negative_numbers = true)]
pub struct SceneArgs {
    #[arg(long, default_value = "default", value_name = "NAME|PATH",
          help = format!("A built-in scene ({}) or a glTF 2.0 file (.gltf, .glb)", BUILTIN_SCENES.join(", ")))]
    pub scene: String,
    /// Let a scene file's buffer and image URIs name files outside its own folder (absolute
    /// paths, `..`, links that point out); without it they are refused
    #[arg(long)]
    pub allow_outside_paths: bool,
    #[arg(long, value_parser = values::real(params::M), help = within("Roughness m of every material", params::M))]
    pub m: Option<f64>,
    #[arg(long, value_parser = values::phong_exponent(),
          help = format!("Phong exponent h of every material, in [{}, {}], or 'mirror'", params::H.min, params::H.max))]
    pub h: Option<PhongExponent>,
    #[arg(long, value_name = "R,G,B", value_parser = values::reflectance(),
          help = format!("Normal-incidence reflectance μ of every material: R,G,B or one value, each in [{}, {}]", params::MU.min, params::MU.max))]
    pub mu: Option<[f64; 3]>,
    #[arg(long, value_name = "SHARE", value_parser = values::real(params::TRANSMISSION),
          help = within("Transmission share τ = 1 − t of every material (0 opaque): drawn as glass, or in the four-term sum as its I_t", params::TRANSMISSION))]
    pub transmission: Option<f64>,
    #[arg(long, value_name = "R,G,B", value_parser = values::rgb(params::IOR),
          help = format!("Refractive index v of every material, given directly (else from μ): R,G,B (channels that differ disperse) or one value, each in [{}, {}]", params::IOR.min, params::IOR.max))]
    pub ior: Option<[f64; 3]>,
    #[arg(long, value_name = "R,G,B", value_parser = values::rgb(params::ABSORPTION),
          help = format!("Absorption coefficient a of every material, per metre: R,G,B or one value, each in [{}, {}]", params::ABSORPTION.min, params::ABSORPTION.max))]
    pub absorption_coef: Option<[f64; 3]>,
    /// How transparent objects absorb: exact (e^(−a·d) everywhere) or rule (the chapter's rule
    /// picks each object's form from its largest a·d: neglected below 0.2, 1 − a·d below 0.5)
    /// [default: rule].
    #[arg(long, value_name = "exact|rule", value_parser = values::named::<shadelab_model::lighting::transmission::AbsorptionChoice>())]
    pub absorption: Option<shadelab_model::lighting::transmission::AbsorptionChoice>,
    /// Every material's Cook–Torrance terms as a set: chapter (Beckmann D, V-groove G, exact F)
    /// or gltf (GGX D, height-correlated Smith G, Schlick's F, as glTF 2.0 specifies) [default:
    /// the scene file's; a glTF file without shadelab's extras opens with gltf]
    #[arg(long, value_name = "SET", value_parser = values::named::<Microfacet>())]
    pub microfacet: Option<Microfacet>,
    /// Every material's facet distribution D, after --microfacet (the chapter's: beckmann)
    #[arg(long, value_name = "D", value_parser = values::named::<Distribution>())]
    pub distribution: Option<Distribution>,
    /// Every material's masking–shadowing G, after --microfacet (the chapter's: v-groove; smith is
    /// the separable form, smith-correlated the height-correlated one)
    #[arg(long, value_name = "G", value_parser = values::named::<Masking>())]
    pub masking: Option<Masking>,
    /// Every material's Fresnel factor F, after --microfacet (the chapter's: exact)
    #[arg(long, value_name = "F", value_parser = values::named::<Fresnel>())]
    pub fresnel: Option<Fresnel>,
    /// Every material's Phong lobe scaled by (h + 1)/2, so that it reflects all it receives at
    /// normal view (on), or the chapter's (V·R)^h (off) [default: the scene file's, else off]
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub phong_normalized: Option<bool>,
    /// Every material's Cook–Torrance lobe compensated for the light its single scattering
    /// loses (on, Turquin's 1 + F0·(1 − E)/E), or not (off), after --microfacet [default: the
    /// scene file's, else off]
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub multiple_scattering: Option<bool>,
    /// Every material's diffuse weighted by what its dielectric layer's Fresnel leaves it (on,
    /// glTF's fresnel_mix 1 − F), or not (off), after --microfacet [default: the scene file's;
    /// on with --microfacet gltf]
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub fresnel_mix: Option<bool>,
    #[arg(long, value_name = "ALPHA", value_parser = values::real(params::FALLOFF),
          help = within("Falloff factor α of every point and spot light, I0/(1 + α d²)", params::FALLOFF))]
    pub falloff: Option<f64>,
    /// Falloff form of every point and spot light: quadratic (1/(1 + α d²)) or linear (the
    /// chapter's 1/(d + d0)).
    #[arg(long, value_name = "FORM", value_parser = values::named::<FalloffForm>())]
    pub falloff_form: Option<FalloffForm>,
    #[arg(long, value_parser = values::real(params::D0), help = within("d0 of the linear falloff 1/(d + d0)", params::D0))]
    pub d0: Option<f64>,
    /// Which of a scene file's cameras to look through: 0 (the first, the default) to the number
    /// of cameras − 1, in the file's node order. A built-in scene has one.
    #[arg(long, value_name = "N")]
    pub camera: Option<String>,
    /// Make every light directional, point, spot, or an area light: rect, disk or sphere (a spot
    /// gets glTF's default cone, 45°, and a rect or disk faces the origin; an area light is
    /// --light-size wide, 0.5 m unless set).
    #[arg(long, value_name = "KIND", value_parser = values::named::<LightKind>())]
    pub light: Option<LightKind>,
    #[arg(long, value_name = "METRES", value_parser = values::real(params::LIGHT_SIZE),
          help = within("Width of every area light: a rect's side, a disk's or sphere's diameter", params::LIGHT_SIZE))]
    pub light_size: Option<f64>,
    #[arg(long, value_name = "K", value_parser = values::count(params::AREA_POINTS),
          help = within("Draw every area light as the chapter's K point sources, each with its own hard shadow (0: the exact area form)", params::AREA_POINTS))]
    pub area_points: Option<u32>,
    /// How every area light's specular is drawn under Cook–Torrance: at its representative point,
    /// or by linearly transformed cosines fitted to the lobe (docs/area-lights.md) [default: each
    /// light's own setting, representative unless a scene file says otherwise].
    #[arg(long, value_name = "representative|ltc", value_parser = values::named::<AreaSpecular>())]
    pub area_specular: Option<AreaSpecular>,
    /// Cast shadows from every light (on) or from none (off) [default: each light's own setting,
    /// on unless a scene file says otherwise].
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub shadows: Option<bool>,
    #[arg(long, value_name = "N", value_parser = values::count(SHADOW_RESOLUTION),
          help = within("Shadow map side in texels of every light", SHADOW_RESOLUTION))]
    pub shadow_resolution: Option<u32>,
    /// Shadow map filter of every light: hard (one comparison), pcf (the hardware 2×2
    /// comparison), poisson (rotated Poisson-disk taps) or pcss (a penumbra as wide as an area
    /// light's similar triangles give, --pcss-taps taps).
    #[arg(long, value_name = "FILTER", value_parser = values::named::<ShadowFilter>())]
    pub shadow_filter: Option<ShadowFilter>,
    #[arg(long, value_name = "N", value_parser = values::count(PCSS_TAPS),
          help = within("Taps of each of PCSS's two passes (blocker search, filter) of every light", PCSS_TAPS))]
    pub pcss_taps: Option<u32>,
    /// Let every directional light split its shadow map into cascades when the view spans a
    /// depth ratio over 8 (on), or keep one map fitted to the scene (off) [default: on].
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub shadow_cascades: Option<bool>,
    /// Light the scene by an environment in place of I_amb, which is set to 0
    /// (docs/environment.md): uniform (I_amb's colour from every direction), sky (Preetham's,
    /// the sun at the first directional light), an equirectangular .hdr or .exr file, or none
    /// (drop the scene file's)
    #[arg(long, value_name = "uniform|sky|none|FILE")]
    pub environment: Option<String>,
    #[arg(long, value_name = "X", value_parser = values::real(shadelab_model::lighting::env_map::ENV_INTENSITY),
          help = within("The environment's intensity, a scale of its radiance", shadelab_model::lighting::env_map::ENV_INTENSITY))]
    pub env_intensity: Option<f64>,
    #[arg(long, value_name = "DEGREES", value_parser = values::real(shadelab_model::lighting::env_map::ENV_ROTATION),
          help = within("The environment's turn about the up axis, in degrees", shadelab_model::lighting::env_map::ENV_ROTATION))]
    pub env_rotation: Option<f64>,
    #[arg(long, value_name = "T", value_parser = values::real(shadelab_model::lighting::sky::TURBIDITY),
          help = within("The sky's turbidity, 2 clear to 10 hazy", shadelab_model::lighting::sky::TURBIDITY))]
    pub turbidity: Option<f64>,
    /// Draw the environment's specular by the split sum (on) or leave it out (off), on the GPU
    /// and in the exact reference; the path-traced truth always has it [default: on]
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub env_specular: Option<bool>,
    /// Occlude the environment's diffuse light by a grid of ambient occlusion precomputed over
    /// the scene (on), on the GPU and in the exact reference; the path-traced truth always traces
    /// visibility [default: off]
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub env_occlusion: Option<bool>,
    /// Draw the environment where the camera sees nothing, in place of the background colour
    /// (on), on the GPU and in the references [default: off]
    #[arg(long, value_name = "ON|OFF", value_parser = values::on_off())]
    pub env_background: Option<bool>,
}

/// `render --small-area-lights`: how an area light too small in an image framing the scene for
/// its area to show is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SmallAreaLights {
    /// Drawn as a point light (the reason is printed).
    Point,
    /// Drawn with their area.
    Area,
}

shadelab_model::named_values!(SmallAreaLights, "--small-area-lights", "point" => Point, "area" => Area);

/// What `render --overlay` draws over the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overlay {
    /// The self-shadow boundary: the edges where the side facing a light changes
    /// (`shadelab_model::terminator`), in `overlay_pass::TERMINATOR_COLOR`.
    Terminator,
    /// The smooth meshes' vertex normals (`shadelab_model::mesh_lines`), in `NORMALS_COLOR`.
    Normals,
    /// The edges the crease-angle rule keeps sharp (`mesh_lines`), in `CREASES_COLOR`.
    Creases,
}

shadelab_model::named_values!(Overlay, "--overlay",
    "terminator" => Terminator, "normals" => Normals, "creases" => Creases
);

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct RenderArgs {
    #[command(flatten)]
    pub mode: ModeArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Draw the view a link's query describes (`'?scene=glass&mat0.m=0.3&orbit=…'`, as the
    /// viewer's "copy link" writes it): its scene, modes, edits, camera, glass views and term
    /// replace the scene and mode flags; a bad key is an error naming it.
    #[arg(long, value_name = "QUERY")]
    pub link: Option<String>,
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
    /// How to draw an area light whose penumbra and highlight would be under a pixel wide in an
    /// image framing the scene: as a point light, printing why (point), or with its area (area).
    #[arg(long, value_name = "point|area", default_value = "point", value_parser = values::named::<SmallAreaLights>())]
    pub small_area_lights: SmallAreaLights,
    /// Where the glass pass finds a path's exit from a transparent object: analytic (exact for
    /// the built-in shapes, a mesh's back faces) or back-faces (for every object, to compare).
    #[arg(long, value_name = "analytic|back-faces", default_value = "analytic",
          value_parser = values::named::<shadelab_model::lighting::transmission::GlassExit>())]
    pub glass_exit: shadelab_model::lighting::transmission::GlassExit,
    /// What transparent objects show: color, tir (red where total internal reflection turned the
    /// path back inside), path (the length inside, white at the object's longest chord) or
    /// regime (the chapter's rule for the pixel's a·d: green neglected, yellow 1 − a·d, red
    /// exact).
    #[arg(long, value_name = "VIEW", default_value = "color",
          value_parser = values::named::<shadelab_model::lighting::transmission::GlassView>())]
    pub glass_view: shadelab_model::lighting::transmission::GlassView,
    /// Draw one term of the model alone: all (the default), ambient (I_amb·r_a·C), diffuse
    /// (Σ I_L·r_d·C·(N·L), cast shadows included) or specular (Σ I_L·r_s·S), which add up to the
    /// whole image; or shadow, the cast-shadow factor as grey.
    #[arg(long, value_name = "TERM", default_value = "all", value_parser = values::named::<shadelab_model::terms::Term>())]
    pub term: shadelab_model::terms::Term,
    /// Write the FLIP error map (magma) of the chapter's screen-space interpolation against the
    /// perspective-correct image instead of the image (PNG only; Gouraud or Phong shading), and
    /// print its mean.
    #[arg(long)]
    pub interpolation_difference: bool,
    /// Write the f64 ray-cast reference of the same scene and term instead of the GPU's image
    /// (scenes of analytic shapes; with --term shadow, its exact factor). An area light is
    /// integrated over its area, its specular too, not taken at the GPU's representative point;
    /// under the Lambert rule and the four-term sum its form is the drawn one (a disk as its
    /// 16-gon, within 0.3 %). Under an environment light it is the GPU's f64 twin (the nine SH
    /// terms and the split sum, as drawn), not the truth: --bounces path traces the truth.
    #[arg(long, conflicts_with_all = ["difference", "interpolation_difference", "overlay"])]
    pub reference: bool,
    /// Write the FLIP error map (magma) of the GPU's image against the f64 reference instead of
    /// the image (PNG; scenes of analytic shapes), and print RMSE, FLIP and the share off. Under
    /// an environment light that reference is the GPU's twin unless --bounces asks for the truth.
    #[arg(long, conflicts_with_all = ["interpolation_difference", "overlay"])]
    pub difference: bool,
    /// With --reference or --difference: path trace the reference, the light between surfaces
    /// taking the place of the constant ambient (the Phong model; docs/reference.md). N surface
    /// vertices a path: 1 is the exact direct light alone, 2 adds one bounce.
    #[arg(long, value_name = "N", value_parser = values::count(params::BOUNCES),
          help = within("Path-traced reference: surface vertices a path has (1: the direct light alone)", params::BOUNCES))]
    pub bounces: Option<u32>,
    /// Paths per pixel of the path-traced reference [default: 64].
    #[arg(long, value_parser = values::count(params::SPP), help = within("Paths per pixel of the path-traced reference [default: 64]", params::SPP))]
    pub spp: Option<u32>,
    /// The seed of the path tracer's random numbers: the same seed, the same image on any number
    /// of threads [default: 1].
    #[arg(long)]
    pub seed: Option<u64>,
    /// Write the ambient error instead of the image: the chapter's constant I_a·r_a·C against the
    /// path-traced light between surfaces (--bounces, default 4; --spp), as signed linear RGB
    /// (.exr) or a map from blue (too dark) to red (too bright) (.png); print the fitted I_a and
    /// the error of the constant, the fitted and the occluded ambient.
    #[arg(long, conflicts_with_all = ["reference", "difference", "interpolation_difference", "overlay"])]
    pub ambient_error: bool,
    /// Draw over the image, comma-separated, depth-tested against the scene: terminator (the
    /// self-shadow boundary, cyan), normals (the smooth meshes' vertex normals, yellow), creases
    /// (the edges the crease-angle rule keeps sharp, orange).
    #[arg(long, value_name = "NAME,...", value_delimiter = ',',
          value_parser = values::named::<Overlay>())]
    pub overlay: Vec<Overlay>,
}

impl RenderArgs {
    /// The path tracer's settings where `--bounces` or `--ambient-error` asks for it.
    pub fn paths(&self) -> Option<shadelab_model::reference::PathSettings> {
        let d = shadelab_model::reference::PathSettings::default();
        (self.bounces.is_some() || self.ambient_error).then(|| shadelab_model::reference::PathSettings {
            bounces: self.bounces.unwrap_or(d.bounces),
            spp: self.spp.unwrap_or(d.spp),
            seed: self.seed.unwrap_or(d.seed),
        })
    }
}

/// The image size (`render` and every `bench`).
#[derive(Args, Debug, Clone)]
pub struct SizeArgs {
    #[arg(long, default_value = "1280", value_parser = values::count(params::WIDTH),
          help = within("Width in pixels", params::WIDTH))]
    pub width: u32,
    #[arg(long, default_value = "720", value_parser = values::count(params::HEIGHT),
          help = within("Height in pixels", params::HEIGHT))]
    pub height: u32,
}

impl SizeArgs {
    /// Width and height in pixels (clap has checked each against its range).
    pub fn pixels(&self) -> (u32, u32) {
        (self.width, self.height)
    }
}

/// The shading mode and specular model (`render`, `bench load`, the viewer).
#[derive(Args, Debug, Clone, Default)]
pub struct ModeArgs {
    /// The shading mode [default: the scene file's, else phong].
    #[arg(long, value_parser = values::named::<ShadingMode>())]
    pub shading: Option<ShadingMode>,
    /// The specular model [default: the scene file's, else cook-torrance].
    #[arg(long, value_parser = values::named::<SpecularModel>())]
    pub specular: Option<SpecularModel>,
    /// The illumination model: lambert (the Lambert rule, 7.1), sum (the four-term sum of
    /// equation (1), with 1/(d + d0) on every point and spot light), phong (7.2) or
    /// cook-torrance (7.3); the last two also set --specular [default: the scene file's, else the
    /// Phong model with --specular].
    #[arg(long, value_parser = values::named::<ModelChoice>())]
    pub model: Option<ModelChoice>,
    /// How Gouraud's colours and Phong shading's normals cross a triangle: perspective (correct,
    /// the GPU's default) or screen (the chapter's scanline form, linear in screen space).
    #[arg(long, default_value = "perspective", value_parser = values::named::<Interpolation>())]
    pub interpolation: Interpolation,
}

impl ModeArgs {
    /// Each flag when given, else what the scene file records, else Phong shading with
    /// Cook–Torrance specular.
    fn resolve(&self, file: SceneSettings) -> RenderSettings {
        let fixed = self.model.and_then(|m| m.split().1);
        RenderSettings {
            interpolation: self.interpolation,
            ..RenderSettings::new(
                self.shading.or(file.shading).unwrap_or(ShadingMode::Phong),
                fixed.or(self.specular).or(file.specular).unwrap_or(SpecularModel::CookTorrance),
            )
        }
    }

    /// Apply `--model` to the loaded scene (its illumination model, and for the four-term sum the
    /// chapter's falloff) and resolve the settings. A `--specular` or `--falloff-form` that
    /// contradicts the model is one line and exit 2.
    pub fn settle(&self, loaded: &mut LoadedScene, scene: &SceneArgs) -> Result<RenderSettings, Failure> {
        if let Some(choice) = self.model {
            let (model, fixed) = choice.split();
            if let (Some(fixed), Some(given)) = (fixed, self.specular)
                && fixed != given
            {
                return Err(Failure::Usage(format!(
                    "--model {choice} uses --specular {fixed}, not --specular {given} (give one of the two)"
                )));
            }
            if model == IlluminationModel::Sum && scene.falloff_form == Some(FalloffForm::Quadratic) {
                return Err(Failure::Usage(
                    "--model sum uses the chapter's falloff 1/(d + d0), not --falloff-form quadratic".into(),
                ));
            }
            loaded.scene.apply(&Overrides::for_model(choice));
        }
        Ok(self.resolve(loaded.settings))
    }
}
