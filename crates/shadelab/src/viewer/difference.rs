//! The viewer's "difference from reference" view: the current mode's image against the f64
//! reference of the exact surface, as a FLIP error map (magma colour scale) with its numbers,
//! beside the mode's GPU time. The reference is ray-cast on a worker thread, so the viewer keeps
//! drawing while it is computed; it is computed again only when the scene, the camera, the
//! specular model or the size changes (a change of shading mode reuses it). Its legend is drawn
//! with the other overlays. In place of the FLIP map it can show the shadow error map: where the
//! GPU's lit/shadowed state (its render with shadows against the same with them off) disagrees
//! with the reference's cast shadows, with the shares of false and missed shadow.

use eframe::egui;
use shadelab_model::reference::{ReferenceImage, render_reference};
use shadelab_model::{Scene, ShadingMode, SpecularModel};
use shadelab_render::image_error::{self, ErrorStats, ShadowStats};
use shadelab_render::{RenderSettings, Renderer, SceneGpu, Target, target};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, channel};

/// The comparison is made at most this wide (the view's aspect kept): the f64 ray cast of a
/// full window would take seconds on two cores, and the error map is smooth enough to be shown
/// scaled up.
pub const DIFFERENCE_MAX_WIDTH: u32 = 480;

/// What a reference image depends on.
#[derive(Clone, PartialEq)]
struct ReferenceKey {
    scene: Scene,
    specular: SpecularModel,
    size: (u32, u32),
}

/// Which error map the difference view shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DifferenceKind {
    /// The FLIP error of the image (magma scale).
    #[default]
    Flip,
    /// Where the lit/shadowed state disagrees with the reference (`image_error::ShadowPixel`).
    Shadow,
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
}

#[derive(Default)]
pub struct DifferenceView {
    pub enabled: bool,
    pub kind: DifferenceKind,
    reference: Option<(ReferenceKey, Arc<ReferenceImage>)>,
    pending: Option<(ReferenceKey, Receiver<ReferenceImage>)>,
    shown: Option<Shown>,
    /// Whether `shown` matches the state of the last update.
    current: bool,
}

/// The comparison size for a view size.
pub fn difference_size(w: u32, h: u32) -> (u32, u32) {
    if w <= DIFFERENCE_MAX_WIDTH {
        return (w.max(1), h.max(1));
    }
    let s = DIFFERENCE_MAX_WIDTH as f64 / w as f64;
    (DIFFERENCE_MAX_WIDTH, ((h as f64 * s).round() as u32).max(1))
}

impl DifferenceView {
    /// The numbers of the map on show, if it matches the current state.
    pub fn stats(&self) -> Option<ErrorStats> {
        self.shown.as_ref().filter(|_| self.current).map(|s| s.stats)
    }

    /// The shadow numbers of the map on show, if it is the current shadow error map.
    pub fn shadow_stats(&self) -> Option<ShadowStats> {
        self.shown.as_ref().filter(|_| self.current).and_then(|s| s.shadow)
    }

    /// Whether a reference is being computed.
    pub fn computing(&self) -> bool {
        self.pending.is_some()
    }

    /// Bring the map up to date with the scene and settings; returns the texture to show, if
    /// the map matches them.
    pub fn update(
        &mut self,
        ctx: &egui::Context,
        renderer: &mut Renderer,
        gpu_scene: &SceneGpu,
        scene: &Scene,
        settings: &RenderSettings,
        view_size: (u32, u32),
    ) -> Option<egui::TextureId> {
        let size = difference_size(view_size.0, view_size.1);
        let key = ReferenceKey { scene: scene.clone(), specular: settings.specular, size };
        self.current = false;
        if let Some(s) = &self.shown
            && s.key == key
            && s.shading == settings.shading
            && s.kind == self.kind
        {
            self.current = true;
            return Some(s.texture.id());
        }
        // One worker at a time: a finished one hands its image over (even if the view has moved
        // on since; it is then replaced), and a new one starts only for the latest key.
        if let Some((k, rx)) = &self.pending
            && let Ok(img) = rx.try_recv()
        {
            self.reference = Some((k.clone(), Arc::new(img)));
            self.pending = None;
        }
        if self.pending.is_none() && self.reference.as_ref().is_none_or(|(k, _)| *k != key) {
            let (tx, rx) = channel();
            let (s, spec, (w, h)) = (scene.clone(), settings.specular, size);
            let repaint = ctx.clone();
            std::thread::spawn(move || {
                // A send fails only when the viewer has been closed: nothing to do.
                let _ = tx.send(render_reference(&s, spec, w, h));
                repaint.request_repaint();
            });
            self.pending = Some((key.clone(), rx));
        }
        if self.pending.is_some() {
            // Look again soon: the worker's repaint request may come before this frame ends.
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
        let reference = match &self.reference {
            Some((k, r)) if *k == key => r.clone(),
            _ => return None,
        };
        let target = Target::new(&renderer.device, size.0, size.1, target::HDR_FORMAT);
        renderer.render(gpu_scene, scene, &target, settings);
        let image = target::read_back(&renderer.device, &renderer.queue, &target);
        let cmp = image_error::compare(&image, &reference);
        let (rgb, shadow) = match self.kind {
            DifferenceKind::Flip => (cmp.flip_map_rgb8, None),
            DifferenceKind::Shadow => {
                // The same frame with every light's shadows off (its permutation may draw with
                // the uber pipeline meanwhile, whose shadow uniform is then zeroed: no shadows).
                let mut unshadowed_scene = scene.clone();
                unshadowed_scene.set_shadows(false);
                renderer.render(gpu_scene, &unshadowed_scene, &target, settings);
                let unshadowed = target::read_back(&renderer.device, &renderer.queue, &target);
                let s = image_error::shadow_disagreement(&image, &unshadowed, &reference);
                (s.map_rgb8(), Some(s.stats))
            }
        };
        let color = egui::ColorImage::from_rgb([size.0 as usize, size.1 as usize], &rgb);
        let texture = ctx.load_texture("difference from reference", color, egui::TextureOptions::LINEAR);
        let id = texture.id();
        let (shading, kind, stats) = (settings.shading, self.kind, cmp.stats);
        self.shown = Some(Shown { key, shading, kind, texture, stats, shadow });
        self.current = true;
        Some(id)
    }
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
