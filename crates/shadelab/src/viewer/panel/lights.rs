//! The panel's lights section: add and remove lights, and per light its kind, position or
//! direction, colour and intensity, falloff, range, spot cones, shadow settings and a view of
//! the light's shadow map.

use super::{slider, tooltip, vec3_row};
use crate::viewer::Viewer;
use crate::viewer::shadow_maps::{SHADOW_MAP_SHOWN_POINTS, ShadowMapViews};
use eframe::egui;
use glam::DVec3;
use shadelab_model::params::{self, NamedValue};
use shadelab_model::scene::MAX_LIGHTS;
use shadelab_model::shadows::{SHADOW_RESOLUTION, ShadowFilter, ShadowSettings, drawn_layers};
use shadelab_model::{AreaSpecular, FalloffForm, Light, LightKind};

/// Where a light's range starts when it is switched on, scene units: beyond the built-in scenes,
/// so the light changes little until the slider moves.
const RANGE_SWITCHED_ON: f64 = 10.0;

impl Viewer {
    pub(super) fn lights_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.strong(format!("lights ({}/{MAX_LIGHTS})", self.scene.lights.len()));
            if ui.add_enabled(self.scene.lights.len() < MAX_LIGHTS, egui::Button::new("add")).clicked() {
                self.scene.lights.push(super::super::link_scene::added_light());
            }
        });
        let mut remove = None;
        // Each light's layers drawn this frame (a cube's faces, a directional light's cascades), for
        // the map's layer menu.
        let layers: Vec<u32> = self.scene.lights.iter().map(|l| drawn_layers(&self.scene, l)).collect();
        for (i, l) in self.scene.lights.iter_mut().enumerate() {
            egui::CollapsingHeader::new(format!("L{} — {}", i + 1, l.kind.name())).id_salt(i).show(ui, |ui| {
                if light_ui(ui, i, l, layers[i].max(1), &mut self.shadow_maps) {
                    remove = Some(i);
                }
            });
        }
        if let Some(i) = remove {
            self.scene.lights.remove(i);
        }
    }
}

/// Light `i`'s section: kind, position or direction, size, colour and intensity, falloff and
/// range, spot cones, shadow settings and map. True when its "remove" button was clicked.
fn light_ui(ui: &mut egui::Ui, i: usize, l: &mut Light, layers: u32, maps: &mut ShadowMapViews) -> bool {
    let removed = light_kind_row(ui, l);
    let positional = !l.kind.is_directional();
    if positional {
        vec3_row(ui, "position", &mut l.position);
    }
    if let Some(name) = l.kind.direction_name() {
        vec3_row(ui, name, &mut l.direction);
        l.direction = l.direction.normalize_or(DVec3::NEG_Y);
    }
    if l.kind.is_area() {
        area_light_ui(ui, l);
    }
    ui.horizontal(|ui| {
        let mut c = l.color.map(|v| v as f32);
        if ui.color_edit_button_rgb(&mut c).changed() {
            l.color = c.map(f64::from);
        }
        slider(ui, &mut l.intensity, &params::INTENSITY, true);
    });
    if positional {
        falloff_ui(ui, l);
    }
    if l.kind.has_cone() {
        spot_cone_ui(ui, l);
    }
    shadow_ui(ui, i, l.kind.is_directional(), &mut l.shadow);
    shadow_map_ui(ui, i, l.kind, layers, maps);
    removed
}

/// The light's kind, one button each (with what the less familiar ones mean), and "remove":
/// true when that was clicked.
fn light_kind_row(ui: &mut egui::Ui, l: &mut Light) -> bool {
    let mut removed = false;
    ui.horizontal(|ui| {
        let mut kind = l.kind;
        for (name, k) in LightKind::ALL {
            let choice = ui.selectable_value(&mut kind, *k, *name);
            let meaning = k.meaning();
            if let Some(m) = meaning {
                choice.on_hover_text(m);
            }
        }
        l.set_kind(kind);
        if ui.button("remove").clicked() {
            removed = true;
        }
    });
    removed
}

