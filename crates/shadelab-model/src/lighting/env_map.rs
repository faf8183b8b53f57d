//! The environment light (docs/environment.md): radiance over the sphere of directions, from a
//! uniform colour, the analytic sky or an equirectangular image, turned about the up axis and
//! scaled. [`Environment`] is what a scene holds and a file saves; [`EnvLight`] is it made ready
//! to shade: its radiance toward any direction, its nine SH coefficients for the GPU, and a
//! sampling density that follows its brightness for the reference's path tracer.

use super::environment::{ShCoefficients, sh_project};
use super::sky::Sky;
use crate::params::ParamRange;
use glam::DVec3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

mod prefilter;
pub use prefilter::{PREFILTER_EXPONENT_MAX, PREFILTER_SOURCE};

crate::param_ranges! {
    /// The environment's scale: 0 (dark) to 10⁴ (a sky in the sun's units).
    pub const ENV_INTENSITY = "--env-intensity", "I_env", "the environment's intensity, a scale of its radiance",
        [0.0, 1e4];
    /// The environment's turn about the up axis, in degrees.
    pub const ENV_ROTATION = "--env-rotation", "φ_env", "the environment's turn about the up axis, in degrees",
        [-360.0, 360.0];

    /// A uniform environment's radiance per channel: as `I_a`'s range, a little past 1 for a bright
    /// overcast sky.
    pub const ENV_RADIANCE = "--ambient", "L_env", "a uniform environment's radiance per channel", [0.0, 1e4];
}

/// The kinds of [`EnvSource`], by name (`extras.shadelab.environment.source`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EnvKind {
    Uniform,
    Sky,
    Image,
}

crate::named_values!(EnvKind, "--environment", "uniform" => Uniform, "sky" => Sky, "image" => Image);

/// The analytic sky is sampled for its sampling density on a grid of this many columns and half
/// as many rows: 1.4° cells, finer than the sky's features away from the sun.
pub const SKY_GRID: u32 = 256;
/// The nine SH terms are projected from a grid of at most this many columns and half as many
/// rows (a larger map averaged into it, the sky sampled at its cells' centres): 5.6° cells, whose
/// averaging moves a coefficient by a term second order in the cell's size, and cheap enough to
/// redo whenever the uniforms are written.
pub const SH_GRID: u32 = 64;

/// An equirectangular radiance map in linear RGB: row 0 looks up (+y), rows are uniform in the
/// angle from +y, columns in the angle φ from +x toward +z.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvImage {
    /// Where it came from (a file name), for messages and for saving.
    pub name: String,
    pub width: u32,
    pub height: u32,
    pub texels: Vec<[f32; 3]>,
}

impl EnvImage {
    /// The texel toward unit `d` (nearest: the map is piecewise constant, as its sampling).
    pub fn cell_of(&self, d: DVec3) -> (u32, u32) {
        let phi = d.z.atan2(d.x).rem_euclid(TAU);
        let theta = d.y.clamp(-1.0, 1.0).acos();
        let x = ((phi / TAU * f64::from(self.width)) as u32).min(self.width - 1);
        let y = ((theta / PI * f64::from(self.height)) as u32).min(self.height - 1);
        (x, y)
    }
    fn texel(&self, x: u32, y: u32) -> [f64; 3] {
        self.texels[(y * self.width + x) as usize].map(f64::from)
    }
}

/// Where an environment's radiance comes from.
#[derive(Clone, Debug)]
pub enum EnvSource {
    /// The same radiance from every direction: the chapter's `I_a`, made occludable.
    Uniform([f64; 3]),
    /// Preetham's sky of turbidity `turbidity`, the sun toward `sun`; `None` follows the scene's
    /// first directional light (or stands overhead without one).
    Sky { turbidity: f64, sun: Option<DVec3> },
    /// An equirectangular map (a file the user brings).
    Image(Arc<EnvImage>),
}

/// Maps compare by pointer first: the viewer compares its scene every frame, and a copy shares
/// the map (an `Arc` of floats, which are not `Eq`, would compare every texel).
impl PartialEq for EnvSource {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (EnvSource::Uniform(a), EnvSource::Uniform(b)) => a == b,
            (EnvSource::Sky { turbidity: t, sun: s }, EnvSource::Sky { turbidity: u, sun: r }) => t == u && s == r,
            (EnvSource::Image(a), EnvSource::Image(b)) => Arc::ptr_eq(a, b) || a == b,
            _ => false,
        }
    }
}

