//! The panel's transparency section (docs/transparency.md): the selected material's transmitted
//! share τ, refractive index and absorption; the scene's absorption choice; what transparent
//! objects show and where their exit is found.

use super::{slider, tooltip};
use crate::viewer::Viewer;
use eframe::egui;
use shadelab_model::lighting::transmission::{AbsorptionChoice, GlassExit, GlassView};
use shadelab_model::params::{self, NamedValue};

impl Viewer {
    pub(super) fn glass_ui(&mut self, ui: &mut egui::Ui) {
        let mat = &mut self.scene.materials[self.selected_material];
        slider(ui, &mut mat.transmission, &params::TRANSMISSION, false);
        if mat.transmission == 0.0 {
            ui.small("opaque (τ = 0): raise it to draw the material as glass");
            return;
        }
        let mut given = mat.ior.is_some();
        ui.checkbox(&mut given, "index v given (else from μ)").on_hover_text(tooltip(&params::IOR));
        if given {
            let mut v = mat.ior.unwrap_or(mat.refractive_index()).map(|x| x.clamp(params::IOR.min, params::IOR.max));
            for (c, name) in v.iter_mut().zip(["v R", "v G", "v B"]) {
                ui.add(egui::Slider::new(c, params::IOR.min..=params::IOR.max).text(name))
                    .on_hover_text("channels that differ disperse: each bends by its own index");
            }
            mat.ior = Some(v);
        } else {
            mat.ior = None;
            let v = mat.refractive_index();
            ui.small(format!("v = (1 + √μ)/(1 − √μ) = ({:.3}, {:.3}, {:.3})", v[0], v[1], v[2]));
        }
        for (c, name) in mat.absorption.iter_mut().zip(["a R", "a G", "a B"]) {
            ui.add(egui::Slider::new(c, params::ABSORPTION.min..=params::ABSORPTION.max).logarithmic(true).text(name))
                .on_hover_text(tooltip(&params::ABSORPTION));
        }
        ui.horizontal(|ui| {
            ui.label("absorption").on_hover_text(
                "exact: e^(−a·d) everywhere; rule: the chapter's rule picks each object's form from its largest a·d \
                 (neglected below 0.2, 1 − a·d below 0.5)",
            );
            for (name, choice) in AbsorptionChoice::ALL {
                ui.radio_value(&mut self.scene.absorption, *choice, *name);
            }
        });
        ui.horizontal(|ui| {
            ui.label("show");
            egui::ComboBox::from_id_salt("glass view").selected_text(self.settings.glass_view.name()).show_ui(
                ui,
                |ui| {
                    for (name, view) in GlassView::ALL {
                        ui.selectable_value(&mut self.settings.glass_view, *view, *name);
                    }
                },
            );
            egui::ComboBox::from_id_salt("glass exit").selected_text(self.settings.glass_exit.name()).show_ui(
                ui,
                |ui| {
                    for (name, exit) in GlassExit::ALL {
                        ui.selectable_value(&mut self.settings.glass_exit, *exit, *name);
                    }
                },
            );
        })
        .response
        .on_hover_text(
            "show: the colour, the total-internal-reflection mask (red), the path length inside (white at the \
             object's longest chord) or the rule's regime (green neglected, yellow 1 − a·d, red exact); \
             exit: exact for the built-in shapes, or from the back faces",
        );
    }
}
