//! Flag values: clap value parsers built from the model's declared ranges and named values, so
//! clap checks every flag as it parses, `--help` lists the allowed values, and a mistake is one
//! line naming the flag and what it allows (exit code 2).

use clap::builder::{PossibleValue, TypedValueParser};
use clap::error::ErrorKind;
use shadelab_model::params::{self, NamedValue, ParamError, ParamRange, PhongExponent};
use std::ffi::OsStr;
use std::sync::Arc;

shadelab_model::param_ranges! {
    /// Warm-up frames of a benchmark (at least one is always drawn, to build the pipelines).
    pub const WARMUP = "--warmup", "N", "number of warm-up frames", [0.0, 1e6];

    /// Frames for benchmarks and the viewer's --exit-after-frames.
    pub const FRAMES = "--frames", "N", "number of frames", [1.0, 1e6];

    /// `bench render --point-lights`: how many point lights replace the scene's, each in
    /// [1, MAX_LIGHTS], the uniform's slots.
    pub const POINT_LIGHTS = "--point-lights", "N", "number of point lights (MAX_LIGHTS)",
        [1.0, shadelab_model::lighting::lights::MAX_LIGHTS as f64];

    /// Triangle counts of `bench mesh --triangles`: each in [1, MAX_TRIANGLES], what the loader takes.
    pub const MESH_TRIANGLES = "--triangles", "N", "triangle count (MAX_TRIANGLES)",
        [1.0, shadelab_model::gltf_io::MAX_TRIANGLES as f64];
}

/// One of the model's rules reading a flag's text.
type Rule<T> = Arc<dyn Fn(&str) -> Result<T, ParamError> + Send + Sync>;

/// A flag's value read by one of the model's rules. `possible` lists a named value's choices
/// for `--help`; it is empty for numbers.
#[derive(Clone)]
pub struct ModelValue<T> {
    parse: Rule<T>,
    possible: Vec<&'static str>,
}

impl<T: Clone + Send + Sync + 'static> TypedValueParser for ModelValue<T> {
    type Value = T;

    fn parse_ref(&self, _cmd: &clap::Command, arg: Option<&clap::Arg>, value: &OsStr) -> Result<T, clap::Error> {
        (self.parse)(&value.to_string_lossy()).map_err(|e| {
            // The flag as typed: one range can serve several flags (--frames, --exit-after-frames).
            let e = match arg.and_then(clap::Arg::get_long) {
                Some(long) => with_flag(e, format!("--{long}")),
                None => e,
            };
            clap::Error::raw(ErrorKind::ValueValidation, e)
        })
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        (!self.possible.is_empty()).then(|| Box::new(self.possible.iter().map(|n| PossibleValue::new(*n))) as Box<_>)
    }
}

fn rule<T>(parse: impl Fn(&str) -> Result<T, ParamError> + Send + Sync + 'static) -> ModelValue<T> {
    ModelValue { parse: Arc::new(parse), possible: Vec::new() }
}

/// A real number in `range`.
pub fn real(range: ParamRange) -> ModelValue<f64> {
    rule(move |t| range.parse(t))
}

/// A whole number in `range`.
pub fn count(range: ParamRange) -> ModelValue<u32> {
    rule(move |t| range.parse_u32(t))
}

/// The Phong exponent: a number in `params::H` or `mirror`.
pub fn phong_exponent() -> ModelValue<PhongExponent> {
    rule(params::parse_h)
}

/// The normal-incidence reflectance μ: `R,G,B` or one value for all three.
pub fn reflectance() -> ModelValue<[f64; 3]> {
    rule(params::parse_mu)
}

/// A per-channel value `R,G,B` (or one for all three), each in `range`.
pub fn rgb(range: ParamRange) -> ModelValue<[f64; 3]> {
    rule(move |t| range.parse_rgb(t))
}

