//! `shadelab bench environment`: what each approximation of the environment light costs against
//! the path-traced truth (docs/environment.md). The rungs, each as the f64 twin of what it draws
//! (the GPU matches its twin to about 1e-5, `tests/tests/gpu/environment.rs`): the constant `I_a` of
//! the environment's mean radiance, the nine SH terms (diffuse), the nine terms with the split
//! sum's specular, those with the diffuse occluded by the precomputed grid (its bake timed on
//! the CPU), and, for comparison, by per-pixel ambient occlusion traced in f64; each GPU rung
//! timed side by side with the others.

use crate::reference_views::traced_with_progress;
use crate::{Failure, cli};
use shadelab_model::lighting::env_map::{EnvSource, Environment};
use shadelab_model::lighting::environment::SH_Y0;
use shadelab_model::lighting::occlusion::OCC_RAYS;
use shadelab_model::reference::{
    PathSettings, ReferenceJob, ambient_occlusion, bake_occlusion, reference_threads, render_reference,
};
use shadelab_model::{Scene, ShadingMode, SpecularModel};
use shadelab_render::timing::{FrameTimer, TimedDraw, median};
use shadelab_render::{Program, RenderSettings, Renderer, Target};

/// Frames timed per rung, after this many unmeasured ones.
const FRAMES: usize = 30;
const WARMUP: usize = 5;

/// RMSE of `a` against `b` over every pixel and channel.
fn rmse(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    let sum: f64 = a.iter().zip(b).flat_map(|(p, q)| (0..3).map(move |c| (p[c] - q[c]).powi(2))).sum();
    (sum / (3 * a.len().max(1)) as f64).sqrt()
}

/// The scene the study lights: the flags' environment, else the sky in place of `I_a`.
fn lit(args: &cli::BenchAmbientArgs) -> Result<Scene, Failure> {
    let mut scene = cli::scene(&args.scene)?;
    if scene.environment.is_none() {
        scene.environment = Some(Environment::new(EnvSource::Sky {
            turbidity: shadelab_model::lighting::sky::TURBIDITY_DEFAULT,
            sun: None,
        }));
        scene.ambient = [0.0; 3];
    }
    Ok(scene)
}

