//! The panel's effects: the pipeline being compiled or last built, and the effects the scene
//! calls for with their reasons (the same analysis as `render --explain`).

use super::shading_meaning;
use crate::viewer::Viewer;
use eframe::egui::{self, Color32};

/// How often the panel looks again while a pipeline compiles on its worker thread.
const BUILD_POLL: std::time::Duration = std::time::Duration::from_millis(50);

impl Viewer {
    pub(super) fn effects_ui(&mut self, ui: &mut egui::Ui) {
        // The frame as the view draws it (derive.rs): its analysis and program, derived once.
        let Some(size) = self.view.as_ref().map(|v| (v.target.width, v.target.height)) else { return };
        let frame = self.derived.get(&self.scene, &self.settings, self.term, size);
        let (analysis, drawn) = (frame.analysis.clone(), frame.program.effects());
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
