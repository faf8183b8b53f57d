//! The plot of `bench shadows`: RMSE against median GPU time, both logarithmic, one line per
//! method through its map resolutions (each point labelled with its map side), the Pareto front
//! dashed through the rows no other row beats, the shadows-off and baseline times as vertical
//! lines.

use super::{Config, FILTERS, Report, Row, filter_name};
use crate::plots::{draw_legend, log_axis, log_range, plot_err, register_font, save};
use plotters::prelude::*;
use shadelab_model::shadows::ShadowFilter;
use std::path::Path;

/// One line of the plot: a method, its colour, and whether a row belongs to it.
struct Method {
    name: String,
    color: RGBColor,
    of: Box<dyn Fn(Config) -> Option<u32>>,
}

/// The methods in the order of the legend; `of` gives the row's requested resolution.
fn methods() -> Vec<Method> {
    let filter_color = |f: ShadowFilter| match f {
        ShadowFilter::Hard => RGBColor(200, 30, 30),
        ShadowFilter::Pcf => RGBColor(35, 90, 180),
        ShadowFilter::Poisson => RGBColor(30, 140, 50),
        ShadowFilter::Pcss => RGBColor(150, 60, 170),
    };
    let mut v: Vec<Method> = FILTERS
        .into_iter()
        .map(|f| Method {
            name: if f == ShadowFilter::Pcss {
                format!("pcss, {} taps", shadelab_model::shadows::SHADOW_PCSS_TAPS)
            } else {
                filter_name(f).into()
            },
            color: filter_color(f),
            of: Box::new(move |c| match c {
                Config::Shadows { resolution, filter } if filter == f => Some(resolution),
                _ => None,
            }),
        })
        .collect();
    v.push(Method {
        name: "pcf, one map (no cascades)".into(),
        color: RGBColor(150, 150, 150),
        of: Box::new(|c| if let Config::OneMap { resolution } = c { Some(resolution) } else { None }),
    });
    for (taps, color) in super::PCSS_TAP_COUNTS.into_iter().zip([RGBColor(200, 140, 220), RGBColor(90, 20, 110)]) {
        v.push(Method {
            name: format!("pcss, {taps} taps"),
            color,
            of: Box::new(move |c| match c {
                Config::PcssTaps { resolution, taps: t } if t == taps => Some(resolution),
                _ => None,
            }),
        });
    }
    v.push(Method {
        name: format!("pcss, {} taps, LTC specular", shadelab_model::shadows::SHADOW_PCSS_TAPS),
        color: RGBColor(230, 60, 130),
        of: Box::new(|c| if let Config::Ltc { resolution } = c { Some(resolution) } else { None }),
    });
    v.push(Method {
        name: "area lights as point lights".into(),
        color: RGBColor(120, 80, 30),
        of: Box::new(|c| if let Config::PointLights { resolution } = c { Some(resolution) } else { None }),
    });
    let point_colors = [RGBColor(240, 150, 30), RGBColor(20, 170, 170), RGBColor(10, 90, 90)];
    for (k, color) in super::POINT_COUNTS.into_iter().zip(point_colors) {
        v.push(Method {
            name: format!("{k} point source{}", if k == 1 { "" } else { "s" }),
            color,
            of: Box::new(move |c| match c {
                Config::Points { resolution, k: n } if n == k => Some(resolution),
                _ => None,
            }),
        });
    }
    v
}

/// RMSE against median GPU time, a line per method, the Pareto front dashed.
pub fn plot(report: &Report, path: &Path) -> anyhow::Result<()> {
    register_font();
    let size = (1300u32, 850u32);
    let mut buf = vec![0u8; (size.0 * size.1 * 3) as usize];
    let time_of = |c: Config| report.rows.iter().find(|r| r.config == c).map_or(f64::NAN, |r| r.median_ms);
    let (off_ms, base_ms) = (time_of(Config::Off), time_of(Config::Baseline));
    let scored: Vec<&Row> = report.rows.iter().filter(|r| r.rmse.is_some()).collect();
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let x = log_range(report.rows.iter().map(|r| r.median_ms));
        let y = log_range(scored.iter().filter_map(|r| r.rmse));
        let (ylo, yhi) = (y.start, y.end);
        let mut chart = ChartBuilder::on(&root)
            .caption(caption(report), ("sans-serif", 18))
            .margin(14)
            .x_label_area_size(45)
            .y_label_area_size(80)
            .build_cartesian_2d(log_axis(x), log_axis(y))
            .map_err(plot_err)?;
        chart
            .configure_mesh()
            .x_desc("median GPU ms per frame (log)")
            .y_desc("RMSE against the exact reference (linear RGB, log)")
            .x_label_formatter(&|v| format!("{v}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()
            .map_err(plot_err)?;
        for (ms, name, color) in
            [(off_ms, "shadows off", RGBColor(110, 110, 110)), (base_ms, "null-shader baseline", BLACK)]
        {
            if ms.is_finite() && ms > 0.0 {
                chart
                    .draw_series(LineSeries::new([(ms, ylo), (ms, yhi)], color.stroke_width(1)))
                    .map_err(plot_err)?
                    .label(format!("{name} ({ms:.3} ms)"))
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
            }
        }
        // The Pareto front: its rows in order of time, joined by a dashed step line.
        let steps = pareto_steps(&scored);
        chart
            .draw_series(DashedLineSeries::new(steps, 6, 4, BLACK.stroke_width(2)))
            .map_err(plot_err)?
            .label("Pareto front (no row both faster and more accurate)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
        for m in methods() {
            let pts = method_points(&m, &scored);
            if pts.is_empty() {
                continue;
            }
            let color = m.color;
            chart
                .draw_series(LineSeries::new(pts.iter().map(|p| (p.0, p.1)), color.stroke_width(2)))
                .map_err(plot_err)?
                .label(m.name)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3)));
            chart
                .draw_series(pts.iter().map(|p| {
                    EmptyElement::at((p.0, p.1))
                        + Circle::new((0, 0), 4, color.filled())
                        + Text::new(p.2.clone(), (6, -14), ("sans-serif", 12).into_font().color(&color))
                }))
                .map_err(plot_err)?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::LowerLeft, 13)?;
        root.present().map_err(plot_err)?;
    }
    save(buf, size, path)
}

/// The plot's title: the scene, the image size, the device and the time source.
fn caption(report: &Report) -> String {
    format!(
        "Error vs time, '{}' {}×{}: {} ({})",
        report.scene,
        report.size.0,
        report.size.1,
        report.device,
        report.time_source.label()
    )
}

/// The Pareto front's rows in order of time, as the corners of a step line through them.
fn pareto_steps(scored: &[&Row]) -> Vec<(f64, f64)> {
    let mut front: Vec<(f64, f64)> =
        scored.iter().filter(|r| r.pareto).map(|r| (r.median_ms, r.rmse.unwrap_or(f64::NAN))).collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    front
        .iter()
        .enumerate()
        .flat_map(|(i, p)| if i == 0 { vec![*p] } else { vec![(p.0, front[i - 1].1), *p] })
        .collect()
}

/// A method's rows as (time, RMSE, label with the map side) in order of time.
fn method_points(m: &Method, scored: &[&Row]) -> Vec<(f64, f64, String)> {
    let mut pts: Vec<(f64, f64, String)> = scored
        .iter()
        .filter_map(|r| {
            let resolution = (m.of)(r.config)?;
            let side = r.side.unwrap_or(resolution);
            let label = if side == resolution { format!("{side}") } else { format!("{resolution} (used {side})") };
            Some((r.median_ms, r.rmse?, label))
        })
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts
}
