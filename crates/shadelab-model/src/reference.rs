//! The reference renderer: rays cast through the same pixel centres as the rasterizer, hitting
//! the *analytic* shapes (exact normals, no tessellation), shaded by the f64 model, with exact
//! hard cast shadows from shadow rays. The ground truth for tests and for the accuracy study.

mod ambient;
mod bvh;
#[cfg(test)]
mod cornell_tests;
#[cfg(test)]
mod env_tests;
mod glass;
mod intersect;
mod light_surfaces;
mod occlusion_bake;
mod path;
#[cfg(test)]
mod path_tests;
mod shadow_rays;
mod spans;
#[cfg(test)]
mod tests;

pub use ambient::{AO_RADIUS_REL, AmbientLadder, ambient_occlusion};
pub use glass::{GLASS_MAX_DEPTH, GLASS_MIN_WEIGHT, SECONDARY_RAY_OFFSET};
pub use intersect::MeshHierarchy;
pub use occlusion_bake::bake_occlusion;
pub use path::{FIREFLY_MIN_SPP, FIREFLY_SHARE, OUTLIER_FACTOR, PATH_COS_MIN, PathSettings, outlier_pixels};
pub use shadow_rays::SHADOW_RAY_OFFSET_REL;

use crate::Light;
use crate::lighting::area_exact::{area_term_exact, area_term_sampled};
use crate::lighting::area_points::area_emitter;
use crate::lighting::env_map::EnvLight;
use crate::lighting::shading::{AreaAt, ShadePoint, shade_exact};
use crate::params::SpecularModel;
use crate::scene::{Material, Scene, UvFootprint};
use glam::DVec3;
pub(crate) use intersect::Geometry;
use intersect::trace;
use shadow_rays::ShadowRays;
use spans::{Span, SpanPixels, trace_rows, trace_span};
use std::cell::Cell;
use std::sync::atomic::{AtomicU64, Ordering};

/// The nearest surface a ray from `o` along `dir` sees (the pick of `lobe.rs`).
pub(crate) fn trace_ray(
    scene: &Scene,
    geo: &Geometry,
    o: glam::DVec3,
    dir: glam::DVec3,
) -> Option<intersect::SurfaceHit> {
    trace(scene, geo, o, dir)
}

/// The threads the reference traces rows on: every core (`RAYON_NUM_THREADS` sets it), one where
/// the target has no threads (the browser).
pub fn reference_threads() -> usize {
    rayon::current_num_threads()
}

/// Builds the hierarchies of the scene's meshes, as a reference image does before its first ray,
/// and returns the bytes they hold (`bench reference` times and reports it).
pub fn hierarchy_bytes(scene: &Scene) -> usize {
    Geometry::new(scene).bvhs.iter().map(bvh::Bvh::bytes).sum()
}

/// A linear RGB image in f64, rows top to bottom.
#[derive(Clone, Debug)]
pub struct ReferenceImage {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<[f64; 3]>,
    /// Index of the object seen at each pixel (`None`: background).
    pub object: Vec<Option<usize>>,
    /// Per pixel, bit `i` set where light `i` casts shadows, would light the point (its term is
    /// not zero) and is hidden from it by some object: the exact lit/shadowed state.
    pub hidden: Vec<u8>,
    /// The same pixels with no cast shadows (equal to `pixels` where `hidden` is 0).
    pub unshadowed: Vec<[f64; 3]>,
    /// The scene's background (`Scene::background`): `None`, pixels with no object are black
    /// with alpha 0.
    pub background: Option<[f64; 3]>,
    /// The largest estimated error of an area light's integral at any pixel
    /// (`area_exact::AreaTerm::error`); 0 without area lights, or where the image draws them as
    /// the GPU does ([`render_drawn`]).
    pub area_error: f64,
    /// Path traced (`ReferenceJob::with_paths`): how, each pixel's estimated indirect light
    /// (included in `pixels`) and its standard error, and the pixels with a firefly
    /// (`path::FIREFLY_SHARE`); `None` and empty for the direct light alone.
    pub paths: Option<PathSettings>,
    pub indirect: Vec<[f64; 3]>,
    /// Path traced: each pixel's constant ambient term for `I_a = 1` (the chapter's stand-in for
    /// the indirect light, from the exact image; through glass too).
    pub per_ambient: Vec<[f64; 3]>,
    pub std_error: Vec<[f64; 3]>,
    pub fireflies: usize,
}

