//! The `shadelab` application: the viewer (eframe), `render`, `bench` and `sweep`. The binary
//! is a thin `main`; the modules live here so that tests can drive the viewer.

// The command-line tools write files and plots; the browser build (`shadelab-web`) is the viewer.
pub mod ambient_views;
#[cfg(not(target_arch = "wasm32"))]
pub mod bench;
pub mod cli;
#[cfg(not(target_arch = "wasm32"))]
pub mod compare;
#[cfg(not(target_arch = "wasm32"))]
pub mod figures;
#[cfg(not(target_arch = "wasm32"))]
pub mod fit_ltc;
pub mod image_file;
#[cfg(not(target_arch = "wasm32"))]
pub mod lobe;
#[cfg(not(target_arch = "wasm32"))]
pub mod plots;
pub mod reference_views;
pub mod render;
#[cfg(not(target_arch = "wasm32"))]
pub mod sweep;
pub mod viewer;

/// Exit code for a user's mistake (bad flag, out-of-range value, bad file).
pub const EXIT_USAGE: u8 = 2;

/// What went wrong: the user's input (exit 2) or the run itself (exit 1).
#[derive(Debug)]
pub enum Failure {
    Usage(String),
    Run(anyhow::Error),
}

impl Failure {
    /// The failure as the one line a panel or a link's error shows.
    pub fn message(&self) -> String {
        match self {
            Failure::Usage(m) => m.clone(),
            Failure::Run(e) => format!("{e:#}"),
        }
    }
}

impl From<shadelab_model::params::ParamError> for Failure {
    fn from(e: shadelab_model::params::ParamError) -> Self {
        Failure::Usage(e.to_string())
    }
}

impl From<anyhow::Error> for Failure {
    fn from(e: anyhow::Error) -> Self {
        Failure::Run(e)
    }
}
