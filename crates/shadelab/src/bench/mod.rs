//! `shadelab bench …`: measurements, one file per bench command, each reported with the device
//! and the command; never asserted.

pub mod accuracy;
pub mod effects;
pub mod glass;
pub mod load;
pub mod mesh;
pub mod microfacet;
pub mod penumbra;
pub mod render;
pub mod shadows;
