//! `extras.shadelab`: the chapter's exact parameters, which glTF's own fields cannot hold.
//!
//! Each concept declares its object as one serde type beside its reading and writing
//! (`MaterialExtras` in `materials.rs`, `LightExtras` in `lights.rs`, …), so a key is typed
//! once, as a field. This file holds what those types are made of: the field types, each of
//! which checks its value (a number in a parameter's range, three numbers, a name, …) and writes
//! a non-finite number as 0 (JSON has no NaN), and [`read`], which decodes an object field by
//! field in the type's declared order, so that a bad value is one error line naming its key.

use super::GltfError;
use super::scene_file::Cx;
use crate::params::{self, NamedValue, ParamRange, PhongExponent};
use glam::DVec3;
use gltf::json;
use serde::de::{self, DeserializeOwned, DeserializeSeed, Deserializer, IntoDeserializer, MapAccess, Visitor};
use serde::ser::SerializeTuple;
use serde::{Deserialize, Serialize, Serializer};
use serde_json::{Map, Value};
use std::marker::PhantomData;

/// The `shadelab` object of `extras` as `T`; absent (no extras, or extras without `shadelab`):
/// `T::default()`. Extras that are not JSON, a `shadelab` that is not an object or a field
/// whose value its type refuses are one error line: `{what}: extras.shadelab.{key} = {value}
/// is not {what the field takes}`.
pub(super) fn read<T: DeserializeOwned + Default>(cx: &Cx, extras: &json::Extras, what: &str) -> Result<T, GltfError> {
    let Some(raw) = extras else { return Ok(T::default()) };
    let v: Value =
        serde_json::from_str(raw.get()).map_err(|e| cx.invalid(format!("{what}: extras are not JSON: {e}")))?;
    match v.get("shadelab") {
        None => Ok(T::default()),
        Some(Value::Object(o)) => T::deserialize(Fields(o)).map_err(|e| cx.invalid(format!("{what}: {e}"))),
        Some(_) => Err(cx.invalid(format!("{what}: extras.shadelab is not an object"))),
    }
}

/// Whether `extras` hold a `shadelab` object at all (a file shadelab wrote, or one that states the
/// chapter's parameters).
pub(super) fn has_shadelab(extras: &json::Extras) -> bool {
    extras
        .as_ref()
        .and_then(|raw| serde_json::from_str::<Value>(raw.get()).ok())
        .is_some_and(|v| v.get("shadelab").is_some())
}

/// `extras` holding `{ "shadelab": value }`, for a JSON document being written.
pub(super) fn shadelab<T: Serialize>(value: &T) -> Value {
    serde_json::json!({ "shadelab": value })
}

/// A number for JSON: a non-finite one, which validated scenes do not hold, becomes 0.
pub(super) fn finite(x: f64) -> f64 {
    if x.is_finite() { x } else { 0.0 }
}

/// A parameter's range, named by a type, so that a field's type says what it is checked against.
pub(super) trait InRange {
    const RANGE: ParamRange;
}

macro_rules! ranges {
    ($($(#[$doc:meta])* $name:ident = $range:expr;)*) => {$(
        $(#[$doc])*
        pub(super) struct $name;
        impl InRange for $name {
            const RANGE: ParamRange = $range;
        }
    )*};
}

ranges! {
    /// [0, 1]: colours and the shares r_s, r_d, r_a, t.
    Unit = params::UNIT;
    /// Beckmann roughness m.
    Roughness = params::M;
    /// The Phong exponent h.
    Exponent = params::H;
    /// Reflectance at normal incidence μ.
    Mu = params::MU;
    /// Absorption coefficient a.
    Absorption = params::ABSORPTION;
    /// Thickness d.
    Thickness = params::THICKNESS;
    /// Refractive index v given directly.
    Ior = crate::params::IOR;
    /// Light intensity I_L.
    Intensity = params::INTENSITY;
    /// Falloff α.
    Falloff = params::FALLOFF;
    /// Falloff distance d0.
    D0 = params::D0;
    /// A spot cone half-angle, up to glTF's f32 π/2.
    Cone = params::CONE_ANGLE_F32;
    /// A light's range.
    LightRange = params::RANGE;
    /// An area light's width or height.
    LightSize = params::LIGHT_SIZE;
    /// How many point sources an area light is drawn as.
    AreaPoints = params::AREA_POINTS;
    /// PCSS's taps per pass.
    PcssTaps = crate::shadows::PCSS_TAPS;
    /// A light's shadow map side in texels.
    ShadowSide = crate::shadows::SHADOW_RESOLUTION;
    /// A uniform environment's radiance.
    EnvRadiance = crate::lighting::env_map::ENV_RADIANCE;
    /// The sky's turbidity.
    Turbidity = crate::lighting::sky::TURBIDITY;
    /// The environment's intensity.
    EnvIntensity = crate::lighting::env_map::ENV_INTENSITY;
    /// The environment's turn, degrees.
    EnvRotation = crate::lighting::env_map::ENV_ROTATION;
}

/// What a field in `R`'s range takes, for the error line.
fn in_range<R: InRange>(what: &str) -> String {
    let r = R::RANGE;
    format!("{what} in [{}, {}] ({})", r.min, r.max, r.meaning)
}

/// A number in `R`'s range.
pub(super) struct Num<R>(pub f64, PhantomData<R>);

impl<R> From<f64> for Num<R> {
    fn from(x: f64) -> Self {
        Num(x, PhantomData)
    }
}

impl<R> Serialize for Num<R> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_f64(finite(self.0))
    }
}

