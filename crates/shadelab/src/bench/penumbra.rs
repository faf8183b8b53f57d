//! `shadelab bench penumbra`: the 10–90 % width of the `penumbra` scene's soft shadow on the
//! ground as its plate rises, against the similar-triangles prediction w = size·h/(H − h)
//! (docs/area-lights.md): the f64 reference (the light's integral over 64² cells with binary
//! visibility against the plate), PCSS, the light as 16 point sources with a hard shadow each,
//! and PCF. Writes a CSV, a Markdown table and a plot of width against height.

use crate::{Failure, cli};
use anyhow::Context;
use glam::DVec3;
use plotters::prelude::*;
use shadelab_model::lighting::area::area_irradiance_quadrature;
use shadelab_model::scene::{PENUMBRA_LIGHT_HEIGHT, PENUMBRA_LIGHT_SIZE, PENUMBRA_PLATE_HALF, Scene, penumbra_scene};
use shadelab_model::shadows::ShadowFilter;
use shadelab_model::{ShadingMode, SpecularModel};
use shadelab_render::{Gpu, RenderSettings, render_image};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The plate's heights above the ground, metres.
pub const HEIGHTS: [f64; 4] = [0.1, 0.25, 0.5, 1.0];
/// Cells a side of the reference's quadrature over the light.
pub const REFERENCE_CELLS: usize = 64;
/// Point sources of the converging method's row.
pub const POINTS: u32 = 16;
/// The view spans 1 m of ground: this many pixels a side make 1.25 mm a pixel.
pub const SIDE: u32 = 800;

/// One height's widths, metres; `None` where a profile does not cross both 10 % and 90 %.
#[derive(Clone, Copy, Debug)]
pub struct WidthRow {
    pub plate_h: f64,
    /// The similar triangles' full width w = size·h/(H − h).
    pub predicted: f64,
    pub reference: Option<f64>,
    pub pcss: Option<f64>,
    pub points: Option<f64>,
    pub pcf: Option<f64>,
}

impl WidthRow {
    /// The measured widths in the tables' order: reference, PCSS, 16 point sources, PCF.
    fn measured(&self) -> [Option<f64>; 4] {
        [self.reference, self.pcss, self.points, self.pcf]
    }
}

/// The `penumbra` scene's plate at `plate_h` seen from straight above through an orthographic
/// camera whose view spans x ∈ [0.3, 1.3] around its shadow's +x edge, without ambient light, so
/// the shadowed over the unshadowed image is the light's visibility V.
pub fn top_view(plate_h: f64) -> Scene {
    let mut scene = penumbra_scene(plate_h);
    scene.ambient = [0.0; 3];
    scene.camera.eye = DVec3::new(0.8, 6.0, 0.0);
    scene.camera.target = DVec3::new(0.8, 0.0, 0.0);
    scene.camera.up = DVec3::NEG_Z;
    scene.camera.orthographic = Some(0.5);
    scene
}

/// Width between the 10 % and 90 % crossings of a shadow profile `v` sampled every `step` along
/// x, rising from shadow to light; `None` when it does not cross both.
pub fn width_10_90(v: &[f64], step: f64) -> Option<f64> {
    let cross = |level: f64| {
        let i = v.windows(2).position(|w| w[0] < level && w[1] >= level)?;
        Some((i as f64 + (level - v[i]) / (v[i + 1] - v[i])) * step)
    };
    Some(cross(0.9)? - cross(0.1)?)
}

