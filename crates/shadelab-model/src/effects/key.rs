//! [`EffectKey`]: the set of simulated effects a shader permutation holds, one bit per declared
//! effect ([`super::DECLARED`]), with the defines and the label derived from it.

use super::declared::{Effect, TEXTURE_COORDS, TEXTURE_EFFECTS};
use std::fmt;

/// The simulated effects a shader permutation contains: one bit per declared effect. Plain
/// `Copy + Hash`: pipelines are cached by it. An effect that is not simulated is never in a key.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct EffectKey(u64);

impl EffectKey {
    /// Every simulated effect present (the "uber" shader: what is not needed is switched off at
    /// run time by the uniforms, e.g. r_s = 0 or α = 0).
    pub const UBER: EffectKey = {
        let mut key = EffectKey::NONE;
        let mut i = 0;
        while i < Effect::ALL.len() {
            key = key.with(Effect::ALL[i]);
            i += 1;
        }
        key
    };
    /// No effect: the shader outputs black (the floor of every effect).
    pub const NONE: EffectKey = EffectKey(0);

    pub const fn has(&self, e: Effect) -> bool {
        self.0 & e.bit() != 0
    }

    /// The key with one effect put in; an effect that is not simulated leaves it as it is.
    pub const fn with(self, e: Effect) -> EffectKey {
        if e.is_simulated() { EffectKey(self.0 | e.bit()) } else { self }
    }

    /// The key with one effect taken out.
    pub const fn without(self, e: Effect) -> EffectKey {
        EffectKey(self.0 & !e.bit())
    }

    /// The key with each of `effects` taken out.
    pub fn without_all(self, effects: &[Effect]) -> EffectKey {
        effects.iter().fold(self, |k, e| k.without(*e))
    }

    /// The effects present, in declaration order.
    pub fn effects(&self) -> Vec<Effect> {
        Effect::ALL.into_iter().filter(|e| self.has(*e)).collect()
    }

    /// The preprocessor names defined for this permutation: its effects', and
    /// [`TEXTURE_COORDS`] when one of them samples a texture.
    pub fn defines(&self) -> Vec<&'static str> {
        let mut out: Vec<&'static str> = self.effects().into_iter().filter_map(Effect::define).collect();
        if self.samples_textures() {
            out.push(TEXTURE_COORDS);
        }
        out
    }

    /// Whether the permutation samples some texture (it then reads texture coordinates).
    pub fn samples_textures(&self) -> bool {
        TEXTURE_EFFECTS.iter().any(|e| self.has(*e))
    }

    /// A short label, e.g. `diffuse+cook-torrance+ambient+dir+point+quad`; `uber` and `none` for
    /// those two keys.
    pub fn label(&self) -> String {
        if *self == EffectKey::UBER {
            return "uber".into();
        }
        let v: Vec<&str> = self.effects().into_iter().map(Effect::label).collect();
        if v.is_empty() { "none".into() } else { v.join("+") }
    }
}

impl FromIterator<Effect> for EffectKey {
    fn from_iter<I: IntoIterator<Item = Effect>>(iter: I) -> EffectKey {
        iter.into_iter().fold(EffectKey::NONE, EffectKey::with)
    }
}

/// The label, e.g. `EffectKey(diffuse+dir)`.
impl fmt::Debug for EffectKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "EffectKey({})", self.label())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::DECLARED;

    #[test]
    fn keys_and_defines() {
        assert_eq!(EffectKey::UBER.defines().len(), Effect::ALL.len() + 1);
        assert!(EffectKey::UBER.defines().contains(&TEXTURE_COORDS));
        for e in TEXTURE_EFFECTS {
            assert!(EffectKey::NONE.with(e).defines().contains(&TEXTURE_COORDS), "{e}");
        }
        assert!(!EffectKey::UBER.without_all(&TEXTURE_EFFECTS).defines().contains(&TEXTURE_COORDS));
        assert!(EffectKey::NONE.defines().is_empty());
        for e in Effect::ALL {
            assert!(!EffectKey::UBER.without(e).has(e));
            assert_eq!(EffectKey::UBER.without(e).effects().len(), Effect::ALL.len() - 1);
            assert_eq!(EffectKey::UBER.without(e).with(e), EffectKey::UBER);
            assert_eq!(EffectKey::NONE.with(e).effects(), vec![e]);
        }
    }

    #[test]
    fn uber_holds_every_simulated_effect_and_nothing_else() {
        for d in DECLARED {
            assert_eq!(EffectKey::UBER.has(d.effect), d.define.is_some(), "{}", d.effect);
            assert_eq!(Effect::ALL.contains(&d.effect), d.define.is_some(), "{}", d.effect);
        }
        assert_eq!(Effect::ALL.into_iter().collect::<EffectKey>(), EffectKey::UBER);
    }

    #[test]
    fn labels_are_those_pipelines_print() {
        assert_eq!(EffectKey::UBER.label(), "uber");
        assert_eq!(EffectKey::NONE.label(), "none");
        let k: EffectKey = [Effect::LightRange, Effect::Diffuse, Effect::SpecularCookTorrance, Effect::PointLights]
            .into_iter()
            .collect();
        assert_eq!(k.label(), "diffuse+cook-torrance+point+range");
        assert_eq!(format!("{k:?}"), "EffectKey(diffuse+cook-torrance+point+range)");
        // Every effect's label in the order they are declared, joined by "+" (no list by hand).
        let all: Vec<&str> = Effect::ALL.into_iter().filter(|e| *e != Effect::Ambient).map(Effect::label).collect();
        assert_eq!(EffectKey::UBER.without(Effect::Ambient).label(), all.join("+"));
        assert!(all.contains(&"blinn-phong") && all.len() > 40, "{all:?}");
        assert_eq!(Effect::SpecularPhong.to_string(), "Phong specular (V·R)^h");
    }
}
