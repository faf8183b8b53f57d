//! The panel's files row: a path field with "open" and "save scene", and the dialog buttons.

use crate::viewer::{FileRequest, Viewer};
use eframe::egui;
use std::path::PathBuf;

impl Viewer {
    pub(super) fn files_row_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.add(
                egui::TextEdit::singleline(&mut self.file_field).desired_width(170.0).hint_text("scene.gltf / .glb"),
            )
            .on_hover_text("a glTF 2.0 file to open (or drop a file on the window)");
            if ui.button("open").on_hover_text("open the file named in the field").clicked() {
                let p = PathBuf::from(self.file_field.trim());
                self.open_file(&p);
            }
            if ui.button("save scene").on_hover_text("write the scene as shown to this .gltf/.glb path").clicked() {
                let name = self.file_field.trim();
                let p = if name.is_empty() { PathBuf::from("shadelab-scene.gltf") } else { PathBuf::from(name) };
                self.save_scene(&p);
            }
        });
        ui.horizontal(|ui| {
            let idle = self.picking.is_none();
            if ui
                .add_enabled(idle, egui::Button::new("open…"))
                .on_hover_text("choose a glTF file in a dialog")
                .clicked()
            {
                self.ask_for_file(FileRequest::Open);
            }
            if ui
                .add_enabled(idle, egui::Button::new("save as…"))
                .on_hover_text("choose where to save the scene as shown (.gltf or .glb)")
                .clicked()
            {
                self.ask_for_file(FileRequest::Save);
            }
            if !idle {
                ui.spinner();
            }
        });
        self.loading_ui(ui);
    }
}
