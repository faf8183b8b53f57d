//! The panel's Cook–Torrance terms: the selected material's D, G and F, each switched live, and
//! the two sets (the chapter's, glTF's) for every material at once (docs/model.md §5).

use eframe::egui;
use shadelab_model::Material;
use shadelab_model::lighting::microfacet::{Distribution, Fresnel, Masking, Microfacet};
use shadelab_model::params::NamedValue;

/// One term's menu: its values by name, the chosen one selected.
fn term_menu<T: NamedValue + PartialEq + std::fmt::Display>(ui: &mut egui::Ui, label: &str, tip: &str, v: &mut T) {
    egui::ComboBox::from_label(label)
        .selected_text(v.to_string())
        .show_ui(ui, |ui| {
            for &(name, value) in T::ALL {
                ui.selectable_value(v, value, name);
            }
        })
        .response
        .on_hover_text(tip);
}

/// The header's name of a set: a preset by its name (`gltf`, `chapter`, with `+ms` when
/// compensated), any other set as `d/g/f` with its options. Short, so that the panel keeps its
/// width and the view its 16:9 whichever preset a file opens with.
fn set_name(t: Microfacet) -> String {
    let plain = Microfacet { multiple_scattering: false, ..t };
    let ms = if t.multiple_scattering { "+ms" } else { "" };
    match [("gltf", Microfacet::GLTF), ("chapter", Microfacet::CHAPTER)].iter().find(|(_, p)| *p == plain) {
        Some((name, _)) => format!("{name}{ms}"),
        None => t.to_string(),
    }
}

/// The terms row: D, G and F of `selected`, and the sets for all of `materials`. Only
/// Cook–Torrance specular reads them, which `active` says.
pub(super) fn microfacet_ui(ui: &mut egui::Ui, materials: &mut [Material], selected: usize, active: bool) {
    let t = materials[selected].microfacet;
    let title = format!("Cook–Torrance terms: {}", set_name(t));
    let header =
        egui::CollapsingHeader::new(title).id_salt("microfacet terms").show(ui, |ui| terms_ui(ui, materials, selected));
    header.header_response.on_hover_text(if active {
        "Cook–Torrance's D, G and F for this material"
    } else {
        "Cook–Torrance's D, G and F: the specular model is Phong, which does not use them"
    });
}

/// The opened section: the sets for every material, and the selected material's three menus.
fn terms_ui(ui: &mut egui::Ui, materials: &mut [Material], selected: usize) {
    ui.horizontal_wrapped(|ui| {
        for (name, set) in Microfacet::ALL {
            let tip = format!("every material: {set}");
            if ui.small_button(format!("all {name}")).on_hover_text(tip).clicked() {
                materials.iter_mut().for_each(|m| m.microfacet = *set);
            }
        }
    });
    let t = &mut materials[selected].microfacet;
    ui.horizontal_wrapped(|ui| {
        term_menu::<Distribution>(ui, "D", "facet distribution (the chapter's: beckmann)", &mut t.d);
        term_menu::<Masking>(ui, "G", "masking–shadowing (the chapter's: v-groove)", &mut t.g);
        term_menu::<Fresnel>(ui, "F", "Fresnel factor (the chapter's: exact)", &mut t.f);
    });
    ui.checkbox(&mut t.multiple_scattering, "multiple scattering").on_hover_text(
        "the light single scattering loses between facets put back, 1 + F0·(1 − E)/E (docs/microfacet.md)",
    );
    ui.checkbox(&mut t.fresnel_mix, "diffuse × (1 − F)").on_hover_text(
        "the diffuse weighted by what the dielectric layer's Fresnel leaves it, glTF's fresnel_mix (docs/model.md §5)",
    );
}
