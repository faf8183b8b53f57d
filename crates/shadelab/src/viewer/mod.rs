//! The interactive viewer (eframe + egui-wgpu): the scene in the central area, drawn by the same
//! `Renderer` as `shadelab render` into an offscreen target that egui shows; the parameter panel
//! at the side edits the model, never wgpu objects. This file holds the viewer's state, its
//! start from the command line, the scenes it shows and its keys; the concerns live beside it:
//! the orbit camera (`orbit`), the view (`view`), the panel's sections (`panel/`), files
//! (`files`), opening a file on a worker thread (`loading`), the scripted run (`scripting`), what is drawn over the view (`overlays`), the
//! difference view (`difference`) and the lights' shadow maps (`shadow_maps`).

mod blit;
mod derive;
pub mod difference;
mod files;
mod link;
mod link_file;
mod link_scene;
mod loading;
mod lobe;
mod orbit;
mod overlays;
mod panel;
mod scripting;
mod shadow_factor;
mod shadow_maps;
mod site_path;
mod view;
#[cfg(target_arch = "wasm32")]
pub mod web;

pub use files::{FilePicker, FileRequest, native_file_picker};
pub use link::{Link, open_headless, parse_query};

use crate::cli;
#[cfg(not(target_arch = "wasm32"))]
use crate::{Failure, image_file};
use difference::DifferenceView;
use eframe::egui::{self, Key};
use eframe::egui_wgpu;
use orbit::Orbit;
use scripting::Script;
use shadelab_model::gltf_io::LoadedScene;
use shadelab_model::{Camera, Scene, ShadingMode, SpecularModel};
use shadelab_render::timing::FrameTimer;
use shadelab_render::{RenderSettings, Renderer, SceneGpu};
use std::path::PathBuf;
use std::sync::Arc;
use view::View;

/// The viewer's command-line options.
#[derive(Debug, Default)]
pub struct Options {
    pub screenshot: Option<PathBuf>,
    pub exit_after_frames: Option<u32>,
    pub shaders: Option<PathBuf>,
    pub scene: cli::SceneArgs,
    pub mode: cli::ModeArgs,
    pub difference: bool,
    /// A link's query to open after the scene (`--link`).
    pub link: Option<String>,
}

#[cfg(not(target_arch = "wasm32"))]
pub fn run(options: Options) -> Result<(), Failure> {
    let Options { screenshot, exit_after_frames, shaders, scene, mode, difference, link } = options;
    // A bad scene file, camera or flag is one line and exit 2, before any window opens.
    let mut loaded = cli::load(&scene)?;
    let settings = mode.settle(&mut loaded, &scene)?;
    if let Some(p) = &screenshot
        && image_file::image_kind(p)? != image_file::ImageKind::Png
    {
        return Err(Failure::Usage(format!("--screenshot: '{}' must be a .png file", p.display())));
    }
    let mut wgpu_options = egui_wgpu::WgpuConfiguration::default();
    if let egui_wgpu::WgpuSetup::CreateNew(create) = &mut wgpu_options.wgpu_setup {
        // Timestamp queries when the adapter has them (the panel's GPU time).
        create.device_descriptor = Arc::new(|adapter| wgpu::DeviceDescriptor {
            label: Some("shadelab viewer"),
            required_features: shadelab_render::gpu::wanted_features(adapter),
            required_limits: adapter.limits(),
            ..Default::default()
        });
    }
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default().with_inner_size([1280.0, 760.0]).with_title("shadelab"),
        renderer: eframe::Renderer::Wgpu,
        wgpu_options,
        ..Default::default()
    };
    eframe::run_native(
        "shadelab",
        options,
        Box::new(move |cc| {
            let mut viewer = Viewer::new(cc, screenshot, exit_after_frames)?;
            viewer.clears_to_panel_fill = true;
            viewer.show_loaded(loaded, &scene.scene)?;
            viewer.shader_dir = shaders;
            viewer.allow_outside_paths = scene.allow_outside_paths;
            viewer.settings = settings;
            viewer.set_difference_view(difference);
            if let Some(query) = &link {
                viewer.open_link(&link::parse_query(query));
            }
            Ok(Box::new(viewer) as Box<dyn eframe::App>)
        }),
    )
    .map_err(|e| Failure::Run(anyhow::anyhow!("viewer: {e}")))
}

