//! The sweep kernel's output columns, declared once: their names, widths and bounds. The kernel's
//! `COL_…` and `SWEEP_OUTPUTS` constants are generated from this list ([`wgsl_columns`]) and put
//! before `shaders/sweep.wgsl`, and the f64 reference of a combination ([`reference`]) writes the
//! same columns by name, so the GPU and the f64 side cannot disagree on positions.

use super::inputs::ShadowCase;
use glam::DVec3;
use shadelab_model::guards::{D0_MIN, H_MAX, M_MIN, MS_ALBEDO_MIN, N_DOT_V_MIN};
use shadelab_model::lighting::area::{self, AreaLight, AreaShape};
use shadelab_model::lighting::area_points::{area_emitter, area_point_sample};
use shadelab_model::lighting::microfacet::{self, Microfacet};
use shadelab_model::lighting::{brdf, common, lights, models, transmission};
use shadelab_model::shadows;
use shadelab_model::{FalloffForm, Light, LightKind, Material, PhongExponent, SpecularModel};

/// One term the kernel writes per combination: `channels` consecutive floats.
#[derive(Clone, Copy, Debug)]
pub struct Column {
    /// The term's name in the report.
    pub name: &'static str,
    /// The WGSL constant `COL_<wgsl>` holding the column's first index.
    pub wgsl: &'static str,
    /// 1, or 3 for a colour.
    pub channels: usize,
    /// The largest value the guards allow.
    pub bound: f64,
    pub why_bound: &'static str,
    /// The term may be negative (a map coordinate outside the map): not counted as an error.
    pub signed: bool,
}

/// The D terms of the table: the D and Smith G columns have one channel each, by code.
const D_COUNT: usize = <microfacet::Distribution as shadelab_model::params::NamedValue>::ALL.len();

/// The peak of the chapter's Beckmann D, `1/(4 m²)` at `m = M_MIN`.
const D_MAX: f64 = 1.0 / (4.0 * M_MIN * M_MIN);