impl EnvSource {
    /// The source's name, as `--environment` and the viewer say it.
    pub fn name(&self) -> &'static str {
        match self {
            EnvSource::Uniform(_) => "uniform",
            EnvSource::Sky { .. } => "sky",
            EnvSource::Image(_) => "image",
        }
    }

    /// The source's kind, as files and links name it.
    pub fn kind(&self) -> EnvKind {
        match self {
            EnvSource::Uniform(_) => EnvKind::Uniform,
            EnvSource::Sky { .. } => EnvKind::Sky,
            EnvSource::Image(_) => EnvKind::Image,
        }
    }

    /// A source of `kind` as the viewer's panel and links start one: a uniform one of `ambient`'s
    /// radiance (the `I_a` it stands for), the sky at [`super::sky::TURBIDITY_DEFAULT`] following
    /// the first directional light; `None` for an image, which only a file gives.
    pub fn starting(kind: EnvKind, ambient: [f64; 3]) -> Option<EnvSource> {
        match kind {
            EnvKind::Uniform => Some(EnvSource::Uniform(ambient)),
            EnvKind::Sky => Some(EnvSource::Sky { turbidity: super::sky::TURBIDITY_DEFAULT, sun: None }),
            EnvKind::Image => None,
        }
    }
}

/// The scene's environment light: one at most per scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Environment {
    pub source: EnvSource,
    /// Within [`ENV_INTENSITY`].
    pub intensity: f64,
    /// Within [`ENV_ROTATION`], degrees.
    pub rotation_deg: f64,
    /// Whether the GPU draws its specular by the split sum (the reference's truth always has it).
    pub specular: bool,
    /// Whether the GPU occludes its diffuse light by the precomputed grid (`occlusion.rs`); the
    /// truth always traces visibility.
    pub occlusion: bool,
    /// Whether it is drawn where the camera sees nothing, in place of the scene's background.
    pub background: bool,
}

impl Environment {
    /// An environment of `source` at intensity 1, unturned.
    pub fn new(source: EnvSource) -> Environment {
        Environment { source, intensity: 1.0, rotation_deg: 0.0, specular: true, occlusion: false, background: false }
    }

    /// The nine SH coefficients the GPU's diffuse term reads (and the exact reference's twin).
    pub fn sh(&self, lights: &[super::lights::Light]) -> ShCoefficients {
        let (radiance, turn) = self.radiance(lights);
        let grid = radiance.sh_grid();
        sh_project(grid.width, grid.height, turn, |x, y| grid.texels[(y * grid.width + x) as usize])
    }

    /// The largest radiance (any channel) of the cells the SH terms are projected from: the SH
    /// diffuse stays under it times `environment::SH_RINGING_BOUND` (the stability sweep's bound).
    pub fn sh_radiance_max(&self, lights: &[super::lights::Light]) -> f64 {
        let (radiance, _) = self.radiance(lights);
        radiance.sh_grid().texels.iter().flatten().fold(0.0, |a: f64, &c| a.max(c))
    }

    /// The environment made ready to shade; `lights` are the scene's (a sky that follows the sun
    /// reads the first directional light).
    pub fn bake(&self, lights: &[super::lights::Light]) -> EnvLight {
        let (radiance, turn) = self.radiance(lights);
        let sh = self.sh(lights);
        let prefiltered = self.prefiltered(lights);
        let sampling = Distribution::new(&radiance.grid());
        EnvLight { radiance, turn, sh, prefiltered, sampling, occlusion: None }
    }

    /// The radiance function in the map's axes, and the turn to world axes.
    fn radiance(&self, lights: &[super::lights::Light]) -> (Radiance, f64) {
        let scale = within(&ENV_INTENSITY, self.intensity);
        let turn = within(&ENV_ROTATION, self.rotation_deg).to_radians();
        let radiance = match &self.source {
            EnvSource::Uniform(c) => Radiance::Uniform(c.map(|x| x.max(0.0) * scale)),
            EnvSource::Sky { turbidity, sun } => {
                let toward = sun.or_else(|| sun_of(lights)).unwrap_or(DVec3::Y);
                // The sky turns with the rest of the environment; the sun given in world axes.
                Radiance::Sky(Sky::new(*turbidity, turn_y(toward, -turn)), scale)
            }
            EnvSource::Image(img) => Radiance::Image(img.clone(), scale),
        };
        (radiance, turn)
    }
}