/// The viewer's state; `pub` so that tests can drive it through egui_kittest.
pub struct Viewer {
    scene_name: String,
    scene: Scene,
    base_camera: Camera,
    orbit: Orbit,
    settings: RenderSettings,
    /// The term of the model on show (`All`: the whole model).
    term: shadelab_model::terms::Term,
    renderer: Renderer,
    gpu_scene: SceneGpu,
    egui_renderer: Arc<egui::mutex::RwLock<egui_wgpu::Renderer>>,
    view: Option<View>,
    timer: FrameTimer,
    /// The scene pass's timestamps, read back without waiting (`TimestampRing`).
    ring: shadelab_render::timestamp_ring::TimestampRing,
    frame_ms: Option<f64>,
    /// The last frame's area lights drawn as point lights, with the reason (the panel shows them).
    small_area_lights: Vec<String>,
    continuous: bool,
    /// The window is cleared to the panel's fill (eframe asks `clear_color`), so the panel paints
    /// none; off where a harness clears to transparent.
    clears_to_panel_fill: bool,
    /// The window's format encodes to sRGB on write, so its clear colour is given linear.
    window_is_srgb: bool,
    selected_material: usize,
    mu_linked: bool,
    script: Script,
    saved_count: u32,
    message: Option<(String, bool)>,
    /// Developer option: reload WGSL from here when it changes.
    pub shader_dir: Option<PathBuf>,
    /// Show the live timing numbers (snapshot tests turn them off: they differ every run).
    pub show_live_numbers: bool,
    shader_stamp: Option<std::time::SystemTime>,
    difference: DifferenceView,
    /// The self-shadow boundary over the view (`overlays::BoundaryOverlay`).
    boundary: overlays::BoundaryOverlay,
    /// The smooth meshes' vertex normals and the kept creases over the view.
    normals: overlays::MeshLinesOverlay,
    creases: overlays::MeshLinesOverlay,
    /// The lights' shadow maps on show in their panel sections.
    shadow_maps: shadow_maps::ShadowMapViews,
    /// The picked pixel's point and its lobe window.
    lobe: lobe::LobeView,
    /// The cast-shadow factor V, shown in place of the frame when it is the term on show.
    shadow_factor: shadow_factor::ShadowFactorView,
    /// The panel's file path field (open / save scene).
    pub file_field: String,
    /// Whether a file opened here may read buffers and images outside its folder
    /// (`--allow-outside-paths`, the files row's *outside paths*).
    pub allow_outside_paths: bool,
    /// How "open…" and "save as…" ask for a file.
    pub file_picker: FilePicker,
    /// The scene's cameras (a file's, in its node order; a built-in scene's one), and the one
    /// looked through.
    cameras: Vec<(String, Camera)>,
    camera_choice: usize,
    /// A dialog on show: what it is for, and where its answer arrives.
    picking: Option<(FileRequest, std::sync::mpsc::Receiver<Option<PathBuf>>)>,
    /// A file being opened on a worker thread (`loading.rs`).
    loading: Option<loading::Loading>,
    /// How the last file opened went (`loading::LoadStats`).
    last_load: Option<loading::LoadStats>,
    /// The adapter drawn with: its backend and name (the panel and the page's state show it).
    adapter: String,
    /// Where this frame put the panel's main switches, by name (`shading:flat`, `term:diffuse`):
    /// the page's state publishes them so that browser tests click them as a person would.
    marks: std::collections::BTreeMap<String, egui::Rect>,
    /// Where the view was drawn this frame, in points.
    view_rect: Option<egui::Rect>,
    /// Frames drawn so far.
    frames: u64,
    /// The frame as drawn, derived once per change (`derive.rs`).
    derived: derive::Derived,
    /// The derivation and camera the view's uniforms were written from, and
    /// `SceneGpu::uniform_writes` after that write: another count means another draw wrote over them.
    uniforms_written: Option<(u64, u64, Camera)>,
    /// The link "copy link" wrote last, shown under the button.
    copied_link: Option<(String, Option<String>)>,
    /// The I_amb an environment chosen in the panel took the place of, given back with "none".
    ambient_replaced: Option<[f64; 3]>,
    /// A link waiting for the file it names (`file=`) to be fetched and opened.
    pending_link: Option<link::Link>,
    /// The site path of the scene on show when a link's `file=` opened it, with the scene as the
    /// file holds it: the next link names the file and writes its edits against that scene.
    link_file: Option<(String, Scene)>,
    /// In the browser: the screenshot being read back, downloaded once it is.
    #[cfg(target_arch = "wasm32")]
    screenshot_reading: Option<shadelab_render::target::PendingReadBack>,
}

