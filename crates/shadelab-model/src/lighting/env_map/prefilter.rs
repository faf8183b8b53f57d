//! The environment's prefiltered levels, the split sum's `L_pre` (docs/environment.md): the
//! environment weighed by the lobe about each texel's direction, one level a roughness, and the
//! levels of the last environments kept, as each texel weighs every source cell.

use super::{EnvSource, Environment, cell_center, cell_solid_angle, sun_of, turn_y};
use crate::lighting::lights::Light;
use glam::DVec3;

impl Environment {
    /// The prefiltered levels the split sum reads (`environment.rs`'s `env_prefiltered`), in
    /// world axes: level 0 the radiance at each texel's centre, level k the environment on a
    /// [`PREFILTER_SOURCE`]-wide grid weighed by the lobe `cos^h` about the texel's direction,
    /// `h` from `m_k` by the project's one h-from-m rule (the lobe Beckmann's D is as wide as).
    pub fn prefiltered(&self, lights: &[Light]) -> Vec<[f32; 4]> {
        let key = self.prefilter_key(lights);
        let mut recent = RECENT_PREFILTERED.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(i) = recent.iter().position(|(k, _)| *k == key) {
            let hit = recent.remove(i);
            recent.insert(0, hit);
            return recent[0].1.clone();
        }
        drop(recent);
        let levels = self.prefilter(lights);
        let mut recent = RECENT_PREFILTERED.lock().unwrap_or_else(|e| e.into_inner());
        recent.insert(0, (key, levels.clone()));
        recent.truncate(RECENT_PREFILTERED_KEPT);
        levels
    }

    /// What the prefiltered levels depend on ([`Self::radiance`]'s inputs): the source, the scale
    /// and the turn, and the sun a sky without its own follows.
    fn prefilter_key(&self, lights: &[Light]) -> PrefilterKey {
        let follows_sun = matches!(self.source, EnvSource::Sky { sun: None, .. });
        PrefilterKey {
            source: self.source.clone(),
            intensity: self.intensity,
            rotation_deg: self.rotation_deg,
            sun: if follows_sun { sun_of(lights) } else { None },
        }
    }

    /// [`Self::prefiltered`], computed.
    fn prefilter(&self, lights: &[Light]) -> Vec<[f32; 4]> {
        use crate::lighting::environment::{ENV_LEVELS, env_level_size};
        use rayon::prelude::*;
        let (radiance, turn) = self.radiance(lights);
        let source = radiance.averaged(PREFILTER_SOURCE);
        let cells: Vec<(DVec3, f64, [f64; 3])> = (0..source.height)
            .flat_map(|y| (0..source.width).map(move |x| (x, y)))
            .map(|(x, y)| {
                let d = turn_y(cell_center(x, y, source.width, source.height), turn);
                let a = cell_solid_angle(y, source.width, source.height);
                (d, a, source.texels[(y * source.width + x) as usize])
            })
            .collect();
        let mut out = Vec::with_capacity(crate::lighting::environment::ENV_PREFILTERED_TEXELS);
        for k in 0..ENV_LEVELS {
            let (w, h) = env_level_size(k);
            let m = f64::from(k) / f64::from(ENV_LEVELS - 1);
            let lobe = crate::params::PhongExponent::from_m(m).value().clamp(1.0, PREFILTER_EXPONENT_MAX);
            let level: Vec<[f32; 4]> = (0..w * h)
                .into_par_iter()
                .map(|i| {
                    let d = turn_y(cell_center(i % w, i / w, w, h), turn);
                    let c = if k == 0 { radiance.at(turn_y(d, -turn)) } else { lobe_mean(&cells, d, lobe) };
                    [c[0] as f32, c[1] as f32, c[2] as f32, 0.0]
                })
                .collect();
            out.extend(level);
        }
        out
    }
}

/// The environments last prefiltered, newest first, with the sun they followed and their levels.
/// A bench, a test or the viewer shades one environment many times, and each prefilter weighs
/// every source cell for every texel; prefiltering is pure, so a kept result is the same levels.
type Prefiltered = (PrefilterKey, Vec<[f32; 4]>);

/// [`Environment::prefilter_key`].
#[derive(Clone, Debug, PartialEq)]
struct PrefilterKey {
    source: EnvSource,
    intensity: f64,
    rotation_deg: f64,
    sun: Option<DVec3>,
}

static RECENT_PREFILTERED: std::sync::Mutex<Vec<Prefiltered>> = std::sync::Mutex::new(Vec::new());
/// How many [`RECENT_PREFILTERED`] keeps: a study alternates between a few environments.
const RECENT_PREFILTERED_KEPT: usize = 4;

/// The prefilter's source grid: this many columns, half as many rows (2.8° cells).
pub const PREFILTER_SOURCE: u32 = 128;
/// The prefilter's lobe exponent at most: 1e3 is a lobe of about 2.5°, as wide as the source's
/// cells; sharper levels would fall between them.
pub const PREFILTER_EXPONENT_MAX: f64 = 1e3;

/// The mean of `cells` (direction, solid angle, radiance) weighed by `max(d·ω, 0)^h`; the
/// nearest cell's radiance where no cell has weight.
fn lobe_mean(cells: &[(DVec3, f64, [f64; 3])], d: DVec3, h: f64) -> [f64; 3] {
    let (mut sum, mut total, mut best) = ([0.0; 3], 0.0, (f64::NEG_INFINITY, [0.0; 3]));
    for (w, a, l) in cells {
        let c = d.dot(*w);
        if c > best.0 {
            best = (c, *l);
        }
        if c > 0.0 {
            let k = c.powf(h) * a;
            total += k;
            for i in 0..3 {
                sum[i] += k * l[i];
            }
        }
    }
    if total > 0.0 { sum.map(|s| s / total) } else { best.1 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kept prefilter is the one computed anew, and a sky that follows the sun is prefiltered
    /// again when the sun moves (the sun is part of what a result is kept for).
    #[test]
    fn kept_prefilters_follow_the_sun() {
        let sky = Environment::new(EnvSource::Sky { turbidity: 3.0, sun: None });
        let sun = |d: DVec3| [Light::directional(d.normalize(), [1.0; 3], 1.0)];
        let (low, high) = (sun(DVec3::new(1.0, -0.3, 0.2)), sun(DVec3::new(0.1, -1.0, 0.0)));
        let first = sky.prefiltered(&low);
        assert_eq!(first, sky.prefilter(&low));
        let moved = sky.prefiltered(&high);
        assert_eq!(moved, sky.prefilter(&high));
        assert_ne!(first, moved);
        assert_eq!(sky.prefiltered(&low), first);
    }
}
