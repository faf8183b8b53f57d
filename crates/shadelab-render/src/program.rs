//! What a draw runs: the per-frame render settings, and the [`Program`] they resolve to for a
//! scene (the lit shader of one shading mode and effect set, or the null-shader baseline).

use shadelab_model::effects::{self, Effect, EffectKey};
use shadelab_model::{Interpolation, Scene, ShadingMode, SpecularModel};

pub use crate::light_loop::LightLoop;

/// The effects that change the lighting itself per pixel: drawn in Phong shading only.
pub const PER_PIXEL_LIGHTING: [Effect; 3] =
    [Effect::MetalRoughnessTexture, Effect::OcclusionTexture, Effect::NormalTexture];

/// Which effect permutation draws a scene (resolved by [`Program::for_scene`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Specialization {
    /// Only the effects the scene calls for (`effects::analyze`).
    #[default]
    Specialized,
    /// Every effect present, the unneeded ones switched off at run time by the uniforms.
    Uber,
    /// A given set (the benchmark's floors: the specialized set less one effect).
    Fixed(EffectKey),
}

/// Per-frame choices that do not change the geometry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderSettings {
    pub shading: ShadingMode,
    pub specular: SpecularModel,
    /// Perspective-correct or the chapter's screen-space interpolation (Gouraud and Phong).
    pub interpolation: Interpolation,
    /// Paint pixels whose colour is NaN or infinite magenta.
    pub debug_nonfinite: bool,
    pub specialization: Specialization,
    /// Where the glass pass finds a path's exit.
    pub glass_exit: shadelab_model::lighting::transmission::GlassExit,
    /// What transparent objects' pixels show.
    pub glass_view: shadelab_model::lighting::transmission::GlassView,
}

impl RenderSettings {
    pub fn new(shading: ShadingMode, specular: SpecularModel) -> RenderSettings {
        RenderSettings { shading, specular, ..Default::default() }
    }
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            shading: ShadingMode::Phong,
            specular: SpecularModel::CookTorrance,
            interpolation: Interpolation::Perspective,
            debug_nonfinite: false,
            specialization: Specialization::Specialized,
            glass_exit: Default::default(),
            glass_view: Default::default(),
        }
    }
}

/// The shader program a draw runs. Plain `Copy + Hash`: with the target's colour format it is
/// the pipeline cache's key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Program {
    /// The lighting shader of one shading mode, containing `effects` (the specular model is one
    /// of them), its light loop built for the scene's lights or reading them from the uniforms.
    Lit { shading: ShadingMode, effects: EffectKey, interpolation: Interpolation, lights: LightLoop },
    /// The null-shader baseline: the same geometry (the smooth mesh), constant colour, no
    /// lighting. What rasterizing the scene costs, the denominator of the cost study.
    NullBaseline,
}

impl Program {
    /// The program that draws `scene` with `settings`: the shading mode, and the effects that
    /// `settings.specialization` picks (the scene's analysis, all of them, or a given set).
    pub fn for_scene(scene: &Scene, settings: &RenderSettings) -> Program {
        let analyzed = match settings.specialization {
            Specialization::Specialized => effects::analyze(scene, settings.specular).key,
            _ => EffectKey::NONE,
        };
        Program::for_analysis(scene, settings, analyzed)
    }

    /// [`Self::for_scene`] with the scene's effect analysis already made (`analyzed`, its key;
    /// used only when `settings` ask for the specialized program): the viewer analyzes a scene
    /// once per change and derives everything from that.
    pub fn for_analysis(scene: &Scene, settings: &RenderSettings, analyzed: EffectKey) -> Program {
        // The uber pipeline draws any scene: its loop reads the lights from the uniforms.
        let lights = match settings.specialization {
            Specialization::Uber => LightLoop::Dynamic,
            _ => LightLoop::for_scene(scene),
        };
        let effects = match settings.specialization {
            // The lighting maps vary the lighting per pixel, which flat and Gouraud shading
            // compute per face or vertex: Phong shading draws them.
            Specialization::Specialized if settings.shading == ShadingMode::Phong => analyzed,
            Specialization::Specialized => analyzed.without_all(&PER_PIXEL_LIGHTING),
            Specialization::Uber => EffectKey::UBER,
            Specialization::Fixed(k) => k,
        };
        // Flat shading interpolates nothing: one program whatever the setting.
        let interpolation =
            if settings.shading == ShadingMode::Flat { Interpolation::Perspective } else { settings.interpolation };
        Program::Lit { shading: settings.shading, effects, interpolation, lights }
    }

    /// The same program without the textures and vertex colours (for a scene that has
    /// no surface attributes to read: the uber program drawing it).
    pub fn without_surfaces(self) -> Program {
        match self {
            Program::Lit { shading, effects, interpolation, lights } => Program::Lit {
                shading,
                effects: effects.without_all(&effects::TEXTURE_EFFECTS).without(Effect::VertexColors),
                interpolation,
                lights,
            },
            Program::NullBaseline => Program::NullBaseline,
        }
    }

    /// The effects the shader module contains (none for the baseline).
    pub fn effects(self) -> EffectKey {
        match self {
            Program::Lit { effects, .. } => effects,
            Program::NullBaseline => EffectKey::NONE,
        }
    }

    /// The uber program of the same shading mode: what the viewer draws while this one builds.
    /// The baseline has no stand-in (it is itself).
    pub fn uber(self) -> Program {
        match self {
            // Without the surface effects: a scene may have no surface buffers to bind, and the
            // stand-in draws the material's factor for the moment the real pipeline builds.
            Program::Lit { shading, interpolation, .. } => {
                let lights = LightLoop::Dynamic;
                Program::Lit { shading, effects: EffectKey::UBER, interpolation, lights }.without_surfaces()
            }
            Program::NullBaseline => Program::NullBaseline,
        }
    }

    /// The entry point of the compute pass that lights its points before the scene pass
    /// (flat and Gouraud shading, `lighting_pass.rs`); `None` for Phong shading and the baseline.
    pub fn lighting_pass(self) -> Option<&'static str> {
        match self {
            Program::Lit { shading, .. } => crate::shaders::lighting_entry_point(shading),
            Program::NullBaseline => None,
        }
    }

    /// Whether it draws the flat (unindexed, per-face) mesh rather than the smooth one.
    pub fn draws_flat_mesh(self) -> bool {
        matches!(self, Program::Lit { shading: ShadingMode::Flat, .. })
    }

    /// How its light loop is built (dynamic for the baseline, which has none).
    pub fn light_loop(self) -> LightLoop {
        match self {
            Program::Lit { lights, .. } => lights,
            Program::NullBaseline => LightLoop::Dynamic,
        }
    }

    /// A short name for logs and labels.
    pub fn label(self) -> String {
        match self {
            Program::Lit { shading, effects, interpolation: Interpolation::Perspective, lights } => {
                format!("{shading:?} [{}] {}", effects.label(), lights.label())
            }
            Program::Lit { shading, effects, interpolation: Interpolation::Screen, lights } => {
                format!("{shading:?} screen-space [{}] {}", effects.label(), lights.label())
            }
            Program::NullBaseline => "null baseline".into(),
        }
    }
}
