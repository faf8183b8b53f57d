//! `shadelab render`: one headless frame to PNG or EXR.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_render::{AdapterChoice, Gpu, LinearImage};
use std::path::Path;

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

pub fn run(args: &cli::RenderArgs) -> Result<(), Failure> {
    let settings = cli::settings(&args.shading, &args.specular, args.debug_nonfinite)?;
    let (width, height) = cli::size(&args.width, &args.height)?;
    let scene = cli::scene(&args.scene)?;
    let kind = image_kind(&args.output)?;
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    log::info!("adapter: {}", gpu.describe());
    let image = shadelab_render::render_image(&gpu, &scene, width, height, &settings);
    save(&image, &args.output, kind).with_context(|| format!("writing {}", args.output.display()))?;
    let bad = image.nonfinite_count();
    if bad > 0 {
        log::warn!("{bad} pixels are not finite");
    }
    Ok(())
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
