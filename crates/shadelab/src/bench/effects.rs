//! `shadelab bench effects`: what specialization saves. Each scene drawn by its specialized
//! pipeline, by the uber pipeline and, per effect, by the specialized pipeline without it; where
//! an area light is too small on screen for its area to show (drawn as a point light, as
//! `render` draws it), also with its area kept.

use crate::{Failure, cli};
use shadelab_model::{Scene, ShadingMode, SpecularModel};
use shadelab_render::timing::{FrameTimer, TimedDraw, median, quantile_sorted};
use shadelab_render::{RenderSettings, Renderer, Target};

/// `shadelab bench effects`: specialized vs uber vs per-effect floors, per scene and shading.
pub fn run(args: &cli::BenchEffectsArgs) -> Result<(), Failure> {
    use shadelab_render::Program;
    let (width, height) = args.size.pixels();
    let (frames, warmup) = (args.frames as usize, args.warmup as usize);
    let scenes = load_scenes(args)?;
    let gpu = crate::render::open_gpu()?;
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let target = Target::new(&gpu.device, width, height, shadelab_render::target::HDR_FORMAT);
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    println!("# shadelab bench effects — {}×{}, {} frames per row after {} warm-up", width, height, frames, warmup);
    println!("# device: {}; time: {}", gpu.describe(), timer.source().label());
    println!("| scene | shading | pipeline | effects | median ms | p10–p90 ms | × specialized |");
    println!("|---|---|---|---|---:|---|---:|");
    let specular = args.model.and_then(|m| m.split().1).unwrap_or(SpecularModel::CookTorrance);
    for kept in &scenes {
        // As `render` draws it: an area light too small to show its area is a point light.
        let mut drawn = kept.clone();
        for line in shadelab_model::effects::draw_small_area_lights_as_points(&mut drawn, height) {
            println!("# {}: {line}", kept.name);
        }
        let scene = &drawn;
        let mut gs = r.upload(scene).map_err(|e| Failure::Usage(format!("{}: {e}", scene.name)))?;
        for shading in ShadingMode::ALL_MODES {
            let base = RenderSettings::new(shading, specular);
            let programs = shading_programs(scene, base);
            // Each row with its scene: the drawn one, and the one keeping small lights' areas.
            let mut rows: Vec<(&Scene, String, RenderSettings)> =
                programs.into_iter().map(|(name, s)| (scene, name, s)).collect();
            if drawn.lights != kept.lights {
                rows.insert(1, (kept, "specialized, small area lights kept".into(), rows[0].2));
            }
            let draws: Vec<TimedDraw> = rows
                .iter()
                .map(|(sc, _, s)| TimedDraw { upload: 0, scene: sc, program: Program::for_scene(sc, s), settings: *s })
                .collect();
            let mut samples =
                timer.interleaved_draws(&mut r, std::slice::from_mut(&mut gs), &target, &draws, frames, warmup);
            let specialized = median(&mut samples[0]);
            for (i, (sc, name, s)) in rows.iter().enumerate() {
                let effects = Program::for_scene(sc, s).effects();
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

/// The named scenes with `--model`, `--light` and `--light-size` applied.
fn load_scenes(args: &cli::BenchEffectsArgs) -> Result<Vec<Scene>, Failure> {
    let mut scenes = args
        .scenes
        .iter()
        .map(|name| cli::scene(&cli::SceneArgs { scene: name.clone(), ..cli::SceneArgs::default() }))
        .collect::<Result<Vec<_>, _>>()?;
    for s in &mut scenes {
        if let Some(m) = args.model {
            s.apply(&shadelab_model::Overrides::for_model(m));
        }
        let area_specular = args.area_specular;
        s.apply(&shadelab_model::Overrides {
            light: args.light,
            light_size: args.light_size,
            area_specular,
            ..Default::default()
        });
    }
    Ok(scenes)
}

/// One shading mode's programs: specialized, uber, and specialized without each of its effects.
fn shading_programs(scene: &Scene, base: RenderSettings) -> Vec<(String, RenderSettings)> {
    use shadelab_render::{Program, Specialization};
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
    programs
}