/// One of a named parameter's values (shading mode, specular model, light kind, falloff form).
pub fn named<T: NamedValue + PartialEq + Send + Sync>() -> ModelValue<T> {
    ModelValue { parse: Arc::new(T::parse_named), possible: T::ALL.iter().map(|(n, _)| *n).collect() }
}

/// A pixel `X,Y`: two whole numbers, each within the image size's range (the image's own size
/// is checked where it is known).
pub fn pixel() -> ModelValue<(u32, u32)> {
    rule(|t: &str| {
        let bad =
            || ParamError::Unknown { flag: String::new(), value: t.into(), allowed: "X,Y (two whole numbers)".into() };
        let (x, y) = t.split_once(',').ok_or_else(bad)?;
        let (x, y) = (x.trim().parse::<u32>().map_err(|_| bad())?, y.trim().parse::<u32>().map_err(|_| bad())?);
        Ok((x, y))
    })
}

/// A switch: `on` (true) or `off` (false), both listed in `--help`.
pub fn on_off() -> ModelValue<bool> {
    let parse = |t: &str| match t.trim().to_ascii_lowercase().as_str() {
        "on" => Ok(true),
        "off" => Ok(false),
        _ => Err(ParamError::Unknown { flag: String::new(), value: t.into(), allowed: "on, off".into() }),
    };
    ModelValue { parse: Arc::new(parse), possible: vec!["on", "off"] }
}

/// A numeric flag's help: what it sets, and its range as the model declares it.
pub fn within(what: &str, range: ParamRange) -> String {
    format!("{what}, in [{}, {}]", range.min, range.max)
}

/// The error, naming `flag`.
fn with_flag(e: ParamError, flag: String) -> ParamError {
    match e {
        ParamError::OutOfRange { value, meaning, min, max, .. } => {
            ParamError::OutOfRange { flag, value, meaning, min, max }
        }
        ParamError::NotANumber { value, allowed, .. } => ParamError::NotANumber { flag, value, allowed },
        ParamError::Unknown { value, allowed, .. } => ParamError::Unknown { flag, value, allowed },
    }
}

/// clap's error as one line: its first line names the flag and what is wrong (a value this
/// module rejects is that line alone; clap's own mistakes add usage and tips below it).
pub fn one_line(e: &clap::Error) -> String {
    let text = e.render().to_string();
    text.lines().next().unwrap_or("error: bad arguments").to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadelab_model::ShadingMode;

    fn parse<T: Clone + Send + Sync + 'static>(p: &ModelValue<T>, flag: &'static str, text: &str) -> Result<T, String> {
        let cmd = clap::Command::new("t");
        let arg = clap::Arg::new("x").long(flag);
        p.parse_ref(&cmd, Some(&arg), OsStr::new(text)).map_err(|e| one_line(&e))
    }

    #[test]
    fn a_rejected_value_is_one_line_naming_the_flag_as_typed() {
        let e = parse(&count(FRAMES), "exit-after-frames", "0").unwrap_err();
        assert!(e.starts_with("error: --exit-after-frames: 0 is out of range") && e.contains("[1, 1000000]"), "{e}");
        let e = parse(&named::<ShadingMode>(), "shading", "toon").unwrap_err();
        assert!(e.contains("--shading: unknown value 'toon' (allowed: flat, gouraud, phong)"), "{e}");
        assert_eq!(parse(&real(params::M), "m", "0.25"), Ok(0.25));
        let e = parse(&on_off(), "shadows", "yes").unwrap_err();
        assert!(e.contains("--shadows: unknown value 'yes' (allowed: on, off)"), "{e}");
        assert_eq!((parse(&on_off(), "shadows", "on"), parse(&on_off(), "shadows", "OFF")), (Ok(true), Ok(false)));
    }

    #[test]
    fn named_values_are_offered_to_help() {
        let p = named::<ShadingMode>();
        let shown: Vec<String> = p.possible_values().unwrap().map(|v| v.get_name().to_string()).collect();
        assert_eq!(shown, ["flat", "gouraud", "phong"]);
        assert!(real(params::M).possible_values().is_none());
    }
}
