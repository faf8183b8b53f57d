//! Cast shadows (docs/model.md §0, §6): each light's shadow settings (whether it casts, the
//! shadow map's resolution, the filter) with their ranges. The GPU answers "is this point seen by
//! the light" from a shadow map (`shaders/shadows.wgsl`, `shadelab_render::shadow_pass`); the f64
//! reference answers it exactly by tracing a ray to the light (`reference`).

use crate::params::{NamedValue, ParamRange};

/// How the shadow map is filtered where a point is compared with it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShadowFilter {
    /// One comparison at the nearest texel: a hard, aliased edge.
    Hard,
    /// The hardware's 2×2 bilinear comparison (percentage-closer filtering over one texel).
    Pcf,
    /// Percentage-closer filtering over rotated Poisson-disk taps (a wider, smoother edge).
    Poisson,
}

impl ShadowFilter {
    /// The value of `Light.shadow_filter` in WGSL: `SHADOW_FILTER_<NAME>` of `shaders/shadows.wgsl`.
    pub fn code(self) -> u32 {
        match self {
            ShadowFilter::Hard => 0,
            ShadowFilter::Pcf => 1,
            ShadowFilter::Poisson => 2,
        }
    }
}

impl NamedValue for ShadowFilter {
    const FLAG: &'static str = "--shadow-filter";
    const ALL: &'static [(&'static str, Self)] =
        &[("hard", ShadowFilter::Hard), ("pcf", ShadowFilter::Pcf), ("poisson", ShadowFilter::Poisson)];
}

/// Side of a light's shadow map in texels (a cube face's side for a point light).
pub const SHADOW_RESOLUTION: ParamRange = ParamRange {
    flag: "--shadow-resolution",
    symbol: "N",
    meaning: "shadow map resolution in texels",
    min: 256.0,
    max: 4096.0,
};

/// The shadow map side a light gets unless it says otherwise.
pub const SHADOW_RESOLUTION_DEFAULT: u32 = 2048;

/// One light's shadow settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ShadowSettings {
    /// The light casts shadows (when the scene has something to shadow; see the effect analysis).
    pub casts: bool,
    /// Shadow map side in texels, within [`SHADOW_RESOLUTION`].
    pub resolution: u32,
    pub filter: ShadowFilter,
}

impl Default for ShadowSettings {
    fn default() -> Self {
        ShadowSettings { casts: true, resolution: SHADOW_RESOLUTION_DEFAULT, filter: ShadowFilter::Pcf }
    }
}

impl ShadowSettings {
    /// The settings with the resolution kept inside [`SHADOW_RESOLUTION`].
    pub fn clamped(self) -> ShadowSettings {
        let r = (self.resolution as f64).clamp(SHADOW_RESOLUTION.min, SHADOW_RESOLUTION.max) as u32;
        ShadowSettings { resolution: r, ..self }
    }
}
