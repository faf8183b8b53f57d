//! `shadelab bench microfacet`: what each Cook–Torrance term costs against what it changes
//! (docs/microfacet.md). The default scene drawn with each combination of D, G and F,
//! and with glTF's whole set (its terms and the Fresnel-weighted diffuse), timed side by side against the null shader; each combination's f64 reference against the
//! chapter's (a different model, not an error) and the GPU against its own reference (the
//! error); maps of where one term's change lies; and Schlick's F against the exact factor per μ,
//! the metals' presets included (an approximation of the same quantity).

mod plot;

use crate::{Failure, cli};
use anyhow::Context;
use shadelab_model::lighting::microfacet::{self, Distribution, Fresnel, Masking, Microfacet};
use shadelab_model::params::NamedValue;
use shadelab_model::reference::{ReferenceImage, render_reference};
use shadelab_model::{Scene, ShadingMode, SpecularModel};
use shadelab_render::image_error::error_over;
use shadelab_render::timing::{FrameTimer, TimedDraw, median};
use shadelab_render::{Gpu, Program, RenderSettings, Renderer, Target};
use std::fmt::Write as _;

/// Steps of c = cos θ in Schlick's table (its largest gap is found to 1e-4 in c).
const SCHLICK_STEPS: usize = 10_000;

/// One combination of the terms on the default scene.
#[derive(Clone, Debug)]
pub struct ComboRow {
    pub terms: Microfacet,
    pub median_ms: f64,
    /// Median over the null shader's, drawn in the same run.
    pub ratio_to_null: f64,
    /// Mean and largest |reference(terms) − reference(chapter's)| over the objects' pixels and
    /// channels: what the choice changes in the model.
    pub mean_change: f64,
    pub max_change: f64,
    /// Mean |GPU − reference(terms)|: what the GPU adds to it.
    pub gpu_error: f64,
}

/// Schlick's F against the exact factor for one μ (one channel).
#[derive(Clone, Debug)]
pub struct SchlickRow {
    pub name: String,
    pub mu: f64,
    /// Largest |Schlick − exact| over c in [0, 1], and the angle of incidence where it is.
    pub max_error: f64,
    pub at_deg: f64,
    /// The gap averaged over the hemisphere of directions, cosine-weighted: ∫ |ΔF| 2c dc.
    pub mean_error: f64,
}

/// Every combination: D × G × F, the chapter's first.
pub fn combinations() -> Vec<Microfacet> {
    let mut out = Vec::new();
    for &(_, d) in Distribution::ALL {
        for &(_, g) in Masking::ALL {
            for &(_, f) in Fresnel::ALL {
                out.push(Microfacet { d, g, f, ..Microfacet::CHAPTER });
            }
        }
    }
    out
}

/// The study's rows: every combination, then glTF's set, whose only difference from the
/// combination before it is the Fresnel-weighted diffuse.
pub fn studied() -> Vec<Microfacet> {
    let mut out = combinations();
    out.push(Microfacet::GLTF);
    out
}

fn with_terms(scene: &Scene, terms: Microfacet) -> Scene {
    let mut s = scene.clone();
    s.materials.iter_mut().for_each(|m| m.microfacet = terms);
    s
}

/// Mean and largest |a − b| over `pixels` and channels.
fn change(a: &ReferenceImage, b: &ReferenceImage, pixels: &[(u32, u32)]) -> (f64, f64) {
    let (mut sum, mut max) = (0.0f64, 0.0f64);
    for &(x, y) in pixels {
        let (p, q) = (a.get(x, y), b.get(x, y));
        for c in 0..3 {
            let e = (p[c] - q[c]).abs();
            sum += e;
            max = max.max(e);
        }
    }
    (sum / (3 * pixels.len().max(1)) as f64, max)
}

/// The smallest 1, 2 or 5 × 10^k at or above `x` (a map's full scale).
fn nice_ceil(x: f64) -> f64 {
    let p = 10f64.powf(x.max(1e-12).log10().floor());
    [1.0, 2.0, 5.0, 10.0].iter().map(|k| k * p).find(|v| *v >= x).unwrap_or(10.0 * p)
}

