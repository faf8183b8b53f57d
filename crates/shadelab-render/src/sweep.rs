//! The stability sweep: every lighting term of the shipped WGSL, evaluated on the GPU over more
//! than 10⁶ combinations of hard inputs, checked against the f64 reference.
//!
//! For every combination it asserts (in the tests) and reports (in `shadelab sweep`): the output
//! is finite and ≥ 0; it is at most the term's bound, which the guards imply; and where the f64
//! reference is well-conditioned, the GPU is within `ERROR_TOLERANCE` of it.

//!
//! The kernel's output columns are declared once in [`columns`]; the inputs, the GPU pass and the
//! report have their own files under `sweep/`. The environment's functions, which read the
//! globals and the environment's buffers, have their own kernel and cases ([`environment`]).

mod columns;
mod dispatch;
mod env_inputs;
pub mod environment;
mod inputs;
mod report;

pub use columns::{COLUMNS, Column, OUTPUTS, wgsl_columns};
pub use dispatch::{SWEEP_KERNEL, sweep_source};
pub use env_inputs::{EnvCase, EnvSweepInputs};
pub use inputs::{Geometry, ShadowCase, SweepInputs};
pub use report::{SweepReport, TermReport};

use crate::gpu::Gpu;
use columns::reference;
use glam::DVec3;
use shadelab_model::guards::MIRROR_V_DOT_R_MIN;
use shadelab_model::lighting::common::safe_normalize;

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

/// Slack on the bounds for f32 rounding of the value itself.
const BOUND_SLACK: f64 = 1.0 + 1e-5;

/// Run the sweep on the GPU and compare with the f64 reference.
pub fn run(gpu: &Gpu, inputs: SweepInputs) -> SweepReport {
    let total = inputs.combinations();
    let gpu_start = std::time::Instant::now();
    let out = dispatch::dispatch(gpu, &inputs, total);
    let gpu_ms = gpu_start.elapsed().as_secs_f64() * 1e3;
    let mut terms = report::terms();
    let f64v = |a: [f32; 3]| DVec3::new(a[0] as f64, a[1] as f64, a[2] as f64);
    for idx in 0..total {
        let [gi, mi, hi, ui, di, ai] = inputs.split(idx);
        let g = &inputs.geometry[gi];
        let (n, v, l) = (f64v(g.n), f64v(g.v), f64v(g.l));
        let (m, (h, mirror), mu) = (inputs.m[mi] as f64, inputs.h[hi], inputs.mu[ui].map(|x| x as f64));
        let (d, (alpha, d0)) = (inputs.d[di] as f64, inputs.alpha[ai]);
        let (h, alpha, d0) = (h as f64, alpha as f64, d0 as f64);
        let shadow = inputs.shadow_case(gi, mi);
        let expected = reference(n, v, l, (m, h, mirror), mu, (d, alpha, d0), 1.0, shadow);
        let gpu_out = &out[idx * OUTPUTS..(idx + 1) * OUTPUTS];
        let mut perturbed: Option<[[f64; OUTPUTS]; 8]> = None;
        let near_switch = is_near_switch(n, v, l, mirror);
        for t in terms.iter_mut() {
            for c in t.columns.clone() {
                let rv = expected[c];
                t.judge(idx, gpu_out[c] as f64, rv, 1.0, |floor| {
                    (!near_switch).then(|| {
                        let p = perturbed.get_or_insert_with(|| {
                            perturbed_references(n, v, l, (m, h, mirror), mu, (d, alpha, d0), shadow)
                        });
                        p.iter().map(|q| (q[c] - rv).abs() / rv.abs().max(floor)).fold(0.0, f64::max)
                    })
                });
            }
        }
    }
    SweepReport { inputs, combinations: total, terms, gpu_ms }
}

