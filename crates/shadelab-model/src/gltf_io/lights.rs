//! Lights: `KHR_lights_punctual` directional, point and spot lights, placed by their nodes (a
//! light shines along its node's −Z), mapped to the chapter's light sources (`I_L = E/π`, the
//! falloff `1/(1 + α d²)`, the spot's cones, glTF's `range`) and back, with the exact parameters
//! and the shadow settings in `extras.shadelab`; at most `MAX_LIGHTS` are kept, and a file
//! without lights gets a default one.

use super::extras::{
    self, AreaPoints, Cone, Count, D0, Falloff, Flag, Intensity, LightRange, LightSize, Named, Num, PcssTaps, Rgb,
    ShadowSide, Unit, Vec3, agrees,
};
use super::scene_file::{Reader, num, quat, rgb, vec3};
use super::{GltfError, POINT_FALLOFF_ALPHA};
use crate::brdf::safe_normalize;
use crate::params::{self, AreaSpecular, FalloffForm, LightKind, NamedValue};
use crate::scene::{Light, MAX_LIGHTS, Scene};
use crate::shadows::{ShadowFilter, ShadowSettings};
use glam::{DMat4, DQuat, DVec3};
use gltf::json;
use gltf::json::extensions::scene::khr_lights_punctual as khr;
use gltf::json::validation::Checked;
use serde_json::{Value, json};

super::extras_struct! {
    /// `extras.shadelab` of a light: the chapter's parameters exactly, and the exact placement (the
    /// node's fields are read as f32), used when it agrees (fields in the order they are checked).
    struct LightExtras {
        #[serde(rename = "I_L")]
        intensity: Option<Num<Intensity>>,
        color: Option<Rgb<Unit>>,
        /// Falloff α.
        alpha: Option<Num<Falloff>>,
        d0: Option<Num<D0>>,
        falloff_form: Option<Named<FalloffForm>>,
        position: Option<Vec3>,
        direction: Option<Vec3>,
        inner_cone: Option<Num<Cone>>,
        outer_cone: Option<Num<Cone>>,
        range: Option<Num<LightRange>>,
        /// The light's `ShadowSettings` (`crate::shadows`).
        casts_shadows: Option<Flag>,
        shadow_resolution: Option<Count<ShadowSide>>,
        shadow_filter: Option<Named<ShadowFilter>>,
        shadow_cascades: Option<Flag>,
        pcss_taps: Option<Count<PcssTaps>>,
        /// An area light (`rect`, `disk`, `sphere`; KHR_lights_punctual has none): the file's light
        /// is its point light (sphere) or hemisphere spot light (rectangle, disk), which other
        /// viewers draw; shadelab draws the area light its centre, size and tangent describe.
        area: Option<Named<LightKind>>,
        width: Option<Num<LightSize>>,
        height: Option<Num<LightSize>>,
        tangent: Option<Vec3>,
        /// How many point sources the area light is drawn as (0: its exact area form).
        points: Option<Count<AreaPoints>>,
        /// How the area light's specular is drawn: `representative` or `ltc`.
        specular: Option<Named<AreaSpecular>>,
    }
}

