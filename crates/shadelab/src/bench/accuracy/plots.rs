//! The accuracy study's plots: error against time with the Pareto front, and how time grows
//! with lights and pixels.

use super::report::{Report, Row, Study};
use crate::plots::{draw_legend, log_axis, log_range, plot_err, register_font, save};
use plotters::coord::Shift;
use plotters::prelude::*;
use shadelab_model::{ShadingMode, SpecularModel};
use std::path::Path;

/// A colour per program: one hue per shading mode, dark for Phong specular, light for
/// Cook–Torrance.
pub fn program_color(shading: Option<ShadingMode>, specular: Option<SpecularModel>) -> RGBColor {
    use ShadingMode as M;
    use SpecularModel as S;
    match (shading, specular) {
        (Some(M::Flat), Some(S::Phong)) => RGBColor(200, 30, 30),
        (Some(M::Flat), Some(S::CookTorrance)) => RGBColor(245, 140, 120),
        (Some(M::Gouraud), Some(S::Phong)) => RGBColor(35, 90, 180),
        (Some(M::Gouraud), Some(S::CookTorrance)) => RGBColor(120, 175, 230),
        (Some(M::Phong), Some(S::Phong)) => RGBColor(30, 140, 50),
        (Some(M::Phong), Some(S::CookTorrance)) => RGBColor(140, 210, 110),
        _ => RGBColor(110, 110, 110),
    }
}

/// The study's programs as (shading, specular), `None` for the baseline.
fn programs() -> Vec<(Option<ShadingMode>, Option<SpecularModel>)> {
    super::report::programs()
        .into_iter()
        .map(|s| s.map_or((None, None), |s| (Some(s.shading), Some(s.specular))))
        .collect()
}

fn label(shading: Option<ShadingMode>, specular: Option<SpecularModel>) -> String {
    match (shading, specular) {
        (Some(s), Some(p)) => format!("{s} shading, {p} specular"),
        _ => "null-shader baseline".into(),
    }
}

/// Error (RMSE) against GPU time, log–log, one panel per scene at the plan's largest size; a
/// line per program through its levels of detail; the Pareto front in black.
pub fn error_vs_time(report: &Report, path: &Path) -> anyhow::Result<()> {
    register_font();
    let size = (1400u32, 1000u32);
    let mut buf = vec![0u8; (size.0 * size.1 * 3) as usize];
    let (w, h) = *report.plan.resolutions.iter().max_by_key(|(w, h)| w * h).unwrap_or(&(0, 0));
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (title, body) = root.split_vertically(40);
        title
            .titled(
                &format!("Error against time, {w}×{h}: {} ({})", report.device, report.time_source.label()),
                ("sans-serif", 20),
            )
            .map_err(plot_err)?;
        let n = report.plan.scenes.len().max(1);
        let cols = if n > 1 { 2 } else { 1 };
        let panels = body.split_evenly((n.div_ceil(cols), cols));
        for (scene, area) in report.plan.scenes.iter().zip(panels.iter()) {
            error_vs_time_panel(area, report, scene, (w, h))?;
        }
        root.present().map_err(plot_err)?;
    }
    save(buf, size, path)
}

/// One scene's panel of [`error_vs_time`]: its rows at `(w, h)`, a line per program, the Pareto fronts.
fn error_vs_time_panel(
    area: &DrawingArea<BitMapBackend<'_>, Shift>,
    report: &Report,
    scene: &str,
    (w, h): (u32, u32),
) -> anyhow::Result<()> {
    let rows: Vec<&Row> = report
        .rows
        .iter()
        .filter(|r| r.study == Study::Modes && r.scene == scene && (r.width, r.height) == (w, h))
        .filter(|r| r.error.is_some())
        .collect();
    let xr = log_range(rows.iter().map(|r| r.median_ms));
    let yr = log_range(rows.iter().map(|r| r.error.unwrap().rmse));
    let mut chart = ChartBuilder::on(area)
        .caption(format!("{scene}: RMSE vs GPU time (levels of detail along each line)"), ("sans-serif", 17))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(log_axis(xr), log_axis(yr))
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .x_desc("median GPU ms per frame")
        .y_desc("RMSE vs exact surface (linear)")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .x_label_formatter(&|v| format!("{v}"))
        .draw()
        .map_err(plot_err)?;
    for (shading, specular) in programs().into_iter().skip(1) {
        let color = program_color(shading, specular);
        let pts = program_points(&rows, shading, specular);
        chart
            .draw_series(LineSeries::new(pts.iter().map(|p| (p.0, p.1)), color.stroke_width(2)))
            .map_err(plot_err)?
            .label(label(shading, specular))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3)));
        chart.draw_series(pts.iter().map(|p| Circle::new((p.0, p.1), 4, color.filled()))).map_err(plot_err)?;
        // The coarsest level is labelled, so a reader sees which end is which.
        if let Some(p) = pts.first() {
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((p.0, p.1))
                        + Text::new(format!("level {}", p.2), (7, -16), ("sans-serif", 13).into_font().color(&color)),
                ))
                .map_err(plot_err)?;
        }
    }
    for specular in SpecularModel::ALL_MODELS {
        let front = pareto_front(&rows, specular);
        let style = match specular {
            SpecularModel::Phong => BLACK.stroke_width(1),
            SpecularModel::CookTorrance => RGBColor(150, 150, 150).stroke_width(1),
        };
        chart
            .draw_series(LineSeries::new(front.iter().copied(), style))
            .map_err(plot_err)?
            .label(format!("Pareto front, {specular} specular"))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
        chart.draw_series(front.iter().map(|p| Cross::new(*p, 6, style.stroke_width(2)))).map_err(plot_err)?;
    }
    draw_legend(&mut chart, SeriesLabelPosition::LowerLeft, 13)?;
    Ok(())
}

