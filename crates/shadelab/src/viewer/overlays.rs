//! What the viewer draws over the scene: a marker where each light is (pinned to the edge when
//! off the view), the difference view's legend (the magma scale or the shadow error map's
//! colours, and the error numbers), and the
//! self-shadow boundary (drawn by the GPU into the view's target, depth-tested).

use super::difference::{DifferenceKind, DifferenceView};
use eframe::egui::{self, Color32, Rect, pos2, vec2};
use glam::DVec3;
use shadelab_model::params::NamedValue;
use shadelab_model::terminator::SceneEdges;
use shadelab_model::{Light, Object, Scene};
use shadelab_render::image_error::ShadowPixel;
use shadelab_render::overlay_pass::{CREASES_COLOR, NORMALS_COLOR, OverlayPass, TERMINATOR_COLOR};
use shadelab_render::{Renderer, Target};

/// Smallest |w| a projected light is divided by: a light in the eye's plane (w = 0) still gets a
/// finite position, far off the view, where its marker is pinned to the edge.
const CLIP_W_MIN: f64 = 1e-9;
/// How far behind the orbit's target a directional light's marker stands, scene units (its
/// direction has no position; this puts the marker where the light comes from).
const DIRECTIONAL_MARKER_DISTANCE: f64 = 4.0;
/// Markers stay this many points inside the view's edge.
const MARKER_MARGIN: f32 = 12.0;
const MARKER_RADIUS: f32 = 6.0;
/// Points between two labels that would have overlapped and were moved apart.
const LABEL_GAP: f32 = 2.0;

/// A marker at each point or spot light, and at the far point a directional light comes from,
/// each labelled with its number and kind.
pub(super) fn light_markers(
    painter: &egui::Painter,
    rect: Rect,
    scene: &Scene,
    orbit_target: DVec3,
    (w, h): (u32, u32),
) {
    // A view narrower than the markers' margins has no room for them.
    if !rect.shrink(MARKER_MARGIN).is_positive() {
        return;
    }
    let vp = scene.camera.projection(w as f64 / h as f64) * scene.camera.view();
    let mut placed: Vec<Rect> = Vec::with_capacity(scene.lights.len());
    for (i, l) in scene.lights.iter().enumerate() {
        let p =
            if l.kind.is_directional() { orbit_target - l.direction * DIRECTIONAL_MARKER_DISTANCE } else { l.position };
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
        let kind = if l.kind.is_directional() { "dir." } else { l.kind.name() };
        let label = format!("L{} {kind}{}", i + 1, if on_view { "" } else { " (off view)" });
        let right_half = at.x > rect.center().x;
        let (align, offset) = if right_half {
            (egui::Align2::RIGHT_TOP, egui::vec2(-9.0, 6.0))
        } else {
            (egui::Align2::LEFT_TOP, egui::vec2(9.0, 6.0))
        };
        let galley = painter.layout_no_wrap(label, egui::FontId::proportional(12.0), Color32::WHITE);
        let wanted = align.anchor_size(at + offset, galley.size());
        let rect = unstacked(wanted, &placed, rect);
        painter.galley(rect.min, galley, Color32::WHITE);
        placed.push(rect);
    }
}

/// Where a label goes: where it wants to be, raised to end inside `view` (a light pinned to the
/// bottom edge), then moved past the labels `placed` before it that it would cover (two lights
/// near each other, or pinned to the same edge): down while it stays in `view`, else up, else
/// whichever leaves less of it outside.
fn unstacked(wanted: Rect, placed: &[Rect], view: Rect) -> Rect {
    let inside = wanted.translate(vec2(0.0, (view.bottom() - wanted.bottom()).min(0.0)));
    let down = moved_clear(inside, placed, 1.0);
    if down.bottom() <= view.bottom() {
        return down;
    }
    let up = moved_clear(inside, placed, -1.0);
    if view.top() - up.top() <= down.bottom() - view.bottom() { up } else { down }
}

