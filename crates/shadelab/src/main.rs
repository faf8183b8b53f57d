//! `shadelab`: the viewer (no subcommand), `render`, `bench`, `sweep`, `figures` and `lobe`.

use clap::Parser;
use shadelab::{EXIT_USAGE, Failure, bench, cli, figures, lobe, render, sweep, viewer};
use std::process::ExitCode;

fn main() -> ExitCode {
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
        Some(cli::Command::Sweep) => sweep::run(),
        Some(cli::Command::Figures(args)) => figures::run(&args),
        Some(cli::Command::Lobe(args)) => lobe::run(&args),
        None => viewer::run(viewer::Options {
            screenshot: cli.screenshot,
            exit_after_frames: cli.exit_after_frames,
            shaders: cli.shaders,
            scene: cli.scene,
            mode: cli.mode,
            difference: cli.difference,
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
