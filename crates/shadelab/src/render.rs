//! `shadelab render`: one headless frame to PNG or EXR.

use crate::cli::{Overlay, SmallAreaLights};
use crate::image_file::{ImageKind, image_kind, save};
use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::ShadingMode;
use shadelab_model::gltf_io::{self, LoadedScene, SceneSettings};
use shadelab_model::params::NamedValue;
use shadelab_render::{Gpu, LinearImage, RenderSettings, UploadError};
use std::path::Path;

/// The overlay's lines for `scene`, in world space, and their colour.
fn overlay_lines(overlay: Overlay, scene: &shadelab_model::Scene) -> (Vec<[glam::DVec3; 2]>, [f32; 3]) {
    use shadelab_render::overlay_pass::{CREASES_COLOR, NORMALS_COLOR, TERMINATOR_COLOR};
    match overlay {
        Overlay::Terminator => (shadelab_model::terminator::scene_terminator(scene), TERMINATOR_COLOR),
        Overlay::Normals => (shadelab_model::mesh_lines::normal_segments(scene), NORMALS_COLOR),
        Overlay::Creases => (shadelab_model::mesh_lines::crease_segments(scene), CREASES_COLOR),
    }
}

/// `--save-scene`: write the scene (overrides applied) as glTF, the extension choosing .gltf or
/// .glb; any other extension is the user's mistake.
pub fn save_scene(scene: &shadelab_model::Scene, settings: SceneSettings, path: &Path) -> Result<(), Failure> {
    match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("gltf" | "glb") => {}
        _ => {
            return Err(Failure::Usage(format!(
                "--save-scene: '{}' has an unsupported extension (allowed: .gltf, .glb)",
                path.display()
            )));
        }
    }
    gltf_io::save_scene(scene, &settings, path).map_err(|e| Failure::Run(e.into()))
}

pub fn run(args: &cli::RenderArgs) -> Result<(), Failure> {
    let (loaded, mode, term) = view_of(args)?;
    let LoadedScene { scene, .. } = loaded;
    if !term.in_model(scene.illumination) {
        return Err(Failure::Usage(format!(
            "--term {}: the {} model has no such term (the four-term sum, --model sum, has I_t; the Lambert rule has no specular term)",
            shadelab_model::params::NamedValue::name(term),
            scene.illumination
        )));
    }
    if !term.in_scene(&scene) {
        return Err(Failure::Usage(format!(
            "--term {}: the scene has no environment light; add --environment uniform, sky or a map file",
            shadelab_model::params::NamedValue::name(term)
        )));
    }
    // One term alone is the scene with the other terms' coefficients at 0 (--save-scene keeps
    // the whole scene).
    let whole = scene;
    let mut scene = term.scene(&whole);
    let settings = RenderSettings { debug_nonfinite: args.debug_nonfinite, ..mode };
    let (width, height) = args.size.pixels();
    // An area light too small on screen for its area to show is drawn as a point light, saying why.
    if args.small_area_lights == SmallAreaLights::Point {
        for line in shadelab_model::effects::draw_small_area_lights_as_points(&mut scene, height) {
            println!("{line}");
        }
    }
    let kind = image_kind(&args.output)?;
    let factor = term == shadelab_model::terms::Term::Shadow;
    if factor && !args.overlay.is_empty() {
        return Err(Failure::Usage("--overlay: not drawn over --term shadow (a grey factor image)".into()));
    }
    if let Some(path) = &args.save_scene {
        let recorded = SceneSettings { shading: Some(settings.shading), specular: Some(settings.specular) };
        save_scene(&whole, recorded, path)?;
    }
    if args.explain {
        print!("{}", explain(&scene, &settings));
    }
    check_difference_flags(args, &scene, &settings, kind)?;
    if args.ambient_error {
        // The f64 reference alone: no GPU.
        return crate::ambient_views::run(&scene, (width, height), &settings, args, kind);
    }
    if (args.reference || args.difference) && !args.interpolation_difference {
        return crate::reference_views::run(&scene, (width, height), &settings, args, kind);
    }
    // Opened only where a GPU image is made: the reference alone is the CPU's.
    let gpu = open_gpu()?;
    if args.interpolation_difference {
        return interpolation_difference(&gpu, &scene, (width, height), &settings, &args.output);
    }
    let image = if factor {
        shadelab_render::render_shadow_factor(&gpu, &scene, (width, height), &settings)
    } else if args.overlay.is_empty() {
        shadelab_render::render_image(&gpu, &scene, width, height, &settings)
    } else {
        render_with_overlays(&gpu, &scene, (width, height), &settings, &args.overlay)
    }
    .map_err(|e| Failure::Usage(format!("{}: {e}", args.scene.scene)))?;
    save(&image, &args.output, kind).with_context(|| format!("writing {}", args.output.display()))?;
    let bad = image.nonfinite_count();
    if bad > 0 {
        log::warn!("{bad} pixels are not finite");
    }
    Ok(())
}

