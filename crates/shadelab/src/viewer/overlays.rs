//! What the viewer draws over the scene: a marker where each light is (pinned to the edge when
//! off the view), and the difference view's legend (the magma scale and the error numbers).

use super::difference::DifferenceView;
use eframe::egui::{self, Color32, Rect, pos2, vec2};
use glam::DVec3;
use shadelab_model::params::NamedValue;
use shadelab_model::{LightKind, Scene};

/// Smallest |w| a projected light is divided by: a light in the eye's plane (w = 0) still gets a
/// finite position, far off the view, where its marker is pinned to the edge.
const CLIP_W_MIN: f64 = 1e-9;
/// How far behind the orbit's target a directional light's marker stands, scene units (its
/// direction has no position; this puts the marker where the light comes from).
const DIRECTIONAL_MARKER_DISTANCE: f64 = 4.0;
/// Markers stay this many points inside the view's edge.
const MARKER_MARGIN: f32 = 12.0;
const MARKER_RADIUS: f32 = 6.0;

/// A marker at each point or spot light, and at the far point a directional light comes from,
/// each labelled with its number and kind.
pub(super) fn light_markers(
    painter: &egui::Painter,
    rect: Rect,
    scene: &Scene,
    orbit_target: DVec3,
    (w, h): (u32, u32),
) {
    let vp = scene.camera.projection(w as f64 / h as f64) * scene.camera.view();
    for (i, l) in scene.lights.iter().enumerate() {
        let p = match l.kind {
            LightKind::Point | LightKind::Spot => l.position,
            LightKind::Directional => orbit_target - l.direction * DIRECTIONAL_MARKER_DISTANCE,
        };
        let clip = vp * p.extend(1.0);
        // Behind the eye the projection flips: divide by |w| so the marker keeps its side.
        let (x, y) = (clip.x / clip.w.abs().max(CLIP_W_MIN), clip.y / clip.w.abs().max(CLIP_W_MIN));
        let at = pos2(
            rect.left() + ((x + 1.0) * 0.5) as f32 * rect.width(),
            rect.top() + ((1.0 - y) * 0.5) as f32 * rect.height(),
        );
        let c = l.color.map(|c| (c.clamp(0.0, 1.0) * 255.0) as u8);
        let color = Color32::from_rgb(c[0], c[1], c[2]);
        let inner = rect.shrink(MARKER_MARGIN);
        let on_view = clip.w > 0.0 && inner.contains(at);
        // A light off the view is pinned to the view's edge and drawn hollow.
        let at = if on_view { at } else { inner.clamp(at) };
        if on_view {
            painter.circle(at, MARKER_RADIUS, color, egui::Stroke::new(1.5, Color32::BLACK));
        } else {
            painter.circle_stroke(at, MARKER_RADIUS, egui::Stroke::new(2.5, color));
        }
        let kind = match l.kind {
            LightKind::Directional => "dir.",
            k => k.name(),
        };
        let label = format!("L{} {kind}{}", i + 1, if on_view { "" } else { " (off view)" });
        let right_half = at.x > rect.center().x;
        let (align, offset) = if right_half {
            (egui::Align2::RIGHT_TOP, egui::vec2(-9.0, 6.0))
        } else {
            (egui::Align2::LEFT_TOP, egui::vec2(9.0, 6.0))
        };
        painter.text(at + offset, align, label, egui::FontId::proportional(12.0), Color32::WHITE);
    }
}

/// The difference view's legend over the view: the magma scale, and the numbers of the map on
/// show for `mode` beside its GPU time (`live`: the time is shown).
pub(super) fn difference_legend(
    painter: &egui::Painter,
    rect: Rect,
    difference: &DifferenceView,
    mode: &str,
    gpu_ms: Option<f64>,
    live: bool,
) {
    let bar = Rect::from_min_size(pos2(rect.left() + 12.0, rect.bottom() - 34.0), vec2(256.0, 12.0));
    let scale = shadelab_render::image_error::magma_scale();
    for (i, c) in scale.iter().enumerate() {
        let x = bar.left() + i as f32 * bar.width() / scale.len() as f32;
        let r = Rect::from_min_max(pos2(x, bar.top()), pos2(x + bar.width() / scale.len() as f32 + 0.5, bar.bottom()));
        painter.rect_filled(r, 0.0, Color32::from_rgb(c[0], c[1], c[2]));
    }
    let font = egui::FontId::proportional(12.0);
    painter.text(bar.left_bottom() + vec2(0.0, 2.0), egui::Align2::LEFT_TOP, "0", font.clone(), Color32::WHITE);
    painter.text(
        bar.right_bottom() + vec2(0.0, 2.0),
        egui::Align2::RIGHT_TOP,
        "1  FLIP error",
        font.clone(),
        Color32::WHITE,
    );
    let text = match (difference.stats(), difference.computing()) {
        (Some(s), _) => {
            let time = match gpu_ms {
                Some(ms) if live => format!(" · {ms:.2} ms GPU"),
                _ => String::new(),
            };
            format!(
                "{mode}{time}\nagainst the f64 reference of the exact surface: FLIP mean {:.4} · RMSE {:.2e} · max {:.3} · {:.1} % of pixels off by > 1/255",
                s.flip_mean,
                s.rmse,
                s.max_abs,
                s.share_off * 100.0
            )
        }
        (None, true) => "computing the f64 reference…".into(),
        (None, false) => String::new(),
    };
    painter.text(rect.left_top() + vec2(10.0, 8.0), egui::Align2::LEFT_TOP, text, font, Color32::WHITE);
}
