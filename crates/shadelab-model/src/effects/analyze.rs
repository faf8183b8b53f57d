//! The effect analysis (docs/model.md §9, "Simulating only what a scene calls for"): from the
//! lights, the materials and the chosen specular model, one rule per declared effect decides
//! whether the shader must contain it, and why. The effects that are on make the scene's
//! [`EffectKey`].

use super::EffectKey;
use super::declared::Effect;
use crate::params::NamedValue;
use crate::params::{AreaSpecular, FalloffForm, IlluminationModel, SpecularModel};
use crate::scene::Scene;
use crate::shadows::ShadowFilter;

pub use crate::lighting::transmission::{ABSORPTION_LINEAR_BELOW, ABSORPTION_NEGLECT_BELOW};

/// One decision of the analysis: the effect, whether and how it is simulated, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Decision {
    pub effect: Effect,
    /// e.g. "on", "off", "neglected", "linear", "not simulated".
    pub state: String,
    pub reason: String,
}

/// The analysis of a scene: the shader's effect set and the reasons.
#[derive(Clone, Debug, PartialEq)]
pub struct Analysis {
    pub key: EffectKey,
    pub decisions: Vec<Decision>,
}

impl Analysis {
    /// One line per decision: `effect: state — reason`.
    pub fn lines(&self) -> Vec<String> {
        self.decisions.iter().map(|d| format!("{}: {} — {}", d.effect, d.state, d.reason)).collect()
    }

    /// Put a simulated effect in or leave it out; its state is "on" or "off".
    pub(super) fn decide(&mut self, effect: Effect, on: bool, reason: String) {
        if on {
            self.key = self.key.with(effect);
        }
        self.decisions.push(Decision { effect, state: (if on { "on" } else { "off" }).into(), reason });
    }
}

/// What the scene calls for with this specular model.
pub fn analyze(scene: &Scene, specular: SpecularModel) -> Analysis {
    let mut a = Analysis { key: EffectKey::NONE, decisions: Vec::new() };
    let mats = &scene.materials;
    let used: Vec<&crate::scene::Material> = scene.objects.iter().filter_map(|o| mats.get(o.material)).collect();
    let lights = &scene.lights[..scene.lights.len().min(crate::scene::MAX_LIGHTS)];
    // Point and spot lights: both have a position, a distance and a falloff.
    let points: Vec<_> = lights.iter().filter(|l| !l.kind.is_directional()).collect();
    let lit = !lights.is_empty();
    // The groups in the order the explanation lists them.
    decide_light_kinds(&mut a, lights, &points);
    decide_area_lights(&mut a, scene, lights);
    decide_falloff(&mut a, &points);
    decide_diffuse_specular(&mut a, scene, &used, lit, specular);
    decide_area_ltc(&mut a, lights);
    decide_ambient_and_sum(&mut a, scene, &used, lit);
    decide_shadows(&mut a, scene, lights);
    super::surface_terms::decide_textures(&mut a, scene);
    super::transparency::decide(&mut a, scene);
    a
}

/// The lights' kinds: directional, point (spots among them) and spot.
fn decide_light_kinds(a: &mut Analysis, lights: &[crate::scene::Light], points: &[&crate::scene::Light]) {
    let n_dir = lights.iter().filter(|l| l.kind.is_directional()).count();
    let n_spot = points.iter().filter(|l| l.kind.has_cone()).count();
    a.decide(Effect::DirectionalLights, n_dir > 0, format!("{n_dir} in the scene"));
    a.decide(
        Effect::PointLights,
        !points.is_empty(),
        if n_spot == 0 {
            format!("{} in the scene", points.len())
        } else {
            format!(
                "{} point and {n_spot} spot light(s) in the scene (a spot is a point light with a cone)",
                points.len() - n_spot
            )
        },
    );
    a.decide(Effect::SpotLights, n_spot > 0, format!("{n_spot} spot light(s)"));
}