impl Viewer {
    /// The viewer on the built-in default scene. `screenshot` and `exit_after` script a run (see
    /// `--screenshot`, `--exit-after-frames`).
    pub fn new(
        cc: &eframe::CreationContext<'_>,
        screenshot_path: Option<PathBuf>,
        exit_after: Option<u32>,
    ) -> Result<Viewer, String> {
        let rs = cc.wgpu_render_state.as_ref().ok_or("the viewer needs eframe's wgpu renderer")?;
        let mut renderer = Renderer::new(&rs.device, &rs.queue);
        // A new effect set compiles on a worker thread; the uber pipeline draws meanwhile. The
        // browser has no threads, but its createRenderPipeline returns at once and compiles in
        // the GPU process, so there the build is asked for directly.
        renderer.pipelines.build_in_background = cfg!(not(target_arch = "wasm32"));
        let scene = Scene::builtin("default").expect("built-in default scene");
        let scene_camera = scene.camera;
        let gpu_scene = renderer.upload(&scene).map_err(|e| e.to_string())?;
        let info = rs.adapter.get_info();
        log::info!("viewer adapter: {info:?}");
        // A browser does not name its adapter: the backend alone then.
        let adapter = match info.name.as_str() {
            "" => format!("{:?}", info.backend),
            name => format!("{:?}: {name}", info.backend),
        };
        // The view is drawn into the window by a paint callback (blit.rs), which finds its
        // pipeline in egui's callback resources.
        rs.renderer.write().callback_resources.insert(blit::BlitResources::new(&rs.device, rs.target_format));
        Ok(Viewer {
            scene_name: "default".into(),
            base_camera: scene.camera,
            orbit: Orbit::from_camera(&scene.camera),
            selected_material: scene.objects.get(1).map_or(0, |o| o.material),
            scene,
            settings: RenderSettings::default(),
            term: shadelab_model::terms::Term::All,
            timer: FrameTimer::new(&rs.device, &rs.queue),
            ring: shadelab_render::timestamp_ring::TimestampRing::new(&rs.device, &rs.queue),
            renderer,
            gpu_scene,
            egui_renderer: rs.renderer.clone(),
            view: None,
            frame_ms: None,
            small_area_lights: Vec::new(),
            continuous: exit_after.is_some(),
            clears_to_panel_fill: false,
            window_is_srgb: rs.target_format.is_srgb(),
            mu_linked: true,
            script: Script::new(screenshot_path, exit_after),
            saved_count: 0,
            message: None,
            shader_dir: None,
            shader_stamp: None,
            show_live_numbers: true,
            difference: DifferenceView::default(),
            boundary: overlays::BoundaryOverlay::default(),
            normals: overlays::MeshLinesOverlay::normals(),
            creases: overlays::MeshLinesOverlay::creases(),
            shadow_maps: shadow_maps::ShadowMapViews::default(),
            shadow_factor: shadow_factor::ShadowFactorView::default(),
            lobe: lobe::LobeView::default(),
            file_field: String::new(),
            allow_outside_paths: false,
            file_picker: native_file_picker(),
            cameras: vec![("the scene's camera".into(), scene_camera)],
            camera_choice: 0,
            picking: None,
            loading: None,
            last_load: None,
            adapter,
            marks: Default::default(),
            view_rect: None,
            frames: 0,
            derived: Default::default(),
            uniforms_written: None,
            copied_link: None,
            ambient_replaced: None,
            pending_link: None,
            link_file: None,
            #[cfg(target_arch = "wasm32")]
            screenshot_reading: None,
        })
    }

