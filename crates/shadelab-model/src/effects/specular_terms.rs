//! The specular terms a material chooses beyond the specular model (docs/model.md §3, §5):
//! Phong's normalized lobe and Cook–Torrance's D, G and F, each an effect that is on only where a
//! material with `r_s > 0` uses it.

use super::analyze::Analysis;
use super::declared::{DECLARED, Effect};

/// Whether a define names a microfacet term's effect: `EFFECT_D_…`, `EFFECT_G_…` or `EFFECT_F_…`.
const fn is_term_define(define: Option<&str>) -> bool {
    let Some(d) = define else { return false };
    let (b, prefix) = (d.as_bytes(), b"EFFECT_");
    if b.len() < 10 || b[8] != b'_' || !matches!(b[7], b'D' | b'G' | b'F') {
        return false;
    }
    let mut i = 0;
    while i < prefix.len() {
        if b[i] != prefix[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// How many declared effects are microfacet terms.
const fn term_count() -> usize {
    let (mut i, mut n) = (0, 0);
    while i < DECLARED.len() {
        if is_term_define(DECLARED[i].define) {
            n += 1;
        }
        i += 1;
    }
    n
}

/// The microfacet terms' effects: each D, G and F of [`crate::lighting::microfacet`], found in
/// the declared effects by their defines, in declaration order.
pub const MICROFACET_EFFECTS: [Effect; term_count()] = {
    let mut out = [Effect::Diffuse; term_count()];
    let (mut i, mut n) = (0, 0);
    while i < DECLARED.len() {
        if is_term_define(DECLARED[i].define) {
            out[n] = DECLARED[i].effect;
            n += 1;
        }
        i += 1;
    }
    out
};

/// The effect of one term: the declared effect whose define is `EFFECT_<kind>_<NAME>`, NAME the
/// term's name in capitals with `_` for `-` (the WGSL's convention; a test holds every term of
/// the tables to exactly one).
fn term_effect(kind: char, name: &str) -> Effect {
    let define = format!("EFFECT_{kind}_{}", name.to_uppercase().replace('-', "_"));
    DECLARED
        .iter()
        .find(|d| d.define == Some(define.as_str()))
        .map(|d| d.effect)
        .unwrap_or_else(|| panic!("{define}: every microfacet term declares its effect"))
}

/// The effects of a material's three microfacet terms.
pub fn microfacet_effects(t: crate::lighting::microfacet::Microfacet) -> [Effect; 3] {
    use crate::params::NamedValue;
    [term_effect('D', t.d.name()), term_effect('G', t.g.name()), term_effect('F', t.f.name())]
}

/// Phong's normalized lobe: on when Phong specular is and a material with r_s > 0 asks for it.
pub(super) fn decide_phong_normalization(a: &mut Analysis, used: &[&crate::scene::Material], phong: bool) {
    decide_asked(a, used, (Effect::PhongNormalized, "Phong specular", phong), |m| m.phong_normalized);
}

/// The lobe's multiple-scattering compensation: on when Cook–Torrance is and a material with
/// r_s > 0 asks for it.
pub(super) fn decide_multiple_scattering(a: &mut Analysis, used: &[&crate::scene::Material], cook_torrance: bool) {
    let effect = (Effect::MultipleScattering, "Cook–Torrance specular", cook_torrance);
    decide_asked(a, used, effect, |m| m.microfacet.multiple_scattering);
}

/// The Fresnel-weighted diffuse: on when Cook–Torrance is and a material with r_s > 0 and r_d > 0
/// asks for it (with no specular layer or no diffuse there is nothing to weigh).
pub(super) fn decide_fresnel_mix(a: &mut Analysis, used: &[&crate::scene::Material], cook_torrance: bool) {
    let effect = (Effect::FresnelMix, "Cook–Torrance specular", cook_torrance);
    decide_asked(a, used, effect, |m| m.microfacet.fresnel_mix && m.r_d > 0.0);
}

/// A material option's effect: on when its specular model (`model`, named, `on`) is and some
/// material with r_s > 0 `asks`; the reason names the first.
fn decide_asked(
    a: &mut Analysis,
    used: &[&crate::scene::Material],
    (effect, model, on): (Effect, &str, bool),
    asks: impl Fn(&crate::scene::Material) -> bool,
) {
    let asking: Vec<&str> = used.iter().filter(|m| asks(m) && m.r_s > 0.0).map(|m| m.name.as_str()).collect();
    let why = if !on {
        format!("{model} is off")
    } else if let Some(first) = asking.first() {
        format!("{} material(s) with r_s > 0 ask for it, '{first}' first", asking.len())
    } else {
        "no material with r_s > 0 asks for it".to_string()
    };
    a.decide(effect, on && !asking.is_empty(), why);
}

/// Each microfacet D, G and F: on when Cook–Torrance is and a material with r_s > 0 uses it.
pub(super) fn decide_microfacet_terms(a: &mut Analysis, used: &[&crate::scene::Material], cook_torrance: bool) {
    for effect in MICROFACET_EFFECTS {
        let users: Vec<&str> = used
            .iter()
            .filter(|m| m.r_s > 0.0 && microfacet_effects(m.microfacet).contains(&effect))
            .map(|m| m.name.as_str())
            .collect();
        let why = if !cook_torrance {
            "Cook–Torrance specular is off".to_string()
        } else if users.is_empty() {
            "no material with r_s > 0 uses it".to_string()
        } else {
            let mut names: Vec<&str> = Vec::new();
            for n in users.iter().map(|n| if n.is_empty() { "(unnamed)" } else { n }) {
                if !names.contains(&n) {
                    names.push(n);
                }
            }
            let more = if names.len() > 3 { format!(" and {} more", names.len() - 3) } else { String::new() };
            names.truncate(3);
            format!("used by {}{more}", names.iter().map(|n| format!("'{n}'")).collect::<Vec<_>>().join(", "))
        };
        a.decide(effect, cook_torrance && !users.is_empty(), why);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::analyze;
    use crate::params::SpecularModel;
    use crate::scene::Scene;

    /// Every D, G and F of the term tables has exactly its own effect, and the term effects are
    /// exactly those: a new term without its declared effect fails here, not in a material.
    #[test]
    fn every_term_of_the_tables_has_its_own_effect() {
        use crate::lighting::microfacet::{Distribution, Fresnel, Masking, Microfacet};
        use crate::params::NamedValue;
        let mut found = Vec::new();
        for &(_, d) in Distribution::ALL {
            found.push(microfacet_effects(Microfacet { d, ..Microfacet::CHAPTER })[0]);
        }
        for &(_, g) in Masking::ALL {
            found.push(microfacet_effects(Microfacet { g, ..Microfacet::CHAPTER })[1]);
        }
        for &(_, f) in Fresnel::ALL {
            found.push(microfacet_effects(Microfacet { f, ..Microfacet::CHAPTER })[2]);
        }
        let mut expected = MICROFACET_EFFECTS.to_vec();
        let key = |e: &Effect| format!("{e:?}");
        found.sort_by_key(key);
        expected.sort_by_key(key);
        assert_eq!(found, expected);
        assert_eq!(MICROFACET_EFFECTS.len(), Distribution::ALL.len() + Masking::ALL.len() + Fresnel::ALL.len());
    }

    #[test]
    fn the_compensation_is_in_only_with_cook_torrance_and_a_material_asking() {
        let mut s = Scene::builtin("default").unwrap();
        assert!(!analyze(&s, SpecularModel::CookTorrance).key.has(Effect::MultipleScattering));
        s.materials[1].microfacet.multiple_scattering = true;
        let a = analyze(&s, SpecularModel::CookTorrance);
        assert!(a.key.has(Effect::MultipleScattering), "{:?}", a.lines());
        assert!(!analyze(&s, SpecularModel::Phong).key.has(Effect::MultipleScattering));
    }

    #[test]
    fn the_fresnel_mix_is_in_only_with_cook_torrance_and_a_diffuse_material_asking() {
        let mut s = Scene::builtin("default").unwrap();
        assert!(!analyze(&s, SpecularModel::CookTorrance).key.has(Effect::FresnelMix));
        s.materials[1].microfacet.fresnel_mix = true;
        let a = analyze(&s, SpecularModel::CookTorrance);
        assert!(a.key.has(Effect::FresnelMix), "{:?}", a.lines());
        assert!(!analyze(&s, SpecularModel::Phong).key.has(Effect::FresnelMix));
        s.materials[1].r_d = 0.0;
        assert!(!analyze(&s, SpecularModel::CookTorrance).key.has(Effect::FresnelMix));
    }

    #[test]
    fn phong_normalization_is_in_only_with_phong_specular_and_a_material_asking() {
        let mut s = Scene::builtin("default").unwrap();
        assert!(!analyze(&s, SpecularModel::Phong).key.has(Effect::PhongNormalized));
        s.materials[1].phong_normalized = true;
        let a = analyze(&s, SpecularModel::Phong);
        assert!(a.key.has(Effect::PhongNormalized), "{:?}", a.lines());
        assert!(!analyze(&s, SpecularModel::CookTorrance).key.has(Effect::PhongNormalized));
    }

    #[test]
    fn each_microfacet_term_is_in_only_where_a_material_uses_it() {
        use crate::lighting::microfacet::{Fresnel, Microfacet};
        let mut s = Scene::builtin("default").unwrap();
        let chapter = microfacet_effects(Microfacet::CHAPTER);
        let gltf = microfacet_effects(Microfacet::GLTF);
        s.materials.iter_mut().for_each(|m| m.microfacet = Microfacet::GLTF);
        let a = analyze(&s, SpecularModel::CookTorrance);
        assert!(gltf.iter().all(|e| a.key.has(*e)) && chapter.iter().all(|e| !a.key.has(*e)), "{:?}", a.lines());
        // One material back to the exact F: both F are in, and the reason names it.
        s.materials[0].microfacet.f = Fresnel::Exact;
        let name = s.materials[0].name.clone();
        let a = analyze(&s, SpecularModel::CookTorrance);
        assert!(a.key.has(Effect::FresnelExact) && a.key.has(Effect::FresnelSchlick));
        let why = &a.decisions.iter().find(|d| d.effect == Effect::FresnelExact).unwrap().reason;
        assert!(why.contains(&format!("'{name}'")), "{why}");
        // Without a specular weight the material's terms are not needed.
        s.materials[0].r_s = 0.0;
        assert!(!analyze(&s, SpecularModel::CookTorrance).key.has(Effect::FresnelExact));
        assert!(!analyze(&s, SpecularModel::Phong).key.has(Effect::FresnelSchlick));
    }
}
