//! The viewer's view of each light's shadow map (docs/model.md §6): a light whose "show shadow
//! map" box is ticked gets its map (one face of a point light's six, or one of a directional
//! light's cascades) read back from the GPU and shown as grey in its panel section. The map is
//! read back only when what it depends on (the scene's objects, lights and meshes, the layer, and
//! for cascades the camera) changed since the last read, not every frame, and without a wait: the
//! copy is taken in a later frame, as the page must.

use eframe::egui;
use shadelab_model::Scene;
use shadelab_render::target::{LinearImage, PendingReadBack};
use shadelab_render::{Renderer, SceneGpu};
use std::collections::BTreeMap;

/// The panel shows a map this many points wide (it is scaled down; the texture keeps every texel).
pub const SHADOW_MAP_SHOWN_POINTS: f32 = 200.0;

/// Drawn texels span grey 0..=this, so the farthest stays apart from the empty texels' white.
const FARTHEST_GREY: f32 = 220.0;

/// What a map on show depends on: the scene's objects, meshes and lights, the layer, and the
/// camera only for a directional light's cascades (fitted to the view; the other maps are fitted
/// to the scene's bounds).
struct MapKey {
    objects: Vec<shadelab_model::Object>,
    meshes: shadelab_model::mesh::Meshes,
    lights: Vec<shadelab_model::Light>,
    face: u32,
    camera: Option<shadelab_model::Camera>,
}

/// The camera a light's map depends on: the view, for a directional light that may use cascades.
fn camera_for(scene: &Scene, light: usize) -> Option<shadelab_model::Camera> {
    let l = scene.lights.get(light)?;
    (l.kind.is_directional() && l.shadow.cascades).then_some(scene.camera)
}

impl MapKey {
    fn new(scene: &Scene, light: usize, face: u32) -> MapKey {
        MapKey {
            objects: scene.objects.clone(),
            meshes: scene.meshes.clone(),
            lights: scene.lights.clone(),
            face,
            camera: camera_for(scene, light),
        }
    }

    fn matches(&self, scene: &Scene, light: usize, face: u32) -> bool {
        self.face == face
            && self.camera == camera_for(scene, light)
            && self.objects == scene.objects
            && self.lights == scene.lights
            && self.meshes == scene.meshes
    }
}

/// One light's map view: the face asked for, the map last read back and the one being read.
#[derive(Default)]
pub struct LightMapView {
    pub face: u32,
    shown: Option<(MapKey, Option<egui::TextureHandle>)>,
    reading: Option<(MapKey, Option<PendingReadBack>)>,
}

/// The lights whose map is on show (by light index).
#[derive(Default)]
pub struct ShadowMapViews {
    views: BTreeMap<usize, LightMapView>,
}

impl ShadowMapViews {
    /// Whether light `i`'s map is on show.
    pub fn is_on(&self, i: usize) -> bool {
        self.views.contains_key(&i)
    }

    /// Show light `i`'s map or stop showing it.
    pub fn set(&mut self, i: usize, on: bool) {
        if on {
            self.views.entry(i).or_default();
        } else {
            self.views.remove(&i);
        }
    }

    /// Light `i`'s view, when its map is on show.
    pub fn view_mut(&mut self, i: usize) -> Option<&mut LightMapView> {
        self.views.get_mut(&i)
    }

    /// Light `i`'s texture on show: `Some(None)` once read back when the light has no map.
    pub fn texture(&self, i: usize) -> Option<Option<&egui::TextureHandle>> {
        self.views.get(&i).and_then(|v| v.shown.as_ref()).map(|(_, t)| t.as_ref())
    }

    /// Forget the lights from index `n` on (after lights were removed) and every map read back.
    pub fn scene_replaced(&mut self, n: usize) {
        self.views.retain(|&i, _| i < n);
        for v in self.views.values_mut() {
            (v.shown, v.reading) = (None, None);
        }
    }

    /// Read back the maps on show whose scene or face changed, and show those read back since;
    /// call after a frame drew the maps. Never waits: a map arrives a frame or more later.
    pub fn update(&mut self, ctx: &egui::Context, renderer: &Renderer, gpu_scene: &SceneGpu, scene: &Scene) {
        if self.views.is_empty() {
            return;
        }
        self.views.retain(|&i, _| i < scene.lights.len());
        for (&i, v) in &mut self.views {
            let current = |k: &MapKey| k.matches(scene, i, v.face);
            if !v.shown.as_ref().is_some_and(|(k, _)| current(k))
                && !v.reading.as_ref().is_some_and(|(k, _)| current(k))
            {
                let pending = renderer.start_shadow_map_read(gpu_scene, i, v.face);
                v.reading = Some((MapKey::new(scene, i, v.face), pending));
            }
            let Some((_, pending)) = &v.reading else { continue };
            let texture = match pending.as_ref().map(|p| p.try_take(&renderer.device)) {
                Some(None) => {
                    ctx.request_repaint();
                    continue;
                }
                Some(Some(Ok(map))) => {
                    let name = format!("shadow map L{} face {}", i + 1, v.face);
                    Some(ctx.load_texture(name, depth_as_grey(&map), egui::TextureOptions::LINEAR))
                }
                // No map for the light, or the read failed (a lost device): nothing to show.
                Some(Some(Err(_))) | None => None,
            };
            let (key, _) = v.reading.take().expect("matched above");
            v.shown = Some((key, texture));
        }
    }
}

/// A map's depths as grey, stretched over the depths it holds (nearest black, farthest grey
/// near white), so a scene filling a thin slice of the light's depth range still shows its
/// shape; texels where nothing was drawn (depth 1) are white.
pub fn depth_as_grey(map: &LinearImage) -> egui::ColorImage {
    let drawn = map.pixels.iter().map(|p| p[0]).filter(|d| d.is_finite() && *d < 1.0);
    let (lo, hi) = drawn.fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), d| (lo.min(d), hi.max(d)));
    let span = (hi - lo).max(f32::EPSILON);
    let rgb: Vec<u8> = map
        .pixels
        .iter()
        .flat_map(|p| {
            let d = p[0];
            let g = if d.is_finite() && d < 1.0 { ((d - lo) / span * FARTHEST_GREY) as u8 } else { 255 };
            [g; 3]
        })
        .collect();
    egui::ColorImage::from_rgb([map.width as usize, map.height as usize], &rgb)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depths_are_stretched_and_empty_texels_are_white() {
        let d = |v: f32| [v, v, v, 1.0];
        let map = LinearImage { width: 4, height: 1, pixels: vec![d(0.2), d(0.6), d(1.0), d(f32::NAN)] };
        let img = depth_as_grey(&map);
        let grey: Vec<u8> = img.pixels.iter().map(|c| c.r()).collect();
        assert_eq!(grey, [0, 220, 255, 255]);
    }
}