    /// Remember where a switch of the panel was drawn this frame (see `marks`).
    pub(super) fn mark(&mut self, name: impl Into<String>, response: &egui::Response) {
        self.marks.insert(name.into(), response.rect);
    }

    /// The point of the pixel picked last (a click on the view), from the f64 model.
    pub fn picked(&self) -> Option<&shadelab_model::lobe::Pick> {
        self.lobe.picked()
    }

    /// The view's size in pixels (its target), once drawn.
    pub fn view_size(&self) -> Option<(u32, u32)> {
        self.view.as_ref().map(|v| (v.target.width, v.target.height))
    }

    /// Show one term of the model alone (`Term::All`: the whole model).
    pub fn set_term(&mut self, term: shadelab_model::terms::Term) {
        self.term = term;
    }

    /// The size of the shadow-factor image last shown (`None` before the first).
    pub fn shadow_factor_size(&self) -> Option<(u32, u32)> {
        self.shadow_factor.size()
    }

    /// Current shading mode, specular model and debug switch.
    pub fn settings(&self) -> RenderSettings {
        self.settings
    }

    /// Show or hide the "difference from reference" view.
    pub fn set_difference_view(&mut self, on: bool) {
        self.difference.enabled = on;
    }

    /// Which map the difference view shows (its "error map" buttons).
    pub fn set_difference_kind(&mut self, kind: difference::DifferenceKind) {
        self.difference.kind = kind;
    }

    /// The difference view's settings (what it shows, against what).
    pub fn difference_view(&self) -> &difference::DifferenceView {
        &self.difference
    }

    /// The ambient error map's numbers, once that map is current.
    pub fn ambient_fit(&self) -> Option<difference::AmbientFit> {
        self.difference.ambient_fit()
    }

    /// The share of the f64 reference traced so far, 0 to 1, while the difference view traces it.
    pub fn reference_progress(&self) -> Option<f32> {
        self.difference.progress()
    }

    /// The error of the current mode against the reference, once the map on show is current.
    pub fn difference(&self) -> Option<shadelab_render::image_error::ErrorStats> {
        self.difference.stats()
    }

    /// Show light `i`'s shadow map in its panel section or not (its "show shadow map" box).
    pub fn set_shadow_map_view(&mut self, i: usize, on: bool) {
        self.shadow_maps.set(i, on);
    }

    /// The size (width, height) of light `i`'s shadow map on show, once read back; `None` while
    /// it is off, not read yet, or the light has no map.
    pub fn shadow_map_shown(&self, i: usize) -> Option<[usize; 2]> {
        self.shadow_maps.texture(i).flatten().map(|t| t.size())
    }

    /// Show the shadow error map in the difference view (`true`) or the FLIP error map.
    pub fn set_shadow_error_map(&mut self, on: bool) {
        self.difference.kind = if on { difference::DifferenceKind::Shadow } else { difference::DifferenceKind::Flip };
    }

    /// The shadow error map's numbers, once the shadow error map on show is current.
    pub fn shadow_difference(&self) -> Option<shadelab_render::image_error::ShadowStats> {
        self.difference.shadow_stats()
    }

    /// How many times the frame as drawn was derived (the effect analysis, the program, the
    /// uniforms): once per change of the scene, the settings, the term or the view's size.
    pub fn derivations(&self) -> u64 {
        self.derived.count()
    }

    /// How many pipelines have been built so far (must not grow per frame).
    pub fn pipeline_builds(&self) -> u32 {
        self.renderer.pipelines.pipeline_builds
    }

    /// Whether pipelines are being built in the background (the uber pipeline draws meanwhile).
    pub fn pipelines_building(&self) -> bool {
        self.renderer.pipelines.building()
    }

