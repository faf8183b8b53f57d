//! The reference's bounding volume hierarchy (`reference/bvh.rs`, f64, median splits, one thread)
//! against the `obvhs` crate's compressed wide BVH (f32, PLOC), on the same triangles and the
//! same rays, in one run (docs/reference.md, "The hierarchy against a crate"): build time, bytes,
//! and rays a second for nearest hits on one thread, each the median of `--runs`; and how often
//! the two find the same triangle. Outside the workspace, so the crate is built only here:
//!
//!     cargo run --release --manifest-path studies/bvh/Cargo.toml -- [--triangles N]... [--file F]... [--rays N] [--runs N]

use glam::{DVec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::{Ray, RayHit};
use obvhs::triangle::Triangle;
use shadelab_model::gltf_io::{load_scene, load_scene_from_slice, synthetic};
use shadelab_model::mesh::TriangleMesh;
use shadelab_model::reference::MeshHierarchy;
use std::time::{Duration, Instant};

/// SplitMix64: the rays' random numbers, the same for both hierarchies.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Rays from a sphere around the mesh's box towards random points inside it: most meet the mesh.
fn rays(mesh: &TriangleMesh, n: usize) -> Vec<(DVec3, DVec3)> {
    let (lo, hi) =
        mesh.positions.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), p| (l.min(*p), h.max(*p)));
    let (centre, radius) = ((lo + hi) * 0.5, (hi - lo).length().max(1e-9));
    let mut rng = Rng(1);
    (0..n)
        .map(|_| {
            let z = 2.0 * rng.uniform() - 1.0;
            let phi = std::f64::consts::TAU * rng.uniform();
            let r = (1.0 - z * z).max(0.0).sqrt();
            let o = centre + DVec3::new(r * phi.cos(), r * phi.sin(), z) * radius;
            let target = lo + (hi - lo) * DVec3::new(rng.uniform(), rng.uniform(), rng.uniform());
            (o, (target - o).normalize())
        })
        .collect()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Milliseconds of `f`, the median of `runs`, and its last result.
fn timed<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut ms = Vec::new();
    let mut last = None;
    for _ in 0..runs {
        let start = Instant::now();
        last = Some(f());
        ms.push(start.elapsed().as_secs_f64() * 1e3);
    }
    (median(ms), last.expect("at least one run"))
}

fn v(p: DVec3) -> Vec3A {
    Vec3A::new(p.x as f32, p.y as f32, p.z as f32)
}

