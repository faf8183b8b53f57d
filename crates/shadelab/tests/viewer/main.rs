//! The viewer's suite, driven by egui_kittest on lavapipe (wgpu): what a person sees and
//! clicks. One binary, one module per part of the viewer, one harness (`harness.rs`).

#[path = "../common/mod.rs"]
mod common;
mod harness;

mod area_lights;
mod boundary;
mod environment;
mod orbit;
mod panel;
mod reference;
mod shadows;
