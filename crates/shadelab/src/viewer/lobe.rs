//! The lobe of the picked pixel: a click on the view picks the point it sees
//! (`shadelab_model::lobe::pick`, the f64 model's ray caster); a window shows its N, V and each
//! light's L with their angles, a polar plot of the specular terms in the light's plane of
//! incidence (Phong and Cook–Torrance overlaid, the material's D, G and F apart, and Cook–Torrance
//! with other microfacet terms beside it), and the Cook–Torrance BRDF over θ_h × θ_d at
//! φ_d = 90°, as BRDF Explorer draws it. Every value comes from the f64 model; egui_plot draws
//! them with axes, zoom, hover readouts and legends.

use eframe::egui::{self, Color32};
use egui_plot::{HoverPosition, Legend, Line, MarkerShape, Plot, PlotImage, PlotPoint, PlotPoints, Points};
use shadelab_model::lighting::microfacet::Microfacet;
use shadelab_model::lobe::{Angles, Lobe, Pick, plane_direction, plane_lobe, theta_h_theta_d_slice};
use shadelab_model::{Material, Scene};

/// Cells per side of the θ_h × θ_d slice.
const SLICE_CELLS: usize = 48;
/// Side of the polar plot and of the slice, in points.
const PLOT_SIDE: f32 = 260.0;

/// The curves of the polar plot: name, colour.
const CURVES: [(&str, Color32); 5] = [
    ("Phong", Color32::from_rgb(90, 170, 255)),
    ("Cook–Torrance", Color32::from_rgb(255, 140, 60)),
    ("D / D_max", Color32::from_rgb(120, 220, 120)),
    ("G", Color32::from_rgb(220, 220, 90)),
    ("F", Color32::from_rgb(230, 110, 200)),
];

/// The overlays' colours, in the order of `Microfacet::ALL` then the others.
const OVERLAY_COLORS: [Color32; 4] = [
    Color32::from_rgb(255, 90, 90),
    Color32::from_rgb(80, 230, 230),
    Color32::from_rgb(200, 160, 255),
    Color32::from_rgb(250, 250, 250),
];

/// The picked point and what its window shows.
pub struct LobeView {
    pick: Option<Pick>,
    /// The light whose plane of incidence is plotted.
    light: usize,
    open: bool,
    /// The slice's texture and values, and the material they were made for.
    slice: Option<(Material, egui::TextureHandle, Vec<f64>)>,
    /// The other microfacet terms whose Cook–Torrance lobe is drawn beside the material's.
    overlays: Vec<Microfacet>,
}

impl Default for LobeView {
    fn default() -> Self {
        LobeView {
            pick: None,
            light: 0,
            open: false,
            slice: None,
            overlays: vec![Microfacet::CHAPTER, Microfacet::GLTF],
        }
    }
}

impl LobeView {
    /// Pick the point pixel `pixel` of a `size` view of `scene` sees (nothing on the background).
    pub fn pick(&mut self, scene: &Scene, pixel: (u32, u32), size: (u32, u32)) {
        self.pick = shadelab_model::lobe::pick(scene, pixel, size);
        self.open = self.pick.is_some();
        if self.pick.as_ref().is_some_and(|p| self.light >= p.lights.len()) {
            self.light = 0;
        }
    }

    /// The point picked last.
    pub fn picked(&self) -> Option<&Pick> {
        self.pick.as_ref()
    }

    /// The window, while a point is picked and the window is open.
    pub fn show(&mut self, ctx: &egui::Context, scene: &Scene) {
        let Some(pick) = self.pick.clone() else { return };
        let mut open = self.open;
        let window = egui::Window::new("lobe of the picked pixel").open(&mut open);
        window.default_pos(egui::pos2(20.0, 60.0)).show(ctx, |ui| {
            let name = scene.objects.get(pick.object).map_or("?", |o| o.name.as_str());
            ui.label(format!("pixel ({}, {}): {name}, material {}", pick.pixel.0, pick.pixel.1, pick.material.name));
            ui.label(format!("N = {}   V = {}", vector(pick.n), vector(pick.v)));
            for (i, (l, _)) in pick.lights.iter().enumerate() {
                let a = Angles::of(pick.n, pick.v, *l);
                ui.radio_value(&mut self.light, i, format!("L{} = {}", i + 1, vector(*l)));
                ui.label(format!(
                    "    θ_i = {:.1}°, θ_v = {:.1}°, θ_h = {:.1}°, θ_d = {:.1}°",
                    a.theta_i, a.theta_v, a.theta_h, a.theta_d
                ));
            }
            let Some(&(l, _)) = pick.lights.get(self.light) else {
                ui.label("no lights: no plane of incidence");
                return;
            };
            self.overlay_menu(ui, &pick.material);
            ui.horizontal(|ui| {
                ui.vertical(|ui| {
                    ui.label(format!("plane of incidence of L{} (dashed: other terms)", self.light + 1)).on_hover_text(
                        "each curve over its own maximum; other terms' Cook–Torrance over the material's",
                    );
                    polar_plot(ui, &pick, l, &self.overlays);
                });
                ui.vertical(|ui| {
                    ui.label(format!("ρ_s ({}), log scale, φ_d = 90°", pick.material.microfacet));
                    self.slice_plot(ui, &pick, l);
                });
            });
        });
        self.open = open;
    }

