//! The twin of `shaders/common.wgsl`: helpers every term uses. The guards of that file are
//! [`crate::guards`]; the codes it shares with Rust are the `code()` of [`crate::LightKind`],
//! [`crate::FalloffForm`] and [`crate::SpecularModel`].

use crate::guards::NORMALIZE_MIN_LEN2;
use glam::DVec3;

/// Normalize `v`, or return `fallback` when `v` is (nearly) zero (guard `NORMALIZE_MIN_LEN2`).
pub fn safe_normalize(v: DVec3, fallback: DVec3) -> DVec3 {
    let len2 = v.length_squared();
    if len2 > NORMALIZE_MIN_LEN2 && len2.is_finite() { v / len2.sqrt() } else { fallback }
}