    /// How many shadow-map layers the shadow passes have drawn so far (none while only the
    /// camera moves, but for a directional light's cascades fitted to the view).
    pub fn shadow_layer_draws(&self) -> u64 {
        self.gpu_scene.shadow_layer_draws
    }

    /// The last frame's area lights drawn as point lights, each with its reason (the panel's lines).
    pub fn small_area_lights(&self) -> &[String] {
        &self.small_area_lights
    }

    /// The scene being shown (parameters edited by the panel).
    pub fn scene_mut(&mut self) -> &mut Scene {
        &mut self.scene
    }

    /// The message line of the panel (text, is it an error).
    pub fn message(&self) -> Option<&(String, bool)> {
        self.message.as_ref()
    }

    /// Developer option: reload the WGSL when a file in the shader folder changed. A file that
    /// does not validate leaves the running pipelines as they are and shows naga's message.
    pub fn poll_shaders(&mut self) {
        let Some(dir) = &self.shader_dir else { return };
        let stamp = shadelab_render::shaders::newest_change(dir);
        if stamp == self.shader_stamp {
            return;
        }
        let first = self.shader_stamp.is_none();
        self.shader_stamp = stamp;
        let result = shadelab_render::shaders::read_lighting_source(dir)
            .map_err(|e| format!("reading shaders from {}: {e}", dir.display()))
            .and_then(|src| self.renderer.pipelines.reload_shaders(&src));
        self.message = Some(match result {
            Ok(()) if first => (format!("shaders from {} (reloaded on change)", dir.display()), false),
            Ok(()) => (format!("shaders reloaded from {}", dir.display()), false),
            Err(e) => (format!("shader error, previous pipelines kept:\n{e}"), true),
        });
    }

    fn load_scene(&mut self, name: &str) {
        match Scene::builtin(name) {
            Some(s) => {
                self.message = self.show_scene(s, name).err().map(|e| (e, true));
            }
            None => self.message = Some((format!("unknown scene '{name}'"), true)),
        }
    }

    /// Show a scene loaded from a file (or a built-in one through `cli::load`), with its cameras;
    /// its shading mode and specular model are the caller's to apply.
    pub fn show_loaded(&mut self, loaded: LoadedScene, name: &str) -> Result<(), String> {
        let gpu_scene = self.renderer.upload(&loaded.scene).map_err(|e| format!("{name}: {e}"))?;
        self.show_loaded_on_gpu(loaded, gpu_scene, name);
        Ok(())
    }

    /// [`Self::show_loaded`] for a scene already on the GPU (uploaded by the loading worker).
    fn show_loaded_on_gpu(&mut self, loaded: LoadedScene, gpu_scene: SceneGpu, name: &str) {
        let first = loaded.scene.camera;
        self.show_scene_on_gpu(loaded.scene, gpu_scene, name);
        self.cameras = loaded.cameras;
        self.camera_choice = self.cameras.iter().position(|(_, c)| *c == first).unwrap_or(0);
    }

    /// Look through camera `i` of the scene (ignored when there is no such camera).
    pub fn choose_camera(&mut self, i: usize) {
        if let Some((_, c)) = self.cameras.get(i) {
            self.camera_choice = i;
            self.base_camera = *c;
            self.orbit = Orbit::from_camera(c);
            self.scene.camera = *c;
        }
    }

    /// Show a scene; one the GPU cannot hold leaves the current scene as it is.
    fn show_scene(&mut self, s: Scene, name: &str) -> Result<(), String> {
        let gpu_scene = self.renderer.upload(&s).map_err(|e| format!("{name}: {e}"))?;
        self.show_scene_on_gpu(s, gpu_scene, name);
        Ok(())
    }

    fn show_scene_on_gpu(&mut self, s: Scene, gpu_scene: SceneGpu, name: &str) {
        self.gpu_scene = gpu_scene;
        self.cameras = vec![("the scene's camera".into(), s.camera)];
        self.camera_choice = 0;
        self.base_camera = s.camera;
        self.orbit = Orbit::from_camera(&s.camera);
        self.selected_material = s.objects.get(1).map_or(0, |o| o.material);
        self.shadow_maps.scene_replaced(s.lights.len());
        self.ambient_replaced = None;
        self.link_file = None;
        self.scene = s;
        self.scene_name = name.into();
    }

