//! `render --ambient-error`: the chapter's constant ambient `I_a·r_a·C` against the light that
//! really passes between the scene's surfaces, path traced (docs/reference.md). Writes the signed
//! error, prints the `I_a` that fits the scene, and the error and time of each rung of the
//! ladder: the constant ambient, the fitted one, ambient occlusion, and the truth itself.

use crate::image_file::{ImageKind, save};
use crate::reference_views::{reference_job, traced_with_progress};
use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::Scene;
use shadelab_model::reference::{AmbientLadder, PathSettings, ReferenceJob, ambient_occlusion};
use shadelab_render::{LinearImage, RenderSettings};

/// Rays a pixel of the ambient occlusion rung: its share's own noise is at most
/// `√(1/4/64) = 6 %`, a few thousandths of the default scene's ambient term, under its error.
pub const AO_RAYS: u32 = 64;

/// The ladder of one view, each rung's time, and the occlusion it used.
pub struct AmbientStudy {
    pub ladder: AmbientLadder,
    pub ao: Vec<f64>,
    pub paths: PathSettings,
    /// Milliseconds: the path-traced truth, the chapter's exact image (the constant and the
    /// fitted rungs' whole cost), and the ambient occlusion rays.
    pub truth_ms: f64,
    pub constant_ms: f64,
    pub ao_ms: f64,
    /// Each pixel's object (`None`: background).
    pub object: Vec<Option<usize>>,
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = web_time::Instant::now();
    let out = f();
    (out, start.elapsed().as_secs_f64() * 1e3)
}

/// Trace the ladder of `scene` at `size`: the truth with `paths` (which holds the constant
/// ambient's terms), the chapter's exact image for its time, and the occlusion with as many rays a pixel as the truth has paths.
pub fn ambient_study(
    scene: &Scene,
    settings: &RenderSettings,
    size: (u32, u32),
    paths: PathSettings,
) -> Result<AmbientStudy, Failure> {
    let job = reference_job(scene, settings, size, Some(paths))?;
    let (traced, truth_ms) = timed(|| traced_with_progress(job, "path-traced reference", size.1));
    // The chapter's image on its own, for its time: the exact reference with the constant ambient.
    let exact = ReferenceJob::new(scene, settings.specular, size.0, size.1);
    let (_, constant_ms) = timed(|| traced_with_progress(exact, "f64 reference", size.1));
    let (ao, ao_ms) = timed(|| ambient_occlusion(scene, size.0, size.1, AO_RAYS, paths.seed));
    let ladder = AmbientLadder::new(&traced, scene.ambient).context("the path-traced image has no ambient terms")?;
    Ok(AmbientStudy { ladder, ao, paths, truth_ms, constant_ms, ao_ms, object: traced.object })
}

/// Rec. 709 luminance.
pub fn luminance(c: [f64; 3]) -> f64 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

/// The signed error as a picture: luminance error `e` from blue (`e = −scale`, too dark) through
/// white (0) to red (`+scale`, too bright); black where the camera sees nothing.
pub fn diverging_map(error: &[[f64; 3]], object: &[Option<usize>], scale: f64, size: (u32, u32)) -> LinearImage {
    const BLUE: [f64; 3] = [0.02, 0.08, 0.6];
    const RED: [f64; 3] = [0.6, 0.01, 0.02];
    let pixels = error
        .iter()
        .zip(object)
        .map(|(e, o)| {
            if o.is_none() {
                return [0.0, 0.0, 0.0, 1.0];
            }
            let t = (luminance(*e) / scale).clamp(-1.0, 1.0);
            let end = if t < 0.0 { BLUE } else { RED };
            let c: [f64; 3] = std::array::from_fn(|i| 1.0 + (end[i] - 1.0) * t.abs());
            [c[0] as f32, c[1] as f32, c[2] as f32, 1.0]
        })
        .collect();
    LinearImage { width: size.0, height: size.1, pixels }
}

/// The 99th percentile of the luminance error's size over the pixels that see something: the
/// map's full colour, so that a few extreme pixels do not wash it out.
pub fn map_scale(error: &[[f64; 3]], object: &[Option<usize>]) -> f64 {
    let mut e: Vec<f64> =
        error.iter().zip(object).filter(|(_, o)| o.is_some()).map(|(e, _)| luminance(*e).abs()).collect();
    if e.is_empty() {
        return 1.0;
    }
    e.sort_by(f64::total_cmp);
    let s = e[((e.len() - 1) as f64 * 0.99) as usize];
    if s > 0.0 { s } else { 1.0 }
}