/// Every column in the order the kernel writes them (and the report lists them).
pub const COLUMNS: [Column; 54] = [
    col("diffuse_lambert", "DIFFUSE_LAMBERT", 1, 1.0, "N·L of unit vectors"),
    col("specular_phong", "SPECULAR_PHONG", 1, 1.0, "(V·R)^h with V·R clamped to [0, 1]"),
    col(
        "phong_normalization × specular_phong",
        "PHONG_NORMALIZED",
        1,
        (H_MAX + 1.0) / 2.0,
        "(h + 1)/2 · (V·R)^h ≤ (H_MAX + 1)/2",
    ),
    col("d_beckmann", "D_BECKMANN", 1, D_MAX, "peak 1/(4 m²) at m = M_MIN"),
    col("g_cook_torrance", "G_COOK_TORRANCE", 1, 1.0, "min{1, …}"),
    col("microfacet_f (fresnel_dielectric at V·H)", "MICROFACET_F", 3, 1.0, "a reflectance"),
    col(
        "specular_cook_torrance",
        "SPECULAR_COOK_TORRANCE",
        3,
        D_MAX / N_DOT_V_MIN,
        "F·D·G/(N·V) ≤ 1 · 1/(4 M_MIN²) · 1 / N_DOT_V_MIN",
    ),
    col(
        "microfacet_d (each D, by code)",
        "MICROFACET_D",
        D_COUNT,
        D_MAX,
        "each D peaks at 1/(4 m²) at m = M_MIN, as Beckmann's",
    ),
    col("g_smith_separable (each D's Λ, by code)", "G_SMITH_SEPARABLE", D_COUNT, 1.0, "a product of two G1 in [0, 1]"),
    col("g_smith_correlated (each D's Λ, by code)", "G_SMITH_CORRELATED", D_COUNT, 1.0, "1/(1 + Λv + Λl), Λ ≥ 0"),
    col("microfacet_f (fresnel_schlick at V·H)", "MICROFACET_F_SCHLICK", 3, 1.0, "F0 + (1 − F0)(1 − c)⁵, F0 in [0, 1]"),
    col(
        "specular_microfacet (glTF: GGX, correlated Smith, Schlick)",
        "SPECULAR_MICROFACET_GLTF",
        3,
        D_MAX / N_DOT_V_MIN,
        "F·D·G/(N·V) ≤ 1 · 1/(4 M_MIN²) · 1 / N_DOT_V_MIN",
    ),
    col(
        "ms_compensation (E = m)",
        "MS_COMPENSATION",
        3,
        1.0 / MS_ALBEDO_MIN,
        "1 + F0 (1 − E)/E ≤ 1/MS_ALBEDO_MIN, F0 ≤ 1",
    ),
    col(
        "fresnel_mix_weight (F0 = μ.x, w = 1; glTF's F, the chapter's)",
        "FRESNEL_MIX_WEIGHT",
        2,
        1.0,
        "1 − w·F, F and w in [0, 1]",
    ),
    col("falloff_quadratic", "FALLOFF_QUADRATIC", 1, 1.0, "1/(1 + α d²), α ≥ 0"),
    col("falloff_linear", "FALLOFF_LINEAR", 1, 1.0 / D0_MIN, "1/(d + d0), d0 ≥ D0_MIN"),
    col("light_contribution (Phong)", "CONTRIBUTION_PHONG", 3, 0.8 + 1.0, "I_L (r_d C + r_s), falloff ≤ 1"),
    col(
        "light_contribution (Cook–Torrance, 1/(d+d0))",
        "CONTRIBUTION_COOK_TORRANCE",
        3,
        (0.8 + D_MAX / N_DOT_V_MIN) / D0_MIN,
        "(r_d C + r_s S_max) / D0_MIN",
    ),
    col("lambert_rule_lit", "LAMBERT_RULE_LIT", 3, 1.0, "R·I·cos α with R, I clamped to [0, 1]"),
    col("lambert_rule_fill", "LAMBERT_RULE_FILL", 3, 1.0, "R·(1 − I) with R, I clamped to [0, 1]"),
    col("reflected_cos_phi", "REFLECTED_COS_PHI", 1, 1.0, "N·V of unit vectors, clamped at 0"),
    col("sum_contribution (1/(d+d0))", "SUM_CONTRIBUTION", 3, (0.8 + 1.0) / D0_MIN, "I (r_d C + r_s), I ≤ 1/D0_MIN"),
    col("transmitted_term (1/(d+d0))", "TRANSMITTED_TERM", 3, 0.8 / D0_MIN, "I·C·(1 − t), I ≤ 1/D0_MIN"),
    col("spot_cone", "SPOT_CONE", 1, 1.0, "a ramp clamped to [0, 1], squared"),
    col("window_range", "WINDOW_RANGE", 1, 1.0, "1 − x⁴, x clamped to [0, 1]"),
    col("shadow_face", "SHADOW_FACE", 1, 5.0, "a cube face index, 0…5"),
    col("shadow_texel_world", "SHADOW_TEXEL_WORLD", 1, f64::INFINITY, "a world length: finite, grows with the scene"),
    Column {
        signed: true,
        ..col("shadow_map_coord", "SHADOW_MAP_COORD", 3, f64::INFINITY, "finite; outside [0, 1] off the map")
    },
    col("shadow_ortho_texel_world", "SHADOW_ORTHO_TEXEL_WORLD", 1, f64::INFINITY, "a world length: finite"),
    col("tinted_surface (C)", "TINTED_SURFACE_C", 3, 1.0, "C·t with C and t in [0, 1]"),
    col("tinted_surface (μ)", "TINTED_SURFACE_MU", 3, 1.0, "μ + μ_t·(t − 1) clamped to [0, 1]"),
    col("vertex_tint", "VERTEX_TINT", 3, 1.0, "clamped to [0, 1], non-finite white"),
    Column {
        signed: true,
        ..col("texture_uv", "TEXTURE_UV", 3, f64::INFINITY, "finite: offset + R·(scale ⊙ uv), no bound of its own")
    },
    col("metallic_scaled (C)", "METALLIC_SCALED_C", 3, 2.0, "C + μ_t·(1 − b), C, μ_t and b in [0, 1]"),
    col("metallic_scaled (μ)", "METALLIC_SCALED_MU", 3, 1.0, "μ·(b + 0.04·(1 − b)) for a metal, b in [0, 1]"),
    col("roughness_scaled", "ROUGHNESS_SCALED", 1, 1.0, "m·g² clamped to [0, 1]"),
    col("phong_h_from_m", "PHONG_H_FROM_M", 1, shadelab_model::guards::H_MAX, "2/m² − 2 clamped to [1, H_MAX]"),
    col("occluded", "OCCLUDED", 1, 0.8, "r_a·(1 + s·(occ − 1)) with r_a = 0.8, occ and s in [0, 1]"),
    col("emitted", "EMITTED", 3, 1.0, "I_e·texel with I_e = μ and the texel clamped to [0, 1]"),
    Column { signed: true, ..col("normal_mapped", "NORMAL_MAPPED", 3, 1.0, "a unit vector, or N") },
    col("area_form (rect, disk, sphere)", "AREA_FORM", 3, f64::INFINITY, "finite: d²·(E/L)/A, E/L ≤ π"),
    col(
        "area_specular_point scale (rect, disk, sphere)",
        "AREA_SPEC_SCALE",
        3,
        f64::INFINITY,
        "finite: cos θ_l·d²/r² ≤ d²/LIGHT_DIST_MIN²",
    ),
    col(
        "area_point_sample form⁺, k = 1 + ⌊7m⌋ summed (rect, disk, sphere)",
        "AREA_POINTS_FORM",
        3,
        f64::INFINITY,
        "finite: Σ gain·d²/max(r², LIGHT_DIST_MIN²)",
    ),
    col("fresnel_dielectric (into v, out of v)", "FRESNEL_DIELECTRIC", 2, 1.0, "a reflectance in [0, 1]; 1 under TIR"),
    Column {
        signed: true,
        ..col("refract_snell (xyz, refracted)", "REFRACT_SNELL", 4, 1.0, "a unit direction and a 0/1 flag")
    },
    col("absorption_exact, absorption_rule (a·d = α·d)", "ABSORPTION", 2, 1.0, "a share in [0, 1], underflowing to 0"),
    col("sphere_chord", "SPHERE_CHORD", 1, f64::INFINITY, "finite: at most the diameter 2α"),
    col(
        "absorption_in_form (exact, linear, neglected; a·d = α·d)",
        "ABSORPTION_IN_FORM",
        3,
        1.0,
        "a share in [0, 1]: 1 − a·d held at 0",
    ),
    col(
        "shape_exit t from m·N along V (sphere, cylinder, cube, pyramid)",
        "SHAPE_EXIT",
        4,
        3.5,
        "0 (on the surface, leaving) to the longest chord, 2√3",
    ),
    col("penumbra_width", "PENUMBRA_WIDTH", 1, f64::INFINITY, "finite: w·d_r/BLOCKER_DIST_MIN"),
    col("pcss_search_radius", "PCSS_SEARCH_RADIUS", 1, f64::INFINITY, "finite: ½w/BLOCKER_DIST_MIN"),
    col("shadow_linear_depth", "SHADOW_LINEAR_DEPTH", 1, f64::INFINITY, "between near and far"),
    col("shadow_stored_depth", "SHADOW_STORED_DEPTH", 1, 1.0, "a depth in [0, 1]"),
    col("receiver_slope", "RECEIVER_SLOPE", 1, shadows::SHADOW_RECEIVER_SLOPE_MAX, "tan θ capped"),
];