impl ReferenceImage {
    pub fn get(&self, x: u32, y: u32) -> [f64; 3] {
        self.pixels[(y * self.width + x) as usize]
    }
    pub fn object_at(&self, x: u32, y: u32) -> Option<usize> {
        self.object[(y * self.width + x) as usize]
    }
    /// The lights hidden from the point seen at pixel `(x, y)`, bit `i` for light `i`.
    pub fn hidden_at(&self, x: u32, y: u32) -> u8 {
        self.hidden[(y * self.width + x) as usize]
    }
    /// Pixels where the reference sees `object` and so do all 8 neighbours (no silhouette): where
    /// an image is compared with the reference without the edges' coverage.
    pub fn interior(&self, object: usize) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for y in 1..self.height.saturating_sub(1) {
            for x in 1..self.width.saturating_sub(1) {
                if (0..9).all(|k| self.object_at(x + k % 3 - 1, y + k / 3 - 1) == Some(object)) {
                    out.push((x, y));
                }
            }
        }
        out
    }

    /// Another image's pixels as a reference to compare with: no objects, no shadows, no
    /// background.
    pub fn from_pixels(width: u32, height: u32, pixels: Vec<[f64; 3]>) -> ReferenceImage {
        let n = pixels.len();
        ReferenceImage {
            background: None,
            unshadowed: pixels.clone(),
            pixels,
            object: vec![None; n],
            hidden: vec![0; n],
            ..ReferenceImage::empty(width, height, None)
        }
    }

    /// A reference image of one colour with nothing in it (for tests of the metrics).
    pub fn uniform(width: u32, height: u32, color: [f64; 3]) -> ReferenceImage {
        let n = (width * height) as usize;
        ReferenceImage {
            pixels: vec![color; n],
            object: vec![None; n],
            hidden: vec![0; n],
            unshadowed: vec![color; n],
            ..ReferenceImage::empty(width, height, Some(color))
        }
    }
}

/// Cells a side of the quadrature over an area light's surface that gives the reference its
/// soft shadows (`ShadowRays::area_visibility`): 16² = 256 shadow rays per pixel and light, so
/// a penumbra is resolved into 256 levels, finer than an 8-bit image's steps across it.
pub const REFERENCE_AREA_CELLS: usize = 16;

/// Render the scene by ray casting in f64 at any resolution. A light whose `shadow.casts` is
/// false lights every point its term reaches, exactly as without shadow rays.
/// An area light is integrated exactly here, its diffuse and its specular over its whole area
/// (`area_exact`), also where the GPU draws it as k point sources or takes its specular at a
/// representative point: the reference is what those approximations are measured against
/// ([`render_drawn`] draws them in f64).
pub fn render_reference(scene: &Scene, specular: SpecularModel, width: u32, height: u32) -> ReferenceImage {
    let mut job = ReferenceJob::new(scene, specular, width, height);
    job.step(height);
    job.finish()
}

/// The scene as the GPU draws it, in f64: an area light drawn as k point sources is k point
/// sources with a hard shadow ray each, and an area light's specular is taken at its
/// representative point (the f64 twins of those approximations); the rest as
/// [`render_reference`].
pub fn render_drawn(scene: &Scene, specular: SpecularModel, width: u32, height: u32) -> ReferenceImage {
    let mut img = ReferenceImage::empty(width, height, scene.background);
    let env = bake_env(scene);
    trace_rows(scene, &Geometry::new(scene), specular, &mut img, 0..height, false, None, env.as_ref());
    img
}

/// The scene's environment made ready to shade, with its occlusion grid where it asks for one
/// ([`bake_occlusion`] with `OCC_RAYS`, seed 1: the GPU's grid, node for node).
pub fn bake_env(scene: &Scene) -> Option<EnvLight> {
    let env = scene.environment.as_ref()?;
    let mut light = env.bake(&scene.lights);
    if env.occlusion {
        light.occlusion = bake_occlusion(scene, crate::lighting::occlusion::OCC_RAYS, 1);
    }
    Some(light)
}