fn measure(name: &str, mesh: &TriangleMesh, n_rays: usize, runs: usize) {
    let n = mesh.triangle_count();
    if n == 0 {
        println!("| {name} | 0 | (no triangle meshes: its shapes are analytic) |  |  |  |  |");
        return;
    }
    let tris: Vec<Triangle> = (0..n)
        .map(|k| {
            let t = mesh.triangle(k);
            Triangle { v0: v(t[0]), v1: v(t[1]), v2: v(t[2]) }
        })
        .collect();
    let rays = rays(mesh, n_rays);
    let (ours_build, ours) = timed(runs, || MeshHierarchy::build(mesh));
    let (theirs_build, theirs) =
        timed(runs, || build_cwbvh_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default()));
    let theirs_bytes =
        theirs.nodes.len() * std::mem::size_of_val(&theirs.nodes[0]) + theirs.primitive_indices.len() * 4;
    let (ours_ms, ours_hits) = timed(runs, || rays.iter().map(|&(o, d)| ours.nearest(o, d)).collect::<Vec<_>>());
    let (theirs_ms, theirs_hits) = timed(runs, || {
        rays.iter()
            .map(|&(o, d)| {
                let mut hit = RayHit::none();
                let found = theirs.ray_traverse(Ray::new_inf(v(o), v(d)), &mut hit, |ray, id| {
                    tris[theirs.primitive_indices[id] as usize].intersect(ray)
                });
                found.then(|| (f64::from(hit.t), theirs.primitive_indices[hit.primitive_id as usize] as usize))
            })
            .collect::<Vec<_>>()
    });
    // The crate's walk with the reference's f64 triangles: its f32 ray only chooses the boxes.
    let (hybrid_ms, hybrid_hits) = timed(runs, || {
        rays.iter()
            .map(|&(o, d)| {
                let mut hit = RayHit::none();
                let mut best: Option<(f64, usize)> = None;
                theirs.ray_traverse(Ray::new_inf(v(o), v(d)), &mut hit, |_, id| {
                    let k = theirs.primitive_indices[id] as usize;
                    match ours.triangle_hit(k, o, d) {
                        Some(t) if best.is_none_or(|b| t < b.0 || (t == b.0 && k < b.1)) => {
                            best = Some((t, k));
                            // Rounded up, so that the walk keeps every box the f64 hit may tie with.
                            (t as f32).next_up()
                        }
                        _ => f32::INFINITY,
                    }
                });
                best
            })
            .collect::<Vec<_>>()
    });
    let met = ours_hits.iter().filter(|h| h.is_some()).count();
    let same = ours_hits.iter().zip(&theirs_hits).filter(|(a, b)| a.map(|h| h.1) == b.map(|h| h.1)).count();
    let mrays = |ms: f64| n_rays as f64 / (ms * 1e3);
    println!(
        "| {name} | {n} | reference | {ours_build:.0} | {:.1} | {:.1} | {:.2} |",
        ours.bytes() as f64 / 1048576.0,
        ours.bytes() as f64 / n as f64,
        mrays(ours_ms)
    );
    println!(
        "| {name} | {n} | obvhs CWBVH | {theirs_build:.0} | {:.1} | {:.1} | {:.2} |",
        theirs_bytes as f64 / 1048576.0,
        theirs_bytes as f64 / n as f64,
        mrays(theirs_ms)
    );
    println!(
        "| {name} | {n} | obvhs CWBVH, f64 triangles | {theirs_build:.0} | {:.1} | {:.1} | {:.2} |",
        theirs_bytes as f64 / 1048576.0,
        theirs_bytes as f64 / n as f64,
        mrays(hybrid_ms)
    );
    let same_hybrid = ours_hits.iter().zip(&hybrid_hits).filter(|(a, b)| a == b).count();
    println!(
        "|  |  | {met} of {n_rays} rays meet the mesh; obvhs finds another triangle for {} rays, with f64 triangles another hit (not bit for bit the same) for {} |  |  |  |  |",
        n_rays - same,
        n_rays - same_hybrid
    );
}

/// A bad argument: one line, and exit status 2.
fn usage(line: String) -> ! {
    eprintln!("error: {line} (studies/bvh [--triangles N]... [--file F]... [--rays N] [--runs N])");
    std::process::exit(2)
}

fn number(flag: &str, text: Option<String>) -> usize {
    match text.as_deref().map(str::parse::<usize>) {
        Some(Ok(n)) if n > 0 => n,
        _ => usage(format!("{flag} needs a whole number above 0, got {text:?}")),
    }
}

fn main() {
    let mut args = std::env::args().skip(1);
    let (mut counts, mut files, mut n_rays, mut runs) = (Vec::new(), Vec::new(), 1_000_000usize, 3usize);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--triangles" => counts.push(number("--triangles", args.next())),
            "--file" => files.push(args.next().unwrap_or_else(|| usage("--file needs a .gltf or .glb file".into()))),
            "--rays" => n_rays = number("--rays", args.next()),
            "--runs" => runs = number("--runs", args.next()),
            other => usage(format!("unknown option '{other}'")),
        }
    }
    if counts.is_empty() && files.is_empty() {
        counts.push(1_000_000);
    }
    println!("# the reference's hierarchy against obvhs {}, one thread, medians of {runs} runs, {n_rays} rays", "0.3");
    println!("| mesh | triangles | hierarchy | build ms | MiB | bytes a triangle | million rays a second |");
    println!("|---|---:|---|---:|---:|---:|---:|");
    for n in counts {
        let (glb, actual) = synthetic::sphere_glb(n, true);
        let scene = load_scene_from_slice(&glb).unwrap_or_else(|e| usage(e.to_string())).scene;
        measure(&format!("generated sphere ({actual})"), &scene.meshes[0], n_rays, runs);
    }
    for f in files {
        let scene = load_scene(std::path::Path::new(&f)).unwrap_or_else(|e| usage(e.to_string())).scene;
        let mut all = TriangleMesh::default();
        for m in scene.meshes.iter() {
            let base = all.positions.len() as u32;
            all.positions.extend(&m.positions);
            all.indices.extend(m.indices.iter().map(|t| t.map(|i| i + base)));
        }
        measure(&f, &all, n_rays, runs);
    }
}
