//! The twin of `shaders/lights.wgsl`: light sources. A light kind is declared here once: its
//! kind and WGSL code, the `Light` parameters and their ranges, the values derived from them for
//! both the GPU and the f64 reference, and its f64 terms.

use super::area::{AreaLight, AreaShape, area_form, area_specular_point};
pub use super::brdf::LightSample;
use super::common::safe_normalize;
use crate::guards::*;
use crate::params::ParamRange;
use crate::shadow_settings::{ShadowFilter, ShadowSettings};
use glam::DVec3;

/// Light source kind (docs/model.md §6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightKind {
    /// Parallel light from a source at infinity.
    Directional,
    /// A point source with distance falloff.
    Point,
    /// A point source that lights only a cone (glTF's spot light): fully inside the inner cone,
    /// not at all outside the outer one, a smooth ramp between.
    Spot,
    /// A rectangle of uniform radiance emitting from its front face (docs/area-lights.md).
    Rect,
    /// A disk of uniform radiance emitting from its front face.
    Disk,
    /// A sphere of uniform radiance.
    Sphere,
}

impl LightKind {
    /// The value of `Light.kind` in WGSL: `LIGHT_<NAME>` of `shaders/lights.wgsl`.
    pub fn code(self) -> u32 {
        match self {
            LightKind::Directional => 0,
            LightKind::Point => 1,
            LightKind::Spot => 2,
            LightKind::Rect => 3,
            LightKind::Disk => 4,
            LightKind::Sphere => 5,
        }
    }

    // What a kind is, each decided here by an exhaustive match: code elsewhere asks these
    // rather than comparing kinds, so a new kind is named by the compiler in this one place.

    /// A light with an area: rectangle, disk or sphere.
    pub fn is_area(self) -> bool {
        use LightKind::*;
        match self {
            Rect | Disk | Sphere => true,
            Directional | Point | Spot => false,
        }
    }

    /// Light from one direction at infinity: no position, no falloff, cascaded shadow maps.
    pub fn is_directional(self) -> bool {
        use LightKind::*;
        match self {
            Directional => true,
            Point | Spot | Rect | Disk | Sphere => false,
        }
    }

    /// Lights only inside its cone (glTF's spot light).
    pub fn has_cone(self) -> bool {
        use LightKind::*;
        match self {
            Spot => true,
            Directional | Point | Rect | Disk | Sphere => false,
        }
    }

    /// Emits alike all round its position: no direction, axis or normal to set.
    pub fn emits_all_round(self) -> bool {
        use LightKind::*;
        match self {
            Point | Sphere => true,
            Directional | Spot | Rect | Disk => false,
        }
    }

    /// The name of its `direction` field where it has one: the way the light travels, a spot's
    /// axis or an emitting face's normal.
    pub fn direction_name(self) -> Option<&'static str> {
        use LightKind::*;
        match self {
            Directional => Some("direction"),
            Spot => Some("axis"),
            Rect | Disk => Some("normal"),
            Point | Sphere => None,
        }
    }

    /// What it is, for a tooltip beside its name (`None`: the name says it).
    pub fn meaning(self) -> Option<&'static str> {
        use LightKind::*;
        match self {
            Directional | Point => None,
            Spot => Some("a point light that lights only a cone (glTF's spot light)"),
            Rect => Some("a rectangle emitting from its front face: soft shadows"),
            Disk => Some("a disk emitting from its front face: soft shadows"),
            Sphere => Some("a sphere emitting all round: soft shadows"),
        }
    }

    /// The names of its `size` values (an area light's: a rectangle's width and height, a disk's
    /// or sphere's diameter); `None` for a kind without an area.
    pub fn size_names(self) -> Option<(&'static str, Option<&'static str>)> {
        use LightKind::*;
        match self {
            Rect => Some(("width", Some("height"))),
            Disk | Sphere => Some(("diameter", None)),
            Directional | Point | Spot => None,
        }
    }

    /// Its shadow map is a cube round its position (six faces), not one projection.
    pub fn has_cube_map(self) -> bool {
        use LightKind::*;
        match self {
            Point | Rect | Disk | Sphere => true,
            Directional | Spot => false,
        }
    }
}

crate::named_values!(LightKind, "--light",
    "directional" => Directional, "point" => Point, "spot" => Spot, "rect" => Rect, "disk" => Disk,
    "sphere" => Sphere
);

