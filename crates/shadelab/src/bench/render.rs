//! `shadelab bench render`: the frame time of one scene for each shading mode × specular model,
//! interleaved in one run with the null-shader baseline (the same geometry, no lighting), and
//! each mode's time over the baseline's.

use crate::{Failure, cli};
use shadelab_model::params::NamedValue;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::timing::{FrameTimer, median, quantile_sorted};
use shadelab_render::{RenderSettings, Renderer, Target};

/// `shadelab bench render`: one table row per shading × specular combination.
pub fn run(args: &cli::BenchRenderArgs) -> Result<(), Failure> {
    let (width, height) = args.size.pixels();
    let (frames, warmup) = (args.frames as usize, args.warmup as usize);
    let scene = cli::scene(&args.scene)?;
    // The new lights take the light flags too (`--shadows`, `--falloff`, …).
    let scene = match args.point_lights {
        Some(n) => {
            let mut s = shadelab_model::scene_variants::with_point_lights(&scene, n as usize);
            s.apply(&cli::overrides(&args.scene));
            s
        }
        None => scene,
    };
    let gpu = crate::render::open_gpu()?;
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(&scene).map_err(|e| Failure::Usage(format!("{}: {e}", args.scene.scene)))?;
    let target = Target::new(&gpu.device, width, height, shadelab_render::target::HDR_FORMAT);
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let combos: Vec<RenderSettings> = ShadingMode::ALL_MODES
        .into_iter()
        .flat_map(|shading| {
            SpecularModel::ALL_MODELS.into_iter().map(move |specular| RenderSettings::new(shading, specular))
        })
        .collect();
    // The baseline first, then every combination, frame by frame.
    let programs: Vec<_> = std::iter::once((shadelab_render::Program::NullBaseline, RenderSettings::default()))
        .chain(combos.iter().map(|s| (shadelab_render::Program::for_scene(&scene, s), *s)))
        .collect();
    let mut samples = timer.interleaved(&mut r, &mut gs, &scene, &target, &programs, frames, warmup);
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
    println!("| shading | specular | median ms | p10 ms | p90 ms | baseline ms | × baseline | ratio to fastest |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|");
    let medians: Vec<f64> = samples.iter_mut().map(|s| median(s)).collect();
    let baseline = medians[0];
    let fastest = medians[1..].iter().copied().fold(f64::INFINITY, f64::min);
    let row = |name: (&str, &str), i: usize| {
        println!(
            "| {} | {} | {:.3} | {:.3} | {:.3} | {:.3} | {:.2} | {:.2} |",
            name.0,
            name.1,
            medians[i],
            quantile_sorted(&samples[i], 0.1),
            quantile_sorted(&samples[i], 0.9),
            baseline,
            medians[i] / baseline,
            medians[i] / fastest
        );
    };
    row(("null baseline", "—"), 0);
    for (i, s) in combos.iter().enumerate() {
        row((s.shading.name(), s.specular.name()), i + 1);
    }
    Ok(())
}
