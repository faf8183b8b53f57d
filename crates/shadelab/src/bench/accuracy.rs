//! The accuracy study's benchmark driver (`shadelab bench accuracy`): what accuracy costs in
//! time. Every shading mode × specular model × level of detail × resolution of the analytic
//! scenes (the scene variants of `shadelab_model::scene_variants`) is timed on the GPU beside a
//! null-shader baseline and measured against the f64 reference of the exact surface (the image
//! error of `shadelab_render::image_error`); then the cost of each added light and of each
//! resolution step. Writes a CSV, a Markdown report and two plots.

use crate::{Failure, cli};
pub use markdown::{markdown, summary};
pub use report::{Crossover, Plan, Report, Row, Study, crossovers, programs};
use report::{MAPPED_FLOOR, TEXTURED_FLOOR, rmse};

mod markdown;
mod plots;
mod report;
use anyhow::Context;
use shadelab_model::reference::{ReferenceImage, render_reference};
use shadelab_model::scene_variants;
use shadelab_model::{ModelChoice, Scene, ShadingMode, SpecularModel};
use shadelab_render::image_error::{self, ErrorStats};
use shadelab_render::timing::{FrameTimer, median, quantile_sorted};
use shadelab_render::{Gpu, Program, RenderSettings, Renderer, Specialization, Target, target};
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// One group: a scene at a level and size, all programs interleaved frame by frame.
struct Group {
    study: Study,
    name: &'static str,
    scene: Scene,
    level: u32,
    size: (u32, u32),
    /// The models study's model (the others: the scene's, the Phong model).
    model: Option<ModelChoice>,
}

impl Group {
    /// The programs drawn: the baseline, then every shading mode × specular model, or for a
    /// model of the models study every shading mode with the specular model it fixes.
    fn programs(&self) -> Vec<Option<RenderSettings>> {
        if self.study == Study::Textures {
            let modes = ShadingMode::ALL_MODES.map(|s| Some(RenderSettings::new(s, SpecularModel::CookTorrance)));
            return std::iter::once(None).chain(modes).collect();
        }
        if self.study == Study::Glass {
            use shadelab_model::effects::Effect;
            let phong = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
            let key = Program::for_scene(&self.scene, &phong).effects();
            let straight = Specialization::Fixed(key.without(Effect::Refraction));
            let back = shadelab_model::lighting::transmission::GlassExit::BackFaces;
            let modes = ShadingMode::ALL_MODES.map(|s| Some(RenderSettings::new(s, SpecularModel::CookTorrance)));
            let cheaper = [
                Some(RenderSettings { specialization: straight, ..phong }),
                Some(RenderSettings { glass_exit: back, ..phong }),
            ];
            return std::iter::once(None).chain(modes).chain(cheaper).collect();
        }
        match self.model {
            None => programs(),
            Some(m) => {
                let specular = m.split().1.unwrap_or(SpecularModel::CookTorrance);
                let modes = ShadingMode::ALL_MODES.map(|s| Some(RenderSettings::new(s, specular)));
                std::iter::once(None).chain(modes).collect()
            }
        }
    }
}

fn groups(plan: &Plan) -> Vec<Group> {
    let at = |name: &str, level| {
        scene_variants::at_level(&Scene::builtin(name).expect("analytic scenes are built in"), level)
    };
    // A group of `study` on the built-in scene `name` at `level` as it is.
    let plain = |study, name, level, size| Group { study, name, scene: at(name, level), level, size, model: None };
    let mut out = Vec::new();
    for &name in &plan.scenes {
        for &level in &plan.levels {
            out.extend(plan.resolutions.iter().map(|&size| plain(Study::Modes, name, level, size)));
        }
    }
    let (name, level, size) = plan.light_study;
    for &n in &plan.light_counts {
        let scene = scene_variants::with_point_lights(&at(name, level), n);
        out.push(Group { study: Study::Lights, name, scene, level, size, model: None });
    }
    let (name, level) = plan.resolution_study;
    out.extend(plan.study_resolutions.iter().map(|&size| plain(Study::Resolution, name, level, size)));
    let (name, level, size) = plan.model_study;
    for m in ModelChoice::ALL_CHOICES {
        // Without cast shadows, whose passes would dominate the models' own cost at small sizes.
        let mut scene = at(name, level);
        scene.apply(&shadelab_model::Overrides::for_model(m));
        scene.set_shadows(false);
        out.push(Group { study: Study::Models, name, scene, level, size, model: Some(m) });
    }
    let (name, level, size) = plan.texture_study;
    let scene = scene_variants::with_textured_floor(&at(name, level), level);
    out.push(Group { study: Study::Textures, name: TEXTURED_FLOOR, scene, level, size, model: None });
    let scene = scene_variants::with_material_maps(&at(name, level), level);
    out.push(Group { study: Study::Textures, name: MAPPED_FLOOR, scene, level, size, model: None });
    if let Some((name, level, size)) = plan.glass_study {
        out.push(plain(Study::Glass, name, level, size));
    }
    out
}