/// Which distance falloff a point light uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FalloffForm {
    /// `I0/(1 + α d²)` (docs/model.md §6).
    Quadratic,
    /// The chapter's `I0/(d + d0)` (docs/model.md §2).
    Linear,
}

impl FalloffForm {
    /// The value of `Light.falloff_form` in WGSL: `FALLOFF_<NAME>` of `shaders/lights.wgsl`.
    pub fn code(self) -> u32 {
        match self {
            FalloffForm::Quadratic => 0,
            FalloffForm::Linear => 1,
        }
    }
}

crate::named_values!(FalloffForm, "--falloff-form", "quadratic" => Quadratic, "linear" => Linear);

/// How an area light's specular is drawn (docs/area-lights.md): at its representative point,
/// or by linearly transformed cosines (`ltc.rs`), under Cook–Torrance; Phong's lobe keeps the
/// representative point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum AreaSpecular {
    /// The point light at the light's point nearest the mirror direction, its peak widened.
    #[default]
    Representative,
    /// The lobe's integral over the light by its fitted LTC.
    Ltc,
}

impl AreaSpecular {
    /// The value of `Light.area_specular` in WGSL: `AREA_SPECULAR_<NAME>` of `shaders/ltc.wgsl`.
    pub fn code(self) -> u32 {
        self as u32
    }
}

crate::named_values!(AreaSpecular, "--area-specular", "representative" => Representative, "ltc" => Ltc);

/// Most lights a scene may hold (the GPU uniform has this many slots; `MAX_LIGHTS` in WGSL).
pub const MAX_LIGHTS: usize = 8;

/// glTF's default outer cone of a spot light (π/4), also the cone a light gets when it is made
/// a spot light.
pub const SPOT_OUTER_CONE_DEFAULT: f64 = std::f64::consts::FRAC_PI_4;

/// How far from the origin a directional light is placed when it becomes a point light: twice as
/// far as any built-in object but the ground (all within 3 of the origin), so it lights them from
/// about the same direction as before.
pub const LIGHT_STAND_OFF: f64 = 6.0;

crate::param_ranges! {
    /// Falloff factor `α` of `I0/(1 + α d²)` (docs/model.md §6).
    pub const FALLOFF = "--falloff", "α", "falloff factor α", [0.0, 1e6];
    /// Minimum distance `d0` of the chapter's `1/(d + d0)` (docs/model.md §2); at least `D0_MIN`.
    pub const D0 = "--d0", "d0", "minimum distance d0 of 1/(d + d0)", [D0_MIN, 1e3];
    /// Half-angle of a spot light's cone, radians (glTF `innerConeAngle`, `outerConeAngle`): from
    /// the axis (0) to a half-space (π/2).
    pub const CONE_ANGLE = "cone angle", "θ", "spot cone half-angle in radians", [0.0, std::f64::consts::FRAC_PI_2];
}
/// [`CONE_ANGLE`] with π/2 rounded up to f32, as glTF files store it.
pub const CONE_ANGLE_F32: ParamRange = ParamRange { max: std::f32::consts::FRAC_PI_2 as f64, ..CONE_ANGLE };
crate::param_ranges! {
    /// Distance at which a point or spot light ends (glTF `range`).
    pub const RANGE = "range", "r", "light range (where its light ends)", [1e-6, 1e9];
    /// Light intensity `I_L` (an HDR multiplier of the light's colour).
    pub const INTENSITY = "intensity", "I_L", "light intensity I_L", [0.0, 1e3];

    /// An area light's size in metres: a rectangle's width (and height), a disk's or sphere's
    /// diameter. 0 is the point-light limit; 10⁶ m is far beyond any scene (the sweep's huge light).
    pub const LIGHT_SIZE = "--light-size", "w", "area light size in m (rect side, disk or sphere diameter)", [0.0, 1e6];

    /// How many point sources an area light is replaced by (0: none, the exact area form). 16
    /// points take 96 shadow-map layers (a cube each), which is what one light may take of
    /// `MAX_SHADOW_LAYERS`.
    pub const AREA_POINTS = "--area-points", "k", "point sources an area light is replaced by (0: exact area form)",
        [0.0, 16.0];
}

