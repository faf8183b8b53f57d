//! `shadelab bench …`: measurements, one file per bench command, each reported with the device
//! and the command; never asserted.

pub mod accuracy;
pub mod ambient;
pub mod effects;
pub mod environment;
pub mod glass;
pub mod load;
pub mod mesh;
pub mod microfacet;
pub mod penumbra;
pub mod reference;
pub mod render;
pub mod shadows;

/// Write `bytes` to `dir/name`, naming the file in the error; the path written.
pub(crate) fn write(dir: &std::path::Path, name: &str, bytes: &[u8]) -> anyhow::Result<std::path::PathBuf> {
    use anyhow::Context;
    let p = dir.join(name);
    std::fs::write(&p, bytes).with_context(|| format!("writing {}", p.display()))?;
    Ok(p)
}
