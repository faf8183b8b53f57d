//! Parameter kinds, their allowed ranges and validation.
//!
//! Every range a user can set is declared once: the CLI validates with it, the viewer builds its
//! sliders from it, and error messages quote it. A user's mistake gets one line naming the flag,
//! the allowed range and the value given. The ranges and kinds of lights and the specular models
//! are declared with their f64 terms (`lighting/lights.rs`, `lighting/brdf.rs`) and re-exported
//! here.

use std::fmt;
use std::str::FromStr;

pub use crate::lighting::brdf::SpecularModel;
pub use crate::lighting::lights::{
    AREA_POINTS, AreaSpecular, CONE_ANGLE, CONE_ANGLE_F32, D0, FALLOFF, FalloffForm, INTENSITY, LIGHT_SIZE, LightKind,
    RANGE,
};
pub use crate::lighting::models::{IlluminationModel, ModelChoice};

/// How lighting is distributed over a face (docs/model.md §8).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ShadingMode {
    /// One normal and one colour per face, lit at the face's centroid.
    Flat,
    /// Lighting at the vertices, colour interpolated.
    Gouraud,
    /// Normals interpolated and renormalized, lighting per pixel.
    Phong,
}

/// How Gouraud's colours and Phong shading's normals are interpolated across a triangle
/// (docs/model.md §8).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Interpolation {
    /// Perspective-correct, as GPUs interpolate by default: linear on the surface in 3D.
    #[default]
    Perspective,
    /// The chapter's scanline form: linear in screen space (WGSL `@interpolate(linear)`), which
    /// bends on large triangles seen at a grazing depth.
    Screen,
}

crate::named_values!(Interpolation, "--interpolation", "perspective" => Perspective, "screen" => Screen);

/// The Phong exponent `h`: a finite sharpness in `[1, H_MAX]`, or the perfect mirror (`h = ∞`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PhongExponent {
    Finite(f64),
    Mirror,
}

impl PhongExponent {
    /// The exponent as the shader sees it: the finite value, or `H_MAX` for the mirror (which
    /// the shader handles by its mirror flag, not by the exponent).
    pub fn value(self) -> f64 {
        match self {
            PhongExponent::Finite(h) => h,
            PhongExponent::Mirror => crate::guards::H_MAX,
        }
    }
    pub fn is_mirror(self) -> bool {
        matches!(self, PhongExponent::Mirror)
    }

    /// The one rule tying the Phong exponent to Beckmann roughness, h = 2/m² − 2 (the exponent
    /// whose lobe has the width of roughness m; docs/model.md §5): m ≤ 0 is the mirror, and h is
    /// kept in [1, H_MAX], the range the shader accepts.
    pub fn from_m(m: f64) -> PhongExponent {
        if m <= 0.0 {
            return PhongExponent::Mirror;
        }
        PhongExponent::Finite((2.0 / (m * m) - 2.0).clamp(1.0, crate::guards::H_MAX))
    }

    /// The same exponent rounded to a whole number (the built-in scenes show whole exponents in
    /// the panel); the mirror stays the mirror.
    pub fn rounded(self) -> PhongExponent {
        match self {
            PhongExponent::Finite(h) => PhongExponent::Finite(h.round()),
            PhongExponent::Mirror => PhongExponent::Mirror,
        }
    }
}

impl fmt::Display for PhongExponent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PhongExponent::Finite(h) => write!(f, "{h}"),
            PhongExponent::Mirror => write!(f, "mirror"),
        }
    }
}

/// A user's mistake in a parameter: one line, naming what, the allowed values and what was given.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParamError {
    #[error("{flag}: {value} is out of range: {meaning} must be in [{min}, {max}]")]
    OutOfRange { flag: String, value: String, meaning: &'static str, min: f64, max: f64 },
    #[error("{flag}: '{value}' is not a number (allowed: {allowed})")]
    NotANumber { flag: String, value: String, allowed: String },
    #[error("{flag}: unknown value '{value}' (allowed: {allowed})")]
    Unknown { flag: String, value: String, allowed: String },
}

/// A numeric parameter's allowed range, its symbol and meaning (used for validation, sliders
/// and tooltips).
#[derive(Clone, Copy, Debug)]
pub struct ParamRange {
    pub flag: &'static str,
    pub symbol: &'static str,
    pub meaning: &'static str,
    pub min: f64,
    pub max: f64,
}

impl ParamRange {
    /// Check a value (NaN and infinities are out of range).
    pub fn check(&self, value: f64) -> Result<f64, ParamError> {
        if value.is_finite() && value >= self.min && value <= self.max {
            Ok(value)
        } else {
            Err(self.out_of_range(value.to_string()))
        }
    }

    /// Parse and check a number given as text.
    pub fn parse(&self, text: &str) -> Result<f64, ParamError> {
        let v: f64 = text.trim().parse().map_err(|_| ParamError::NotANumber {
            flag: self.flag.to_string(),
            value: text.to_string(),
            allowed: format!("a number in [{}, {}]", self.min, self.max),
        })?;
        self.check(v)
    }

