//! The analysis of transparent objects (docs/transparency.md): whether the glass pass runs, whether
//! its rays bend, and how each object absorbs, with the chapter's `a·d` rule (7.5) picking each
//! object's form from the longest path light can take inside it.

use super::analyze::Analysis;
use super::declared::Effect;
use crate::lighting::transmission::{
    ABSORPTION_LINEAR_BELOW, ABSORPTION_NEGLECT_BELOW, AbsorptionChoice, AbsorptionForm, absorption_regime,
};
use crate::scene::{Scene, Shape};

/// The longest straight path inside object `i` in world units: a sphere's largest diameter, a
/// cylinder's diagonal through both caps, the diagonal of any other shape's box (a pyramid's and
/// a mesh's longest chord is at most that); 0 for the plane, which has no inside.
pub fn longest_chord(scene: &Scene, i: usize) -> f64 {
    let Some(o) = scene.objects.get(i) else { return 0.0 };
    let s = o.transform.scale.abs();
    match o.shape {
        Shape::Plane => 0.0,
        Shape::Sphere => 2.0 * s.max_element(),
        Shape::Cylinder => (2.0 * s.x.max(s.z)).hypot(2.0 * s.y),
        Shape::Cube | Shape::Pyramid => 2.0 * s.length(),
        Shape::Mesh(m) => scene.meshes.bounds(m).map_or(0.0, |(lo, hi)| ((hi - lo) * s).length()),
    }
}

/// The largest optical depth a path through object `i` reaches: the largest channel's `a` times
/// [`longest_chord`].
pub fn largest_optical_depth(scene: &Scene, i: usize) -> f64 {
    let a = scene
        .objects
        .get(i)
        .and_then(|o| scene.materials.get(o.material))
        .map_or(0.0, |m| m.absorption.iter().cloned().fold(0.0, f64::max));
    a * longest_chord(scene, i)
}

/// How object `i` absorbs: `--absorption exact` takes e^(−a·d) wherever anything absorbs; the
/// rule picks the form from [`largest_optical_depth`]. A material with a = 0 absorbs nothing.
pub fn absorption_form(scene: &Scene, i: usize) -> AbsorptionForm {
    let ad = largest_optical_depth(scene, i);
    match scene.absorption {
        _ if ad == 0.0 => AbsorptionForm::Neglected,
        AbsorptionChoice::Exact => AbsorptionForm::Exact,
        AbsorptionChoice::Rule => absorption_regime(ad),
    }
}

fn form_name(form: AbsorptionForm) -> &'static str {
    match form {
        AbsorptionForm::Exact => "exact e^(−a·d)",
        AbsorptionForm::Linear => "linear 1 − a·d",
        AbsorptionForm::Neglected => "neglected",
    }
}