const fn col(name: &'static str, wgsl: &'static str, channels: usize, bound: f64, why_bound: &'static str) -> Column {
    Column { name, wgsl, channels, bound, why_bound, signed: false }
}

/// Floats the kernel writes per combination (`SWEEP_OUTPUTS` in WGSL).
pub const OUTPUTS: usize = outputs_of(&COLUMNS);

/// Floats a kernel with `columns` writes per combination.
pub(super) const fn outputs_of(columns: &[Column]) -> usize {
    let (mut n, mut i) = (0, 0);
    while i < columns.len() {
        n += columns[i].channels;
        i += 1;
    }
    n
}

/// The first index of the column named `wgsl` (a name not in [`COLUMNS`] fails to compile where
/// used in a constant).
pub const fn offset(wgsl: &str) -> usize {
    offset_in(&COLUMNS, wgsl)
}

/// The first index of the column named `wgsl` among `columns`.
pub(super) const fn offset_in(columns: &[Column], wgsl: &str) -> usize {
    let (mut at, mut i) = (0, 0);
    while i < columns.len() {
        if same(columns[i].wgsl, wgsl) {
            return at;
        }
        at += columns[i].channels;
        i += 1;
    }
    panic!("no such sweep column")
}

const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The columns' index ranges, in the order of [`COLUMNS`].
pub fn ranges() -> impl Iterator<Item = (Column, std::ops::Range<usize>)> {
    ranges_of(&COLUMNS)
}

/// The index ranges of `columns`, in their order.
pub(super) fn ranges_of(columns: &'static [Column]) -> impl Iterator<Item = (Column, std::ops::Range<usize>)> {
    columns.iter().scan(0, |at, c| {
        let r = *at..*at + c.channels;
        *at = r.end;
        Some((*c, r))
    })
}

/// The WGSL the kernel is compiled with: `SWEEP_OUTPUTS`, one `COL_…` per column, and the
/// constants the kernel shares with [`reference`] (as f32, the values the f64 side reads).
pub fn wgsl_columns() -> String {
    let mut s = String::from("// Generated from crates/shadelab-render/src/sweep/columns.rs.\n");
    let c = SWEEP_COLOR.map(|x| x as f32);
    s += &format!("const SWEEP_COLOR: vec3<f32> = vec3({:?}, {:?}, {:?});\n", c[0], c[1], c[2]);
    s += &format!("const SWEEP_CONE_PER_M: f32 = {:?};\n", SWEEP_CONE_PER_M as f32);
    s += &format!("const SWEEP_SHADOW_RESOLUTION: f32 = {:?};\n", SWEEP_SHADOW_RESOLUTION as f32);
    s += &format!("const SWEEP_OUTPUTS: u32 = {OUTPUTS}u;\n");
    for (c, r) in ranges() {
        s += &format!("const COL_{}: u32 = {}u;\n", c.wgsl, r.start);
    }
    s
}

