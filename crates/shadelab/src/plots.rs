//! The helpers every plot shares (plotters, drawn into a buffer and saved as PNG): the font, log
//! axes, the legend, saving.

use plotters::coord::combinators::{BindKeyPoints, LogCoord, WithKeyPoints};
use plotters::prelude::*;
use std::path::Path;

/// Text is drawn with egui's own font (shipped with the viewer), so plots need no system fonts.
pub fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        plotters::style::register_font("sans-serif", FontStyle::Normal, epaint_default_fonts::UBUNTU_LIGHT)
            .unwrap_or_else(|_| panic!("egui's bundled font is a valid TrueType font"));
    });
}

/// Log-axis range that holds every value, padded by a factor on each side.
pub(crate) fn log_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !lo.is_finite() {
        return 1e-3..1.0;
    }
    let hi = if hi <= lo { lo * 10.0 } else { hi };
    lo / 1.3..hi * 1.3
}

/// Axis labels at 1, 2, 5 × 10^k inside a range (a log axis otherwise labels only the powers
/// of ten, which a range of one decade may not contain).
fn nice_points(r: &std::ops::Range<f64>) -> Vec<f64> {
    let mut out = Vec::new();
    let mut decade = 10f64.powf(r.start.log10().floor());
    while decade <= r.end {
        for m in [1.0, 2.0, 5.0] {
            let v = m * decade;
            if r.contains(&v) {
                out.push(v);
            }
        }
        decade *= 10.0;
    }
    out
}

/// A log axis over a range with [`nice_points`] as its labels.
pub(crate) fn log_axis(r: std::ops::Range<f64>) -> WithKeyPoints<LogCoord<f64>> {
    let points = nice_points(&r);
    r.log_scale().with_key_points(points)
}

pub(crate) fn save(buf: Vec<u8>, (w, h): (u32, u32), path: &Path) -> anyhow::Result<()> {
    image::RgbImage::from_raw(w, h, buf).ok_or_else(|| anyhow::anyhow!("plot buffer size"))?.save(path)?;
    Ok(())
}

pub(crate) fn plot_err(e: impl std::fmt::Display) -> anyhow::Error {
    anyhow::anyhow!("drawing the plot: {e}")
}

/// A chart's legend in the plots' frame (a light box, a black border) at `position`, its labels
/// `font_px` high.
pub(crate) fn draw_legend<'a, DB: DrawingBackend + 'a, CT: plotters::coord::CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
    font_px: u32,
) -> anyhow::Result<()> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", font_px))
        .draw()
        .map_err(plot_err)
}
