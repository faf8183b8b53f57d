//! `shadelab bench load`: what a scene file costs to open, phase by phase, with the process's
//! peak memory.

use crate::{Failure, cli};
use shadelab_render::timing::{FrameTimer, median};
use shadelab_render::{Gpu, Renderer, Target};

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
pub fn run(args: &cli::BenchLoadArgs) -> Result<(), Failure> {
    use std::time::Instant;
    let (width, height) = args.size.pixels();
    let gpu = crate::render::open_gpu()?;
    let rss_device = peak_rss_kib();
    let ms = |t: Instant| t.elapsed().as_secs_f64() * 1e3;

    let start = Instant::now();
    let mut loaded = cli::load(&args.scene)?;
    let load_ms = ms(start);
    let settings = args.mode.settle(&mut loaded, &args.scene)?;
    let scene = loaded.scene;
    let (shading, specular) = (settings.shading, settings.specular);

    let t = Instant::now();
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(&scene).map_err(|e| Failure::Usage(format!("{}: {e}", args.scene.scene)))?;
    wait(&gpu);
    let upload_ms = ms(t);

    let target = Target::new(&gpu.device, width, height, shadelab_render::target::HDR_FORMAT);
    let t = Instant::now();
    r.render(&mut gs, &scene, &target, &settings);
    wait(&gpu);
    let first_frame_ms = ms(t);
    let to_first_frame_ms = ms(start);

    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let program = shadelab_render::Program::for_scene(&scene, &settings);
    // Each steady frame draws its shadow maps, as a frame after a change does.
    let mut steady: Vec<f64> = (0..LOAD_STEADY_FRAMES)
        .map(|_| {
            gs.redraw_shadows();
            r.write_uniforms(&mut gs, &scene, &target, &settings);
            timer.frame(&mut r, &mut gs, &target, program)
        })
        .collect();
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