/// Colour of the material in the per-light contribution (`SWEEP_COLOR` in the kernel).
const SWEEP_COLOR: [f64; 3] = [0.8, 0.5, 0.2];
/// Outer spot cone per unit of m (`SWEEP_CONE_PER_M` in the kernel): π/2 as an f32, the value
/// the GPU multiplies by.
const SWEEP_CONE_PER_M: f64 = std::f32::consts::FRAC_PI_2 as f64;

/// How many input perturbations an area form's summed terms are each rounded by on the GPU: each
/// is an atan2 (WGSL bounds its error at 4096 ulps, against one for a product) of directions
/// already a few ulps off; ten perturbations, 160 ulps, stays far inside that bound.
pub(super) const AREA_TERM_ROUNDING: f64 = 10.0;

/// Map side the sweep's `shadow_ortho_texel_world` divides by (`SWEEP_SHADOW_RESOLUTION`).
const SWEEP_SHADOW_RESOLUTION: f64 = 2048.0;

const DIFFUSE_LAMBERT: usize = offset("DIFFUSE_LAMBERT");
const SPECULAR_PHONG: usize = offset("SPECULAR_PHONG");
const PHONG_NORMALIZED: usize = offset("PHONG_NORMALIZED");
const D_BECKMANN: usize = offset("D_BECKMANN");
const G_COOK_TORRANCE: usize = offset("G_COOK_TORRANCE");
const MICROFACET_F: usize = offset("MICROFACET_F");
const SPECULAR_COOK_TORRANCE: usize = offset("SPECULAR_COOK_TORRANCE");
const MICROFACET_D: usize = offset("MICROFACET_D");
const G_SMITH_SEPARABLE: usize = offset("G_SMITH_SEPARABLE");
const G_SMITH_CORRELATED: usize = offset("G_SMITH_CORRELATED");
const MICROFACET_F_SCHLICK: usize = offset("MICROFACET_F_SCHLICK");
const SPECULAR_MICROFACET_GLTF: usize = offset("SPECULAR_MICROFACET_GLTF");
const MS_COMPENSATION: usize = offset("MS_COMPENSATION");
const FRESNEL_MIX_WEIGHT: usize = offset("FRESNEL_MIX_WEIGHT");
const FALLOFF_QUADRATIC: usize = offset("FALLOFF_QUADRATIC");
const FALLOFF_LINEAR: usize = offset("FALLOFF_LINEAR");
const CONTRIBUTION_PHONG: usize = offset("CONTRIBUTION_PHONG");
const CONTRIBUTION_COOK_TORRANCE: usize = offset("CONTRIBUTION_COOK_TORRANCE");
const LAMBERT_RULE_LIT: usize = offset("LAMBERT_RULE_LIT");
const LAMBERT_RULE_FILL: usize = offset("LAMBERT_RULE_FILL");
const REFLECTED_COS_PHI: usize = offset("REFLECTED_COS_PHI");
const SUM_CONTRIBUTION: usize = offset("SUM_CONTRIBUTION");
const TRANSMITTED_TERM: usize = offset("TRANSMITTED_TERM");
const SPOT_CONE: usize = offset("SPOT_CONE");
const WINDOW_RANGE: usize = offset("WINDOW_RANGE");
const SHADOW_FACE: usize = offset("SHADOW_FACE");
const SHADOW_TEXEL_WORLD: usize = offset("SHADOW_TEXEL_WORLD");
const SHADOW_MAP_COORD: usize = offset("SHADOW_MAP_COORD");
const SHADOW_ORTHO_TEXEL_WORLD: usize = offset("SHADOW_ORTHO_TEXEL_WORLD");
const TINTED_SURFACE_C: usize = offset("TINTED_SURFACE_C");
const TINTED_SURFACE_MU: usize = offset("TINTED_SURFACE_MU");
const VERTEX_TINT: usize = offset("VERTEX_TINT");
const TEXTURE_UV: usize = offset("TEXTURE_UV");
const METALLIC_SCALED_C: usize = offset("METALLIC_SCALED_C");
const METALLIC_SCALED_MU: usize = offset("METALLIC_SCALED_MU");
const ROUGHNESS_SCALED: usize = offset("ROUGHNESS_SCALED");
const PHONG_H_FROM_M: usize = offset("PHONG_H_FROM_M");
const OCCLUDED: usize = offset("OCCLUDED");
const EMITTED: usize = offset("EMITTED");
const NORMAL_MAPPED: usize = offset("NORMAL_MAPPED");
const AREA_FORM: usize = offset("AREA_FORM");
const AREA_SPEC_SCALE: usize = offset("AREA_SPEC_SCALE");
const AREA_POINTS_FORM: usize = offset("AREA_POINTS_FORM");
const FRESNEL_DIELECTRIC: usize = offset("FRESNEL_DIELECTRIC");
const REFRACT_SNELL: usize = offset("REFRACT_SNELL");
const ABSORPTION: usize = offset("ABSORPTION");
const SPHERE_CHORD: usize = offset("SPHERE_CHORD");
const ABSORPTION_IN_FORM: usize = offset("ABSORPTION_IN_FORM");
const SHAPE_EXIT: usize = offset("SHAPE_EXIT");
const PENUMBRA_WIDTH: usize = offset("PENUMBRA_WIDTH");
const PCSS_SEARCH_RADIUS: usize = offset("PCSS_SEARCH_RADIUS");
const SHADOW_LINEAR_DEPTH: usize = offset("SHADOW_LINEAR_DEPTH");
const SHADOW_STORED_DEPTH: usize = offset("SHADOW_STORED_DEPTH");
const RECEIVER_SLOPE: usize = offset("RECEIVER_SLOPE");

