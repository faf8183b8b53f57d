//! One term of the illumination model at a time (docs/model.md §1–§3a): the image of the ambient,
//! the diffuse, the specular (or reflected), the environment's specular or the transmitted term
//! alone is the image of the same scene with the other terms' coefficients set to 0 (I_amb and
//! r_a, r_d, r_s, the transmission, the lights' intensities, the environment's split sum). The GPU
//! and the f64 reference draw the same transformed scene, so each term has both, and the terms add
//! up to the full image.

use crate::params::IlluminationModel;
use crate::scene::Scene;

/// Which part of the model an image shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Term {
    /// Every term summed: the model as it is.
    #[default]
    All,
    /// `I_amb·r_a·C` alone.
    Ambient,
    /// `Σ V·I_L·r_d·C·(N·L)` alone, cast shadows included.
    Diffuse,
    /// `Σ V·I_L·r_s·S` alone (Phong or Cook–Torrance), cast shadows included; the four-term
    /// sum's reflected term `I_r`.
    Specular,
    /// The environment light's specular `r_s·L_pre·(F0·(E − B) + B)` alone (the split sum,
    /// docs/environment.md). The environment's diffuse light is the ambient term's: it stands
    /// for `I_amb`.
    EnvSpecular,
    /// The four-term sum's transmitted term `I_t = K_t·(1 − t)·I/(d + d0)` alone.
    Transmitted,
    /// The cast-shadow factor: the share of the lights' diffuse and specular light that reaches
    /// each point (1 lit, 0 in every light's shadow), as grey. Not a summand: [`shadow_factor`]
    /// of the image with and without cast shadows.
    Shadow,
}

crate::named_values!(Term, "--term",
    "all" => All, "ambient" => Ambient, "diffuse" => Diffuse, "specular" => Specular,
    "environment-specular" => EnvSpecular, "transmitted" => Transmitted, "shadow" => Shadow
);

impl Term {
    /// The terms that add up to [`Term::All`] (in every model; a model without a term draws it
    /// black, see [`Term::in_model`]).
    pub const PARTS: [Term; 5] = [Term::Ambient, Term::Diffuse, Term::Specular, Term::EnvSpecular, Term::Transmitted];

    /// Whether `model` has this term: the Lambert rule has its fill (shown as ambient) and its lit
    /// part (diffuse); the Phong model has no transmitted term; the four-term sum has all but the
    /// environment's specular, which only the Phong model draws.
    pub fn in_model(self, model: IlluminationModel) -> bool {
        !matches!(
            (self, model),
            (Term::Specular, IlluminationModel::Lambert)
                | (Term::EnvSpecular, IlluminationModel::Lambert | IlluminationModel::Sum)
                | (Term::Transmitted, IlluminationModel::Lambert | IlluminationModel::Phong)
        )
    }

    /// Whether `scene` can show this term: its model has it, and the environment's specular needs
    /// an environment light.
    pub fn in_scene(self, scene: &Scene) -> bool {
        self.in_model(scene.illumination) && (self != Term::EnvSpecular || scene.environment.is_some())
    }

    /// The term's symbol in `model`: the four-term sum calls its specular term `I_r`, and the
    /// Lambert rule's ambient part is its fill `R(1−I)`.
    pub fn symbol_in(self, model: IlluminationModel) -> &'static str {
        match (self, model) {
            (Term::Specular, IlluminationModel::Sum) => "I_r",
            (Term::Ambient, IlluminationModel::Lambert) => "R(1−I)",
            (Term::Diffuse, IlluminationModel::Lambert) => "R·I·cos α",
            _ => self.symbol(),
        }
    }

    /// The chapter's symbol of the term (`all` for the whole model).
    pub fn symbol(self) -> &'static str {
        match self {
            Term::All => "all",
            Term::Ambient => "I_a",
            Term::Diffuse => "I_d",
            Term::Specular => "I_s",
            Term::EnvSpecular => "I_env,s",
            Term::Transmitted => "I_t",
            Term::Shadow => "V",
        }
    }

    /// What the term is, for a tooltip or a caption.
    pub fn meaning(self) -> &'static str {
        match self {
            Term::All => "the whole model: the sum of its terms",
            Term::Ambient => {
                "the ambient term I_amb·r_a·C alone, with the environment's diffuse light that stands for it"
            }
            Term::Diffuse => "the diffuse term Σ I_L·r_d·C·(N·L) alone, with cast shadows",
            Term::Specular => {
                "the specular term Σ I_L·r_s·S alone (the four-term sum's reflected I_r), with cast shadows"
            }
            Term::EnvSpecular => "the environment's specular r_s·L_pre·(F0·(E − B) + B) alone, by the split sum",
            Term::Transmitted => "the four-term sum's transmitted term Σ K_t·(1 − t)·I/(d + d0) alone",
            Term::Shadow => "the cast-shadow factor V: the share of the lights' light that reaches each point",
        }
    }

    /// `scene` with every coefficient of the other terms set to 0 (`All`: unchanged; `Shadow`:
    /// the shadowed terms, diffuse and specular, whose image with and without shadows gives the
    /// factor).
    pub fn scene(self, scene: &Scene) -> Scene {
        let mut s = scene.clone();
        self.apply(&mut s);
        s
    }

    /// Set the other terms' coefficients of `scene` to 0 in place (the lights, the geometry and
    /// this term's coefficients stay). A summand also drops the background (black, alpha 0), so
    /// the summands add up to the whole image on every pixel with the background composited
    /// under them; the shadow factor, not a summand, keeps it.
    pub fn apply(self, scene: &mut Scene) {
        if self == Term::All {
            return;
        }
        if self != Term::Shadow {
            scene.background = None;
            if let Some(e) = scene.environment.as_mut() {
                e.background = false;
            }
        }
        if self != Term::Ambient {
            scene.ambient = [0.0; 3];
        }
        // The environment's specular is its own term; the lights' terms are the others'. The
        // lights keep their directions: a sky follows the first directional one.
        if self == Term::EnvSpecular {
            for l in &mut scene.lights {
                l.intensity = 0.0;
            }
        } else if let Some(e) = scene.environment.as_mut() {
            e.specular = false;
        }
        for m in &mut scene.materials {
            // r_a weighs the Lambert rule's fill as well as the ambient term.
            if self != Term::Ambient {
                m.r_a = 0.0;
            }
            if self != Term::Transmitted {
                m.transmission = 0.0;
            }
            if self == Term::Shadow {
                continue;
            }
            if self != Term::Diffuse {
                m.r_d = 0.0;
            }
            if !matches!(self, Term::Specular | Term::EnvSpecular) {
                m.r_s = 0.0;
            }
        }
    }
}