/// An area light's size, how many point sources draw it, and how its specular is drawn.
fn area_light_ui(ui: &mut egui::Ui, l: &mut Light) {
    // A rectangle has a width and a height; a disk or sphere one diameter.
    let (w, h) = l.kind.size_names().unwrap_or(("diameter", None));
    let (w, h) = (format!("{w} m"), h.map(|h| format!("{h} m")));
    ui.add(
        egui::Slider::new(&mut l.size[0], params::LIGHT_SIZE.min..=params::LIGHT_SIZE.max).logarithmic(true).text(w),
    )
    .on_hover_text(tooltip(&params::LIGHT_SIZE));
    match h {
        Some(h) => {
            ui.add(
                egui::Slider::new(&mut l.size[1], params::LIGHT_SIZE.min..=params::LIGHT_SIZE.max)
                    .logarithmic(true)
                    .text(h),
            )
            .on_hover_text(tooltip(&params::LIGHT_SIZE));
        }
        None => l.size[1] = l.size[0],
    }
    // 0: the exact area form; k: the chapter's k point sources, to show what it
    // calls unnatural (k = 1) and how k hard shadows converge to the penumbra.
    ui.add(egui::Slider::new(&mut l.area_points, 0..=params::AREA_POINTS.max as u32).text("points k (0 = exact)"))
        .on_hover_text(tooltip(&params::AREA_POINTS));
    // The specular of the exact form: at one point, or the lobe integrated over the light.
    ui.add_enabled_ui(l.area_points == 0, |ui| {
        ui.horizontal(|ui| {
            ui.label("specular");
            ui.selectable_value(&mut l.area_specular, AreaSpecular::Representative, "representative point")
                .on_hover_text("the point light at the light's point nearest the mirror direction, its peak widened");
            ui.selectable_value(&mut l.area_specular, AreaSpecular::Ltc, "LTC").on_hover_text(
                "Cook–Torrance's lobe integrated over the light by its fitted linearly transformed cosine (Phong's lobe keeps the representative point)",
            );
        });
    });
}

