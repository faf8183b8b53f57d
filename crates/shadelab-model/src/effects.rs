//! Effect analysis: what a scene calls for (spec §7.1: the coefficients' complexity trades against
//! time; §7.5: absorption linearized below a·d = 0.5, neglected below 0.2). From the lights, the
//! materials and the chosen specular model it derives the set of effects the shader must contain,
//! each decision with its reason. The renderer builds one pipeline per set ([`EffectKey`]), whose
//! shader holds only those effects.

use crate::params::{FalloffForm, LightKind, SpecularModel};
use crate::scene::Scene;

/// Absorption inside a translucent material below this `a·d` is neglected (spec §7.5).
pub const ABSORPTION_NEGLECT_BELOW: f64 = 0.2;
/// Absorption below this `a·d` is linearized, `e^(−a·d) ≈ 1 − a·d` (spec §7.5).
pub const ABSORPTION_LINEAR_BELOW: f64 = 0.5;

/// The effects a shader permutation contains. Plain `Copy + Hash`: pipelines are cached by it.
/// Each flag is one preprocessor name in the WGSL (see [`EffectKey::defines`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct EffectKey {
    /// Lambert diffuse `r_d·C·(N·L)`.
    pub diffuse: bool,
    /// Phong specular `(V·R)^h`.
    pub specular_phong: bool,
    /// Cook–Torrance specular `F·D·G/(N·V)` (and the Fresnel index from μ).
    pub specular_cook_torrance: bool,
    /// Ambient `I_amb·r_a·C`.
    pub ambient: bool,
    /// Directional lights.
    pub directional_lights: bool,
    /// Point lights (distance and direction per point).
    pub point_lights: bool,
    /// `1/(1 + α d²)` for point lights with α > 0.
    pub falloff_quadratic: bool,
    /// The chapter's `1/(d + d0)`.
    pub falloff_linear: bool,
    /// Spot cones (on top of point lights: a spot light is a point light with a cone).
    pub spot_lights: bool,
    /// glTF's range window on point and spot lights that have a range.
    pub light_range: bool,
}

/// One effect of [`EffectKey`], by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Effect {
    Diffuse,
    SpecularPhong,
    SpecularCookTorrance,
    Ambient,
    DirectionalLights,
    PointLights,
    FalloffQuadratic,
    FalloffLinear,
    SpotLights,
    LightRange,
}

impl Effect {
    pub const ALL: [Effect; 10] = [
        Effect::Diffuse,
        Effect::SpecularPhong,
        Effect::SpecularCookTorrance,
        Effect::Ambient,
        Effect::DirectionalLights,
        Effect::PointLights,
        Effect::FalloffQuadratic,
        Effect::FalloffLinear,
        Effect::SpotLights,
        Effect::LightRange,
    ];

    /// The WGSL preprocessor name of the effect.
    pub fn define(self) -> &'static str {
        match self {
            Effect::Diffuse => "EFFECT_DIFFUSE",
            Effect::SpecularPhong => "EFFECT_SPECULAR_PHONG",
            Effect::SpecularCookTorrance => "EFFECT_SPECULAR_COOK_TORRANCE",
            Effect::Ambient => "EFFECT_AMBIENT",
            Effect::DirectionalLights => "EFFECT_DIRECTIONAL_LIGHTS",
            Effect::PointLights => "EFFECT_POINT_LIGHTS",
            Effect::FalloffQuadratic => "EFFECT_FALLOFF_QUADRATIC",
            Effect::FalloffLinear => "EFFECT_FALLOFF_LINEAR",
            Effect::SpotLights => "EFFECT_SPOT_LIGHTS",
            Effect::LightRange => "EFFECT_LIGHT_RANGE",
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Effect::Diffuse => "diffuse",
            Effect::SpecularPhong => "Phong specular",
            Effect::SpecularCookTorrance => "Cook–Torrance specular",
            Effect::Ambient => "ambient",
            Effect::DirectionalLights => "directional lights",
            Effect::PointLights => "point lights",
            Effect::FalloffQuadratic => "falloff 1/(1+αd²)",
            Effect::FalloffLinear => "falloff 1/(d+d0)",
            Effect::SpotLights => "spot cones",
            Effect::LightRange => "light range",
        }
    }

    /// The WGSL functions only this effect calls (the structural test checks that a permutation
    /// without the effect calls none of them).
    pub fn functions(self) -> &'static [&'static str] {
        match self {
            Effect::Diffuse => &["diffuse_lambert"],
            Effect::SpecularPhong => &["specular_phong"],
            Effect::SpecularCookTorrance => {
                &["specular_cook_torrance", "d_beckmann", "g_cook_torrance", "f_fresnel_exact", "fresnel_v_from_mu"]
            }
            Effect::Ambient => &[],
            Effect::DirectionalLights => &[],
            Effect::PointLights => &[],
            Effect::FalloffQuadratic => &["falloff_quadratic"],
            Effect::FalloffLinear => &["falloff_linear"],
            Effect::SpotLights => &["spot_cone"],
            Effect::LightRange => &["window_range"],
        }
    }
}