    /// The parameters panel on the right. Where the window is cleared to its fill it paints none:
    /// on a CPU rasterizer that fill cost a tenth of the frame (docs/performance.md).
    fn parameters_panel(&mut self, ui: &mut egui::Ui) {
        let fill = ui.visuals().panel_fill;
        let mut frame = egui::Frame::side_top_panel(ui.style());
        if self.clears_to_panel_fill {
            frame = frame.fill(egui::Color32::TRANSPARENT);
        }
        egui::Panel::right("parameters").frame(frame).resizable(true).default_size(340.0).show(ui, |ui| {
            // The fill the panel stands on, painted or not: the scroll area's fades blend into it.
            let stands_on = egui::UiStackInfo::default().with_frame(egui::Frame::NONE.fill(fill));
            ui.scope_builder(egui::UiBuilder::new().ui_stack_info(stands_on), |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.panel(ui));
            });
        });
    }

    fn keyboard(&mut self, ctx: &egui::Context) {
        if ctx.memory(|m| m.focused().is_some()) {
            return; // typing into a field
        }
        ctx.input(|i| {
            if i.key_pressed(Key::Num1) {
                self.settings.shading = ShadingMode::Flat;
            }
            if i.key_pressed(Key::Num2) {
                self.settings.shading = ShadingMode::Gouraud;
            }
            if i.key_pressed(Key::Num3) {
                self.settings.shading = ShadingMode::Phong;
            }
            if i.key_pressed(Key::S) {
                self.settings.specular = match self.settings.specular {
                    SpecularModel::Phong => SpecularModel::CookTorrance,
                    SpecularModel::CookTorrance => SpecularModel::Phong,
                };
            }
        });
        if ctx.input(|i| i.key_pressed(Key::F12)) {
            self.save_view_png();
        }
    }
}

impl eframe::App for Viewer {
    /// The panel's fill: the window's clear paints the panel's background (`parameters_panel`).
    fn clear_color(&self, visuals: &egui::Visuals) -> [f32; 4] {
        window_clear(visuals.panel_fill, self.window_is_srgb)
    }

    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if self.shader_dir.is_some() {
            self.poll_shaders();
            ctx.request_repaint_after(std::time::Duration::from_millis(500));
        }
        self.marks.clear();
        self.keyboard(&ctx);
        self.dropped_files(&ctx);
        self.poll_file_dialog(&ctx);
        self.poll_loading(&ctx);
        #[cfg(target_arch = "wasm32")]
        self.poll_screenshot(&ctx);
        self.parameters_panel(ui);
        egui::CentralPanel::default().frame(egui::Frame::NONE).show(ui, |ui| self.viewport(ui));
        self.lobe.show(&ctx, &self.scene);
        self.script.after_frame(&ctx, self.frame_ms);
        self.frames += 1;
        #[cfg(target_arch = "wasm32")]
        web::publish_state(self);
        if self.continuous {
            ctx.request_repaint();
        }
    }
}

/// The clear value that stores `color` in a window: its sRGB bytes as they are where the format
/// stores what it is given, linear where the format encodes to sRGB on write.
fn window_clear(color: egui::Color32, srgb: bool) -> [f32; 4] {
    if srgb { egui::Rgba::from(color).to_array() } else { color.to_normalized_gamma_f32() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clear_stores_the_fills_bytes_in_either_format() {
        let fill = egui::Visuals::dark().panel_fill;
        let [r, ..] = window_clear(fill, false);
        assert_eq!((r * 255.0).round() as u8, fill.r());
        // An sRGB format encodes the linear value back to the same byte.
        let [r, ..] = window_clear(fill, true);
        assert!(r < fill.r() as f32 / 255.0, "{r} is not linear");
        assert_eq!(egui::Color32::from(egui::Rgba::from_rgb(r, r, r)).r(), fill.r());
    }
}
