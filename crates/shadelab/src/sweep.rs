//! `shadelab sweep`: the stability sweep of every lighting term of the shipped WGSL against the
//! f64 reference, printed as a table.

use crate::Failure;

/// `shadelab sweep`: the stability sweep's table; exits 1 if any check fails.
pub fn run() -> Result<(), Failure> {
    use shadelab_render::sweep::{self, ERROR_TOLERANCE, SweepInputs};
    let gpu = crate::render::open_gpu()?;
    let start = std::time::Instant::now();
    let report = sweep::run(&gpu, SweepInputs::standard());
    println!("# shadelab sweep — device: {}", gpu.describe());
    println!(
        "# GPU pass + readback {:.0} ms, whole sweep {:.1} s; error tolerance {ERROR_TOLERANCE:e} where the f64 reference is well-conditioned",
        report.gpu_ms,
        start.elapsed().as_secs_f64()
    );
    print!("{}", report.table());
    let start = std::time::Instant::now();
    let env_report = sweep::environment::run(&gpu, sweep::EnvSweepInputs::standard());
    println!(
        "\n## The environment's functions\n\n# GPU passes + readback {:.0} ms, whole environment sweep {:.1} s; values in each environment's scale (its largest radiance; shares in 1)\n",
        env_report.gpu_ms,
        start.elapsed().as_secs_f64()
    );
    print!("{}", env_report.table());
    let failed: Vec<_> = report
        .terms
        .iter()
        .chain(&env_report.terms)
        .filter(|t| t.nonfinite + t.negative + t.over_bound > 0 || t.max_rel_err > ERROR_TOLERANCE)
        .map(|t| t.name)
        .collect();
    if failed.is_empty() {
        println!("\nall terms finite, ≥ 0, within their bounds and within {ERROR_TOLERANCE:e} of f64");
        Ok(())
    } else {
        Err(Failure::Run(anyhow::anyhow!("sweep failed for: {}", failed.join(", "))))
    }
}