/// The size an area light gets when a light is made one: half a metre, about the built-in
/// scenes' objects' size, so its penumbra is plain to see.
pub const LIGHT_SIZE_DEFAULT: f64 = 0.5;

/// A light source (docs/model.md §6).
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    /// Position (point lights).
    pub position: DVec3,
    /// Direction the light travels (directional lights); `L = −direction`.
    pub direction: DVec3,
    /// Linear RGB colour.
    pub color: [f64; 3],
    /// Intensity `I_L` (multiplies the colour).
    pub intensity: f64,
    /// Falloff form of point lights.
    pub falloff_form: FalloffForm,
    /// `α` of `1/(1 + α d²)`.
    pub falloff_alpha: f64,
    /// `d0` of `1/(d + d0)`.
    pub d0: f64,
    /// Spot lights: half-angles of the inner cone (full light) and of the outer cone (no light
    /// beyond), radians, `0 ≤ inner < outer ≤ π/2` (glTF `innerConeAngle`, `outerConeAngle`).
    /// The axis is `direction`.
    pub inner_cone: f64,
    pub outer_cone: f64,
    /// Point and spot lights: the distance at which the light ends (glTF `range`), reached
    /// smoothly by [`window_range`]; `None`: it never ends.
    pub range: Option<f64>,
    /// Whether and how the light casts shadows (docs/model.md §0).
    pub shadow: ShadowSettings,
    /// Area lights: width and height in metres (a disk's or sphere's diameter in both), within
    /// [`LIGHT_SIZE`]. A rectangle or disk emits along `direction` (its normal).
    pub size: [f64; 2],
    /// Area lights: the direction of a rectangle's width (made perpendicular to the normal when
    /// used, see [`Light::area_light`]).
    pub tangent: DVec3,
    /// Area lights: 0 draws the exact area form; k ≥ 1 replaces the light by the chapter's k
    /// point sources on it, each with its own hard shadow (`area_points.rs`), within
    /// [`AREA_POINTS`].
    pub area_points: u32,
    /// Area lights drawn in their exact form: how the specular is drawn.
    pub area_specular: AreaSpecular,
}

impl Light {
    pub fn directional(direction: DVec3, color: [f64; 3], intensity: f64) -> Self {
        Light {
            kind: LightKind::Directional,
            direction: direction.normalize(),
            ..Light::point(-direction.normalize() * LIGHT_STAND_OFF, color, intensity, 0.0)
        }
    }
    pub fn point(position: DVec3, color: [f64; 3], intensity: f64, falloff_alpha: f64) -> Self {
        Light {
            kind: LightKind::Point,
            position,
            direction: (-position).normalize_or(DVec3::NEG_Y),
            color,
            intensity,
            falloff_form: FalloffForm::Quadratic,
            falloff_alpha,
            d0: 1.0,
            inner_cone: 0.0,
            outer_cone: SPOT_OUTER_CONE_DEFAULT,
            range: None,
            shadow: ShadowSettings::default(),
            size: [LIGHT_SIZE_DEFAULT; 2],
            tangent: DVec3::X,
            area_points: 0,
            area_specular: AreaSpecular::Representative,
        }
    }
    /// A spot light at `position` shining along `direction`, with cones `inner < outer` (radians).
    pub fn spot(
        position: DVec3,
        direction: DVec3,
        color: [f64; 3],
        intensity: f64,
        falloff_alpha: f64,
        (inner_cone, outer_cone): (f64, f64),
    ) -> Self {
        Light {
            kind: LightKind::Spot,
            direction: direction.normalize_or(DVec3::NEG_Y),
            inner_cone,
            outer_cone,
            ..Light::point(position, color, intensity, falloff_alpha)
        }
    }

    /// An area light of `kind` centred at `position`, a flat one facing along `direction`, of
    /// width and height `size` (a disk's or sphere's diameter in both).
    pub fn area(
        kind: LightKind,
        position: DVec3,
        direction: DVec3,
        size: [f64; 2],
        color: [f64; 3],
        intensity: f64,
        falloff_alpha: f64,
    ) -> Self {
        let mut light = Light::point(position, color, intensity, falloff_alpha);
        light.set_kind(kind);
        Light { direction: direction.normalize_or(DVec3::NEG_Y), size, ..light }
    }