impl<'de, R: InRange> Deserialize<'de> for Num<R> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        v.as_f64()
            .and_then(|x| R::RANGE.check(x).ok())
            .map(Num::from)
            .ok_or_else(|| de::Error::custom(in_range::<R>("a number")))
    }
}

/// A whole number in `R`'s range (a shadow map's side).
pub(super) struct Count<R>(pub u32, PhantomData<R>);

impl<R> From<u32> for Count<R> {
    fn from(n: u32) -> Self {
        Count(n, PhantomData)
    }
}

impl<R> Serialize for Count<R> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_u32(self.0)
    }
}

impl<'de, R: InRange> Deserialize<'de> for Count<R> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        // A whole number written as 2048 or 2048.0; the range's bounds are below u32::MAX.
        v.as_f64()
            .filter(|x| x.fract() == 0.0)
            .and_then(|x| R::RANGE.check(x).ok())
            .map(|x| Count::from(x as u32))
            .ok_or_else(|| de::Error::custom(in_range::<R>("an integer")))
    }
}

/// `true` or `false` (whether a light casts shadows).
pub(super) struct Flag(pub bool);

impl Serialize for Flag {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_bool(self.0)
    }
}

impl<'de> Deserialize<'de> for Flag {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Value::deserialize(d)?.as_bool().map(Flag).ok_or_else(|| de::Error::custom("true or false"))
    }
}

/// Three numbers in `R`'s range (a colour, μ per channel, a per channel).
pub(super) struct Rgb<R>(pub [f64; 3], PhantomData<R>);

impl<R> From<[f64; 3]> for Rgb<R> {
    fn from(c: [f64; 3]) -> Self {
        Rgb(c, PhantomData)
    }
}

impl<R> Serialize for Rgb<R> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        three(s, self.0)
    }
}

impl<'de, R: InRange> Deserialize<'de> for Rgb<R> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        let checked = |x: &Value| x.as_f64().and_then(|x| R::RANGE.check(x).ok());
        numbers(&v, checked).map(Rgb::from).ok_or_else(|| de::Error::custom(in_range::<R>("3 numbers")))
    }
}

/// Three numbers: a position, a direction, a scale.
pub(super) struct Vec3(pub DVec3);

impl Serialize for Vec3 {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        three(s, self.0.to_array())
    }
}

impl<'de> Deserialize<'de> for Vec3 {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        numbers(&v, Value::as_f64).map(|a| Vec3(DVec3::from_array(a))).ok_or_else(|| de::Error::custom("3 numbers"))
    }
}

/// A number without a range of its own (an angle, a distance checked against the file's fields).
pub(super) struct Number(pub f64);

impl Serialize for Number {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_f64(finite(self.0))
    }
}

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Value::deserialize(d)?.as_f64().map(Number).ok_or_else(|| de::Error::custom("a number"))
    }
}

/// One of a [`NamedValue`]'s names (a shading mode, a specular model, a falloff form).
pub(super) struct Named<T>(pub T);

impl<T: NamedValue + PartialEq> Serialize for Named<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.0.name())
    }
}

impl<'de, T: NamedValue + PartialEq> Deserialize<'de> for Named<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        let allowed = || format!("one of {}", T::ALL.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", "));
        let name = v.as_str().ok_or_else(|| de::Error::custom(allowed()))?;
        T::parse_named(name).map(Named).map_err(|_| de::Error::custom(allowed()))
    }
}

/// The Phong exponent: `"mirror"`, or a number in `H`'s range.
pub(super) struct Phong(pub PhongExponent);

