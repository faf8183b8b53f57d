//! The stability sweep: every lighting term of the shipped WGSL, evaluated on the GPU over more
//! than 10⁶ combinations of hard inputs, checked against the f64 reference.
//!
//! For every combination it asserts (in the tests) and reports (in `shadelab sweep`): the output
//! is finite and ≥ 0; it is at most the term's bound, which the guards imply; and where the f64
//! reference is well-conditioned, the GPU is within `ERROR_TOLERANCE` of it.

use crate::gpu::Gpu;
use crate::shaders;
use glam::DVec3;
use shadelab_model::brdf;
use shadelab_model::guards::*;
use shadelab_model::scene::{Light, Material};
use shadelab_model::{FalloffForm, LightKind, PhongExponent, SpecularModel};
use wgpu::util::DeviceExt;

/// Relative change of the f64 reference under an input perturbation of `INPUT_PERTURBATION`
/// above which a combination counts as ill-conditioned: there the value is decided by input
/// rounding (a term switching on at N·L = 0, (V·R)^1e9, the mirror threshold), not by the
/// arithmetic, and f32 cannot be expected to match f64.
pub const WELL_CONDITIONED_CHANGE: f64 = 1e-3;
/// Relative size of that perturbation: about 16 f32 ulps of a unit vector, larger than the
/// rounding of the GPU's own inputs (one ulp) and dot products (a few ulps).
pub const INPUT_PERTURBATION: f64 = 1e-6;
/// Distance from a switch of the model (N·L = 0, N·V = 0, V·R = MIRROR_V_DOT_R_MIN) within which
/// a combination counts as ill-conditioned: an f32 dot product of unit vectors is off by up to
/// ~1e-7, so within 1e-6 the GPU may land on the other side. (Perturbing the input vectors does
/// not show this near V·R = 1, where the dot product moves only to second order.)
pub const SWITCH_MARGIN: f64 = 1e-6;
/// Largest relative error allowed between GPU (f32) and reference (f64) where well-conditioned.
/// A well-conditioned output moves by at most 1e-3 under a 1e-6 input change, so f32 rounding
/// (~1e-7) moves it by ~1e-4: the tolerance leaves a factor of 10.
pub const ERROR_TOLERANCE: f64 = 1e-3;
/// Errors up to this need no conditioning check: they pass whatever the conditioning. Above it,
/// an output at an ill-conditioned point is excluded from the error check and counted.
pub const ERROR_CHECK_CONDITIONING: f64 = 1e-5;
/// Values below this count as zero when computing a relative error (f32 flushes the far tails of
/// exp() to 0 where f64 still has 1e-300).
pub const ERROR_ABS_FLOOR: f64 = 1e-6;

/// Colour of the material in the per-light contribution (`SWEEP_COLOR` in sweep.wgsl).
const SWEEP_COLOR: [f64; 3] = [0.8, 0.5, 0.2];
const OUTPUTS: usize = 20;
/// Outer spot cone per unit of m (`SWEEP_CONE_PER_M` in sweep.wgsl, π/2 as an f32).
const SWEEP_CONE_PER_M: f64 = std::f32::consts::FRAC_PI_2 as f64;

/// One geometry: a (possibly zero or non-unit) normal, and unit view and light vectors, in f32
/// as the GPU gets them.
#[derive(Clone, Copy, Debug)]
pub struct Geometry {
    pub n: [f32; 3],
    pub v: [f32; 3],
    pub l: [f32; 3],
    pub label: &'static str,
}

/// The sweep's axes; the combinations are their full product.
pub struct SweepInputs {
    pub geometry: Vec<Geometry>,
    pub m: Vec<f32>,
    /// (h, mirror)
    pub h: Vec<(f32, bool)>,
    pub mu: Vec<[f32; 3]>,
    pub d: Vec<f32>,
    /// (α of the quadratic falloff, d0 of the linear one)
    pub alpha: Vec<(f32, f32)>,
}

fn unit(v: DVec3) -> [f32; 3] {
    v.normalize().as_vec3().to_array()
}

fn dir(theta_deg: f64, phi_deg: f64) -> DVec3 {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    DVec3::new(t.sin() * p.cos(), t.cos(), t.sin() * p.sin())
}