/// [`render_reference`] a few rows at a time, for a caller without threads (the browser, which
/// spreads it over frames so the page keeps drawing). The image is the same, row for row.
pub struct ReferenceJob {
    scene: Scene,
    /// Its transforms and hierarchies, built once for every step.
    geo: Geometry,
    specular: SpecularModel,
    paths: Option<PathSettings>,
    /// With `paths`: the scene without its lights at `I_a = 1` and at `I_a = 0`, whose exact
    /// images differ by each pixel's constant ambient term per unit of `I_a`.
    unit: Option<[Scene; 2]>,
    /// The scene's environment light, baked once.
    env: Option<EnvLight>,
    img: ReferenceImage,
    next_row: u32,
}

impl ReferenceJob {
    pub fn new(scene: &Scene, specular: SpecularModel, width: u32, height: u32) -> ReferenceJob {
        let exact: Vec<Light> = scene.lights.iter().map(|l| Light { area_points: 0, ..l.clone() }).collect();
        let scene = Scene { lights: exact, ..scene.clone() };
        let img = ReferenceImage::empty(width, height, scene.background);
        let geo = Geometry::new(&scene);
        let env = bake_env(&scene);
        ReferenceJob { scene, geo, specular, paths: None, unit: None, env, img, next_row: 0 }
    }

    /// The scene's light between surfaces, path traced (`path.rs`): the exact direct light as
    /// [`ReferenceJob::new`] traces it, without the constant ambient, plus the indirect light of
    /// `paths`. Only for the chapter's Phong model, the one whose ambient stands for that light.
    pub fn with_paths(
        scene: &Scene,
        specular: SpecularModel,
        width: u32,
        height: u32,
        paths: PathSettings,
    ) -> Result<ReferenceJob, String> {
        if scene.illumination != crate::IlluminationModel::Phong {
            return Err("path tracing: only for the Phong illumination model (--model phong or cook-torrance), whose I_a stands for the light between surfaces".into());
        }
        for (range, value) in [(crate::params::BOUNCES, paths.bounces), (crate::params::SPP, paths.spp)] {
            range.check(f64::from(value)).map_err(|e| e.to_string())?;
        }
        // The truth traces the environment's visibility: it bakes no occlusion grid.
        let environment =
            scene.environment.clone().map(|e| crate::lighting::env_map::Environment { occlusion: false, ..e });
        let traced = Scene { ambient: [0.0; 3], environment, ..scene.clone() };
        let mut job = ReferenceJob::new(&traced, specular, width, height);
        job.paths = Some(paths);
        // The ambient term is linear in I_a and owes nothing to the lights: two images without
        // them give it, at a fraction of the cost of the lit image's exact area lights.
        let lightless = Scene { lights: Vec::new(), ..job.scene.clone() };
        job.unit = Some([Scene { ambient: [1.0; 3], ..lightless.clone() }, lightless]);
        job.img.paths = Some(paths);
        Ok(job)
    }

    /// Trace up to `rows` more rows; true once every row is traced.
    pub fn step(&mut self, rows: u32) -> bool {
        let end = self.next_row.saturating_add(rows).min(self.img.height);
        let paths = self.paths.as_ref().zip(self.unit.as_ref());
        let env = self.env.as_ref();
        trace_rows(&self.scene, &self.geo, self.specular, &mut self.img, self.next_row..end, true, paths, env);
        self.next_row = end;
        self.done()
    }

    pub fn done(&self) -> bool {
        self.next_row >= self.img.height
    }

    /// The share of rows traced, 0 to 1.
    pub fn progress(&self) -> f32 {
        self.next_row as f32 / self.img.height.max(1) as f32
    }

    /// The image; rows not traced yet are missing, so call it once [`Self::done`].
    pub fn finish(self) -> ReferenceImage {
        self.img
    }
}

impl ReferenceImage {
    /// No pixels yet, room for `width × height`.
    fn empty(width: u32, height: u32, background: Option<[f64; 3]>) -> ReferenceImage {
        let n = (width as usize) * (height as usize);
        ReferenceImage {
            width,
            height,
            pixels: Vec::with_capacity(n),
            object: Vec::with_capacity(n),
            hidden: Vec::with_capacity(n),
            unshadowed: Vec::with_capacity(n),
            background,
            area_error: 0.0,
            paths: None,
            indirect: Vec::new(),
            per_ambient: Vec::new(),
            std_error: Vec::new(),
            fireflies: 0,
        }
    }
}

