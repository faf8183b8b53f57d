//! `shadelab bench shadows`: what shadow accuracy costs (docs/model.md §6, docs/area-lights.md).
//! One scene with every light's shadow map at each resolution × filter, beside the same frame
//! without shadows and the null-shader baseline, all interleaved frame by frame; each against the
//! f64 reference's exact shadows (image RMSE and the share of pixels whose lit/shadowed state
//! disagrees). A scene with area lights adds their other methods: PCSS at 8 and 32 taps, the
//! light as k = 1, 4, 16 point sources with a hard shadow each, and as the point light. Writes a
//! CSV, a Markdown table with the Pareto front of (time, RMSE), and a plot of both.

mod plot;
pub use plot::plot;

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::reference::{ReferenceImage, render_reference};
use shadelab_model::shadows::ShadowFilter;
use shadelab_model::{AreaSpecular, Scene};
use shadelab_render::image_error;
use shadelab_render::timing::{FrameTimer, TimeSource, TimedDraw, median, quantile_sorted};
use shadelab_render::{Gpu, LinearImage, Program, RenderSettings, Renderer, SceneGpu, Target, target};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Shadow-map sides of the full run (the model's whole range, `SHADOW_RESOLUTION`).
pub const RESOLUTIONS: [u32; 5] = [256, 512, 1024, 2048, 4096];
/// Sides of `--quick`: both ends and the middle.
pub const QUICK_RESOLUTIONS: [u32; 3] = [256, 1024, 4096];
/// Every filter, in the order of the table.
pub const FILTERS: [ShadowFilter; 4] =
    [ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Poisson, ShadowFilter::Pcss];
/// PCSS's other tap counts measured for a scene with area lights (the filter's rows take the
/// default `SHADOW_PCSS_TAPS`, 32).
pub const PCSS_TAP_COUNTS: [u32; 2] = [8, 16];
/// The k of the k-point-source rows (a scene with area lights).
pub const POINT_COUNTS: [u32; 3] = [1, 4, 16];

/// What one row measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Config {
    /// Every light casting at this map side with this filter.
    Shadows { resolution: u32, filter: ShadowFilter },
    /// The same with PCF and the directional lights' cascades off (one map fitted to the whole
    /// scene); measured only for a scene whose view calls for cascades.
    OneMap { resolution: u32 },
    /// Every area light drawn as its centre's point light with PCF (the chapter's one point
    /// source); measured only for a scene with area lights.
    PointLights { resolution: u32 },
    /// PCSS with `taps` taps per pass (a scene with area lights).
    PcssTaps { resolution: u32, taps: u32 },
    /// Every area light as `k` point sources, each with a PCF hard shadow from its own cube (a
    /// scene with area lights).
    Points { resolution: u32, k: u32 },
    /// PCSS with every area light's specular by LTC in place of its representative point (a
    /// scene with area lights).
    Ltc { resolution: u32 },
    /// The same frame with no light casting (no shadow pass).
    Off,
    /// `Program::NullBaseline`: the same geometry, a constant colour.
    Baseline,
}

impl Config {
    pub fn name(self) -> String {
        match self {
            Config::Shadows { resolution, filter } => format!("{resolution} {}", filter_name(filter)),
            Config::OneMap { resolution } => format!("{resolution} pcf, one map (no cascades)"),
            Config::PointLights { resolution } => format!("{resolution} pcf, area lights as point lights"),
            Config::PcssTaps { resolution, taps } => format!("{resolution} pcss, {taps} taps"),
            Config::Points { resolution, k } => {
                format!("{resolution} pcf, area lights as {k} point source{}", if k == 1 { "" } else { "s" })
            }
            Config::Ltc { resolution } => format!("{resolution} pcss, LTC specular"),
            Config::Off => "shadows off".into(),
            Config::Baseline => "null-shader baseline".into(),
        }
    }
}

pub fn filter_name(f: ShadowFilter) -> &'static str {
    match f {
        ShadowFilter::Hard => "hard",
        ShadowFilter::Pcf => "pcf",
        ShadowFilter::Poisson => "poisson",
        ShadowFilter::Pcss => "pcss",
    }
}

