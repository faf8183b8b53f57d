//! The viewer's "difference from reference" view: the current mode's image against the f64
//! reference of the exact surface, as a FLIP error map (magma colour scale) with its numbers,
//! beside the mode's GPU time. The reference is ray-cast on a worker thread, so the viewer keeps
//! drawing while it is computed; it is computed again only when the scene, the camera, the
//! specular model or the size changes (a change of shading mode reuses it). Its legend is drawn
//! with the other overlays. In place of the FLIP map it can show the shadow error map: where the
//! GPU's lit/shadowed state (its render with shadows against the same with them off) disagrees
//! with the reference's cast shadows, with the shares of false and missed shadow. The FLIP map
//! compares with the f64 twin or with the path-traced truth (bounces and paths set in the panel),
//! which the page traces coarse first.

use eframe::egui;
use shadelab_model::reference::{PathSettings, ReferenceImage, ReferenceJob};
use shadelab_model::{Scene, ShadingMode, SpecularModel};
use shadelab_render::image_error::{self, ErrorStats, ShadowStats};
use shadelab_render::{RenderSettings, Renderer, SceneGpu, Target, target};
use std::sync::Arc;
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::mpsc::{Receiver, channel};
use target::PendingReadBack;

/// The comparison is made at most this wide (the view's aspect kept): the f64 ray cast of a
/// full window would take seconds on two cores, and the error map is smooth enough to be shown
/// scaled up.
pub const DIFFERENCE_MAX_WIDTH: u32 = 480;

/// The truth's paths until the panel changes them: 4 surface vertices a path carry all but
/// (1 − ρ)·ρ³ of the light between surfaces, and 32 paths a pixel bring its noise under the default scene's
/// ambient error (docs/reference.md) in about 2 s on two cores at the map's 480 px.
pub const VIEWER_PATHS: PathSettings = PathSettings { bounces: 4, spp: 32, seed: 1 };

/// On the page a path-traced truth is first traced at this fraction of the map's side, a
/// sixteenth of the work, and shown while the full one is traced: the page's one thread takes
/// minutes for the full map and seconds for the coarse one.
const COARSE_DIVISOR: u32 = 4;

/// What a reference image depends on: with `paths`, it is path traced.
#[derive(Clone, PartialEq)]
struct ReferenceKey {
    scene: Scene,
    specular: SpecularModel,
    size: (u32, u32),
    paths: Option<PathSettings>,
}

/// Which error map the difference view shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DifferenceKind {
    /// The FLIP error of the image (magma scale).
    #[default]
    Flip,
    /// Where the lit/shadowed state disagrees with the reference (`image_error::ShadowPixel`).
    Shadow,
    /// The chapter's constant ambient against the path-traced light between surfaces
    /// ([`VIEWER_PATHS`]), both in f64: the signed error, blue too dark, red too bright.
    Ambient,
}

/// What the FLIP error map is measured against.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Against {
    /// The f64 reference of the exact surface: the GPU's own model with exact area lights and
    /// cast shadows; under an environment light its twin (the nine SH terms, the split sum).
    #[default]
    Twin,
    /// The path-traced truth ([`DifferenceView::paths`]): the light between surfaces and the
    /// environment over the BRDF with visibility, as `--reference --bounces` traces it.
    Truth,
}

/// The path tracer's settings for the truth (the ambient error map's and, against the truth,
/// the FLIP map's): [`VIEWER_PATHS`] until the panel changes them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TruthPaths(pub PathSettings);

impl Default for TruthPaths {
    fn default() -> Self {
        TruthPaths(VIEWER_PATHS)
    }
}

/// The ambient error map's numbers: the error at its full colour, the truth's noise, and the
/// `I_a` that fits the scene best beside the scene's own.
#[derive(Clone, Copy, Debug)]
pub struct AmbientFit {
    pub scale: f64,
    pub noise: f64,
    pub fitted: [f64; 3],
    pub ambient: [f64; 3],
}

/// The map on show: what it is of, its texture, its numbers (the shadow numbers with the
/// shadow error map).
struct Shown {
    key: ReferenceKey,
    shading: ShadingMode,
    kind: DifferenceKind,
    texture: egui::TextureHandle,
    stats: ErrorStats,
    shadow: Option<ShadowStats>,
    ambient: Option<AmbientFit>,
    /// Traced at a [`COARSE_DIVISOR`]th of the map's side, ahead of the full map.
    coarse: bool,
}

/// A reference being traced: on a worker thread, or in the browser (no threads) a few rows a
/// frame ([`ROW_BUDGET_MS`]).
enum Tracing {
    /// The image and the time its tracing took, ms; the share traced so far, in ten-thousandths.
    Worker(Receiver<(ReferenceImage, f64)>, Arc<AtomicU32>),
    /// The job and the time its steps have taken so far, ms.
    #[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
    Steps(Box<ReferenceJob>, f64),
}