/// Below this luminance of the unshadowed light a point has nothing to be shadowed (facing away
/// from every light, or the background): its factor is 1. 1e-6 is far below one 8-bit step and
/// far above f32 rounding of an unlit point (0).
pub const SHADOW_FACTOR_LIGHT_MIN: f64 = 1e-6;

/// The cast-shadow factor of a pixel: the luminance of its light with shadows over that without
/// (Rec. 709 weights), in [0, 1]; 1 where the unshadowed light is below
/// [`SHADOW_FACTOR_LIGHT_MIN`].
pub fn shadow_factor(shadowed: [f64; 3], unshadowed: [f64; 3]) -> f64 {
    let y = |c: [f64; 3]| 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    let (s, u) = (y(shadowed), y(unshadowed));
    if u < SHADOW_FACTOR_LIGHT_MIN || !(s.is_finite() && u.is_finite()) { 1.0 } else { (s / u).clamp(0.0, 1.0) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::SpecularModel;
    use crate::reference::render_reference;

    /// The f64 terms add up to the full image, pixel by pixel, in each of the four models (the
    /// four-term sum on a scene whose materials transmit, so that I_t is not zero; in the other
    /// models a transmitting material is glass, which the terms do not split), with the constant
    /// ambient and under an occluded sky in its place.
    #[test]
    fn the_reference_terms_sum_to_the_full_image() {
        use crate::lighting::env_map::{EnvSource, Environment};
        let sky = Environment { occlusion: true, ..Environment::new(EnvSource::Sky { turbidity: 3.0, sun: None }) };
        for (choice, env) in
            crate::params::ModelChoice::ALL_CHOICES.into_iter().flat_map(|c| [(c, None), (c, Some(sky.clone()))])
        {
            let mut scene = Scene::builtin("default").unwrap();
            if env.is_some() {
                (scene.environment, scene.ambient) = (env, [0.0; 3]);
            }
            let (model, specular) = choice.split();
            let specular = specular.unwrap_or(SpecularModel::Phong);
            scene.apply(&crate::scene::Overrides::for_model(choice));
            if model == crate::params::IlluminationModel::Sum {
                for m in &mut scene.materials {
                    m.transmission = 0.3;
                }
            }
            let full = render_reference(&scene, specular, 96, 54);
            let parts: Vec<_> =
                Term::PARTS.iter().map(|t| render_reference(&t.scene(&scene), specular, 96, 54)).collect();
            let mut worst = 0.0f64;
            let mut lit = 0;
            for (i, p) in full.pixels.iter().enumerate() {
                if full.object[i].is_none() {
                    continue;
                }
                lit += 1;
                for (c, whole) in p.iter().enumerate() {
                    let sum: f64 = parts.iter().map(|q| q.pixels[i][c]).sum();
                    worst = worst.max((sum - whole).abs());
                }
            }
            assert!(lit > 1000, "{lit} pixels on objects");
            assert!(worst < 1e-12, "{choice:?}: the terms differ from the whole by {worst}");
            // Each term the scene has is non-zero somewhere; a term it lacks is black.
            for (t, img) in Term::PARTS.iter().zip(&parts) {
                let on = img.pixels.iter().zip(&img.object).filter(|(p, o)| o.is_some() && p[0] > 1e-6).count();
                // The split sum is Cook–Torrance's: under Phong specular the term is black.
                if t.in_scene(&scene) && (*t != Term::EnvSpecular || specular == SpecularModel::CookTorrance) {
                    assert!(on > 100, "{choice:?} {t:?}: {on} pixels");
                } else {
                    assert_eq!(on, 0, "{choice:?} {t:?} is not a term of {model}");
                }
            }
        }
    }

    #[test]
    fn each_term_keeps_only_its_coefficients() {
        let s = Scene::builtin("default").unwrap();
        let a = Term::Ambient.scene(&s);
        assert!(a.ambient == s.ambient && a.materials.iter().all(|m| m.r_d == 0.0 && m.r_s == 0.0));
        let d = Term::Diffuse.scene(&s);
        assert!(
            d.ambient == [0.0; 3] && d.materials.iter().zip(&s.materials).all(|(m, o)| m.r_d == o.r_d && m.r_s == 0.0)
        );
        let sp = Term::Specular.scene(&s);
        assert!(
            sp.ambient == [0.0; 3]
                && sp.materials.iter().zip(&s.materials).all(|(m, o)| m.r_s == o.r_s && m.r_d == 0.0)
        );
        assert_eq!(Term::All.scene(&s), s);
    }
}