/// Measure every height of `heights` at `side`² pixels.
pub fn measure(gpu: &Gpu, heights: &[f64], side: u32) -> anyhow::Result<Vec<WidthRow>> {
    let step = 1.0 / side as f64;
    let (top, size, half) = (PENUMBRA_LIGHT_HEIGHT, PENUMBRA_LIGHT_SIZE, PENUMBRA_PLATE_HALF);
    let settings = RenderSettings::new(ShadingMode::Phong, SpecularModel::CookTorrance);
    let rows = (side / 2 - 4)..(side / 2 + 5);
    let mut out = Vec::new();
    for &plate_h in heights {
        let mut scene = top_view(plate_h);
        let light = scene.lights[0].area_light().context("the penumbra scene's light is an area light")?;
        // The reference along the view's middle row: pixel centres at x = 0.3 + (i + ½)/side.
        let blocked = |p: DVec3, q: DVec3| {
            let c = p + (q - p) * (plate_h / q.y);
            !(c.x.abs() <= half && c.z.abs() <= half)
        };
        let reference: Vec<f64> = (0..side)
            .map(|i| {
                let p = DVec3::new(0.3 + (i as f64 + 0.5) * step, 0.0, 0.0);
                let clear = area_irradiance_quadrature(&light, p, DVec3::Y, REFERENCE_CELLS, &|_, _| true);
                area_irradiance_quadrature(&light, p, DVec3::Y, REFERENCE_CELLS, &blocked) / clear
            })
            .collect();
        let mut gpu_width = |filter: ShadowFilter, points: u32| -> anyhow::Result<Option<f64>> {
            scene.lights[0].shadow.filter = filter;
            scene.lights[0].area_points = points;
            scene.set_shadows(true);
            let on = render_image(gpu, &scene, side, side, &settings)?;
            scene.set_shadows(false);
            let off = render_image(gpu, &scene, side, side, &settings)?;
            // V per pixel, averaged over nine rows about the middle (the PCSS taps turn per pixel).
            let v: Vec<f64> = (0..side)
                .map(|x| {
                    rows.clone().map(|y| (on.get(x, y)[0] / off.get(x, y)[0]) as f64).sum::<f64>() / rows.len() as f64
                })
                .collect();
            Ok(width_10_90(&v, step))
        };
        out.push(WidthRow {
            plate_h,
            predicted: size * plate_h / (top - plate_h),
            reference: width_10_90(&reference, step),
            pcss: gpu_width(ShadowFilter::Pcss, 0)?,
            points: gpu_width(ShadowFilter::Pcf, POINTS)?,
            pcf: gpu_width(ShadowFilter::Pcf, 0)?,
        });
    }
    Ok(out)
}

fn cell(v: Option<f64>) -> String {
    v.map_or("—".into(), |x| format!("{x:.4}"))
}

/// The CSV header; one line per height follows (empty where a profile does not cross).
pub const CSV_HEADER: &str = "plate_h,predicted,predicted_10_90,reference,pcss,points16,pcf";

pub fn csv(rows: &[WidthRow]) -> String {
    let mut s = format!("{CSV_HEADER}\n");
    let opt = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.6}"));
    for r in rows {
        let measured = r.measured().map(opt).join(",");
        let _ = writeln!(s, "{},{:.6},{:.6},{measured}", r.plate_h, r.predicted, 0.8 * r.predicted);
    }
    s
}

/// The table with the command and device above it.
pub fn markdown(rows: &[WidthRow], device: &str, command: &str) -> String {
    let mut s = format!("# Penumbra width against the similar triangles — `{command}`\n\n");
    let _ = writeln!(
        s,
        "Scene 'penumbra' from straight above, {SIDE} px a metre. Device: {device}. 10–90 % widths in metres; a square light's ramp spans 0.8·w of the predicted w.\n"
    );
    s += "| plate height h (m) | predicted w | 0.8·w | reference | PCSS | 16 point sources | PCF |\n";
    s += "|---:|---:|---:|---:|---:|---:|---:|\n";
    for r in rows {
        let measured = r.measured().map(cell).join(" | ");
        let _ = writeln!(s, "| {:.2} | {:.4} | {:.4} | {measured} |", r.plate_h, r.predicted, 0.8 * r.predicted);
    }
    s
}

