//! The environment sweep's inputs: its hard environments, each with an occlusion grid, and the
//! axes every environment is evaluated over (the main sweep's geometries, m and μ, and the
//! occlusion points' distances).

use super::inputs::{Geometry, SweepInputs};
use glam::DVec3;
use shadelab_model::lighting::env_map::{EnvImage, EnvSource, Environment};
use shadelab_model::lighting::occlusion::{OcclusionGrid, occ_quantize};
use shadelab_model::{Light, Scene};
use std::sync::Arc;

/// One environment as the renderer writes it for the GPU, with the occlusion grid read beside it.
pub struct EnvCase {
    pub label: &'static str,
    pub env: Environment,
    /// The scene's lights, which a sky without its own sun follows.
    pub lights: Vec<Light>,
    pub grid: OcclusionGrid,
    pub grid_label: &'static str,
}

/// The environment sweep's cases and axes; each case is evaluated over the axes' full product.
pub struct EnvSweepInputs {
    pub cases: Vec<EnvCase>,
    pub geometry: Vec<Geometry>,
    pub m: Vec<f32>,
    pub mu: Vec<[f32; 3]>,
    /// The occlusion point's distance from the grid's centre along l, metres.
    pub d: Vec<f32>,
}

fn image(label: &str, w: u32, h: u32, f: impl Fn(u32, u32) -> [f32; 3]) -> EnvSource {
    let texels = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| f(x, y)).collect();
    EnvSource::Image(Arc::new(EnvImage { name: label.into(), width: w, height: h, texels }))
}

/// A grid of `dims` nodes `cell` apart from `origin`, each node from `node(index)`.
fn grid(origin: DVec3, cell: f64, dims: [u32; 3], node: impl Fn(usize) -> [u8; 8]) -> OcclusionGrid {
    let count = dims.iter().product::<u32>() as usize;
    OcclusionGrid { origin, cell, dims, nodes: (0..count).map(node).collect() }
}