/// What the reference needs to shade any point: the scene, its inverse transforms, its shadow
/// rays, the specular model, and whether area lights are integrated exactly (with the largest
/// error estimate met so far).
struct Context<'a> {
    pub scene: &'a Scene,
    pub geo: &'a Geometry,
    pub rays: &'a ShadowRays<'a>,
    pub specular: SpecularModel,
    pub exact: bool,
    /// The scene's environment light, baked once per image.
    pub env: Option<&'a EnvLight>,
    /// How the environment shades: its nine SH terms (`Sh`, the model's own f64 twin), or traced
    /// by the path tracer (`Traced`, the truth), where the exact direct light holds none of it.
    pub env_use: EnvUse,
    /// The bits of a non-negative f64, whose order is theirs as integers.
    pub area_error: AtomicU64,
    /// Each of the scene's lights' surface (`Light::area_light`), made once for every ray that
    /// may meet one.
    pub areas: Vec<Option<crate::lighting::area::AreaLight>>,
}

/// How a [`Context`] treats the environment light.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum EnvUse {
    Sh,
    Traced,
}

/// A point shaded with and without cast shadows, and the lights hidden from it.
#[derive(Clone, Copy, Debug, Default)]
struct Shaded {
    pub lit: [f64; 3],
    pub unshadowed: [f64; 3],
    pub hidden: u8,
}

