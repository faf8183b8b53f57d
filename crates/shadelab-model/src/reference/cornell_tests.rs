//! The path-traced reference against an independent renderer (docs/reference.md, "Checks
//! against another renderer"): the Cornell box as Mitsuba 3 renders it
//! (`studies/mitsuba/cornell.py` wrote `assets/mitsuba/mitsuba-cornell-N.exr`, 96×96, 4096 paths a
//! pixel, the light a black surface that emits from its front), where the same light is in the
//! same units.

use super::*;

const SIZE: u32 = 96;

/// Mitsuba's image of the Cornell box with `bounces` surface vertices a path.
fn mitsuba(bounces: u32) -> Vec<[f64; 3]> {
    let path = format!("{}/../../assets/mitsuba/mitsuba-cornell-{bounces}.exr", env!("CARGO_MANIFEST_DIR"));
    let img = image::open(&path).unwrap_or_else(|e| panic!("{path}: {e}")).to_rgb32f();
    assert_eq!(img.dimensions(), (SIZE, SIZE));
    img.pixels().map(|p| p.0.map(f64::from)).collect()
}

/// A pixel's neighbours differ from it by at most this share of its light, where it is compared:
/// Mitsuba averages over a pixel and shadelab takes its centre, so the two agree only where the
/// image is smooth across the pixel, not at an edge (one object's faces meet at an edge too).
const SMOOTH: f64 = 0.1;

/// Per channel, shadelab's mean over Mitsuba's on the pixels both see the same way, and the
/// largest relative difference of 12×12 blocks' means beyond four times its noise: the pixels whose 3×3 neighbourhood sees
/// one object and is smooth ([`SMOOTH`]), away from the light (whose own pixels
/// [`the_light_the_camera_sees_is_mitsubas`] compares).
/// `direct` (shadelab's noiseless direct light) decides where the image is smooth; also returns
/// how many blocks were compared.
fn agreement(direct: &ReferenceImage, ours: &ReferenceImage, theirs: &[[f64; 3]]) -> ([f64; 3], f64, usize) {
    let n = SIZE as usize;
    let lit = |i: usize| theirs[i].iter().copied().fold(0.0, f64::max) > 3.0;
    let keep: Vec<bool> = (0..n * n)
        .map(|i| {
            let (x, y) = (i % n, i / n);
            let inner = x > 0 && y > 0 && x + 1 < n && y + 1 < n;
            let sum = |j: usize| direct.pixels[j].iter().sum::<f64>();
            inner
                && direct.object[i].is_some()
                && (0..9).all(|k| {
                    let j = (y + k / 3 - 1) * n + x + k % 3 - 1;
                    direct.object[j] == direct.object[i] && !lit(j) && (sum(j) - sum(i)).abs() <= SMOOTH * sum(i)
                })
        })
        .collect();
    let mean = |img: &dyn Fn(usize) -> [f64; 3], c: usize, cells: &mut dyn Iterator<Item = usize>| {
        let (mut s, mut k) = (0.0, 0);
        for i in cells {
            s += img(i)[c];
            k += 1;
        }
        s / k.max(1) as f64
    };
    let ours_at = |i: usize| ours.pixels[i];
    let theirs_at = |i: usize| theirs[i];
    let ratio = std::array::from_fn(|c| {
        mean(&ours_at, c, &mut (0..n * n).filter(|&i| keep[i]))
            / mean(&theirs_at, c, &mut (0..n * n).filter(|&i| keep[i]))
    });
    let (mut worst, mut blocks) = (0.0f64, 0);
    for by in (0..n).step_by(12) {
        for bx in (0..n).step_by(12) {
            let cells: Vec<usize> = (0..144).map(|k| (by + k / 12) * n + bx + k % 12).filter(|&i| keep[i]).collect();
            if cells.len() < 100 {
                continue;
            }
            let total =
                |img: &dyn Fn(usize) -> [f64; 3]| (0..3).map(|c| mean(img, c, &mut cells.iter().copied())).sum::<f64>();
            let (a, b) = (total(&ours_at), total(&theirs_at));
            // The block's own noise: its mean's standard error, from the pixels' (0 for the direct
            // light); a difference within four of it is not measured.
            let var: f64 = cells.iter().filter_map(|&i| ours.std_error.get(i)).flatten().map(|e| e * e).sum();
            let noise = var.sqrt() / cells.len() as f64;
            worst = worst.max(((a - b).abs() - 4.0 * noise).max(0.0) / b);
            blocks += 1;
        }
    }
    (ratio, worst, blocks)
}

