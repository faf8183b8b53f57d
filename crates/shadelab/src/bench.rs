//! `shadelab bench …`: measurements, reported with the device and the command; never asserted.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::timing::{FrameTimer, median, quantile_sorted};
use shadelab_render::{AdapterChoice, Gpu, RenderSettings, Renderer, Target};

pub fn run_render(args: &cli::BenchRenderArgs) -> Result<(), Failure> {
    let (width, height) = cli::size(&args.width, &args.height)?;
    let frames = cli::FRAMES.parse_u32(&args.frames)? as usize;
    let warmup = cli::WARMUP.parse_u32(&args.warmup)? as usize;
    let scene = cli::scene(&args.scene)?;
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let gs = r.upload(&scene);
    let target = Target::new(&gpu.device, width, height, shadelab_render::target::HDR_FORMAT);
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let combos: Vec<RenderSettings> = ShadingMode::ALL_MODES
        .into_iter()
        .flat_map(|shading| {
            SpecularModel::ALL_MODELS.into_iter().map(move |specular| RenderSettings::new(shading, specular))
        })
        .collect();
    let mut samples = timer.interleaved(&mut r, &gs, &scene, &target, &combos, frames, warmup);
    println!(
        "# shadelab bench render — scene '{}', {}×{}, {} triangles, {} lights",
        scene.name,
        width,
        height,
        scene.triangle_count(),
        scene.lights.len()
    );
    println!(
        "# device: {}; time: {}; {} frames per row after {} warm-up",
        gpu.describe(),
        timer.source().label(),
        frames,
        warmup
    );
    println!("| shading | specular | median ms | p10 ms | p90 ms | ratio to fastest |");
    println!("|---|---|---:|---:|---:|---:|");
    let medians: Vec<f64> = samples.iter_mut().map(|s| median(s)).collect();
    let fastest = medians.iter().copied().fold(f64::INFINITY, f64::min);
    for (i, s) in combos.iter().enumerate() {
        println!(
            "| {} | {} | {:.3} | {:.3} | {:.3} | {:.2} |",
            s.shading,
            s.specular,
            medians[i],
            quantile_sorted(&samples[i], 0.1),
            quantile_sorted(&samples[i], 0.9),
            medians[i] / fastest
        );
    }
    Ok(())
}

/// `shadelab sweep`: the stability sweep's table; exits 1 if any check fails.
pub fn run_sweep() -> Result<(), Failure> {
    use shadelab_render::sweep::{self, ERROR_TOLERANCE, SweepInputs};
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    let start = std::time::Instant::now();
    let report = sweep::run(&gpu, SweepInputs::standard());
    println!("# shadelab sweep — device: {}", gpu.describe());
    println!(
        "# GPU pass + readback {:.0} ms, whole sweep {:.1} s; error tolerance {ERROR_TOLERANCE:e} where the f64 reference is well-conditioned",
        report.gpu_ms,
        start.elapsed().as_secs_f64()
    );
    print!("{}", report.table());
    let failed: Vec<_> = report
        .terms
        .iter()
        .filter(|t| t.nonfinite + t.negative + t.over_bound > 0 || t.max_rel_err > ERROR_TOLERANCE)
        .map(|t| t.name)
        .collect();
    if failed.is_empty() {
        println!("\nall terms finite, ≥ 0, within their bounds and within {ERROR_TOLERANCE:e} of f64");
        Ok(())
    } else {
        Err(Failure::Run(anyhow::anyhow!("sweep failed for: {}", failed.join(", "))))
    }
}

/// `shadelab bench effects`: specialized vs uber vs per-effect floors, per scene and shading.
pub fn run_effects(args: &cli::BenchEffectsArgs) -> Result<(), Failure> {
    use shadelab_render::Specialization;
    let (width, height) = cli::size(&args.width, &args.height)?;
    let frames = cli::FRAMES.parse_u32(&args.frames)? as usize;
    let warmup = cli::WARMUP.parse_u32(&args.warmup)? as usize;
    let scenes = args
        .scenes
        .iter()
        .map(|name| cli::scene(&cli::SceneArgs { scene: name.clone(), ..cli::SceneArgs::default() }))
        .collect::<Result<Vec<_>, _>>()?;
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let target = Target::new(&gpu.device, width, height, shadelab_render::target::HDR_FORMAT);
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    println!("# shadelab bench effects — {}×{}, {} frames per row after {} warm-up", width, height, frames, warmup);
    println!("# device: {}; time: {}", gpu.describe(), timer.source().label());
    println!("| scene | shading | pipeline | effects | median ms | p10–p90 ms | × specialized |");
    println!("|---|---|---|---|---:|---|---:|");
    let specular = SpecularModel::CookTorrance;
    for scene in &scenes {
        let gs = r.upload(scene);
        let key = shadelab_model::effects::analyze(scene, specular).key;
        for shading in ShadingMode::ALL_MODES {
            let base = RenderSettings::new(shading, specular);
            let mut programs = vec![
                ("specialized".to_string(), RenderSettings { specialization: Specialization::Specialized, ..base }),
                ("uber".to_string(), RenderSettings { specialization: Specialization::Uber, ..base }),
            ];
            for e in key.effects() {
                programs.push((
                    format!("without {}", e.name()),
                    RenderSettings { specialization: Specialization::Fixed(key.without(e)), ..base },
                ));
            }
            let settings: Vec<RenderSettings> = programs.iter().map(|(_, s)| *s).collect();
            let mut samples = timer.interleaved(&mut r, &gs, scene, &target, &settings, frames, warmup);
            let specialized = median(&mut samples[0]);
            for (i, (name, s)) in programs.iter().enumerate() {
                r.write_uniforms(&gs, scene, &target, s);
                let m = median(&mut samples[i]);
                println!(
                    "| {} | {} | {} | {} | {:.3} | {:.3}–{:.3} | {:.3} |",
                    scene.name,
                    shading,
                    name,
                    gs.effects().label(),
                    m,
                    quantile_sorted(&samples[i], 0.1),
                    quantile_sorted(&samples[i], 0.9),
                    m / specialized
                );
            }
        }
    }
    Ok(())
}