impl Reader<'_> {
    /// The lights of `light_nodes` (node, light, world matrix) into the scene: at most
    /// `MAX_LIGHTS` (a warning past it), a default directional light when there are none.
    pub(super) fn lights(
        &mut self,
        light_nodes: Vec<(usize, usize, DMat4)>,
        scene: &mut Scene,
    ) -> Result<(), GltfError> {
        let all = file_lights(self.root);
        for (ni, li, world) in light_nodes {
            let light = self.get(all, li, "light", &format!("node {ni}: "))?;
            let l = self.light(li, light, &world)?;
            scene.lights.push(l);
        }
        if scene.lights.len() > MAX_LIGHTS {
            self.cx.warn(format!(
                "{} lights: the first {MAX_LIGHTS} are kept (MAX_LIGHTS, the GPU's light slots)",
                scene.lights.len()
            ));
            scene.lights.truncate(MAX_LIGHTS);
        }
        if scene.lights.is_empty() {
            log::info!("{}: no lights; a default directional light is added", self.cx.file);
            self.cx.warn("no lights: a default directional light is added".into());
            scene.lights.push(Light::directional(DVec3::new(-0.55, -1.0, -0.7), [1.0; 3], 1.0));
        }
        Ok(())
    }

    fn light(&mut self, li: usize, l: &khr::Light, world: &DMat4) -> Result<Light, GltfError> {
        let what = format!("light {li}");
        let mut light = self.file_light(&what, l, world)?;
        // The file's kind: an area light in the extras replaces `light.kind`, not this.
        let kind = light.kind;
        let ex: LightExtras = extras::read(&self.cx, &l.extras, &what)?;
        let file_filter = exact_params(&mut light, &ex);
        self.area_params(&what, &mut light, &ex, kind, world, file_filter);
        self.held_cones(&what, light, kind)
    }

    /// The light as the file's own fields describe it, before `extras.shadelab` is applied.
    fn file_light(&mut self, what: &str, l: &khr::Light, world: &DMat4) -> Result<Light, GltfError> {
        let intensity = l.intensity as f64;
        if !intensity.is_finite() || intensity < 0.0 || !l.color.iter().all(|c| c.is_finite()) {
            return Err(self
                .cx
                .invalid(format!("{what}: intensity {intensity} or colour {:?} is not finite and ≥ 0", l.color)));
        }
        let position = world.transform_point3(DVec3::ZERO);
        let direction = safe_normalize(world.transform_vector3(DVec3::NEG_Z), DVec3::NEG_Y);
        let color = l.color.map(|c| (c as f64).clamp(0.0, 1.0));
        // glTF: lux (directional) or candela (point, spot); `I_L = E/π` (see the module's docs).
        let mut i_l = intensity / std::f64::consts::PI;
        if i_l > params::INTENSITY.max {
            self.cx.warn(format!("{what}: I_L = intensity/π = {i_l} is clamped to {}", params::INTENSITY.max));
            i_l = params::INTENSITY.max;
        }
        let kind = match l.type_ {
            Checked::Valid(khr::Type::Directional) => LightKind::Directional,
            Checked::Valid(khr::Type::Point) => LightKind::Point,
            Checked::Valid(khr::Type::Spot) => LightKind::Spot,
            Checked::Invalid => return Err(self.cx.invalid(format!("{what}: unknown light type"))),
        };
        let (inner_cone, outer_cone) = match (&l.spot, kind) {
            (Some(s), LightKind::Spot) => (s.inner_cone_angle as f64, s.outer_cone_angle as f64),
            (None, LightKind::Spot) => return Err(self.cx.invalid(format!("{what}: a spot light without `spot`"))),
            _ => (0.0, crate::scene::SPOT_OUTER_CONE_DEFAULT),
        };
        let range = match l.range {
            Some(r) if kind.is_directional() => {
                self.cx.warn(format!("{what}: range {r} ignored: a directional light has no distance"));
                None
            }
            Some(r) => Some(params::RANGE.check(r as f64).map_err(|_| {
                self.cx.invalid(format!("{what}: range {r} is not in [{}, {}]", params::RANGE.min, params::RANGE.max))
            })?),
            None => None,
        };
        Ok(Light {
            kind,
            position,
            direction,
            color,
            intensity: i_l,
            falloff_form: FalloffForm::Quadratic,
            falloff_alpha: if kind.is_directional() { 0.0 } else { POINT_FALLOFF_ALPHA },
            d0: 1.0,
            inner_cone,
            outer_cone,
            range,
            shadow: ShadowSettings::default(),
            size: [crate::lighting::lights::LIGHT_SIZE_DEFAULT; 2],
            tangent: DVec3::X,
            area_points: 0,
            area_specular: AreaSpecular::Representative,
        })
    }

    /// The extras' area light, size, tangent, point count and specular (`kind`: the file's light
    /// kind).
    fn area_params(
        &mut self,
        what: &str,
        light: &mut Light,
        ex: &LightExtras,
        kind: LightKind,
        world: &DMat4,
        file_filter: bool,
    ) {
        match ex.area.as_ref().map(|a| a.0) {
            Some(area) if area.is_area() && !kind.is_directional() => {
                light.kind = area;
                // The file's spot cone stands in for a flat light's face; the light has none.
                light.inner_cone = 0.0;
                light.outer_cone = crate::scene::SPOT_OUTER_CONE_DEFAULT;
                light.tangent = world.transform_vector3(DVec3::X);
                // Soft shadows unless the file chose a filter.
                if !file_filter {
                    light.shadow.filter = ShadowFilter::Pcss;
                }
            }
            Some(area) => self.cx.warn(format!(
                "{what}: extras area \"{}\" ignored: it must be rect, disk or sphere on a point or spot light",
                area.name()
            )),
            None => {
                if ex.width.is_some() || ex.height.is_some() || ex.points.is_some() || ex.specular.is_some() {
                    self.cx
                        .warn(format!("{what}: extras width, height, points and specular ignored: not an area light"));
                }
            }
        }
        if let Some(v) = &ex.width {
            light.size[0] = v.0;
        }
        light.size[1] = ex.height.as_ref().map_or(light.size[0], |v| v.0);
        if let Some(t) = &ex.tangent {
            light.tangent = t.0;
        }
        if let Some(k) = ex.points.as_ref().filter(|_| light.kind.is_area()) {
            light.area_points = k.0;
        }
        if let Some(s) = ex.specular.as_ref().filter(|_| light.kind.is_area()) {
            light.area_specular = s.0;
        }
    }

    /// The light with its spot cones checked and held to [0, π/2] (`kind`: the file's light kind).
    fn held_cones(&self, what: &str, mut light: Light, kind: LightKind) -> Result<Light, GltfError> {
        // glTF's f32 π/2 is a little above f64's: the cones are held to [0, π/2] after the check.
        let (inner, outer) = (light.inner_cone, light.outer_cone);
        let span = params::CONE_ANGLE_F32;
        if kind.has_cone() && !(span.min <= inner && inner < outer && outer <= span.max) {
            return Err(self.cx.invalid(format!(
                "{what}: spot cone angles inner {}, outer {} must be 0 ≤ inner < outer ≤ π/2 (radians)",
                // As the file wrote them (f32), not widened to f64's digits.
                inner as f32,
                outer as f32
            )));
        }
        light.inner_cone = inner.min(params::CONE_ANGLE.max);
        light.outer_cone = outer.min(params::CONE_ANGLE.max);
        Ok(light)
    }
}