impl EffectKey {
    /// Every effect present (the "uber" shader: what is not needed is switched off at run time
    /// by the uniforms, e.g. r_s = 0 or α = 0).
    pub const UBER: EffectKey = EffectKey {
        diffuse: true,
        specular_phong: true,
        specular_cook_torrance: true,
        ambient: true,
        directional_lights: true,
        point_lights: true,
        falloff_quadratic: true,
        falloff_linear: true,
        spot_lights: true,
        light_range: true,
    };
    /// No effect: the shader outputs black (the floor of every effect).
    pub const NONE: EffectKey = EffectKey {
        diffuse: false,
        specular_phong: false,
        specular_cook_torrance: false,
        ambient: false,
        directional_lights: false,
        point_lights: false,
        falloff_quadratic: false,
        falloff_linear: false,
        spot_lights: false,
        light_range: false,
    };

    pub fn has(&self, e: Effect) -> bool {
        *self.flag(e)
    }

    fn flag(&self, e: Effect) -> &bool {
        match e {
            Effect::Diffuse => &self.diffuse,
            Effect::SpecularPhong => &self.specular_phong,
            Effect::SpecularCookTorrance => &self.specular_cook_torrance,
            Effect::Ambient => &self.ambient,
            Effect::DirectionalLights => &self.directional_lights,
            Effect::PointLights => &self.point_lights,
            Effect::FalloffQuadratic => &self.falloff_quadratic,
            Effect::FalloffLinear => &self.falloff_linear,
            Effect::SpotLights => &self.spot_lights,
            Effect::LightRange => &self.light_range,
        }
    }

    /// The key with one effect taken out.
    pub fn without(mut self, e: Effect) -> EffectKey {
        let f = match e {
            Effect::Diffuse => &mut self.diffuse,
            Effect::SpecularPhong => &mut self.specular_phong,
            Effect::SpecularCookTorrance => &mut self.specular_cook_torrance,
            Effect::Ambient => &mut self.ambient,
            Effect::DirectionalLights => &mut self.directional_lights,
            Effect::PointLights => &mut self.point_lights,
            Effect::FalloffQuadratic => &mut self.falloff_quadratic,
            Effect::FalloffLinear => &mut self.falloff_linear,
            Effect::SpotLights => &mut self.spot_lights,
            Effect::LightRange => &mut self.light_range,
        };
        *f = false;
        self
    }

    /// The effects present.
    pub fn effects(&self) -> Vec<Effect> {
        Effect::ALL.into_iter().filter(|e| self.has(*e)).collect()
    }

    /// The preprocessor names defined for this permutation.
    pub fn defines(&self) -> Vec<&'static str> {
        self.effects().into_iter().map(Effect::define).collect()
    }

    /// A short label, e.g. `diffuse+cook-torrance+ambient+dir+point+quad`.
    pub fn label(&self) -> String {
        if *self == EffectKey::UBER {
            return "uber".into();
        }
        let short = |e: Effect| match e {
            Effect::Diffuse => "diffuse",
            Effect::SpecularPhong => "phong",
            Effect::SpecularCookTorrance => "cook-torrance",
            Effect::Ambient => "ambient",
            Effect::DirectionalLights => "dir",
            Effect::PointLights => "point",
            Effect::FalloffQuadratic => "quad",
            Effect::FalloffLinear => "linear",
            Effect::SpotLights => "spot",
            Effect::LightRange => "range",
        };
        let v: Vec<&str> = self.effects().into_iter().map(short).collect();
        if v.is_empty() { "none".into() } else { v.join("+") }
    }
}

/// One decision of the analysis: the effect, whether and how it is simulated, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Decision {
    pub effect: &'static str,
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
}

fn decide(out: &mut Vec<Decision>, effect: &'static str, on: bool, reason: String) -> bool {
    out.push(Decision { effect, state: if on { "on" } else { "off" }.into(), reason });
    on
}