/// Run the study. `progress` is told each finished group.
pub fn run_plan(gpu: &Gpu, plan: &Plan, command: &str, mut progress: impl FnMut(&str)) -> Report {
    let start = std::time::Instant::now();
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    // The reference depends on the scene's lights and model, the size and the specular model,
    // not on the level of detail: computed once per combination. The lights are keyed by their
    // exact parameters: the study's ring of n point lights and a scene's own n lights differ.
    let mut references: HashMap<(String, String, (u32, u32), SpecularModel), ReferenceImage> = HashMap::new();
    let mut rows = Vec::new();
    for g in groups(plan) {
        let (w, h) = g.size;
        let mut gs = r.upload(&g.scene).expect("the study scenes are analytic shapes, far below any buffer limit");
        let target = Target::new(&gpu.device, w, h, target::HDR_FORMAT);
        let programs = g.programs();
        let draws: Vec<(Program, RenderSettings)> = programs
            .iter()
            .map(|s| match s {
                Some(s) => (Program::for_scene(&g.scene, s), *s),
                None => (Program::NullBaseline, RenderSettings::default()),
            })
            .collect();
        let mut samples = timer.interleaved(&mut r, &mut gs, &g.scene, &target, &draws, plan.frames, plan.warmup);
        let baseline_ms = median(&mut samples[0]);
        for (i, s) in programs.iter().enumerate() {
            let error = s.map(|s| {
                r.render(&mut gs, &g.scene, &target, &s);
                let image = target::read_back(&gpu.device, &gpu.queue, &target);
                let lit = format!("{:?} {:?}", g.scene.illumination, g.scene.lights);
                let key = (g.name.to_string(), lit, g.size, s.specular);
                let reference = references.entry(key).or_insert_with(|| render_reference(&g.scene, s.specular, w, h));
                image_error::compare(&image, reference).stats
            });
            let m = median(&mut samples[i]);
            rows.push(Row {
                study: g.study,
                scene: g.name.to_string(),
                level: g.level,
                triangles: g.scene.triangle_count(),
                width: w,
                height: h,
                lights: g.scene.lights.len(),
                shading: s.map(|s| s.shading),
                specular: s.map(|s| s.specular),
                model: s.map(|s| g.model.unwrap_or(ModelChoice::of(g.scene.illumination, s.specular))),
                frames: plan.frames,
                median_ms: m,
                p10_ms: quantile_sorted(&samples[i], 0.1),
                p90_ms: quantile_sorted(&samples[i], 0.9),
                ratio_to_baseline: m / baseline_ms,
                error,
                pareto: false,
                variant: s.map_or("", glass_variant),
            });
        }
        progress(&format!("{} {} L{} {}×{}", g.study.name(), g.name, g.level, w, h));
    }
    mark_pareto(&mut rows);
    Report {
        rows,
        device: gpu.describe(),
        time_source: timer.source(),
        plan: plan.clone(),
        command: command.to_string(),
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// How a glass study's settings draw the glass: straight through (its key without refraction),
/// with the back-face exit, or as the scene calls for ("").
fn glass_variant(s: RenderSettings) -> &'static str {
    use shadelab_model::lighting::transmission::GlassExit;
    match (s.specialization, s.glass_exit) {
        (Specialization::Fixed(_), _) => "straight through",
        (_, GlassExit::BackFaces) => "back-face exit",
        _ => "",
    }
}

/// Mark, within each (scene, resolution, specular model) of the modes study, the shaded rows no
/// other row beats in both time and RMSE. Specular models are kept apart: each is compared with
/// its own exact image, so their errors measure different things.
pub fn mark_pareto(rows: &mut [Row]) {
    let key = |r: &Row| (r.scene.clone(), r.width, r.height, r.specular);
    let mut keys: Vec<_> = rows.iter().filter(|r| r.study == Study::Modes && r.error.is_some()).map(key).collect();
    keys.dedup();
    for k in keys {
        let mut idx: Vec<usize> = (0..rows.len())
            .filter(|&i| rows[i].study == Study::Modes && rows[i].error.is_some() && key(&rows[i]) == k)
            .collect();
        idx.sort_by(|&a, &b| {
            rows[a].median_ms.total_cmp(&rows[b].median_ms).then(rmse(&rows[a]).total_cmp(&rmse(&rows[b])))
        });
        let mut best = f64::INFINITY;
        for i in idx {
            let e = rmse(&rows[i]);
            if e < best {
                rows[i].pareto = true;
                best = e;
            }
        }
    }
}

/// The CSV header; one line per row follows.
pub const CSV_HEADER: &str = "study,scene,level,triangles,width,height,lights,shading,specular,frames,median_ms,p10_ms,p90_ms,ratio_to_baseline,rmse,max_abs,flip_mean,share_off_1_255,pareto,model,variant";

pub fn csv(report: &Report) -> String {
    let mut s = String::from(CSV_HEADER);
    s.push('\n');
    for r in &report.rows {
        let (sh, sp) = match (r.shading, r.specular) {
            (Some(a), Some(b)) => (a.to_string(), b.to_string()),
            _ => ("baseline".into(), "none".into()),
        };
        let e = |f: fn(&ErrorStats) -> f64| r.error.as_ref().map_or(String::new(), |x| format!("{:.6e}", f(x)));
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{:.4},{:.4},{:.4},{:.4},{},{},{},{},{},{},{}",
            r.study.name(),
            r.scene,
            r.level,
            r.triangles,
            r.width,
            r.height,
            r.lights,
            sh,
            sp,
            r.frames,
            r.median_ms,
            r.p10_ms,
            r.p90_ms,
            r.ratio_to_baseline,
            e(|x| x.rmse),
            e(|x| x.max_abs),
            e(|x| x.flip_mean),
            e(|x| x.share_off),
            r.pareto,
            r.model.map_or("none".to_string(), |m| m.to_string()),
            r.variant
        );
    }
    s
}