/// The extras' exact parameters and shadow settings over the light; whether they chose a filter.
fn exact_params(light: &mut Light, ex: &LightExtras) -> bool {
    let set = |field: &mut f64, v: Option<f64>| {
        if let Some(v) = v {
            *field = v;
        }
    };
    set(&mut light.intensity, ex.intensity.as_ref().map(|v| v.0));
    if let Some(c) = &ex.color {
        light.color = c.0;
    }
    set(&mut light.falloff_alpha, ex.alpha.as_ref().map(|v| v.0));
    set(&mut light.d0, ex.d0.as_ref().map(|v| v.0));
    if let Some(f) = &ex.falloff_form {
        light.falloff_form = f.0;
    }
    if let Some(p) = ex.position.as_ref().filter(|p| agrees(p.0, light.position)) {
        light.position = p.0;
    }
    if let Some(d) = ex.direction.as_ref().filter(|d| agrees(d.0, light.direction)) {
        light.direction = d.0;
    }
    set(&mut light.inner_cone, ex.inner_cone.as_ref().map(|v| v.0));
    set(&mut light.outer_cone, ex.outer_cone.as_ref().map(|v| v.0));
    if let Some(v) = &ex.range {
        light.range = Some(v.0);
    }
    if let Some(c) = &ex.casts_shadows {
        light.shadow.casts = c.0;
    }
    if let Some(r) = &ex.shadow_resolution {
        light.shadow.resolution = r.0;
    }
    if let Some(c) = &ex.shadow_cascades {
        light.shadow.cascades = c.0;
    }
    if let Some(n) = &ex.pcss_taps {
        light.shadow.pcss_taps = n.0;
    }
    if let Some(f) = &ex.shadow_filter {
        light.shadow.filter = f.0;
    }
    ex.shadow_filter.is_some()
}

