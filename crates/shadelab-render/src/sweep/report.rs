//! The sweep's report: one row per column of the kernel ([`super::columns::COLUMNS`]), its
//! counts and largest error, and the Markdown table `shadelab sweep` prints.

use super::columns::ranges;
use super::inputs::SweepInputs;

/// One term of the report, over all its outputs (channels).
#[derive(Clone, Debug)]
pub struct TermReport {
    pub name: &'static str,
    /// Output columns of the kernel.
    pub columns: std::ops::Range<usize>,
    /// The largest value the guards allow.
    pub bound: f64,
    pub why_bound: &'static str,
    /// Negative values are legitimate (not counted in `negative`).
    pub signed: bool,
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
        s += &table_head("max value", "bound");
        for t in &self.terms {
            s += &t.row(t.worst.map(|i| self.inputs.describe(i)));
        }
        s
    }
}

/// The table's head: its columns, with the names of the value's and the bound's.
pub(super) fn table_head(value: &str, bound: &str) -> String {
    format!(
        "| term | non-finite | < 0 | > bound | {value} | {bound} | max rel. error | not compared (ill-conditioned, error > 1e-5) | worst input |\n|---|---:|---:|---:|---:|---:|---:|---:|---|\n"
    )
}

impl TermReport {
    /// A row with nothing counted yet.
    pub(super) fn new(
        name: &'static str,
        columns: std::ops::Range<usize>,
        bound: f64,
        why_bound: &'static str,
        signed: bool,
    ) -> Self {
        TermReport {
            name,
            columns,
            bound,
            why_bound,
            signed,
            nonfinite: 0,
            negative: 0,
            over_bound: 0,
            max_value: 0.0,
            max_rel_err: 0.0,
            worst: None,
            ill_conditioned: 0,
        }
    }

    /// The row in the table, its worst input in words.
    pub(super) fn row(&self, worst: Option<String>) -> String {
        format!(
            "| `{}` | {} | {} | {} | {:.3e} | {:.3e} | {:.2e} | {} | {} |\n",
            self.name,
            self.nonfinite,
            self.negative,
            self.over_bound,
            self.max_value,
            self.bound,
            self.max_rel_err,
            self.ill_conditioned,
            worst.unwrap_or_else(|| "—".into())
        )
    }
}

/// An empty row per column, in the order of the columns.
pub(super) fn terms() -> Vec<TermReport> {
    ranges().map(|(c, columns)| TermReport::new(c.name, columns, c.bound, c.why_bound, c.signed)).collect()
}