/// Files a run writes into its output folder.
pub const OUTPUTS: [&str; 4] = ["accuracy.csv", "accuracy.md", "error-vs-time.png", "scaling.png"];

pub fn write_outputs(report: &Report, dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let paths: Vec<PathBuf> = OUTPUTS.iter().map(|f| dir.join(f)).collect();
    std::fs::write(&paths[0], csv(report)).with_context(|| format!("writing {}", paths[0].display()))?;
    std::fs::write(&paths[1], markdown(report)).with_context(|| format!("writing {}", paths[1].display()))?;
    plots::error_vs_time(report, &paths[2]).with_context(|| format!("writing {}", paths[2].display()))?;
    plots::scaling(report, &paths[3]).with_context(|| format!("writing {}", paths[3].display()))?;
    Ok(paths)
}

pub fn run(args: &cli::BenchAccuracyArgs) -> Result<(), Failure> {
    let mut plan = if args.quick { Plan::quick() } else { Plan::full() };
    if let Some(f) = args.frames {
        plan.frames = f as usize;
    }
    if let Some(w) = args.warmup {
        plan.warmup = w as usize;
    }
    // A folder that cannot be made is the user's to fix, and is found before minutes of work.
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Failure::Usage(format!("--out: cannot create folder '{}': {e}", args.out.display())))?;
    let gpu = crate::render::open_gpu()?;
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    let total = groups(&plan).len() as u64;
    let bar = indicatif::ProgressBar::new(total).with_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} groups  {msg}")
            .expect("static template")
            .progress_chars("=> "),
    );
    eprintln!("# shadelab bench accuracy — {} groups on {}", total, gpu.describe());
    let report = run_plan(&gpu, &plan, &command, |msg| {
        bar.set_message(msg.to_string());
        bar.inc(1);
    });
    bar.finish_and_clear();
    let paths = write_outputs(&report, &args.out)?;
    print!("{}", summary(&report));
    for p in paths {
        println!("wrote {}", p.display());
    }
    Ok(())
}