/// The colour map of |a − b| (largest channel), white at `full`.
fn map(a: &ReferenceImage, b: &ReferenceImage, full: f64) -> Vec<u8> {
    let lut = shadelab_render::image_error::magma_scale();
    let (w, h) = (a.width, a.height);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .flat_map(|(x, y)| {
            let (p, q) = (a.get(x, y), b.get(x, y));
            let e = (0..3).map(|c| (p[c] - q[c]).abs()).fold(0.0, f64::max);
            lut[((e / full).clamp(0.0, 1.0) * (lut.len() - 1) as f64).round() as usize]
        })
        .collect()
}

/// The three single-term changes the maps show: (file stem, caption, the terms).
pub const MAPS: [(&str, &str, Microfacet); 3] = [
    (
        "microfacet-d-ggx-vs-beckmann",
        "GGX D against Beckmann D",
        Microfacet { d: Distribution::Ggx, ..Microfacet::CHAPTER },
    ),
    (
        "microfacet-g-smith-correlated-vs-v-groove",
        "height-correlated Smith G against the V-groove G",
        Microfacet { g: Masking::SmithCorrelated, ..Microfacet::CHAPTER },
    ),
    (
        "microfacet-f-schlick-vs-exact",
        "Schlick's F against the exact F",
        Microfacet { f: Fresnel::Schlick, ..Microfacet::CHAPTER },
    ),
];

/// One map of [`MAPS`]: black no change, white `full` or more.
pub struct MapImage {
    pub stem: &'static str,
    pub caption: &'static str,
    pub full: f64,
    pub pixels: Vec<u8>,
}

/// The [`studied`] terms on the default scene: timed side by side with the null shader, and each
/// reference against the chapter's; with the maps of [`MAPS`].
pub fn combos(
    gpu: &Gpu,
    (w, h): (u32, u32),
    frames: usize,
    warmup: usize,
) -> anyhow::Result<(Vec<ComboRow>, f64, Vec<MapImage>)> {
    let scene = Scene::builtin("default").expect("built in");
    let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let all = studied();
    let scenes: Vec<Scene> = all.iter().map(|t| with_terms(&scene, *t)).collect();
    let mut r = Renderer::new(&gpu.device, &gpu.queue);
    let mut gs = r.upload(&scene)?;
    let target = Target::new(&gpu.device, w, h, shadelab_render::target::HDR_FORMAT);
    let mut draws = vec![TimedDraw {
        upload: 0,
        scene: &scene,
        program: Program::NullBaseline,
        settings: RenderSettings::default(),
    }];
    draws.extend(scenes.iter().map(|s| TimedDraw {
        upload: 0,
        scene: s,
        program: Program::for_scene(s, &settings),
        settings,
    }));
    let timer = FrameTimer::new(&gpu.device, &gpu.queue);
    let mut samples = timer.interleaved_draws(&mut r, std::slice::from_mut(&mut gs), &target, &draws, frames, warmup);
    let times: Vec<f64> = samples.iter_mut().map(|s| median(s)).collect();
    let null_ms = times[0];
    let chapter = render_reference(&scene, SpecularModel::CookTorrance, w, h);
    let pixels: Vec<(u32, u32)> = (0..scene.objects.len()).flat_map(|i| chapter.interior(i)).collect();
    let (mut rows, mut maps) = (Vec::new(), Vec::new());
    for (i, (terms, s)) in all.iter().zip(&scenes).enumerate() {
        let reference = render_reference(s, SpecularModel::CookTorrance, w, h);
        let (mean_change, max_change) = change(&reference, &chapter, &pixels);
        r.render(&mut gs, s, &target, &settings);
        let img = shadelab_render::target::read_back(&gpu.device, &gpu.queue, &target);
        rows.push(ComboRow {
            terms: *terms,
            median_ms: times[i + 1],
            ratio_to_null: times[i + 1] / null_ms,
            mean_change,
            max_change,
            gpu_error: error_over(&img, &reference, &pixels).0,
        });
        if let Some((stem, caption, _)) = MAPS.iter().find(|(_, _, t)| t == terms) {
            let full = nice_ceil(max_change);
            maps.push(MapImage { stem, caption, full, pixels: map(&reference, &chapter, full) });
        }
    }
    Ok((rows, null_ms, maps))
}

