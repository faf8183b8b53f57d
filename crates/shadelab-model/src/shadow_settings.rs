//! A light's shadow settings: whether it casts, its map's filter and resolution, PCSS's taps and
//! a directional light's cascades. Plain settings with their ranges, apart from the projections
//! and the layer plan (`shadows`), so that lights and the scene hold them without depending on
//! the code that reads the scene.

/// How the shadow map is filtered where a point is compared with it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShadowFilter {
    /// One comparison at the nearest texel: a hard, aliased edge.
    Hard,
    /// The hardware's 2×2 bilinear comparison (percentage-closer filtering over one texel).
    Pcf,
    /// Percentage-closer filtering over rotated Poisson-disk taps (a wider, smoother edge).
    Poisson,
    /// Percentage-closer soft shadows: the penumbra of an area light, as wide as its size and
    /// the blocker's and receiver's distances give (docs/area-lights.md); a light without an
    /// area gets `Pcf`'s edge.
    Pcss,
}

impl ShadowFilter {
    /// The value of `ShadowLight.shadow_filter` in WGSL: `SHADOW_FILTER_<NAME>` of `shaders/shadows.wgsl`.
    pub fn code(self) -> u32 {
        match self {
            ShadowFilter::Hard => 0,
            ShadowFilter::Pcf => 1,
            ShadowFilter::Poisson => 2,
            ShadowFilter::Pcss => 3,
        }
    }
}

crate::named_values!(ShadowFilter, "--shadow-filter",
    "hard" => Hard, "pcf" => Pcf, "poisson" => Poisson, "pcss" => Pcss
);

crate::param_ranges! {
    /// Side of a light's shadow map in texels (a cube face's side for a point light).
    pub const SHADOW_RESOLUTION = "--shadow-resolution", "N", "shadow map resolution in texels", [256.0, 4096.0];

    /// Taps of each of PCSS's two passes (blocker search, filter): 4 is a coarse but usable
    /// penumbra, 64 four times the default's cost; the study times several.
    pub const PCSS_TAPS = "--pcss-taps", "n", "taps of each PCSS pass", [4.0, 64.0];
}

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
    /// A directional light may split its map into cascades when the view calls for them
    /// ([`cascade_count`]); off, it keeps one map fitted to the whole scene.
    pub cascades: bool,
    /// Taps of each of PCSS's two passes, within [`PCSS_TAPS`].
    pub pcss_taps: u32,
}

impl Default for ShadowSettings {
    fn default() -> Self {
        ShadowSettings {
            casts: true,
            resolution: SHADOW_RESOLUTION_DEFAULT,
            filter: ShadowFilter::Pcf,
            cascades: true,
            pcss_taps: SHADOW_PCSS_TAPS,
        }
    }
}

impl ShadowSettings {
    /// The settings with the resolution kept inside [`SHADOW_RESOLUTION`] and the PCSS taps
    /// inside [`PCSS_TAPS`].
    pub fn clamped(self) -> ShadowSettings {
        let r = (self.resolution as f64).clamp(SHADOW_RESOLUTION.min, SHADOW_RESOLUTION.max) as u32;
        let taps = (self.pcss_taps as f64).clamp(PCSS_TAPS.min, PCSS_TAPS.max) as u32;
        ShadowSettings { resolution: r, pcss_taps: taps, ..self }
    }
}

/// The default taps of each of PCSS's two passes (`ShadowFilter::Pcss`): 32. The blocker search's
/// spiral puts n·√q of its taps in a blocker cone q of the search region wide; on the `penumbra`
/// scene (q ≈ 1/13 with the plate 1 m up) 16 taps put 4 there, too few to find a plate edge
/// covering the cone's outer tenth, and the penumbra's 10–90 % width measured 0.64–0.77 of the
/// reference's; 32 put 9 and measure 0.73–0.86 (64: 0.84–0.92), `bench penumbra`.
/// `ShadowSettings::pcss_taps` sets another count within [`PCSS_TAPS`].
pub const SHADOW_PCSS_TAPS: u32 = 32;
