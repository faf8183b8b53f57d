//! The environment's sweep: the GPU functions of `environment.wgsl` and `occlusion.wgsl` (the SH
//! diffuse, level 0 as the background reads it, the prefiltered lookup, the split sum's B and its
//! whole specular, the occlusion grid's lookup), over hard environments and grids, each against
//! its f64 twin, with the main sweep's checks (docs/stability.md). Values are measured in the
//! environment's own scale (its largest radiance), so one bound and one error floor hold for a
//! black map and a texel of 10⁶ alike.

use super::SWITCH_MARGIN;
use super::columns::{AREA_TERM_ROUNDING, Column, offset_in, outputs_of, ranges_of};
use super::env_inputs::{EnvCase, EnvSweepInputs, grid_centre};
use super::report::TermReport;
use crate::gpu::Gpu;
use glam::DVec3;
use shadelab_model::lighting::area::{AreaLight, AreaShape};
use shadelab_model::lighting::environment::{self as env, SH_RINGING_BOUND, ShCoefficients};
use shadelab_model::lighting::microfacet::{Distribution, Masking, Microfacet, fresnel_v_from_mu};
use shadelab_model::lighting::ms_table::MS_PAIRS;
use shadelab_model::lighting::{common::safe_normalize, ltc, occlusion};
use shadelab_model::params::NamedValue;
use wgpu::util::DeviceExt;

/// The scale a column's values and bound are measured in.
#[derive(Clone, Copy)]
enum Scale {
    /// The largest radiance of the cells the SH terms are projected from.
    ShRadiance,
    /// The largest texel of the prefiltered levels.
    Levels,
    /// A share: 1.
    One,
}

const fn col(name: &'static str, wgsl: &'static str, channels: usize, bound: f64, why_bound: &'static str) -> Column {
    Column { name, wgsl, channels, bound, why_bound, signed: false }
}

/// The kernel's output columns, their bounds in the scale of [`ENV_SCALES`].
const ENV_COLUMNS: [Column; 7] = [
    col(
        "env_sh_radiance",
        "SH_RADIANCE",
        3,
        SH_RINGING_BOUND,
        "the nine terms' overshoot SH_RINGING_BOUND × the largest radiance",
    ),
    col(
        "env_level_sample (level 0 along −V, the background's lookup)",
        "LEVEL_SAMPLE",
        3,
        1.0,
        "bilinear: at most the largest texel",
    ),
    col(
        "env_prefiltered (toward N's mirror of V, at m)",
        "PREFILTERED",
        3,
        1.0,
        "a blend of bilinear lookups: at most the largest texel",
    ),
    col("env_split_b (every D × G pair)", "SPLIT_B", MS_PAIRS, 1.0, "a share of the lobe's albedo, at most 1"),
    col(
        "env_specular (the chapter's terms, glTF's)",
        "SPECULAR",
        6,
        1.0,
        "the largest texel times F0·(E − B) + B ≤ max(E, B) ≤ 1",
    ),
    col("env_occlusion (at the grid's centre + l·d)", "OCCLUSION", 1, 1.0, "an open share"),
    col(
        "area_specular_ltc (rect, disk, sphere at l·d × every D, over π·E·d²/A)",
        "AREA_LTC",
        3 * Distribution::ALL.len(),
        1.0,
        "the LTC's mass over the light, at most all of it",
    ),
];

/// Each column's scale, in the order of [`ENV_COLUMNS`].
const ENV_SCALES: [Scale; 7] =
    [Scale::ShRadiance, Scale::Levels, Scale::Levels, Scale::One, Scale::Levels, Scale::One, Scale::One];

/// Floats the kernel writes per combination.
pub const ENV_OUTPUTS: usize = outputs_of(&ENV_COLUMNS);

const SH_RADIANCE: usize = offset_in(&ENV_COLUMNS, "SH_RADIANCE");
const LEVEL_SAMPLE: usize = offset_in(&ENV_COLUMNS, "LEVEL_SAMPLE");
const PREFILTERED: usize = offset_in(&ENV_COLUMNS, "PREFILTERED");
const SPLIT_B: usize = offset_in(&ENV_COLUMNS, "SPLIT_B");
const SPECULAR: usize = offset_in(&ENV_COLUMNS, "SPECULAR");
const OCCLUSION: usize = offset_in(&ENV_COLUMNS, "OCCLUSION");
const AREA_LTC: usize = offset_in(&ENV_COLUMNS, "AREA_LTC");

