//! `shadelab lobe --pixel X,Y`: the viewer's pick headless. The point pixel (X, Y) of a render
//! sees (`shadelab_model::lobe::pick`, the f64 model), its N, V and each light's angles printed,
//! and the plots of the viewer's lobe window written as one PNG: the specular terms in the
//! light's plane of incidence (polar), and the Cook–Torrance ρ_s over θ_h × θ_d at φ_d = 90°.

use crate::{Failure, cli};
use anyhow::Context;
use glam::DVec3;
use plotters::coord::Shift;
use plotters::prelude::*;
use shadelab_model::lobe::{Angles, Lobe, Pick, pick, plane_lobe, theta_h_theta_d_slice};

/// Cells per side of the slice.
const SLICE_CELLS: usize = 90;

/// The text `lobe` prints: the pixel, N, V, and per light L and its angles.
pub fn describe(p: &Pick) -> String {
    let v3 = |v: glam::DVec3| format!("({:.3}, {:.3}, {:.3})", v.x, v.y, v.z);
    let mut s = format!(
        "pixel ({}, {}): object {}, material {}\nN = {}\nV = {}\n",
        p.pixel.0,
        p.pixel.1,
        p.object,
        p.material.name,
        v3(p.n),
        v3(p.v)
    );
    for (i, (l, _)) in p.lights.iter().enumerate() {
        let a = Angles::of(p.n, p.v, *l);
        s += &format!(
            "L{} = {}: θ_i = {:.1}°, θ_v = {:.1}°, θ_h = {:.1}°, θ_d = {:.1}°\n",
            i + 1,
            v3(*l),
            a.theta_i,
            a.theta_v,
            a.theta_h,
            a.theta_d
        );
    }
    s
}

pub fn run(args: &cli::LobeArgs) -> Result<(), Failure> {
    let scene = cli::scene(&args.scene)?;
    let (w, h) = args.size.pixels();
    let (x, y) = args.pixel;
    if x >= w || y >= h {
        return Err(Failure::Usage(format!("--pixel: {x},{y} is outside the {w}×{h} image (X < {w}, Y < {h})")));
    }
    let Some(p) = pick(&scene, (x, y), (w, h)) else {
        return Err(Failure::Usage(format!("--pixel: {x},{y} sees the background, no surface")));
    };
    let n_lights = p.lights.len();
    if args.plane_of == 0 || args.plane_of > n_lights {
        return Err(Failure::Usage(format!(
            "--plane-of: {} is not a light of the scene (1 to {n_lights})",
            args.plane_of
        )));
    }
    print!("{}", describe(&p));
    plot(&p, args.plane_of - 1, &args.output).with_context(|| format!("writing {}", args.output.display()))?;
    Ok(())
}

fn plot_err<E: std::fmt::Debug>(e: E) -> anyhow::Error {
    anyhow::anyhow!("plot: {e:?}")
}

/// The polar plot (left) and the slice (right) of light `light` of a pick.
fn plot(p: &Pick, light: usize, path: &std::path::Path) -> anyhow::Result<()> {
    crate::plots::register_font();
    let size = (1100u32, 560u32);
    let mut buf = vec![0u8; (size.0 * size.1 * 3) as usize];
    let l = p.lights[light].0;
    let lobe = plane_lobe(p.n, l, &p.material);
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (left, right) = root.split_horizontally(560);
        polar_panel(&left, p, light, &lobe)?;
        slice_panel(&right, p, l)?;
        root.present().map_err(plot_err)?;
    }
    image::RgbImage::from_raw(size.0, size.1, buf).context("plot buffer")?.save(path)?;
    Ok(())
}

