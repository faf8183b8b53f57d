//! The white furnace's plot: the lobe's albedo E (F = 1) against the view angle, one line per
//! D / G pair, one panel per roughness; 1 (no energy lost) dashed.

use super::FurnaceRow;
use crate::plots::{draw_legend, plot_err, register_font, save};
use plotters::prelude::*;
use shadelab_model::lighting::microfacet::Distribution;
use shadelab_model::params::NamedValue;
use std::path::Path;

/// The G's hues by code (red, blue, green, then around again for a G beyond them).
const G_HUES: [(u8, u8, u8); 3] = [(200, 60, 40), (40, 110, 190), (40, 150, 60)];

/// A hue per G; each D after Beckmann's (dark) a step lighter, by its code, so a new term gets a
/// colour of its own without an edit here.
fn color(row: &FurnaceRow) -> RGBColor {
    let (r, g, b) = G_HUES[row.terms.g.code() as usize % G_HUES.len()];
    let step = 0.6 * f64::from(row.terms.d.code()) / (Distribution::ALL.len() - 1).max(1) as f64;
    let lift = |c: u8| (f64::from(c) + (255.0 - f64::from(c)) * step).round() as u8;
    RGBColor(lift(r), lift(g), lift(b))
}

/// One panel per roughness of `ms` (every other one, to keep them legible), E against θ_v.
pub fn furnace(rows: &[FurnaceRow], ms: &[f64], views_deg: &[f64], path: &Path) -> anyhow::Result<()> {
    register_font();
    let panels: Vec<usize> = (0..ms.len()).step_by(2).collect();
    let size = (460 * panels.len() as u32, 460u32);
    let mut buf = vec![0u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (title, body) = root.split_vertically(36);
        title.titled("White furnace: the specular lobe's albedo with F = 1", ("sans-serif", 19)).map_err(plot_err)?;
        for (k, (area, &mi)) in body.split_evenly((1, panels.len())).iter().zip(&panels).enumerate() {
            let ymin = rows.iter().flat_map(|r| r.albedo[mi].iter().copied()).fold(1.0, f64::min);
            let mut chart = ChartBuilder::on(area)
                .caption(format!("m = {}", ms[mi]), ("sans-serif", 16))
                .margin(10)
                .x_label_area_size(36)
                .y_label_area_size(50)
                .build_cartesian_2d(0.0..90.0, (ymin - 0.05).max(0.0)..1.05)
                .map_err(plot_err)?;
            chart.configure_mesh().x_desc("view angle θ_v (°)").y_desc("albedo E").draw().map_err(plot_err)?;
            chart
                .draw_series(DashedLineSeries::new([(0.0, 1.0), (90.0, 1.0)], 6, 4, BLACK.stroke_width(1)))
                .map_err(plot_err)?;
            for r in rows {
                let c = color(r);
                let pts: Vec<(f64, f64)> = views_deg.iter().copied().zip(r.albedo[mi].iter().copied()).collect();
                chart
                    .draw_series(LineSeries::new(pts.iter().copied(), c.stroke_width(2)))
                    .map_err(plot_err)?
                    .label(format!("{} / {}", r.terms.d, r.terms.g))
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], c.stroke_width(3)));
                chart.draw_series(pts.iter().map(|p| Circle::new(*p, 3, c.filled()))).map_err(plot_err)?;
            }
            // One legend, in the first panel, whose lower left the lines leave free.
            if k == 0 {
                draw_legend(&mut chart, SeriesLabelPosition::LowerLeft, 11)?;
            }
        }
    }
    save(buf, size, path)
}
