//! The panel's live numbers: the scene pass's time and the frame interval (hidden for snapshot
//! tests, where they differ every run), the scene's size, and continuous rendering.

use crate::viewer::Viewer;
use eframe::egui;
use shadelab_render::timing::TimeSource;

/// Smallest frame interval the fps is computed from, seconds (the first frame reports 0).
const FRAME_INTERVAL_MIN: f32 = 1e-6;

impl Viewer {
    pub(super) fn live_numbers_ui(&mut self, ui: &mut egui::Ui) {
        let source = match self.timer.source() {
            TimeSource::GpuTimestamps => "GPU, timestamps",
            // The browser cannot wait for the GPU: its CPU figure is the submit alone.
            TimeSource::CpuSubmitWait if cfg!(target_arch = "wasm32") => {
                "CPU, submit only: a page cannot wait for the GPU"
            }
            TimeSource::CpuSubmitWait => "CPU, submit+wait",
        };
        if self.show_live_numbers {
            if let Some(ms) = self.frame_ms {
                ui.label(format!("scene pass: {ms:.2} ms ({source})"));
            }
            let dt = ui.input(|i| i.unstable_dt).max(FRAME_INTERVAL_MIN);
            ui.label(format!("frame interval: {:.1} ms ({:.0} fps)", dt * 1e3, 1.0 / dt));
        } else {
            ui.label(format!("scene pass: — ms ({source})"));
        }
        ui.label(format!("adapter: {}", self.adapter));
        let per_second = self.derived.per_second();
        ui.label(format!("frame derived {} times ({per_second} in the last second)", self.derived.count()))
            .on_hover_text("the effect analysis, the program and the uniforms: derived again only when the scene, the settings, the term or the view's size change");
        ui.label(format!(
            "{} triangles, {} lights, {} pipelines built",
            self.gpu_scene.triangle_count,
            self.scene.lights.len(),
            self.renderer.pipelines.pipeline_builds
        ));
        ui.checkbox(&mut self.continuous, "render continuously (for live timing)");
    }
}
