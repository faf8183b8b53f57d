//! `render --reference` and `render --difference`: the f64 ray-cast reference of the scene (and
//! of the term on show) in place of the GPU's image, or the FLIP map of the one against the
//! other, so that each term has its reference and its difference map from the command line too.

use crate::image_file::{ImageKind, save};
use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::reference::{PathSettings, ReferenceImage, ReferenceJob};
use shadelab_model::terms::{Term, shadow_factor};
use shadelab_render::image_error::{compare_images, reference_image};
use shadelab_render::{LinearImage, RenderSettings};
use std::io::{IsTerminal, Write};

/// Which reference a scene under an environment light gets, in one line (`None` without one):
/// the exact reference evaluates the environment as the GPU does (its twin), only the path tracer
/// integrates it (the truth), so a difference from the twin is not an error against the truth.
pub fn environment_reference(scene: &shadelab_model::Scene, paths: Option<PathSettings>) -> Option<String> {
    scene.environment.as_ref()?;
    Some(match paths {
        None => "reference: under the environment light, the GPU's f64 twin (its nine SH terms, split sum and \
                 occlusion grid, as drawn), not the truth; --bounces N path traces the truth"
            .into(),
        Some(p) => format!(
            "reference: the path-traced truth, the environment integrated over the BRDF with visibility by ray \
             ({} vertices, {} paths a pixel)",
            p.bounces, p.spp
        ),
    })
}

/// Rows a progress step traces: a fiftieth of the image, so the bar moves in 2 % steps.
const PROGRESS_STEPS: u32 = 50;

/// The reference traced as the viewer traces it (`ReferenceJob`, the same code path), a fiftieth
/// of its rows at a time, with a progress bar on standard error when that is a terminal.
pub fn traced_with_progress(mut job: ReferenceJob, label: &str, height: u32) -> ReferenceImage {
    let rows = height.div_ceil(PROGRESS_STEPS).max(1);
    let mut err = std::io::stderr();
    let bar = err.is_terminal();
    while !job.step(rows) {
        if bar {
            let done = (job.progress() * 40.0).round() as usize;
            let _ = write!(
                err,
                "\r{label} [{}{}] {:3.0} %",
                "#".repeat(done),
                " ".repeat(40 - done.min(40)),
                job.progress() * 100.0
            );
            let _ = err.flush();
        }
    }
    if bar {
        let _ = write!(err, "\r{}\r", " ".repeat(60 + label.len()));
    }
    job.finish()
}

/// The job `render` traces: the exact reference, or with `paths` the path-traced one (one clear
/// line where the scene's model has no light between surfaces to trace).
pub fn reference_job(
    scene: &shadelab_model::Scene,
    settings: &RenderSettings,
    size: (u32, u32),
    paths: Option<PathSettings>,
) -> Result<ReferenceJob, Failure> {
    match paths {
        None => Ok(ReferenceJob::new(scene, settings.specular, size.0, size.1)),
        Some(p) => ReferenceJob::with_paths(scene, settings.specular, size.0, size.1, p).map_err(Failure::Usage),
    }
}

/// The reference of `scene` at `size` as a linear image: its pixels, or with `--term shadow`
/// its exact cast-shadow factor as grey (the background kept), as the GPU's factor is drawn.
fn reference_of(r: &ReferenceImage, term: Term) -> LinearImage {
    if term != Term::Shadow {
        return reference_image(r);
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
    LinearImage { width: r.width, height: r.height, pixels }
}

/// `render --reference` (the CPU's alone) or `--difference` (which opens the GPU for its side).
pub fn run(
    scene: &shadelab_model::Scene,
    size: (u32, u32),
    settings: &RenderSettings,
    args: &cli::RenderArgs,
    kind: ImageKind,
) -> Result<(), Failure> {
    // The difference's GPU side, opened before the reference is traced, so that a missing
    // adapter is said at once rather than after minutes of paths.
    let gpu = if args.reference { None } else { Some(crate::render::open_gpu()?) };
    let start = web_time::Instant::now();
    let paths = args.paths();
    // Which reference this is: the twin and the truth differ under an environment.
    if let Some(line) = environment_reference(scene, paths) {
        println!("{line}");
    }
    let label = if paths.is_some() { "path-traced reference" } else { "f64 reference" };
    let traced = traced_with_progress(reference_job(scene, settings, size, paths)?, label, size.1);
    let reference = reference_of(&traced, args.term);
    let noise = paths.map(|p| noise_line(&traced, p)).unwrap_or_default();
    let Some(gpu) = gpu else {
        // --reference: its time and threads (RAYON_NUM_THREADS=1: one, as the web page's, docs/web.md).
        let ms = start.elapsed().as_secs_f64() * 1e3;
        let threads = shadelab_model::reference::reference_threads();
        println!("{label} of {} ({}×{}) in {ms:.1} ms, {threads} thread(s){noise}", scene.name, size.0, size.1);
        save(&reference, &args.output, kind).with_context(|| format!("writing {}", args.output.display()))?;
        return Ok(());
    };
    let image = if args.term == Term::Shadow {
        shadelab_render::render_shadow_factor(&gpu, scene, size, settings)
    } else {
        shadelab_render::render_image(&gpu, scene, size.0, size.1, settings)
    }
    .map_err(|e| Failure::Usage(e.to_string()))?;
    let cmp = compare_images(&image, &reference);
    image::RgbImage::from_raw(size.0, size.1, cmp.flip_map_rgb8)
        .context("FLIP map size")?
        .save(&args.output)
        .with_context(|| format!("writing {}", args.output.display()))?;
    println!(
        "{} against the {label} ({} shading, term {}): RMSE {:.3e}, max {:.3}, mean FLIP {:.5}, {:.2} % of pixels visibly off{noise}",
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

/// The path tracer's settings and its noise, for the printed line: the root mean square of the
/// pixels' standard error (a difference under it is not measured) and the fireflies.
fn noise_line(traced: &ReferenceImage, p: PathSettings) -> String {
    let n = traced.std_error.len().max(1) as f64 * 3.0;
    let rms = (traced.std_error.iter().flatten().map(|e| e * e).sum::<f64>() / n).sqrt();
    format!(
        "; {} bounces, {} paths a pixel, seed {}: noise (RMS standard error) {rms:.3e}, {} pixels with a firefly (one path over {:.0} % of the pixel's indirect light), {} above {}× their 3×3 median",
        p.bounces,
        p.spp,
        p.seed,
        traced.fireflies,
        shadelab_model::reference::FIREFLY_SHARE * 100.0,
        shadelab_model::reference::outlier_pixels(&traced.pixels, traced.width as usize),
        shadelab_model::reference::OUTLIER_FACTOR
    )
}
