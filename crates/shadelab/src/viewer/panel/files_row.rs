//! The panel's files row: a path field with "open" and "save scene", and the dialog buttons.

use crate::viewer::{FileRequest, Viewer};
use eframe::egui;
#[cfg(not(target_arch = "wasm32"))]
use std::path::PathBuf;

impl Viewer {
    pub(super) fn files_row_ui(&mut self, ui: &mut egui::Ui) {
        // A page cannot read or write paths: its picker and downloads are the buttons below.
        #[cfg(not(target_arch = "wasm32"))]
        ui.horizontal(|ui| {
            ui.add(
                egui::TextEdit::singleline(&mut self.file_field).desired_width(170.0).hint_text("scene.gltf / .glb"),
            )
            .on_hover_text(
                "a glTF 2.0 file to open, or an .hdr/.exr map to light the scene by (or drop a file on the window)",
            );
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
            let (open_tip, save_tip) = if cfg!(target_arch = "wasm32") {
                (
                    "choose a .glb, or a .gltf with its .bin and images, all at once, or an .hdr/.exr environment map (or drop them on the page)",
                    "download the scene as shown as shadelab-scene.glb",
                )
            } else {
                (
                    "choose a glTF file, or an .hdr/.exr environment map, in a dialog",
                    "choose where to save the scene as shown (.gltf or .glb)",
                )
            };
            let open = ui.add_enabled(idle, egui::Button::new("open…")).on_hover_text(open_tip);
            self.mark("open", &open);
            if open.clicked() {
                self.ask_for_file(FileRequest::Open);
            }
            let save = ui.add_enabled(idle, egui::Button::new("save as…")).on_hover_text(save_tip);
            self.mark("save", &save);
            if save.clicked() {
                self.ask_for_file(FileRequest::Save);
            }
            // A link needs the page's address: the desktop has none to give.
            #[cfg(target_arch = "wasm32")]
            self.copy_link_ui(ui);
            // A page reads only the files it is given: paths outside a folder do not arise there.
            #[cfg(not(target_arch = "wasm32"))]
            ui.checkbox(&mut self.allow_outside_paths, "outside paths").on_hover_text(
                "let a file's buffers and images lie outside its folder (absolute paths, '..', links); \
                 off, they are refused (--allow-outside-paths)",
            );
            if !idle {
                ui.spinner();
            }
        });
        self.copied_link_ui(ui);
        self.loading_ui(ui);
    }
}