/// Area lights in their exact form, then those drawn as point sources (with the shadow cubes
/// they share when there are fewer than their points).
fn decide_area_lights(a: &mut Analysis, scene: &Scene, lights: &[crate::scene::Light]) {
    let areas: Vec<String> = lights
        .iter()
        .enumerate()
        .filter(|(_, l)| l.kind.is_area() && !l.drawn_as_points())
        .map(|(i, l)| format!("{} light L{}", l.kind.name(), i + 1))
        .collect();
    a.decide(
        Effect::AreaLights,
        !areas.is_empty(),
        if areas.is_empty() {
            "no rect, disk or sphere light drawn with its exact area form".into()
        } else {
            areas.join(", ")
        },
    );
    let cubes = crate::shadows::shadow_cubes(scene);
    let as_points: Vec<String> = lights
        .iter()
        .enumerate()
        .filter(|(_, l)| l.drawn_as_points())
        .map(|(i, l)| {
            let k = l.area_points;
            let shared = match cubes.get(i) {
                Some(&c) if c > 0 && c < k => format!(" sharing {c} shadow cubes (MAX_SHADOW_LAYERS)"),
                _ => String::new(),
            };
            format!("{} light L{} as {k} point source(s){shared}", l.kind.name(), i + 1)
        })
        .collect();
    a.decide(
        Effect::AreaPoints,
        !as_points.is_empty(),
        if as_points.is_empty() { "no area light drawn as point sources".into() } else { as_points.join(", ") },
    );
}

/// The area lights whose specular is drawn by LTC: drawn in their exact form, asking for it,
/// under Cook–Torrance (Phong's lobe keeps the representative point).
fn decide_area_ltc(a: &mut Analysis, lights: &[crate::scene::Light]) {
    let asking: Vec<String> = lights
        .iter()
        .enumerate()
        .filter(|(_, l)| l.kind.is_area() && !l.drawn_as_points() && l.area_specular == AreaSpecular::Ltc)
        .map(|(i, l)| format!("{} light L{}", l.kind.name(), i + 1))
        .collect();
    let ct = a.key.has(Effect::SpecularCookTorrance);
    let (on, why) = match (asking.is_empty(), ct) {
        (true, _) => (false, "no area light asks for LTC".to_string()),
        (false, false) => {
            (false, format!("{} ask(s) for LTC, which draws Cook–Torrance's lobe only", asking.join(", ")))
        }
        (false, true) => (true, asking.join(", ")),
    };
    a.decide(Effect::AreaLtc, on, why);
}

/// The point and spot lights' range and falloff forms.
fn decide_falloff(a: &mut Analysis, points: &[&crate::scene::Light]) {
    let ranged = points.iter().filter(|l| l.range.is_some()).count();
    a.decide(
        Effect::LightRange,
        ranged > 0,
        if ranged > 0 {
            format!("{ranged} point or spot light(s) end at a range")
        } else {
            "no light has a range".into()
        },
    );
    let quad: Vec<_> =
        points.iter().filter(|l| l.falloff_form == FalloffForm::Quadratic && l.falloff_alpha > 0.0).collect();
    a.decide(
        Effect::FalloffQuadratic,
        !quad.is_empty(),
        if quad.is_empty() {
            "no point or spot light with α > 0 (α = 0 is no falloff)".into()
        } else {
            let alphas: Vec<String> = quad.iter().map(|l| format!("{}", l.falloff_alpha)).collect();
            format!("{} point or spot light(s) with α = {}", quad.len(), alphas.join(", "))
        },
    );
    let lin = points.iter().filter(|l| l.falloff_form == FalloffForm::Linear).count();
    a.decide(
        Effect::FalloffLinear,
        lin > 0,
        if lin > 0 {
            format!("{lin} point or spot light(s) use the chapter's form")
        } else {
            "no point or spot light uses it".into()
        },
    );
}

