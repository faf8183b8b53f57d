//! The panel's scene and modes: the built-in scene and the file's camera to look through, the
//! shading mode, the specular model, the debug and difference views, and the self-shadow
//! boundary over the view; with the difference view, which error map it shows.

use super::shading_meaning;
use crate::viewer::Viewer;
use crate::viewer::difference::{Against, DifferenceKind};
use eframe::egui;
use shadelab_model::params::{self, NamedValue};
use shadelab_model::scene::BUILTIN_SCENES;
use shadelab_model::terms::Term;
use shadelab_model::{IlluminationModel, Interpolation, ModelChoice, Overrides, ShadingMode, SpecularModel};

impl Viewer {
    /// The scene menu, and the camera menu when the scene has several cameras.
    pub(super) fn scene_ui(&mut self, ui: &mut egui::Ui) {
        let mut scene_choice = self.scene_name.clone();
        egui::ComboBox::from_label("scene").selected_text(&scene_choice).show_ui(ui, |ui| {
            for name in BUILTIN_SCENES {
                ui.selectable_value(&mut scene_choice, name.to_string(), *name);
            }
        });
        if scene_choice != self.scene_name {
            self.load_scene(&scene_choice);
        }
        if self.cameras.len() > 1 {
            let mut choice = self.camera_choice;
            egui::ComboBox::from_label("camera").selected_text(&self.cameras[choice].0).show_ui(ui, |ui| {
                for (i, (name, _)) in self.cameras.iter().enumerate() {
                    ui.selectable_value(&mut choice, i, name);
                }
            });
            if choice != self.camera_choice {
                self.choose_camera(choice);
            }
        }
    }

    /// Switch to one of the four models: the scene's illumination model (the four-term sum with
    /// 1/(d + d0) on its point and spot lights), and the specular model the choice fixes; a term
    /// the new model lacks gives way to the whole model.
    pub fn choose_model(&mut self, choice: ModelChoice) {
        let (model, specular) = choice.split();
        self.scene.apply(&Overrides::for_model(choice));
        if let Some(s) = specular {
            self.settings.specular = s;
        }
        if !self.term.in_model(model) {
            self.term = Term::All;
        }
    }

