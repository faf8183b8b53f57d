//! A pipeline's light loop: built for its scene's lights (their number and each one's kind, set as
//! the pipeline-overridable constants `LOOP_LIGHTS` and `LOOP_KINDS` of `shaders/shading.wgsl`),
//! or reading them from the uniforms. Known when the pipeline is built, the count lets the shader
//! compiler unroll the loop and read each light's uniforms at a fixed offset, and the kinds let it
//! drop the code of the kinds a slot does not hold (docs/performance.md measures the saving).

use shadelab_model::Scene;
use shadelab_model::lighting::lights::MAX_LIGHTS;
use shadelab_model::params::NamedValue;

/// Bits of `LOOP_KINDS` per light slot (`LOOP_KIND_BITS` in WGSL): a `LightKind::code`.
pub const KIND_BITS: u32 = 3;

/// How a pipeline's light loop is built. Part of the pipeline key: a scene whose light count or
/// kinds change gets another pipeline (the viewer builds it while the uber pipeline draws).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum LightLoop {
    /// The count and the kinds read from the uniforms: draws any scene (the uber pipeline).
    #[default]
    Dynamic,
    /// Exactly `count` lights, slot i's kind code in bits `KIND_BITS·i` of `kinds`.
    Fixed { count: u8, kinds: u32 },
}

impl LightLoop {
    /// The loop for `scene`'s lights, in the scene's order (the order of the uniform's slots).
    pub fn for_scene(scene: &Scene) -> LightLoop {
        let lights = &scene.lights[..scene.lights.len().min(MAX_LIGHTS)];
        let kinds = lights.iter().enumerate().fold(0u32, |k, (i, l)| k | (l.kind.code() << (KIND_BITS * i as u32)));
        // MAX_LIGHTS slots of KIND_BITS fit in 24 bits (held by a test), exact in the f64 an
        // override constant is given as.
        LightLoop::Fixed { count: lights.len() as u8, kinds }
    }

    /// The pipeline-overridable constants that build it (none: the WGSL defaults, dynamic).
    pub fn constants(self) -> Vec<(&'static str, f64)> {
        match self {
            LightLoop::Dynamic => Vec::new(),
            LightLoop::Fixed { count, kinds } => vec![("LOOP_LIGHTS", count as f64), ("LOOP_KINDS", kinds as f64)],
        }
    }

    /// A short name for labels: "2 lights (directional, point)" or "lights from uniforms".
    pub fn label(self) -> String {
        match self {
            LightLoop::Dynamic => "lights from uniforms".into(),
            LightLoop::Fixed { count, kinds } => {
                let names: Vec<&str> = (0..count as u32)
                    .map(|i| (kinds >> (KIND_BITS * i)) & ((1 << KIND_BITS) - 1))
                    .map(|code| {
                        shadelab_model::LightKind::ALL
                            .iter()
                            .find(|(_, k)| k.code() == code)
                            .map_or("?", |(name, _)| *name)
                    })
                    .collect();
                format!("{count} light{} ({})", if count == 1 { "" } else { "s" }, names.join(", "))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadelab_model::LightKind;

    #[test]
    fn every_kind_code_fits_its_bits_and_every_slot_fits_the_mask() {
        for (name, k) in LightKind::ALL {
            assert!(k.code() < 1 << KIND_BITS, "{name}: code {} needs more than {KIND_BITS} bits", k.code());
        }
        assert!(MAX_LIGHTS as u32 * KIND_BITS <= 24, "LightLoop::Fixed.kinds must be exact as an f32 and f64");
    }

    #[test]
    fn the_wgsl_loop_constants_are_these() {
        let src = crate::shaders::lighting_source();
        let bits = format!("const LOOP_KIND_BITS: u32 = {KIND_BITS}u;");
        let mask = format!("const LOOP_KIND_MASK: u32 = {}u;", (1u32 << KIND_BITS) - 1);
        assert!(src.contains(&bits), "shading.wgsl lacks `{bits}`");
        assert!(src.contains(&mask), "shading.wgsl lacks `{mask}`");
        assert!(src.contains("override LOOP_LIGHTS: u32") && src.contains("override LOOP_KINDS: u32"));
    }

    #[test]
    fn a_scenes_loop_holds_its_kinds_in_order() {
        let mut scene = Scene::builtin("default").unwrap();
        let kinds = [LightKind::Spot, LightKind::Directional, LightKind::Point];
        scene.lights.truncate(1);
        while scene.lights.len() < kinds.len() {
            scene.lights.push(scene.lights[0].clone());
        }
        for (l, k) in scene.lights.iter_mut().zip(kinds) {
            l.set_kind(k);
        }
        let lp = LightLoop::for_scene(&scene);
        let expect = LightKind::Spot.code() | LightKind::Directional.code() << 3 | LightKind::Point.code() << 6;
        assert_eq!(lp, LightLoop::Fixed { count: 3, kinds: expect });
        assert_eq!(lp.label(), "3 lights (spot, directional, point)");
        assert_eq!(lp.constants(), vec![("LOOP_LIGHTS", 3.0), ("LOOP_KINDS", expect as f64)]);
        assert!(LightLoop::Dynamic.constants().is_empty());
    }
}