impl SweepInputs {
    /// The hard cases of spec §9 plus a deterministic spread of ordinary directions.
    pub fn standard() -> SweepInputs {
        let y = [0.0f32, 1.0, 0.0];
        let mut g = vec![
            Geometry { n: y, v: y, l: y, label: "normal incidence" },
            Geometry { n: y, v: unit(dir(30.0, 0.0)), l: [1.0, 0.0, 0.0], label: "light exactly at 90°" },
            Geometry { n: y, v: [1.0, 0.0, 0.0], l: unit(dir(30.0, 180.0)), label: "view exactly at 90°" },
            Geometry { n: y, v: [0.0, 0.0, 1.0], l: [1.0, 0.0, 0.0], label: "light and view at 90°" },
            Geometry { n: y, v: [-1.0, 0.0, 0.0], l: [1.0, 0.0, 0.0], label: "L = −V at 90°" },
            Geometry { n: y, v: unit(dir(40.0, 180.0) * -1.0), l: unit(dir(40.0, 180.0)), label: "L = −V" },
            Geometry { n: y, v: unit(dir(120.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "back-facing view" },
            Geometry { n: y, v: unit(dir(30.0, 0.0)), l: unit(dir(120.0, 180.0)), label: "light below horizon" },
            Geometry { n: [0.0; 3], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "zero normal" },
            Geometry { n: [0.0, 1e-3, 0.0], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "short normal" },
            Geometry { n: [0.0, 1e-12, 0.0], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "tiny normal" },
            Geometry { n: [0.0, 1e3, 0.0], v: unit(dir(30.0, 0.0)), l: unit(dir(30.0, 180.0)), label: "long normal" },
            Geometry {
                n: [0.3, 2.0, -0.5],
                v: unit(dir(10.0, 45.0)),
                l: unit(dir(50.0, 200.0)),
                label: "non-unit normal",
            },
        ];
        // Grazing light and view at angles approaching 90° from both sides.
        for (k, eps) in [1e-7f64, 1e-5, 1e-3, -1e-7, -1e-5].into_iter().enumerate() {
            let t = 90.0 - eps.to_degrees();
            let labels = [
                "grazing light +1e-7",
                "grazing light +1e-5",
                "grazing light +1e-3",
                "grazing light −1e-7",
                "grazing light −1e-5",
            ];
            g.push(Geometry { n: y, v: unit(dir(20.0, 0.0)), l: unit(dir(t, 180.0)), label: labels[k] });
            let labels = [
                "grazing view +1e-7",
                "grazing view +1e-5",
                "grazing view +1e-3",
                "grazing view −1e-7",
                "grazing view −1e-5",
            ];
            g.push(Geometry { n: y, v: unit(dir(t, 0.0)), l: unit(dir(20.0, 180.0)), label: labels[k] });
            g.push(Geometry { n: y, v: unit(dir(t, 0.0)), l: unit(dir(t, 180.0)), label: "both grazing, mirror" });
        }
        // Exactly and nearly in the mirror direction.
        for theta in [0.5, 10.0, 45.0, 80.0, 89.9] {
            g.push(Geometry { n: y, v: unit(dir(theta, 0.0)), l: unit(dir(theta, 180.0)), label: "mirror direction" });
            for off in [1e-4, 1e-3, 0.08, 1.0] {
                g.push(Geometry {
                    n: y,
                    v: unit(dir(theta + off, 0.0)),
                    l: unit(dir(theta, 180.0)),
                    label: "near mirror direction",
                });
            }
        }
        // A deterministic spread over the sphere (normals tilted too).
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut rnd = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        while g.len() < 150 {
            let n = dir(rnd() * 60.0, rnd() * 360.0);
            let v = dir(rnd() * 180.0, rnd() * 360.0);
            let l = dir(rnd() * 180.0, rnd() * 360.0);
            g.push(Geometry { n: unit(n), v: unit(v), l: unit(l), label: "spread" });
        }
        SweepInputs {
            geometry: g,
            m: vec![0.0, 1e-6, 1e-3, 0.01, 0.05, 0.2, 0.5, 1.0],
            h: vec![
                (1.0, false),
                (2.0, false),
                (20.0, false),
                (1e3, false),
                (1e6, false),
                (1e9, false),
                (H_MAX as f32, true),
            ],
            mu: vec![[0.0; 3], [1e-6, 0.02, 0.04], [0.5; 3], [1.0, 0.766, 0.336], [1.0; 3]],
            d: vec![0.0, 1e-6, 1e-4, 0.01, 1.0, 100.0, 1e4],
            alpha: vec![(0.0, D0_MIN as f32), (1e-3, 0.01), (1.0, 1.0), (1e3, 10.0), (1e6, 1e3)],
        }
    }

    pub fn combinations(&self) -> usize {
        self.geometry.len() * self.m.len() * self.h.len() * self.mu.len() * self.d.len() * self.alpha.len()
    }

    /// The axes' indices of a combination (the kernel's decomposition).
    fn split(&self, idx: usize) -> [usize; 6] {
        let mut r = idx;
        let ai = r % self.alpha.len();
        r /= self.alpha.len();
        let di = r % self.d.len();
        r /= self.d.len();
        let ui = r % self.mu.len();
        r /= self.mu.len();
        let hi = r % self.h.len();
        r /= self.h.len();
        let mi = r % self.m.len();
        [r / self.m.len(), mi, hi, ui, di, ai]
    }

    /// A combination's inputs in words.
    pub fn describe(&self, idx: usize) -> String {
        let [gi, mi, hi, ui, di, ai] = self.split(idx);
        let g = &self.geometry[gi];
        let h = if self.h[hi].1 { "mirror".to_string() } else { format!("{:e}", self.h[hi].0) };
        format!(
            "{}: n={:?} v={:?} l={:?} m={:e} h={} μ={:?} d={:e} α={:e} d0={:e}",
            g.label, g.n, g.v, g.l, self.m[mi], h, self.mu[ui], self.d[di], self.alpha[ai].0, self.alpha[ai].1
        )
    }

    fn table(&self) -> Vec<[f32; 4]> {
        let mut t = Vec::new();
        for g in &self.geometry {
            for v in [g.n, g.v, g.l] {
                t.push([v[0], v[1], v[2], 0.0]);
            }
        }
        t.extend(self.m.iter().map(|&m| [m, 0.0, 0.0, 0.0]));
        t.extend(self.h.iter().map(|&(h, mirror)| [h, mirror as u32 as f32, 0.0, 0.0]));
        t.extend(self.mu.iter().map(|mu| [mu[0], mu[1], mu[2], 0.0]));
        t.extend(self.d.iter().map(|&d| [d, 0.0, 0.0, 0.0]));
        t.extend(self.alpha.iter().map(|&(a, d0)| [a, d0, 0.0, 0.0]));
        t
    }
}

/// The f64 reference of the kernel's outputs for one combination's inputs.
#[allow(clippy::too_many_arguments)]
/// `l_len` scales the light direction a point light's sample gives, and the spot cone's cosines
/// (1 for the exact model): the GPU's `to_light / d` is a unit vector, and its `cos` of a cone
/// angle exact, only to a few f32 ulps. (Near 1 an f32 cosine is good to 6e-8, so a cone under a
/// degree, where `1 − cos` is ~1e-4 or less, is decided by that rounding.)
fn reference(
    n_raw: DVec3,
    v: DVec3,
    l: DVec3,
    (m, h, mirror): (f64, f64, bool),
    mu: [f64; 3],
    (d, alpha, d0): (f64, f64, f64),
    l_len: f64,
) -> [f64; OUTPUTS] {
    let n = brdf::safe_normalize(n_raw, v);
    let half = brdf::safe_normalize(l + v, n);
    let r = 2.0 * n.dot(l) * n - l;
    let v_index = mu.map(brdf::fresnel_v_from_mu);
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
    let quadratic = brdf::light_sample(&light, DVec3::ZERO, n);
    light.falloff_form = FalloffForm::Linear;
    let linear = brdf::light_sample(&light, DVec3::ZERO, n);
    let (quadratic, linear) = ((quadratic.0 * l_len, quadratic.1), (linear.0 * l_len, linear.1));
    let mat = Material {
        color: SWEEP_COLOR,
        r_s: 1.0,
        r_d: 1.0,
        m,
        h: if mirror { PhongExponent::Mirror } else { PhongExponent::Finite(h) },
        mu,
        ..Material::default()
    };
    let f = v_index.map(|vi| brdf::f_fresnel_exact(v.dot(half), vi));
    let ct = brdf::specular_cook_torrance(n, v, l, m, v_index);
    let cp = brdf::light_contribution(quadratic.0, quadratic.1, n, v, &mat, v_index, SpecularModel::Phong);
    let cc = brdf::light_contribution(linear.0, linear.1, n, v, &mat, v_index, SpecularModel::CookTorrance);
    let outer = m * SWEEP_CONE_PER_M;
    let inner = outer * alpha.min(1.0);
    [
        brdf::diffuse_lambert(n.dot(l)),
        brdf::specular_phong(v.dot(r), h, mirror),
        brdf::d_beckmann(n.dot(half), n.cross(half).length_squared(), m),
        brdf::g_cook_torrance(n.dot(half), n.dot(v), n.dot(l), v.dot(half)),
        f[0],
        f[1],
        f[2],
        ct[0],
        ct[1],
        ct[2],
        brdf::falloff_quadratic(d, alpha),
        brdf::falloff_linear(d, d0),
        cp[0],
        cp[1],
        cp[2],
        cc[0],
        cc[1],
        cc[2],
        brdf::spot_cone(v.dot(l), inner.cos() * l_len, outer.cos() * l_len),
        brdf::window_range(d, d0),
    ]
}

/// One term of the report, over all its outputs (channels).
#[derive(Clone, Debug)]
pub struct TermReport {
    pub name: &'static str,
    /// Output columns of the kernel.
    pub columns: std::ops::Range<usize>,
    /// The largest value the guards allow.
    pub bound: f64,
    pub why_bound: &'static str,
    pub nonfinite: usize,
    pub negative: usize,
    pub over_bound: usize,
    pub max_value: f64,
    /// Largest relative error against f64 where well-conditioned, and where.
    pub max_rel_err: f64,
    pub worst: Option<usize>,
    /// Outputs with an error above `ERROR_CHECK_CONDITIONING` where the reference is
    /// ill-conditioned: not compared.
    pub ill_conditioned: usize,
}

pub struct SweepReport {
    pub inputs: SweepInputs,
    pub combinations: usize,
    pub terms: Vec<TermReport>,
    pub gpu_ms: f64,
}

impl SweepReport {
    pub fn nonfinite(&self) -> usize {
        self.terms.iter().map(|t| t.nonfinite).sum()
    }

    /// The report as a Markdown table.
    pub fn table(&self) -> String {
        let mut s = format!(
            "{} combinations ({} geometries × {} m × {} h × {} μ × {} d × {} α), {} non-finite outputs\n\n",
            self.combinations,
            self.inputs.geometry.len(),
            self.inputs.m.len(),
            self.inputs.h.len(),
            self.inputs.mu.len(),
            self.inputs.d.len(),
            self.inputs.alpha.len(),
            self.nonfinite()
        );
        s += "| term | non-finite | < 0 | > bound | max value | bound | max rel. error | not compared (ill-conditioned, error > 1e-5) | worst input |\n";
        s += "|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
        for t in &self.terms {
            s += &format!(
                "| `{}` | {} | {} | {} | {:.3e} | {:.3e} | {:.2e} | {} | {} |\n",
                t.name,
                t.nonfinite,
                t.negative,
                t.over_bound,
                t.max_value,
                t.bound,
                t.max_rel_err,
                t.ill_conditioned,
                t.worst.map(|i| self.inputs.describe(i)).unwrap_or_else(|| "—".into())
            );
        }
        s
    }
}

fn terms() -> Vec<TermReport> {
    let d_max = 1.0 / (4.0 * M_MIN * M_MIN);
    let t = |name, columns, bound, why_bound| TermReport {
        name,
        columns,
        bound,
        why_bound,
        nonfinite: 0,
        negative: 0,
        over_bound: 0,
        max_value: 0.0,
        max_rel_err: 0.0,
        worst: None,
        ill_conditioned: 0,
    };
    vec![
        t("diffuse_lambert", 0..1, 1.0, "N·L of unit vectors"),
        t("specular_phong", 1..2, 1.0, "(V·R)^h with V·R clamped to [0, 1]"),
        t("d_beckmann", 2..3, d_max, "peak 1/(4 m²) at m = M_MIN"),
        t("g_cook_torrance", 3..4, 1.0, "min{1, …}"),
        t("f_fresnel_exact", 4..7, 1.0, "a reflectance"),
        t("specular_cook_torrance", 7..10, d_max / N_DOT_V_MIN, "F·D·G/(N·V) ≤ 1 · 1/(4 M_MIN²) · 1 / N_DOT_V_MIN"),
        t("falloff_quadratic", 10..11, 1.0, "1/(1 + α d²), α ≥ 0"),
        t("falloff_linear", 11..12, 1.0 / D0_MIN, "1/(d + d0), d0 ≥ D0_MIN"),
        t("light_contribution (Phong)", 12..15, 0.8 + 1.0, "I_L (r_d C + r_s), falloff ≤ 1"),
        t(
            "light_contribution (Cook–Torrance, 1/(d+d0))",
            15..18,
            (0.8 + d_max / N_DOT_V_MIN) / D0_MIN,
            "(r_d C + r_s S_max) / D0_MIN",
        ),
        t("spot_cone", 18..19, 1.0, "a ramp clamped to [0, 1], squared"),
        t("window_range", 19..20, 1.0, "1 − x⁴, x clamped to [0, 1]"),
    ]
}

/// Slack on the bounds for f32 rounding of the value itself.
const BOUND_SLACK: f64 = 1.0 + 1e-5;

/// Run the sweep on the GPU and compare with the f64 reference.
pub fn run(gpu: &Gpu, inputs: SweepInputs) -> SweepReport {
    let total = inputs.combinations();
    let gpu_start = std::time::Instant::now();
    let out = dispatch(gpu, &inputs, total);
    let gpu_ms = gpu_start.elapsed().as_secs_f64() * 1e3;
    let mut terms = terms();
    let f64v = |a: [f32; 3]| DVec3::new(a[0] as f64, a[1] as f64, a[2] as f64);
    for idx in 0..total {
        let [gi, mi, hi, ui, di, ai] = inputs.split(idx);
        let g = &inputs.geometry[gi];
        let (n, v, l) = (f64v(g.n), f64v(g.v), f64v(g.l));
        let (m, (h, mirror), mu) = (inputs.m[mi] as f64, inputs.h[hi], inputs.mu[ui].map(|x| x as f64));
        let (d, (alpha, d0)) = (inputs.d[di] as f64, inputs.alpha[ai]);
        let (h, alpha, d0) = (h as f64, alpha as f64, d0 as f64);
        let expected = reference(n, v, l, (m, h, mirror), mu, (d, alpha, d0), 1.0);
        let gpu_out = &out[idx * OUTPUTS..(idx + 1) * OUTPUTS];
        let mut perturbed: Option<[[f64; OUTPUTS]; 8]> = None;
        let near_switch = {
            let nn = brdf::safe_normalize(n, v);
            let r = 2.0 * nn.dot(l) * nn - l;
            nn.dot(l).abs() < SWITCH_MARGIN
                || nn.dot(v).abs() < SWITCH_MARGIN
                || (mirror && (v.dot(r) - MIRROR_V_DOT_R_MIN).abs() < SWITCH_MARGIN)
        };
        for t in terms.iter_mut() {
            for c in t.columns.clone() {
                let (gv, rv) = (gpu_out[c] as f64, expected[c]);
                if !gv.is_finite() {
                    t.nonfinite += 1;
                    continue;
                }
                if gv < 0.0 {
                    t.negative += 1;
                }
                if gv > t.bound * BOUND_SLACK {
                    t.over_bound += 1;
                }
                t.max_value = t.max_value.max(gv);
                let err = (gv - rv).abs() / rv.abs().max(ERROR_ABS_FLOOR);
                if err <= ERROR_CHECK_CONDITIONING {
                    if err > t.max_rel_err {
                        t.max_rel_err = err;
                        t.worst = Some(idx);
                    }
                    continue;
                }
                if near_switch {
                    t.ill_conditioned += 1;
                    continue;
                }
                let p = perturbed.get_or_insert_with(|| {
                    // Rotate each vector by INPUT_PERTURBATION radians about two axes perpendicular
                    // to it, and scale its components by 1 ± INPUT_PERTURBATION (the rounding a
                    // position gets per component), both ways; scale the scalars and the length
                    // of the sampled light direction alike.
                    let (pn, pv, pl) = (perpendiculars(n), perpendiculars(v), perpendiculars(l));
                    let patterns = [DVec3::new(1.0, -1.0, 1.0), DVec3::new(-1.0, 1.0, 1.0)];
                    std::array::from_fn(|j| {
                        let k = if j % 2 == 0 { INPUT_PERTURBATION } else { -INPUT_PERTURBATION };
                        let (dn, dv, dl) = match j / 2 {
                            a @ 0..=1 => (pn[a] * k * n.length(), pv[a] * k, pl[a] * k),
                            a => {
                                let s = patterns[a - 2] * k;
                                (n * s, v * s, l * -s)
                            }
                        };
                        reference(
                            n + dn,
                            (v + dv).normalize(),
                            (l + dl).normalize(),
                            (m * (1.0 + k), if mirror { h } else { h * (1.0 + k) }, mirror),
                            mu.map(|x| x * (1.0 + k)),
                            (d * (1.0 + k) + k.abs(), alpha * (1.0 + k), d0 * (1.0 + k)),
                            1.0 + k,
                        )
                    })
                });
                let change = p.iter().map(|q| (q[c] - rv).abs() / rv.abs().max(ERROR_ABS_FLOOR)).fold(0.0, f64::max);
                if change > WELL_CONDITIONED_CHANGE {
                    t.ill_conditioned += 1;
                    continue;
                }
                if err > t.max_rel_err {
                    t.max_rel_err = err;
                    t.worst = Some(idx);
                }
            }
        }
    }
    SweepReport { inputs, combinations: total, terms, gpu_ms }
}

/// Two unit vectors perpendicular to `v` and to each other (any two, for a zero `v`).
fn perpendiculars(v: DVec3) -> [DVec3; 2] {
    let u = v.normalize_or(DVec3::Y);
    let axis = if u.x.abs() < 0.5 { DVec3::X } else { DVec3::Z };
    let p1 = u.cross(axis).normalize();
    [p1, u.cross(p1)]
}

fn dispatch(gpu: &Gpu, inputs: &SweepInputs, total: usize) -> Vec<f32> {
    let device = &gpu.device;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("sweep"),
        source: wgpu::ShaderSource::Wgsl(shaders::sweep_source().into()),
    });
    let counts: [u32; 8] = [
        inputs.geometry.len() as u32,
        inputs.m.len() as u32,
        inputs.h.len() as u32,
        inputs.mu.len() as u32,
        inputs.d.len() as u32,
        inputs.alpha.len() as u32,
        total as u32,
        (inputs.geometry.len() * 3) as u32,
    ];
    let counts_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("sweep counts"),
        contents: bytemuck::cast_slice(&counts),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let table_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("sweep table"),
        contents: bytemuck::cast_slice(&inputs.table()),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let out_size = (total * OUTPUTS * 4) as u64;
    let out_buf = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("sweep outputs"),
        size: out_size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let read_buf = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("sweep readback"),
        size: out_size,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("sweep"),
        layout: None,
        module: &module,
        entry_point: Some("sweep"),
        compilation_options: Default::default(),
        cache: None,
    });
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("sweep"),
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: counts_buf.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 1, resource: table_buf.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 2, resource: out_buf.as_entire_binding() },
        ],
    });
    let groups = total.div_ceil(64) as u32;
    let max = device.limits().max_compute_workgroups_per_dimension;
    let (gx, gy) = if groups <= max { (groups, 1) } else { (max, groups.div_ceil(max)) };
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
    }
    enc.copy_buffer_to_buffer(&out_buf, 0, &read_buf, 0, out_size);
    gpu.queue.submit([enc.finish()]);
    let slice = read_buf.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("map sweep outputs"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    let data = slice.get_mapped_range().expect("mapped").to_vec();
    read_buf.unmap();
    bytemuck::cast_slice(&data).to_vec()
}