impl TermReport {
    /// Count one output into the row: `gv` the GPU's value, `rv` its f64 twin's, `scale` what the
    /// bound, the reported value and the error's floor are measured in (1 for the terms).
    /// `change(floor)` is the twin's largest relative change under the input perturbations, asked
    /// only where the error needs it; `None` near a switch of the model. Returns whether this
    /// output became the row's worst.
    fn judge(&mut self, idx: usize, gv: f64, rv: f64, scale: f64, change: impl FnOnce(f64) -> Option<f64>) -> bool {
        if !gv.is_finite() {
            self.nonfinite += 1;
            return false;
        }
        if gv < 0.0 && !self.signed {
            self.negative += 1;
        }
        if gv > self.bound * scale * BOUND_SLACK {
            self.over_bound += 1;
        }
        self.max_value = self.max_value.max(gv / scale);
        let floor = ERROR_ABS_FLOOR * scale;
        let err = (gv - rv).abs() / rv.abs().max(floor);
        if err > ERROR_CHECK_CONDITIONING && change(floor).is_none_or(|c| c > WELL_CONDITIONED_CHANGE) {
            self.ill_conditioned += 1;
            return false;
        }
        if err > self.max_rel_err {
            self.max_rel_err = err;
            self.worst = Some(idx);
            return true;
        }
        false
    }
}

/// Whether the inputs are within `SWITCH_MARGIN` of a switch (N·L = 0, N·V = 0, the mirror threshold).
fn is_near_switch(n: DVec3, v: DVec3, l: DVec3, mirror: bool) -> bool {
    let nn = safe_normalize(n, v);
    let r = 2.0 * nn.dot(l) * nn - l;
    nn.dot(l).abs() < SWITCH_MARGIN
        || nn.dot(v).abs() < SWITCH_MARGIN
        || (mirror && (v.dot(r) - MIRROR_V_DOT_R_MIN).abs() < SWITCH_MARGIN)
}

/// The f64 reference at the eight perturbations of a combination's inputs, for its conditioning.
fn perturbed_references(
    n: DVec3,
    v: DVec3,
    l: DVec3,
    (m, h, mirror): (f64, f64, bool),
    mu: [f64; 3],
    (d, alpha, d0): (f64, f64, f64),
    shadow: &ShadowCase,
) -> [[f64; OUTPUTS]; 8] {
    std::array::from_fn(|j| {
        let (k, [dn, dv, dl]) = perturbation(j, [n, v, l]);
        reference(
            n + dn,
            (v + dv).normalize(),
            (l + dl).normalize(),
            (m * (1.0 + k), if mirror { h } else { h * (1.0 + k) }, mirror),
            mu.map(|x| x * (1.0 + k)),
            (d * (1.0 + k) + k.abs(), alpha * (1.0 + k), d0 * (1.0 + k)),
            1.0 + k,
            shadow,
        )
    })
}

/// Perturbation `j` of eight of the vectors `[a, b, c]`: `(k, their changes)` with `k` =
/// ±`INPUT_PERTURBATION`. Pairs 0 and 1 turn each vector by `k` radians about one of two axes
/// perpendicular to it; pairs 2 and 3 scale its components by 1 ± k (the rounding a position gets
/// per component), the third the other way. The caller scales its scalars by 1 + k alike.
fn perturbation(j: usize, vectors: [DVec3; 3]) -> (f64, [DVec3; 3]) {
    let k = if j % 2 == 0 { INPUT_PERTURBATION } else { -INPUT_PERTURBATION };
    let patterns = [DVec3::new(1.0, -1.0, 1.0), DVec3::new(-1.0, 1.0, 1.0)];
    let deltas = match j / 2 {
        a @ 0..=1 => vectors.map(|x| perpendiculars(x)[a] * k * x.length()),
        a => {
            let s = patterns[a - 2] * k;
            [vectors[0] * s, vectors[1] * s, vectors[2] * -s]
        }
    };
    (k, deltas)
}

/// Two unit vectors perpendicular to `v` and to each other (any two, for a zero `v`).
fn perpendiculars(v: DVec3) -> [DVec3; 2] {
    let u = v.normalize_or(DVec3::Y);
    let axis = if u.x.abs() < 0.5 { DVec3::X } else { DVec3::Z };
    let p1 = u.cross(axis).normalize();
    [p1, u.cross(p1)]
}