/// A program's rows as (time, RMSE, level), in order of level.
fn program_points(
    rows: &[&Row],
    shading: Option<ShadingMode>,
    specular: Option<SpecularModel>,
) -> Vec<(f64, f64, u32)> {
    let mut pts: Vec<(f64, f64, u32)> = rows
        .iter()
        .filter(|r| r.shading == shading && r.specular == specular)
        .map(|r| (r.median_ms, r.error.unwrap().rmse, r.level))
        .collect();
    pts.sort_by_key(|p| p.2);
    pts
}

/// The Pareto front's rows with `specular` as (time, RMSE), in order of time.
fn pareto_front(rows: &[&Row], specular: SpecularModel) -> Vec<(f64, f64)> {
    let mut front: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.pareto && r.specular == Some(specular))
        .map(|r| (r.median_ms, r.error.unwrap().rmse))
        .collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    front
}

/// How time grows: per added light (left) and per pixel count (right, log–log), every program
/// and the baseline.
pub fn scaling(report: &Report, path: &Path) -> anyhow::Result<()> {
    register_font();
    let size = (1400u32, 560u32);
    let mut buf = vec![0u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (title, body) = root.split_vertically(40);
        title
            .titled(&format!("How cost grows: {} ({})", report.device, report.time_source.label()), ("sans-serif", 20))
            .map_err(plot_err)?;
        let (left, right) = body.split_horizontally(size.0 / 2);

        let lights: Vec<&Row> = report.rows.iter().filter(|r| r.study == Study::Lights).collect();
        let max_lights = lights.iter().map(|r| r.lights).max().unwrap_or(1) as f64;
        let ymax = lights.iter().map(|r| r.median_ms).fold(0.0, f64::max) * 1.15 + 1e-3;
        let (ls, ll, (lw, lh)) = report.plan.light_study;
        let mut chart = ChartBuilder::on(&left)
            .caption(format!("per light: {ls}, level {ll}, {lw}×{lh}"), ("sans-serif", 17))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(0.5..max_lights + 0.5, 0.0..ymax)
            .map_err(plot_err)?;
        chart.configure_mesh().x_desc("point lights").y_desc("median GPU ms per frame").draw().map_err(plot_err)?;
        for (shading, specular) in programs() {
            let color = program_color(shading, specular);
            let pts: Vec<(f64, f64)> = lights
                .iter()
                .filter(|r| r.shading == shading && r.specular == specular)
                .map(|r| (r.lights as f64, r.median_ms))
                .collect();
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
                .map_err(plot_err)?
                .label(label(shading, specular))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3)));
            chart.draw_series(pts.iter().map(|p| Circle::new(*p, 4, color.filled()))).map_err(plot_err)?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperLeft, 13)?;

        let res: Vec<&Row> = report.rows.iter().filter(|r| r.study == Study::Resolution).collect();
        let mpx = |r: &Row| (r.width * r.height) as f64 / 1e6;
        let (rs, rl) = report.plan.resolution_study;
        let mut chart = ChartBuilder::on(&right)
            .caption(format!("per pixel: {rs}, level {rl}"), ("sans-serif", 17))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(
                log_axis(log_range(res.iter().map(|r| mpx(r)))),
                log_axis(log_range(res.iter().map(|r| r.median_ms))),
            )
            .map_err(plot_err)?;
        chart
            .configure_mesh()
            .x_desc("megapixels")
            .y_desc("median GPU ms per frame")
            .x_label_formatter(&|v| format!("{v}"))
            .y_label_formatter(&|v| format!("{v}"))
            .draw()
            .map_err(plot_err)?;
        for (shading, specular) in programs() {
            let color = program_color(shading, specular);
            let pts: Vec<(f64, f64)> = res
                .iter()
                .filter(|r| r.shading == shading && r.specular == specular)
                .map(|r| (mpx(r), r.median_ms))
                .collect();
            chart.draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2))).map_err(plot_err)?;
            chart.draw_series(pts.iter().map(|p| Circle::new(*p, 4, color.filled()))).map_err(plot_err)?;
        }
        root.present().map_err(plot_err)?;
    }
    save(buf, size, path)
}
