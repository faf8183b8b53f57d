//! The chapter's constant ambient against the light between surfaces (docs/reference.md, "The
//! chapter's I_a against the truth"). The chapter's `I_a·r_a·C` stands for the light that reaches
//! a surface after reflections off the others; the path tracer computes that light. From one
//! path-traced image, which also holds each pixel's constant ambient per unit of `I_a`, this
//! builds each rung of the ladder:
//! the constant ambient, the `I_a` that fits the scene best, ambient occlusion, and the truth.

use super::intersect::{occluded, trace};
use super::path::{Rng, cosine_direction};
use super::shadow_rays::ShadowRays;
use super::{Geometry, ReferenceImage, SECONDARY_RAY_OFFSET};
use crate::scene::Scene;
use rayon::prelude::*;

/// Ambient occlusion counts occluders within this share of the scene's size (its largest
/// coordinate): a tenth keeps the contact and crease darkening it stands for, not the closure
/// of the whole scene, which only the path tracer's light accounts for.
pub const AO_RADIUS_REL: f64 = 0.1;

/// Per pixel, the share of `rays` cosine-distributed rays from the surface the camera ray sees
/// that meet nothing within [`AO_RADIUS_REL`] of the scene's size; 1 where the camera sees
/// nothing. The random numbers derive from `seed` and the pixel, as the path tracer's do.
pub fn ambient_occlusion(scene: &Scene, width: u32, height: u32, rays: u32, seed: u64) -> Vec<f64> {
    let geo = Geometry::new(scene);
    let scale = ShadowRays::new(scene, &geo).scale;
    let (offset, radius) = (SECONDARY_RAY_OFFSET * scale, AO_RADIUS_REL * scale);
    let rows: Vec<Vec<f64>> = (0..height)
        .into_par_iter()
        .map(|y| {
            (0..width)
                .map(|x| {
                    let (o, dir) = scene.camera.ray(x, y, width, height);
                    let Some(hit) = trace(scene, &geo, o, dir) else { return 1.0 };
                    // The side the camera sees, so that a surface seen from behind is not
                    // occluded by itself.
                    let ng =
                        if hit.geometric_normal.dot(dir) > 0.0 { -hit.geometric_normal } else { hit.geometric_normal };
                    let n = if hit.normal.dot(ng) < 0.0 { -hit.normal } else { hit.normal };
                    let mut rng = Rng::new(seed, x, y);
                    let open = (0..rays)
                        .filter(|_| {
                            let w = cosine_direction(n, rng.uniform(), rng.uniform());
                            let side = if ng.dot(w) >= 0.0 { 1.0 } else { -1.0 };
                            !occluded(scene, &geo, hit.point + ng * (side * offset), w, radius)
                        })
                        .count();
                    open as f64 / f64::from(rays.max(1))
                })
                .collect()
        })
        .collect();
    rows.concat()
}

/// The parts of one view that every rung of the ladder is made of, per pixel.
pub struct AmbientLadder {
    pub width: u32,
    pub height: u32,
    /// The exact direct light, without ambient.
    pub direct: Vec<[f64; 3]>,
    /// The constant ambient term for `I_a = 1` (through glass too, as the reference carries it).
    pub per_ambient: Vec<[f64; 3]>,
    /// The path-traced indirect light and its standard error.
    pub indirect: Vec<[f64; 3]>,
    pub std_error: Vec<[f64; 3]>,
    /// The scene's own `I_a`.
    pub ambient: [f64; 3],
}

impl AmbientLadder {
    /// From `traced` (`ReferenceJob::with_paths`), which holds the truth and each pixel's
    /// constant ambient per unit of `I_a`; `None` when it is not path traced.
    pub fn new(traced: &ReferenceImage, ambient: [f64; 3]) -> Option<AmbientLadder> {
        let n = traced.pixels.len();
        if traced.indirect.len() != n || traced.per_ambient.len() != n {
            return None;
        }
        let direct: Vec<[f64; 3]> =
            traced.pixels.iter().zip(&traced.indirect).map(|(p, i)| std::array::from_fn(|c| p[c] - i[c])).collect();
        Some(AmbientLadder {
            width: traced.width,
            height: traced.height,
            direct,
            per_ambient: traced.per_ambient.clone(),
            indirect: traced.indirect.clone(),
            std_error: traced.std_error.clone(),
            ambient,
        })
    }

    /// The direct light plus the ambient term scaled per pixel by `k(pixel)` per channel.
    fn with_ambient(&self, k: impl Fn(usize) -> [f64; 3]) -> Vec<[f64; 3]> {
        (0..self.direct.len())
            .map(|i| {
                let (d, a, k) = (self.direct[i], self.per_ambient[i], k(i));
                std::array::from_fn(|c| d[c] + k[c] * a[c])
            })
            .collect()
    }

    /// The chapter's image: the constant `I_a·r_a·C`.
    pub fn constant(&self) -> Vec<[f64; 3]> {
        self.with_ambient(|_| self.ambient)
    }

    /// The truth: the direct light plus the light between surfaces.
    pub fn truth(&self) -> Vec<[f64; 3]> {
        self.direct.iter().zip(&self.indirect).map(|(d, i)| std::array::from_fn(|c| d[c] + i[c])).collect()
    }

    /// The `I_a` per channel whose constant ambient comes closest to the truth in the least
    /// squares over the pixels: `Σ a·i / Σ a²` with `a` the term for `I_a = 1` and `i` the
    /// indirect light; 0 where no pixel has an ambient term.
    pub fn fitted_ambient(&self) -> [f64; 3] {
        std::array::from_fn(|c| {
            let (mut ai, mut aa) = (0.0, 0.0);
            for (a, i) in self.per_ambient.iter().zip(&self.indirect) {
                ai += a[c] * i[c];
                aa += a[c] * a[c];
            }
            if aa > 0.0 { ai / aa } else { 0.0 }
        })
    }

    /// The constant ambient with the fitted `I_a`.
    pub fn fitted(&self) -> Vec<[f64; 3]> {
        let k = self.fitted_ambient();
        self.with_ambient(|_| k)
    }

    /// The constant ambient darkened by each pixel's ambient occlusion `ao`.
    pub fn occluded(&self, ao: &[f64]) -> Vec<[f64; 3]> {
        self.with_ambient(|i| self.ambient.map(|a| a * ao.get(i).copied().unwrap_or(1.0)))
    }

    /// `image − truth` per pixel: positive where the image has too much light.
    pub fn error(&self, image: &[[f64; 3]]) -> Vec<[f64; 3]> {
        image.iter().zip(self.truth()).map(|(p, t)| std::array::from_fn(|c| p[c] - t[c])).collect()
    }

    /// The root mean square of `image − truth` over pixels and channels.
    pub fn rmse(&self, image: &[[f64; 3]]) -> f64 {
        let e = self.error(image);
        let sum: f64 = e.iter().flatten().map(|x| x * x).sum();
        (sum / (3 * e.len()).max(1) as f64).sqrt()
    }

    /// The root mean square of the truth's own noise (its standard error): a difference under it
    /// is not measured.
    pub fn noise(&self) -> f64 {
        let sum: f64 = self.std_error.iter().flatten().map(|x| x * x).sum();
        (sum / (3 * self.std_error.len()).max(1) as f64).sqrt()
    }
}