/// The f64 reference of the kernel's outputs for one combination's inputs.
///
/// `l_len` scales the light direction a point light's sample gives, and the spot cone's cosines
/// (1 for the exact model): the GPU's `to_light / d` is a unit vector, and its `cos` of a cone
/// angle exact, only to a few f32 ulps. (Near 1 an f32 cosine is good to 6e-8, so a cone under a
/// degree, where `1 − cos` is ~1e-4 or less, is decided by that rounding.)
// One argument per axis of the sweep, as the kernel reads them.
#[allow(clippy::too_many_arguments)]
pub(super) fn reference(
    n_raw: DVec3,
    v: DVec3,
    l: DVec3,
    (m, h, mirror): (f64, f64, bool),
    mu: [f64; 3],
    (d, alpha, d0): (f64, f64, f64),
    l_len: f64,
    shadow: &ShadowCase,
) -> [f64; OUTPUTS] {
    let n = common::safe_normalize(n_raw, v);
    let v_index = mu.map(brdf::fresnel_v_from_mu);
    let inp = Combination { n_raw, n, v, l, m, h, mirror, mu, v_index, d, alpha, d0, l_len };
    // NaN marks a column not written (a test checks there is none).
    let mut out = [f64::NAN; OUTPUTS];
    light_columns(&mut out, &inp);
    microfacet_columns(&mut out, &inp);
    shadow_map_columns(&mut out, &inp, shadow);
    surface_map_columns(&mut out, &inp);
    area_columns(&mut out, &inp);
    transmission_columns(&mut out, &inp);
    pcss_columns(&mut out, &inp);
    out
}

/// One combination's inputs as [`reference`]'s column groups read them (`n` is `n_raw` normalized).
#[derive(Clone, Copy)]
struct Combination {
    n_raw: DVec3,
    n: DVec3,
    v: DVec3,
    l: DVec3,
    m: f64,
    h: f64,
    mirror: bool,
    mu: [f64; 3],
    /// Fresnel's v of each channel of μ.
    v_index: [f64; 3],
    d: f64,
    alpha: f64,
    d0: f64,
    l_len: f64,
}

/// Writes a colour's three channels at column offset `at`.
fn rgb(out: &mut [f64; OUTPUTS], at: usize, c: [f64; 3]) {
    out[at..at + 3].copy_from_slice(&c);
}