/// The adapter the command line's renders, benches and studies draw with (`SHADELAB_ADAPTER`'s
/// choice), named in the log.
pub(crate) fn open_gpu() -> anyhow::Result<Gpu> {
    let gpu = Gpu::from_env().context("opening a GPU adapter")?;
    log::info!("adapter: {}", gpu.describe());
    Ok(gpu)
}

/// The scene, settings and term `render` draws: the flags', or with `--link` the link's (its
/// scene, modes, edits, orbit, glass views and term replace the flags' own).
fn view_of(args: &cli::RenderArgs) -> Result<(LoadedScene, RenderSettings, shadelab_model::terms::Term), Failure> {
    if let Some(query) = &args.link {
        let (loaded, settings, term) = crate::viewer::open_headless(&crate::viewer::parse_query(query))
            .map_err(|e| Failure::Usage(format!("--{e}")))?;
        return Ok((loaded, settings, term.unwrap_or(args.term)));
    }
    let mut loaded = cli::load(&args.scene)?;
    let mode = args.mode.settle(&mut loaded, &args.scene)?;
    Ok((loaded, RenderSettings { glass_exit: args.glass_exit, glass_view: args.glass_view, ..mode }, args.term))
}

/// Errors for `--reference`, `--difference` and `--interpolation-difference` where they cannot apply.
fn check_difference_flags(
    args: &cli::RenderArgs,
    scene: &shadelab_model::Scene,
    settings: &RenderSettings,
    kind: ImageKind,
) -> Result<(), Failure> {
    if (args.reference || args.difference) && !shadelab_model::scene_variants::reference_covers(scene) {
        return Err(Failure::Usage(format!(
            "--reference, --difference: only for scenes of analytic shapes and file meshes of at most {} triangles in all (REFERENCE_MESH_TRIANGLES, the loader's limit)",
            shadelab_model::scene_variants::REFERENCE_MESH_TRIANGLES
        )));
    }
    let traced = args.reference || args.difference || args.ambient_error;
    if !traced && (args.bounces.is_some() || args.spp.is_some() || args.seed.is_some()) {
        return Err(Failure::Usage(
            "--bounces, --spp, --seed: only with --reference, --difference or --ambient-error".into(),
        ));
    }
    if args.paths().is_some() && args.term != shadelab_model::terms::Term::All {
        return Err(Failure::Usage(
            "--bounces, --ambient-error: the path-traced reference draws every term (--term all)".into(),
        ));
    }
    if args.ambient_error && !shadelab_model::scene_variants::reference_covers(scene) {
        return Err(Failure::Usage(format!(
            "--ambient-error: only for scenes of analytic shapes and file meshes of at most {} triangles in all (REFERENCE_MESH_TRIANGLES)",
            shadelab_model::scene_variants::REFERENCE_MESH_TRIANGLES
        )));
    }
    if args.difference && kind != ImageKind::Png {
        return Err(Failure::Usage("--difference: writes a .png error map".into()));
    }
    if args.interpolation_difference && (kind != ImageKind::Png || settings.shading == ShadingMode::Flat) {
        return Err(Failure::Usage(
            "--interpolation-difference: writes a .png error map, of Gouraud or Phong shading (flat interpolates nothing)"
                .into(),
        ));
    }
    Ok(())
}

