//! The image files the commands write: the kind from the file's extension, and a linear image
//! saved as 8-bit sRGB PNG or linear float EXR.

use crate::Failure;
use anyhow::Context;
use shadelab_render::LinearImage;
use std::path::Path;

/// An image file's kind, from its extension.
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