/// The BRDF, falloff, per-light contribution, other-model and spot-and-window columns.
fn light_columns(out: &mut [f64; OUTPUTS], inp: &Combination) {
    let Combination { n, v, l, m, h, mirror, mu, v_index, d, alpha, d0, l_len, .. } = *inp;
    let half = common::safe_normalize(l + v, n);
    let r = 2.0 * n.dot(l) * n - l;
    let mut light = Light {
        kind: LightKind::Point,
        position: l * d,
        direction: -l,
        color: [1.0; 3],
        intensity: 1.0,
        falloff_form: FalloffForm::Quadratic,
        falloff_alpha: alpha,
        d0,
        ..Light::point(DVec3::ZERO, [1.0; 3], 1.0, 0.0)
    };
    // The GPU's unit direction, to its rounding; a point light's form is N·L of that direction.
    let scaled = |mut s: lights::LightSample| {
        s.l *= l_len;
        s.form = n.dot(s.l);
        s
    };
    let quadratic = scaled(lights::light_sample(&light, DVec3::ZERO, n, v, m));
    light.falloff_form = FalloffForm::Linear;
    let linear = scaled(lights::light_sample(&light, DVec3::ZERO, n, v, m));
    let mat = Material {
        color: SWEEP_COLOR,
        r_s: 1.0,
        r_d: 1.0,
        m,
        h: if mirror { PhongExponent::Mirror } else { PhongExponent::Finite(h) },
        mu,
        ..Material::default()
    };
    let outer = m * SWEEP_CONE_PER_M;
    let inner = outer * alpha.min(1.0);
    out[DIFFUSE_LAMBERT] = brdf::diffuse_lambert(n.dot(l));
    out[SPECULAR_PHONG] = brdf::specular_phong(v.dot(r), h, mirror);
    out[PHONG_NORMALIZED] = brdf::phong_normalization(h, mirror) * brdf::specular_phong(v.dot(r), h, mirror);
    out[D_BECKMANN] = brdf::d_beckmann(n.dot(half), n.cross(half).length_squared(), m);
    out[G_COOK_TORRANCE] = brdf::g_cook_torrance(n.dot(half), n.dot(v), n.dot(l), v.dot(half));
    rgb(out, MICROFACET_F, microfacet::microfacet_f(Microfacet::CHAPTER, v.dot(half), v_index));
    rgb(out, SPECULAR_COOK_TORRANCE, brdf::specular_cook_torrance(n, v, l, m, v_index));
    out[FALLOFF_QUADRATIC] = lights::falloff_quadratic(d, alpha);
    out[FALLOFF_LINEAR] = lights::falloff_linear(d, d0);
    let cp = brdf::light_contribution(&quadratic, n, v, &mat, v_index, SpecularModel::Phong, 1.0);
    rgb(out, CONTRIBUTION_PHONG, cp);
    let cc = brdf::light_contribution(&linear, n, v, &mat, v_index, SpecularModel::CookTorrance, 1.0);
    rgb(out, CONTRIBUTION_COOK_TORRANCE, cc);
    // The other models at the linear falloff's sample; m in [0, 1] doubles as the share 1 − t.
    let (nl, nv) = (linear.form, n.dot(v));
    rgb(out, LAMBERT_RULE_LIT, models::lambert_rule_lit(SWEEP_COLOR, linear.radiance, nl));
    rgb(out, LAMBERT_RULE_FILL, models::lambert_rule_fill(SWEEP_COLOR, linear.radiance));
    out[REFLECTED_COS_PHI] = models::reflected_cos_phi(nl, nv);
    rgb(out, SUM_CONTRIBUTION, models::sum_contribution(linear.radiance, nl, nv, SWEEP_COLOR, 1.0, 1.0));
    rgb(out, TRANSMITTED_TERM, models::transmitted_term(linear.radiance, SWEEP_COLOR, m));
    out[SPOT_CONE] = lights::spot_cone(v.dot(l), inner.cos() * l_len, outer.cos() * l_len);
    out[WINDOW_RANGE] = lights::window_range(d, d0);
}

/// The microfacet terms beyond the chapter's: every D and Smith's G on each D's Λ, Schlick's F
/// and the glTF preset's whole specular.
fn microfacet_columns(out: &mut [f64; OUTPUTS], inp: &Combination) {
    use microfacet::Distribution;
    use shadelab_model::params::NamedValue;
    let Combination { n, v, l, m, v_index, .. } = *inp;
    let half = common::safe_normalize(l + v, n);
    let (nv, nl) = (n.dot(v), n.dot(l));
    // Every D of the term table and its Smith G, each at its code's channel.
    for &(_, d) in Distribution::ALL {
        let k = d.code() as usize;
        let terms = Microfacet { d, ..Microfacet::CHAPTER };
        out[MICROFACET_D + k] = microfacet::microfacet_d(terms, n.dot(half), n.cross(half).length_squared(), m);
        out[G_SMITH_SEPARABLE + k] = microfacet::g_smith_separable(d, nv, nl, m);
        out[G_SMITH_CORRELATED + k] = microfacet::g_smith_correlated(d, nv, nl, m);
    }
    rgb(out, MICROFACET_F_SCHLICK, microfacet::microfacet_f(Microfacet::GLTF, v.dot(half), v_index));
    rgb(out, SPECULAR_MICROFACET_GLTF, microfacet::specular_microfacet(n, v, l, m, v_index, Microfacet::GLTF, 1.0));
    // The compensation over E = m (0 to 1, the floor at 0 included).
    rgb(out, MS_COMPENSATION, shadelab_model::lighting::multiscatter::ms_compensation(m, v_index));
    for (k, terms) in [Microfacet::GLTF, Microfacet::CHAPTER].into_iter().enumerate() {
        out[FRESNEL_MIX_WEIGHT + k] = microfacet::fresnel_mix_weight(terms, n, v, l, inp.mu[0], 1.0);
    }
}