/// The Phong model's diffuse term and its two specular models (only the chosen one is on).
fn decide_diffuse_specular(
    a: &mut Analysis,
    scene: &Scene,
    used: &[&crate::scene::Material],
    lit: bool,
    specular: SpecularModel,
) {
    let model = scene.illumination;
    let phong_model = model == IlluminationModel::Phong;
    let other_model = format!("the illumination model is {model}, which has its own terms");
    let max_rd = used.iter().map(|m| m.r_d * m.max_color().iter().cloned().fold(0.0, f64::max)).fold(0.0, f64::max);
    a.decide(
        Effect::Diffuse,
        phong_model && lit && max_rd > 0.0,
        if !phong_model {
            other_model.clone()
        } else if !lit {
            "no lights".into()
        } else if max_rd > 0.0 {
            "some material has r_d·C > 0".into()
        } else {
            "every material has r_d = 0 or C = 0".into()
        },
    );
    let max_rs = used.iter().map(|m| m.r_s).fold(0.0, f64::max);
    // An environment's split sum lights the Cook–Torrance lobe without any light.
    let env_specular = scene.environment.as_ref().is_some_and(|e| e.specular);
    let spec_reason = |this: SpecularModel| -> (bool, String) {
        if !phong_model {
            (false, other_model.clone())
        } else if specular != this {
            (false, format!("the specular model is {specular}"))
        } else if !lit && !(this == SpecularModel::CookTorrance && env_specular) {
            (false, "no lights".into())
        } else if max_rs > 0.0 {
            (true, format!("the specular model is {specular} and some material has r_s > 0"))
        } else {
            (false, "every material has r_s = 0".into())
        }
    };
    let (on, why) = spec_reason(SpecularModel::Phong);
    a.decide(Effect::SpecularPhong, on, why);
    super::specular_terms::decide_phong_normalization(a, used, on);
    let (on, why) = spec_reason(SpecularModel::CookTorrance);
    a.decide(Effect::SpecularCookTorrance, on, why);
    super::specular_terms::decide_microfacet_terms(a, used, on);
    super::specular_terms::decide_multiple_scattering(a, used, on);
    super::specular_terms::decide_fresnel_mix(a, used, on);
}

/// The environment's split-sum specular: an environment that asks for it, the Phong model with
/// Cook–Torrance, and a material with a specular term.
fn decide_environment_specular(a: &mut Analysis, scene: &Scene, used: &[&crate::scene::Material]) {
    let env = scene.environment.as_ref();
    let ct = a.key.has(Effect::SpecularCookTorrance) && scene.illumination == IlluminationModel::Phong;
    let (on, why) = match env {
        None => (false, "no environment light".to_string()),
        Some(e) if !e.specular => (false, "the environment's specular is off".into()),
        Some(_) if !ct => (false, "the split sum is Cook–Torrance's, under the Phong model".into()),
        Some(_) if !used.iter().any(|m| m.r_s > 0.0) => (false, "every material has r_s = 0".into()),
        Some(e) => {
            (true, format!("the scene has an environment light ({}) and Cook–Torrance specular", e.source.name()))
        }
    };
    a.decide(Effect::EnvironmentSpecular, on, why);
}

/// The environment's precomputed occlusion: an environment that asks for it, with its diffuse
/// term drawn (the grid occludes only that).
fn decide_environment_occlusion(a: &mut Analysis, env: Option<&crate::lighting::env_map::Environment>) {
    let (on, why) = match env {
        None => (false, "no environment light".to_string()),
        Some(e) if !e.occlusion => (false, "the environment's occlusion is off".into()),
        Some(_) if !a.key.has(Effect::EnvironmentSh) => (false, "no environment diffuse term to occlude".into()),
        Some(_) => (true, "the environment asks for occlusion and its diffuse term is drawn".into()),
    };
    a.decide(Effect::EnvironmentOcclusion, on, why);
}

