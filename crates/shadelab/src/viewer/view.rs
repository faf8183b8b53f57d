//! The view: the scene drawn by the shared `Renderer` into an offscreen target at the central
//! area's size, copied into the window by a paint callback (blit.rs), or the difference view's
//! error map shown by egui in its place, with the overlays on top (the self-shadow boundary drawn
//! into the target after the frame).

use super::difference::SideView;
use super::{Viewer, overlays};
use eframe::egui::{self, Color32, Rect, pos2};
use shadelab_model::params;
use shadelab_render::Target;

/// Format of the view's target: sRGB-encoded bytes, as the window and egui's textures hold them.
const VIEW_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// The view's target (blit.rs copies it into the window).
pub(super) struct View {
    pub target: Target,
}

impl Viewer {
    /// Draw the self-shadow boundary over the view or not (the panel's switch).
    pub fn set_self_shadow_boundary(&mut self, on: bool) {
        self.boundary.enabled = on;
    }

    /// How many vertex-normal and crease lines the last frame drew (0 for a switch that is off).
    pub fn mesh_line_counts(&self) -> (u32, u32) {
        (self.normals.line_count(), self.creases.line_count())
    }

    /// How many self-shadow boundary edges the last frame drew (0 with the switch off).
    pub fn self_shadow_boundary_edges(&self) -> u32 {
        self.boundary.line_count()
    }

    fn ensure_view(&mut self, w: u32, h: u32) {
        if self.view.as_ref().is_some_and(|v| v.target.width == w && v.target.height == h) {
            return;
        }
        let device = &self.renderer.device;
        let target = Target::new(device, w, h, VIEW_FORMAT);
        if let Some(blit) = self.egui_renderer.write().callback_resources.get_mut::<super::blit::BlitResources>() {
            blit.set_view(device, &target);
        }
        self.view = Some(View { target });
    }

    /// The central area: steer the camera, draw the frame, show it with its overlays.
    pub(super) fn viewport(&mut self, ui: &mut egui::Ui) {
        let avail = ui.available_size();
        let (rect, response) = ui.allocate_exact_size(avail, egui::Sense::click_and_drag());
        self.view_rect = Some(rect);
        let ppp = ui.ctx().pixels_per_point();
        let w = ((avail.x * ppp).round().max(0.0) as u32).min(params::WIDTH.max as u32);
        let h = ((avail.y * ppp).round().max(0.0) as u32).min(params::HEIGHT.max as u32);
        if w == 0 || h == 0 {
            return; // minimized or squeezed to nothing: no frame to draw
        }
        self.orbit.steer(ui, &response, &self.base_camera);
        self.scene.camera = self.orbit.camera(&self.base_camera).fitted(w as f64 / h as f64);
        // A click (not a drag) picks the pixel under the cursor for the lobe window.
        if response.clicked()
            && let Some(pos) = response.interact_pointer_pos()
        {
            let px = (((pos.x - rect.min.x) * ppp).max(0.0) as u32).min(w - 1);
            let py = (((pos.y - rect.min.y) * ppp).max(0.0) as u32).min(h - 1);
            self.lobe.pick(&self.scene, (px, py), (w, h));
        }
        let (shown, error_map) = self.draw_view(ui, (w, h));
        self.paint_view(ui, rect, ppp, (w, h), shown, error_map);
    }

