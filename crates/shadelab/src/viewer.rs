//! The interactive viewer (eframe): placeholder until the panel lands.

use crate::Failure;
use std::path::PathBuf;

pub fn run(_screenshot: Option<PathBuf>, _frames: Option<&str>) -> Result<(), Failure> {
    Err(Failure::Run(anyhow::anyhow!("viewer not built yet")))
}