/// A point or spot light's falloff form with its parameter, and its range.
fn falloff_ui(ui: &mut egui::Ui, l: &mut Light) {
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

/// A spot light's outer and inner cones.
fn spot_cone_ui(ui: &mut egui::Ui, l: &mut Light) {
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

/// One light's shadow settings: whether it casts, its shadow map's side (the powers of two in
/// `SHADOW_RESOLUTION`; a file's other side is shown as it is until changed), its filter, and
/// for a directional light whether it may use cascades.
fn shadow_ui(ui: &mut egui::Ui, light: usize, directional: bool, shadow: &mut ShadowSettings) {
    ui.horizontal(|ui| {
        ui.checkbox(&mut shadow.casts, "casts shadows")
            .on_hover_text("the light's shadow map hides what another object blocks from it (when the scene has any)");
        ui.add_enabled_ui(shadow.casts, |ui| {
            egui::ComboBox::from_id_salt(("shadow resolution", light))
                .selected_text(format!("{} px", shadow.resolution))
                .show_ui(ui, |ui| {
                    for side in shadow_sides() {
                        ui.selectable_value(&mut shadow.resolution, side, format!("{side} px"));
                    }
                })
                .response
                .on_hover_text(format!(
                    "{} — {}, in [{}, {}]: finer edges, more memory and time",
                    SHADOW_RESOLUTION.symbol, SHADOW_RESOLUTION.meaning, SHADOW_RESOLUTION.min, SHADOW_RESOLUTION.max
                ));
            egui::ComboBox::from_id_salt(("shadow filter", light))
                .selected_text(shadow.filter.name())
                .show_ui(ui, |ui| {
                    for (name, f) in ShadowFilter::ALL {
                        ui.selectable_value(&mut shadow.filter, *f, *name).on_hover_text(filter_meaning(*f));
                    }
                })
                .response
                .on_hover_text(format!("shadow filter: {}", filter_meaning(shadow.filter)));
            if shadow.filter == ShadowFilter::Pcss {
                let taps = shadelab_model::shadows::PCSS_TAPS;
                ui.add(egui::Slider::new(&mut shadow.pcss_taps, taps.min as u32..=taps.max as u32).text("taps"))
                    .on_hover_text(format!("{}: {}, in [{}, {}]", taps.symbol, taps.meaning, taps.min, taps.max));
            }
            if directional {
                ui.checkbox(&mut shadow.cascades, "cascades").on_hover_text(
                    "split the map along the view's depth when the objects in view span a depth ratio over 8, \
                     finest near the camera",
                );
            }
        });
    });
}

/// The "show shadow map" box, a menu of the map's `layers` (a point light's six faces, a
/// directional light's cascades), and the map as grey (nearest black, empty white) once the view
/// has read it back.
fn shadow_map_ui(ui: &mut egui::Ui, light: usize, kind: LightKind, layers: u32, maps: &mut ShadowMapViews) {
    let mut on = maps.is_on(light);
    ui.horizontal(|ui| {
        ui.checkbox(&mut on, "show shadow map")
            .on_hover_text("the depth the light sees, as grey: near black, far light grey, nothing drawn white");
        maps.set(light, on);
        if let Some(view) = maps.view_mut(light)
            && kind.has_cube_map()
        {
            egui::ComboBox::from_id_salt(("shadow map face", light))
                .selected_text(CUBE_FACES[view.face.min(5) as usize])
                .show_ui(ui, |ui| {
                    for (f, name) in CUBE_FACES.iter().enumerate() {
                        ui.selectable_value(&mut view.face, f as u32, *name);
                    }
                })
                .response
                .on_hover_text("which of the point light's six cube faces");
        } else if let Some(view) = maps.view_mut(light)
            && layers > 1
        {
            view.face = view.face.min(layers - 1);
            egui::ComboBox::from_id_salt(("shadow map cascade", light))
                .selected_text(format!("cascade {}", view.face + 1))
                .show_ui(ui, |ui| {
                    for c in 0..layers {
                        ui.selectable_value(&mut view.face, c, format!("cascade {}", c + 1));
                    }
                })
                .response
                .on_hover_text("which of the directional light's cascades, 1 nearest the camera (the finest)");
        } else if let Some(view) = maps.view_mut(light) {
            view.face = 0;
        }
    });
    match maps.texture(light) {
        Some(Some(t)) => {
            let [w, h] = t.size();
            let side = SHADOW_MAP_SHOWN_POINTS;
            ui.image((t.id(), egui::vec2(side, side * h as f32 / w.max(1) as f32)))
                .on_hover_text(format!("{w} × {h} texels"));
        }
        Some(None) => {
            ui.small("no shadow map: the light casts none here (nothing it could hide from another surface)");
        }
        None if on => {
            ui.small("reading the shadow map…");
        }
        None => {}
    }
}

/// A point light's cube faces in layer order (+x, −x, +y, −y, +z, −z).
const CUBE_FACES: [&str; 6] = ["face +x", "face −x", "face +y", "face −y", "face +z", "face −z"];

/// The powers of two within `SHADOW_RESOLUTION` (256, 512, …, 4096).
fn shadow_sides() -> impl Iterator<Item = u32> {
    let (lo, hi) = (SHADOW_RESOLUTION.min as u32, SHADOW_RESOLUTION.max as u32);
    (0..u32::BITS).map(|k| 1u32 << k).filter(move |side| (lo..=hi).contains(side))
}

/// What a filter does, for its tooltip.
fn filter_meaning(f: ShadowFilter) -> &'static str {
    match f {
        ShadowFilter::Hard => "one comparison at the nearest texel: a hard, aliased edge",
        ShadowFilter::Pcf => "the hardware's 2×2 comparison: an edge softened over one texel",
        ShadowFilter::Poisson => "rotated Poisson-disk taps: a wider, smoother edge, at more samples per pixel",
        ShadowFilter::Pcss => {
            "percentage-closer soft shadows: an area light's penumbra, as wide as the light's size and \
             the occluder's and receiver's distances make it (a light without an area: pcf)"
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn shadow_sides_are_the_powers_of_two_in_the_range() {
        assert_eq!(super::shadow_sides().collect::<Vec<_>>(), [256, 512, 1024, 2048, 4096]);
    }
}
