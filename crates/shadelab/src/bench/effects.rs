//! `shadelab bench effects`: what specialization saves. Each scene drawn by its specialized
//! pipeline, by the uber pipeline and, per effect, by the specialized pipeline without it.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::timing::{FrameTimer, median, quantile_sorted};
use shadelab_render::{AdapterChoice, Gpu, RenderSettings, Renderer, Target};

/// `shadelab bench effects`: specialized vs uber vs per-effect floors, per scene and shading.
pub fn run(args: &cli::BenchEffectsArgs) -> Result<(), Failure> {
    use shadelab_render::{Program, Specialization};
    let (width, height) = args.size.pixels();
    let (frames, warmup) = (args.frames as usize, args.warmup as usize);
    let mut scenes = args
        .scenes
        .iter()
        .map(|name| cli::scene(&cli::SceneArgs { scene: name.clone(), ..cli::SceneArgs::default() }))
        .collect::<Result<Vec<_>, _>>()?;
    if let Some(m) = args.model {
        for s in &mut scenes {
            s.apply(&shadelab_model::Overrides::for_model(m));
        }
    }
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let target = Target::new(&gpu.device, width, height, shadelab_render::target::HDR_FORMAT);
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    println!("# shadelab bench effects — {}×{}, {} frames per row after {} warm-up", width, height, frames, warmup);
    println!("# device: {}; time: {}", gpu.describe(), timer.source().label());
    println!("| scene | shading | pipeline | effects | median ms | p10–p90 ms | × specialized |");
    println!("|---|---|---|---|---:|---|---:|");
    let specular = args.model.and_then(|m| m.split().1).unwrap_or(SpecularModel::CookTorrance);
    for scene in &scenes {
        let gs = r.upload(scene).map_err(|e| Failure::Usage(format!("{}: {e}", scene.name)))?;
        for shading in ShadingMode::ALL_MODES {
            let base = RenderSettings::new(shading, specular);
            // The mode's own program: the per-vertex modes hold no per-pixel lighting maps.
            let key = Program::for_scene(scene, &base).effects();
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
            let settings: Vec<(Program, RenderSettings)> =
                programs.iter().map(|(_, s)| (Program::for_scene(scene, s), *s)).collect();
            let mut samples = timer.interleaved(&mut r, &gs, scene, &target, &settings, frames, warmup);
            let specialized = median(&mut samples[0]);
            for (i, (name, s)) in programs.iter().enumerate() {
                let effects = Program::for_scene(scene, s).effects();
                let m = median(&mut samples[i]);
                println!(
                    "| {} | {} | {} | {} | {:.3} | {:.3}–{:.3} | {:.3} |",
                    scene.name,
                    shading,
                    name,
                    effects.label(),
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