/// The hard grids: the default scene's as baked, the smallest grid with mixed open and closed
/// nodes at a micrometre cell, every node closed (no open node near: the lookup's fallback), and
/// a grid of 10 km cells far from the origin.
fn grids() -> [(OcclusionGrid, &'static str); 4] {
    use shadelab_model::lighting::occlusion::OCC_RAYS;
    let default = Scene::builtin("default").expect("built-in");
    let baked =
        shadelab_model::reference::bake_occlusion(&default, OCC_RAYS, 1).expect("the default scene has objects");
    // About the origin, where f32 positions resolve its micrometre cell.
    let mixed = grid(DVec3::splat(-0.5e-6), 1e-6, [2, 2, 2], |i| {
        let share = |k: usize| occ_quantize(((i * 7 + k * 3) % 11) as f64 / 10.0);
        [share(0), share(1), share(2), share(3), share(4), share(5), if i % 3 == 0 { 0 } else { 255 }, 0]
    });
    let closed = grid(DVec3::splat(-1.0), 0.5, [4, 4, 4], |_| [255, 255, 255, 255, 255, 255, 0, 0]);
    // Varied bytes, the open byte (the node's weight) among them; the eighth stays zero.
    let far = grid(DVec3::new(1e5, -2e4, 3e4), 1e4, [3, 2, 3], |i| {
        let mut b = [255u8, 0, 128, 64, 32, 200, 255, 0].map(|b| b ^ (i as u8).wrapping_mul(37));
        b[7] = 0;
        b
    });
    [
        (baked, "the default scene's"),
        (mixed, "2×2×2 nodes, cell 1e-6 about the origin, mixed"),
        (closed, "every node closed"),
        (far, "10 km cells, 1e5 from the origin"),
    ]
}

impl EnvSweepInputs {
    /// The hard environments (a sun at and below the horizon, a black map, a single bright
    /// texel, a 1×1 map and a turned map at the largest intensity), over the main sweep's
    /// geometries, m and μ.
    pub fn standard() -> EnvSweepInputs {
        let main = SweepInputs::standard();
        let [baked, mixed, closed, far] = grids();
        let sky = |turbidity: f64, sun: DVec3| EnvSource::Sky { turbidity, sun: Some(sun) };
        let bright = image("one bright texel", 64, 32, |x, y| if (x, y) == (17, 9) { [1e6; 3] } else { [0.0; 3] });
        let turned = Environment {
            intensity: 1e4,
            rotation_deg: 137.0,
            ..Environment::new(image("ramp", 16, 8, |x, y| [x as f32, y as f32, 0.5]))
        };
        let case = |label, env, (grid, grid_label): (OcclusionGrid, &'static str)| EnvCase {
            label,
            env,
            lights: Vec::new(),
            grid,
            grid_label,
        };
        let followed = EnvCase {
            lights: vec![Light::directional(DVec3::new(-1.0, 1e-7, 0.0), [1.0; 3], 1.0)],
            ..case(
                "sky following a light at the horizon",
                Environment::new(EnvSource::Sky { turbidity: 4.0, sun: None }),
                far.clone(),
            )
        };
        EnvSweepInputs {
            cases: vec![
                case("sky, sun at the horizon", Environment::new(sky(2.0, DVec3::X)), baked.clone()),
                case(
                    "sky, sun below the horizon, turbidity 10",
                    Environment::new(sky(10.0, DVec3::new(0.0, -1.0, 0.2))),
                    mixed,
                ),
                case("black map", Environment::new(image("black", 8, 4, |_, _| [0.0; 3])), closed),
                case("one texel of 1e6 in 64×32", Environment::new(bright), baked.clone()),
                case("1×1 map", Environment::new(image("one texel", 1, 1, |_, _| [0.3, 0.5, 0.7])), far),
                case("ramp map, turned 137°, intensity 1e4 (the most)", turned, baked),
                followed,
            ],
            geometry: main.geometry,
            m: main.m,
            mu: main.mu,
            d: vec![0.0, 1e-6, 1e-3, 0.1, 0.5, 1.0, 3.0, 1e7],
        }
    }

    /// Combinations per case.
    pub fn combinations(&self) -> usize {
        self.geometry.len() * self.m.len() * self.mu.len() * self.d.len()
    }

    /// The axes' indices of a combination (the kernel's decomposition): geometry, m, μ, d.
    pub(super) fn split(&self, idx: usize) -> [usize; 4] {
        let mut r = idx;
        let di = r % self.d.len();
        r /= self.d.len();
        let ui = r % self.mu.len();
        r /= self.mu.len();
        let mi = r % self.m.len();
        [r / self.m.len(), mi, ui, di]
    }

    /// A combination of a case in words.
    pub fn describe(&self, case: usize, idx: usize) -> String {
        let [gi, mi, ui, di] = self.split(idx);
        let (c, g) = (&self.cases[case], &self.geometry[gi]);
        format!(
            "{} (grid: {}); {}: n={:?} v={:?} l={:?} m={:e} μ={:?} d={:e}",
            c.label, c.grid_label, g.label, g.n, g.v, g.l, self.m[mi], self.mu[ui], self.d[di]
        )
    }

    /// The rows the kernel reads: geometry (n, v, l) each, then m, μ and d.
    pub(super) fn table(&self) -> Vec<[f32; 4]> {
        let mut t = super::inputs::geometry_rows(&self.geometry);
        t.extend(self.m.iter().map(|&m| [m, 0.0, 0.0, 0.0]));
        t.extend(self.mu.iter().map(|u| [u[0], u[1], u[2], 0.0]));
        t.extend(self.d.iter().map(|&d| [d, 0.0, 0.0, 0.0]));
        t
    }
}

/// The grid's centre as the GPU gets it (f32), where the occlusion points depart from.
pub(super) fn grid_centre(grid: &OcclusionGrid) -> [f32; 3] {
    let extent = DVec3::new(f64::from(grid.dims[0]), f64::from(grid.dims[1]), f64::from(grid.dims[2])) - 1.0;
    (grid.origin + extent * (0.5 * grid.cell)).as_vec3().to_array()
}