/// The polar plot of light `light`'s plane of incidence: L and each specular term over its maximum.
fn polar_panel(
    area: &DrawingArea<BitMapBackend<'_>, Shift>,
    p: &Pick,
    light: usize,
    lobe: &Lobe,
) -> anyhow::Result<()> {
    let l = p.lights[light].0;
    let mut chart = ChartBuilder::on(area)
        .caption(format!("plane of incidence of L{}, each curve over its maximum", light + 1), ("sans-serif", 18))
        .margin(14)
        // Below the surface (y < 0) is the legend's room; the ranges keep circles round.
        .build_cartesian_2d(-1.05f64..1.05, -0.85f64..1.05)
        .map_err(plot_err)?;
    let at = |theta: f64, r: f64| (theta.to_radians().sin() * r, theta.to_radians().cos() * r);
    for r in [0.5, 1.0] {
        chart
            .draw_series(LineSeries::new((0..=180).map(|k| at(-90.0 + k as f64, r)), RGBColor(200, 200, 200)))
            .map_err(plot_err)?;
    }
    let theta_l = -(p.n.dot(l).clamp(-1.0, 1.0).acos().to_degrees());
    chart
        .draw_series(LineSeries::new([(0.0, 0.0), at(theta_l, 1.0)], RGBColor(200, 160, 0).stroke_width(2)))
        .map_err(plot_err)?
        .label("L")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 16, y)], RGBColor(200, 160, 0)));
    let curves: [(&str, &[f64], RGBColor); 5] = [
        ("Phong (V·R)^h", &lobe.phong, RGBColor(30, 100, 220)),
        ("Cook–Torrance F·D·G/(N·V)", &lobe.cook_torrance, RGBColor(230, 110, 20)),
        ("D / D_max", &lobe.d, RGBColor(40, 160, 40)),
        ("G", &lobe.g, RGBColor(150, 150, 0)),
        ("F", &lobe.f, RGBColor(200, 40, 160)),
    ];
    for (name, values, color) in curves {
        let max = values.iter().cloned().fold(0.0, f64::max);
        if max <= 0.0 || !max.is_finite() {
            continue;
        }
        chart
            .draw_series(LineSeries::new(
                lobe.theta.iter().zip(values).map(|(t, v)| at(*t, v / max)),
                color.stroke_width(2),
            ))
            .map_err(plot_err)?
            .label(format!("{name} (max {max:.3})"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(SeriesLabelPosition::LowerLeft)
        .label_font(("sans-serif", 13))
        .draw()
        .map_err(plot_err)?;
    Ok(())
}

/// The slice of the Cook–Torrance ρ_s over θ_h × θ_d at φ_d = 90°, the pick's angles to `l` marked.
fn slice_panel(area: &DrawingArea<BitMapBackend<'_>, Shift>, p: &Pick, l: DVec3) -> anyhow::Result<()> {
    let values = theta_h_theta_d_slice(&p.material, SLICE_CELLS);
    let peak = values.iter().cloned().fold(f64::MIN_POSITIVE, f64::max);
    let lut = shadelab_render::image_error::magma_scale();
    let mut chart = ChartBuilder::on(area)
        .caption("Cook–Torrance ρ_s, φ_d = 90°, log scale (6 decades)", ("sans-serif", 18))
        .margin(14)
        .x_label_area_size(36)
        .y_label_area_size(44)
        .build_cartesian_2d(0f64..90.0, 90f64..0.0)
        .map_err(plot_err)?;
    chart.configure_mesh().x_desc("θ_h (°)").y_desc("θ_d (°)").disable_mesh().draw().map_err(plot_err)?;
    let cell = 90.0 / SLICE_CELLS as f64;
    chart
        .draw_series(values.iter().enumerate().map(|(i, v)| {
            let (cx, cy) = ((i % SLICE_CELLS) as f64 * cell, (i / SLICE_CELLS) as f64 * cell);
            let t = if *v > 0.0 { ((v / peak).log10() / 6.0 + 1.0).clamp(0.0, 1.0) } else { 0.0 };
            let c = lut[(t * 255.0).round() as usize];
            Rectangle::new([(cx, cy), (cx + cell, cy + cell)], RGBColor(c[0], c[1], c[2]).filled())
        }))
        .map_err(plot_err)?;
    let a = Angles::of(p.n, p.v, l);
    chart.draw_series([Circle::new((a.theta_h, a.theta_d), 6, WHITE.stroke_width(2))]).map_err(plot_err)?;
    Ok(())
}