/// Width against height: the prediction's 0.8·w as a dashed line, each method's points joined.
pub fn plot(rows: &[WidthRow], device: &str, path: &Path) -> anyhow::Result<()> {
    use crate::plots::{draw_legend, plot_err, register_font, save};
    register_font();
    let size = (1000u32, 700u32);
    let mut buf = vec![0u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let h_max = rows.iter().map(|r| r.plate_h).fold(0.0, f64::max) * 1.05;
        let w_max = rows
            .iter()
            .flat_map(|r| [Some(0.8 * r.predicted), r.reference, r.pcss, r.points, r.pcf])
            .flatten()
            .fold(0.0, f64::max)
            * 1.1;
        let mut chart = ChartBuilder::on(&root)
            .caption(format!("Penumbra 10–90 % width against the plate's height: {device}"), ("sans-serif", 18))
            .margin(14)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(0.0..h_max, 0.0..w_max)
            .map_err(plot_err)?;
        chart
            .configure_mesh()
            .x_desc("plate height above the ground h, m")
            .y_desc("10–90 % width on the ground, m")
            .draw()
            .map_err(plot_err)?;
        // The prediction as a smooth curve: 0.8·size·h/(H − h).
        let curve: Vec<(f64, f64)> = (0..=100)
            .map(|i| i as f64 / 100.0 * h_max)
            .map(|h| (h, 0.8 * PENUMBRA_LIGHT_SIZE * h / (PENUMBRA_LIGHT_HEIGHT - h)))
            .collect();
        chart
            .draw_series(DashedLineSeries::new(curve, 6, 4, BLACK.stroke_width(2)))
            .map_err(plot_err)?
            .label("similar triangles, 0.8·w")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
        let series: [(&str, RGBColor, fn(&WidthRow) -> Option<f64>); 4] = [
            ("reference (64² cells, binary visibility)", RGBColor(90, 90, 90), |r| r.reference),
            ("PCSS", RGBColor(150, 60, 170), |r| r.pcss),
            ("16 point sources", RGBColor(10, 90, 90), |r| r.points),
            ("PCF", RGBColor(35, 90, 180), |r| r.pcf),
        ];
        for (name, color, of) in series {
            let pts: Vec<(f64, f64)> = rows.iter().filter_map(|r| Some((r.plate_h, of(r)?))).collect();
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
                .map_err(plot_err)?
                .label(name)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3)));
            chart.draw_series(pts.iter().map(|p| Circle::new(*p, 4, color.filled()))).map_err(plot_err)?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperLeft, 14)?;
        root.present().map_err(plot_err)?;
    }
    save(buf, size, path)
}

/// Files a run writes into its output folder.
pub const OUTPUTS: [&str; 3] = ["penumbra.csv", "penumbra.md", "penumbra.png"];

/// Write the CSV, the table and the plot into `dir`.
pub fn write_outputs(rows: &[WidthRow], device: &str, command: &str, dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let paths: Vec<PathBuf> = OUTPUTS.iter().map(|f| dir.join(f)).collect();
    std::fs::write(&paths[0], csv(rows)).with_context(|| format!("writing {}", paths[0].display()))?;
    std::fs::write(&paths[1], markdown(rows, device, command))
        .with_context(|| format!("writing {}", paths[1].display()))?;
    plot(rows, device, &paths[2]).with_context(|| format!("writing {}", paths[2].display()))?;
    Ok(paths)
}

/// `shadelab bench penumbra`.
pub fn run(args: &cli::BenchPenumbraArgs) -> Result<(), Failure> {
    std::fs::create_dir_all(&args.output)
        .map_err(|e| Failure::Usage(format!("--output: cannot create folder '{}': {e}", args.output.display())))?;
    let gpu = crate::render::open_gpu()?;
    let command = std::iter::once("shadelab".to_string()).chain(std::env::args().skip(1)).collect::<Vec<_>>().join(" ");
    let rows = measure(&gpu, &HEIGHTS, SIDE)?;
    let paths = write_outputs(&rows, &gpu.describe(), &command, &args.output)?;
    print!("{}", markdown(&rows, &gpu.describe(), &command));
    for p in paths {
        println!("wrote {}", p.display());
    }
    Ok(())
}