/// The ambient term, the Lambert rule, and the four-term sum with its transmitted term.
fn decide_ambient_and_sum(a: &mut Analysis, scene: &Scene, used: &[&crate::scene::Material], lit: bool) {
    let model = scene.illumination;
    let amb = scene.ambient.iter().cloned().fold(0.0, f64::max);
    let max_ra = used.iter().map(|m| m.r_a).fold(0.0, f64::max);
    a.decide(
        Effect::Ambient,
        model != IlluminationModel::Lambert && amb > 0.0 && max_ra > 0.0,
        if model == IlluminationModel::Lambert {
            "the Lambert rule has no I_amb: its fill R·(1 − I) stands for it".into()
        } else if amb <= 0.0 {
            "I_amb = 0".into()
        } else if max_ra <= 0.0 {
            "every material has r_a = 0".into()
        } else {
            format!("I_amb = {amb} and some material has r_a > 0")
        },
    );
    let env = scene.environment.as_ref();
    a.decide(
        Effect::EnvironmentSh,
        model != IlluminationModel::Lambert && env.is_some() && max_ra > 0.0,
        match env {
            None => "no environment light".into(),
            Some(_) if model == IlluminationModel::Lambert => {
                "the Lambert rule has no I_amb for it to stand for".into()
            }
            Some(_) if max_ra <= 0.0 => "an environment, but every material has r_a = 0".into(),
            Some(e) => {
                format!("the scene has an environment light ({}) and some material has r_a > 0", e.source.name())
            }
        },
    );
    decide_environment_occlusion(a, env);
    let (on, why) = match env {
        None => (false, "no environment light".to_string()),
        Some(e) if !e.background => (false, "the environment is not the background".into()),
        Some(e) => (true, format!("the environment ({}) is drawn as the background", e.source.name())),
    };
    a.decide(Effect::EnvironmentBackground, on, why);
    decide_environment_specular(a, scene, used);
    a.decide(Effect::LambertRule, model == IlluminationModel::Lambert, format!("the illumination model is {model}"));
    let sum = model == IlluminationModel::Sum;
    a.decide(
        Effect::FourTermSum,
        sum && lit,
        if !sum {
            format!("the illumination model is {model}")
        } else if lit {
            "the illumination model is the four-term sum".into()
        } else {
            "the four-term sum, but no lights: only K_a·I_a is left".into()
        },
    );
    let t_share = used.iter().map(|m| m.transmission).fold(0.0, f64::max);
    a.decide(
        Effect::TransmittedTerm,
        sum && lit && t_share > 0.0,
        if !sum {
            format!("the illumination model is {model}, which has no I_t")
        } else if !lit {
            "no lights".into()
        } else if t_share > 0.0 {
            format!("the four-term sum and some material transmits (1 − t up to {t_share})")
        } else {
            "every material is opaque (1 − t = 0)".into()
        },
    );
}

/// Cast shadows, then the filters and cascades, which need them.
fn decide_shadows(a: &mut Analysis, scene: &Scene, lights: &[crate::scene::Light]) {
    let (on, why) = cast_shadows(scene, lights);
    a.decide(Effect::CastShadows, on, why);
    for (effect, filter) in [
        (Effect::ShadowFilterHard, ShadowFilter::Hard),
        (Effect::ShadowFilterPcf, ShadowFilter::Pcf),
        (Effect::ShadowFilterPoisson, ShadowFilter::Poisson),
        (Effect::ShadowFilterPcss, ShadowFilter::Pcss),
    ] {
        let (used, why) = shadow_filter(lights, on, filter);
        a.decide(effect, used, why);
    }
    let (cascades, why) = shadow_cascades(scene, lights, on);
    a.decide(Effect::ShadowCascades, cascades, why);
}

/// Cast shadows are on when some light casts them and some object can hide another surface from
/// it: two or more objects, or a file mesh (which may be concave). A single convex shape (or a
/// plane) alone needs none: the only shadow it can have is its own, the N·L term.
fn cast_shadows(scene: &Scene, lights: &[crate::scene::Light]) -> (bool, String) {
    let casting = lights.iter().filter(|l| l.shadow.casts).count();
    let meshes = scene.objects.iter().filter(|o| matches!(o.shape, crate::scene::Shape::Mesh(_))).count();
    if lights.is_empty() {
        (false, "no lights".into())
    } else if casting == 0 {
        (false, "no light casts shadows (every light's shadow setting is off)".into())
    } else if scene.objects.len() >= 2 {
        (true, format!("{casting} light(s) cast shadows and {} objects can shadow one another", scene.objects.len()))
    } else if meshes > 0 {
        (true, format!("{casting} light(s) cast shadows and a file mesh can shadow itself"))
    } else if let Some(o) = scene.objects.first() {
        (
            false,
            format!(
                "one convex object ({}) with nothing to receive its shadow: its own shadow is the N·L term",
                o.shape.name()
            ),
        )
    } else {
        (false, "no objects".into())
    }
}

/// A shadow filter is on when shadows are and some casting light uses it: the others' code is
/// left out (a CPU rasterizer would run it for every pixel).
fn shadow_filter(lights: &[crate::scene::Light], shadows: bool, filter: ShadowFilter) -> (bool, String) {
    let name = filter.name();
    if !shadows {
        return (false, "no cast shadows".into());
    }
    let n = lights.iter().filter(|l| l.shadow.casts && l.drawn_shadow_filter() == filter).count();
    if n > 0 {
        (true, format!("{n} casting light(s) filter with {name}"))
    } else {
        (false, format!("no casting light filters with {name}"))
    }
}

