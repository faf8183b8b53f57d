//! A view's scene edits as link keys (docs/web.md, "Links"): every material, every light with its
//! shadow settings, the ambient term and the environment, each written only where it differs from
//! the scene the link's other keys open, so a link to an untouched scene stays short. A float is
//! written in the shortest form that reads back to the same bits; a value is read with the range
//! or the names its flag has, and a bad one is named by its key while the others apply.

use glam::DVec3;
use shadelab_model::lighting::env_map::{ENV_INTENSITY, ENV_RADIANCE, ENV_ROTATION, EnvKind, EnvSource, Environment};
use shadelab_model::lighting::lights::{self, Light, MAX_LIGHTS};
use shadelab_model::lighting::sky::TURBIDITY;
use shadelab_model::params::{self, NamedValue, ParamRange, PhongExponent};
use shadelab_model::scene::{Material, Overrides};
use shadelab_model::shadow_settings::{PCSS_TAPS, SHADOW_RESOLUTION};
use shadelab_model::{ModelChoice, Scene};

shadelab_model::param_ranges! {
    /// A light's position or an area light's tangent, per coordinate: a million metres, far past
    /// any scene a link opens (the built-in ones span a few).
    pub const COORDINATE = "coordinate", "x", "a coordinate in metres", [-1e6, 1e6];
    /// How many lights a link's scene holds: the uniform's slots.
    pub const LIGHT_COUNT = "lights", "N", "number of lights (MAX_LIGHTS)", [0.0, MAX_LIGHTS as f64];
}

/// A direction shorter than this has no direction to keep: 1e-12 is far below any direction a
/// panel or a file writes (unit vectors) and far above f64's underflow.
const DIRECTION_LENGTH_MIN: f64 = 1e-12;

/// One field of a `T` a link carries: its key, its value as text and its reading.
struct Field<T> {
    key: &'static str,
    get: fn(&T) -> String,
    set: fn(&mut T, &str) -> Result<(), String>,
}

/// A float in the shortest form that reads back to the same bits (Rust's `Display` of `f64`).
fn num(x: f64) -> String {
    format!("{x}")
}

fn list(xs: &[f64]) -> String {
    xs.iter().map(|x| num(*x)).collect::<Vec<_>>().join(",")
}

fn on_or_off(on: bool) -> String {
    if on { "on" } else { "off" }.to_string()
}

fn real(range: ParamRange, text: &str) -> Result<f64, String> {
    range.parse(text).map_err(|e| e.to_string())
}

fn count(range: ParamRange, text: &str) -> Result<u32, String> {
    range.parse_u32(text).map_err(|e| e.to_string())
}

