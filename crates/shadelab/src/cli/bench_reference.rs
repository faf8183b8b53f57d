//! `shadelab bench reference`'s flags.

use super::{SceneArgs, SizeArgs, values, within};
use clap::Args;

/// Runs of each timing: the table gives their median.
pub const REFERENCE_RUNS: shadelab_model::params::ParamRange = shadelab_model::params::ParamRange {
    flag: "--runs",
    symbol: "runs",
    meaning: "timed runs of each row",
    min: 1.0,
    max: 100.0,
};

#[derive(Args, Debug)]
pub struct BenchReferenceArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub size: SizeArgs,
    #[arg(long, default_value = "3", value_parser = values::count(REFERENCE_RUNS),
          help = within("Timed runs of each row (the median is reported)", REFERENCE_RUNS))]
    pub runs: u32,
}
