//! The lobe of the picked pixel: a click on the view picks the point it sees
//! (`shadelab_model::lobe::pick`, the f64 model's ray caster); a window shows its N, V and each
//! light's L with their angles, a polar plot of the specular terms in the light's plane of
//! incidence (Phong and Cook–Torrance overlaid, the chapter's D, G and F apart), and the
//! Cook–Torrance BRDF over θ_h × θ_d at φ_d = 90°, as BRDF Explorer draws it. Every value comes
//! from the f64 model. The plots are drawn with egui's painter.

use eframe::egui::{self, Color32, Pos2, Rect, Stroke, pos2, vec2};
use shadelab_model::lobe::{Angles, Lobe, Pick, plane_direction, plane_lobe, theta_h_theta_d_slice};
use shadelab_model::{Material, Scene};

/// Cells per side of the θ_h × θ_d slice.
const SLICE_CELLS: usize = 48;
/// Side of the polar plot and of the slice, in points.
const PLOT_SIDE: f32 = 220.0;

/// The curves of the polar plot: name, colour.
const CURVES: [(&str, Color32); 5] = [
    ("Phong (V·R)^h", Color32::from_rgb(90, 170, 255)),
    ("Cook–Torrance F·D·G/(N·V)", Color32::from_rgb(255, 140, 60)),
    ("D / D_max", Color32::from_rgb(120, 220, 120)),
    ("G", Color32::from_rgb(220, 220, 90)),
    ("F", Color32::from_rgb(230, 110, 200)),
];

/// The picked point and what its window shows.
#[derive(Default)]
pub struct LobeView {
    pick: Option<Pick>,
    /// The light whose plane of incidence is plotted.
    light: usize,
    open: bool,
    /// The slice's texture and the material it was made for.
    slice: Option<(Material, egui::TextureHandle)>,
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
        egui::Window::new("lobe of the picked pixel").open(&mut open).default_pos(pos2(20.0, 60.0)).show(ctx, |ui| {
            let name = scene.objects.get(pick.object).map_or("?", |o| o.name.as_str());
            ui.label(format!("pixel ({}, {}): {name}, material {}", pick.pixel.0, pick.pixel.1, pick.material.name));
            ui.label(format!("N = {}", vector(pick.n)));
            ui.label(format!("V = {}", vector(pick.v)));
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
            let lobe = plane_lobe(pick.n, l, &pick.material);
            ui.horizontal(|ui| {
                ui.vertical(|ui| {
                    ui.label(format!("plane of incidence of L{} (each curve over its maximum)", self.light + 1));
                    polar_plot(ui, &lobe, &pick, l);
                    for (k, (name, color)) in CURVES.iter().enumerate() {
                        let max = curve(&lobe, k).iter().cloned().fold(0.0, f64::max);
                        ui.colored_label(*color, format!("{name}: max {max:.3}"));
                    }
                });
                ui.vertical(|ui| {
                    ui.label("Cook–Torrance ρ_s, θ_h across × θ_d down (0–90°), φ_d = 90°, log scale");
                    self.slice_plot(ui, &pick, l);
                });
            });
        });
        self.open = open;
    }

    fn slice_plot(&mut self, ui: &mut egui::Ui, pick: &Pick, l: glam::DVec3) {
        if self.slice.as_ref().is_none_or(|(m, _)| *m != pick.material) {
            let values = theta_h_theta_d_slice(&pick.material, SLICE_CELLS);
            // log10 over six decades below the peak, through the magma scale.
            let peak = values.iter().cloned().fold(f64::MIN_POSITIVE, f64::max);
            let lut = shadelab_render::image_error::magma_scale();
            let rgb: Vec<u8> = values
                .iter()
                .flat_map(|v| {
                    let t = if *v > 0.0 { ((v / peak).log10() / 6.0 + 1.0).clamp(0.0, 1.0) } else { 0.0 };
                    lut[(t * 255.0).round() as usize]
                })
                .collect();
            let image = egui::ColorImage::from_rgb([SLICE_CELLS, SLICE_CELLS], &rgb);
            let texture = ui.ctx().load_texture("θh θd slice", image, egui::TextureOptions::NEAREST);
            self.slice = Some((pick.material.clone(), texture));
        }
        let (rect, _) = ui.allocate_exact_size(vec2(PLOT_SIDE, PLOT_SIDE), egui::Sense::hover());
        let painter = ui.painter_at(rect);
        if let Some((_, t)) = &self.slice {
            painter.image(t.id(), rect, Rect::from_min_max(pos2(0.0, 0.0), pos2(1.0, 1.0)), Color32::WHITE);
        }
        // The picked point's (θ_h, θ_d) for this light.
        let a = Angles::of(pick.n, pick.v, l);
        let at = pos2(
            rect.left() + (a.theta_h / 90.0) as f32 * rect.width(),
            rect.top() + (a.theta_d / 90.0) as f32 * rect.height(),
        );
        painter.circle_stroke(at, 5.0, Stroke::new(2.0, Color32::WHITE));
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

/// The polar plot: N up, the surface along the bottom edge, L's direction and V's projection into
/// the plane as lines, each curve at radius value/max along its direction.
fn polar_plot(ui: &mut egui::Ui, lobe: &Lobe, pick: &Pick, l: glam::DVec3) {
    let (rect, _) = ui.allocate_exact_size(vec2(PLOT_SIDE, PLOT_SIDE / 2.0 + 12.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    let centre = pos2(rect.center().x, rect.bottom() - 6.0);
    let radius = PLOT_SIDE / 2.0 - 6.0;
    let at = |theta_deg: f64, r: f64| -> Pos2 {
        let t = theta_deg.to_radians();
        centre + vec2((t.sin() * r) as f32, -(t.cos() * r) as f32) * radius
    };
    let grid = Stroke::new(1.0, Color32::from_gray(70));
    painter.line_segment([at(-90.0, 1.0), at(90.0, 1.0)], grid);
    for r in [0.5, 1.0] {
        painter.add(egui::Shape::line((0..=36).map(|k| at(-90.0 + 5.0 * k as f64, r)).collect(), grid));
    }
    painter.line_segment([centre, at(0.0, 1.0)], grid);
    // L on its side (negative θ), V where it leaves the plane's projection.
    let theta_l = -(pick.n.dot(l).clamp(-1.0, 1.0).acos().to_degrees());
    painter.line_segment([centre, at(theta_l, 1.0)], Stroke::new(2.0, Color32::from_rgb(255, 230, 120)));
    let t = plane_direction(pick.n, l, 90.0);
    let theta_v = pick.v.dot(t).atan2(pick.v.dot(pick.n)).to_degrees();
    painter.line_segment([centre, at(theta_v, 1.0)], Stroke::new(2.0, Color32::WHITE));
    for (k, (_, color)) in CURVES.iter().enumerate() {
        let values = curve(lobe, k);
        let max = values.iter().cloned().fold(0.0, f64::max);
        if max <= 0.0 || !max.is_finite() {
            continue;
        }
        let points: Vec<Pos2> = lobe.theta.iter().zip(values).map(|(th, v)| at(*th, v / max)).collect();
        painter.add(egui::Shape::line(points, Stroke::new(1.5, *color)));
    }
}
