//! `cargo xtask fuzz [--seconds N]`: build the targets in `fuzz/` with libFuzzer's coverage
//! instrumentation and run each for N seconds on its checked-in seeds. A target that panics,
//! aborts, hangs past `TIMEOUT_SECONDS` or allocates past `RSS_LIMIT_MB` fails the run, and
//! libFuzzer writes the input under `target/fuzz/artifacts/<target>/`. `cargo xtask test` runs
//! every target for `CI_SECONDS`.
//!
//! The build needs no nightly: coverage is stable `-C passes=sancov-module` with its LLVM options,
//! and `--cfg fuzzing`. The code under test is safe Rust, where a memory error is a panic
//! already, so no sanitizer is added (it would double the time for nothing it could find).

use std::path::Path;
use std::process::Command;

/// Each target and its seed folders (relative to the repository).
pub const TARGETS: [(&str, &[&str]); 4] = [
    ("load_scene", &["tests/gltf-corpus", "assets"]),
    ("texture_image", &["fuzz/seeds/texture_image"]),
    ("env_image", &["fuzz/seeds/env_image", "assets/mitsuba"]),
    ("extras", &["fuzz/seeds/extras"]),
];
/// Seconds the targets run in `cargo xtask test`, side by side: at the fuzz build's opt-level 1
/// they run as many inputs in 30 s as at opt-level 3 in 20 s (0.84–1.23 times as many, per
/// target; docs/testing.md).
pub const CI_SECONDS: u32 = 30;
/// One input may take this long before libFuzzer calls it a hang (a scene is bounded far below).
const TIMEOUT_SECONDS: u32 = 10;
/// Memory one input may take: the loader's own limits keep a hostile file far below it.
const RSS_LIMIT_MB: u32 = 2048;
/// The coverage instrumentation libFuzzer needs (what cargo-fuzz passes, without a sanitizer).
const RUSTFLAGS: &str = "-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
    -Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
    -Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks";
/// Given explicitly so that the flags reach the targets and not the build scripts.
const HOST: &str = "x86_64-unknown-linux-gnu";

/// `cargo xtask fuzz [--seconds N]`.
pub fn main(args: &[String]) -> Result<(), String> {
    let seconds = match args {
        [] => 60,
        [flag, n] if flag == "--seconds" => n
            .parse::<u32>()
            .ok()
            .filter(|n| (1..=86_400).contains(n))
            .ok_or_else(|| format!("--seconds: '{n}' is not a whole number of seconds in [1, 86400]"))?,
        _ => return Err("usage: cargo xtask fuzz [--seconds N]".into()),
    };
    run(seconds)
}

/// Build every target once, then run them all for `seconds`, side by side.
pub fn run(seconds: u32) -> Result<(), String> {
    build()?;
    run_targets(seconds)
}

/// The repository and the fuzz targets' own target folder.
fn folders() -> (&'static Path, std::path::PathBuf) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("xtask/ is in the repository");
    (root, root.join("target/fuzz"))
}

/// Build every target with the coverage instrumentation.
pub fn build() -> Result<(), String> {
    let (root, target_dir) = folders();
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut build = Command::new(cargo);
    build
        .current_dir(root)
        .args(["build", "--release", "--bins", "--manifest-path", "fuzz/Cargo.toml", "--target", HOST])
        .arg("--target-dir")
        .arg(&target_dir)
        .env("RUSTFLAGS", RUSTFLAGS);
    if crate::run(&mut build) { Ok(()) } else { Err("building the fuzz targets failed".into()) }
}

/// Run every built target for `seconds`, side by side.
pub fn run_targets(seconds: u32) -> Result<(), String> {
    let (root, target_dir) = folders();
    // The targets run side by side: each is one process on one core, so on a machine with
    // several they take the time of one.
    let mut running = Vec::new();
    for (name, seeds) in TARGETS {
        let corpus = target_dir.join("corpus").join(name);
        let artifacts = target_dir.join("artifacts").join(name);
        std::fs::create_dir_all(&corpus)
            .and_then(|_| std::fs::create_dir_all(&artifacts))
            .map_err(|e| e.to_string())?;
        let mut cmd = Command::new(target_dir.join(HOST).join("release").join(name));
        cmd.current_dir(root).arg(&corpus).args(seeds);
        cmd.arg(format!("-max_total_time={seconds}"))
            .arg(format!("-timeout={TIMEOUT_SECONDS}"))
            .arg(format!("-rss_limit_mb={RSS_LIMIT_MB}"))
            .arg(format!("-artifact_prefix={}/", artifacts.display()))
            .arg("-print_final_stats=1");
        eprintln!("xtask: running {cmd:?}");
        running.push((name, artifacts, cmd.spawn()));
    }
    let mut failed = Vec::new();
    for (name, artifacts, child) in running {
        if !child.and_then(|mut c| c.wait()).is_ok_and(|s| s.success()) {
            failed.push(format!("{name} (its input is in {})", artifacts.display()));
        }
    }
    if failed.is_empty() { Ok(()) } else { Err(format!("a fuzz target found a crash: {}", failed.join(", "))) }
}