    /// Parse and check an integer.
    pub fn parse_u32(&self, text: &str) -> Result<u32, ParamError> {
        let v: i64 = text.trim().parse().map_err(|_| ParamError::NotANumber {
            flag: self.flag.to_string(),
            value: text.to_string(),
            allowed: format!("an integer in [{}, {}]", self.min, self.max),
        })?;
        if (v as f64) < self.min || (v as f64) > self.max {
            return Err(self.out_of_range(v.to_string()));
        }
        Ok(v as u32)
    }

    fn out_of_range(&self, value: String) -> ParamError {
        ParamError::OutOfRange {
            flag: self.flag.to_string(),
            value,
            meaning: self.meaning,
            min: self.min,
            max: self.max,
        }
    }
}

crate::param_ranges! {
    /// Beckmann roughness `m` (docs/model.md §5). 0 is allowed (clamped to `M_MIN` inside the model); above 1
    /// the lobe is so wide the highlight has gone, and the white-furnace check covers [0.05, 1].
    pub const M = "--m", "m", "roughness m (Beckmann facet slope)", [0.0, 1.0];
    /// The transmission share `1 − t` of the four-term sum's `I_t` (docs/model.md §2): glTF's
    /// transmission factor, 0 opaque.
    pub const TRANSMISSION = "--transmission", "1 − t", "transmission share 1 − t (0 opaque)", [0.0, 1.0];
    /// A transparent material's refractive index `v` per channel, given directly (docs/transparency.md);
    /// without it `v` follows μ. 1 is no interface; diamond is 2.42, and 3 covers every clear solid.
    pub const IOR = "--ior", "v", "refractive index v (per channel)", [1.0, 3.0];
    /// Absorption coefficient `a` per channel, per metre (docs/transparency.md), from the flag, the
    /// panel or a file: 5/m leaves under 1 % of the light after a metre (a·d = 5); a metal's 1e6/m
    /// the same after 5 µm, and `e^(−a·d)` is 0 in f64 long before that.
    pub const ABSORPTION = "--absorption-coef", "a", "absorption coefficient a per metre (per channel)", [0.0, 1e6];
    /// A material's thickness `d` in metres, read from a file (`KHR_materials_volume`, extras).
    pub const THICKNESS = "d", "d", "thickness d in metres", [0.0, 1e6];
    /// Phong exponent `h` (docs/model.md §3); "mirror" is accepted besides the numbers.
    pub const H = "--h", "h", "Phong exponent h (sharpness; 'mirror' for h = ∞)", [1.0, crate::guards::H_MAX];
    /// Reflectance at normal incidence `μ`, per colour channel (docs/model.md §5).
    pub const MU = "--mu", "μ", "normal-incidence reflectance μ (per channel)", [0.0, 1.0];
    /// Image width in pixels.
    pub const WIDTH = "--width", "w", "image width in pixels", [1.0, 8192.0];
    /// Image height in pixels.
    pub const HEIGHT = "--height", "h", "image height in pixels", [1.0, 8192.0];
    /// A shape's tessellation (segments around, or subdivisions per edge).
    pub const TESSELLATION = "--tessellation", "n", "tessellation (segments or subdivisions)", [1.0, 4096.0];
    /// Colour channels, shares r_s, r_d, r_a and intensities in [0, 1].
    pub const UNIT = "value", "", "a share or colour", [0.0, 1.0];
}
/// Parse the Phong exponent: a number in `H`'s range, or `mirror`.
pub fn parse_h(text: &str) -> Result<PhongExponent, ParamError> {
    if text.trim().eq_ignore_ascii_case("mirror") {
        return Ok(PhongExponent::Mirror);
    }
    H.parse(text).map(PhongExponent::Finite).map_err(|e| match e {
        ParamError::NotANumber { flag, value, .. } => ParamError::NotANumber {
            flag,
            value,
            allowed: format!("a number in [1, {}] or 'mirror'", crate::guards::H_MAX),
        },
        e => e,
    })
}

/// Parse `μ` as `R,G,B` or one value for all three channels.
pub fn parse_mu(text: &str) -> Result<[f64; 3], ParamError> {
    MU.parse_rgb(text)
}

impl ParamRange {
    /// A per-channel value: `R,G,B` or one value for all three, each in the range.
    pub fn parse_rgb(&self, text: &str) -> Result<[f64; 3], ParamError> {
        let parts: Vec<&str> = text.split(',').collect();
        match parts.as_slice() {
            [one] => Ok([self.parse(one)?; 3]),
            [r, g, b] => Ok([self.parse(r)?, self.parse(g)?, self.parse(b)?]),
            _ => Err(ParamError::NotANumber {
                flag: self.flag.into(),
                value: text.into(),
                allowed: format!("R,G,B or one value, each in [{}, {}]", self.min, self.max),
            }),
        }
    }
}

