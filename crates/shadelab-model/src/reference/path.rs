//! The reference's path tracer (docs/reference.md, "Light between surfaces"): the rendering
//! equation over the scene, with the chapter's models as BRDFs and its lights as emitters. The
//! image is the exact direct light of [`super::render_reference`] without the constant ambient,
//! plus the indirect light estimated by paths of cosine-distributed bounces.
//!
//! Units: the chapter's light carries no 1/π, so a light of intensity `I_L` stands for the
//! irradiance `π·I_L`, and the model's term for a direction `ω` (cosine included) is `π·f_r·cos`.
//! Light `L_i` arriving from `ω` then adds `f_r·L_i·cos dω = term(ω)·L_i·dω/π`; with `ω` drawn with
//! density `p` one sample is `term(ω)·L_i/(π·p)`: with `p = cos/π`, `r_d·C·L_i` for the diffuse
//! term. Bounces mix that density with a lobe about the mirror direction ([`LOBE_SHARE`]).

use super::glass::{Leaves, Tracer};
use super::intersect::{SurfaceHit, trace};
use super::light_surfaces::{LightHit, light_hit, light_radiance};
use super::{Context, Shaded, Span};
use crate::Light;
use crate::lighting::common::safe_normalize;
use crate::lighting::shading::{ShadePoint, shade_exact};
use crate::params::{PhongExponent, SpecularModel};
use crate::scene::Material;
use glam::{DVec3, DVec4};
use std::cell::RefCell;

/// A sampled direction this close to the surface's plane (its cosine) is dropped: its density
/// `cos/π` is under 3e-10, so the light it would bring is below 1e-9 of the pixel's, and the
/// division by the cosine would overflow near 0.
pub const PATH_COS_MIN: f64 = 1e-9;

/// Where a material has a specular term, this share of its bounces is drawn from a lobe about the
/// mirror direction and the rest with density `cos/π` (one-sample multiple importance sampling:
/// every bounce is weighted by the mixture's density, so the estimate stays unbiased while a
/// glossy highlight's light is found by the lobe).
pub const LOBE_SHARE: f64 = 0.5;
/// The sampling lobe `cos^e` about the mirror direction has `e` within [1, this]: 1e4 keeps it
/// within about 1° of the mirror, finer than a pixel's reflection; a sharper highlight is
/// still found, at more noise.
pub const LOBE_EXPONENT_MAX: f64 = 1e4;

/// A pixel has a firefly when one of its paths alone brings more than this share of its indirect
/// light (with at least [`FIREFLY_MIN_SPP`] paths): reported, never clamped.
pub const FIREFLY_SHARE: f64 = 0.25;
/// Paths a pixel needs before one path's share says anything: with 8, an even share is 1/8.
pub const FIREFLY_MIN_SPP: u32 = 8;

/// A pixel is an outlier when its luminance is above this many times the median of its 3×3
/// neighbourhood (itself included; at the border, the neighbours inside): the image-space count
/// of fireflies, which needs no per-path record and reads any renderer's image alike.
pub const OUTLIER_FACTOR: f64 = 10.0;

/// The pixels of `pixels` (`width` a row) above [`OUTLIER_FACTOR`] times their 3×3 median.
pub fn outlier_pixels(pixels: &[[f64; 3]], width: usize) -> usize {
    let height = pixels.len() / width.max(1);
    let lum: Vec<f64> = pixels.iter().map(|&c| luminance(c)).collect();
    let mut count = 0;
    for y in 0..height {
        for x in 0..width {
            let mut around: Vec<f64> = (y.saturating_sub(1)..(y + 2).min(height))
                .flat_map(|j| (x.saturating_sub(1)..(x + 2).min(width)).map(move |i| (i, j)))
                .map(|(i, j)| lum[j * width + i])
                .collect();
            around.sort_by(f64::total_cmp);
            let median = around[around.len() / 2];
            if lum[y * width + x] > OUTLIER_FACTOR * median {
                count += 1;
            }
        }
    }
    count
}

