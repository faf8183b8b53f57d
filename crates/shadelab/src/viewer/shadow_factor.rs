//! The viewer's shadow-factor view (`Term::Shadow`, V): the frame rendered with and without cast
//! shadows at the difference view's size, their ratio per pixel as grey
//! (`shadelab_render::shadow_factor_with`), shown in place of the frame. It is redrawn only when
//! the scene, the mode or the size changes.

use super::difference::SideView;
use eframe::egui;
use shadelab_model::Scene;
use shadelab_render::{RenderSettings, Target, target};

/// The factor image on show and what it was made from.
#[derive(Default)]
pub struct ShadowFactorView {
    shown: Option<(Scene, RenderSettings, (u32, u32), egui::TextureHandle)>,
}

impl ShadowFactorView {
    /// The texture of the factor of `scene` (its shadowed terms) at (at most) the difference
    /// view's size for `view_size`.
    pub fn update(&mut self, from: SideView) -> egui::TextureId {
        let SideView { ctx, renderer, gpu_scene, scene, settings, view_size } = from;
        let size = super::difference::difference_size(view_size.0, view_size.1);
        if let Some((s, st, sz, t)) = &self.shown
            && s == scene
            && st == settings
            && *sz == size
        {
            return t.id();
        }
        let target = Target::new(&renderer.device, size.0, size.1, target::HDR_FORMAT);
        let factor = shadelab_render::shadow_factor_with(renderer, gpu_scene, scene, &target, settings);
        let color = egui::ColorImage::from_rgb([size.0 as usize, size.1 as usize], &factor.to_srgb8());
        let texture = ctx.load_texture("cast-shadow factor", color, egui::TextureOptions::LINEAR);
        let id = texture.id();
        self.shown = Some((scene.clone(), *settings, size, texture));
        id
    }

    /// The factor image's size once drawn (tests).
    pub fn size(&self) -> Option<(u32, u32)> {
        self.shown.as_ref().map(|s| s.2)
    }
}
