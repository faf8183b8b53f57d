//! `shadelab render`: one headless frame to PNG or EXR.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::gltf_io::{self, LoadedScene, SceneSettings};
use shadelab_model::params::NamedValue;
use shadelab_render::{AdapterChoice, Gpu, LinearImage, RenderSettings};
use std::path::Path;

/// What `render --overlay` draws over the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overlay {
    /// The self-shadow boundary: the edges where the side facing a light changes
    /// (`shadelab_model::terminator`), in `overlay_pass::TERMINATOR_COLOR`.
    Terminator,
}

impl NamedValue for Overlay {
    const FLAG: &'static str = "--overlay";
    const ALL: &'static [(&'static str, Self)] = &[("terminator", Overlay::Terminator)];
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageKind {
    Png,
    Exr,
}

/// The output kind from the file's extension.
pub fn image_kind(path: &Path) -> Result<ImageKind, Failure> {
    match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("png") => Ok(ImageKind::Png),
        Some("exr") => Ok(ImageKind::Exr),
        _ => Err(Failure::Usage(format!(
            "--output: '{}' has an unsupported extension (allowed: .png, .exr)",
            path.display()
        ))),
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
    let LoadedScene { scene, settings: file, .. } = cli::load(&args.scene)?;
    // One term alone is the scene with the other terms' coefficients at 0 (--save-scene keeps
    // the whole scene).
    let whole = scene;
    let scene = args.term.scene(&whole);
    let settings = RenderSettings { debug_nonfinite: args.debug_nonfinite, ..args.mode.resolve(file) };
    let (width, height) = args.size.pixels();
    let kind = image_kind(&args.output)?;
    if let Some(path) = &args.save_scene {
        let recorded = SceneSettings { shading: Some(settings.shading), specular: Some(settings.specular) };
        save_scene(&whole, recorded, path)?;
    }
    if args.explain {
        print!("{}", explain(&scene, &settings));
    }
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    log::info!("adapter: {}", gpu.describe());
    let image = if args.overlay.contains(&Overlay::Terminator) {
        let edges = shadelab_model::terminator::scene_terminator(&scene);
        log::info!("overlay terminator: {} edges", edges.len());
        let color = shadelab_render::overlay_pass::TERMINATOR_COLOR;
        shadelab_render::overlay_pass::render_image_with_lines(&gpu, &scene, (width, height), &settings, &edges, color)
    } else {
        shadelab_render::render_image(&gpu, &scene, width, height, &settings)
    }
    .map_err(|e| Failure::Usage(format!("{}: {e}", args.scene.scene)))?;
    save(&image, &args.output, kind).with_context(|| format!("writing {}", args.output.display()))?;
    let bad = image.nonfinite_count();
    if bad > 0 {
        log::warn!("{bad} pixels are not finite");
    }
    Ok(())
}

/// The effect analysis of a scene with these settings, one line per decision (`--explain`).
pub fn explain(scene: &shadelab_model::Scene, settings: &shadelab_render::RenderSettings) -> String {
    let a = shadelab_model::effects::analyze(scene, settings.specular);
    let mut s = format!(
        "# effects of scene '{}' with {} shading and {} specular — pipeline [{}]\n",
        scene.name,
        settings.shading,
        settings.specular,
        a.key.label()
    );
    for line in a.lines() {
        s.push_str(&line);
        s.push('\n');
    }
    s
}

/// Write a linear image: PNG as 8-bit sRGB, EXR as linear 32-bit float RGBA.
pub fn save(image: &LinearImage, path: &Path, kind: ImageKind) -> anyhow::Result<()> {
    match kind {
        ImageKind::Png => {
            let img =
                image::RgbImage::from_raw(image.width, image.height, image.to_srgb8()).context("image buffer size")?;
            img.save(path)?;
        }
        ImageKind::Exr => {
            let flat: Vec<f32> = image.pixels.iter().flatten().copied().collect();
            let img = image::Rgba32FImage::from_raw(image.width, image.height, flat).context("image buffer size")?;
            img.save(path)?;
        }
    }
    Ok(())
}