/// Toward the sun a sky without its own follows: against the scene's first directional light.
fn sun_of(lights: &[super::lights::Light]) -> Option<DVec3> {
    lights.iter().find(|l| l.kind.is_directional()).map(|l| -l.direction)
}

/// `v` clamped into `range`; a NaN is its minimum. The scene's checks refuse such values with a
/// message before here; the clamp keeps a value set in code from reaching the sums.
fn within(range: &ParamRange, v: f64) -> f64 {
    if v.is_nan() { range.min } else { v.clamp(range.min, range.max) }
}

/// An environment ready to shade.
#[derive(Clone, Debug)]
pub struct EnvLight {
    radiance: Radiance,
    /// The turn about +y, radians: world φ = map φ + turn.
    turn: f64,
    /// The nine coefficients the GPU's diffuse term reads (`environment.wgsl`).
    pub sh: ShCoefficients,
    /// The prefiltered levels the GPU's specular reads ([`Environment::prefiltered`]).
    pub prefiltered: Vec<[f32; 4]>,
    sampling: Distribution,
    /// The scene's occlusion grid, where the environment asks for it: the geometry's, so the
    /// reference bakes it beside the light (`reference::bake_env`).
    pub occlusion: Option<super::occlusion::OcclusionGrid>,
}

#[derive(Clone, Debug)]
enum Radiance {
    Uniform([f64; 3]),
    Sky(Sky, f64),
    Image(Arc<EnvImage>, f64),
}

/// A grid of cell radiances in the map's own axes.
struct Grid {
    width: u32,
    height: u32,
    texels: Vec<[f64; 3]>,
}

impl Radiance {
    /// Radiance toward unit `d` in the map's axes.
    fn at(&self, d: DVec3) -> [f64; 3] {
        match self {
            Radiance::Uniform(c) => *c,
            Radiance::Sky(sky, s) => sky.radiance(d).map(|x| x * s),
            Radiance::Image(img, s) => {
                let (x, y) = img.cell_of(d);
                img.texel(x, y).map(|v| v.max(0.0) * s)
            }
        }
    }

    /// The map as cells: the image's own, a uniform colour's one cell, the sky at each cell's
    /// centre on a [`SKY_GRID`] grid.
    fn grid(&self) -> Grid {
        match self {
            Radiance::Uniform(c) => Grid { width: 1, height: 1, texels: vec![*c] },
            Radiance::Image(img, _) => Grid {
                width: img.width,
                height: img.height,
                texels: (0..img.height)
                    .flat_map(|y| (0..img.width).map(move |x| (x, y)))
                    .map(|(x, y)| self.at(cell_center(x, y, img.width, img.height)))
                    .collect(),
            },
            Radiance::Sky(..) => self.sampled(SKY_GRID, SKY_GRID / 2),
        }
    }
}

impl Radiance {
    /// The map on at most [`SH_GRID`] × [`SH_GRID`]/2 cells: an image's texels averaged (by
    /// solid angle) into the cell holding their centre, the sky at the cells' centres.
    fn sh_grid(&self) -> Grid {
        self.averaged(SH_GRID)
    }

    /// The map on at most `side` × `side`/2 cells, as [`Self::sh_grid`].
    fn averaged(&self, side: u32) -> Grid {
        match self {
            Radiance::Uniform(_) => self.grid(),
            Radiance::Sky(..) => self.sampled(side, side / 2),
            Radiance::Image(img, s) if img.width > side || img.height > side / 2 => {
                let (w, h) = (img.width.min(side), img.height.min(side / 2));
                let mut sum = vec![[0.0; 3]; (w * h) as usize];
                let mut area = vec![0.0; (w * h) as usize];
                for y in 0..img.height {
                    let a = cell_solid_angle(y, img.width, img.height);
                    let cy = (u64::from(y) * u64::from(h) / u64::from(img.height)) as u32;
                    for x in 0..img.width {
                        let cx = (u64::from(x) * u64::from(w) / u64::from(img.width)) as u32;
                        let k = (cy * w + cx) as usize;
                        let t = img.texel(x, y);
                        for c in 0..3 {
                            sum[k][c] += t[c].max(0.0) * s * a;
                        }
                        area[k] += a;
                    }
                }
                let texels =
                    sum.iter().zip(&area).map(|(t, a)| t.map(|v| if *a > 0.0 { v / a } else { 0.0 })).collect();
                Grid { width: w, height: h, texels }
            }
            Radiance::Image(..) => self.grid(),
        }
    }