/// The shadow-map columns: the cube face, the texel's world size and the map coordinate.
fn shadow_map_columns(out: &mut [f64; OUTPUTS], inp: &Combination, shadow: &ShadowCase) {
    let Combination { n, l, d, .. } = *inp;
    let to_p = l * d;
    let texel = shadows::shadow_texel_world(shadow.texel_world as f64, shadow.perspective, d * n.dot(l));
    out[SHADOW_FACE] = shadows::shadow_face(to_p) as f64;
    out[SHADOW_TEXEL_WORLD] = texel;
    let q = to_p + n * (shadows::SHADOW_NORMAL_OFFSET_TEXELS as f64 * texel);
    rgb(out, SHADOW_MAP_COORD, shadows::shadow_map_coord(shadow.dmat4(), q).to_array());
    out[SHADOW_ORTHO_TEXEL_WORLD] = shadows::shadow_ortho_texel_world(shadow.dmat4(), SWEEP_SHADOW_RESOLUTION);
}

/// The surface columns: tint, vertex colour, texture coordinates and the material maps.
fn surface_map_columns(out: &mut [f64; OUTPUTS], inp: &Combination) {
    let Combination { n_raw, n, v, l, m, h, mu, d, alpha, d0, .. } = *inp;
    // The surface at a tint of m in every channel, μ's tinted part μ itself (a metal); the raw
    // normal as a vertex colour (outside [0, 1]); d and α as texture coordinates, transformed by
    // the offset (d0, d), a rotation of 4m right angles and the scale (h, d).
    let (c, mu_t) = shadelab_model::scene::tinted_surface(SWEEP_COLOR, mu, mu, [m; 3]);
    rgb(out, TINTED_SURFACE_C, c);
    rgb(out, TINTED_SURFACE_MU, mu_t);
    rgb(out, VERTEX_TINT, shadelab_model::scene::vertex_tint(n_raw.to_array()));
    let uv = shadelab_model::scene::texture_uv([d, alpha], [d0, d], 4.0 * m * SWEEP_CONE_PER_M, [h, d]);
    rgb(out, TEXTURE_UV, [uv[0], uv[1], 0.0]);
    // The material maps with the raw normal's channels as texels (outside [0, 1]): a metal
    // (μ_t = μ, M·F0 = 0.04·μ) at metal scale x, the roughness m at scale y, r_a = 0.8 occluded by
    // z at strength m, and I_e = μ times the normal as an emissive texel.
    let (x, y, z) = (n_raw.x, n_raw.y, n_raw.z);
    let (c, mu_s, _) = shadelab_model::scene::metallic_scaled(SWEEP_COLOR, mu, mu, mu.map(|c| 0.04 * c), x);
    rgb(out, METALLIC_SCALED_C, c);
    rgb(out, METALLIC_SCALED_MU, mu_s);
    out[ROUGHNESS_SCALED] = shadelab_model::scene::roughness_scaled(m, y);
    out[PHONG_H_FROM_M] = shadelab_model::scene::phong_h_from_m(m);
    out[OCCLUDED] = shadelab_model::scene::occluded(0.8, z, m);
    rgb(out, EMITTED, shadelab_model::scene::emitted(mu, n_raw.to_array()));
    // N turned by the raw normal as a texel in the frame of L as tangent (along N at normal
    // incidence: no frame), its sign from V·L, scale h.
    let w = if v.dot(l) < 0.0 { -1.0 } else { 1.0 };
    let mapped = shadelab_model::scene::normal_mapped(n, [l.x, l.y, l.z, w], n_raw.to_array(), h);
    rgb(out, NORMAL_MAPPED, mapped.to_array());
}

/// The area-light columns: each shape's diffuse form, specular scale and point-source form.
fn area_columns(out: &mut [f64; OUTPUTS], inp: &Combination) {
    let Combination { n, v, l, m, d, alpha, l_len, .. } = *inp;
    // Area lights at l·d facing −v, α as their size (0 to 1e6 m): the diffuse form and the
    // specular point's scale of each shape. Their corners' components are as large as the light,
    // so their rounding moves the light's plane by about its size times the perturbation
    // (`l_len − 1`, 0 for the exact model): a point within that of the plane is ill-conditioned,
    // as is a sliver the horizon leaves, where the edge terms cancel.
    let normal = -v;
    let plane_rounding = normal * (alpha * (l_len - 1.0));
    let tangent = common::safe_normalize(normal.cross(DVec3::Z), DVec3::X);
    let half = 0.5 * alpha;
    let shapes = [
        AreaShape::Rect { half_x: half, half_y: half },
        AreaShape::Disk { radius: half },
        AreaShape::Sphere { radius: half },
    ];
    for (k, shape) in shapes.into_iter().enumerate() {
        let a = AreaLight { shape, center: l * d + plane_rounding, normal, tangent };
        // Each term of the form's sum is an atan2 of f32 directions, rounded by several times
        // the inputs' perturbation (WGSL allows atan2 4096 ulps): the form's change is the sum of
        // their magnitudes times AREA_TERM_ROUNDING perturbations.
        let rounding = area::area_form_rounding(&a, DVec3::ZERO, n) * (l_len - 1.0) * AREA_TERM_ROUNDING;
        out[AREA_FORM + k] = area::area_form(&a, DVec3::ZERO, n) + rounding;
        out[AREA_SPEC_SCALE + k] = area::area_specular_point(&a, DVec3::ZERO, n, v, m).1;
        // The same light as k = 1 + ⌊7m⌋ point sources: their forms, each clipped at 0 as the
        // diffuse term takes it, summed.
        let kind = [LightKind::Rect, LightKind::Disk, LightKind::Sphere][k];
        let mut light = Light::area(kind, a.center, normal, [alpha; 2], [1.0; 3], 1.0, 0.0);
        (light.tangent, light.area_points) = (tangent, 1 + (m * 7.0) as u32);
        let base = lights::LightSample { l, radiance: [1.0; 3], form: 0.0, spec_scale: 1.0, ltc: None };
        out[AREA_POINTS_FORM + k] = (0..light.area_points)
            .map(|j| {
                brdf::diffuse_lambert(area_point_sample(&base, &light, &area_emitter(&light, j), DVec3::ZERO, n).form)
            })
            .sum();
    }
}