/// Enum parameters given by name on the command line.
pub trait NamedValue: Sized + Copy + 'static {
    /// The flag this value is given with.
    const FLAG: &'static str;
    /// Every value with its name.
    const ALL: &'static [(&'static str, Self)];

    fn name(self) -> &'static str
    where
        Self: PartialEq,
    {
        Self::ALL.iter().find(|(_, v)| *v == self).map(|(n, _)| *n).unwrap_or("?")
    }

    fn parse_named(text: &str) -> Result<Self, ParamError> {
        let t = text.trim().to_ascii_lowercase();
        Self::ALL.iter().find(|(n, _)| *n == t).map(|(_, v)| *v).ok_or_else(|| ParamError::Unknown {
            flag: Self::FLAG.into(),
            value: text.into(),
            allowed: Self::ALL.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", "),
        })
    }
}

crate::named_values!(ShadingMode, "--shading", "flat" => Flat, "gouraud" => Gouraud, "phong" => Phong);
/// Declares [`ParamRange`] constants, one a line: `pub const NAME = flag, symbol, meaning,
/// [min, max];`, each with its doc comment, so a range reads as the table row it is.
#[macro_export]
macro_rules! param_ranges {
    ($($(#[$doc:meta])* $vis:vis const $name:ident = $flag:literal, $symbol:literal, $meaning:literal,
        [$min:expr, $max:expr];)+) => {$(
        $(#[$doc])*
        $vis const $name: $crate::params::ParamRange =
            $crate::params::ParamRange { flag: $flag, symbol: $symbol, meaning: $meaning, min: $min, max: $max };
    )+};
}

/// Implements [`NamedValue`] for an enum from its flag and its `"name" => Variant` table, one
/// line a few values, so each table is written once in the crate's own words.
#[macro_export]
macro_rules! named_values {
    ($t:ident, $flag:literal, $($name:literal => $v:ident),+ $(,)?) => {
        impl $crate::params::NamedValue for $t {
            const FLAG: &'static str = $flag;
            const ALL: &'static [(&'static str, Self)] = &[$(($name, $t::$v)),+];
        }
    };
}

macro_rules! from_str_named {
    ($($t:ty),*) => {$(
        impl FromStr for $t {
            type Err = ParamError;
            fn from_str(s: &str) -> Result<Self, ParamError> { Self::parse_named(s) }
        }
        impl fmt::Display for $t {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result { f.write_str(self.name()) }
        }
    )*};
}
from_str_named!(
    ShadingMode,
    SpecularModel,
    IlluminationModel,
    ModelChoice,
    Interpolation,
    LightKind,
    FalloffForm,
    AreaSpecular
);

impl ShadingMode {
    pub const ALL_MODES: [ShadingMode; 3] = [ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong];
}
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_reject_out_of_range_and_non_finite() {
        assert!(M.check(-0.1).is_err());
        assert!(M.check(f64::NAN).is_err());
        assert!(M.check(0.0).is_ok());
        assert!(MU.parse("1.5").is_err());
        assert!(WIDTH.parse_u32("0").is_err());
        assert!(WIDTH.parse_u32("8193").is_err());
        assert_eq!(WIDTH.parse_u32("8192"), Ok(8192));
        assert!(parse_h("0.5").is_err());
        assert_eq!(parse_h("mirror"), Ok(PhongExponent::Mirror));
        assert_eq!(parse_mu("0.5"), Ok([0.5; 3]));
        assert_eq!(parse_mu("1,0.5,0"), Ok([1.0, 0.5, 0.0]));
        assert!(parse_mu("1,0.5").is_err());
    }

    #[test]
    fn errors_are_one_line_naming_flag_and_range() {
        let e = M.check(-1.0).unwrap_err().to_string();
        assert!(!e.contains('\n'));
        assert!(e.contains("--m") && e.contains("[0, 1]"), "{e}");
        let e = ShadingMode::parse_named("toon").unwrap_err().to_string();
        assert!(e.contains("--shading") && e.contains("flat, gouraud, phong"), "{e}");
    }

    #[test]
    fn named_values_round_trip() {
        for (n, v) in SpecularModel::ALL {
            assert_eq!(SpecularModel::parse_named(n), Ok(*v));
            assert_eq!(v.name(), *n);
        }
    }
}

crate::param_ranges! {
    /// Surface vertices a path-traced reference path has (docs/reference.md): 1 is the direct light
    /// alone; 64 carries a furnace of albedo 0.5 to within 1e-19 of its limit.
    pub const BOUNCES = "--bounces", "N", "surface vertices a path has (1: the direct light alone)", [1.0, 64.0];
    /// Paths per pixel of the path-traced reference: 65 536 brings a pixel's noise 256 times under
    /// one path's.
    pub const SPP = "--spp", "spp", "paths per pixel", [1.0, 65536.0];
}
