//! `shadelab bench …`: measurements, reported with the device and the command; never asserted.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::params::NamedValue;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::timing::{FrameTimer, median, quantile_sorted};
use shadelab_render::{AdapterChoice, Gpu, RenderSettings, Renderer, Target};

pub fn run_render(args: &cli::BenchRenderArgs) -> Result<(), Failure> {
    let (width, height) = args.size.parse()?;
    let frames = cli::FRAMES.parse_u32(&args.frames)? as usize;
    let warmup = cli::WARMUP.parse_u32(&args.warmup)? as usize;
    let scene = cli::scene(&args.scene)?;
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let gs = r.upload(&scene).map_err(|e| Failure::Usage(format!("{}: {e}", args.scene.scene)))?;
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
    let (width, height) = args.size.parse()?;
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
        let gs = r.upload(scene).map_err(|e| Failure::Usage(format!("{}: {e}", scene.name)))?;
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

/// Frames timed after the first one by `bench load` (their median is reported).
const LOAD_STEADY_FRAMES: usize = 5;

/// The process's peak resident memory so far in KiB (`VmHWM` of `/proc/self/status`: the same
/// counter as `/usr/bin/time -v`'s "Maximum resident set size"), where Linux provides it.
fn peak_rss_kib() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

fn wait(gpu: &Gpu) {
    gpu.device.poll(wgpu::PollType::wait_indefinitely()).expect("device poll");
}

/// `shadelab bench load`: one scene, opened in phases, each timed on the wall clock (the GPU
/// work of a phase is waited for before its clock stops). The device is opened first, so its
/// start-up is not counted as the scene's.
pub fn run_load(args: &cli::BenchLoadArgs) -> Result<(), Failure> {
    use std::time::Instant;
    let (width, height) = args.size.parse()?;
    let gpu = Gpu::headless(AdapterChoice::from_env()).context("opening a GPU adapter")?;
    let rss_device = peak_rss_kib();
    let ms = |t: Instant| t.elapsed().as_secs_f64() * 1e3;

    let start = Instant::now();
    let shadelab_model::gltf_io::LoadedScene { scene, settings: file, .. } = cli::load(&args.scene)?;
    let load_ms = ms(start);
    let settings = args.mode.resolve(file)?;
    let (shading, specular) = (settings.shading, settings.specular);

    let t = Instant::now();
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let gs = r.upload(&scene).map_err(|e| Failure::Usage(format!("{}: {e}", args.scene.scene)))?;
    wait(&gpu);
    let upload_ms = ms(t);

    let target = Target::new(&gpu.device, width, height, shadelab_render::target::HDR_FORMAT);
    let t = Instant::now();
    r.render(&gs, &scene, &target, &settings);
    wait(&gpu);
    let first_frame_ms = ms(t);
    let to_first_frame_ms = ms(start);

    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let mut steady: Vec<f64> = (0..LOAD_STEADY_FRAMES).map(|_| timer.frame(&mut r, &gs, &target, &settings)).collect();
    let kib = |v: Option<u64>| v.map_or("unknown".to_string(), |k| format!("{:.0}", k as f64 / 1024.0));

    println!("# shadelab bench load — {}, {width}×{height}, {shading} shading, {specular} specular", args.scene.scene);
    println!("# device: {}; wall-clock phases, each waits for its GPU work", gpu.describe());
    println!("triangles {}", scene.triangle_count());
    println!("objects {}", scene.objects.len());
    println!("load_ms {load_ms:.1}");
    println!("upload_ms {upload_ms:.1}");
    println!("first_frame_ms {first_frame_ms:.1}");
    println!("to_first_frame_ms {to_first_frame_ms:.1}");
    println!("next_frame_ms {:.2} ({}, median of {LOAD_STEADY_FRAMES})", median(&mut steady), timer.source().label());
    println!("peak_rss_after_device_mib {}", kib(rss_device));
    println!("peak_rss_mib {}", kib(peak_rss_kib()));
    Ok(())
}

/// Triangle counts of `bench mesh --triangles`: each in [1, MAX_TRIANGLES].
const MESH_TRIANGLES: shadelab_model::params::ParamRange = shadelab_model::params::ParamRange {
    flag: "--triangles",
    symbol: "N",
    meaning: "triangle count (MAX_TRIANGLES)",
    min: 1.0,
    max: shadelab_model::gltf_io::MAX_TRIANGLES as f64,
};

/// One `bench load` run in a fresh process: its `key value` lines, and `/usr/bin/time -v`'s
/// peak and wall time when that tool is installed.
struct LoadRun {
    values: std::collections::HashMap<String, String>,
    /// The `# device:` line's adapter.
    device: String,
    time_v_peak_mib: Option<f64>,
}

const TIME_V: &str = "/usr/bin/time";

fn run_load_process(scene: &str, args: &cli::BenchMeshArgs) -> anyhow::Result<LoadRun> {
    let exe = std::env::current_exe().context("finding the shadelab binary")?;
    let with_time = std::path::Path::new(TIME_V).is_file();
    let mut cmd = if with_time {
        let mut c = std::process::Command::new(TIME_V);
        c.arg("-v").arg(&exe);
        c
    } else {
        std::process::Command::new(&exe)
    };
    cmd.args(["bench", "load", "--scene", scene, "--shading", &args.shading]).args([
        "--width",
        &args.size.width,
        "--height",
        &args.size.height,
    ]);
    let out = cmd.output().context("running shadelab bench load")?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        let line = stderr.lines().find(|l| l.starts_with("error")).unwrap_or("no error line");
        anyhow::bail!("bench load --scene {scene} failed ({}): {line}", out.status);
    }
    let values = stdout
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once(' '))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    let device = stdout
        .lines()
        .find_map(|l| l.strip_prefix("# device: "))
        .map_or("unknown".into(), |l| l.split(';').next().unwrap_or(l).to_string());
    let time_v_peak_mib = stderr
        .lines()
        .find_map(|l| l.trim().strip_prefix("Maximum resident set size (kbytes):"))
        .and_then(|v| v.trim().parse::<f64>().ok())
        .map(|k| k / 1024.0);
    Ok(LoadRun { values, device, time_v_peak_mib })
}

