//! The panel's environment section (docs/environment.md): the source (none, a uniform colour in
//! place of I_amb, the sky, or the map a file, `--environment` or the files row brought), its intensity, turn,
//! the sky's turbidity (each slider over its declared range), whether the split sum draws its
//! specular, whether the precomputed grid occludes its diffuse light and whether it is drawn as
//! the background.

use super::slider;
use crate::viewer::Viewer;
use eframe::egui;
use shadelab_model::lighting::env_map::{ENV_INTENSITY, ENV_ROTATION, EnvImage, EnvKind, EnvSource, Environment};
use shadelab_model::lighting::sky::TURBIDITY;

/// The sources the menu offers.
#[derive(Clone, Copy, PartialEq)]
enum Choice {
    None,
    Uniform,
    Sky,
    Map,
}

impl Viewer {
    pub(super) fn environment_ui(&mut self, ui: &mut egui::Ui) {
        let current = match self.scene.environment.as_ref().map(|e| &e.source) {
            None => Choice::None,
            Some(EnvSource::Uniform(_)) => Choice::Uniform,
            Some(EnvSource::Sky { .. }) => Choice::Sky,
            Some(EnvSource::Image(_)) => Choice::Map,
        };
        let mut choice = current;
        let map = self.scene.environment.as_ref().and_then(|e| match &e.source {
            EnvSource::Image(img) => Some(img.clone()),
            _ => None,
        });
        let label = |c: Choice| match c {
            Choice::None => "none (the constant I_amb)".to_string(),
            Choice::Uniform => "uniform (I_amb from every direction)".to_string(),
            Choice::Sky => "sky (Preetham)".to_string(),
            Choice::Map => map.as_ref().map_or("map".into(), |m| format!("map {}", m.name)),
        };
        let marks = &mut self.marks;
        egui::ComboBox::from_label("environment").selected_text(label(current)).show_ui(ui, |ui| {
            for c in [Choice::None, Choice::Uniform, Choice::Sky] {
                let r = ui.selectable_value(&mut choice, c, label(c));
                marks.insert(format!("environment:{}", ["none", "uniform", "sky"][c as usize]), r.rect);
            }
            if map.is_some() {
                ui.selectable_value(&mut choice, Choice::Map, label(Choice::Map));
            }
        });
        if choice != current {
            self.choose_environment(choice == Choice::None, choice == Choice::Uniform);
        }
        let Some(env) = self.scene.environment.as_mut() else {
            ui.small("a sky or a map lights the scene in place of I_amb; open a map (.hdr, .exr) as a scene file");
            return;
        };
        slider(ui, &mut env.intensity, &ENV_INTENSITY, true);
        slider(ui, &mut env.rotation_deg, &ENV_ROTATION, false);
        if let EnvSource::Sky { turbidity, sun } = &mut env.source {
            slider(ui, turbidity, &TURBIDITY, false);
            ui.small(if sun.is_some() {
                "the sun as the file gives it"
            } else {
                "the sun at the first directional light"
            });
        }
        let r = ui.checkbox(&mut env.specular, "specular (split sum)");
        self.marks.insert("environment:specular".into(), r.rect);
        let r = ui.checkbox(&mut env.occlusion, "occlusion (precomputed grid)").on_hover_text(
            "the diffuse light times the open share of a grid of ambient occlusion baked over the scene (once per change of the geometry)",
        );
        self.marks.insert("environment:occlusion".into(), r.rect);
        let r = ui.checkbox(&mut env.background, "show as the background");
        self.marks.insert("environment:background".into(), r.rect);
        ui.small(
            "diffuse by nine SH terms, specular by the split sum (Cook–Torrance): the difference view's path-traced truth has the rest",
        );
    }

    /// Light the scene by a map read from a file (`read`: the map and its warnings, or one error
    /// line), in place of I_amb as the other sources; the scene on show stays when it fails.
    pub fn use_env_map(&mut self, read: Result<(EnvImage, Vec<String>), String>) {
        let (img, warnings) = match read {
            Ok(r) => r,
            Err(e) => {
                self.message = Some((e, true));
                return;
            }
        };
        let name = img.name.clone();
        let previous = self.scene.environment.take();
        self.choose_environment(false, false);
        let mut env = Environment::new(EnvSource::Image(std::sync::Arc::new(img)));
        // The switches of the environment it replaces stay as they were.
        if let Some(p) = previous {
            (env.intensity, env.rotation_deg, env.specular, env.occlusion, env.background) =
                (p.intensity, p.rotation_deg, p.specular, p.occlusion, p.background);
        }
        self.scene.environment = Some(env);
        let mut said = format!("environment map {name}");
        for w in &warnings {
            log::warn!("{w}");
            said.push_str(&format!("; {w}"));
        }
        self.message = Some((said, false));
    }

    /// Switch the environment: none gives back the I_amb the panel's environment replaced,
    /// uniform takes I_amb's colour, the sky follows the sun; either of the last two sets I_amb
    /// to 0, since it stands for it.
    fn choose_environment(&mut self, none: bool, uniform: bool) {
        self.scene.environment = None;
        if none {
            if self.term == shadelab_model::terms::Term::EnvSpecular {
                self.term = shadelab_model::terms::Term::All;
            }
            if let Some(a) = self.ambient_replaced.take() {
                self.scene.ambient = a;
            }
            return;
        }
        let ambient = *self.ambient_replaced.get_or_insert(self.scene.ambient);
        let kind = if uniform { EnvKind::Uniform } else { EnvKind::Sky };
        self.scene.environment = EnvSource::starting(kind, ambient).map(Environment::new);
        self.scene.ambient = [0.0; 3];
    }
}