/// Light `i` as a `KHR_lights_punctual` light and the node that places it (its −Z along the
/// light's direction). `intensity = I_L·π` (the loader's `I_L = E/π` backwards); a quadratic
/// point or spot light's is divided by α, so that `I_L/(1 + αd²)` and glTF's `intensity/(π d²)`
/// agree far from the light. The exact parameters go in `extras.shadelab`.
pub(super) fn write_light(i: usize, l: &Light) -> (Value, Value) {
    let pi = std::f64::consts::PI;
    let (kind, intensity) = if l.kind.is_directional() {
        ("directional", l.intensity * pi)
    } else {
        // Other viewers see a sphere light as a point light, a flat one as a spot lighting
        // the half-space in front of it.
        let kind = if l.kind.emits_all_round() { "point" } else { "spot" };
        let far = if l.falloff_form == FalloffForm::Quadratic && l.falloff_alpha > 0.0 { l.falloff_alpha } else { 1.0 };
        (kind, l.intensity * pi / far)
    };
    let spot = l.kind.has_cone();
    let area = l.kind.is_area();
    let range = l.range.filter(|_| !l.kind.is_directional());
    let ex = LightExtras {
        intensity: Some(l.intensity.into()),
        color: Some(l.color.into()),
        alpha: Some(l.falloff_alpha.into()),
        d0: Some(l.d0.into()),
        falloff_form: Some(Named(l.falloff_form)),
        position: Some(Vec3(l.position)),
        direction: Some(Vec3(l.direction)),
        inner_cone: spot.then(|| l.inner_cone.into()),
        outer_cone: spot.then(|| l.outer_cone.into()),
        range: range.map(Num::from),
        casts_shadows: Some(Flag(l.shadow.casts)),
        // A validated light's side is in range; one that is not is written held to it.
        shadow_resolution: Some(l.shadow.clamped().resolution.into()),
        shadow_filter: Some(Named(l.shadow.filter)),
        shadow_cascades: Some(Flag(l.shadow.cascades)),
        pcss_taps: Some(l.shadow.clamped().pcss_taps.into()),
        area: area.then_some(Named(l.kind)),
        width: area.then(|| l.size[0].into()),
        height: area.then(|| l.size[1].into()),
        tangent: area.then(|| Vec3(l.area_tangent())),
        points: area.then(|| l.area_points.into()),
        specular: area.then_some(Named(l.area_specular)),
    };
    let mut light = json!({
        "type": kind,
        "color": rgb(l.color),
        "intensity": num(intensity),
        "extras": extras::shadelab(&ex),
    });
    if spot {
        light["spot"] = json!({ "innerConeAngle": num(l.inner_cone), "outerConeAngle": num(l.outer_cone) });
    } else if kind == "spot" {
        light["spot"] = json!({ "innerConeAngle": 0.0, "outerConeAngle": num(params::CONE_ANGLE_F32.max) });
    }
    if let Some(r) = range {
        light["range"] = num(r);
    }
    let node = json!({
        "name": format!("light {i}"),
        "translation": vec3(l.position),
        "rotation": quat(DQuat::from_rotation_arc(DVec3::NEG_Z, l.direction.normalize_or(DVec3::NEG_Y))),
        "extensions": { "KHR_lights_punctual": { "light": i } },
    });
    (light, node)
}

/// The `KHR_lights_punctual` lights of a parsed file (none without the extension).
fn file_lights(root: &json::Root) -> &[khr::Light] {
    root.extensions.as_ref().and_then(|e| e.khr_lights_punctual.as_ref()).map_or(&[][..], |l| &l.lights[..])
}