/// In the browser, the f64 reference traces rows for at most this long a frame, so the page keeps
/// drawing at about 20 frames a second while it runs.
pub const ROW_BUDGET_MS: f64 = 40.0;

/// The GPU's images of a comparison, read back without waiting (the browser's maps complete
/// between frames): the render, and with the shadow error map the render without shadows.
struct Reading {
    key: ReferenceKey,
    shading: ShadingMode,
    kind: DifferenceKind,
    lit: PendingReadBack,
    unshadowed: Option<PendingReadBack>,
}

#[derive(Default)]
pub struct DifferenceView {
    pub enabled: bool,
    pub kind: DifferenceKind,
    /// What the FLIP map compares with (the shadow map always takes the exact cast shadows).
    pub against: Against,
    pub paths: TruthPaths,
    reference: Option<(ReferenceKey, Arc<ReferenceImage>)>,
    /// How long the last reference took to trace, ms (on the page's one thread, or a worker on every core).
    pub traced_ms: Option<f64>,
    pending: Option<(ReferenceKey, Tracing)>,
    reading: Option<Reading>,
    shown: Option<Shown>,
    /// Whether `shown` matches the state of the last update.
    current: bool,
    /// Why the last reference could not be traced (shown in the legend).
    pub error: Option<String>,
}

/// The comparison size for a view size.
pub fn difference_size(w: u32, h: u32) -> (u32, u32) {
    if w <= DIFFERENCE_MAX_WIDTH {
        return (w.max(1), h.max(1));
    }
    let s = DIFFERENCE_MAX_WIDTH as f64 / w as f64;
    (DIFFERENCE_MAX_WIDTH, ((h as f64 * s).round() as u32).max(1))
}

/// What a view shown in place of the frame (the difference map, the shadow factor) is drawn from:
/// the frame's renderer, scene and settings, and the view's size in pixels.
pub struct SideView<'a> {
    pub ctx: &'a egui::Context,
    pub renderer: &'a mut Renderer,
    pub gpu_scene: &'a mut SceneGpu,
    pub scene: &'a Scene,
    pub settings: &'a RenderSettings,
    pub view_size: (u32, u32),
}

impl DifferenceView {
    /// The path tracer's settings when the map on show is measured against the truth.
    pub fn truth(&self) -> Option<PathSettings> {
        match (self.kind, self.against) {
            (DifferenceKind::Ambient, _) | (DifferenceKind::Flip, Against::Truth) => Some(self.paths.0),
            _ => None,
        }
    }

    /// The numbers of the map on show, if it matches the current state.
    pub fn stats(&self) -> Option<ErrorStats> {
        self.shown.as_ref().filter(|_| self.current).map(|s| s.stats)
    }

    /// The shadow numbers of the map on show, if it is the current shadow error map.
    pub fn shadow_stats(&self) -> Option<ShadowStats> {
        self.shown.as_ref().filter(|_| self.current).and_then(|s| s.shadow)
    }

    /// Whether the map on show is the coarse one, shown while the full one is traced.
    pub fn coarse_on_show(&self) -> bool {
        !self.current && self.shown.as_ref().is_some_and(|s| s.coarse)
    }

    /// The ambient error map's numbers, if it is the current map.
    pub fn ambient_fit(&self) -> Option<AmbientFit> {
        self.shown.as_ref().filter(|_| self.current).and_then(|s| s.ambient)
    }

    /// The size of the reference on hand, if any (the page's state publishes it).
    #[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
    pub fn reference_size(&self) -> Option<(u32, u32)> {
        self.reference.as_ref().map(|(k, _)| k.size)
    }

    /// Whether a reference is being computed.
    pub fn computing(&self) -> bool {
        self.pending.is_some()
    }

    /// The share of the reference traced so far, 0 to 1, while it is traced.
    pub fn progress(&self) -> Option<f32> {
        match &self.pending {
            Some((_, Tracing::Steps(job, _))) => Some(job.progress()),
            Some((_, Tracing::Worker(_, done))) => Some(done.load(Ordering::Relaxed) as f32 / 1e4),
            None => None,
        }
    }