/// `r` moved along y (`dir`: 1 down, -1 up) past each placed rectangle it meets, until it meets
/// none. It only moves one way, so it passes each placed rectangle at most once.
fn moved_clear(mut r: Rect, placed: &[Rect], dir: f32) -> Rect {
    for _ in 0..placed.len() {
        let Some(p) = placed.iter().find(|p| p.intersects(r)) else { break };
        let step = if dir > 0.0 { p.bottom() - r.top() } else { p.top() - r.bottom() };
        r = r.translate(vec2(0.0, step + dir * LABEL_GAP));
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    fn label(x: f32, y: f32) -> Rect {
        Rect::from_min_size(pos2(x, y), vec2(100.0, 14.0))
    }

    #[test]
    fn labels_that_would_overlap_are_moved_apart() {
        let view = Rect::from_min_size(pos2(0.0, 0.0), vec2(400.0, 300.0));
        // Three lights pinned to the same edge, one apart from them.
        let wanted = [label(10.0, 20.0), label(12.0, 24.0), label(300.0, 22.0), label(11.0, 21.0)];
        let mut placed = Vec::new();
        for w in wanted {
            placed.push(unstacked(w, &placed, view));
        }
        assert_eq!(placed[0], wanted[0], "the first label stays where it wants to be");
        assert_eq!(placed[2], wanted[2], "a label that covers none stays");
        for (i, a) in placed.iter().enumerate() {
            assert_eq!(a.size(), wanted[i].size());
            assert_eq!(a.left(), wanted[i].left(), "labels move along y only");
            for b in &placed[i + 1..] {
                assert!(!a.intersects(*b), "{a:?} and {b:?} overlap");
            }
        }
        assert!(placed[1].top() > placed[0].bottom() && placed[3].top() > placed[1].bottom());
    }

    #[test]
    fn labels_of_lights_pinned_to_the_bottom_stay_in_the_view_and_apart() {
        let view = Rect::from_min_size(pos2(0.0, 0.0), vec2(400.0, 300.0));
        // A marker pinned to the bottom edge, its label below it as `light_markers` anchors it.
        let marker = pos2(50.0, view.bottom() - MARKER_MARGIN);
        let wanted = Rect::from_min_size(marker + vec2(9.0, 6.0), vec2(100.0, 14.0));
        assert!(wanted.bottom() > view.bottom(), "the case: the label would hang out of the view");
        let first = unstacked(wanted, &[], view);
        assert_eq!(first.bottom(), view.bottom());
        let second = unstacked(wanted.translate(vec2(4.0, 0.0)), &[first], view);
        assert!(second.bottom() < first.top(), "{second:?} should stand above {first:?}");
        // A view too short for both: the second label leaves as little of it outside as it can.
        let short = Rect::from_min_size(pos2(0.0, 280.0), vec2(400.0, 20.0));
        let first = unstacked(wanted, &[], short);
        let second = unstacked(wanted, &[first], short);
        assert!(!second.intersects(first));
        assert!(second.bottom() - short.bottom() <= 16.0 + LABEL_GAP && short.top() - second.top() <= 16.0);
    }
}

/// The difference view's legend over the view: the magma scale or the shadow error map's
/// colours, and the numbers of the map on show for `mode` beside its GPU time (`live`: the time
/// is shown), with the shadow shares under the shadow error map; `environment`: the scene has an
/// environment light, under which the f64 reference is the GPU's twin.
pub(super) fn difference_legend(
    painter: &egui::Painter,
    rect: Rect,
    difference: &DifferenceView,
    mode: &str,
    gpu_ms: Option<f64>,
    live: bool,
    environment: bool,
) {
    let font = egui::FontId::proportional(12.0);
    match difference.kind {
        DifferenceKind::Flip => magma_legend(painter, rect, &font),
        DifferenceKind::Shadow => shadow_legend(painter, rect, &font),
        DifferenceKind::Ambient => ambient_legend(painter, rect, &font, difference.ambient_fit().map(|f| f.scale)),
    }
    let against = match (difference.kind, difference.truth()) {
        (DifferenceKind::Ambient, Some(p)) => format!(
            "the chapter's constant I_a·r_a·C (f64) against the path-traced light between surfaces ({} vertices, {} paths a pixel)",
            p.bounces, p.spp
        ),
        (_, Some(p)) => format!("against the path-traced truth ({} vertices, {} paths a pixel)", p.bounces, p.spp),
        _ if environment => "against the f64 twin (under the environment: the GPU's SH terms and split sum)".into(),
        _ => "against the f64 reference of the exact surface".to_string(),
    };
    let label = if difference.truth().is_some() { "path-traced truth" } else { "f64 reference" };
    // The path-traced maps' longer heading takes its own line.
    let sep = if difference.truth().is_some() { "\n" } else { " " };
    let text = match (difference.stats(), difference.computing()) {
        (Some(s), _) => {
            let time = match gpu_ms {
                Some(ms) if live => format!(" · {ms:.2} ms GPU"),
                _ => String::new(),
            };
            let shadow = match difference.shadow_stats() {
                Some(sh) => format!(
                    "\nlit/shadowed state: {:.2} % of pixels disagree ({:.2} % false shadow, {:.2} % missed shadow; {:.1} % shadowed in the reference)",
                    sh.share_disagreeing * 100.0,
                    sh.share_false_shadow * 100.0,
                    sh.share_missed_shadow * 100.0,
                    sh.share_shadowed_reference * 100.0
                ),
                None => String::new(),
            };
            let fit = match difference.ambient_fit() {
                Some(f) => format!(
                    "\ntruth's noise {:.1e} · I_a that fits best [{:.3}, {:.3}, {:.3}], the scene's [{:.3}, {:.3}, {:.3}]",
                    f.noise, f.fitted[0], f.fitted[1], f.fitted[2], f.ambient[0], f.ambient[1], f.ambient[2]
                ),
                None => String::new(),
            };
            format!(
                "{mode}{time}\n{against}:{sep}FLIP mean {:.4} · RMSE {:.2e} · max {:.3} · {:.1} % of pixels off by > 1/255{shadow}{fit}",
                s.flip_mean,
                s.rmse,
                s.max_abs,
                s.share_off * 100.0
            )
        }
        (None, true) => match difference.progress() {
            Some(p) if difference.coarse_on_show() => {
                format!("a coarse map (a quarter of the side) while the {label} is traced in full… {:.0} %", p * 100.0)
            }
            // In the browser it is traced a few rows a frame, on the page's one thread.
            Some(p) if cfg!(target_arch = "wasm32") => {
                format!("computing the {label}… {:.0} % (in this page's thread, a few rows a frame)", p * 100.0)
            }
            Some(p) => {
                let threads = shadelab_model::reference::reference_threads();
                format!("computing the {label}… {:.0} % (on {threads} thread(s))", p * 100.0)
            }
            None => format!("computing the {label}…"),
        },
        (None, false) => difference.error.clone().unwrap_or_default(),
    };
    painter.text(rect.left_top() + vec2(10.0, 8.0), egui::Align2::LEFT_TOP, text, font, Color32::WHITE);
}

/// The FLIP map's magma scale from 0 to 1 at the view's bottom left.
fn magma_legend(painter: &egui::Painter, rect: Rect, font: &egui::FontId) {
    let bar = Rect::from_min_size(pos2(rect.left() + 12.0, rect.bottom() - 34.0), vec2(256.0, 12.0));
    let scale = shadelab_render::image_error::magma_scale();
    for (i, c) in scale.iter().enumerate() {
        let x = bar.left() + i as f32 * bar.width() / scale.len() as f32;
        let r = Rect::from_min_max(pos2(x, bar.top()), pos2(x + bar.width() / scale.len() as f32 + 0.5, bar.bottom()));
        painter.rect_filled(r, 0.0, Color32::from_rgb(c[0], c[1], c[2]));
    }
    painter.text(bar.left_bottom() + vec2(0.0, 2.0), egui::Align2::LEFT_TOP, "0", font.clone(), Color32::WHITE);
    painter.text(
        bar.right_bottom() + vec2(0.0, 2.0),
        egui::Align2::RIGHT_TOP,
        "1  FLIP error",
        font.clone(),
        Color32::WHITE,
    );
}

/// The ambient error map's scale at the view's bottom left: blue (too dark) through white to red
/// (too bright), at ± its full colour when known.
fn ambient_legend(painter: &egui::Painter, rect: Rect, font: &egui::FontId, scale: Option<f64>) {
    let bar = Rect::from_min_size(pos2(rect.left() + 12.0, rect.bottom() - 34.0), vec2(256.0, 12.0));
    let steps = 64;
    for i in 0..steps {
        let t = (i as f64 + 0.5) / steps as f64 * 2.0 - 1.0;
        let map = crate::ambient_views::diverging_map(&[[t, t, t]], &[Some(0)], 1.0, (1, 1)).to_srgb8();
        let x = bar.left() + i as f32 * bar.width() / steps as f32;
        let r = Rect::from_min_max(pos2(x, bar.top()), pos2(x + bar.width() / steps as f32 + 0.5, bar.bottom()));
        painter.rect_filled(r, 0.0, Color32::from_rgb(map[0], map[1], map[2]));
    }
    let s = scale.map_or(String::new(), |s| format!("{s:.3} "));
    let left = format!("−{s}too dark");
    painter.text(bar.left_bottom() + vec2(0.0, 2.0), egui::Align2::LEFT_TOP, left, font.clone(), Color32::WHITE);
    let right = format!("too bright +{s}");
    painter.text(bar.right_bottom() + vec2(0.0, 2.0), egui::Align2::RIGHT_TOP, right, font.clone(), Color32::WHITE);
}

/// The shadow error map's four colours, each with what it means, at the view's bottom left.
fn shadow_legend(painter: &egui::Painter, rect: Rect, font: &egui::FontId) {
    let entries = [
        (ShadowPixel::Lit, "lit on both"),
        (ShadowPixel::Shadowed, "shadowed on both"),
        (ShadowPixel::FalseShadow, "false shadow (GPU only)"),
        (ShadowPixel::MissedShadow, "missed shadow (reference only)"),
    ];
    let mut at = pos2(rect.left() + 12.0, rect.bottom() - 30.0);
    for (p, name) in entries {
        let [r, g, b] = p.rgb8();
        let swatch = Rect::from_min_size(at, vec2(12.0, 12.0));
        painter.rect_filled(swatch, 0.0, Color32::from_rgb(r, g, b));
        painter.rect_stroke(swatch, 0.0, egui::Stroke::new(1.0, Color32::GRAY), egui::StrokeKind::Outside);
        let text = painter.text(at + vec2(16.0, 0.0), egui::Align2::LEFT_TOP, name, font.clone(), Color32::WHITE);
        at.x = text.right() + 14.0;
    }
}

/// What the scene's edges were built from: its name, objects and mesh sizes (comparing whole
/// file meshes every frame would cost as much as welding them again).
#[derive(Clone, Debug, PartialEq)]
struct EdgesOf {
    scene: String,
    objects: Vec<Object>,
    meshes: Vec<(usize, usize)>,
}

impl EdgesOf {
    fn new(scene: &Scene) -> EdgesOf {
        EdgesOf {
            scene: scene.name.clone(),
            objects: scene.objects.clone(),
            meshes: scene.meshes.iter().map(|m| (m.positions.len(), m.indices.len())).collect(),
        }
    }
}

/// The self-shadow boundary over the view (the panel's "self-shadow boundary" switch): the
/// scene's welded edges, rebuilt when its objects change, and the lines, re-evaluated when a
/// light changes, drawn by the render crate's overlay pass.
#[derive(Default)]
pub(super) struct BoundaryOverlay {
    pub enabled: bool,
    pass: Option<OverlayPass>,
    edges: Option<(EdgesOf, SceneEdges)>,
    lights: Option<Vec<Light>>,
}

impl BoundaryOverlay {
    /// Draw the boundary of `scene`'s lights into `target`, over the frame just drawn there (and
    /// its depth); nothing when the switch is off.
    pub fn draw(&mut self, renderer: &Renderer, target: &Target, scene: &Scene) {
        if !self.enabled {
            return;
        }
        let of = EdgesOf::new(scene);
        if self.edges.as_ref().is_none_or(|(built, _)| *built != of) {
            self.edges = Some((of, SceneEdges::new(scene)));
            self.lights = None;
        }
        let (device, queue) = (&renderer.device, &renderer.queue);
        let pass = self.pass.get_or_insert_with(|| OverlayPass::new(device));
        if self.lights.as_deref() != Some(&scene.lights[..]) {
            let edges = &self.edges.as_ref().expect("edges just built").1;
            pass.set_lines(device, &edges.terminator(&scene.lights), TERMINATOR_COLOR);
            self.lights = Some(scene.lights.clone());
        }
        pass.draw(device, queue, target, &scene.camera);
    }

    /// How many boundary edges are drawn (0 while the switch is off or before the first frame).
    pub fn line_count(&self) -> u32 {
        match (&self.pass, self.enabled) {
            (Some(p), true) => p.line_count(),
            _ => 0,
        }
    }
}

/// One set of the meshes' lines over the view (the panel's "vertex normals" or "creases"
/// switch): built from the scene's objects and meshes, rebuilt only when they change.
pub(super) struct MeshLinesOverlay {
    pub enabled: bool,
    lines: fn(&Scene) -> Vec<[DVec3; 2]>,
    color: [f32; 3],
    pass: Option<OverlayPass>,
    built: Option<EdgesOf>,
}

impl MeshLinesOverlay {
    /// The smooth meshes' vertex normals (`shadelab_model::mesh_lines`), yellow.
    pub fn normals() -> MeshLinesOverlay {
        Self::of(shadelab_model::mesh_lines::normal_segments, NORMALS_COLOR)
    }

    /// The edges the crease-angle rule keeps sharp, orange.
    pub fn creases() -> MeshLinesOverlay {
        Self::of(shadelab_model::mesh_lines::crease_segments, CREASES_COLOR)
    }

    fn of(lines: fn(&Scene) -> Vec<[DVec3; 2]>, color: [f32; 3]) -> MeshLinesOverlay {
        MeshLinesOverlay { enabled: false, lines, color, pass: None, built: None }
    }

    /// Draw the lines into `target` over the frame (and its depth); nothing when switched off.
    pub fn draw(&mut self, renderer: &Renderer, target: &Target, scene: &Scene) {
        if !self.enabled {
            return;
        }
        let (device, queue) = (&renderer.device, &renderer.queue);
        let pass = self.pass.get_or_insert_with(|| OverlayPass::new(device));
        let of = EdgesOf::new(scene);
        if self.built.as_ref() != Some(&of) {
            pass.set_lines(device, &(self.lines)(scene), self.color);
            self.built = Some(of);
        }
        pass.draw(device, queue, target, &scene.camera);
    }

    /// How many lines are drawn (0 while switched off or before the first frame).
    pub fn line_count(&self) -> u32 {
        match (&self.pass, self.enabled) {
            (Some(p), true) => p.line_count(),
            _ => 0,
        }
    }
}