impl Serialize for Phong {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.0 {
            PhongExponent::Mirror => s.serialize_str("mirror"),
            PhongExponent::Finite(h) => s.serialize_f64(finite(h)),
        }
    }
}

impl<'de> Deserialize<'de> for Phong {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        if v.as_str() == Some("mirror") {
            return Ok(Phong(PhongExponent::Mirror));
        }
        Num::<Exponent>::deserialize(&v).map(|h| Phong(PhongExponent::Finite(h.0))).map_err(de::Error::custom)
    }
}

/// A field whose check depends on other fields: the value as a `T`, or as the file wrote it.
pub(super) struct Lenient<T>(pub Result<T, Value>);

impl<T: Serialize> Serialize for Lenient<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match &self.0 {
            Ok(t) => t.serialize(s),
            Err(v) => v.serialize(s),
        }
    }
}

impl<'de, T: DeserializeOwned> Deserialize<'de> for Lenient<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Value::deserialize(d)?;
        Ok(Lenient(T::deserialize(&v).map_err(|_| v.clone())))
    }
}

fn three<S: Serializer>(s: S, v: [f64; 3]) -> Result<S::Ok, S::Error> {
    let mut t = s.serialize_tuple(3)?;
    for x in v {
        t.serialize_element(&finite(x))?;
    }
    t.end()
}

/// Three elements of a JSON array, each read by `each`.
fn numbers(v: &Value, each: impl Fn(&Value) -> Option<f64>) -> Option<[f64; 3]> {
    match v.as_array()?.as_slice() {
        [a, b, c] => Some([each(a)?, each(b)?, each(c)?]),
        _ => None,
    }
}

/// An `extras.shadelab` object as a serde deserializer: a struct's fields are visited in its
/// declared order (the order the checks run in), keys it does not declare are ignored, and a
/// value its field refuses is reported with the key and the value as written.
struct Fields<'v>(&'v Map<String, Value>);

impl<'de> Deserializer<'de> for Fields<'de> {
    type Error = serde_json::Error;

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Self::Error> {
        visitor.visit_map(FieldValues { map: self.0, fields: fields.iter(), current: None })
    }

    fn deserialize_any<V: Visitor<'de>>(self, _visitor: V) -> Result<V::Value, Self::Error> {
        Err(de::Error::custom("extras.shadelab is read into a struct"))
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf option
        unit unit_struct newtype_struct seq tuple tuple_struct map enum identifier ignored_any
    }
}

struct FieldValues<'v> {
    map: &'v Map<String, Value>,
    fields: std::slice::Iter<'static, &'static str>,
    current: Option<(&'static str, &'v Value)>,
}

impl<'de> MapAccess<'de> for FieldValues<'de> {
    type Error = serde_json::Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(&mut self, seed: K) -> Result<Option<K::Value>, Self::Error> {
        for &key in self.fields.by_ref() {
            if let Some(v) = self.map.get(key) {
                self.current = Some((key, v));
                return seed.deserialize(key.into_deserializer()).map(Some);
            }
        }
        Ok(None)
    }

    fn next_value_seed<S: DeserializeSeed<'de>>(&mut self, seed: S) -> Result<S::Value, Self::Error> {
        let Some((key, v)) = self.current.take() else { return Err(de::Error::custom("a value without its key")) };
        seed.deserialize(Present(v))
            .map_err(|allowed| de::Error::custom(format!("extras.shadelab.{key} = {v} is not {allowed}")))
    }
}

/// A value that is there: an `Option` field of it is `Some` even for `null`, so that the field's
/// type, not serde, decides whether `null` is allowed (it never is).
struct Present<'v>(&'v Value);

impl<'de> Deserializer<'de> for Present<'de> {
    type Error = serde_json::Error;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Self::Error> {
        self.0.deserialize_any(visitor)
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Self::Error> {
        visitor.visit_some(self.0)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
        unit unit_struct newtype_struct seq tuple tuple_struct map struct enum identifier ignored_any
    }
}

/// Whether a value shadelab wrote exactly in extras still agrees with what the file's f32
/// fields say (1e-5 relative: f32 rounding and a few products, not an edit).
pub(super) fn agrees(exact: DVec3, from_node: DVec3) -> bool {
    let scale = 1.0 + exact.abs().max_element().max(from_node.abs().max_element());
    (exact - from_node).abs().max_element() <= AGREES_RELATIVE * scale && exact.is_finite()
}

/// How far (relative) an exact value may lie from the file's f32 fields and still be used.
const AGREES_RELATIVE: f64 = 1e-5;