    /// The radiance at the centres of a `w × h` grid's cells.
    fn sampled(&self, w: u32, h: u32) -> Grid {
        let texels =
            (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| self.at(cell_center(x, y, w, h))).collect();
        Grid { width: w, height: h, texels }
    }
}

/// The unit direction at the centre of cell `(x, y)` of a `w × h` map.
fn cell_center(x: u32, y: u32, w: u32, h: u32) -> DVec3 {
    let phi = TAU * (f64::from(x) + 0.5) / f64::from(w);
    let theta = PI * (f64::from(y) + 0.5) / f64::from(h);
    DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin())
}

/// `d` turned by `angle` about +y (φ grows by `angle`).
fn turn_y(d: DVec3, angle: f64) -> DVec3 {
    let (s, c) = angle.sin_cos();
    DVec3::new(c * d.x - s * d.z, d.y, s * d.x + c * d.z)
}

/// Rec. 709 luminance, the brightness sampling follows.
fn luminance(c: [f64; 3]) -> f64 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

/// A piecewise-constant density over the map's cells, each cell's probability its luminance
/// times its solid angle: rows by their marginal, then a column within the row.
#[derive(Clone, Debug)]
struct Distribution {
    width: u32,
    height: u32,
    /// Cumulative row probabilities (`height + 1` entries from 0 to 1).
    rows: Vec<f64>,
    /// Per row, cumulative column probabilities within the row (`width + 1` entries each).
    columns: Vec<f64>,
    /// Each cell's probability.
    cells: Vec<f64>,
}

impl Distribution {
    fn new(grid: &Grid) -> Distribution {
        let (w, h) = (grid.width, grid.height);
        let mut weights: Vec<f64> = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| luminance(grid.texels[(y * w + x) as usize]).max(0.0) * cell_solid_angle(y, w, h))
            .collect();
        let total: f64 = weights.iter().sum();
        // A black map is sampled uniformly over the sphere: its directions bring nothing, and a
        // density is still needed where the BRDF's samples are weighed against it.
        if !(total > 0.0) || !total.is_finite() {
            weights = (0..h).flat_map(|y| (0..w).map(move |_| cell_solid_angle(y, w, h))).collect();
        }
        let total: f64 = weights.iter().sum();
        let cells: Vec<f64> = weights.iter().map(|v| v / total).collect();
        let mut rows = vec![0.0];
        let mut columns = Vec::with_capacity(((w + 1) * h) as usize);
        for y in 0..h as usize {
            let row = &cells[y * w as usize..(y + 1) * w as usize];
            let sum: f64 = row.iter().sum();
            rows.push(rows[y] + sum);
            let mut c = 0.0;
            columns.push(0.0);
            for p in row {
                c += if sum > 0.0 { p / sum } else { 1.0 / f64::from(w) };
                columns.push(c);
            }
        }
        Distribution { width: w, height: h, rows, columns, cells }
    }

    /// The cell holding `u` in cumulative `cdf` (its first `n + 1` entries), and where in it.
    fn pick(cdf: &[f64], u: f64) -> (usize, f64) {
        let n = cdf.len() - 1;
        let total = cdf[n];
        let u = u * total;
        let i = cdf.partition_point(|&c| c <= u).saturating_sub(1).min(n - 1);
        let width = cdf[i + 1] - cdf[i];
        let t = if width > 0.0 { ((u - cdf[i]) / width).clamp(0.0, 1.0) } else { 0.5 };
        (i, t)
    }
}

/// The solid angle of a cell of row `y` of a `w × h` map.
fn cell_solid_angle(y: u32, w: u32, h: u32) -> f64 {
    let t = |r: u32| PI * f64::from(r) / f64::from(h);
    (t(y).cos() - t(y + 1).cos()) * TAU / f64::from(w)
}

impl EnvLight {
    /// What the camera sees toward unit `d` where it meets nothing: the radiance itself (`exact`,
    /// the truth's), or the GPU's background, level 0 of the prefiltered levels, bilinear.
    pub fn background_toward(&self, d: DVec3, exact: bool) -> [f64; 3] {
        if exact { self.radiance(d) } else { super::environment::env_level_sample(&self.prefiltered, 0, d) }
    }

    /// Radiance arriving from world direction `d` (unit, pointing away from the point).
    pub fn radiance(&self, d: DVec3) -> [f64; 3] {
        self.radiance.at(turn_y(d, -self.turn))
    }

    /// The source's value for a uniform environment, `None` for the others.
    pub fn uniform(&self) -> Option<[f64; 3]> {
        match self.radiance {
            Radiance::Uniform(c) => Some(c),
            _ => None,
        }
    }