/// One measured row.
#[derive(Clone, Debug)]
pub struct Row {
    pub config: Config,
    /// The map side the GPU used (the memory budget may halve a requested 4096); `None` without maps.
    pub side: Option<u32>,
    pub median_ms: f64,
    pub p10_ms: f64,
    pub p90_ms: f64,
    pub ratio_to_baseline: f64,
    pub ratio_to_off: f64,
    /// RMSE against the reference (linear RGB); `None` for the baseline.
    pub rmse: Option<f64>,
    /// Share of pixels whose lit/shadowed state disagrees with the reference; `None` for the baseline.
    pub share_disagreeing: Option<f64>,
    /// On the Pareto front of (median time, RMSE): no other row is as fast and as accurate and
    /// better in one of them.
    pub pareto: bool,
}

/// Everything a run produced.
pub struct Report {
    pub rows: Vec<Row>,
    pub scene: String,
    pub size: (u32, u32),
    pub frames: usize,
    pub warmup: usize,
    pub device: String,
    pub time_source: TimeSource,
    pub command: String,
    pub seconds: f64,
}

/// The scene with every light casting at `resolution` with `filter`.
fn with_shadows(scene: &Scene, resolution: u32, filter: ShadowFilter) -> Scene {
    let mut s = scene.clone();
    for l in &mut s.lights {
        l.shadow.casts = true;
        l.shadow.resolution = resolution;
        l.shadow.filter = filter;
    }
    s
}

/// The scene with every light casting at `resolution` with PCF and no cascades.
fn one_map(scene: &Scene, resolution: u32) -> Scene {
    let mut s = with_shadows(scene, resolution, ShadowFilter::Pcf);
    for l in &mut s.lights {
        l.shadow.cascades = false;
    }
    s
}

/// The scene with every area light its centre's point light, casting at `resolution` with PCF.
fn as_point_lights(scene: &Scene, resolution: u32) -> Scene {
    let mut s = with_shadows(scene, resolution, ShadowFilter::Pcf);
    for l in s.lights.iter_mut().filter(|l| l.kind.is_area()) {
        l.set_kind(shadelab_model::LightKind::Point);
    }
    s
}

/// The scene with every area light as `k` point sources, casting at `resolution` with PCF.
fn as_points(scene: &Scene, resolution: u32, k: u32) -> Scene {
    let mut s = with_shadows(scene, resolution, ShadowFilter::Pcf);
    for l in s.lights.iter_mut().filter(|l| l.kind.is_area()) {
        l.area_points = k;
    }
    s
}

/// The scene with every light casting at `resolution` with PCSS of `taps` taps per pass.
/// The scene with every light casting at `resolution` with PCSS, every area light's specular by
/// LTC.
fn with_ltc(scene: &Scene, resolution: u32) -> Scene {
    let mut s = with_shadows(scene, resolution, ShadowFilter::Pcss);
    s.apply(&shadelab_model::Overrides { area_specular: Some(AreaSpecular::Ltc), ..Default::default() });
    s
}

fn with_pcss_taps(scene: &Scene, resolution: u32, taps: u32) -> Scene {
    let mut s = with_shadows(scene, resolution, ShadowFilter::Pcss);
    for l in &mut s.lights {
        l.shadow.pcss_taps = taps;
    }
    s
}

/// Mark the rows with an error that no other row beats in both median time and RMSE.
pub fn mark_pareto(rows: &mut [Row]) {
    let scored: Vec<(usize, f64, f64)> =
        rows.iter().enumerate().filter_map(|(i, r)| Some((i, r.median_ms, r.rmse?))).collect();
    for &(i, t, e) in &scored {
        let beaten = scored.iter().any(|&(j, u, f)| j != i && u <= t && f <= e && (u < t || f < e));
        rows[i].pareto = !beaten;
    }
}

/// Whether the scene's view gives its directional lights cascades (then the one-map rows are
/// measured beside them).
fn has_cascades(scene: &Scene) -> bool {
    scene.lights.iter().any(|l| l.kind.is_directional()) && shadelab_model::shadows::cascade_count(scene) > 1
}