/// Schlick's F against the exact factor at one μ.
pub fn schlick_row(name: &str, mu: f64) -> SchlickRow {
    let v = microfacet::fresnel_v_from_mu(mu);
    let (mut max, mut at, mut integral) = (0.0f64, 1.0f64, 0.0f64);
    let dc = 1.0 / SCHLICK_STEPS as f64;
    for i in 0..=SCHLICK_STEPS {
        let c = i as f64 * dc;
        let e = (microfacet::fresnel_schlick(c, v) - microfacet::fresnel_dielectric(c, v)).abs();
        if e > max {
            (max, at) = (e, c);
        }
        // The trapezoid rule on ∫ e·2c dc.
        let weight = if i == 0 || i == SCHLICK_STEPS { 0.5 } else { 1.0 };
        integral += weight * e * 2.0 * c * dc;
    }
    SchlickRow { name: name.into(), mu, max_error: max, at_deg: at.acos().to_degrees(), mean_error: integral }
}

/// Schlick's table: dielectric μ from 0.02 to 0.9, and each metal preset's three channels.
pub fn schlick_rows() -> Vec<SchlickRow> {
    let mut rows: Vec<SchlickRow> =
        [0.02, 0.04, 0.1, 0.2, 0.5, 0.9].iter().map(|&mu| schlick_row("dielectric", mu)).collect();
    for p in shadelab_model::presets::PRESETS.iter().filter(|p| p.metal) {
        for (c, channel) in ["R", "G", "B"].iter().enumerate() {
            rows.push(schlick_row(&format!("{} {channel}", p.name), p.mu[c]));
        }
    }
    rows
}

/// The furnace's roughnesses and view angles (degrees).
pub const FURNACE_M: [f64; 5] = [0.1, 0.3, 0.5, 0.7, 1.0];
pub const FURNACE_VIEW_DEG: [f64; 6] = [0.0, 30.0, 60.0, 75.0, 85.0, 89.0];

/// One D × G pair's albedo `E` (F = 1) at each roughness (rows) and view angle (columns), and
/// the same with the multiple-scattering compensation (its table's E put back, F0 = 1).
pub struct FurnaceRow {
    pub terms: Microfacet,
    pub albedo: Vec<Vec<f64>>,
    pub compensated: Vec<Vec<f64>>,
}

/// The white furnace over every D × G pair, roughness and view angle (f64, no GPU).
pub fn furnace_rows() -> Vec<FurnaceRow> {
    use shadelab_model::furnace::{FURNACE_SAMPLES, directional_albedo, pairs};
    use shadelab_model::lighting::{ms_table::ms_albedo, multiscatter::ms_compensation};
    let grid = |f: &dyn Fn(f64, f64) -> f64| -> Vec<Vec<f64>> {
        FURNACE_M.iter().map(|&m| FURNACE_VIEW_DEG.iter().map(|deg| f(m, deg.to_radians().cos())).collect()).collect()
    };
    pairs()
        .into_iter()
        .map(|terms| {
            let albedo = grid(&|m, c| directional_albedo(terms, m, c, FURNACE_SAMPLES / 2));
            // F0 = 1: a white furnace for the compensated lobe too.
            let compensated = grid(&|m, c| {
                directional_albedo(terms, m, c, FURNACE_SAMPLES / 2)
                    * ms_compensation(ms_albedo(terms, c, m), [1e9; 3])[0]
            });
            FurnaceRow { terms, albedo, compensated }
        })
        .collect()
}

