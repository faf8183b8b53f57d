//! Named numerical guards of the lighting model.
//!
//! Every constant here has a twin of the same name in `shaders/common.wgsl`; the test
//! `wgsl_guards_equal_rust_guards` (in `shadelab-render`, `twins.rs`) parses the WGSL with naga
//! and holds the two equal. The guards clamp *inputs* (cosines, roughness, refractive index, distances): WGSL
//! lets an implementation assume there is no NaN or infinity, so filtering bad values afterwards
//! does not work.

/// Squared length under which a vector counts as zero and is replaced by a fallback instead of
/// being normalized. For a vector of this length the inverse length is 1e10, far below f32's
/// maximum (3.4e38), and its squared components stay above f32's smallest normal (1.2e-38).
pub const NORMALIZE_MIN_LEN2: f64 = 1e-20;

/// Smallest cos of the viewer angle used in the Cook–Torrance denominator `N·V`. It bounds the
/// factor `1/(N·V)` by 1e4 (the view is grazing beyond 89.994°) so that a silhouette pixel stays
/// finite in f32; above it the exact value is used.
pub const N_DOT_V_MIN: f64 = 1e-4;

/// Smallest `N·H` fed to the Beckmann distribution (for `N·H > 0`). At it, `(N·H)⁴ = 1e-16` and
/// the exponent `(1 − 1/(N·H)²)/m²` is at most about −1e14: `exp` underflows to exactly 0 before
/// the prefactor (at most 2.5e21) can overflow f32.
pub const N_DOT_H_MIN: f64 = 1e-4;

/// Smallest Beckmann roughness `m` the model evaluates; `m = 0` (a perfect mirror, a Dirac lobe)
/// is clamped to it. It caps the distribution's peak `1/(4m²)` at 2.5e5, and the lobe's
/// half-width (about 0.06°) is already below one pixel of a 1280-wide, 45° view.
pub const M_MIN: f64 = 1e-3;

/// Largest finite Phong exponent `h`. `(V·R)^h` is evaluated as `exp2(h·log2(V·R))`, which for
/// `V·R` in (0, 1] and `h ≤ 1e9` is at least `exp2(-1.5e11)` = 0: finite, no overflow.
pub const H_MAX: f64 = 1e9;

/// Smallest argument of `log2` in the Phong term `exp2(h·log2(V·R))`. At `V·R = 0` the term is 0
/// by a test, but both sides of that test are evaluated, and `log2(0) = −∞` times `h` is an
/// infinity WGSL may assume away. At this floor `log2` is about −126 and `h·log2 ≥ −1.3e11`: finite,
/// and `exp2` of it is 0. (In f32, 1e-38 lies just under the smallest normal number, 1.18e-38.)
pub const PHONG_LOG2_ARG_MIN: f64 = 1e-38;

/// The "mirror" Phong setting (`h = ∞`): light is reflected only where `V·R` is at least this,
/// i.e. within 0.08° of the mirror direction. A true Dirac lobe would never cover a pixel centre;
/// 1 − 1e-6 is 16 f32 ulps below 1, so the test is still meaningful in f32.
pub const MIRROR_V_DOT_R_MIN: f64 = 1.0 - 1e-6;

/// Smallest `V·H` the geometric attenuation divides by. The quotient `num/(V·H)` is used only
/// where `num < V·H`, so `V·H > 0` there; but both sides of that test are evaluated, and
/// `V·H = num = 0` would be 0/0. Any floor below every `V·H` a lit point has works: 1e-30 is a
/// normal f32, and its reciprocal is finite.
pub const G_V_DOT_H_MIN: f64 = 1e-30;

/// Largest `√μ` used to derive the refractive index `v = (1 + √μ)/(1 − √μ)`. `μ = 1` would make
/// `v` infinite; at this cap `v ≈ 2e4` and `F(c = 1) = 0.9998`, within 2e-4 of the perfect
/// reflector it stands for.
pub const FRESNEL_SQRT_MU_MAX: f64 = 0.9999;

/// Smallest `g + c` in the exact Fresnel term. Only `v = 1` (μ = 0, no interface) with `c = 0`
/// reaches 0/0 there; with this floor F is 0, the value it has for every other `c` at `v = 1`.
pub const FRESNEL_G_PLUS_C_MIN: f64 = 1e-6;

/// Floor of the height-correlated Smith G's denominator `G1v + G1l − G1v·G1l`. Its numerator
/// `G1v·G1l` never exceeds it, so the floor changes nothing but 0/0 (both directions grazing),
/// which it makes 0; 1e-30 is a normal f32.
pub const SMITH_DENOM_MIN: f64 = 1e-30;

/// Smallest `N·X` Blinn–Phong's Smith Λ evaluates (a smaller positive cosine is clamped to it):
/// its `1/c` and `1/√(c²·u^(2/n))` stay at most 1e12, far inside f32, and `c²` a normal f32;
/// G1 there is at most 4e-9 (about `c·√(2π(h + 1))` at the largest h), so the clamp moves no pixel.
pub const BLINN_PHONG_COS_MIN: f64 = 1e-12;

