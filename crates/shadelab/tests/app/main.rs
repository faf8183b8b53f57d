//! The app's suite: the `shadelab` binary's commands run as a user runs them (on lavapipe), and
//! the benchmarks' and the accuracy study's measurements. One binary, one module per command or
//! study, so the suite links once.

#[path = "../common/mod.rs"]
mod common;

mod accuracy_study;
mod bench_ambient;
mod bench_glass;
mod bench_microfacet;
mod bench_reference;
mod bench_shadows;
mod cli;
mod cli_compare;
mod cli_environment;
mod cli_paths;
mod cli_views;
mod gltf_cli;
mod penumbra_widths;