impl Context<'_> {
    /// The environment toward unit `dir` where it is shown as the background (the truth's exact
    /// radiance, the GPU's level 0 in its f64 twin): what a ray that meets nothing sees.
    pub(super) fn env_background(&self, dir: DVec3) -> Option<[f64; 3]> {
        let env = self.env.filter(|_| self.scene.environment.as_ref().is_some_and(|e| e.background))?;
        Some(env.background_toward(dir, self.env_use == EnvUse::Traced))
    }

    /// The surface at `hit` with material `base`: its shading normal (perturbed by the material's
    /// normal texture where it has one), its parameters (written into `slot` where textures or
    /// vertex colours vary them; `fresh`: `slot` is not a copy of `base` yet) and its emission.
    pub fn surface<'m>(
        &self,
        hit: &intersect::SurfaceHit,
        base: &'m Material,
        slot: &'m mut Material,
        fresh: bool,
        footprint: Option<&UvFootprint>,
    ) -> (DVec3, &'m Material, [f64; 3]) {
        let textures = &self.scene.textures;
        let n = base.normal_at(textures, hit.uv, footprint, hit.normal, hit.tangent);
        if !base.varies(hit.vertex_color) {
            return (n, base, base.emission);
        }
        let at = base.surface_at(textures, hit.uv, footprint, hit.vertex_color);
        if fresh {
            *slot = base.clone();
        }
        (slot.color, slot.mu, slot.m, slot.h, slot.r_a) = (at.color, at.mu, at.m, at.h, at.r_a);
        (n, &*slot, at.emission)
    }

    /// The model at `hit` seen from `eye` (homogeneous), with exact cast shadows: the point's
    /// parameters in a copy of its material (`tinted`, made once per image, not per pixel), or
    /// `material` when given (the glass surface's own); its emission added. With `sampler`, each
    /// area light's term is one random point's estimate of its integral (`area_term_sampled`, the
    /// path tracer's bounces), under the sampler's weight, instead of the refined integral, and
    /// the unshadowed light is not computed (it is `lit`).
    pub(crate) fn shade_hit(
        &self,
        hit: &intersect::SurfaceHit,
        eye: glam::DVec4,
        tinted: &mut [Material],
        footprint: Option<&UvFootprint>,
        material: Option<&Material>,
        sampler: Option<path::Sampler>,
    ) -> Shaded {
        let scene = self.scene;
        let mi = scene.objects[hit.object].material;
        let base = material.unwrap_or(&scene.materials[mi]);
        let (n, mat, emission) = self.surface(hit, base, &mut tinted[mi], material.is_some(), footprint);
        let p = hit.point;
        let emit = |c: [f64; 3]| -> [f64; 3] { std::array::from_fn(|i| c[i] + emission[i]) };
        let (rays, specular) = (self.rays, self.specular);
        let (hidden, dimmed) = (Cell::new(0u8), Cell::new(false));
        let drawn = self.env.filter(|_| self.env_use == EnvUse::Sh);
        let env_sh = drawn.map(|e| &e.sh);
        // The split sum where the scene's environment asks the GPU for it.
        let split_sum = scene.environment.as_ref().is_some_and(|e| e.specular);
        let env_prefiltered = drawn.filter(|_| split_sum).map(|e| e.prefiltered.as_slice());
        let env_occlusion = drawn.and_then(|e| e.occlusion.as_ref());
        let at = ShadePoint {
            p,
            n_in: n,
            eye,
            mat,
            ambient: scene.ambient,
            env_sh,
            env_prefiltered,
            env_occlusion,
            specular,
            model: scene.illumination,
        };
        let ng = hit.geometric_normal;
        let visible = rays.cell_visible(ng);
        // An area light's exact term, shadowed; its unshadowed term kept for the image without
        // cast shadows.
        let clear = Cell::new([None::<[f64; 3]>; crate::scene::MAX_LIGHTS]);
        let mut exact = |a: &AreaAt| -> Option<[f64; 3]> {
            if !self.exact {
                return None;
            }
            let shadow = a.light.shadow.casts.then_some(&visible as &dyn Fn(DVec3, DVec3) -> bool);
            let term = match sampler {
                Some(sampler) => {
                    let uw = {
                        let mut rng = sampler.rng.borrow_mut();
                        (rng.uniform(), rng.uniform())
                    };
                    area_term_sampled(a, shadow, uw, sampler.weight)?
                }
                None => match (shadow, a.light.area_light()) {
                    // Many cells from one point: only the objects near the segments are tested.
                    (Some(_), Some(area)) => area_term_exact(a, Some(&rays.cells_visible_from(ng, a.p, &area)))?,
                    _ => area_term_exact(a, shadow)?,
                },
            };
            // Only a positive error can raise the largest; skipping the rest keeps the threads
            // off the shared atomic at every path vertex, whose sampled terms have none.
            if term.error > 0.0 {
                self.area_error.fetch_max(term.error.to_bits(), Ordering::Relaxed);
            }
            let mut kept = clear.get();
            kept[a.index] = Some(term.clear);
            clear.set(kept);
            dimmed.set(dimmed.get() || term.lit != term.clear);
            // Hidden as a soft shadow is: more than half of its diffuse light blocked.
            if term.diffuse_share < 0.5 {
                hidden.set(hidden.get() | 1 << a.index);
            }
            Some(term.lit)
        };
        let lit = shade_exact(
            &at,
            &scene.lights,
            |i, light, j, l| {
                // A point source of an area light drawn as points: its own hard shadow.
                if light.drawn_as_points() {
                    let at = Light { position: area_emitter(light, j).position, area_points: 0, ..light.clone() };
                    let blocked = light.shadow.casts && rays.hidden(&at, p, ng, l);
                    dimmed.set(dimmed.get() || blocked);
                    return if blocked { 0.0 } else { 1.0 };
                }
                // An area light's soft shadow: the share of its cells a ray reaches; the
                // pixel counts as hidden from it when more than half of its light is blocked.
                let soft =
                    light.shadow.casts.then(|| rays.area_visibility(light, p, n, ng, REFERENCE_AREA_CELLS)).flatten();
                if let Some(v) = soft {
                    if v < 0.5 {
                        hidden.set(hidden.get() | 1 << i);
                    }
                    dimmed.set(dimmed.get() || v < 1.0);
                    return v;
                }
                if light.shadow.casts && rays.hidden(light, p, ng, l) {
                    hidden.set(hidden.get() | 1 << i);
                    0.0
                } else {
                    1.0
                }
            },
            &mut exact,
        );
        let hidden = hidden.get();
        // A path's vertex keeps only its lit light: no image without cast shadows is made of it.
        let unshadowed = if (hidden == 0 && !dimmed.get()) || sampler.is_some() {
            lit
        } else {
            let kept = clear.get();
            shade_exact(&at, &scene.lights, |_, _, _, _| 1.0, &mut |a| kept[a.index])
        };
        Shaded { lit: emit(lit), unshadowed: emit(unshadowed), hidden }
    }
}