    /// A world direction drawn with the sampling density from two uniform numbers, and its
    /// density per steradian.
    pub fn sample(&self, u1: f64, u2: f64) -> (DVec3, f64) {
        let s = &self.sampling;
        let (y, ty) = Distribution::pick(&s.rows, u1);
        let w1 = s.width as usize + 1;
        let (x, tx) = Distribution::pick(&s.columns[y * w1..(y + 1) * w1], u2);
        // Uniform in solid angle within the cell: cos θ linear, φ linear.
        let (h, w) = (f64::from(s.height), f64::from(s.width));
        let (c0, c1) = ((PI * y as f64 / h).cos(), (PI * (y as f64 + 1.0) / h).cos());
        let mu = c0 + (c1 - c0) * ty;
        let phi = TAU * (x as f64 + tx) / w;
        let r = (1.0 - mu * mu).max(0.0).sqrt();
        let local = DVec3::new(r * phi.cos(), mu, r * phi.sin());
        let d = turn_y(local, self.turn);
        (d, self.pdf(d))
    }

    /// The sampling density per steradian toward world direction `d`.
    pub fn pdf(&self, d: DVec3) -> f64 {
        let s = &self.sampling;
        let local = turn_y(d, -self.turn);
        let phi = local.z.atan2(local.x).rem_euclid(TAU);
        let theta = local.y.clamp(-1.0, 1.0).acos();
        let x = ((phi / TAU * f64::from(s.width)) as u32).min(s.width - 1);
        let y = ((theta / PI * f64::from(s.height)) as u32).min(s.height - 1);
        s.cells[(y * s.width + x) as usize] / cell_solid_angle(y, s.width, s.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(w: u32, h: u32, f: impl Fn(u32, u32) -> [f32; 3]) -> Arc<EnvImage> {
        let texels = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| f(x, y)).collect();
        Arc::new(EnvImage { name: "test".into(), width: w, height: h, texels })
    }

    /// The sampling density integrates to 1 over the sphere and each sample's density is the
    /// one `pdf` gives for its direction; a single bright texel draws every sample into it.
    #[test]
    fn sampling_density_is_a_density() {
        let hot = image(16, 8, |x, y| if (x, y) == (5, 2) { [50.0, 40.0, 30.0] } else { [0.1, 0.2, 0.3] });
        // Each with the solid angle where it has light: the sky is black below the horizon.
        for (env, support) in [
            (Environment::new(EnvSource::Image(hot)), 4.0 * PI),
            (Environment::new(EnvSource::Sky { turbidity: 3.0, sun: Some(DVec3::new(1.0, 0.2, 0.3)) }), 2.0 * PI),
            (Environment { rotation_deg: 73.0, ..Environment::new(EnvSource::Uniform([0.5; 3])) }, 4.0 * PI),
        ] {
            let light = env.bake(&[]);
            let n = 200_000;
            let mut mean_inverse = 0.0;
            for i in 0..n {
                let u1 = (f64::from(i) + 0.5) / f64::from(n);
                let u2 = ((f64::from(i) * 0.618_033_988_749_895) % 1.0).abs();
                let (d, p) = light.sample(u1, u2);
                assert!((d.length() - 1.0).abs() < 1e-12 && p > 0.0, "{d} {p}");
                assert!((light.pdf(d) - p).abs() <= 1e-9 * p, "{} {p}", light.pdf(d));
                mean_inverse += 1.0 / p / f64::from(n);
            }
            // E[1/p] over samples drawn with p is the measure of where p > 0.
            assert!((mean_inverse - support).abs() < 0.05, "{:?}: {mean_inverse}", env.source.name());
        }
    }

    /// Turning the environment turns its radiance: the bright texel's direction moves by the
    /// angle about +y.
    #[test]
    fn rotation_turns_the_map() {
        let hot = image(8, 4, |x, y| if (x, y) == (1, 1) { [9.0; 3] } else { [0.0; 3] });
        let still = Environment::new(EnvSource::Image(hot.clone())).bake(&[]);
        let turned = Environment { rotation_deg: 90.0, ..Environment::new(EnvSource::Image(hot)) }.bake(&[]);
        let d = cell_center(1, 1, 8, 4);
        assert_eq!(still.radiance(d), [9.0; 3]);
        assert_eq!(turned.radiance(d), [0.0; 3]);
        assert_eq!(turned.radiance(turn_y(d, 90f64.to_radians())), [9.0; 3]);
    }
}