/// Measure `scene` at `size` for every resolution × filter, shadows off and the baseline.
pub fn run_plan(
    gpu: &Gpu,
    scene: &Scene,
    resolutions: &[u32],
    size: (u32, u32),
    frames: usize,
    warmup: usize,
    command: &str,
) -> Result<Report, Failure> {
    let start = std::time::Instant::now();
    let settings = RenderSettings::default();
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let target = Target::new(&gpu.device, size.0, size.1, target::HDR_FORMAT);
    let (mut uploads, configs) = plan(&mut r, scene, resolutions)?;
    let program = |c: Config, s: &Scene| match c {
        Config::Baseline => Program::NullBaseline,
        _ => Program::for_scene(s, &settings),
    };
    // Interleaved frame by frame, each row with its own scene (its shadow settings).
    let draws: Vec<TimedDraw> =
        configs.iter().map(|(c, g, s)| TimedDraw { upload: *g, scene: s, program: program(*c, s), settings }).collect();
    let mut samples = timer.interleaved_draws(&mut r, &mut uploads, &target, &draws, frames, warmup);
    // The exact image, once: the reference's shadows do not depend on the map.
    let reference =
        render_reference(&with_shadows(scene, RESOLUTIONS[0], ShadowFilter::Pcf), settings.specular, size.0, size.1);
    let mut images = Vec::new();
    for (c, g, s) in &configs {
        let image = (*c != Config::Baseline).then(|| {
            r.render(&mut uploads[*g], s, &target, &settings);
            target::read_back(&gpu.device, &gpu.queue, &target)
        });
        images.push(image);
    }
    let off_image = images[1].clone().expect("the shadows-off row is rendered");
    // A row that draws the specular another way tells lit from shadowed against its own frame
    // without shadows (rendered once, untimed).
    let ltc_off = configs.iter().any(|(c, ..)| matches!(c, Config::Ltc { .. })).then(|| {
        let mut s = with_ltc(scene, RESOLUTIONS[0]);
        s.set_shadows(false);
        r.render(&mut uploads[0], &s, &target, &settings);
        target::read_back(&gpu.device, &gpu.queue, &target)
    });
    let baseline_ms = median(&mut samples[0]);
    let off_ms = median(&mut samples[1]);
    let mut rows = Vec::new();
    for (i, (c, g, _)) in configs.iter().enumerate() {
        let m = median(&mut samples[i]);
        let side = map_side(&r, c, &uploads[*g]);
        let off = match c {
            Config::Ltc { .. } => ltc_off.as_ref().unwrap_or(&off_image),
            _ => &off_image,
        };
        let (rmse, share) = shadow_errors(images[i].as_ref(), off, &reference);
        rows.push(Row {
            config: *c,
            side,
            median_ms: m,
            p10_ms: quantile_sorted(&samples[i], 0.1),
            p90_ms: quantile_sorted(&samples[i], 0.9),
            ratio_to_baseline: m / baseline_ms,
            ratio_to_off: m / off_ms,
            rmse,
            share_disagreeing: share,
            pareto: false,
        });
    }
    mark_pareto(&mut rows);
    // Shadow rows first (resolution, then filter), then shadows off, then the baseline.
    rows.rotate_left(2);
    let n = rows.len();
    rows.swap(n - 2, n - 1);
    Ok(Report {
        rows,
        scene: scene.name.clone(),
        size,
        frames,
        warmup,
        device: gpu.describe(),
        time_source: timer.source(),
        command: command.to_string(),
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// The uploads (one per map side and light form) and every row's config, upload index and scene.
#[allow(clippy::type_complexity)]
fn plan(
    r: &mut Renderer,
    scene: &Scene,
    resolutions: &[u32],
) -> Result<(Vec<SceneGpu>, Vec<(Config, usize, Scene)>), Failure> {
    let upload = |r: &mut Renderer, s: &Scene| r.upload(s).map_err(|e| Failure::Usage(format!("{}: {e}", scene.name)));
    // One upload per resolution keeps each map array allocated once: a filter is only a uniform,
    // a new side would reallocate the maps between interleaved frames.
    let mut off_scene = scene.clone();
    off_scene.set_shadows(false);
    let mut uploads: Vec<SceneGpu> = vec![upload(&mut *r, &off_scene)?];
    let mut configs: Vec<(Config, usize, Scene)> =
        vec![(Config::Baseline, 0, off_scene.clone()), (Config::Off, 0, off_scene.clone())];
    for &resolution in resolutions {
        uploads.push(upload(&mut *r, &with_shadows(scene, resolution, ShadowFilter::Pcf))?);
        let filters_upload = uploads.len() - 1;
        for filter in FILTERS {
            configs.push((
                Config::Shadows { resolution, filter },
                uploads.len() - 1,
                with_shadows(scene, resolution, filter),
            ));
        }
        if has_cascades(scene) {
            uploads.push(upload(&mut *r, &one_map(scene, resolution))?);
            configs.push((Config::OneMap { resolution }, uploads.len() - 1, one_map(scene, resolution)));
        }
        if scene.lights.iter().any(|l| l.kind.is_area()) {
            let points = as_point_lights(scene, resolution);
            uploads.push(upload(&mut *r, &points)?);
            configs.push((Config::PointLights { resolution }, uploads.len() - 1, points));
            // Tap counts and the specular's method are uniforms: they share the filters' upload
            // (the same maps).
            for taps in PCSS_TAP_COUNTS {
                let s = with_pcss_taps(scene, resolution, taps);
                configs.push((Config::PcssTaps { resolution, taps }, filters_upload, s));
            }
            configs.push((Config::Ltc { resolution }, filters_upload, with_ltc(scene, resolution)));
            for k in POINT_COUNTS {
                let points = as_points(scene, resolution, k);
                uploads.push(upload(&mut *r, &points)?);
                configs.push((Config::Points { resolution, k }, uploads.len() - 1, points));
            }
        }
    }
    Ok((uploads, configs))
}

/// The largest shadow-map side the row's upload drew with; `None` for a row without maps.
fn map_side(r: &Renderer, c: &Config, gpu_scene: &SceneGpu) -> Option<u32> {
    match c {
        Config::Shadows { .. }
        | Config::OneMap { .. }
        | Config::PointLights { .. }
        | Config::PcssTaps { .. }
        | Config::Points { .. }
        | Config::Ltc { .. } => {
            r.shadow_plan(gpu_scene).and_then(|p| p.lights.iter().flatten().map(|l| l.resolution).max())
        }
        _ => None,
    }
}

/// A row's image RMSE and share of pixels disagreeing in shadow; `None`s for a row not rendered.
fn shadow_errors(
    image: Option<&LinearImage>,
    off_image: &LinearImage,
    reference: &ReferenceImage,
) -> (Option<f64>, Option<f64>) {
    match image {
        Some(img) => (
            Some(image_error::compare(img, reference).stats.rmse),
            Some(image_error::shadow_disagreement(img, off_image, reference).stats.share_disagreeing),
        ),
        None => (None, None),
    }
}

/// The CSV header; one line per row follows (empty fields where a row has no value).
pub const CSV_HEADER: &str = "config,resolution,map_side,filter,frames,median_ms,p10_ms,p90_ms,ratio_to_baseline,ratio_to_off,rmse,share_disagreeing,pcss_taps,points,pareto";

pub fn csv(report: &Report) -> String {
    let mut s = String::from(CSV_HEADER);
    s.push('\n');
    for r in &report.rows {
        let (kind, res, filter) = match r.config {
            Config::Shadows { resolution, filter } => ("shadows", resolution.to_string(), filter_name(filter)),
            Config::OneMap { resolution } => ("one-map", resolution.to_string(), "pcf"),
            Config::PointLights { resolution } => ("point-lights", resolution.to_string(), "pcf"),
            Config::PcssTaps { resolution, .. } => ("pcss-taps", resolution.to_string(), "pcss"),
            Config::Points { resolution, .. } => ("points", resolution.to_string(), "pcf"),
            Config::Ltc { resolution } => ("ltc", resolution.to_string(), "pcss"),
            Config::Off => ("off", String::new(), ""),
            Config::Baseline => ("baseline", String::new(), ""),
        };
        let (taps, points) = match r.config {
            Config::Shadows { filter: ShadowFilter::Pcss, .. } => {
                (shadelab_model::shadows::SHADOW_PCSS_TAPS.to_string(), String::new())
            }
            Config::PcssTaps { taps, .. } => (taps.to_string(), String::new()),
            Config::Ltc { .. } => (shadelab_model::shadows::SHADOW_PCSS_TAPS.to_string(), String::new()),
            Config::Points { k, .. } => (String::new(), k.to_string()),
            _ => (String::new(), String::new()),
        };
        let opt = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.6e}"));
        let _ = writeln!(
            s,
            "{kind},{res},{},{filter},{},{:.4},{:.4},{:.4},{:.4},{:.4},{},{},{taps},{points},{}",
            r.side.map_or(String::new(), |v| v.to_string()),
            report.frames,
            r.median_ms,
            r.p10_ms,
            r.p90_ms,
            r.ratio_to_baseline,
            r.ratio_to_off,
            opt(r.rmse),
            opt(r.share_disagreeing),
            r.pareto
        );
    }
    s
}

/// The Markdown table with the command, device and time source above it.
pub fn markdown(report: &Report) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# What shadow accuracy costs — `{}`\n", report.command);
    let _ = writeln!(
        s,
        "Scene '{}', {}×{}, Phong shading with Cook–Torrance specular. Device: {}. Time: {}, median of {} frames after {} warm-up, every row interleaved frame by frame. Error: against the f64 ray-cast reference with exact shadow rays. Run took {:.0} s.\n",
        report.scene,
        report.size.0,
        report.size.1,
        report.device,
        report.time_source.label(),
        report.frames,
        report.warmup,
        report.seconds
    );
    let _ = writeln!(
        s,
        "Map side: what the GPU used (every layer fits in `SHADOW_MAP_BUDGET_BYTES`, so a request may be halved). ×base: over the null-shader baseline; ×off: over the same frame without shadows. Disagree: share of pixels lit on one side and in a cast shadow on the other. Pareto: no other row is both as fast and as accurate (RMSE).\n"
    );
    let _ = writeln!(s, "| shadows | map side | median ms | p10–p90 ms | ×base | ×off | RMSE | disagree | Pareto |");
    let _ = writeln!(s, "|---|---:|---:|---|---:|---:|---:|---:|:---:|");
    for r in &report.rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:.3} | {:.3}–{:.3} | {:.2} | {:.2} | {} | {} | {} |",
            r.config.name(),
            r.side.map_or(String::new(), |v| v.to_string()),
            r.median_ms,
            r.p10_ms,
            r.p90_ms,
            r.ratio_to_baseline,
            r.ratio_to_off,
            r.rmse.map_or(String::new(), |v| format!("{v:.3e}")),
            r.share_disagreeing.map_or(String::new(), |v| format!("{:.3} %", v * 100.0)),
            if r.pareto { "●" } else { "" },
        );
    }
    s
}

