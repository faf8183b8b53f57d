//! `shadelab bench glass`: what transparency costs against its accuracy (docs/transparency.md).
//! The `glass` scene drawn opaque, with its glass going straight through, with the analytic exit
//! and with the back-face exit, timed side by side and each compared with the reference's
//! Whitted tracer; then the chapter's absorption rule against the exact form on the absorbing
//! cylinder at a range of a·d, its error beside the time it saves. Writes a Markdown
//! report, a CSV per table and the rule's error maps.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::effects::Effect;
use shadelab_model::lighting::transmission::{AbsorptionChoice, GlassExit};
use shadelab_model::reference::render_reference;
use shadelab_model::{Scene, ShadingMode, SpecularModel};
use shadelab_render::image_error::error_over;
use shadelab_render::timing::{FrameTimer, TimedDraw, median};
use shadelab_render::{Gpu, LinearImage, Program, RenderSettings, Renderer, SceneGpu, Specialization, Target};
use std::fmt::Write as _;
use std::time::Instant;

/// The absorbing cylinder's largest a·d in the rule's rows: both sides of each threshold.
pub const OPTICAL_DEPTHS: [f64; 6] = [0.1, 0.19, 0.3, 0.49, 1.0, 2.5];
/// The optical depths whose error maps are written (just under each threshold).
const MAPS: [f64; 2] = [0.19, 0.49];
/// The error maps' white: |rule − exact| of this much light is the top of the colour scale.
const MAP_FULL_SCALE: f64 = 0.1;

/// One way of drawing the glass scene: its GPU time and its error against the reference on the
/// transparent objects' pixels.
#[derive(Clone, Debug)]
pub struct MethodRow {
    pub method: &'static str,
    pub median_ms: f64,
    pub p10_ms: f64,
    pub p90_ms: f64,
    /// Mean |GPU − reference| over the transparent objects' inside pixels and channels.
    pub mean_error: f64,
    /// Mean FLIP of the whole image against the reference.
    pub flip: f64,
}

/// The rule against the exact form at one optical depth.
#[derive(Clone, Debug)]
pub struct RuleRow {
    pub ad_max: f64,
    pub form: &'static str,
    /// Mean and largest |rule − exact| over the cylinder's inside pixels and channels.
    pub mean_error: f64,
    pub max_error: f64,
    pub exact_ms: f64,
    pub rule_ms: f64,
}

/// `scene` drawn with `settings` by `r` into `target`, read back.
fn draw(
    r: &mut Renderer,
    gpu: &Gpu,
    gs: &mut SceneGpu,
    scene: &Scene,
    target: &Target,
    settings: &RenderSettings,
) -> LinearImage {
    r.render(gs, scene, target, settings);
    shadelab_render::target::read_back(&gpu.device, &gpu.queue, target)
}

/// Time `draws` side by side: (median, p10, p90) ms each.
fn time(
    r: &mut Renderer,
    gpu: &Gpu,
    gs: &mut SceneGpu,
    target: &Target,
    draws: &[TimedDraw],
    frames: usize,
    warmup: usize,
) -> Vec<(f64, f64, f64)> {
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let mut samples = timer.interleaved_draws(r, std::slice::from_mut(gs), target, draws, frames, warmup);
    samples
        .iter_mut()
        .map(|s| {
            let m = median(s);
            s.sort_by(f64::total_cmp);
            let q = |f: f64| shadelab_render::timing::quantile_sorted(s, f);
            (m, q(0.1), q(0.9))
        })
        .collect()
}

