//! `shadelab`: the viewer (no subcommand), `render`, `bench`, `sweep`, `figures`, `lobe`,
//! `compare` and `fit-ltc`.

use clap::Parser;
use shadelab::{EXIT_USAGE, Failure, bench, cli, compare, figures, fit_ltc, lobe, render, sweep, viewer};
use std::process::ExitCode;

/// Give Mesa a private `XDG_RUNTIME_DIR` when the environment has none: without one its window-system
/// code prints "error: XDG_RUNTIME_DIR is invalid or not set" on every device open, even on
/// success (headless renders, CI). A per-user folder under the temp dir, mode 0700, as the XDG
/// spec asks of it.
fn ensure_runtime_dir() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_some_and(|d| std::path::Path::new(&d).is_dir()) {
        return;
    }
    let user = std::env::var("USER").unwrap_or_else(|_| "user".into());
    let dir = std::env::temp_dir().join(format!("shadelab-xdg-{user}"));
    if std::fs::create_dir_all(&dir).is_err() {
        return;
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let _ = std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700));
    }
    // SAFETY: called first in main, before any other thread exists, so nothing reads the
    // environment concurrently.
    unsafe { std::env::set_var("XDG_RUNTIME_DIR", &dir) };
}

fn main() -> ExitCode {
    ensure_runtime_dir();
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let cli = match cli::Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            use clap::error::ErrorKind::*;
            if matches!(e.kind(), DisplayHelp | DisplayVersion | DisplayHelpOnMissingArgumentOrSubcommand) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            eprintln!("{}", cli::one_line(&e));
            return ExitCode::from(EXIT_USAGE);
        }
    };
    let result = match cli.command {
        Some(cli::Command::Render(args)) => render::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Render(args))) => bench::render::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Accuracy(args))) => bench::accuracy::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Effects(args))) => bench::effects::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Load(args))) => bench::load::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Mesh(args))) => bench::mesh::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Shadows(args))) => bench::shadows::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Penumbra(args))) => bench::penumbra::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Glass(args))) => bench::glass::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Microfacet(args))) => bench::microfacet::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Reference(args))) => bench::reference::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Ambient(args))) => bench::ambient::run(&args),
        Some(cli::Command::Bench(cli::BenchCommand::Environment(args))) => bench::environment::run(&args),
        Some(cli::Command::Sweep) => sweep::run(),
        Some(cli::Command::Figures(args)) => figures::run(&args),
        Some(cli::Command::Lobe(args)) => lobe::run(&args),
        Some(cli::Command::Compare(args)) => compare::run(&args),
        Some(cli::Command::FitLtc(args)) => fit_ltc::run(&args),
        None => viewer::run(viewer::Options {
            screenshot: cli.screenshot,
            exit_after_frames: cli.exit_after_frames,
            shaders: cli.shaders,
            scene: cli.scene,
            mode: cli.mode,
            difference: cli.difference,
            link: cli.link,
        }),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(EXIT_USAGE)
        }
        Err(Failure::Run(e)) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