/// What the scene calls for with this specular model.
pub fn analyze(scene: &Scene, specular: SpecularModel) -> Analysis {
    let mut d = Vec::new();
    let mats = &scene.materials;
    let used: Vec<&crate::scene::Material> =
        scene.objects.iter().filter_map(|o| mats.get(o.material)).collect::<Vec<_>>();
    let lights = &scene.lights[..scene.lights.len().min(crate::scene::MAX_LIGHTS)];
    let n_dir = lights.iter().filter(|l| l.kind == LightKind::Directional).count();
    // Point and spot lights: both have a position, a distance and a falloff.
    let points: Vec<_> = lights.iter().filter(|l| l.kind != LightKind::Directional).collect();
    let n_spot = points.iter().filter(|l| l.kind == LightKind::Spot).count();
    let lit = !lights.is_empty();

    let directional_lights = decide(&mut d, "directional lights", n_dir > 0, format!("{n_dir} in the scene"));
    let point_lights = decide(
        &mut d,
        "point lights",
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
    let spot_lights = decide(&mut d, "spot cones", n_spot > 0, format!("{n_spot} spot light(s)"));
    let ranged = points.iter().filter(|l| l.range.is_some()).count();
    let light_range = decide(
        &mut d,
        "light range",
        ranged > 0,
        if ranged > 0 {
            format!("{ranged} point or spot light(s) end at a range")
        } else {
            "no light has a range".into()
        },
    );
    let quad: Vec<_> =
        points.iter().filter(|l| l.falloff_form == FalloffForm::Quadratic && l.falloff_alpha > 0.0).collect();
    let falloff_quadratic = decide(
        &mut d,
        "falloff 1/(1+αd²)",
        !quad.is_empty(),
        if quad.is_empty() {
            "no point or spot light with α > 0 (α = 0 is no falloff)".into()
        } else {
            let alphas: Vec<String> = quad.iter().map(|l| format!("{}", l.falloff_alpha)).collect();
            format!("{} point or spot light(s) with α = {}", quad.len(), alphas.join(", "))
        },
    );
    let lin = points.iter().filter(|l| l.falloff_form == FalloffForm::Linear).count();
    let falloff_linear = decide(
        &mut d,
        "falloff 1/(d+d0)",
        lin > 0,
        if lin > 0 {
            format!("{lin} point or spot light(s) use the chapter's form")
        } else {
            "no point or spot light uses it".into()
        },
    );
    let max_rd = used.iter().map(|m| m.r_d * m.color.iter().cloned().fold(0.0, f64::max)).fold(0.0, f64::max);
    let diffuse = decide(
        &mut d,
        "diffuse (Lambert)",
        lit && max_rd > 0.0,
        if !lit {
            "no lights".into()
        } else if max_rd > 0.0 {
            "some material has r_d·C > 0".into()
        } else {
            "every material has r_d = 0 or C = 0".into()
        },
    );
    let max_rs = used.iter().map(|m| m.r_s).fold(0.0, f64::max);
    let spec_reason = |model: SpecularModel| -> (bool, String) {
        if specular != model {
            (false, format!("the specular model is {specular}"))
        } else if !lit {
            (false, "no lights".into())
        } else if max_rs > 0.0 {
            (true, format!("the specular model is {specular} and some material has r_s > 0"))
        } else {
            (false, "every material has r_s = 0".into())
        }
    };
    let (on, why) = spec_reason(SpecularModel::Phong);
    let specular_phong = decide(&mut d, "Phong specular (V·R)^h", on, why);
    let (on, why) = spec_reason(SpecularModel::CookTorrance);
    let specular_cook_torrance = decide(&mut d, "Cook–Torrance specular", on, why);
    let amb = scene.ambient.iter().cloned().fold(0.0, f64::max);
    let max_ra = used.iter().map(|m| m.r_a).fold(0.0, f64::max);
    let ambient = decide(
        &mut d,
        "ambient I_amb·r_a·C",
        amb > 0.0 && max_ra > 0.0,
        if amb <= 0.0 {
            "I_amb = 0".into()
        } else if max_ra <= 0.0 {
            "every material has r_a = 0".into()
        } else {
            format!("I_amb = {amb} and some material has r_a > 0")
        },
    );
    d.push(Decision {
        effect: "cast shadows",
        state: "not simulated".into(),
        reason: "the renderer has no shadow pass; own shadow (N·L ≤ 0) is part of every light's term".into(),
    });
    let transmitting: Vec<_> = used.iter().filter(|m| m.transmission > 0.0).collect();
    d.push(Decision {
        effect: "transmission",
        state: if transmitting.is_empty() { "off" } else { "needed, not simulated yet" }.into(),
        reason: if transmitting.is_empty() {
            "every material is opaque (transparency t = 1 in the chapter's terms)".into()
        } else {
            format!("{} material(s) transmit light; the renderer draws them opaque", transmitting.len())
        },
    });
    let ad = transmitting
        .iter()
        .map(|m| m.absorption.iter().cloned().fold(0.0, f64::max) * m.thickness)
        .fold(0.0f64, f64::max);
    let (state, reason) = if transmitting.is_empty() {
        ("off".to_string(), "nothing transmits".to_string())
    } else if ad < ABSORPTION_NEGLECT_BELOW {
        ("neglected".into(), format!("a·d = {ad:.3} < {ABSORPTION_NEGLECT_BELOW} (spec §7.5)"))
    } else if ad < ABSORPTION_LINEAR_BELOW {
        ("linear 1 − a·d".into(), format!("a·d = {ad:.3} < {ABSORPTION_LINEAR_BELOW} (spec §7.5)"))
    } else {
        ("exact e^(−a·d)".into(), format!("a·d = {ad:.3} ≥ {ABSORPTION_LINEAR_BELOW} (spec §7.5)"))
    };
    d.push(Decision { effect: "absorption", state, reason });
    Analysis {
        key: EffectKey {
            diffuse,
            specular_phong,
            specular_cook_torrance,
            ambient,
            directional_lights,
            point_lights,
            falloff_quadratic,
            falloff_linear,
            spot_lights,
            light_range,
        },
        decisions: d,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Light;
    use glam::DVec3;

    #[test]
    fn default_scene_needs_what_it_uses() {
        let s = Scene::builtin("default").unwrap();
        let a = analyze(&s, SpecularModel::CookTorrance);
        assert!(a.key.diffuse && a.key.ambient && a.key.specular_cook_torrance && !a.key.specular_phong);
        assert!(a.key.directional_lights && a.key.point_lights && a.key.falloff_quadratic && !a.key.falloff_linear);
        assert_eq!(analyze(&s, SpecularModel::Phong).key, a.key.without(Effect::SpecularCookTorrance).with_phong());
        assert!(a.lines().iter().any(|l| l.starts_with("cast shadows: not simulated")));
    }

    impl EffectKey {
        fn with_phong(mut self) -> EffectKey {
            self.specular_phong = true;
            self
        }
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
        assert_eq!(a.key.effects(), vec![Effect::Diffuse, Effect::DirectionalLights], "{:?}", a.lines());
        s.lights.push(Light::point(DVec3::Y * 3.0, [1.0; 3], 1.0, 0.0));
        assert!(!analyze(&s, SpecularModel::Phong).key.falloff_quadratic, "α = 0 needs no falloff");
        s.lights[1].falloff_form = FalloffForm::Linear;
        let k = analyze(&s, SpecularModel::Phong).key;
        assert!(k.point_lights && k.falloff_linear && !k.falloff_quadratic);
        assert!(!k.spot_lights && !k.light_range);
        s.lights[1].set_kind(LightKind::Spot);
        let k = analyze(&s, SpecularModel::Phong).key;
        assert!(k.point_lights && k.spot_lights && !k.light_range, "a spot needs the point-light path too");
        s.lights[1].range = Some(4.0);
        assert!(analyze(&s, SpecularModel::Phong).key.light_range);
        s.lights.clear();
        assert_eq!(analyze(&s, SpecularModel::Phong).key, EffectKey::NONE.with_ambient_if(false));
    }

    impl EffectKey {
        fn with_ambient_if(mut self, on: bool) -> EffectKey {
            self.ambient = on;
            self
        }
    }

    #[test]
    fn absorption_follows_the_chapter_rule() {
        let mut s = Scene::builtin("sphere").unwrap();
        let state = |s: &Scene| {
            analyze(s, SpecularModel::Phong).decisions.iter().find(|d| d.effect == "absorption").unwrap().clone()
        };
        assert_eq!(state(&s).state, "off");
        let m = &mut s.materials[1];
        m.transmission = 0.5;
        m.thickness = 1.0;
        for (a, expect) in [(0.12, "neglected"), (0.3, "linear 1 − a·d"), (0.9, "exact e^(−a·d)")] {
            s.materials[1].absorption = [a, 0.0, 0.0];
            let d = state(&s);
            assert_eq!(d.state, expect, "{d:?}");
            assert!(d.reason.contains(&format!("{a:.3}")), "{d:?}");
        }
    }

    #[test]
    fn keys_and_defines() {
        assert_eq!(EffectKey::UBER.defines().len(), Effect::ALL.len());
        assert!(EffectKey::NONE.defines().is_empty());
        for e in Effect::ALL {
            assert!(!EffectKey::UBER.without(e).has(e));
            assert_eq!(EffectKey::UBER.without(e).effects().len(), Effect::ALL.len() - 1);
        }
    }
}
