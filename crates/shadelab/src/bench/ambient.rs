//! `shadelab bench ambient`: what closing the chapter's ambient gap costs (docs/reference.md).
//! Every rung of the ladder against one path-traced truth of many paths a pixel: the constant
//! `I_a`, the fitted `I_a`, ambient occlusion, and path tracing at 1, 4, 16, … paths, each with
//! its time on this machine's cores and its RMSE against the truth.

use crate::ambient_views::ambient_study;
use crate::{Failure, cli};
use shadelab_model::reference::{PathSettings, ReferenceJob, reference_threads};
use shadelab_render::RenderSettings;

/// The path-traced rows' seed: another than the truth's, so that their noise and its are
/// independent and the RMSE measures both.
const ROW_SEED: u64 = 2;

/// `shadelab bench ambient`.
pub fn run(args: &cli::BenchAmbientArgs) -> Result<(), Failure> {
    let scene = cli::scene(&args.scene)?;
    let size = (args.width, args.height);
    let settings = RenderSettings::new(shadelab_model::ShadingMode::Phong, shadelab_model::SpecularModel::CookTorrance);
    let truth_paths = PathSettings { bounces: args.bounces, spp: args.truth_spp, seed: 1 };
    let study = ambient_study(&scene, &settings, size, truth_paths)?;
    let ladder = &study.ladder;
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    println!(
        "# shadelab bench ambient — {}, {}×{}, {} bounces, on {} thread(s)",
        args.scene.scene,
        size.0,
        size.1,
        args.bounces,
        reference_threads()
    );
    println!("#     {command}");
    let noise = ladder.noise();
    println!(
        "truth: {} paths a pixel in {:.0} ms, its noise (RMS standard error) {noise:.2e}: an RMSE under {:.2e} is not measured",
        args.truth_spp,
        study.truth_ms,
        2.0 * noise
    );
    let f = ladder.fitted_ambient();
    println!(
        "fitted I_a: [{:.4}, {:.4}, {:.4}], the scene's [{:.4}, {:.4}, {:.4}]",
        f[0], f[1], f[2], ladder.ambient[0], ladder.ambient[1], ladder.ambient[2]
    );
    println!("| image | ms | RMSE against the truth |");
    println!("|---|---:|---:|");
    println!("| constant I_a (the chapter) | {:.1} | {:.3e} |", study.constant_ms, ladder.rmse(&ladder.constant()));
    println!("| fitted I_a | {:.1} | {:.3e} |", study.constant_ms, ladder.rmse(&ladder.fitted()));
    println!(
        "| ambient occlusion, {} rays | {:.1} | {:.3e} |",
        crate::ambient_views::AO_RAYS,
        study.constant_ms + study.ao_ms,
        ladder.rmse(&ladder.occluded(&study.ao))
    );
    let mut spp = 1;
    while spp * 4 <= args.truth_spp {
        let paths = PathSettings { bounces: args.bounces, spp, seed: ROW_SEED };
        let start = web_time::Instant::now();
        let mut job =
            ReferenceJob::with_paths(&scene, settings.specular, size.0, size.1, paths).map_err(Failure::Usage)?;
        job.step(size.1);
        let ms = start.elapsed().as_secs_f64() * 1e3;
        let traced = job.finish();
        println!("| path traced, {spp} paths | {ms:.1} | {:.3e} |", ladder.rmse(&traced.pixels));
        spp *= 4;
    }
    Ok(())
}
