//! The GPU suite: every test that renders through the render crate on lavapipe and holds the
//! image to a golden, the f64 reference or a measurement. One binary, one module per concept,
//! so the suite links once.

mod area_lights;
mod area_points;
mod environment;
mod glass;
mod lavapipe;
mod material_maps;
mod overlay;
mod shadows;
mod stability;
mod textures;
