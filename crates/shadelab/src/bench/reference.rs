//! `shadelab bench reference`: what the f64 reference costs on a scene (docs/reference.md). The
//! hierarchy of its meshes, built and measured as an image builds it, and the whole reference
//! image timed on every core and on one, each the median of `--runs`.

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::SpecularModel;
use shadelab_model::reference::{hierarchy_bytes, reference_threads, render_reference};
use shadelab_render::timing::median;

/// Milliseconds `f` takes, the median of `runs` runs.
fn timed(runs: u32, mut f: impl FnMut()) -> f64 {
    let mut ms: Vec<f64> = (0..runs)
        .map(|_| {
            let start = web_time::Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    median(&mut ms)
}

/// `shadelab bench reference`.
pub fn run(args: &cli::BenchReferenceArgs) -> Result<(), Failure> {
    let scene = cli::scene(&args.scene)?;
    let (w, h) = args.size.pixels();
    let triangles: usize = scene.meshes.iter().map(|m| m.triangle_count()).sum();
    let mut bytes = 0;
    let build_ms = timed(args.runs, || bytes = hierarchy_bytes(&scene));
    let image = |s: &shadelab_model::Scene| drop(render_reference(s, SpecularModel::CookTorrance, w, h));
    let all_ms = timed(args.runs, || image(&scene));
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().context("a one-thread pool")?;
    let one_ms = one.install(|| timed(args.runs, || image(&scene)));
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    println!("# shadelab bench reference — {w}×{h}, Cook–Torrance, medians of {} runs", args.runs);
    println!("#     {command}");
    println!(
        "| scene | mesh triangles | hierarchy build ms | hierarchy MB | bytes a triangle | reference ms, {} threads | reference ms, 1 thread | speed-up |",
        reference_threads()
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    let per = if triangles > 0 { bytes as f64 / triangles as f64 } else { 0.0 };
    println!(
        "| {} | {triangles} | {build_ms:.1} | {:.1} | {per:.1} | {all_ms:.1} | {one_ms:.1} | {:.2} |",
        args.scene.scene,
        bytes as f64 / 1e6,
        one_ms / all_ms
    );
    Ok(())
}