    /// Bring the map up to date with the scene and settings; returns the texture to show, if
    /// the map matches them.
    pub fn update(&mut self, from: SideView) -> Option<egui::TextureId> {
        let SideView { ctx, renderer, gpu_scene, scene, settings, view_size } = from;
        let full = difference_size(view_size.0, view_size.1);
        let key = ReferenceKey { scene: scene.clone(), specular: settings.specular, size: full, paths: self.truth() };
        self.current = false;
        let shown_for = |k: &ReferenceKey| {
            self.shown.as_ref().filter(|s| s.key == *k && s.shading == settings.shading && s.kind == self.kind)
        };
        if let Some(s) = shown_for(&key) {
            self.current = true;
            return Some(s.texture.id());
        }
        // On the page a path-traced map comes coarse first; the coarse map stands in meanwhile.
        let coarse = (cfg!(target_arch = "wasm32") && key.paths.is_some()).then(|| ReferenceKey {
            size: ((full.0 / COARSE_DIVISOR).max(1), (full.1 / COARSE_DIVISOR).max(1)),
            ..key.clone()
        });
        let fallback = coarse.as_ref().and_then(|c| shown_for(c)).map(|s| s.texture.id());
        let full_on_hand = self.reference.as_ref().is_some_and(|(k, _)| *k == key);
        let key = match coarse {
            Some(c) if fallback.is_none() && !full_on_hand => c,
            _ => key,
        };
        self.trace(ctx, scene, settings.specular, &key);
        let reference = match &self.reference {
            Some((k, r)) if *k == key => r.clone(),
            _ => return fallback,
        };
        let fresh = |r: &Reading| r.key == key && r.shading == settings.shading && r.kind == self.kind;
        if !self.reading.as_ref().is_some_and(fresh) {
            self.reading = Some(self.start_reading(renderer, gpu_scene, scene, settings, key));
        }
        let Some(reading) = self.reading.as_ref() else { return fallback };
        let device = &renderer.device;
        let (Some(lit), unshadowed) =
            (reading.lit.try_take(device), reading.unshadowed.as_ref().map(|u| u.try_take(device)))
        else {
            ctx.request_repaint();
            return fallback;
        };
        if matches!(unshadowed, Some(None)) {
            ctx.request_repaint();
            return fallback;
        }
        let reading = self.reading.take()?;
        let image = lit.ok()?;
        let cmp = image_error::compare(&image, &reference);
        let (mut rgb, shadow) = match unshadowed.flatten() {
            None => (cmp.flip_map_rgb8, None),
            Some(unshadowed) => {
                let s = image_error::shadow_disagreement(&image, &unshadowed.ok()?, &reference);
                (s.map_rgb8(), Some(s.stats))
            }
        };
        let mut stats = cmp.stats;
        let ambient = if reading.kind == DifferenceKind::Ambient {
            let (map, constant, fit) = ambient_map(&reference, scene.ambient)?;
            (rgb, stats) = (map, constant);
            Some(fit)
        } else {
            None
        };
        let size = (image.width, image.height);
        let color = egui::ColorImage::from_rgb([size.0 as usize, size.1 as usize], &rgb);
        let texture = ctx.load_texture("difference from reference", color, egui::TextureOptions::LINEAR);
        let id = texture.id();
        let Reading { key, shading, kind, .. } = reading;
        let coarse = key.size != full;
        self.shown = Some(Shown { key, shading, kind, texture, stats, shadow, ambient, coarse });
        self.current = !coarse;
        Some(id)
    }

    /// Bring the reference up to `key`: take a finished one, and start one for the latest key when
    /// none runs. One at a time: a finished one hands its image over even if the view has moved
    /// on since (it is then replaced).
    fn trace(&mut self, ctx: &egui::Context, scene: &Scene, specular: SpecularModel, key: &ReferenceKey) {
        if let Some((k, tracing)) = self.pending.take() {
            match tracing {
                Tracing::Worker(rx, done) => match rx.try_recv() {
                    Ok((img, ms)) => {
                        self.reference = Some((k, Arc::new(img)));
                        self.traced_ms = Some(ms);
                    }
                    Err(std::sync::mpsc::TryRecvError::Empty) => self.pending = Some((k, Tracing::Worker(rx, done))),
                    // The worker is gone without an image: trace again below.
                    Err(std::sync::mpsc::TryRecvError::Disconnected) => {}
                },
                Tracing::Steps(mut job, ms) => {
                    let start = web_time::Instant::now();
                    while !job.step(1) && start.elapsed().as_secs_f64() * 1e3 < ROW_BUDGET_MS {}
                    let ms = ms + start.elapsed().as_secs_f64() * 1e3;
                    if job.done() {
                        self.reference = Some((k, Arc::new(job.finish())));
                        self.traced_ms = Some(ms);
                    } else {
                        self.pending = Some((k, Tracing::Steps(job, ms)));
                    }
                }
            }
        }
        if self.pending.is_none() && self.reference.as_ref().is_none_or(|(k, _)| k != key) {
            let (w, h) = key.size;
            let job = match key.paths {
                None => ReferenceJob::new(scene, specular, w, h),
                Some(p) => match ReferenceJob::with_paths(scene, specular, w, h, p) {
                    Ok(job) => job,
                    Err(e) => {
                        // Shown in the legend; the view keeps drawing the scene.
                        self.error = Some(e);
                        return;
                    }
                },
            };
            self.error = None;
            let tracing = if cfg!(target_arch = "wasm32") {
                Tracing::Steps(Box::new(job), 0.0)
            } else {
                let (tx, rx) = channel();
                let repaint = ctx.clone();
                let done = Arc::new(AtomicU32::new(0));
                let shared = done.clone();
                std::thread::spawn(move || {
                    let (mut job, start) = (job, web_time::Instant::now());
                    // A fiftieth of the rows a step (each step on every core), so the view can
                    // show how far it is.
                    while !job.step(h.div_ceil(50).max(1)) {
                        shared.store((job.progress() * 1e4) as u32, Ordering::Relaxed);
                        repaint.request_repaint();
                    }
                    // A send fails only when the viewer has been closed: nothing to do.
                    let _ = tx.send((job.finish(), start.elapsed().as_secs_f64() * 1e3));
                    repaint.request_repaint();
                });
                Tracing::Worker(rx, done)
            };
            self.pending = Some((key.clone(), tracing));
        }
        if self.pending.is_some() {
            // Look again soon: the worker's repaint request may come before this frame ends.
            ctx.request_repaint_after(std::time::Duration::from_millis(if cfg!(target_arch = "wasm32") {
                0
            } else {
                100
            }));
        }
    }