/// How the path tracer samples: surface vertices per path and paths per pixel (within
/// `params::BOUNCES` and `params::SPP`), and the seed every
/// pixel's random numbers derive from (the same seed gives the same image on any number of
/// threads).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PathSettings {
    pub bounces: u32,
    pub spp: u32,
    pub seed: u64,
}

impl Default for PathSettings {
    fn default() -> Self {
        PathSettings { bounces: 4, spp: 64, seed: 1 }
    }
}

/// SplitMix64: the pixel's stream of random numbers, seeded from the seed and the pixel.
pub(super) struct Rng(u64);

impl Rng {
    pub(super) fn new(seed: u64, x: u32, y: u32) -> Rng {
        let mut r = Rng(seed ^ (u64::from(y) << 32 | u64::from(x)).wrapping_mul(0xA24B_AED4_963E_E407));
        r.next();
        r
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1), 53 bits.
    pub(super) fn uniform(&mut self) -> f64 {
        (self.next() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// A direction drawn with density `cos/π` about unit `n` (Malley: the unit disk lifted).
pub(super) fn cosine_direction(n: DVec3, u1: f64, u2: f64) -> DVec3 {
    let (r, phi) = (u1.sqrt(), std::f64::consts::TAU * u2);
    let (t, b) = n.any_orthonormal_pair();
    safe_normalize(t * (r * phi.cos()) + b * (r * phi.sin()) + n * (1.0 - u1).max(0.0).sqrt(), n)
}

/// The exponent of the sampling lobe for `mat`'s specular term: its Phong exponent `h`, or for
/// Cook–Torrance the `h = 2/m² − 2` of its roughness; `None` without a specular term.
fn lobe_exponent(mat: &Material, specular: SpecularModel) -> Option<f64> {
    let h = match specular {
        SpecularModel::Phong => mat.h,
        _ => PhongExponent::from_m(mat.m),
    };
    (mat.r_s > 0.0 && mat.mu.iter().any(|&m| m > 0.0)).then(|| h.value().clamp(1.0, LOBE_EXPONENT_MAX))
}

/// A direction drawn with density `(e + 1)/(2π)·cos^e` about unit `r`.
fn lobe_direction(r: DVec3, e: f64, u1: f64, u2: f64) -> DVec3 {
    let cos = u1.powf(1.0 / (e + 1.0));
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let phi = std::f64::consts::TAU * u2;
    let (t, b) = r.any_orthonormal_pair();
    safe_normalize(t * (sin * phi.cos()) + b * (sin * phi.sin()) + r * cos, r)
}

/// The density of [`lobe_direction`] at `w`.
fn lobe_density(w: DVec3, r: DVec3, e: f64) -> f64 {
    (e + 1.0) / std::f64::consts::TAU * w.dot(r).max(0.0).powf(e)
}

/// How a path vertex samples its area lights' direct light: its random numbers, and the
/// multiple importance weight of a light's point given the direction to it and its density
/// per solid angle (the power heuristic against the vertex's bounce, [`mis_weight`]).
#[derive(Clone, Copy)]
pub(crate) struct Sampler<'a> {
    pub rng: &'a RefCell<Rng>,
    pub weight: &'a dyn Fn(DVec3, f64) -> f64,
}

/// One span's indirect light: its mean per pixel, the standard error of that mean, and the pixels
/// with a firefly.
#[derive(Default)]
pub(super) struct SpanIndirect {
    pub light: Vec<[f64; 3]>,
    pub std_error: Vec<[f64; 3]>,
    pub fireflies: usize,
}

/// What a path's leaves are: the whole light at a vertex, or (the camera's own vertex through
/// glass, whose direct light the exact image holds) only its indirect part.
#[derive(Clone, Copy)]
struct PathLeaves<'a> {
    paths: &'a PathSettings,
    rng: &'a RefCell<Rng>,
    /// The vertex a leaf is: 1 for the camera's surface.
    depth: u32,
    whole: bool,
    /// The scene's materials, where a point's textured parameters are written (one per row).
    tinted: &'a RefCell<Vec<Material>>,
}

impl Leaves for PathLeaves<'_> {
    fn opaque(&self, ctx: &Context, hit: &SurfaceHit, from: DVec3) -> [f64; 3] {
        let depth = self.depth;
        let vertex = vertex_bounce(ctx, hit, from, &mut self.tinted.borrow_mut());
        let mut light = if self.whole {
            // The area lights' points weighed against this vertex's bounce, which meets them too.
            let bounce = &vertex.0;
            let weight = |l: DVec3, p_light: f64| power_heuristic(p_light, bounce.density(l));
            let sampler = Sampler { rng: self.rng, weight: &weight };
            ctx.shade_hit(hit, from.extend(1.0), &mut self.tinted.borrow_mut(), None, None, Some(sampler)).lit
        } else {
            [0.0; 3]
        };
        let more = indirect_at(ctx, self, hit, from, depth, vertex);
        for (l, m) in light.iter_mut().zip(more) {
            *l += m;
        }
        light
    }
    fn background(&self, ctx: &Context, dir: DVec3) -> [f64; 3] {
        // A bounce that leaves through glass meets the environment, whole: the environment's own
        // samples stop at glass, so no other strategy finds this path. The camera's own view
        // through glass is in the exact image already, and the picture's background is no light.
        match ctx.env.filter(|_| self.whole && ctx.env_use == super::EnvUse::Traced) {
            Some(env) => env.radiance(dir),
            None => [0.0; 3],
        }
    }
    fn glass_surface(&self, ctx: &Context, hit: &SurfaceHit, eye: DVec4, material: &Material) -> Shaded {
        if self.whole {
            // Glass samples no bounce that could meet a light: its light's points weigh 1.
            let sampler = Sampler { rng: self.rng, weight: &|_, _| 1.0 };
            ctx.shade_hit(hit, eye, &mut self.tinted.borrow_mut(), None, Some(material), Some(sampler))
        } else {
            Shaded::default()
        }
    }
}

