//! `shadelab compare`: the error of one PNG against another of the same size, with the numbers
//! the difference view shows (FLIP mean, RMSE, max, share of pixels off by more than 1/255). For
//! scripts and CI that diff screenshots; the browser tests hold the web page to a native render
//! with it.

use crate::cli::CompareArgs;
use crate::{Failure, image_file};
use anyhow::anyhow;
use shadelab_render::LinearImage;
use shadelab_render::image_error::compare_images;
use std::path::Path;

fn load(path: &Path) -> Result<LinearImage, Failure> {
    let img = image::open(path).map_err(|e| Failure::Usage(format!("compare: {}: {e}", path.display())))?.to_rgb8();
    Ok(LinearImage::from_srgb8(img.width(), img.height(), img.as_raw()))
}

pub fn run(args: &CompareArgs) -> Result<(), Failure> {
    let (reference, test) = (load(&args.reference)?, load(&args.test)?);
    if (reference.width, reference.height) != (test.width, test.height) {
        return Err(Failure::Usage(format!(
            "compare: {} is {}×{} but {} is {}×{} (the images must have the same size)",
            args.reference.display(),
            reference.width,
            reference.height,
            args.test.display(),
            test.width,
            test.height
        )));
    }
    let cmp = compare_images(&test, &reference);
    let s = cmp.stats;
    println!(
        "FLIP mean {:.4}, RMSE {:.3e}, max {:.3}, {:.2} % of pixels off by > 1/255",
        s.flip_mean,
        s.rmse,
        s.max_abs,
        s.share_off * 100.0
    );
    if let Some(path) = &args.map {
        let map = LinearImage::from_srgb8(test.width, test.height, &cmp.flip_map_rgb8);
        image_file::save(&map, path, image_file::ImageKind::Png)?;
    }
    match args.max_flip {
        Some(max) if s.flip_mean > max => {
            Err(Failure::Run(anyhow!("FLIP mean {:.4} is above --max-flip {max}", s.flip_mean)))
        }
        _ => Ok(()),
    }
}
