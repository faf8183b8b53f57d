//! `render --reference` and `render --difference`: the f64 ray-cast reference of the scene (and
//! of the term on show) in place of the GPU's image, or the FLIP map of the one against the
//! other, so that each term has its reference and its difference map from the command line too.

use crate::render::{ImageKind, save};
use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::reference::render_reference;
use shadelab_model::terms::{Term, shadow_factor};
use shadelab_render::image_error::{compare_images, reference_image};
use shadelab_render::{Gpu, LinearImage, RenderSettings};

/// The reference of `scene` at `size` as a linear image: its pixels, or with `--term shadow`
/// its exact cast-shadow factor as grey (the background kept), as the GPU's factor is drawn.
fn reference_of(scene: &shadelab_model::Scene, size: (u32, u32), settings: &RenderSettings, term: Term) -> LinearImage {
    let r = render_reference(scene, settings.specular, size.0, size.1);
    if term != Term::Shadow {
        return reference_image(&r);
    }
    let pixels = (0..r.pixels.len())
        .map(|i| match r.object[i] {
            None => {
                let b = r.pixels[i];
                [b[0] as f32, b[1] as f32, b[2] as f32, 1.0]
            }
            Some(_) => {
                let v = shadow_factor(r.pixels[i], r.unshadowed[i]) as f32;
                [v, v, v, 1.0]
            }
        })
        .collect();
    LinearImage { width: size.0, height: size.1, pixels }
}

pub fn run(
    gpu: &Gpu,
    scene: &shadelab_model::Scene,
    size: (u32, u32),
    settings: &RenderSettings,
    args: &cli::RenderArgs,
    kind: ImageKind,
) -> Result<(), Failure> {
    let start = web_time::Instant::now();
    let reference = reference_of(scene, size, settings, args.term);
    if args.reference {
        // Its time on one thread: the web page's reference is measured against it (docs/web.md).
        let ms = start.elapsed().as_secs_f64() * 1e3;
        println!("f64 reference of {} ({}×{}) in {ms:.1} ms, one thread", scene.name, size.0, size.1);
        save(&reference, &args.output, kind).with_context(|| format!("writing {}", args.output.display()))?;
        return Ok(());
    }
    let image = if args.term == Term::Shadow {
        shadelab_render::render_shadow_factor(gpu, scene, size, settings)
    } else {
        shadelab_render::render_image(gpu, scene, size.0, size.1, settings)
    }
    .map_err(|e| Failure::Usage(e.to_string()))?;
    let cmp = compare_images(&image, &reference);
    image::RgbImage::from_raw(size.0, size.1, cmp.flip_map_rgb8)
        .context("FLIP map size")?
        .save(&args.output)
        .with_context(|| format!("writing {}", args.output.display()))?;
    println!(
        "{} against the f64 reference ({} shading, term {}): RMSE {:.3e}, max {:.3}, mean FLIP {:.5}, {:.2} % of pixels visibly off",
        scene.name,
        settings.shading,
        shadelab_model::params::NamedValue::name(args.term),
        cmp.stats.rmse,
        cmp.stats.max_abs,
        cmp.stats.flip_mean,
        100.0 * cmp.stats.share_off
    );
    Ok(())
}