/// The glass scene's ways of drawing, timed side by side and compared with the reference.
pub fn methods(gpu: &Gpu, (w, h): (u32, u32), frames: usize, warmup: usize) -> anyhow::Result<Vec<MethodRow>> {
    let scene = Scene::builtin("glass").expect("built in");
    let mut opaque = scene.clone();
    for m in &mut opaque.materials {
        m.transmission = 0.0;
    }
    let base = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let key = Program::for_scene(&scene, &base).effects();
    let straight = RenderSettings { specialization: Specialization::Fixed(key.without(Effect::Refraction)), ..base };
    let back = RenderSettings { glass_exit: GlassExit::BackFaces, ..base };
    let rows: [(&str, &Scene, RenderSettings); 4] = [
        ("opaque (τ = 0)", &opaque, base),
        ("glass, straight through (no refraction)", &scene, straight),
        ("glass, analytic exit", &scene, base),
        ("glass, back-face exit", &scene, back),
    ];
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(&scene)?;
    let target = Target::new(&gpu.device, w, h, shadelab_render::target::HDR_FORMAT);
    let draws: Vec<TimedDraw> = rows
        .iter()
        .map(|(_, s, settings)| TimedDraw {
            upload: 0,
            scene: s,
            program: Program::for_scene(s, settings),
            settings: *settings,
        })
        .collect();
    let times = time(&mut r, gpu, &mut gs, &target, &draws, frames, warmup);
    let started = Instant::now();
    let reference = render_reference(&scene, SpecularModel::CookTorrance, w, h);
    let reference_ms = started.elapsed().as_secs_f64() * 1e3;
    let glass: Vec<usize> = (0..scene.objects.len()).filter(|&i| scene.drawn_as_glass(i)).collect();
    let pixels: Vec<(u32, u32)> = glass.iter().flat_map(|&i| reference.interior(i)).collect();
    let mut out = Vec::new();
    for ((method, s, settings), (median_ms, p10_ms, p90_ms)) in rows.iter().zip(times) {
        let img = draw(&mut r, gpu, &mut gs, s, &target, settings);
        let flip = shadelab_render::image_error::compare(&img, &reference).stats.flip_mean;
        out.push(MethodRow {
            method,
            median_ms,
            p10_ms,
            p90_ms,
            mean_error: error_over(&img, &reference, &pixels).0,
            flip,
        });
    }
    out.push(MethodRow {
        method: "f64 Whitted reference (CPU, one thread)",
        median_ms: reference_ms,
        p10_ms: reference_ms,
        p90_ms: reference_ms,
        mean_error: 0.0,
        flip: 0.0,
    });
    Ok(out)
}

/// The absorbing cylinder at each of `depths` (its largest a·d): the rule against the exact
/// form, timed side by side; and the error map of the rule at the depths in `MAPS`.
pub fn rule(
    gpu: &Gpu,
    (w, h): (u32, u32),
    frames: usize,
    warmup: usize,
    depths: &[f64],
) -> anyhow::Result<(Vec<RuleRow>, Vec<(f64, Vec<u8>)>)> {
    let mut scene = Scene::builtin("glass").expect("built in");
    let cyl = scene.objects.iter().position(|o| o.name == "absorbing cylinder").expect("in the glass scene");
    let chord = shadelab_model::effects::longest_chord(&scene, cyl);
    let mi = scene.objects[cyl].material;
    let pixels = render_reference(&scene, SpecularModel::CookTorrance, w, h).interior(cyl);
    let base = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(&scene)?;
    let target = Target::new(&gpu.device, w, h, shadelab_render::target::HDR_FORMAT);
    let (mut rows, mut maps) = (Vec::new(), Vec::new());
    for &ad in depths {
        // The cylinder absorbs blue the most, red a fifth of it, as in the scene.
        scene.materials[mi].absorption = [0.2, 0.6, 1.0].map(|k| k * ad / chord);
        let exact = Scene { absorption: AbsorptionChoice::Exact, ..scene.clone() };
        let by_rule = Scene { absorption: AbsorptionChoice::Rule, ..scene.clone() };
        let draws: Vec<TimedDraw> = [&exact, &by_rule]
            .iter()
            .map(|s| TimedDraw { upload: 0, scene: s, program: Program::for_scene(s, &base), settings: base })
            .collect();
        let times = time(&mut r, gpu, &mut gs, &target, &draws, frames, warmup);
        let a = draw(&mut r, gpu, &mut gs, &exact, &target, &base);
        let b = draw(&mut r, gpu, &mut gs, &by_rule, &target, &base);
        let (mut sum, mut max) = (0.0f64, 0.0f64);
        for &(x, y) in &pixels {
            for c in 0..3 {
                let e = (a.get(x, y)[c] - b.get(x, y)[c]).abs() as f64;
                sum += e;
                max = max.max(e);
            }
        }
        let form = match shadelab_model::effects::absorption_form(&by_rule, cyl) {
            shadelab_model::lighting::transmission::AbsorptionForm::Exact => "exact e^(−a·d)",
            shadelab_model::lighting::transmission::AbsorptionForm::Linear => "linear 1 − a·d",
            shadelab_model::lighting::transmission::AbsorptionForm::Neglected => "neglected",
        };
        rows.push(RuleRow {
            ad_max: ad,
            form,
            mean_error: sum / (3 * pixels.len().max(1)) as f64,
            max_error: max,
            exact_ms: times[0].0,
            rule_ms: times[1].0,
        });
        if MAPS.contains(&ad) {
            let lut = shadelab_render::image_error::magma_scale();
            let map: Vec<u8> = a
                .pixels
                .iter()
                .zip(&b.pixels)
                .flat_map(|(p, q)| {
                    let e = (0..3).map(|c| (p[c] - q[c]).abs() as f64).fold(0.0, f64::max);
                    lut[((e / MAP_FULL_SCALE).clamp(0.0, 1.0) * (lut.len() - 1) as f64).round() as usize]
                })
                .collect();
            maps.push((ad, map));
        }
    }
    Ok((rows, maps))
}