/// The bounce sampling at `hit` seen from `from`, with the shading normal the model takes and
/// the index of the point's material (its textured parameters written into `tinted`).
fn vertex_bounce(ctx: &Context, hit: &SurfaceHit, from: DVec3, tinted: &mut [Material]) -> (Bounce, DVec3, usize) {
    let mi = ctx.scene.objects[hit.object].material;
    let (n_in, mat, _) = ctx.surface(hit, &ctx.scene.materials[mi], &mut tinted[mi], false, None);
    let n = safe_normalize(n_in, hit.geometric_normal);
    // The mirror of the view about the normal, the axis of the specular lobe.
    let v = safe_normalize(from - hit.point, n);
    let r = safe_normalize(n * (2.0 * n.dot(v)) - v, n);
    (Bounce { n, r, lobe: lobe_exponent(mat, ctx.specular) }, n_in, mi)
}

/// Whether the vertex's direct light draws `light` by its points (`area_term_sampled`), so that
/// a bounce meeting it is the other of two strategies: the exact Phong model's integrated area
/// lights. Others are whole in the direct light, and a bounce meeting them brings nothing.
fn sampled_by_area(ctx: &Context, light: &Light) -> bool {
    ctx.exact
        && ctx.scene.illumination == crate::IlluminationModel::Phong
        && light.kind.is_area()
        && !light.drawn_as_points()
}

