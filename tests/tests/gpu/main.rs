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

/// The largest |difference| of any colour channel (the first three) between two images' pixels,
/// in f64 so the f32 GPU images and the f64 reference's compare alike.
fn max_rgb_gap<T: Copy + Into<f64>, const N: usize>(a: &[[T; N]], b: &[[T; N]]) -> f64 {
    a.iter().zip(b).flat_map(|(p, q)| (0..3).map(move |c| (p[c].into() - q[c].into()).abs())).fold(0.0, f64::max)
}