/// The environment sweep's kernel (`shaders/sweep_environment.wgsl`).
pub const ENV_SWEEP_KERNEL: &str = include_str!("../../../../shaders/sweep_environment.wgsl");

/// The environment sweep's compute module: the terms, globals and bindings through the
/// environment's functions as shipped, the generated columns, then the kernel.
pub fn env_sweep_source() -> String {
    format!("{}\n{}\n{}", crate::shaders::environment_terms_source(), wgsl_env_columns(), ENV_SWEEP_KERNEL)
}

/// The kernel's `ENV_SWEEP_OUTPUTS` and `ENV_COL_…` constants.
fn wgsl_env_columns() -> String {
    let mut s = String::from("// Generated from crates/shadelab-render/src/sweep/environment.rs.\n");
    s += &format!("const ENV_SWEEP_OUTPUTS: u32 = {ENV_OUTPUTS}u;\n");
    for (c, r) in ranges_of(&ENV_COLUMNS) {
        s += &format!("const ENV_COL_{}: u32 = {}u;\n", c.wgsl, r.start);
    }
    s
}

/// One case made ready as the renderer makes it: the levels and SH terms the GPU reads (the SH
/// rounded to f32 as the uniforms hold them), the grid, and the scales of its values.
struct Prepared<'a> {
    case: &'a EnvCase,
    pre: Vec<[f32; 4]>,
    sh: ShCoefficients,
    centre: [f32; 3],
    sh_max: f64,
    levels_max: f64,
}