/// The indirect light at vertex `depth` of a path, seen from `from`, with the vertex's bounce
/// sampling as [`vertex_bounce`] gave it (its material then in `tinted`): the environment's light at
/// the vertex (when the scene has one), and one bounce drawn from the mixture of `cos/π` about
/// the shading normal and the specular lobe ([`LOBE_SHARE`]), with the whole light that comes
/// back along it. A bounce that meets an area light ends there (`light_surfaces.rs`); at the
/// last vertex it is drawn for that meeting alone.
fn indirect_at(
    ctx: &Context,
    leaves: &PathLeaves,
    hit: &SurfaceHit,
    from: DVec3,
    depth: u32,
    (bounce, n_in, mi): (Bounce, DVec3, usize),
) -> [f64; 3] {
    let env = ctx.env.filter(|_| ctx.env_use == super::EnvUse::Traced);
    let scene = ctx.scene;
    let last = depth >= leaves.paths.bounces;
    let meets_lights = leaves.whole && scene.lights.iter().any(|l| sampled_by_area(ctx, l));
    if last && env.is_none() && !meets_lights {
        return [0.0; 3];
    }
    // Two more numbers only with an environment, so a scene without one keeps its images.
    let [u0, u1, u2, u3, u4] = {
        let mut rng = leaves.rng.borrow_mut();
        let mut u: [f64; 5] = std::array::from_fn(|k| if k < 3 { rng.uniform() } else { 0.0 });
        if env.is_some() {
            u[3] = rng.uniform();
            u[4] = rng.uniform();
        }
        u
    };
    let p = hit.point;
    let tinted = leaves.tinted.borrow_mut();
    let (n, mat) = (bounce.n, &tinted[mi]);
    let ng = hit.geometric_normal;
    let origin = |w: DVec3| {
        let side = if ng.dot(w) >= 0.0 { 1.0 } else { -1.0 };
        p + ng * (side * super::SECONDARY_RAY_OFFSET * ctx.rays.scale)
    };
    let mut out = [0.0; 3];
    // The environment sampled by its own density, weighed against the bounce's (power heuristic).
    if let Some(env) = env {
        let (w, p_env) = env.sample(u3, u4);
        if w.dot(n) >= PATH_COS_MIN && p_env > 0.0 {
            let term = model_term_towards(ctx, p, n_in, from, mat, w);
            let clear = |w: DVec3| {
                trace(scene, ctx.geo, origin(w), w).is_none() && light_hit(&ctx.areas, origin(w), w).is_none()
            };
            if term != [0.0; 3] && clear(w) {
                let weight = power_heuristic(p_env, bounce.density(w));
                let l = env.radiance(w);
                for i in 0..3 {
                    out[i] += term[i] * l[i] * weight / (std::f64::consts::PI * p_env);
                }
            }
        }
    }
    let w = bounce.direction(u0, u1, u2);
    let cos = w.dot(n);
    if cos < PATH_COS_MIN {
        return out;
    }
    let density = bounce.density(w);
    let term = model_term_towards(ctx, p, n_in, from, mat, w);
    drop(tinted);
    if term == [0.0; 3] {
        return out;
    }
    let o = origin(w);
    let next = trace(scene, ctx.geo, o, w);
    let met = light_hit(&ctx.areas, o, w).filter(|h| next.as_ref().is_none_or(|s| h.t < (s.point - o).length()));
    let incoming = match (met, next) {
        (Some(h), _) if leaves.whole => return add(out, light_met(ctx, &h, p, term, density)),
        (Some(_), _) => return out,
        // A bounce that leaves meets the environment, weighed against its own sampling.
        (None, None) => env.map_or([0.0; 3], |e| {
            let weight = power_heuristic(density, e.pdf(w));
            e.radiance(w).map(|l| l * weight)
        }),
        (None, Some(_)) if last => [0.0; 3],
        (None, Some(next)) => {
            let whole = PathLeaves { depth: depth + 1, whole: true, ..*leaves };
            if scene.drawn_as_glass(next.object) {
                Tracer::new(ctx, &whole).glass_color(&next, w, p.extend(1.0), 0, [1.0; 3], None).lit
            } else {
                whole.opaque(ctx, &next, p)
            }
        }
    };
    // term·L_i·dω/π over the density of ω.
    for i in 0..3 {
        out[i] += term[i] * incoming[i] / (std::f64::consts::PI * density);
    }
    out
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| a[i] + b[i])
}