    /// The light's size for its penumbra (`ShadowLight.light_size` in WGSL): the diameter of the
    /// disc of its area as seen face-on (a disk's or sphere's diameter, 1.13 × a square's side);
    /// 0 for a light without an area.
    pub fn penumbra_size(&self) -> f64 {
        self.area_light().map_or(0.0, |a| 2.0 * (a.emitting_area() / std::f64::consts::PI).sqrt())
    }

    /// The light's shape placed in the world, for area kinds: centre, unit normal (the way it
    /// emits), a unit tangent perpendicular to it (the rectangle's width), half-sizes or radius.
    pub fn area_light(&self) -> Option<AreaLight> {
        let half = |i: usize| self.size[i].abs() * 0.5;
        let shape = match self.kind {
            LightKind::Rect => AreaShape::Rect { half_x: half(0), half_y: half(1) },
            LightKind::Disk => AreaShape::Disk { radius: half(0) },
            LightKind::Sphere => AreaShape::Sphere { radius: half(0) },
            LightKind::Directional | LightKind::Point | LightKind::Spot => return None,
        };
        let normal = self.spot_axis();
        Some(AreaLight { shape, center: self.position, normal, tangent: self.area_tangent() })
    }

    /// The unit tangent of a flat light (WGSL `Light.tangent`): `tangent` made perpendicular to
    /// the normal, or any perpendicular when it is along the normal.
    pub fn area_tangent(&self) -> DVec3 {
        let normal = self.spot_axis();
        let t = self.tangent - normal * self.tangent.dot(normal);
        let any = if normal.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
        safe_normalize(t, (any - normal * any.dot(normal)).normalize())
    }

    /// Turn the light into another kind, keeping where it shines from: a directional light
    /// becomes a point or spot light `LIGHT_STAND_OFF` units back along its direction from the
    /// origin (a spot keeps the direction as its axis); a point light becomes a directional light
    /// or a spot light along the line from it to the origin; a spot light keeps its position
    /// (point) or its axis (directional).
    pub fn set_kind(&mut self, kind: LightKind) {
        use LightKind::*;
        match (self.kind, kind) {
            (Directional, Point | Spot | Rect | Disk | Sphere) => self.position = -self.direction * LIGHT_STAND_OFF,
            (Point, Directional | Spot | Rect | Disk | Sphere) => {
                self.direction = (-self.position).normalize_or(DVec3::NEG_Y)
            }
            _ => {}
        }
        // An area light's shadow is soft: it takes PCSS, which a light without an area gives back.
        if kind.is_area() && !self.kind.is_area() && self.shadow.filter == ShadowFilter::Pcf {
            self.shadow.filter = ShadowFilter::Pcss;
        }
        if !kind.is_area() && self.kind.is_area() && self.shadow.filter == ShadowFilter::Pcss {
            self.shadow.filter = ShadowFilter::Pcf;
        }
        self.kind = kind;
    }

    /// Whether the light is drawn as the chapter's k point sources (an area light with
    /// `area_points` ≥ 1) instead of its exact area form.
    pub fn drawn_as_points(&self) -> bool {
        self.kind.is_area() && self.area_points > 0
    }

    /// The shadow filter the light is drawn with: its own, except that PCSS becomes PCF where the
    /// light is drawn as points (each point casts a hard shadow; their mean is the penumbra).
    /// The effect analysis and the shadow uniform both ask this, so they cannot disagree.
    pub fn drawn_shadow_filter(&self) -> ShadowFilter {
        match self.shadow.filter {
            ShadowFilter::Pcss if self.drawn_as_points() => ShadowFilter::Pcf,
            f => f,
        }
    }

    /// The incident intensity `I_L` per channel before falloff: colour × intensity (WGSL
    /// `Light.radiance`).
    pub fn radiance(&self) -> [f64; 3] {
        self.color.map(|c| c * self.intensity)
    }

    /// The unit axis a spot light shines along (WGSL `Light.spot_axis`); straight down for a
    /// zero direction.
    pub fn spot_axis(&self) -> DVec3 {
        safe_normalize(self.direction, DVec3::NEG_Y)
    }

    /// Cosines of the spot's inner and outer half-angles (WGSL `Light.cos_inner`, `cos_outer`).
    pub fn cone_cosines(&self) -> (f64, f64) {
        (self.inner_cone.cos(), self.outer_cone.cos())
    }
}