pub fn markdown(methods: &[MethodRow], rules: &[RuleRow], device: &str, command: &str) -> String {
    let mut s = String::new();
    let opaque = methods.first().map_or(f64::NAN, |m| m.median_ms);
    let _ = writeln!(
        s,
        "# What transparency costs\n\n    {command}\n\nDevice: {device}. GPU times are medians of frames drawn side by side (interleaved).\n"
    );
    let _ = writeln!(s, "| method | median ms | p10–p90 ms | × opaque | mean abs error on the glass | mean FLIP |");
    let _ = writeln!(s, "|---|---:|---|---:|---:|---:|");
    for m in methods {
        let _ = writeln!(
            s,
            "| {} | {:.3} | {:.3}–{:.3} | {:.2} | {:.4} | {:.4} |",
            m.method,
            m.median_ms,
            m.p10_ms,
            m.p90_ms,
            m.median_ms / opaque,
            m.mean_error,
            m.flip
        );
    }
    let _ = writeln!(
        s,
        "\nThe chapter's absorption rule against the exact form, on the absorbing cylinder (a·d up to the value given, its longest chord):\n"
    );
    let _ = writeln!(
        s,
        "| a·d max | the rule's form | mean abs error | max abs error | exact ms | rule ms | rule / exact |"
    );
    let _ = writeln!(s, "|---:|---|---:|---:|---:|---:|---:|");
    for r in rules {
        let _ = writeln!(
            s,
            "| {} | {} | {:.4} | {:.4} | {:.3} | {:.3} | {:.3} |",
            r.ad_max,
            r.form,
            r.mean_error,
            r.max_error,
            r.exact_ms,
            r.rule_ms,
            r.rule_ms / r.exact_ms
        );
    }
    s
}

/// The methods' rows as CSV.
pub fn methods_csv(methods: &[MethodRow]) -> String {
    let mut s = String::from("method,median_ms,p10_ms,p90_ms,mean_abs_error_on_glass,mean_flip\n");
    for m in methods {
        let _ = writeln!(s, "{},{},{},{},{},{}", m.method, m.median_ms, m.p10_ms, m.p90_ms, m.mean_error, m.flip);
    }
    s
}

/// The rule's rows as CSV.
pub fn rule_csv(rules: &[RuleRow]) -> String {
    let mut s = String::from("ad_max,form,mean_abs_error,max_abs_error,exact_ms,rule_ms\n");
    for r in rules {
        let _ = writeln!(s, "{},{},{},{},{},{}", r.ad_max, r.form, r.mean_error, r.max_error, r.exact_ms, r.rule_ms);
    }
    s
}

/// `shadelab bench glass`.
pub fn run(args: &cli::BenchGlassArgs) -> Result<(), Failure> {
    std::fs::create_dir_all(&args.output)
        .map_err(|e| Failure::Usage(format!("--output: cannot create folder '{}': {e}", args.output.display())))?;
    let gpu = crate::render::open_gpu()?;
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    let size = (args.width, args.height);
    let (frames, warmup) = args.frames.counts();
    let methods = methods(&gpu, size, frames, warmup)?;
    let (rules, maps) = rule(&gpu, size, frames, warmup, &OPTICAL_DEPTHS)?;
    let md = markdown(&methods, &rules, &gpu.describe(), &command);
    let mut paths = vec![
        super::write(&args.output, "glass.md", md.as_bytes())?,
        super::write(&args.output, "glass-methods.csv", methods_csv(&methods).as_bytes())?,
        super::write(&args.output, "glass-rule.csv", rule_csv(&rules).as_bytes())?,
    ];
    for (ad, map) in maps {
        let p = args.output.join(format!("absorption-rule-error-{:03}.png", (ad * 100.0).round() as u32));
        image::RgbImage::from_raw(size.0, size.1, map)
            .context("error map size")?
            .save(&p)
            .with_context(|| format!("writing {}", p.display()))?;
        paths.push(p);
    }
    print!("{md}");
    for p in paths {
        println!("wrote {}", p.display());
    }
    Ok(())
}