/// A bounce from `p`, drawn with `density`, that met a light's surface: the light's front gives
/// the bounce's estimate of that light's direct light (`light_radiance`), weighed against the
/// vertex's own sampling of its points ([`sampled_by_area`]); a back, or a light the direct
/// light holds whole, gives nothing.
fn light_met(ctx: &Context, h: &LightHit, p: DVec3, term: [f64; 3], density: f64) -> [f64; 3] {
    let light = &ctx.scene.lights[h.light];
    if !h.front || !sampled_by_area(ctx, light) {
        return [0.0; 3];
    }
    let Some(radiance) = light_radiance(light, p) else { return [0.0; 3] };
    let weight = power_heuristic(density, h.density);
    // term·L·dω/π over the density.
    std::array::from_fn(|i| term[i] * radiance[i] * weight / (std::f64::consts::PI * density))
}

/// Veach's power heuristic: the weight of a sample drawn with density `a` where the other
/// strategy's density is `b`.
fn power_heuristic(a: f64, b: f64) -> f64 {
    let (a2, b2) = (a * a, b * b);
    if a2 + b2 > 0.0 { a2 / (a2 + b2) } else { 0.0 }
}

/// A bounce's sampling at one vertex: the mixture of `cos/π` about `n` and the lobe about `r`.
struct Bounce {
    n: DVec3,
    r: DVec3,
    lobe: Option<f64>,
}

impl Bounce {
    fn share(&self) -> f64 {
        if self.lobe.is_some() { LOBE_SHARE } else { 0.0 }
    }
    fn direction(&self, u0: f64, u1: f64, u2: f64) -> DVec3 {
        match self.lobe {
            Some(e) if u0 < self.share() => lobe_direction(self.r, e, u1, u2),
            _ => cosine_direction(self.n, u1, u2),
        }
    }
    fn density(&self, w: DVec3) -> f64 {
        let share = self.share();
        (1.0 - share) * w.dot(self.n).max(0.0) / std::f64::consts::PI
            + self.lobe.map_or(0.0, |e| share * lobe_density(w, self.r, e))
    }
}

/// The model's term (cosine included) at `p` seen from `from` for a unit light arriving from unit
/// `w`: the chapter's models taken as a BRDF, the same function the direct light calls.
fn model_term_towards(ctx: &Context, p: DVec3, n: DVec3, from: DVec3, mat: &Material, w: DVec3) -> [f64; 3] {
    let probe = Light::directional(-w, [1.0; 3], 1.0);
    let at = ShadePoint {
        p,
        n_in: n,
        eye: from.extend(1.0),
        mat,
        ambient: [0.0; 3],
        env_sh: None,
        env_prefiltered: None,
        env_occlusion: None,
        specular: ctx.specular,
        model: ctx.scene.illumination,
    };
    shade_exact(&at, std::slice::from_ref(&probe), |_, _, _, _| 1.0, &mut |_| None)
}