/// Cascades are on when shadows are, some directional light casts them with its cascades
/// allowed, and the camera is perspective. The view's depth range is not asked: it sets how many
/// cascades a frame draws (`shadows::cascade_count`, a uniform), so orbiting never changes the
/// program or the maps.
fn shadow_cascades(scene: &Scene, lights: &[crate::scene::Light], shadows: bool) -> (bool, String) {
    use crate::shadows::{SHADOW_CASCADE_DEPTH_RATIO, SHADOW_CASCADES_MAX};
    let directional = |l: &&crate::scene::Light| l.kind.is_directional() && l.shadow.casts;
    if !shadows {
        return (false, "no cast shadows".into());
    }
    if !lights.iter().any(|l| directional(&l)) {
        return (false, "no directional light casts shadows".into());
    }
    if !lights.iter().filter(directional).any(|l| l.shadow.cascades) {
        return (false, "every directional light's cascades setting is off".into());
    }
    if scene.camera.orthographic.is_some() {
        return (false, "the camera is orthographic: a pixel covers the same area at every depth".into());
    }
    (
        true,
        format!(
            "a directional light casts with cascades allowed and the camera is perspective: up to \
             {SHADOW_CASCADES_MAX} maps, one per depth ratio of {SHADOW_CASCADE_DEPTH_RATIO} in view, chosen each frame"
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::LightKind;
    use crate::scene::Light;
    use glam::DVec3;

    #[test]
    fn default_scene_needs_what_it_uses() {
        let s = Scene::builtin("default").unwrap();
        let a = analyze(&s, SpecularModel::CookTorrance);
        let k = a.key;
        assert!(
            k.has(Effect::Diffuse)
                && k.has(Effect::Ambient)
                && k.has(Effect::SpecularCookTorrance)
                && !k.has(Effect::SpecularPhong)
        );
        assert!(
            k.has(Effect::DirectionalLights)
                && k.has(Effect::PointLights)
                && k.has(Effect::FalloffQuadratic)
                && !k.has(Effect::FalloffLinear)
        );
        // The chapter's three terms come with Cook–Torrance and go with it.
        let chapter = [Effect::DistributionBeckmann, Effect::MaskingVGroove, Effect::FresnelExact];
        assert!(chapter.iter().all(|e| k.has(*e)), "{:?}", a.lines());
        assert_eq!(
            analyze(&s, SpecularModel::Phong).key,
            k.without(Effect::SpecularCookTorrance).without_all(&chapter).with(Effect::SpecularPhong)
        );
        assert!(k.has(Effect::CastShadows), "{:?}", a.lines());
    }

    #[test]
    fn each_parameter_switches_its_effect() {
        let mut s = Scene::builtin("sphere").unwrap();
        s.ambient = [0.0; 3];
        for m in &mut s.materials {
            m.r_s = 0.0;
        }
        s.lights = vec![Light::directional(DVec3::NEG_Y, [1.0; 3], 1.0)];
        let a = analyze(&s, SpecularModel::CookTorrance);
        assert_eq!(
            a.key.effects(),
            // Cascades come with a perspective camera and a directional caster, whatever the view.
            vec![
                Effect::Diffuse,
                Effect::DirectionalLights,
                Effect::CastShadows,
                Effect::ShadowFilterPcf,
                Effect::ShadowCascades
            ],
            "{:?}",
            a.lines()
        );
        s.set_shadows(false);
        assert_eq!(
            analyze(&s, SpecularModel::CookTorrance).key.effects(),
            vec![Effect::Diffuse, Effect::DirectionalLights]
        );
        s.lights.push(Light::point(DVec3::Y * 3.0, [1.0; 3], 1.0, 0.0));
        assert!(!analyze(&s, SpecularModel::Phong).key.has(Effect::FalloffQuadratic), "α = 0 needs no falloff");
        s.lights[1].falloff_form = FalloffForm::Linear;
        let k = analyze(&s, SpecularModel::Phong).key;
        assert!(k.has(Effect::PointLights) && k.has(Effect::FalloffLinear) && !k.has(Effect::FalloffQuadratic));
        assert!(!k.has(Effect::SpotLights) && !k.has(Effect::LightRange));
        s.lights[1].set_kind(LightKind::Spot);
        let k = analyze(&s, SpecularModel::Phong).key;
        assert!(
            k.has(Effect::PointLights) && k.has(Effect::SpotLights) && !k.has(Effect::LightRange),
            "a spot needs the point-light path too"
        );
        s.lights[1].range = Some(4.0);
        assert!(analyze(&s, SpecularModel::Phong).key.has(Effect::LightRange));
        s.lights.clear();
        assert_eq!(analyze(&s, SpecularModel::Phong).key, EffectKey::NONE);
    }

    #[test]
    fn a_shadow_filter_is_in_the_shader_only_when_a_light_uses_it() {
        let key = |s: &Scene| analyze(s, SpecularModel::Phong).key;
        let mut s = Scene::builtin("default").unwrap();
        let filters = [Effect::ShadowFilterHard, Effect::ShadowFilterPcf, Effect::ShadowFilterPoisson];
        assert_eq!(filters.map(|f| key(&s).has(f)), [false, true, false], "the default filter is pcf");
        s.lights[0].shadow.filter = ShadowFilter::Poisson;
        s.lights[1].shadow.filter = ShadowFilter::Hard;
        assert_eq!(filters.map(|f| key(&s).has(f)), [true, false, true]);
        s.lights[1].shadow.casts = false;
        assert_eq!(
            filters.map(|f| key(&s).has(f)),
            [false, false, true],
            "a light that casts no shadow needs no filter"
        );
        s.set_shadows(false);
        assert_eq!(filters.map(|f| key(&s).has(f)), [false; 3]);
    }

    #[test]
    fn cascades_need_a_directional_caster_and_a_perspective_camera() {
        let on = |s: &Scene| analyze(s, SpecularModel::Phong).key.has(Effect::ShadowCascades);
        let mut s = Scene::builtin("field").unwrap();
        assert!(on(&s));
        // The view's depth does not decide the program: a camera moved close or far keeps it.
        for distance in [0.5, 2.0, 50.0] {
            let mut moved = s.clone();
            moved.camera.eye = moved.camera.target + (s.camera.eye - s.camera.target) * distance;
            assert!(on(&moved), "distance × {distance}");
        }
        let mut ortho = s.clone();
        ortho.camera.orthographic = Some(4.0);
        assert!(!on(&ortho), "an orthographic view needs one map");
        s.lights[0].shadow.cascades = false;
        assert!(!on(&s), "cascades off");
        s.lights[0].shadow.cascades = true;
        s.lights[0].set_kind(LightKind::Point);
        assert!(!on(&s), "a point light has no cascades");
        s.lights[0].set_kind(LightKind::Directional);
        s.set_shadows(false);
        assert!(!on(&s), "no shadows, no cascades");
    }

    #[test]
    fn cast_shadows_need_something_to_hide() {
        let on = |s: &Scene| analyze(s, SpecularModel::Phong).key.has(Effect::CastShadows);
        let mut s = Scene::builtin("sphere").unwrap();
        assert!(on(&s), "a sphere on the ground casts onto it");
        for shape in [crate::scene::Shape::Sphere, crate::scene::Shape::Cube, crate::scene::Shape::Pyramid] {
            s.objects.retain(|o| o.name != "ground");
            s.objects[0].shape = shape;
            assert!(!on(&s), "{shape:?} alone shadows only itself (N·L)");
        }
        s.meshes.push(crate::mesh::TriangleMesh::from_soup("t", &[[DVec3::ZERO, DVec3::X, DVec3::Y]], None));
        s.objects[0].shape = crate::scene::Shape::Mesh(0);
        assert!(on(&s), "a file mesh may be concave");
        s.set_shadows(false);
        assert!(!on(&s));
    }

    /// Every declared effect has exactly one decision, and the key is the simulated effects that
    /// are on.
    #[test]
    fn every_declared_effect_is_decided_once() {
        for name in crate::scene::BUILTIN_SCENES {
            let s = Scene::builtin(name).unwrap();
            for specular in SpecularModel::ALL_MODELS {
                let a = analyze(&s, specular);
                for d in super::super::DECLARED {
                    assert_eq!(a.decisions.iter().filter(|x| x.effect == d.effect).count(), 1, "{name}: {}", d.effect);
                }
                let on: EffectKey = a.decisions.iter().filter(|d| d.state == "on").map(|d| d.effect).collect();
                assert_eq!(on, a.key, "{name}");
            }
        }
    }
}