/// `shadelab bench environment`.
pub fn run(args: &cli::BenchAmbientArgs) -> Result<(), Failure> {
    let scene = lit(args)?;
    let env = scene.environment.clone().expect("set above");
    let (w, h) = (args.width, args.height);
    let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let paths = PathSettings { bounces: args.bounces, spp: args.truth_spp, seed: 1 };
    let job = ReferenceJob::with_paths(&scene, settings.specular, w, h, paths).map_err(Failure::Usage)?;
    let start = web_time::Instant::now();
    let truth = traced_with_progress(job, "path-traced truth", h);
    let truth_ms = start.elapsed().as_secs_f64() * 1e3;
    // The constant that stands for the environment: its mean radiance, band 0 of its SH terms.
    let sh = env.sh(&scene.lights);
    let mean = sh[0].map(|c| c * SH_Y0);
    let constant = Scene { ambient: mean, environment: None, ..scene.clone() };
    let bare = Scene { ambient: [0.0; 3], environment: None, ..scene.clone() };
    let diffuse = Scene {
        environment: Some(shadelab_model::lighting::env_map::Environment { specular: false, ..env.clone() }),
        ..scene.clone()
    };
    let split = Scene {
        environment: Some(shadelab_model::lighting::env_map::Environment { specular: true, ..env.clone() }),
        ..scene.clone()
    };
    let grid =
        Scene { environment: Some(Environment { specular: true, occlusion: true, ..env.clone() }), ..scene.clone() };
    let start = web_time::Instant::now();
    let baked = bake_occlusion(&scene, OCC_RAYS, 1);
    let bake_ms = start.elapsed().as_secs_f64() * 1e3;
    let nodes = baked.as_ref().map_or(0, |g| g.nodes.len());
    let grid_image = render_reference(&grid, settings.specular, w, h);
    let sh_image = render_reference(&diffuse, settings.specular, w, h);
    let split_image = render_reference(&split, settings.specular, w, h);
    let constant_image = render_reference(&constant, settings.specular, w, h);
    let bare_image = render_reference(&bare, settings.specular, w, h);
    let start = web_time::Instant::now();
    let ao = ambient_occlusion(&scene, w, h, crate::ambient_views::AO_RAYS, 1);
    let ao_ms = start.elapsed().as_secs_f64() * 1e3;
    // The diffuse part occluded, the specular part as drawn.
    let occluded: Vec<[f64; 3]> = (0..sh_image.pixels.len())
        .map(|i| {
            let (d, s, b) = (sh_image.pixels[i], split_image.pixels[i], bare_image.pixels[i]);
            std::array::from_fn(|c| b[c] + ao[i] * (d[c] - b[c]) + (s[c] - d[c]))
        })
        .collect();
    let [null_ms, constant_ms, sh_ms, split_ms, grid_ms] =
        gpu_times(&[&constant, &diffuse, &split, &grid], &settings, (w, h))?;
    let noise = {
        let n = truth.std_error.len().max(1) as f64;
        (truth.std_error.iter().map(|e| e.iter().map(|v| v * v).sum::<f64>() / 3.0).sum::<f64>() / n).sqrt()
    };
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    println!(
        "# shadelab bench environment — {}, {} environment, {w}×{h}, {} bounces, on {} thread(s)",
        args.scene.scene,
        env.source.name(),
        args.bounces,
        reference_threads()
    );
    println!("#     {command}");
    println!(
        "truth: {} paths a pixel in {truth_ms:.0} ms, its noise (RMS standard error) {noise:.2e}: an RMSE under {:.2e} is not measured",
        args.truth_spp,
        2.0 * noise
    );
    println!("the constant I_a (the mean radiance): [{:.4}, {:.4}, {:.4}]", mean[0], mean[1], mean[2]);
    println!("| image | GPU frame ms (median of {FRAMES}) | RMSE against the truth |");
    println!("|---|---:|---:|");
    println!("| null shader | {null_ms:.3} | |");
    println!("| constant I_a (the chapter) | {constant_ms:.3} | {:.3e} |", rmse(&constant_image.pixels, &truth.pixels));
    println!("| nine SH terms | {sh_ms:.3} | {:.3e} |", rmse(&sh_image.pixels, &truth.pixels));
    println!(
        "| nine SH terms + split-sum specular | {split_ms:.3} | {:.3e} |",
        rmse(&split_image.pixels, &truth.pixels)
    );
    println!(
        "| + the diffuse occluded by the precomputed grid ({nodes} nodes, baked in {bake_ms:.0} ms on the CPU) | {grid_ms:.3} | {:.3e} |",
        rmse(&grid_image.pixels, &truth.pixels)
    );
    println!(
        "| + per-pixel ambient occlusion of the diffuse, {} rays (f64 only: {ao_ms:.0} ms on the CPU) | | {:.3e} |",
        crate::ambient_views::AO_RAYS,
        rmse(&occluded, &truth.pixels)
    );
    println!("| no environment light at all | | {:.3e} |", rmse(&bare_image.pixels, &truth.pixels));
    Ok(())
}

/// The GPU's frame for the null shader and each of `scenes` (one scene's variants: the same
/// geometry), drawn interleaved: medians in ms, the null shader's first.
fn gpu_times(scenes: &[&Scene; 4], settings: &RenderSettings, (w, h): (u32, u32)) -> anyhow::Result<[f64; 5]> {
    let gpu = crate::render::open_gpu()?;
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(scenes[0])?;
    let target = Target::new(&gpu.device, w, h, shadelab_render::target::HDR_FORMAT);
    let mut draws = vec![TimedDraw {
        upload: 0,
        scene: scenes[0],
        program: Program::NullBaseline,
        settings: RenderSettings::default(),
    }];
    draws.extend(scenes.iter().map(|s| TimedDraw {
        upload: 0,
        scene: s,
        program: Program::for_scene(s, settings),
        settings: *settings,
    }));
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let mut samples = timer.interleaved_draws(&mut r, std::slice::from_mut(&mut gs), &target, &draws, FRAMES, WARMUP);
    Ok(std::array::from_fn(|i| median(&mut samples[i])))
}