/// The transmission columns: Fresnel, refraction, absorption, the sphere's chord and shape exits.
fn transmission_columns(out: &mut [f64; OUTPUTS], inp: &Combination) {
    let Combination { n, v, l, m, v_index, d, alpha, .. } = *inp;
    // Light through a surface at N, met along −V: into a medium of index v (μ's red channel) and
    // out of it (total internal reflection past its critical angle); absorption over a·d = α·d
    // (0 to 1e10); the chord from l·d·m towards V through a sphere of radius α at the origin.
    let (vr, c) = (v_index[0], n.dot(v));
    out[FRESNEL_DIELECTRIC] = microfacet::fresnel_dielectric(c, vr);
    out[FRESNEL_DIELECTRIC + 1] = microfacet::fresnel_dielectric(c, 1.0 / vr);
    let refracted = transmission::refract_snell(-v, n, 1.0 / vr).map_or([0.0; 4], |t| [t.x, t.y, t.z, 1.0]);
    out[REFRACT_SNELL..REFRACT_SNELL + 4].copy_from_slice(&refracted);
    out[ABSORPTION] = transmission::absorption_exact(alpha * d);
    out[ABSORPTION + 1] = transmission::absorption_rule(alpha * d);
    out[SPHERE_CHORD] = transmission::sphere_chord(l * (d * m), v, DVec3::ZERO, alpha);
    for form in 0..3 {
        out[ABSORPTION_IN_FORM + form] = transmission::absorption_in_form(alpha * d, form as u32);
    }
    // The exit from m·N inside each unit shape along V: on the surface (m = 1) and leaving, the
    // exit touches the entry; grazing views run along it.
    use transmission::{SHAPE_CUBE, SHAPE_CYLINDER, SHAPE_PYRAMID, SHAPE_SPHERE};
    for (k, shape) in [SHAPE_SPHERE, SHAPE_CYLINDER, SHAPE_CUBE, SHAPE_PYRAMID].into_iter().enumerate() {
        out[SHAPE_EXIT + k] = transmission::shape_exit(shape, n * m, v).map_or(-1.0, |e| e.0);
    }
}

/// The PCSS and shadow-depth columns.
fn pcss_columns(out: &mut [f64; OUTPUTS], inp: &Combination) {
    let Combination { n, l, m, d, alpha, d0, .. } = *inp;
    // PCSS with a light α wide, the receiver at d and the blocker at d0 (d = d0 among them: a
    // receiver touching its blocker); m as a stored depth between near d0 and far d0 + d.
    out[PENUMBRA_WIDTH] = shadows::penumbra_width(alpha, d, d0);
    out[PCSS_SEARCH_RADIUS] = shadows::pcss_search_radius(alpha, d, d0);
    out[SHADOW_LINEAR_DEPTH] = shadows::shadow_linear_depth(m, d0, d0 + d);
    out[SHADOW_STORED_DEPTH] = shadows::shadow_stored_depth(d, d0, d0 + d);
    out[RECEIVER_SLOPE] = shadows::receiver_slope(n.dot(l));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The f64 reference writes every column, and the kernel names every column it is given.
    #[test]
    fn every_column_is_written_on_both_sides() {
        let y = DVec3::Y;
        let case = super::super::SweepInputs::standard().shadow[0];
        let out = reference(y, y, y, (0.2, 20.0, false), [0.04; 3], (1.0, 0.1, 1.0), 1.0, &case);
        assert!(out.iter().all(|x| !x.is_nan()), "{out:?}");
        for c in COLUMNS {
            let name = format!("COL_{}", c.wgsl);
            assert!(crate::sweep::SWEEP_KERNEL.contains(&name), "sweep.wgsl does not write {name}");
        }
        assert_eq!(ranges().last().map(|(_, r)| r.end), Some(OUTPUTS));
    }
}