    /// Shading mode, the model and its specular term, the term on show, the non-finite debug paint, the self-shadow boundary and
    /// the difference view.
    pub(super) fn modes_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.label("shading");
            for (i, (name, mode)) in ShadingMode::ALL.iter().enumerate() {
                let r = ui.selectable_value(&mut self.settings.shading, *mode, *name).on_hover_text(format!(
                    "{} (key {})",
                    shading_meaning(*mode),
                    i + 1
                ));
                self.mark(format!("shading:{name}"), &r);
            }
        });
        self.model_ui(ui);
        self.view_options_ui(ui);
        self.difference_ui(ui);
    }

    /// The model menu, the Phong model's specular term and the term on show.
    fn model_ui(&mut self, ui: &mut egui::Ui) {
        let current = ModelChoice::of(self.scene.illumination, self.settings.specular);
        let mut choice = current;
        let marks = &mut self.marks;
        let menu = egui::ComboBox::from_label("model").selected_text(current.label()).show_ui(ui, |ui| {
            for c in ModelChoice::ALL_CHOICES {
                let r = ui.selectable_value(&mut choice, c, c.label()).on_hover_text(c.title());
                marks.insert(format!("model:{}", c.name()), r.rect);
            }
        });
        self.mark("model", &menu.response);
        if choice != current {
            self.choose_model(choice);
        }
        let phong_model = self.scene.illumination == IlluminationModel::Phong;
        ui.add_enabled_ui(phong_model, |ui| {
            ui.horizontal(|ui| {
                ui.label("specular");
                ui.selectable_value(&mut self.settings.specular, SpecularModel::Phong, "Phong (V·R)^h")
                    .on_hover_text("Phong specular: (V·R)^h, the light's colour (key S toggles)");
                ui.selectable_value(&mut self.settings.specular, SpecularModel::CookTorrance, "Cook–Torrance")
                    .on_hover_text(
                        "Cook–Torrance: Beckmann D(m), geometric G, exact Fresnel F(μ) per channel (key S toggles)",
                    );
            })
        })
        .response
        .on_disabled_hover_text("the specular term belongs to the Phong model (phong, cook-torrance)");
        ui.horizontal(|ui| {
            ui.label("term");
            let model = self.scene.illumination;
            let offered: Vec<_> = Term::ALL.iter().filter(|(_, t)| t.in_scene(&self.scene)).collect();
            for (name, term) in offered {
                let r = ui.selectable_value(&mut self.term, *term, term.symbol_in(model)).on_hover_text(term.meaning());
                self.mark(format!("term:{name}"), &r);
            }
        });
    }

    /// Screen-space interpolation, the non-finite paint and the lines drawn over the view.
    fn view_options_ui(&mut self, ui: &mut egui::Ui) {
        let mut screen = self.settings.interpolation == Interpolation::Screen;
        ui.add_enabled(
            self.settings.shading != ShadingMode::Flat,
            egui::Checkbox::new(&mut screen, "chapter's screen-space interpolation"),
        )
        .on_hover_text(
            "interpolate Gouraud's colours and Phong's normals linearly in screen space, along the \
             scanlines as the chapter does, instead of perspective-correctly; the difference view \
             shows what it costs in accuracy",
        )
        .on_disabled_hover_text("flat shading interpolates nothing");
        self.settings.interpolation = if screen { Interpolation::Screen } else { Interpolation::Perspective };
        ui.checkbox(&mut self.settings.debug_nonfinite, "paint non-finite pixels magenta");
        ui.checkbox(&mut self.boundary.enabled, "self-shadow boundary").on_hover_text(
            "draw the edges where the side facing a light changes (N·L changes sign between the \
             two faces), over the view, hidden behind objects",
        );
        ui.horizontal(|ui| {
            ui.checkbox(&mut self.normals.enabled, "vertex normals")
                .on_hover_text("the smooth meshes' vertex normals (Gouraud's and Phong's), yellow");
            ui.checkbox(&mut self.creases.enabled, "creases")
                .on_hover_text("the edges the crease-angle rule keeps sharp (faces more than 60° apart), orange");
        });
    }

    /// The difference view's checkbox and, when it is on, which error map it shows.
    fn difference_ui(&mut self, ui: &mut egui::Ui) {
        let covered = shadelab_model::scene_variants::reference_covers(&self.scene);
        let r = ui.add_enabled(covered, egui::Checkbox::new(&mut self.difference.enabled, "difference from reference"));
        self.mark("difference", &r);
        r.on_hover_text(format!(
            "FLIP error map of this mode against the f64 ray-cast reference of the exact surface \
                 (at most {} px wide), with RMSE and the GPU time",
            crate::viewer::difference::DIFFERENCE_MAX_WIDTH
        ))
        .on_disabled_hover_text(format!(
            "only for scenes of analytic shapes and file meshes of at most {} triangles in all",
            shadelab_model::scene_variants::REFERENCE_MESH_TRIANGLES
        ));
        if self.difference.enabled && covered {
            ui.horizontal(|ui| {
                ui.label("error map");
                ui.selectable_value(&mut self.difference.kind, DifferenceKind::Flip, "FLIP error")
                    .on_hover_text("the FLIP error of this mode's image against the reference (magma scale)");
                ui.selectable_value(&mut self.difference.kind, DifferenceKind::Shadow, "shadow error").on_hover_text(
                    "where the lit/shadowed state disagrees with the reference's exact cast shadows: \
                     this render with shadows against the same with them off, red false shadow, \
                     cyan missed shadow",
                );
            });
            // Its own row, so the panel keeps its width.
            ui.horizontal(|ui| {
                ui.label("against the truth");
                let phong = self.scene.illumination == shadelab_model::IlluminationModel::Phong;
                let r = ui.add_enabled(
                    phong,
                    egui::Button::selectable(self.difference.kind == DifferenceKind::Ambient, "ambient error"),
                );
                if r.clicked() {
                    self.difference.kind = DifferenceKind::Ambient;
                }
                self.mark("ambient error", &r);
                r.on_hover_text(
                    "this image, with the chapter's constant ambient I_a·r_a·C, against the light that \
                     really passes between the surfaces (path traced): blue too dark, red too bright, \
                     with the I_a that fits the scene best",
                )
                .on_disabled_hover_text("only for the Phong illumination model, whose I_a stands for that light");
            });
            self.truth_ui(ui);
        }
    }

    /// What the FLIP map compares with, and the path tracer's bounces and paths for the truth.
    fn truth_ui(&mut self, ui: &mut egui::Ui) {
        if self.difference.kind == DifferenceKind::Flip {
            ui.horizontal(|ui| {
                ui.label("reference");
                let r = ui.selectable_value(&mut self.difference.against, Against::Twin, "f64 twin");
                self.mark("f64 twin", &r);
                r.on_hover_text(
                    "the same model as the GPU in f64, with area lights integrated and cast shadows \
                     traced exactly; under an environment light it has the GPU's nine SH terms and split sum",
                );
                let r = ui.selectable_value(&mut self.difference.against, Against::Truth, "path-traced truth");
                self.mark("path-traced truth", &r);
                r.on_hover_text(
                    "the light path traced: what passes between the surfaces (where the chapter has I_a) \
                     and the environment over the BRDF with visibility",
                );
            });
        }
        if self.difference.truth().is_none() {
            return;
        }
        let p = &mut self.difference.paths.0;
        ui.horizontal(|ui| {
            let (b, s) = (params::BOUNCES, params::SPP);
            ui.label("vertices");
            ui.add(egui::DragValue::new(&mut p.bounces).range(b.min as u32..=b.max as u32))
                .on_hover_text("surface vertices a path has: 1 is the direct light alone");
            ui.label("paths");
            ui.add(egui::DragValue::new(&mut p.spp).range(s.min as u32..=s.max as u32).speed(1.0))
                .on_hover_text("paths per pixel: the truth's noise falls as one over their square root");
        });
    }
}