/// Smallest lobe albedo E the multiple-scattering compensation `1 + F0·(1 − E)/E` divides by.
/// The table's albedos are all above 0.3 (GGX with Smith at m = 1, normal view); the floor only
/// keeps a value the table does not hold from dividing by 0, and bounds the factor by 20.
pub const MS_ALBEDO_MIN: f64 = 0.05;

/// Distance under which a point light counts as touching the surface: the direction to it is
/// undefined, so `L = N` (the light is straight above the surface point) is used instead.
pub const LIGHT_DIST_MIN: f64 = 1e-4;

/// Smallest `d0` of the chapter's `1/(d + d0)` falloff: it bounds the falloff factor by 1e3 when
/// a light touches a surface (d = 0). Parameter validation keeps `d0` at or above it.
pub const D0_MIN: f64 = 1e-3;

/// Smallest span `cos(inner) − cos(outer)` of a spot light's ramp (KHR_lights_punctual's own
/// recommended floor). Equal cones would divide by zero; with this floor the edge is a ramp at
/// most 1e-3 wide in cos, about 0.08° at a 45° cone (the hard edge it stands for, at a pixel's
/// scale), and the ramp's slope is at most 1e3.
pub const SPOT_COS_SPAN_MIN: f64 = 1e-3;

/// A texture coordinate that is not finite samples here (u or v alone): a NaN must not reach a
/// texel index, and 0 is a coordinate every wrap mode maps inside the image.
pub const NONFINITE_UV: f64 = 0.0;

/// Squared length under which the cross product of the unit directions to two neighbouring
/// corners of an area light counts as zero: the edge is seen end-on (or the corners coincide),
/// and its term in Lambert's edge formula is zero. 1e-24 is (1e-12)², below any edge f32 or f64
/// resolves between unit vectors and far above either's smallest normal number.
pub const EDGE_CROSS_MIN_LEN2: f64 = 1e-24;

/// Angular radius (radians) under which an area light is lit as its centre's point light
/// (a Lambertian point for a rectangle or disk). Lambert's edge formula sums terms of size σ to a
/// total of size σ², so f32 loses about ε/σ² of it (1.5e-4 at 0.02), while the point's own
/// error grows as σ² (4e-4 at 0.02): at 0.02 both stay under the zero-size test's 1e-3.
pub const AREA_POINT_LIMIT_ANGLE: f64 = 0.02;

/// How close to a sphere light's surface, relative to its radius, the LTC specular takes the
/// light as filling the point's hemisphere: the disk that covers the sphere's cone, of radius
/// `r·d/√(d² − r²)`, is 22 r wide at 1e-3 above the surface, and its f32 corners would lose the
/// cone's edge beyond that.
pub const SPHERE_DISK_MARGIN: f64 = 1e-3;

/// Smallest blocker distance (m) in the penumbra width w_light·(d_r − d_b)/d_b: a blocker at the
/// light would make it infinite; a tenth of a millimetre caps it.
pub const BLOCKER_DIST_MIN: f64 = 1e-4;

/// Smallest quadratic coefficient `a = |d|²` (a ray's squared length across a sphere or a
/// cylinder's side) the glass exit divides by: only a zero direction gets below it, and
/// `shape_exit` turns that away first; 1e-30 stays a normal f32.
pub const QUADRIC_A_MIN: f64 = 1e-30;

/// All guards by name, in the order they are declared (used by the WGSL ↔ Rust equality test and
/// by the table of guards in docs/model.md §9).
pub const ALL: &[(&str, f64)] = &[
    ("NORMALIZE_MIN_LEN2", NORMALIZE_MIN_LEN2),
    ("N_DOT_V_MIN", N_DOT_V_MIN),
    ("N_DOT_H_MIN", N_DOT_H_MIN),
    ("M_MIN", M_MIN),
    ("H_MAX", H_MAX),
    ("PHONG_LOG2_ARG_MIN", PHONG_LOG2_ARG_MIN),
    ("MIRROR_V_DOT_R_MIN", MIRROR_V_DOT_R_MIN),
    ("G_V_DOT_H_MIN", G_V_DOT_H_MIN),
    ("FRESNEL_SQRT_MU_MAX", FRESNEL_SQRT_MU_MAX),
    ("FRESNEL_G_PLUS_C_MIN", FRESNEL_G_PLUS_C_MIN),
    ("SMITH_DENOM_MIN", SMITH_DENOM_MIN),
    ("BLINN_PHONG_COS_MIN", BLINN_PHONG_COS_MIN),
    ("MS_ALBEDO_MIN", MS_ALBEDO_MIN),
    ("LIGHT_DIST_MIN", LIGHT_DIST_MIN),
    ("D0_MIN", D0_MIN),
    ("SPOT_COS_SPAN_MIN", SPOT_COS_SPAN_MIN),
    ("NONFINITE_UV", NONFINITE_UV),
    ("EDGE_CROSS_MIN_LEN2", EDGE_CROSS_MIN_LEN2),
    ("AREA_POINT_LIMIT_ANGLE", AREA_POINT_LIMIT_ANGLE),
    ("SPHERE_DISK_MARGIN", SPHERE_DISK_MARGIN),
    ("BLOCKER_DIST_MIN", BLOCKER_DIST_MIN),
    ("QUADRIC_A_MIN", QUADRIC_A_MIN),
];
