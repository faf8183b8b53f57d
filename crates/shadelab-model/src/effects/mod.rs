//! Effects: what a shader permutation may contain and what a scene calls for. Each effect is
//! declared once ([`DECLARED`], in `declared.rs`; the set a permutation holds, [`EffectKey`], in
//! `key.rs`); the analysis (`analyze.rs`) decides, per
//! scene, which of them the shader must hold, each with its reason. The renderer builds one
//! pipeline per set ([`EffectKey`]), whose shader holds only those effects.

mod analyze;
mod declaration;
mod declared;
mod effect;
mod key;
mod small_area_lights;
mod specular_terms;
mod surface_terms;
mod transparency;

pub use analyze::{ABSORPTION_LINEAR_BELOW, ABSORPTION_NEGLECT_BELOW, Analysis, Decision, analyze};
pub use declared::{DECLARED, Declaration, Effect, TEXTURE_COORDS, TEXTURE_EFFECTS};
pub use key::EffectKey;
pub use small_area_lights::{
    SMALL_AREA_MAX_PX, SMALL_AREA_MAX_RADIUS_OVER_DISTANCE, SmallAreaLight, draw_small_area_lights_as_points,
    small_area_light,
};
pub use specular_terms::{MICROFACET_EFFECTS, microfacet_effects};
pub use transparency::{absorption_form, largest_optical_depth, longest_chord};