/// docs/model.md §6: falloff `1/(1 + α d²)`; in (0, 1] for α ≥ 0.
pub fn falloff_quadratic(d: f64, alpha: f64) -> f64 {
    1.0 / (1.0 + alpha.max(0.0) * d * d)
}

/// docs/model.md §2: the chapter's `1/(d + d0)` falloff, `d0` kept at or above `D0_MIN`.
pub fn falloff_linear(d: f64, d0: f64) -> f64 {
    1.0 / (d.max(0.0) + d0.max(D0_MIN))
}

/// KHR_lights_punctual's spot cone (the extension's recommended form): 1 inside the inner cone,
/// 0 outside the outer one, between them the square of a ramp linear in the cosine. `cos_angle`
/// is the cosine between the spot's axis and the direction from the light to the point; the
/// span `cos_inner − cos_outer` is kept at or above `SPOT_COS_SPAN_MIN`.
pub fn spot_cone(cos_angle: f64, cos_inner: f64, cos_outer: f64) -> f64 {
    let t = ((cos_angle - cos_outer) / (cos_inner - cos_outer).max(SPOT_COS_SPAN_MIN)).clamp(0.0, 1.0);
    t * t
}

/// KHR_lights_punctual's range window (the extension's recommended form)
/// `clamp(1 − (d/range)⁴, 0, 1)`: the light fades to exactly 0 at `d = range`, with hardly any
/// change near the light. A range of 0 or less is none (1 everywhere).
pub fn window_range(d: f64, range: f64) -> f64 {
    if range <= 0.0 {
        return 1.0;
    }
    let x = (d.max(0.0) / range).min(1.0);
    let x2 = x * x;
    1.0 - x2 * x2
}

/// The light's radiance at `p` with unit normal `n` ([`light_sample`]'s `radiance`): its colour
/// times intensity, times its falloff, range window and cone at the distance and direction of
/// its position (a directional light's is constant).
pub fn light_radiance_at(light: &Light, p: DVec3, n: DVec3) -> [f64; 3] {
    incident(light, p, n).0
}

/// The light's radiance at `p` and the unit direction to it (to its position, `n` within
/// `LIGHT_DIST_MIN`; against a directional light's direction).
fn incident(light: &Light, p: DVec3, n: DVec3) -> ([f64; 3], DVec3) {
    let radiance = light.radiance();
    if light.kind.is_directional() {
        return (radiance, safe_normalize(-light.direction, n));
    }
    let to_light = light.position - p;
    let d = to_light.length();
    let l = if d > LIGHT_DIST_MIN { to_light / d } else { n };
    let mut f = match light.falloff_form {
        FalloffForm::Quadratic => falloff_quadratic(d, light.falloff_alpha),
        FalloffForm::Linear => falloff_linear(d, light.d0),
    };
    if let Some(range) = light.range {
        f *= window_range(d, range);
    }
    if light.kind.has_cone() {
        let (cos_inner, cos_outer) = light.cone_cosines();
        f *= spot_cone((-l).dot(light.spot_axis()), cos_inner, cos_outer);
    }
    (radiance.map(|r| r * f), l)
}

/// Direction to a light (unit), its incident intensity `I_L` per channel, and the diffuse and
/// specular factors at point `p` with unit normal `n`, seen along unit `v`, roughness `m` (read
/// by area lights only). A light with a position closer than `LIGHT_DIST_MIN` touches the
/// surface: `L = N`. An area light is its centre's point light (the same falloff at the distance
/// to its centre) with `N·L` replaced by the exact area form and the specular taken at its
/// representative point.
pub fn light_sample(light: &Light, p: DVec3, n: DVec3, v: DVec3, m: f64) -> LightSample {
    let (radiance, l) = incident(light, p, n);
    if light.kind.is_directional() {
        return LightSample { l, radiance, form: n.dot(l), spec_scale: 1.0, ltc: None };
    }
    match light.area_light().filter(|_| light.area_points == 0) {
        Some(area) => {
            let (l, spec_scale) = area_specular_point(&area, p, n, v, m);
            LightSample { l, radiance, form: area_form(&area, p, n), spec_scale, ltc: None }
        }
        None => LightSample { l, radiance, form: n.dot(l), spec_scale: 1.0, ltc: None },
    }
}