/// The furnace's table, and the cells above 1 and the one that loses most, named.
fn furnace_markdown(s: &mut String, rows: &[FurnaceRow]) {
    let _ = writeln!(
        s,
        "\nThe white furnace: the lobe's directional albedo E = (1/π) ∫ D·G/(N·V) dω_L with F = 1 (1: no energy lost), per D / G, roughness m and view angle θ_v:\n"
    );
    let head: Vec<String> = FURNACE_VIEW_DEG.iter().map(|d| format!("θ_v = {d}°")).collect();
    let _ = writeln!(s, "| D / G | m | {} |", head.join(" | "));
    let _ = writeln!(s, "|---|---:|{}", "---:|".repeat(FURNACE_VIEW_DEG.len()));
    let (mut over, mut least) = (Vec::new(), (f64::INFINITY, String::new()));
    for r in rows {
        for (mi, m) in FURNACE_M.iter().enumerate() {
            let cells: Vec<String> = r.albedo[mi].iter().map(|e| format!("{e:.4}")).collect();
            let _ = writeln!(s, "| {} / {} | {m} | {} |", r.terms.d, r.terms.g, cells.join(" | "));
            for (vi, e) in r.albedo[mi].iter().enumerate() {
                let at = format!("{} / {} at m = {m}, θ_v = {}°", r.terms.d, r.terms.g, FURNACE_VIEW_DEG[vi]);
                if *e > 1.0 + FURNACE_TOLERANCE {
                    over.push(format!("{at} ({e:.4})"));
                }
                if *e < least.0 {
                    least = (*e, at);
                }
            }
        }
    }
    let _ = writeln!(
        s,
        "\nAbove 1 (more than {FURNACE_TOLERANCE} over): {}. Loses most: {} (E = {:.4}).",
        if over.is_empty() { "none".to_string() } else { over.join("; ") },
        least.1,
        least.0
    );
    let _ = writeln!(s, "\nWith the multiple-scattering compensation (F0 = 1), over the same grid:\n");
    let _ = writeln!(s, "| D / G | smallest E | largest E |");
    let _ = writeln!(s, "|---|---:|---:|");
    for r in rows {
        let all = r.compensated.iter().flatten();
        let (lo, hi) = all.fold((f64::INFINITY, 0.0f64), |(lo, hi), e| (lo.min(*e), hi.max(*e)));
        let _ = writeln!(s, "| {} / {} | {lo:.4} | {hi:.4} |", r.terms.d, r.terms.g);
    }
}

/// How far above 1 an albedo counts as gaining energy: the quadrature's error at
/// `FURNACE_SAMPLES / 2` per side (its test holds it to 2e-3 against an independent one).
const FURNACE_TOLERANCE: f64 = 2e-3;

pub fn markdown(
    rows: &[ComboRow],
    null_ms: f64,
    maps: &[MapImage],
    schlick: &[SchlickRow],
    furnace: &[FurnaceRow],
    device: &str,
    command: &str,
) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# What each microfacet term costs against what it changes\n\n    {command}\n\nDevice: {device}. The default scene, Phong shading, Cook–Torrance, every material with the terms of the row. GPU times are medians of frames drawn side by side (interleaved) with the null shader ({null_ms:.3} ms). *Change*: |f64 reference with these terms − f64 reference with the chapter's| over the objects' pixels (a different model, not an error). *GPU error*: |GPU − f64 reference with the same terms|.\n"
    );
    let _ = writeln!(
        s,
        "| D / G / F (+mix: the Fresnel-weighted diffuse) | median ms | × null | mean change | max change | GPU mean error |"
    );
    let _ = writeln!(s, "|---|---:|---:|---:|---:|---:|");
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {:.3} | {:.2} | {:.5} | {:.4} | {:.2e} |",
            r.terms, r.median_ms, r.ratio_to_null, r.mean_change, r.max_change, r.gpu_error
        );
    }
    let _ = writeln!(
        s,
        "\nWhere one term's change lies (|reference − the chapter's reference|, magma scale, white at the value given):\n"
    );
    for m in maps {
        let _ = writeln!(s, "- `{}.png`: {}, white at {}", m.stem, m.caption, m.full);
    }
    let _ = writeln!(
        s,
        "\nSchlick's F against the exact factor of the same v (an approximation of the same quantity), over the angle of incidence:\n"
    );
    let _ = writeln!(s, "| material | μ | max abs error | at θ (°) | cosine-weighted mean abs error |");
    let _ = writeln!(s, "|---|---:|---:|---:|---:|");
    for r in schlick {
        let _ =
            writeln!(s, "| {} | {:.3} | {:.4} | {:.1} | {:.5} |", r.name, r.mu, r.max_error, r.at_deg, r.mean_error);
    }
    furnace_markdown(&mut s, furnace);
    s
}

pub fn combos_csv(rows: &[ComboRow]) -> String {
    let mut s = String::from("d,g,f,fresnel_mix,median_ms,ratio_to_null,mean_change,max_change,gpu_mean_error\n");
    for r in rows {
        let t = r.terms;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{}",
            t.d, t.g, t.f, t.fresnel_mix, r.median_ms, r.ratio_to_null, r.mean_change, r.max_change, r.gpu_error
        );
    }
    s
}