impl<'a> Prepared<'a> {
    fn new(case: &'a EnvCase) -> Prepared<'a> {
        let pre = case.env.prefiltered(&case.lights);
        let sh = case.env.sh(&case.lights).map(|c| c.map(|x| x as f32 as f64));
        let levels_max = pre.iter().flat_map(|t| &t[..3]).fold(0.0, |a: f64, &x| a.max(x as f64));
        let sh_max = case.env.sh_radiance_max(&case.lights);
        Prepared { case, pre, sh, centre: grid_centre(&case.grid), sh_max, levels_max }
    }

    /// The scale a column's values are measured in (1 where the environment is black).
    fn scale(&self, s: Scale) -> f64 {
        let x = match s {
            Scale::ShRadiance => self.sh_max,
            Scale::Levels => self.levels_max,
            Scale::One => 1.0,
        };
        if x > 0.0 { x } else { 1.0 }
    }

    /// The occlusion column's point for direction `l` and distance `d`, as the kernel forms it.
    fn point(&self, l: DVec3, d: f64) -> DVec3 {
        DVec3::from_array(self.centre.map(f64::from)) + l * d
    }

    /// The f64 twins at one combination, in the kernel's column order; `p` the occlusion's point,
    /// `k` the inputs' perturbation (0 unperturbed), which the LTC's summed terms are rounded by.
    fn reference(&self, n_raw: DVec3, v: DVec3, m: f64, mu: [f64; 3], p: DVec3, k: f64) -> [f64; ENV_OUTPUTS] {
        let n = safe_normalize(n_raw, v);
        let v_index = mu.map(fresnel_v_from_mu);
        let mut out = [0.0; ENV_OUTPUTS];
        let mut put = |at: usize, c: &[f64]| out[at..at + c.len()].copy_from_slice(c);
        put(SH_RADIANCE, &env::env_sh_radiance(&self.sh, n));
        put(LEVEL_SAMPLE, &env::env_level_sample(&self.pre, 0, -v));
        let r = safe_normalize(n * (2.0 * n.dot(v)) - v, n);
        put(PREFILTERED, &env::env_prefiltered(&self.pre, r, m));
        let pairs: Vec<f64> = pairs().map(|terms| env::env_split_b(terms, n.dot(v), m)).collect();
        put(SPLIT_B, &pairs);
        put(SPECULAR, &env::env_specular(&self.pre, n, v, m, Microfacet::CHAPTER, v_index));
        put(SPECULAR + 3, &env::env_specular(&self.pre, n, v, m, Microfacet::GLTF, v_index));
        put(OCCLUSION, &[occlusion::env_occlusion(&self.case.grid, p, n)]);
        let to = p - DVec3::from_array(self.centre.map(f64::from));
        put(AREA_LTC, &area_ltc(n, v, to, m, k));
        out
    }
}

/// The kernel's `env_area_ltc`: for each shape at `to` from the point, facing it, half as wide as
/// far, and every D, its LTC's share of `π·E·d²/A_emit` (E = 1); 0 at the point limit. Under a
/// perturbation `k` each share moves by its summed terms' size times `k` times
/// `AREA_TERM_ROUNDING`, as the main sweep's area form does, so that a share f32 cancels to
/// nothing counts as ill-conditioned.
fn area_ltc(n: DVec3, v: DVec3, to: DVec3, m: f64, k: f64) -> Vec<f64> {
    let d = to.length();
    let normal = -safe_normalize(to, n);
    let half = 0.5 * d;
    let shapes = [
        AreaShape::Rect { half_x: half, half_y: half },
        AreaShape::Disk { radius: half },
        AreaShape::Sphere { radius: half },
    ];
    let mut out = Vec::new();
    for shape in shapes {
        let light = AreaLight { shape, center: to, normal, tangent: ltc::any_tangent(normal) };
        for dk in 0..Distribution::ALL.len() {
            let minv = ltc::ltc_matrix(dk as u32, n.dot(v), m);
            let s = ltc::area_specular_ltc(&light, DVec3::ZERO, n, v, minv, 1.0).unwrap_or(0.0);
            let share = if s > 0.0 { s * light.emitting_area() / (std::f64::consts::PI * d * d) } else { 0.0 };
            let rounding = ltc::ltc_rounding(&light, DVec3::ZERO, n, v, minv) * k.abs() * AREA_TERM_ROUNDING;
            out.push(share + rounding);
        }
    }
    out
}

/// Every D × G pair in the tables' order (d·3 + g), as the kernel loops over them.
fn pairs() -> impl Iterator<Item = Microfacet> {
    Distribution::ALL
        .iter()
        .flat_map(|&(_, d)| Masking::ALL.iter().map(move |&(_, g)| Microfacet { d, g, ..Microfacet::CHAPTER }))
}

/// The environment sweep's report: a row per column over every case.
pub struct EnvSweepReport {
    pub inputs: EnvSweepInputs,
    pub terms: Vec<TermReport>,
    pub gpu_ms: f64,
    /// The case of each row's worst combination.
    worst_case: Vec<usize>,
}

impl EnvSweepReport {
    /// The report as a Markdown table.
    pub fn table(&self) -> String {
        let i = &self.inputs;
        let mut s = format!(
            "{} environments × {} combinations ({} geometries × {} m × {} μ × {} d)\n\n",
            i.cases.len(),
            i.combinations(),
            i.geometry.len(),
            i.m.len(),
            i.mu.len(),
            i.d.len()
        );
        s += &super::report::table_head("max value / scale", "bound / scale");
        for (t, &case) in self.terms.iter().zip(&self.worst_case) {
            s += &t.row(t.worst.map(|w| i.describe(case, w)));
        }
        s
    }
}

/// Run the environment sweep on the GPU, case by case, and compare with the f64 twins.
pub fn run(gpu: &Gpu, inputs: EnvSweepInputs) -> EnvSweepReport {
    let mut terms: Vec<TermReport> =
        ranges_of(&ENV_COLUMNS).map(|(c, r)| TermReport::new(c.name, r, c.bound, c.why_bound, c.signed)).collect();
    let mut worst_case = vec![0; terms.len()];
    let kernel = Kernel::new(gpu, &inputs);
    let mut gpu_ms = 0.0;
    for (ci, case) in inputs.cases.iter().enumerate() {
        let prep = Prepared::new(case);
        let start = std::time::Instant::now();
        let out = kernel.dispatch(gpu, &prep, &inputs);
        gpu_ms += start.elapsed().as_secs_f64() * 1e3;
        check_case(&inputs, &prep, &out, &mut terms, |t| worst_case[t] = ci);
    }
    EnvSweepReport { inputs, terms, gpu_ms, worst_case }
}

/// Count one case's outputs into `terms`; `on_worst(t)` is told when term t's worst moves here.
fn check_case(
    inputs: &EnvSweepInputs,
    prep: &Prepared,
    out: &[f32],
    terms: &mut [TermReport],
    mut on_worst: impl FnMut(usize),
) {
    let f64v = |a: [f32; 3]| DVec3::new(a[0] as f64, a[1] as f64, a[2] as f64);
    let scales = ENV_SCALES.map(|s| prep.scale(s));
    for idx in 0..inputs.combinations() {
        let [gi, mi, ui, di] = inputs.split(idx);
        let g = &inputs.geometry[gi];
        let (n, v, l) = (f64v(g.n), f64v(g.v), f64v(g.l));
        let (m, mu, d) = (inputs.m[mi] as f64, inputs.mu[ui].map(f64::from), inputs.d[di] as f64);
        let p = prep.point(l, d);
        let expected = prep.reference(n, v, m, mu, p, 0.0);
        let gpu_out = &out[idx * ENV_OUTPUTS..(idx + 1) * ENV_OUTPUTS];
        let near_switch = safe_normalize(n, v).dot(v).abs() < SWITCH_MARGIN;
        let mut perturbed: Option<[[f64; ENV_OUTPUTS]; 8]> = None;
        for (ti, t) in terms.iter_mut().enumerate() {
            for c in t.columns.clone() {
                let rv = expected[c];
                let worst = t.judge(idx, gpu_out[c] as f64, rv, scales[ti], |floor| {
                    (!near_switch).then(|| {
                        let q = perturbed.get_or_insert_with(|| perturbed_references(prep, n, v, m, mu, p));
                        q.iter().map(|q| (q[c] - rv).abs() / rv.abs().max(floor)).fold(0.0, f64::max)
                    })
                });
                if worst {
                    on_worst(ti);
                }
            }
        }
    }
}

/// The f64 twins at the eight perturbations of a combination's inputs, the main sweep's
/// ([`super::perturbation`]): the occlusion's point is perturbed as a position, relative to its
/// size.
fn perturbed_references(
    prep: &Prepared,
    n: DVec3,
    v: DVec3,
    m: f64,
    mu: [f64; 3],
    p: DVec3,
) -> [[f64; ENV_OUTPUTS]; 8] {
    std::array::from_fn(|j| {
        let (k, [dn, dv, dp]) = super::perturbation(j, [n, v, p]);
        let mu = mu.map(|x| x * (1.0 + k));
        prep.reference(n + dn, (v + dv).normalize(), m * (1.0 + k), mu, p + dp, k)
    })
}

/// The kernel's pipeline and the buffers every case shares.
struct Kernel {
    pipeline: wgpu::ComputePipeline,
    table: wgpu::Buffer,
}

impl Kernel {
    fn new(gpu: &Gpu, inputs: &EnvSweepInputs) -> Kernel {
        let device = &gpu.device;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("environment sweep"),
            source: wgpu::ShaderSource::Wgsl(env_sweep_source().into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("environment sweep"),
            layout: None,
            module: &module,
            entry_point: Some("sweep_environment"),
            compilation_options: Default::default(),
            cache: None,
        });
        let table = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("environment sweep table"),
            contents: bytemuck::cast_slice(&inputs.table()),
            usage: wgpu::BufferUsages::STORAGE,
        });
        Kernel { pipeline, table }
    }

    /// One case's outputs: its globals, levels and grid written as the renderer writes them.
    fn dispatch(&self, gpu: &Gpu, prep: &Prepared, inputs: &EnvSweepInputs) -> Vec<f32> {
        let device = &gpu.device;
        let init = |label, contents: &[u8], usage| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        let globals =
            init("environment sweep globals", bytemuck::bytes_of(&globals(prep)), wgpu::BufferUsages::UNIFORM);
        let tables = crate::uniforms::TablesUniform::new();
        let tables = init("environment sweep tables", bytemuck::bytes_of(&tables), wgpu::BufferUsages::UNIFORM);
        let levels = init("environment sweep levels", bytemuck::cast_slice(&prep.pre), wgpu::BufferUsages::STORAGE);
        let nodes = prep.case.grid.gpu_words();
        let nodes = init("environment sweep grid", bytemuck::cast_slice(&nodes), wgpu::BufferUsages::STORAGE);
        let total = inputs.combinations();
        let len = |x: usize| x as u32;
        let c = prep.centre.map(f32::to_bits);
        let counts: [u32; 12] = [
            len(inputs.geometry.len()),
            len(inputs.m.len()),
            len(inputs.mu.len()),
            len(inputs.d.len()),
            len(total),
            0,
            0,
            0,
            c[0],
            c[1],
            c[2],
            0,
        ];
        let counts = init("environment sweep counts", bytemuck::cast_slice(&counts), wgpu::BufferUsages::UNIFORM);
        let size = (total * ENV_OUTPUTS * 4) as u64;
        let buffer = |label, usage| {
            device.create_buffer(&wgpu::BufferDescriptor { label: Some(label), size, usage, mapped_at_creation: false })
        };
        let out = buffer("environment sweep outputs", wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC);
        let read = buffer("environment sweep readback", wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ);
        let group = |index, entries: &[(u32, &wgpu::Buffer)]| {
            let entries: Vec<_> = entries
                .iter()
                .map(|&(binding, b)| wgpu::BindGroupEntry { binding, resource: b.as_entire_binding() })
                .collect();
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("environment sweep"),
                layout: &self.pipeline.get_bind_group_layout(index),
                entries: &entries,
            })
        };
        let environment = group(0, &[(0, &globals), (1, &levels), (2, &nodes), (3, &tables)]);
        let own = group(1, &[(11, &counts), (12, &self.table), (13, &out)]);
        let mut enc = device.create_command_encoder(&Default::default());
        {
            let mut pass = enc.begin_compute_pass(&Default::default());
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &environment, &[]);
            pass.set_bind_group(1, &own, &[]);
            pass.dispatch_workgroups(total.div_ceil(64) as u32, 1, 1);
        }
        enc.copy_buffer_to_buffer(&out, 0, &read, 0, size);
        gpu.queue.submit([enc.finish()]);
        super::dispatch::read_back(device, &read)
    }
}