    /// Render the comparison's images and start reading them back. Natively the read is waited
    /// for here (the image is ready in this frame); the browser takes it in a later frame.
    fn start_reading(
        &self,
        renderer: &mut Renderer,
        gpu_scene: &mut SceneGpu,
        scene: &Scene,
        settings: &RenderSettings,
        key: ReferenceKey,
    ) -> Reading {
        let size = key.size;
        // The mode's own pipeline, built now if it is not yet: the uber pipeline that draws the
        // view meanwhile is not what the map measures.
        let background = std::mem::replace(&mut renderer.pipelines.build_in_background, false);
        let target = Target::new(&renderer.device, size.0, size.1, target::HDR_FORMAT);
        renderer.render(gpu_scene, scene, &target, settings);
        let lit = target::start_read_back(&renderer.device, &renderer.queue, &target);
        let unshadowed = (self.kind == DifferenceKind::Shadow).then(|| {
            // The same frame with every light's shadows off (its permutation may draw with
            // the uber pipeline meanwhile, whose shadow uniform is then zeroed: no shadows).
            let mut unshadowed_scene = scene.clone();
            unshadowed_scene.set_shadows(false);
            let target = Target::new(&renderer.device, size.0, size.1, target::HDR_FORMAT);
            renderer.render(gpu_scene, &unshadowed_scene, &target, settings);
            target::start_read_back(&renderer.device, &renderer.queue, &target)
        });
        renderer.pipelines.build_in_background = background;
        #[cfg(not(target_arch = "wasm32"))]
        let _ = renderer.device.poll(wgpu::PollType::wait_indefinitely());
        Reading { key, shading: settings.shading, kind: self.kind, lit, unshadowed }
    }
}

/// The ambient error map: the chapter's constant ambient against the path-traced `truth`, both
/// in f64 (`AmbientLadder`), as RGB8, with the constant image's error numbers and the fit.
fn ambient_map(truth: &ReferenceImage, ambient: [f64; 3]) -> Option<(Vec<u8>, ErrorStats, AmbientFit)> {
    let ladder = shadelab_model::reference::AmbientLadder::new(truth, ambient)?;
    let constant = ladder.constant();
    let error = ladder.error(&constant);
    let scale = crate::ambient_views::map_scale(&error, &truth.object);
    let map = crate::ambient_views::diverging_map(&error, &truth.object, scale, (truth.width, truth.height));
    let image = shadelab_render::LinearImage {
        width: truth.width,
        height: truth.height,
        pixels: constant.iter().map(|c| [c[0] as f32, c[1] as f32, c[2] as f32, 1.0]).collect(),
    };
    let stats = image_error::compare(&image, truth).stats;
    let fit = AmbientFit { scale, noise: ladder.noise(), fitted: ladder.fitted_ambient(), ambient };
    Some((map.to_srgb8(), stats, fit))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comparison_size_keeps_aspect_and_caps_width() {
        assert_eq!(difference_size(320, 180), (320, 180));
        assert_eq!(difference_size(960, 540), (480, 270));
        assert_eq!(difference_size(4000, 10), (480, 1));
        assert_eq!(difference_size(0, 0), (1, 1));
    }
}