/// `N` numbers `a,b,…`, each within `range`.
fn numbers<const N: usize>(range: ParamRange, text: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = text.split(',').collect();
    if parts.len() != N {
        return Err(format!("'{text}' is not {N} numbers a,b,… in [{}, {}] ({})", range.min, range.max, range.meaning));
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(parts) {
        *o = real(range, p)?;
    }
    Ok(out)
}

fn vector(text: &str) -> Result<DVec3, String> {
    numbers::<3>(COORDINATE, text).map(DVec3::from_array)
}

fn direction(text: &str) -> Result<DVec3, String> {
    let d = vector(text)?;
    if d.length() < DIRECTION_LENGTH_MIN {
        return Err(format!("'{text}' has no direction (length below {DIRECTION_LENGTH_MIN})"));
    }
    Ok(d)
}

/// `on`/`off` and their usual spellings.
pub(super) fn on_off(value: &str) -> Option<bool> {
    match value.to_ascii_lowercase().as_str() {
        "on" | "true" | "1" | "yes" | "" => Some(true),
        "off" | "false" | "0" | "no" => Some(false),
        _ => None,
    }
}

fn switch(text: &str) -> Result<bool, String> {
    on_off(text).ok_or_else(|| format!("'{text}' is not on or off"))
}

fn named<T: NamedValue>(text: &str) -> Result<T, String> {
    T::parse_named(text).map_err(|e| e.to_string())
}

fn phong(h: PhongExponent) -> String {
    match h {
        PhongExponent::Finite(h) => num(h),
        PhongExponent::Mirror => "mirror".into(),
    }
}

/// A field read by `$read` (a real or a count within a range, a switch, a name) and written by
/// `$write`.
macro_rules! field {
    ($key:literal, $($f:ident).+, $write:expr, $read:expr) => {
        Field {
            key: $key,
            get: |t| $write(t.$($f).+),
            set: |t, v| {
                t.$($f).+ = $read(v)?;
                Ok(())
            },
        }
    };
}

macro_rules! real {
    ($key:literal, $($f:ident).+, $range:expr) => {
        field!($key, $($f).+, num, |v| real($range, v))
    };
}

macro_rules! rgb {
    ($key:literal, $($f:ident).+, $range:expr) => {
        field!($key, $($f).+, |c: [f64; 3]| list(&c), |v| numbers::<3>($range, v))
    };
}

macro_rules! switch {
    ($key:literal, $($f:ident).+) => {
        field!($key, $($f).+, on_or_off, switch)
    };
}

macro_rules! named {
    ($key:literal, $($f:ident).+) => {
        field!($key, $($f).+, |x: _| NamedValue::name(x).to_string(), named)
    };
}

/// A material's fields, `mat<i>.<key>`: the chapter's parameters, glass and the microfacet terms.
const MATERIAL: &[Field<Material>] = &[
    rgb!("C", color, params::UNIT),
    real!("r_s", r_s, params::UNIT),
    real!("r_d", r_d, params::UNIT),
    real!("r_a", r_a, params::UNIT),
    real!("m", m, params::M),
    field!("h", h, phong, |v| params::parse_h(v).map_err(|e| e.to_string())),
    rgb!("mu", mu, params::MU),
    real!("t", transmission, params::TRANSMISSION),
    field!("ior", ior, |c: Option<[f64; 3]>| c.map_or("auto".into(), |c| list(&c)), |v: &str| match v {
        "auto" => Ok(None),
        v => numbers::<3>(params::IOR, v).map(Some),
    }),
    rgb!("a", absorption, params::ABSORPTION),
    real!("d", thickness, params::THICKNESS),
    rgb!("e", emission, params::UNIT),
    named!("D", microfacet.d),
    named!("G", microfacet.g),
    named!("F", microfacet.f),
    switch!("ms", microfacet.multiple_scattering),
    switch!("fmix", microfacet.fresnel_mix),
    real!("fmix-f0", fresnel_mix.f0, params::UNIT),
    real!("fmix-w", fresnel_mix.weight, params::UNIT),
    switch!("norm", phong_normalized),
];

/// A light's fields, `light<i>.<key>`: kind, placement, falloff, cone, area and shadows.
const LIGHT: &[Field<Light>] = &[
    named!("kind", kind),
    field!("pos", position, |v: DVec3| list(&v.to_array()), vector),
    field!("dir", direction, |v: DVec3| list(&v.to_array()), direction),
    rgb!("C", color, params::UNIT),
    real!("I", intensity, lights::INTENSITY),
    named!("form", falloff_form),
    real!("alpha", falloff_alpha, lights::FALLOFF),
    real!("d0", d0, lights::D0),
    real!("inner", inner_cone, lights::CONE_ANGLE),
    real!("outer", outer_cone, lights::CONE_ANGLE),
    field!("range", range, |r: Option<f64>| r.map_or("none".into(), num), |v: &str| match v {
        "none" => Ok(None),
        v => real(lights::RANGE, v).map(Some),
    }),
    field!("size", size, |s: [f64; 2]| list(&s), |v| numbers::<2>(lights::LIGHT_SIZE, v)),
    field!("tangent", tangent, |v: DVec3| list(&v.to_array()), direction),
    field!("points", area_points, |n: u32| n.to_string(), |v| count(lights::AREA_POINTS, v)),
    named!("spec", area_specular),
    switch!("shadows", shadow.casts),
    field!("res", shadow.resolution, |n: u32| n.to_string(), |v| count(SHADOW_RESOLUTION, v)),
    named!("filter", shadow.filter),
    switch!("cascades", shadow.cascades),
    field!("taps", shadow.pcss_taps, |n: u32| n.to_string(), |v| count(PCSS_TAPS, v)),
];

/// The environment's fields, `env.<key>`, after `env=<source>`.
const ENVIRONMENT: &[Field<Environment>] = &[
    real!("I", intensity, ENV_INTENSITY),
    real!("rot", rotation_deg, ENV_ROTATION),
    switch!("spec", specular),
    switch!("occl", occlusion),
    switch!("bg", background),
];

/// A light the link adds past the scene's own: the panel's new light, before its keys.
pub fn added_light() -> Light {
    Light::point(DVec3::new(2.0, 2.5, 2.0), [1.0; 3], 1.0, 0.05)
}

/// The source's own fields: a uniform one's radiance, the sky's turbidity and sun.
fn source_keys(source: &EnvSource, base: Option<&EnvSource>, out: &mut Vec<(String, String)>) {
    match (source, base) {
        (EnvSource::Uniform(c), Some(EnvSource::Uniform(b))) if c == b => {}
        (EnvSource::Uniform(c), _) => out.push(("env.L".into(), list(c))),
        (EnvSource::Sky { turbidity, sun }, b) => {
            let (bt, bs) = match b {
                Some(EnvSource::Sky { turbidity, sun }) => (Some(*turbidity), Some(*sun)),
                _ => (None, None),
            };
            if bt != Some(*turbidity) {
                out.push(("env.T".into(), num(*turbidity)));
            }
            if bs != Some(*sun) {
                out.push(("env.sun".into(), sun.map_or("follow".into(), |s| list(&s.to_array()))));
            }
        }
        (EnvSource::Image(_), _) => {}
    }
}

fn diff<T>(fields: &[Field<T>], prefix: &str, now: &T, base: &T, out: &mut Vec<(String, String)>) {
    for f in fields {
        let v = (f.get)(now);
        if v != (f.get)(base) {
            out.push((format!("{prefix}{}", f.key), v));
        }
    }
}

/// The keys that take `base` to `scene`, in the order they are read back; and a note where
/// something cannot travel (an image environment, which is a file).
pub fn scene_keys(scene: &Scene, base: &Scene) -> (Vec<(String, String)>, Option<String>) {
    let mut out = Vec::new();
    if scene.ambient != base.ambient {
        out.push(("Ia".into(), list(&scene.ambient)));
    }
    for (i, (m, b)) in scene.materials.iter().zip(&base.materials).enumerate() {
        diff(MATERIAL, &format!("mat{i}."), m, b, &mut out);
    }
    if scene.lights.len() != base.lights.len() {
        out.push(("lights".into(), scene.lights.len().to_string()));
    }
    let added = added_light();
    for (i, l) in scene.lights.iter().enumerate() {
        diff(LIGHT, &format!("light{i}."), l, base.lights.get(i).unwrap_or(&added), &mut out);
    }
    let mut note = None;
    match (&scene.environment, &base.environment) {
        (None, None) => {}
        (None, Some(_)) => out.push(("env".into(), "none".into())),
        (Some(e), _) if e.source.kind() == EnvKind::Image => {
            note = Some("an image environment is a file, which a link cannot carry: it is left out".to_string());
        }
        (Some(e), b) => {
            let kind = e.source.kind();
            let from = match b {
                Some(b) if b.source.kind() == kind => b.clone(),
                _ => {
                    out.push(("env".into(), kind.name().into()));
                    Environment::new(EnvSource::starting(kind, scene.ambient).expect("not an image"))
                }
            };
            source_keys(&e.source, Some(&from.source), &mut out);
            diff(ENVIRONMENT, "env.", e, &from, &mut out);
        }
    }
    (out, note)
}

/// The scene a file's link writes its edits against: the file's scene as loaded, under the
/// link's model (as `ModeArgs::settle` gives it).
pub fn base(raw: &Scene, model: ModelChoice) -> Scene {
    let mut s = raw.clone();
    s.apply(&Overrides::for_model(model));
    s
}

/// Whether `key` is one of a scene's edits (read by [`apply_scene_key`] once the scene is open).
pub fn is_scene_key(key: &str) -> bool {
    let indexed = |prefix: &str| {
        key.strip_prefix(prefix).and_then(|r| r.split_once('.')).is_some_and(|(i, _)| i.parse::<usize>().is_ok())
    };
    matches!(key, "Ia" | "lights" | "env") || key.starts_with("env.") || indexed("mat") || indexed("light")
}

fn set<T>(fields: &[Field<T>], t: &mut T, key: &str, value: &str) -> Result<(), String> {
    let f = fields.iter().find(|f| f.key == key).ok_or_else(|| {
        let keys: Vec<&str> = fields.iter().map(|f| f.key).collect();
        format!("'{key}' is not one of {}", keys.join(", "))
    })?;
    (f.set)(t, value)
}

/// Whether a key changes what the other keys apply to (the light count, the environment's
/// source): those are read first.
pub fn is_structural(key: &str) -> bool {
    matches!(key, "lights" | "env")
}

/// Apply one edit to `scene`; an error says what is wrong with the value or the index.
pub fn apply_scene_key(scene: &mut Scene, key: &str, value: &str) -> Result<(), String> {
    let indexed = |prefix: &str, noun: &str, len: usize| -> Result<Option<(usize, String)>, String> {
        let Some((i, field)) = key.strip_prefix(prefix).and_then(|r| r.split_once('.')) else {
            return Ok(None);
        };
        let i: usize = i.parse().map_err(|_| format!("'{i}' is not an index"))?;
        if i >= len {
            return Err(format!("the scene has {len} {noun}: index {i} is past them"));
        }
        Ok(Some((i, field.to_string())))
    };
    match key {
        "Ia" => scene.ambient = numbers::<3>(params::UNIT, value)?,
        "lights" => {
            let n = count(LIGHT_COUNT, value)? as usize;
            scene.lights.resize(n, added_light());
        }
        "env" => {
            scene.environment = match value {
                "none" => None,
                v => match named::<EnvKind>(v)? {
                    EnvKind::Image => return Err("an image environment is a file, which a link cannot carry".into()),
                    kind => EnvSource::starting(kind, scene.ambient).map(Environment::new),
                },
            }
        }
        _ => {
            if let Some(field) = key.strip_prefix("env.") {
                let env = scene.environment.as_mut().ok_or("the scene has no environment: give env= first")?;
                return apply_env_key(env, field, value);
            }
            if let Some((i, field)) = indexed("mat", "materials", scene.materials.len())? {
                return set(MATERIAL, &mut scene.materials[i], &field, value);
            }
            if let Some((i, field)) = indexed("light", "lights", scene.lights.len())? {
                return set(LIGHT, &mut scene.lights[i], &field, value);
            }
            return Err(format!("'{key}' is not a key of a scene"));
        }
    }
    Ok(())
}

fn apply_env_key(env: &mut Environment, field: &str, value: &str) -> Result<(), String> {
    match (&mut env.source, field) {
        (EnvSource::Uniform(c), "L") => *c = numbers::<3>(ENV_RADIANCE, value)?,
        (EnvSource::Sky { turbidity, .. }, "T") => *turbidity = real(TURBIDITY, value)?,
        (EnvSource::Sky { sun, .. }, "sun") => *sun = if value == "follow" { None } else { Some(direction(value)?) },
        (_, "L" | "T" | "sun") => return Err(format!("env.{field} is not a field of this environment's source")),
        _ => return set(ENVIRONMENT, env, field, value),
    }
    Ok(())
}

#[cfg(test)]
#[path = "link_scene_tests.rs"]
mod tests;