/// The span's indirect light, `paths.spp` paths a pixel, each pixel with its own random numbers.
fn indirect_span(ctx: &Context, paths: &PathSettings, span: &Span) -> SpanIndirect {
    let Span { y, width, height, .. } = *span;
    let mut row = SpanIndirect::default();
    let eye = ctx.scene.camera.eye_h();
    let tinted = RefCell::new(ctx.scene.materials.clone());
    for x in span.xs.clone() {
        let rng = RefCell::new(Rng::new(paths.seed, x, y));
        let (o, dir) = ctx.scene.camera.ray(x, y, width, height);
        let Some(hit) = trace(ctx.scene, ctx.geo, o, dir) else {
            row.light.push([0.0; 3]);
            row.std_error.push([0.0; 3]);
            continue;
        };
        let leaves = PathLeaves { paths, rng: &rng, depth: 1, whole: false, tinted: &tinted };
        let glass = ctx.scene.drawn_as_glass(hit.object);
        let (mut sum, mut sum_sq, mut largest) = ([0.0; 3], [0.0; 3], 0.0f64);
        for _ in 0..paths.spp {
            let s = if glass {
                Tracer::new(ctx, &leaves).glass_color(&hit, dir, eye, 0, [1.0; 3], None).lit
            } else {
                // The point's parameters are written anew each path: deeper vertices of the same
                // material overwrite them.
                let vertex = vertex_bounce(ctx, &hit, eye.truncate(), &mut tinted.borrow_mut());
                indirect_at(ctx, &leaves, &hit, eye.truncate(), 1, vertex)
            };
            for i in 0..3 {
                sum[i] += s[i];
                sum_sq[i] += s[i] * s[i];
            }
            largest = largest.max(luminance(s));
        }
        let k = f64::from(paths.spp);
        let mean = sum.map(|s| s / k);
        // The standard error of the mean: the samples' variance over k (0 with one sample).
        let std_error = std::array::from_fn(|i| {
            if paths.spp < 2 {
                return 0.0;
            }
            let var = (sum_sq[i] / k - mean[i] * mean[i]).max(0.0) * k / (k - 1.0);
            (var / k).sqrt()
        });
        if paths.spp >= FIREFLY_MIN_SPP && largest > FIREFLY_SHARE * luminance(sum) && largest > 0.0 {
            row.fireflies += 1;
        }
        row.light.push(mean);
        row.std_error.push(std_error);
    }
    row
}

/// A span of a path-traced image: `row`, the exact direct light without ambient, gains the
/// indirect light with its noise, and the constant ambient per unit of `I_a` (the span traced in
/// `unit`'s scenes without lights, at `I_a = 1` less at `I_a = 0`).
pub(super) fn add_paths(
    ctx: &Context,
    [one, zero]: &[Context; 2],
    paths: &PathSettings,
    span: &Span,
    row: &mut super::SpanPixels,
) {
    let (with_one, with_zero) = (super::trace_span(one, span), super::trace_span(zero, span));
    row.per_ambient =
        with_one.pixels.iter().zip(&with_zero.pixels).map(|(u, d)| std::array::from_fn(|i| u[i] - d[i])).collect();
    let more = indirect_span(ctx, paths, span);
    // The indirect light is the same with and without the direct light's cast shadows.
    for (k, m) in more.light.iter().enumerate() {
        for i in 0..3 {
            row.pixels[k][i] += m[i];
            row.unshadowed[k][i] += m[i];
        }
    }
    row.indirect = more.light;
    row.std_error = more.std_error;
    row.fireflies = more.fireflies;
    lights_seen(ctx, span, row);
}

/// The camera's rays that meet an area light before any surface see the light: its front's
/// radiance ([`light_radiance`]), its back black. The truth's picture shows its lights as a
/// physical renderer's does; the exact image's (the GPU's twin's) sees through them.
fn lights_seen(ctx: &Context, span: &Span, row: &mut super::SpanPixels) {
    for x in span.xs.clone() {
        let (o, dir) = ctx.scene.camera.ray(x, span.y, span.width, span.height);
        let Some(h) = light_hit(&ctx.areas, o, dir) else { continue };
        if trace(ctx.scene, ctx.geo, o, dir).is_some_and(|s| (s.point - o).length() < h.t) {
            continue;
        }
        let seen = if h.front { light_radiance(&ctx.scene.lights[h.light], o).unwrap_or([0.0; 3]) } else { [0.0; 3] };
        let k = (x - span.xs.start) as usize;
        (row.pixels[k], row.unshadowed[k]) = (seen, seen);
        (row.indirect[k], row.std_error[k], row.per_ambient[k]) = ([0.0; 3], [0.0; 3], [0.0; 3]);
    }
}

/// Rec. 709 luminance of linear RGB.
fn luminance(c: [f64; 3]) -> f64 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}
