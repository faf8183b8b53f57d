//! The panel's effects: the pipeline being compiled or last built, and the effects the scene
//! calls for with their reasons (the same analysis as `render --explain`).

use super::shading_meaning;
use crate::viewer::Viewer;
use eframe::egui::{self, Color32};
use shadelab_render::Program;

/// How often the panel looks again while a pipeline compiles on its worker thread.
const BUILD_POLL: std::time::Duration = std::time::Duration::from_millis(50);

impl Viewer {
    pub(super) fn effects_ui(&mut self, ui: &mut egui::Ui) {
        // The lights as the last frame drew them: small area lights as point lights.
        let lights = self.scene.lights.clone();
        if let Some(view) = &self.view {
            shadelab_model::effects::draw_small_area_lights_as_points(&mut self.scene, view.target.height);
        }
        let analysis = shadelab_model::effects::analyze(&self.scene, self.settings.specular);
        let drawn = Program::for_scene(&self.scene, &self.settings).effects();
        self.scene.lights = lights;
        if self.renderer.pipelines.building() {
            ui.label(
                egui::RichText::new(format!("compiling pipeline [{}]… drawn with the uber pipeline", drawn.label()))
                    .color(Color32::YELLOW),
            );
            ui.ctx().request_repaint_after(BUILD_POLL);
        } else if let Some((key, took)) = self.renderer.pipelines.last_build
            && self.show_live_numbers
        {
            ui.small(format!(
                "last pipeline built: [{}] in {:.0} ms",
                key.program.effects().label(),
                took.as_secs_f64() * 1e3
            ));
        }
        for line in &self.small_area_lights {
            ui.small(line);
        }
        egui::CollapsingHeader::new("effects called for").default_open(false).show(ui, |ui| {
            ui.small(format!("pipeline [{}]", analysis.key.label()));
            ui.small(shading_meaning(self.settings.shading));
            for line in analysis.lines() {
                ui.label(format!("• {line}"));
            }
        });
    }
}
