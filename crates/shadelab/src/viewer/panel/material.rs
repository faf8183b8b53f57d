//! The panel's material section: which material, its μ presets, m, h, μ, colour and shares, and
//! the scene's ambient intensity.

use super::{named_slider, slider, tooltip};
use crate::viewer::Viewer;
use eframe::egui;
use shadelab_model::PhongExponent;
use shadelab_model::params;
use shadelab_model::presets::PRESETS;

impl Viewer {
    pub(super) fn material_ui(&mut self, ui: &mut egui::Ui) {
        let names: Vec<String> = self.scene.materials.iter().map(|m| m.name.clone()).collect();
        self.selected_material = self.selected_material.min(names.len().saturating_sub(1));
        egui::ComboBox::from_label("material").selected_text(&names[self.selected_material]).show_ui(ui, |ui| {
            for (i, n) in names.iter().enumerate() {
                ui.selectable_value(&mut self.selected_material, i, n);
            }
        });
        let mat = &mut self.scene.materials[self.selected_material];
        ui.horizontal_wrapped(|ui| {
            ui.label("μ presets:");
            for p in PRESETS {
                let tip = format!("μ = ({:.3}, {:.3}, {:.3}) — {}", p.mu[0], p.mu[1], p.mu[2], p.source);
                if ui.button(p.name).on_hover_text(tip).clicked() {
                    mat.mu = p.mu;
                    mat.color = p.color;
                    mat.r_d = if p.metal { 0.1 } else { 0.8 };
                }
            }
        });
        ui.small(format!("μ = ({:.3}, {:.3}, {:.3})", mat.mu[0], mat.mu[1], mat.mu[2]));
        if let Some(line) = textures_line(mat) {
            ui.small(line).on_hover_text(
                "Textures scale these parameters per pixel (docs/textures.md); the sliders set what they scale. \
                 Metallic–roughness, occlusion and normal textures are drawn in Phong shading.",
            );
        }
        slider(ui, &mut mat.m, &params::M, false);
        let cook_torrance = self.settings.specular == shadelab_model::SpecularModel::CookTorrance;
        super::microfacet::microfacet_ui(ui, &mut self.scene.materials, self.selected_material, cook_torrance);
        let mat = &mut self.scene.materials[self.selected_material];
        let mut mirror = mat.h.is_mirror();
        let mut h = mat.h.value();
        ui.horizontal(|ui| {
            ui.add_enabled(
                !mirror,
                egui::Slider::new(&mut h, params::H.min..=params::H.max).logarithmic(true).text("h"),
            )
            .on_hover_text(tooltip(&params::H));
            ui.checkbox(&mut mirror, "mirror").on_hover_text("h = ∞: a perfect mirror");
            ui.checkbox(&mut mat.phong_normalized, "normalized").on_hover_text(
                "Phong's lobe × (h + 1)/2, so that it reflects all it receives at normal view (docs/model.md §3)",
            );
        });
        mat.h = if mirror { PhongExponent::Mirror } else { PhongExponent::Finite(h) };
        ui.checkbox(&mut self.mu_linked, "μ linked (one value for R, G, B)");
        if self.mu_linked {
            let mut v = mat.mu[0];
            if slider(ui, &mut v, &params::MU, false) {
                mat.mu = [v; 3];
            }
        } else {
            for (c, name) in mat.mu.iter_mut().zip(["μ R", "μ G", "μ B"]) {
                ui.add(egui::Slider::new(c, params::MU.min..=params::MU.max).text(name))
                    .on_hover_text(tooltip(&params::MU));
            }
        }
        ui.horizontal(|ui| {
            let mut c = mat.color.map(|v| v as f32);
            ui.label("C").on_hover_text("surface colour C (linear RGB)");
            if ui.color_edit_button_rgb(&mut c).changed() {
                mat.color = c.map(f64::from);
            }
        });
        for (v, name, meaning) in [
            (&mut mat.r_s, "r_s", "specular share r_s"),
            (&mut mat.r_d, "r_d", "diffuse share r_d"),
            (&mut mat.r_a, "r_a", "ambient reflectance r_a"),
        ] {
            named_slider(ui, v, &params::UNIT, name, meaning);
        }
        let mut amb = self.scene.ambient[0];
        if named_slider(ui, &mut amb, &params::UNIT, "I_amb", "ambient intensity I_amb of the scene") {
            self.scene.ambient = [amb; 3];
        }
    }
}

/// The material's textures and emission, one short line (`None`: it has neither).
fn textures_line(m: &shadelab_model::Material) -> Option<String> {
    let maps = &m.maps;
    let names: Vec<&str> = [
        (m.base_color_texture.is_some(), "base colour"),
        (maps.metal_roughness.is_some(), "metallic–roughness"),
        (maps.occlusion.is_some(), "occlusion"),
        (maps.emissive.is_some(), "emissive"),
        (maps.normal.is_some(), "normal"),
    ]
    .into_iter()
    .filter_map(|(has, name)| has.then_some(name))
    .collect();
    let emits = m.emission.iter().any(|e| *e > 0.0);
    let e = m.emission;
    match (names.is_empty(), emits) {
        (true, false) => None,
        (true, true) => Some(format!("emits I_e = ({:.2}, {:.2}, {:.2})", e[0], e[1], e[2])),
        (false, false) => Some(format!("textures: {}", names.join(", "))),
        (false, true) => {
            Some(format!("textures: {}; emits I_e = ({:.2}, {:.2}, {:.2})", names.join(", "), e[0], e[1], e[2]))
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_textures_line_names_each_texture_and_the_emission() {
        let s = shadelab_model::assets::textured_floor();
        let floor = s.objects.iter().find(|o| matches!(o.shape, shadelab_model::Shape::Mesh(_))).unwrap();
        assert_eq!(
            super::textures_line(&s.materials[floor.material]).as_deref(),
            Some(
                "textures: base colour, metallic–roughness, occlusion, emissive, normal; emits I_e = (0.30, 0.15, 0.05)"
            )
        );
        assert_eq!(super::textures_line(&shadelab_model::Material::default()), None);
    }
}