    /// The checkboxes of the terms drawn beside the material's own, in a collapsed section.
    fn overlay_menu(&mut self, ui: &mut egui::Ui, material: &Material) {
        let title = format!(
            "material's terms {}; other terms beside them ({} chosen)",
            material.microfacet,
            self.overlays.len()
        );
        egui::CollapsingHeader::new(title).id_salt("lobe overlays").show(ui, |ui| {
            for terms in shadelab_model::furnace::pairs().into_iter().flat_map(|t| {
                use shadelab_model::params::NamedValue;
                shadelab_model::lighting::microfacet::Fresnel::ALL.iter().map(move |&(_, f)| Microfacet { f, ..t })
            }) {
                let mut on = self.overlays.contains(&terms);
                if ui.checkbox(&mut on, terms.to_string()).changed() {
                    self.overlays.retain(|t| *t != terms);
                    if on {
                        self.overlays.push(terms);
                    }
                }
            }
        });
    }

    fn slice_plot(&mut self, ui: &mut egui::Ui, pick: &Pick, l: glam::DVec3) {
        if self.slice.as_ref().is_none_or(|(m, _, _)| *m != pick.material) {
            let values = theta_h_theta_d_slice(&pick.material, SLICE_CELLS);
            // log10 over six decades below the peak, through the magma scale; rows flipped so
            // that θ_d grows upwards, as the plot's y axis does.
            let peak = values.iter().cloned().fold(f64::MIN_POSITIVE, f64::max);
            let lut = shadelab_render::image_error::magma_scale();
            let rgb: Vec<u8> = (0..SLICE_CELLS)
                .rev()
                .flat_map(|y| values[y * SLICE_CELLS..(y + 1) * SLICE_CELLS].iter())
                .flat_map(|v| {
                    let t = if *v > 0.0 { ((v / peak).log10() / 6.0 + 1.0).clamp(0.0, 1.0) } else { 0.0 };
                    lut[(t * 255.0).round() as usize]
                })
                .collect();
            let image = egui::ColorImage::from_rgb([SLICE_CELLS, SLICE_CELLS], &rgb);
            let texture = ui.ctx().load_texture("θh θd slice", image, egui::TextureOptions::NEAREST);
            self.slice = Some((pick.material.clone(), texture, values));
        }
        let Some((_, texture, values)) = &self.slice else { return };
        let a = Angles::of(pick.n, pick.v, l);
        let cell = |deg: f64| ((deg / 90.0 * SLICE_CELLS as f64) as usize).min(SLICE_CELLS - 1);
        let at = |p: &PlotPoint| values[cell(p.y.clamp(0.0, 90.0)) * SLICE_CELLS + cell(p.x.clamp(0.0, 90.0))];
        let readout = move |pos: &HoverPosition<'_>| {
            let p = match pos {
                HoverPosition::NearDataPoint { position, .. } => position,
                HoverPosition::Elsewhere { position } => position,
            };
            Some(format!("θ_h = {:.1}°, θ_d = {:.1}°\nρ_s = {:.4e}", p.x, p.y, at(p)))
        };
        Plot::new("θh θd slice")
            .width(PLOT_SIDE)
            .height(PLOT_SIDE)
            .data_aspect(1.0)
            .x_axis_label("θ_h (°)")
            .y_axis_label("θ_d (°)")
            .include_x(0.0)
            .include_x(90.0)
            .include_y(0.0)
            .include_y(90.0)
            .label_formatter(readout)
            .show(ui, |p| {
                p.image(PlotImage::new("ρ_s", texture.id(), PlotPoint::new(45.0, 45.0), [90.0, 90.0]));
                let here = Points::new("this pixel", vec![[a.theta_h, a.theta_d]]);
                p.points(here.shape(MarkerShape::Circle).radius(5.0).filled(false).color(Color32::WHITE));
            });
    }
}