    /// Draw the frame and its overlays into the view's target, and the picture shown in its
    /// place if any; returns that picture and whether it is the difference view's error map.
    fn draw_view(&mut self, ui: &egui::Ui, (w, h): (u32, u32)) -> (Option<egui::TextureId>, bool) {
        self.ensure_view(w, h);
        let view = self.view.as_ref().expect("view just made");
        // The frame as drawn, derived once per change (derive.rs); the uniforms written when it
        // changed or when another draw (the difference view's, a screenshot's) wrote over them.
        let drawn = self.derived.get(&self.scene, &self.settings, self.term, (w, h));
        // Which derivation and camera the uniforms hold, and the write count after writing them
        // (the panel may have made this frame's derivation already). An orbit writes them again
        // without deriving; the shadow maps are redrawn only where a layer's projection changed.
        let now = (drawn.derivation, self.gpu_scene.uniform_writes, drawn.scene.camera);
        if self.uniforms_written != Some(now) {
            self.renderer.write_uniforms_for(
                &mut self.gpu_scene,
                &drawn.scene,
                &view.target,
                &self.settings,
                drawn.program,
            );
            self.small_area_lights = drawn.small_area_lights.clone();
            self.uniforms_written = Some((now.0, now.1 + 1, now.2));
        }
        let program = drawn.program;
        // With timestamps the frame is timed in the ring and never waited for (the panel shows
        // the newest time read back); without them the CPU's submit + wait is the only clock.
        self.frame_ms = if self.ring.timed() {
            self.ring.frame(&mut self.renderer, &mut self.gpu_scene, &view.target, program).or(self.frame_ms)
        } else {
            Some(self.timer.frame(&mut self.renderer, &mut self.gpu_scene, &view.target, program))
        };
        self.boundary.draw(&self.renderer, &view.target, &drawn.scene);
        self.creases.draw(&self.renderer, &view.target, &drawn.scene);
        self.normals.draw(&self.renderer, &view.target, &drawn.scene);
        // The lights' maps this frame drew, for their panel sections (read back only on a change).
        self.shadow_maps.update(ui.ctx(), &self.renderer, &self.gpu_scene, &drawn.scene);
        // Another picture in the view's place (an egui texture), or the scene itself.
        let mut shown = None;
        // The scenes the f64 reference renders: analytic shapes and file meshes within its limit.
        let covered = shadelab_model::scene_variants::reference_covers(&self.scene);
        let factor = self.term == shadelab_model::terms::Term::Shadow;
        let ctx = ui.ctx().clone();
        let from = SideView {
            ctx: &ctx,
            renderer: &mut self.renderer,
            gpu_scene: &mut self.gpu_scene,
            scene: &drawn.scene,
            settings: &self.settings,
            view_size: (w, h),
        };
        if factor {
            shown = Some(self.shadow_factor.update(from));
        } else if self.difference.enabled && covered {
            shown = self.difference.update(from);
        }
        (shown, self.difference.enabled && covered && !factor)
    }

    /// Paint the view: `shown` or the scene itself, then the difference view's legend when
    /// `error_map`, else the light markers and the picked pixel.
    fn paint_view(
        &self,
        ui: &egui::Ui,
        rect: Rect,
        ppp: f32,
        (w, h): (u32, u32),
        shown: Option<egui::TextureId>,
        error_map: bool,
    ) {
        let painter = ui.painter_at(rect);
        match shown {
            Some(t) => {
                painter.image(t, rect, Rect::from_min_max(pos2(0.0, 0.0), pos2(1.0, 1.0)), Color32::WHITE);
            }
            // The scene itself: its texels straight into the window (blit.rs).
            None => {
                painter.add(super::blit::shape(rect));
            }
        }
        if error_map {
            let mode = format!("{} shading, {} specular", self.settings.shading, self.settings.specular);
            let env = self.scene.environment.is_some();
            let (ms, live) = (self.frame_ms, self.show_live_numbers);
            overlays::difference_legend(&painter, rect, &self.difference, &mode, ms, live, env);
            return; // the light markers would hide the error map
        }
        overlays::light_markers(&painter, rect, &self.scene, self.orbit.target, (w, h));
        if let Some(p) = self.lobe.picked() {
            let at = rect.min + egui::vec2(p.pixel.0 as f32 + 0.5, p.pixel.1 as f32 + 0.5) / ppp;
            painter.circle_stroke(at, 4.0, egui::Stroke::new(1.5, Color32::WHITE));
        }
    }
}