pub fn schlick_csv(rows: &[SchlickRow]) -> String {
    let mut s = String::from("material,mu,max_abs_error,at_deg,mean_abs_error\n");
    for r in rows {
        let _ = writeln!(s, "{},{},{},{},{}", r.name, r.mu, r.max_error, r.at_deg, r.mean_error);
    }
    s
}

pub fn furnace_csv(rows: &[FurnaceRow]) -> String {
    let mut s = String::from("d,g,m,view_deg,albedo,albedo_compensated\n");
    for r in rows {
        for (mi, m) in FURNACE_M.iter().enumerate() {
            for (vi, deg) in FURNACE_VIEW_DEG.iter().enumerate() {
                let (e, c) = (r.albedo[mi][vi], r.compensated[mi][vi]);
                let _ = writeln!(s, "{},{},{m},{deg},{e},{c}", r.terms.d, r.terms.g);
            }
        }
    }
    s
}

/// `shadelab bench microfacet`.
pub fn run(args: &cli::BenchMicrofacetArgs) -> Result<(), Failure> {
    std::fs::create_dir_all(&args.output)
        .map_err(|e| Failure::Usage(format!("--output: cannot create folder '{}': {e}", args.output.display())))?;
    let gpu = crate::render::open_gpu()?;
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    let size = (args.width, args.height);
    let (frames, warmup) = args.frames.counts();
    let (rows, null_ms, maps) = combos(&gpu, size, frames, warmup)?;
    let schlick = schlick_rows();
    let furnace = furnace_rows();
    let md = markdown(&rows, null_ms, &maps, &schlick, &furnace, &gpu.describe(), &command);
    let mut paths = vec![
        super::write(&args.output, "microfacet.md", md.as_bytes())?,
        super::write(&args.output, "microfacet-combos.csv", combos_csv(&rows).as_bytes())?,
        super::write(&args.output, "microfacet-schlick.csv", schlick_csv(&schlick).as_bytes())?,
        super::write(&args.output, "microfacet-furnace.csv", furnace_csv(&furnace).as_bytes())?,
    ];
    let plot = args.output.join("microfacet-furnace.png");
    plot::furnace(&furnace, &FURNACE_M, &FURNACE_VIEW_DEG, &plot)?;
    paths.push(plot);
    for m in maps {
        let p = args.output.join(format!("{}.png", m.stem));
        image::RgbImage::from_raw(size.0, size.1, m.pixels)
            .context("map size")?
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schlicks_table_meets_the_exact_factor_at_its_ends_and_names_the_worst_angle() {
        let glass = schlick_row("glass", 0.04);
        // The model test's figure (lighting::microfacet): 0.0357 at c ≈ 0.088, θ ≈ 85°.
        assert!((glass.max_error - 0.0357).abs() < 5e-4 && (glass.at_deg - 85.0).abs() < 1.0, "{glass:?}");
        assert!(glass.mean_error > 0.0 && glass.mean_error < glass.max_error);
        // μ = 0 is no interface: the exact factor is 0 everywhere, Schlick's still rises as
        // (1 − c)⁵ to 1 at grazing.
        let none = schlick_row("none", 0.0);
        assert!((none.max_error - 1.0).abs() < 1e-9 && none.at_deg == 90.0, "{none:?}");
        let rows = schlick_rows();
        assert_eq!(rows.len(), 6 + 3 * shadelab_model::presets::PRESETS.iter().filter(|p| p.metal).count());
        // Every D × G × F of the term tables, the chapter's first; glTF's set after them.
        let count = Distribution::ALL.len() * Masking::ALL.len() * Fresnel::ALL.len();
        assert_eq!(combinations().len(), count);
        assert_eq!(combinations()[0], Microfacet::CHAPTER);
        assert_eq!(studied()[count], Microfacet::GLTF);
        assert_eq!(nice_ceil(0.0139), 0.02);
        assert_eq!(nice_ceil(0.3347), 0.5);
        assert_eq!(nice_ceil(0.001), 0.001);
    }
}