/// The frame with `--overlay`'s line sets drawn over it.
fn render_with_overlays(
    gpu: &Gpu,
    scene: &shadelab_model::Scene,
    (width, height): (u32, u32),
    settings: &RenderSettings,
    overlay: &[Overlay],
) -> Result<LinearImage, UploadError> {
    // Each overlay once, in the order given (a later one drawn over an earlier one).
    let mut overlays: Vec<Overlay> = Vec::new();
    for o in overlay {
        if !overlays.contains(o) {
            overlays.push(*o);
        }
    }
    let lines: Vec<_> = overlays.iter().map(|o| (*o, overlay_lines(*o, scene))).collect();
    for (o, (l, _)) in &lines {
        log::info!("overlay {}: {} lines", o.name(), l.len());
    }
    let sets: Vec<_> = lines.iter().map(|(_, (l, c))| (l.as_slice(), *c)).collect();
    shadelab_render::overlay_pass::render_image_with_line_sets(gpu, scene, (width, height), settings, &sets)
}

/// `render --interpolation-difference`: the FLIP map of the screen-space image against the
/// perspective-correct one, written as PNG, with its mean printed.
fn interpolation_difference(
    gpu: &Gpu,
    scene: &shadelab_model::Scene,
    (width, height): (u32, u32),
    settings: &RenderSettings,
    output: &Path,
) -> Result<(), Failure> {
    use shadelab_model::Interpolation;
    let at = |interpolation| {
        let s = RenderSettings { interpolation, ..*settings };
        shadelab_render::render_image(gpu, scene, width, height, &s).map_err(|e| Failure::Usage(e.to_string()))
    };
    let (screen, perspective) = (at(Interpolation::Screen)?, at(Interpolation::Perspective)?);
    let cmp = shadelab_render::image_error::compare_images(&screen, &perspective);
    image::RgbImage::from_raw(width, height, cmp.flip_map_rgb8)
        .context("FLIP map size")?
        .save(output)
        .with_context(|| format!("writing {}", output.display()))?;
    println!(
        "screen-space vs perspective-correct interpolation ({} shading): mean FLIP {:.5}, RMSE {:.2e}, {:.3} % of pixels visibly off",
        settings.shading,
        cmp.stats.flip_mean,
        cmp.stats.rmse,
        100.0 * cmp.stats.share_off
    );
    Ok(())
}

/// The effect analysis of a scene with these settings, one line per decision (`--explain`), and
/// a line for each effect the analysis calls for that this shading mode's program leaves out.
pub fn explain(scene: &shadelab_model::Scene, settings: &shadelab_render::RenderSettings) -> String {
    let a = shadelab_model::effects::analyze(scene, settings.specular);
    let lit = shadelab_render::Program::for_scene(scene, settings);
    let program = lit.effects();
    let model = shadelab_model::ModelChoice::of(scene.illumination, settings.specular);
    let mut s = format!(
        "# effects of scene '{}' with {} shading and the {} model — pipeline [{}]\n",
        scene.name,
        settings.shading,
        model,
        program.label()
    );
    for line in a.lines() {
        s.push_str(&line);
        s.push('\n');
    }
    s.push_str(&format!(
        "light loop: {} — the pipeline is built for the scene's lights: the loop unrolled, each slot with its kind's code only\n",
        lit.light_loop().label()
    ));
    let per = if settings.shading == shadelab_model::ShadingMode::Flat { "face" } else { "vertex" };
    for e in a.key.effects().into_iter().filter(|e| !program.has(*e)) {
        s.push_str(&format!(
            "{e}: not drawn in {} shading — it varies the lighting per pixel, which this mode computes once per {per}; Phong shading draws it\n",
            settings.shading
        ));
    }
    s
}