/// `render --ambient-error`.
pub fn run(
    scene: &Scene,
    size: (u32, u32),
    settings: &RenderSettings,
    args: &cli::RenderArgs,
    kind: ImageKind,
) -> Result<(), Failure> {
    let paths = args.paths().context("--ambient-error traces paths")?;
    let study = ambient_study(scene, settings, size, paths)?;
    let ladder = &study.ladder;
    let constant = ladder.constant();
    let error = ladder.error(&constant);
    let image = match kind {
        ImageKind::Exr => LinearImage {
            width: size.0,
            height: size.1,
            pixels: error.iter().map(|e| [e[0] as f32, e[1] as f32, e[2] as f32, 1.0]).collect(),
        },
        ImageKind::Png => diverging_map(&error, &study.object, map_scale(&error, &study.object), size),
    };
    save(&image, &args.output, kind).with_context(|| format!("writing {}", args.output.display()))?;
    print!("{}", report(scene, &study, kind == ImageKind::Png).map_err(|e| Failure::Usage(e.to_string()))?);
    Ok(())
}

/// The printed report: the shares of light, the fitted `I_a`, the ladder's errors and times, and
/// per object how much light the constant ambient gives against the light that really arrives.
pub fn report(scene: &Scene, study: &AmbientStudy, png: bool) -> Result<String, std::fmt::Error> {
    use std::fmt::Write as _;
    let (ladder, p) = (&study.ladder, study.paths);
    let (constant, truth) = (ladder.constant(), ladder.truth());
    let sum = |v: &[[f64; 3]]| v.iter().map(|c| luminance(*c)).sum::<f64>();
    let ambient: Vec<[f64; 3]> =
        ladder.per_ambient.iter().map(|a| std::array::from_fn(|c| a[c] * ladder.ambient[c])).collect();
    let mut out = String::new();
    writeln!(
        out,
        "ambient error of {} ({}×{}), {} bounces, {} paths a pixel, seed {}",
        scene.name, ladder.width, ladder.height, p.bounces, p.spp, p.seed
    )?;
    writeln!(
        out,
        "light between surfaces: {:.1} % of the true image; the constant I_a·r_a·C: {:.1} % of the chapter's",
        100.0 * sum(&ladder.indirect) / sum(&truth).max(f64::MIN_POSITIVE),
        100.0 * sum(&ambient) / sum(&constant).max(f64::MIN_POSITIVE)
    )?;
    let f = ladder.fitted_ambient();
    let a = ladder.ambient;
    writeln!(
        out,
        "fitted I_a: [{:.4}, {:.4}, {:.4}] (the scene's: [{:.4}, {:.4}, {:.4}])",
        f[0], f[1], f[2], a[0], a[1], a[2]
    )?;
    if png {
        writeln!(out, "map: luminance error, blue too dark, red too bright, full colour at its 99th percentile")?;
    }
    writeln!(out, "| image | ms | RMSE against the truth |")?;
    writeln!(out, "|---|---:|---:|")?;
    writeln!(out, "| constant I_a | {:.1} | {:.3e} |", study.constant_ms, ladder.rmse(&constant))?;
    writeln!(out, "| fitted I_a | {:.1} | {:.3e} |", study.constant_ms, ladder.rmse(&ladder.fitted()))?;
    let ao_ms = study.constant_ms + study.ao_ms;
    writeln!(out, "| ambient occlusion | {ao_ms:.1} | {:.3e} |", ladder.rmse(&ladder.occluded(&study.ao)))?;
    writeln!(out, "| path traced (the truth) | {:.1} | noise {:.3e} |", study.truth_ms, ladder.noise())?;
    writeln!(out, "| object | constant ambient over the true light between surfaces |")?;
    writeln!(out, "|---|---:|")?;
    for (i, obj) in scene.objects.iter().enumerate() {
        let (mut given, mut real) = (0.0, 0.0);
        for (k, o) in study.object.iter().enumerate() {
            if *o == Some(i) {
                given += luminance(ambient[k]);
                real += luminance(ladder.indirect[k]);
            }
        }
        if real > 0.0 {
            writeln!(out, "| {} | {:.2}× |", obj.name, given / real)?;
        }
    }
    Ok(out)
}