/// `shadelab bench mesh`: large generated meshes through `bench load`, one process each, beside a
/// baseline process on the built-in default scene (what the device and the program hold anyway).
pub fn run_mesh(args: &cli::BenchMeshArgs) -> Result<(), Failure> {
    let counts: Vec<usize> =
        args.triangles.split(',').map(|t| MESH_TRIANGLES.parse_u32(t).map(|n| n as usize)).collect::<Result<_, _>>()?;
    args.size.parse()?;
    ShadingMode::parse_named(&args.shading)?;
    std::fs::create_dir_all(&args.out).with_context(|| format!("creating {}", args.out.display()))?;
    let has_time = std::path::Path::new(TIME_V).is_file();
    if !has_time {
        eprintln!("{TIME_V} is not installed (Debian: apt-get install time): peak memory from /proc/self/status only");
    }
    eprintln!("baseline: bench load --scene default");
    let base = run_load_process("default", args)?;
    let field = |r: &LoadRun, k: &str| r.values.get(k).cloned().unwrap_or_else(|| "?".into());
    let peak = |r: &LoadRun| {
        r.time_v_peak_mib.or_else(|| r.values.get("peak_rss_mib").and_then(|v| v.parse().ok())).unwrap_or(f64::NAN)
    };
    println!(
        "# shadelab bench mesh — generated spheres {}, {}×{}, {} shading; one process per row",
        if args.without_normals { "without normals (crease-angle rule)" } else { "with normals" },
        args.size.width,
        args.size.height,
        args.shading
    );
    println!("# device: {}", base.device);
    println!(
        "# peak memory: {}; baseline (built-in default scene): {:.0} MiB",
        if has_time { "/usr/bin/time -v, maximum resident set size" } else { "VmHWM of /proc/self/status" },
        peak(&base)
    );
    println!(
        "| triangles | file MiB | load s | build + upload s | first frame s | open → first frame s | next frame ms | peak MiB | bytes/triangle over baseline |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in counts {
        let (glb, actual) = shadelab_model::gltf_io::synthetic::sphere_glb(n, !args.without_normals);
        let kind = if args.without_normals { "-without-normals" } else { "" };
        let path = args.out.join(format!("sphere-{actual}{kind}.glb"));
        std::fs::write(&path, &glb).with_context(|| format!("writing {}", path.display()))?;
        let file_mib = glb.len() as f64 / (1024.0 * 1024.0);
        drop(glb);
        eprintln!("{actual} triangles: bench load --scene {}", path.display());
        let run = run_load_process(&path.to_string_lossy(), args)?;
        let s = |k: &str| field(&run, k).parse::<f64>().map_or("?".into(), |v| format!("{:.2}", v / 1e3));
        let over = (peak(&run) - peak(&base)) * 1024.0 * 1024.0 / actual as f64;
        println!(
            "| {actual} | {file_mib:.1} | {} | {} | {} | {} | {} | {:.0} | {over:.0} |",
            s("load_ms"),
            s("upload_ms"),
            s("first_frame_ms"),
            s("to_first_frame_ms"),
            field(&run, "next_frame_ms").split(' ').next().unwrap_or("?"),
            peak(&run)
        );
    }
    Ok(())
}