/// The globals as the frame writes them for a scene with this environment and grid: its SH
/// terms and the grid's placement; nothing else is read (the tables are bound beside them).
fn globals(prep: &Prepared) -> crate::uniforms::GlobalsUniform {
    use bytemuck::Zeroable;
    let mut g = crate::uniforms::GlobalsUniform::zeroed();
    g.env_sh = prep.sh.map(|c| [c[0] as f32, c[1] as f32, c[2] as f32, 0.0]);
    g.env_occlusion = prep.case.grid.gpu_placement();
    g
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The columns lie one after another in the kernel's order, and the last ends at
    /// `ENV_OUTPUTS`, the kernel's stride.
    #[test]
    fn the_columns_are_where_both_sides_write_them() {
        let at: Vec<(&str, usize)> = ranges_of(&ENV_COLUMNS).map(|(c, r)| (c.wgsl, r.start)).collect();
        let written = [
            ("SH_RADIANCE", 0),
            ("LEVEL_SAMPLE", 3),
            ("PREFILTERED", 6),
            ("SPLIT_B", 9),
            ("SPECULAR", 9 + MS_PAIRS),
            ("OCCLUSION", 15 + MS_PAIRS),
            ("AREA_LTC", 16 + MS_PAIRS),
        ];
        assert_eq!(at, written);
        assert_eq!(ENV_OUTPUTS, 16 + MS_PAIRS + 3 * Distribution::ALL.len());
        // One B column per pair of the term tables.
        assert_eq!(pairs().count(), Distribution::ALL.len() * Masking::ALL.len());
        assert_eq!(pairs().count(), MS_PAIRS);
    }
}
