//! The parameter panel at the side, section by section (scene and modes, files, material,
//! transparency, lights, the environment, live numbers, the effects called for). It edits the model and the render settings,
//! never wgpu objects; every slider takes its range from the parameter's declared range.

mod effects;
mod environment;
mod files_row;
mod glass;
mod lights;
mod live;
mod material;
mod microfacet;
mod scene;

use super::Viewer;
use eframe::egui::{self, Color32};
use glam::DVec3;
use shadelab_model::ShadingMode;
use shadelab_model::params::ParamRange;

/// How far from the origin the panel places a light, per coordinate (scene units): the built-in
/// scenes span a few units, and a file's lights may be placed a little wider.
const POSITION_LIMIT: f64 = 50.0;
/// Scene units per point dragged on a position or direction field.
const POSITION_DRAG_SPEED: f64 = 0.05;

impl Viewer {
    pub(super) fn panel(&mut self, ui: &mut egui::Ui) {
        ui.heading("shadelab");
        if let Some((msg, err)) = &self.message {
            let text = egui::RichText::new(msg).color(if *err { Color32::LIGHT_RED } else { Color32::LIGHT_GREEN });
            ui.label(if *err { text.monospace() } else { text });
        }
        self.scene_ui(ui);
        self.files_row_ui(ui);
        self.modes_ui(ui);
        ui.separator();
        self.material_ui(ui);
        ui.separator();
        self.lights_ui(ui);
        egui::CollapsingHeader::new("environment light")
            .default_open(self.scene.environment.is_some())
            .show(ui, |ui| self.environment_ui(ui));
        ui.separator();
        // The selected material's transparency: open where some material lets light through.
        egui::CollapsingHeader::new("transparency")
            .default_open(self.scene.materials.iter().any(|m| m.transmits()))
            .show(ui, |ui| self.glass_ui(ui));
        self.live_numbers_ui(ui);
        self.effects_ui(ui);
        self.view_actions_ui(ui);
    }

    /// "copy link" (in the browser): the view on show as a link to the page (`viewer/link.rs`),
    /// to the clipboard and under the button.
    #[cfg(target_arch = "wasm32")]
    pub(super) fn copy_link_ui(&mut self, ui: &mut egui::Ui) {
        let r = ui
            .button("copy link")
            .on_hover_text("copy a link that opens this view in shadelab's web page: the scene, its edits, the camera, the modes and the switches");
        self.mark("copy link", &r);
        if r.clicked() {
            let (link, note) = self.link(&super::web::page_address());
            ui.ctx().copy_text(link.clone());
            self.copied_link = Some((link, note));
        }
    }

    /// The link "copy link" wrote last, under the files row.
    pub(super) fn copied_link_ui(&self, ui: &mut egui::Ui) {
        if let Some((link, note)) = &self.copied_link {
            ui.add(egui::Label::new(egui::RichText::new(link).small().monospace()).wrap());
            if let Some(note) = note {
                ui.small(note);
            }
        }
    }

    /// The view's buttons (screenshot, camera reset) and the keys and pointer gestures.
    fn view_actions_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            if ui.button("screenshot (F12)").on_hover_text("save the view as PNG at its resolution").clicked() {
                self.save_view_png();
            }
            if ui.button("reset camera").on_hover_text("or double-click the view").clicked() {
                self.orbit = super::orbit::Orbit::from_camera(&self.base_camera);
            }
        });
        #[cfg(target_arch = "wasm32")]
        ui.small(
            "in the browser: the reference is traced a few rows a frame on the page's one thread; a file \
             opens a stage a frame",
        );
        ui.small("drag: orbit · right/middle drag: pan · wheel: zoom · 1/2/3: shading · S: specular · F12: screenshot");
    }
}

/// A row of three drag values for a vector (a light's position or direction).
fn vec3_row(ui: &mut egui::Ui, label: &str, v: &mut DVec3) {
    ui.horizontal(|ui| {
        ui.label(label);
        for c in [&mut v.x, &mut v.y, &mut v.z] {
            ui.add(egui::DragValue::new(c).speed(POSITION_DRAG_SPEED).range(-POSITION_LIMIT..=POSITION_LIMIT));
        }
    });
}

/// A parameter's symbol, meaning and range, as its slider's tooltip.
fn tooltip(r: &ParamRange) -> String {
    format!("{} — {}, in [{}, {}]", r.symbol, r.meaning, r.min, r.max)
}

/// A slider over a parameter's declared range, with its symbol and meaning as tooltip.
fn slider(ui: &mut egui::Ui, v: &mut f64, r: &ParamRange, log: bool) -> bool {
    ui.add(egui::Slider::new(v, r.min..=r.max).logarithmic(log).text(r.symbol)).on_hover_text(tooltip(r)).changed()
}

/// A slider over a parameter's declared range, labelled `name` and explained by `meaning`.
fn named_slider(ui: &mut egui::Ui, v: &mut f64, r: &ParamRange, name: &str, meaning: &str) -> bool {
    ui.add(egui::Slider::new(v, r.min..=r.max).text(name)).on_hover_text(meaning).changed()
}

/// What a shading mode does, for its tooltip and the effects list.
fn shading_meaning(m: ShadingMode) -> &'static str {
    match m {
        ShadingMode::Flat => "flat: one normal and one colour per face, lit at its centroid",
        ShadingMode::Gouraud => "Gouraud: lit at the vertices, colour interpolated",
        ShadingMode::Phong => "Phong shading: normals interpolated and renormalized, lit per pixel",
    }
}