/// shadelab's path-traced image of the Cornell box with `paths`.
fn traced(paths: PathSettings) -> ReferenceImage {
    let scene = Scene::builtin("cornell").unwrap();
    let mut job = ReferenceJob::with_paths(&scene, SpecularModel::CookTorrance, SIZE, SIZE, paths).unwrap();
    job.step(SIZE);
    job.finish()
}

/// The direct light alone: shadelab's exact reference is Mitsuba's image within its falloff's
/// approximation of `1/d²` (under 0.25 %, `CORNELL_FALLOFF`) and Mitsuba's noise.
#[test]
fn the_cornell_box_direct_light_is_mitsubas() {
    let direct = traced(PathSettings { bounces: 1, spp: 1, seed: 1 });
    let (ratio, worst, blocks) = agreement(&direct, &direct, &mitsuba(1));
    assert!(blocks >= 15, "only {blocks} blocks compared");
    assert!(ratio.iter().all(|r| (0.997..1.002).contains(r)), "{ratio:?}");
    assert!(worst < 0.01, "a block differs by {worst}");
}

/// With light between surfaces, at 2, 3, 4 and 6 surface vertices: the light is a surface in both
/// renderers (a bounce that meets it ends there; `light_surfaces.rs`), and shadelab's path tracer
/// is Mitsuba's image within 0.5 % in the mean (measured at 128×128, 256 paths: 0.13–0.26 %
/// darker, inside the falloff's 0.25 %; before the light was a surface, 0.3 % brighter at 3
/// vertices and 0.65 % at 6), and each block within 2 % beyond its noise.
#[test]
fn the_cornell_box_with_bounces_is_mitsubas() {
    let direct = traced(PathSettings { bounces: 1, spp: 1, seed: 1 });
    for bounces in [2, 3, 4, 6] {
        let (ratio, worst, blocks) =
            agreement(&direct, &traced(PathSettings { bounces, spp: 64, seed: 1 }), &mitsuba(bounces));
        eprintln!("{bounces} vertices: mean ratio {ratio:?}, worst block {worst:.4} beyond its noise");
        assert!(blocks >= 15, "{bounces} vertices: only {blocks} blocks compared");
        assert!(ratio.iter().all(|r| (0.995..1.005).contains(r)), "{bounces} vertices: {ratio:?}");
        assert!(worst < 0.02, "{bounces} vertices: a block differs by {worst}");
    }
}

/// The camera sees the light as Mitsuba draws it: where a pixel and its neighbours are all on the
/// light, shadelab's truth is its radiance, Mitsuba's `(17, 12, 4)`, within 1e-3 (the chapter's
/// falloff `1/(1 + αd²)` stands for `1/d²` within `1/(αd²)`, about 1e-4 at the camera).
#[test]
fn the_light_the_camera_sees_is_mitsubas() {
    let ours = traced(PathSettings { bounces: 1, spp: 1, seed: 1 });
    let theirs = mitsuba(1);
    let n = SIZE as usize;
    let mut seen = 0;
    for y in 1..n - 1 {
        for x in 1..n - 1 {
            if !(0..9).all(|k| theirs[(y + k / 3 - 1) * n + x + k % 3 - 1][0] > 3.0) {
                continue;
            }
            let (a, b) = (ours.pixels[y * n + x], theirs[y * n + x]);
            for c in 0..3 {
                assert!((a[c] / b[c] - 1.0).abs() < 1e-3, "pixel ({x}, {y}): {a:?} against {b:?}");
            }
            seen += 1;
        }
    }
    assert!(seen >= 4, "only {seen} pixels wholly on the light");
}