/// A unit vector, three decimals.
fn vector(v: glam::DVec3) -> String {
    format!("({:.3}, {:.3}, {:.3})", v.x, v.y, v.z)
}

/// The values of curve `k` of [`CURVES`].
fn curve(lobe: &Lobe, k: usize) -> &[f64] {
    match k {
        0 => &lobe.phong,
        1 => &lobe.cook_torrance,
        2 => &lobe.d,
        3 => &lobe.g,
        _ => &lobe.f,
    }
}

/// Points of `values` along `theta` at radius value/scale: N up (y), the mirror side to the right.
fn polar(theta: &[f64], values: &[f64], scale: f64) -> PlotPoints<'static> {
    theta
        .iter()
        .zip(values)
        .map(|(th, v)| {
            let (t, r) = (th.to_radians(), v / scale);
            [t.sin() * r, t.cos() * r]
        })
        .collect()
}

/// The polar plot: N up, the surface along the x axis, L's direction and V's projection into the
/// plane as lines. Each of the material's curves is over its own maximum; the other terms'
/// Cook–Torrance lobes are over the material's Cook–Torrance maximum, so their heights compare.
fn polar_plot(ui: &mut egui::Ui, pick: &Pick, l: glam::DVec3, overlays: &[Microfacet]) {
    let lobe = plane_lobe(pick.n, l, &pick.material);
    let ct_max = lobe.cook_torrance.iter().cloned().fold(0.0, f64::max);
    let others: Vec<(Microfacet, Lobe)> = overlays
        .iter()
        .filter(|t| **t != pick.material.microfacet)
        .map(|t| (*t, plane_lobe(pick.n, l, &Material { microfacet: *t, ..pick.material.clone() })))
        .collect();
    let theta_l = -(pick.n.dot(l).clamp(-1.0, 1.0).acos());
    let t = plane_direction(pick.n, l, 90.0);
    let theta_v = pick.v.dot(t).atan2(pick.v.dot(pick.n));
    let readout = |pos: &HoverPosition<'_>| match pos {
        HoverPosition::NearDataPoint { plot_name, position, .. } => {
            let theta = position.x.atan2(position.y).to_degrees();
            Some(format!("{plot_name}\nθ = {theta:.1}°, value/max = {:.3}", position.x.hypot(position.y)))
        }
        HoverPosition::Elsewhere { .. } => None,
    };
    // The half below the surface holds the legend.
    Plot::new("lobe polar")
        .width(PLOT_SIDE * 1.3)
        .height(PLOT_SIDE * 1.3)
        .data_aspect(1.0)
        .include_x(-1.05)
        .include_x(1.05)
        .include_y(-1.05)
        .include_y(1.05)
        .legend(Legend::default().position(egui_plot::Corner::LeftBottom).text_style(egui::TextStyle::Small))
        .label_formatter(readout)
        .show(ui, |p| {
            let ray = |name: &str, th: f64| Line::new(name.to_string(), vec![[0.0, 0.0], [th.sin(), th.cos()]]);
            p.line(ray("L", theta_l).color(Color32::from_rgb(255, 230, 120)).width(2.0));
            p.line(ray("V (projected)", theta_v).color(Color32::WHITE).width(2.0));
            for (k, (name, color)) in CURVES.iter().enumerate() {
                let values = curve(&lobe, k);
                let max = values.iter().cloned().fold(0.0, f64::max);
                if max > 0.0 && max.is_finite() {
                    let label = format!("{name} (max {max:.3})");
                    p.line(Line::new(label, polar(&lobe.theta, values, max)).color(*color).width(1.5));
                }
            }
            if ct_max > 0.0 && ct_max.is_finite() {
                for (i, (terms, other)) in others.iter().enumerate() {
                    let color = OVERLAY_COLORS[i % OVERLAY_COLORS.len()];
                    let label = format!("CT {terms}");
                    let line = Line::new(label, polar(&other.theta, &other.cook_torrance, ct_max));
                    p.line(line.color(color).width(1.5).style(egui_plot::LineStyle::dashed_loose()));
                }
            }
        });
}