/// Files a run writes into its output folder.
pub const OUTPUTS: [&str; 3] = ["shadows.csv", "shadows.md", "shadows.png"];

pub fn write_outputs(report: &Report, dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let paths: Vec<PathBuf> = OUTPUTS.iter().map(|f| dir.join(f)).collect();
    std::fs::write(&paths[0], csv(report)).with_context(|| format!("writing {}", paths[0].display()))?;
    std::fs::write(&paths[1], markdown(report)).with_context(|| format!("writing {}", paths[1].display()))?;
    plot(report, &paths[2]).with_context(|| format!("writing {}", paths[2].display()))?;
    Ok(paths)
}

/// `shadelab bench shadows`.
pub fn run(args: &cli::BenchShadowsArgs) -> Result<(), Failure> {
    let resolutions: &[u32] = if args.quick { &QUICK_RESOLUTIONS } else { &RESOLUTIONS };
    let frames = args.frames.unwrap_or(if args.quick { 5 } else { 30 }) as usize;
    let warmup = args.warmup.unwrap_or(if args.quick { 1 } else { 3 }) as usize;
    let scene = cli::scene(&cli::SceneArgs { scene: args.scene.clone(), ..cli::SceneArgs::default() })?;
    // A folder that cannot be made is the user's to fix, and is found before the work.
    std::fs::create_dir_all(&args.output)
        .map_err(|e| Failure::Usage(format!("--output: cannot create folder '{}': {e}", args.output.display())))?;
    let gpu = crate::render::open_gpu()?;
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    eprintln!("# shadelab bench shadows — scene '{}' on {}", scene.name, gpu.describe());
    let report = run_plan(&gpu, &scene, resolutions, args.size.pixels(), frames, warmup, &command)?;
    let paths = write_outputs(&report, &args.output)?;
    print!("{}", markdown(&report));
    for p in paths {
        println!("wrote {}", p.display());
    }
    Ok(())
}