/// Transmission, refraction and absorption: each with its reason.
pub(super) fn decide(a: &mut Analysis, scene: &Scene) {
    let glass: Vec<usize> = (0..scene.objects.len()).filter(|&i| scene.drawn_as_glass(i)).collect();
    let transmitting =
        scene.objects.iter().filter(|o| scene.materials.get(o.material).is_some_and(|m| m.transmits())).count();
    let name = |i: usize| scene.objects[i].name.clone();
    let names = |list: &[usize]| list.iter().map(|&i| name(i)).collect::<Vec<_>>().join(", ");
    a.decide(
        Effect::Transmission,
        !glass.is_empty(),
        if !glass.is_empty() {
            format!(
                "{} object(s) let light through ({}): drawn after the opaque scene, far to near, over it",
                glass.len(),
                names(&glass)
            )
        } else if transmitting > 0 {
            "the four-term sum draws transmission as its own I_t term".into()
        } else {
            "every material is opaque (transparency t = 1 in the chapter's terms)".into()
        },
    );
    let material = |i: usize| &scene.materials[scene.objects[i].material];
    let bending: Vec<usize> = glass.iter().copied().filter(|&i| material(i).refractive_index() != [1.0; 3]).collect();
    a.decide(
        Effect::Refraction,
        !bending.is_empty(),
        if glass.is_empty() {
            "nothing transmits".into()
        } else if bending.is_empty() {
            "every transparent material has index v = 1: no interface, rays go straight".into()
        } else {
            let dispersing = bending.iter().filter(|&&i| material(i).disperses()).count();
            format!(
                "{} transparent object(s) with index v ≠ 1 bend rays by Snell's law (7.5){}",
                bending.len(),
                if dispersing > 0 { format!(", {dispersing} dispersing per channel") } else { String::new() }
            )
        },
    );
    let forms: Vec<(usize, AbsorptionForm)> = glass.iter().map(|&i| (i, absorption_form(scene, i))).collect();
    let absorbing = forms.iter().any(|(_, f)| *f != AbsorptionForm::Neglected);
    let why = forms
        .iter()
        .map(|&(i, f)| {
            let ad = largest_optical_depth(scene, i);
            let bound = match f {
                _ if scene.absorption == AbsorptionChoice::Exact && ad > 0.0 => "--absorption exact".to_string(),
                AbsorptionForm::Neglected => format!("< {ABSORPTION_NEGLECT_BELOW}"),
                AbsorptionForm::Linear => format!("< {ABSORPTION_LINEAR_BELOW}"),
                AbsorptionForm::Exact => format!("≥ {ABSORPTION_LINEAR_BELOW}"),
            };
            format!("{} {} (a·d up to {ad:.3} {bound})", name(i), form_name(f))
        })
        .collect::<Vec<_>>()
        .join(", ");
    a.decide(
        Effect::Absorption,
        absorbing,
        if glass.is_empty() { "nothing transmits".into() } else { format!("{why}; the chapter's rule, 7.5") },
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::analyze;
    use crate::params::SpecularModel;

    fn decision(s: &Scene, effect: Effect) -> crate::effects::Decision {
        analyze(s, SpecularModel::Phong).decisions.iter().find(|d| d.effect == effect).unwrap().clone()
    }

    #[test]
    fn absorption_follows_the_chapter_rule_per_object() {
        let mut s = Scene::builtin("sphere").unwrap();
        assert_eq!(decision(&s, Effect::Absorption).state, "off");
        let i = s.objects.iter().position(|o| o.shape == Shape::Sphere).unwrap();
        let mi = s.objects[i].material;
        s.materials[mi].transmission = 0.5;
        let d = longest_chord(&s, i);
        assert_eq!(d, 2.0 * s.objects[i].transform.scale.x);
        for (ad, form) in [
            (0.0, AbsorptionForm::Neglected),
            (0.19, AbsorptionForm::Neglected),
            (0.3, AbsorptionForm::Linear),
            (0.9, AbsorptionForm::Exact),
        ] {
            s.materials[mi].absorption = [ad / d, 0.0, 0.0];
            assert_eq!(absorption_form(&s, i), form, "a·d = {ad}");
            let dec = decision(&s, Effect::Absorption);
            assert_eq!(dec.state, if form == AbsorptionForm::Neglected { "off" } else { "on" }, "{dec:?}");
            assert!(dec.reason.contains(form_name(form)), "{dec:?}");
            s.absorption = AbsorptionChoice::Exact;
            let exact = if ad == 0.0 { AbsorptionForm::Neglected } else { AbsorptionForm::Exact };
            assert_eq!(absorption_form(&s, i), exact);
            s.absorption = AbsorptionChoice::Rule;
        }
    }

    /// The glass scene calls for all three, each object named; the four-term sum for none.
    #[test]
    fn the_glass_scene_calls_for_transmission_refraction_and_absorption() {
        let mut s = Scene::builtin("glass").unwrap();
        for e in [Effect::Transmission, Effect::Refraction, Effect::Absorption] {
            let d = decision(&s, e);
            assert_eq!(d.state, "on", "{d:?}");
        }
        assert!(decision(&s, Effect::Absorption).reason.contains("absorbing cylinder exact"));
        assert!(decision(&s, Effect::Absorption).reason.contains("glass sphere neglected"));
        for m in &mut s.materials {
            m.ior = Some([1.0; 3]);
        }
        assert_eq!(decision(&s, Effect::Refraction).state, "off");
        s.illumination = crate::params::IlluminationModel::Sum;
        let d = decision(&s, Effect::Transmission);
        assert_eq!(d.state, "off");
        assert!(d.reason.contains("I_t"));
    }

    #[test]
    fn longest_chords() {
        let mut s = Scene::builtin("glass").unwrap();
        let cyl = s.objects.iter().position(|o| o.shape == Shape::Cylinder).unwrap();
        assert!((longest_chord(&s, cyl) - (0.7f64).hypot(1.0)).abs() < 1e-12);
        s.objects[cyl].shape = Shape::Plane;
        assert_eq!(longest_chord(&s, cyl), 0.0);
        assert_eq!(longest_chord(&s, 999), 0.0);
    }
}
