//! The panel's lights section: add and remove lights, and per light its kind, position or
//! direction, colour and intensity, falloff, range and spot cones.

use super::{slider, tooltip, vec3_row};
use crate::viewer::Viewer;
use eframe::egui;
use glam::DVec3;
use shadelab_model::params::{self, NamedValue};
use shadelab_model::scene::MAX_LIGHTS;
use shadelab_model::{FalloffForm, Light, LightKind};

/// Where a light's range starts when it is switched on, scene units: beyond the built-in scenes,
/// so the light changes little until the slider moves.
const RANGE_SWITCHED_ON: f64 = 10.0;

impl Viewer {
    pub(super) fn lights_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.strong(format!("lights ({}/{MAX_LIGHTS})", self.scene.lights.len()));
            if ui.add_enabled(self.scene.lights.len() < MAX_LIGHTS, egui::Button::new("add")).clicked() {
                self.scene.lights.push(Light::point(DVec3::new(2.0, 2.5, 2.0), [1.0; 3], 1.0, 0.05));
            }
        });
        let mut remove = None;
        for (i, l) in self.scene.lights.iter_mut().enumerate() {
            egui::CollapsingHeader::new(format!("L{} — {}", i + 1, l.kind.name())).id_salt(i).show(ui, |ui| {
                ui.horizontal(|ui| {
                    let mut kind = l.kind;
                    for (name, k) in LightKind::ALL {
                        let choice = ui.selectable_value(&mut kind, *k, *name);
                        if *k == LightKind::Spot {
                            choice.on_hover_text("a point light that lights only a cone (glTF's spot light)");
                        }
                    }
                    l.set_kind(kind);
                    if ui.button("remove").clicked() {
                        remove = Some(i);
                    }
                });
                let positional = l.kind != LightKind::Directional;
                if positional {
                    vec3_row(ui, "position", &mut l.position);
                }
                if l.kind != LightKind::Point {
                    vec3_row(ui, if positional { "axis" } else { "direction" }, &mut l.direction);
                    l.direction = l.direction.normalize_or(DVec3::NEG_Y);
                }
                ui.horizontal(|ui| {
                    let mut c = l.color.map(|v| v as f32);
                    if ui.color_edit_button_rgb(&mut c).changed() {
                        l.color = c.map(f64::from);
                    }
                    slider(ui, &mut l.intensity, &params::INTENSITY, true);
                });
                if positional {
                    ui.horizontal(|ui| {
                        ui.selectable_value(&mut l.falloff_form, FalloffForm::Quadratic, "1/(1+αd²)");
                        ui.selectable_value(&mut l.falloff_form, FalloffForm::Linear, "1/(d+d0)");
                    });
                    match l.falloff_form {
                        FalloffForm::Quadratic => slider(ui, &mut l.falloff_alpha, &params::FALLOFF, true),
                        FalloffForm::Linear => slider(ui, &mut l.d0, &params::D0, true),
                    };
                    ui.horizontal(|ui| {
                        let mut ends = l.range.is_some();
                        ui.checkbox(&mut ends, "range")
                            .on_hover_text("the light ends at this distance, fading as glTF's 1 − (d/range)⁴");
                        let mut r = l.range.unwrap_or(RANGE_SWITCHED_ON);
                        if ends {
                            ui.add(egui::Slider::new(&mut r, params::RANGE.min..=params::RANGE.max).logarithmic(true))
                                .on_hover_text(tooltip(&params::RANGE));
                        }
                        l.range = ends.then_some(r);
                    });
                }
                if l.kind == LightKind::Spot {
                    // Degrees on the panel, radians in the model, both in the declared cone range;
                    // the inner cone stays inside the outer (equal cones are the model's hard edge).
                    let cone = params::CONE_ANGLE;
                    let (lowest, widest) = (cone.min.to_degrees(), cone.max.to_degrees());
                    let mut outer = l.outer_cone.to_degrees();
                    let mut inner = l.inner_cone.to_degrees();
                    ui.add(egui::Slider::new(&mut outer, lowest..=widest).text("outer cone °"))
                        .on_hover_text("half-angle beyond which the spot gives no light");
                    ui.add(egui::Slider::new(&mut inner, lowest..=outer).text("inner cone °"))
                        .on_hover_text("half-angle within which the spot gives its full light");
                    l.outer_cone = outer.to_radians().clamp(cone.min, cone.max);
                    l.inner_cone = inner.min(outer).to_radians().max(cone.min).min(l.outer_cone);
                }
            });
        }
        if let Some(i) = remove {
            self.scene.lights.remove(i);
        }
    }
}
