//! The interactive viewer (eframe + egui-wgpu): the scene in the central area, drawn by the same
//! `Renderer` as `shadelab render` into an offscreen target that egui shows; the parameter panel
//! at the side edits the model, never wgpu objects.

use crate::difference::DifferenceView;
use crate::{Failure, cli, render};
use eframe::egui::{self, Color32, Key, PointerButton, Rect, pos2};
use eframe::egui_wgpu;
use glam::DVec3;
use shadelab_model::gltf_io::LoadedScene;
use shadelab_model::params::{self, NamedValue, ParamRange};
use shadelab_model::presets::PRESETS;
use shadelab_model::scene::{BUILTIN_SCENES, MAX_LIGHTS};
use shadelab_model::{Camera, FalloffForm, Light, LightKind, PhongExponent, Scene, ShadingMode, SpecularModel};
use shadelab_render::timing::{FrameTimer, TimeSource};
use shadelab_render::{RenderSettings, Renderer, SceneGpu, Target};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// Format of the view's target: egui samples it as linear colour, like its own textures.
const VIEW_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
/// Frames after which `--screenshot` alone takes its picture.
const SCREENSHOT_DEFAULT_FRAME: u32 = 5;

/// The viewer's command-line options.
#[derive(Debug, Default)]
pub struct Options {
    pub screenshot: Option<PathBuf>,
    pub exit_after_frames: Option<String>,
    pub shaders: Option<PathBuf>,
    pub scene: cli::SceneArgs,
    pub mode: cli::ModeArgs,
    pub difference: bool,
}

pub fn run(options: Options) -> Result<(), Failure> {
    let Options { screenshot, exit_after_frames, shaders, scene, mode, difference } = options;
    let exit_after = exit_after_frames.as_deref().map(|f| cli::FRAMES.parse_u32(f)).transpose()?;
    // A bad scene file, camera or flag is one line and exit 2, before any window opens.
    let loaded = cli::load(&scene)?;
    let settings = mode.resolve(loaded.settings)?;
    if let Some(p) = &screenshot
        && render::image_kind(p)? != render::ImageKind::Png
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
            let mut viewer = Viewer::new(cc, screenshot, exit_after)?;
            viewer.show_loaded(loaded, &scene.scene)?;
            viewer.shader_dir = shaders;
            viewer.settings = settings;
            viewer.set_difference_view(difference);
            Ok(Box::new(viewer) as Box<dyn eframe::App>)
        }),
    )
    .map_err(|e| Failure::Run(anyhow::anyhow!("viewer: {e}")))
}

/// Orbit camera around a target: yaw and pitch in radians, distance in scene units.
#[derive(Clone, Copy, Debug)]
struct Orbit {
    target: DVec3,
    yaw: f64,
    pitch: f64,
    distance: f64,
}

impl Orbit {
    fn from_camera(c: &Camera) -> Orbit {
        let d = c.eye - c.target;
        let distance = d.length();
        Orbit { target: c.target, yaw: d.x.atan2(d.z), pitch: (d.y / distance).asin(), distance }
    }
    fn camera(&self, base: &Camera) -> Camera {
        let dir = DVec3::new(self.pitch.cos() * self.yaw.sin(), self.pitch.sin(), self.pitch.cos() * self.yaw.cos());
        Camera { eye: self.target + dir * self.distance, target: self.target, ..*base }
    }
}

struct View {
    target: Target,
    texture: egui::TextureId,
}

/// What a file dialog is asked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileRequest {
    /// A glTF file to open.
    Open,
    /// Where to save the scene.
    Save,
}

/// Asks the person for a file: the native dialog ([`native_file_picker`]), or a stand-in in
/// tests. `None`: nothing chosen. Called on a worker thread, so a dialog never stops the drawing.
pub type FilePicker = Arc<dyn Fn(FileRequest) -> Option<PathBuf> + Send + Sync>;

/// The desktop's file dialog (rfd: the XDG desktop portal, else zenity; GTK is not needed),
/// filtered to glTF files.
pub fn native_file_picker() -> FilePicker {
    Arc::new(|request| {
        let dialog = rfd::FileDialog::new().add_filter("glTF 2.0 scene", &["gltf", "glb"]);
        match request {
            FileRequest::Open => dialog.set_title("Open a scene").pick_file(),
            FileRequest::Save => dialog.set_title("Save the scene").set_file_name("scene.gltf").save_file(),
        }
    })
}

/// The viewer's state; `pub` so that tests can drive it through egui_kittest.
pub struct Viewer {
    scene_name: String,
    scene: Scene,
    base_camera: Camera,
    orbit: Orbit,
    settings: RenderSettings,
    renderer: Renderer,
    gpu_scene: SceneGpu,
    egui_renderer: Arc<egui::mutex::RwLock<egui_wgpu::Renderer>>,
    view: Option<View>,
    timer: FrameTimer,
    frame_ms: Option<f64>,
    continuous: bool,
    selected_material: usize,
    mu_linked: bool,
    frames: u32,
    exit_after: Option<u32>,
    screenshot_path: Option<PathBuf>,
    screenshot_slot: Arc<Mutex<Option<Arc<egui::ColorImage>>>>,
    screenshot_requested: bool,
    saved_count: u32,
    message: Option<(String, bool)>,
    /// Developer option: reload WGSL from here when it changes.
    pub shader_dir: Option<PathBuf>,
    /// Show the live timing numbers (snapshot tests turn them off: they differ every run).
    pub show_live_numbers: bool,
    shader_stamp: Option<std::time::SystemTime>,
    difference: DifferenceView,
    /// The panel's file path field (open / save scene).
    pub file_field: String,
    /// How "open…" and "save as…" ask for a file.
    pub file_picker: FilePicker,
    /// The scene's cameras (a file's, in its node order; a built-in scene's one), and the one
    /// looked through.
    cameras: Vec<(String, Camera)>,
    camera_choice: usize,
    /// A dialog on show: what it is for, and where its answer arrives.
    picking: Option<(FileRequest, std::sync::mpsc::Receiver<Option<PathBuf>>)>,
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
        // A new effect set compiles on a worker thread; the uber pipeline draws meanwhile.
        renderer.build_in_background = true;
        let scene = Scene::builtin("default").expect("built-in default scene");
        let scene_camera = scene.camera;
        let gpu_scene = renderer.upload(&scene).map_err(|e| e.to_string())?;
        log::info!("viewer adapter: {:?}", rs.adapter.get_info());
        Ok(Viewer {
            scene_name: "default".into(),
            base_camera: scene.camera,
            orbit: Orbit::from_camera(&scene.camera),
            selected_material: scene.objects.get(1).map_or(0, |o| o.material),
            scene,
            settings: RenderSettings::default(),
            timer: FrameTimer::new(&rs.device, &rs.queue),
            renderer,
            gpu_scene,
            egui_renderer: rs.renderer.clone(),
            view: None,
            frame_ms: None,
            continuous: exit_after.is_some(),
            mu_linked: true,
            frames: 0,
            exit_after,
            screenshot_path,
            screenshot_slot: Arc::new(Mutex::new(None)),
            screenshot_requested: false,
            saved_count: 0,
            message: None,
            shader_dir: None,
            shader_stamp: None,
            show_live_numbers: true,
            difference: DifferenceView::default(),
            file_field: String::new(),
            file_picker: native_file_picker(),
            cameras: vec![("the scene's camera".into(), scene_camera)],
            camera_choice: 0,
            picking: None,
        })
    }

    /// Current shading mode, specular model and debug switch.
    pub fn settings(&self) -> RenderSettings {
        self.settings
    }

    /// Show or hide the "difference from reference" view.
    pub fn set_difference_view(&mut self, on: bool) {
        self.difference.enabled = on;
    }

    /// The error of the current mode against the reference, once the map on show is current.
    pub fn difference(&self) -> Option<shadelab_render::accuracy::ErrorStats> {
        self.difference.stats()
    }

    /// How many pipelines have been built so far (must not grow per frame).
    pub fn pipeline_builds(&self) -> u32 {
        self.renderer.pipeline_builds
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
            .and_then(|src| self.renderer.reload_shaders(&src));
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
        let first = loaded.scene.camera;
        self.show_scene(loaded.scene, name)?;
        self.cameras = loaded.cameras;
        self.camera_choice = self.cameras.iter().position(|(_, c)| *c == first).unwrap_or(0);
        Ok(())
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
        self.gpu_scene = self.renderer.upload(&s).map_err(|e| format!("{name}: {e}"))?;
        self.cameras = vec![("the scene's camera".into(), s.camera)];
        self.camera_choice = 0;
        self.base_camera = s.camera;
        self.orbit = Orbit::from_camera(&s.camera);
        self.selected_material = s.objects.get(1).map_or(0, |o| o.material);
        self.scene = s;
        self.scene_name = name.into();
        Ok(())
    }

    /// Open a glTF 2.0 file (the path field, or a file dropped on the window). A bad file leaves
    /// the current scene as it is and shows the loader's one-line error.
    pub fn open_file(&mut self, path: &std::path::Path) {
        match shadelab_model::gltf_io::load_scene(path) {
            Ok(loaded) => {
                let mut text = format!("opened {}", path.display());
                for w in &loaded.warnings {
                    text.push_str(&format!("\nwarning: {w}"));
                }
                let settings = loaded.settings;
                if let Err(e) = self.show_loaded(loaded, &path.display().to_string()) {
                    self.message = Some((e, true));
                    return;
                }
                if let Some(m) = settings.shading {
                    self.settings.shading = m;
                }
                if let Some(m) = settings.specular {
                    self.settings.specular = m;
                }
                self.message = Some((text, false));
            }
            Err(e) => self.message = Some((e.to_string(), true)),
        }
    }

    /// Write the scene as shown (parameters, camera, shading mode, specular model) to a glTF file.
    pub fn save_scene(&mut self, path: &std::path::Path) {
        let settings = shadelab_model::gltf_io::SceneSettings {
            shading: Some(self.settings.shading),
            specular: Some(self.settings.specular),
        };
        let mut scene = self.scene.clone();
        scene.camera = self.orbit.camera(&self.base_camera);
        self.message = Some(match shadelab_model::gltf_io::save_scene(&scene, &settings, path) {
            Ok(()) => (format!("saved {}", path.display()), false),
            Err(e) => (e.to_string(), true),
        });
    }

    /// Show a file dialog on a worker thread (one at a time); its answer is taken by
    /// [`Self::poll_file_dialog`].
    fn ask_for_file(&mut self, request: FileRequest) {
        if self.picking.is_some() {
            return;
        }
        let (tx, rx) = std::sync::mpsc::channel();
        let picker = self.file_picker.clone();
        std::thread::spawn(move || {
            // A send fails only if the viewer is gone: nothing to do then.
            let _ = tx.send(picker(request));
        });
        self.picking = Some((request, rx));
    }

    /// Act on a file dialog's answer when it has come: open or save the chosen file.
    fn poll_file_dialog(&mut self, ctx: &egui::Context) {
        let Some((request, rx)) = &self.picking else { return };
        let answer = match rx.try_recv() {
            Ok(answer) => answer,
            Err(std::sync::mpsc::TryRecvError::Empty) => {
                // Look again soon: the answer comes from outside egui's events.
                ctx.request_repaint_after(std::time::Duration::from_millis(100));
                return;
            }
            Err(std::sync::mpsc::TryRecvError::Disconnected) => None,
        };
        let request = *request;
        self.picking = None;
        match answer {
            Some(path) => {
                self.file_field = path.display().to_string();
                match request {
                    FileRequest::Open => self.open_file(&path),
                    FileRequest::Save => self.save_scene(&path),
                }
            }
            None => {
                self.message = Some((
                    "no file chosen (the dialog was closed, or this desktop has no file dialog: type a path \
                     or drop a file on the window)"
                        .into(),
                    false,
                ))
            }
        }
    }

    /// Files dropped on the window are opened (the last one, if several).
    fn dropped_files(&mut self, ctx: &egui::Context) {
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw.dropped_files.iter().map(|f| f.path().to_path_buf()).filter(|p| !p.as_os_str().is_empty()).collect()
        });
        if let Some(p) = dropped.last() {
            self.open_file(p);
        }
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

    /// Render the current view again into a float target at the view's resolution and save it.
    fn save_view_png(&mut self) {
        let Some(view) = &self.view else { return };
        let (w, h) = (view.target.width, view.target.height);
        let target = Target::new(&self.renderer.device, w, h, shadelab_render::target::HDR_FORMAT);
        self.renderer.render(&self.gpu_scene, &self.scene, &target, &self.settings);
        let image = shadelab_render::target::read_back(&self.renderer.device, &self.renderer.queue, &target);
        self.saved_count += 1;
        let path = PathBuf::from(format!("shadelab-screenshot-{}.png", self.saved_count));
        self.message = Some(match render::save(&image, &path, render::ImageKind::Png) {
            Ok(()) => (format!("saved {} ({w}×{h})", path.display()), false),
            Err(e) => (format!("screenshot failed: {e:#}"), true),
        });
    }

    fn ensure_view(&mut self, w: u32, h: u32) {
        if self.view.as_ref().is_some_and(|v| v.target.width == w && v.target.height == h) {
            return;
        }
        let device = &self.renderer.device;
        let target = Target::new(device, w, h, VIEW_FORMAT);
        // egui takes a texture's values as sRGB-encoded: give it the stored bytes undecoded.
        let shown = target.encoded_view();
        let mut er = self.egui_renderer.write();
        let texture = match &self.view {
            Some(v) => {
                er.update_egui_texture_from_wgpu_texture(device, &shown, wgpu::FilterMode::Linear, v.texture);
                v.texture
            }
            None => er.register_native_texture(device, &shown, wgpu::FilterMode::Linear),
        };
        self.view = Some(View { target, texture });
    }

    fn viewport(&mut self, ui: &mut egui::Ui) {
        let avail = ui.available_size();
        let (rect, response) = ui.allocate_exact_size(avail, egui::Sense::click_and_drag());
        let ppp = ui.ctx().pixels_per_point();
        let w = ((avail.x * ppp).round().max(0.0) as u32).min(8192);
        let h = ((avail.y * ppp).round().max(0.0) as u32).min(8192);
        if w == 0 || h == 0 {
            return; // minimized or squeezed to nothing: no frame to draw
        }
        // Camera: drag orbits, right/middle drag pans, wheel zooms.
        let delta = response.drag_delta();
        if response.dragged_by(PointerButton::Primary) {
            self.orbit.yaw -= delta.x as f64 * 0.01;
            self.orbit.pitch = (self.orbit.pitch + delta.y as f64 * 0.01).clamp(-1.5, 1.5);
        }
        if response.dragged_by(PointerButton::Secondary) || response.dragged_by(PointerButton::Middle) {
            let cam = self.orbit.camera(&self.base_camera);
            let forward = (cam.target - cam.eye).normalize();
            let right = forward.cross(cam.up).normalize();
            let up = right.cross(forward);
            let scale = self.orbit.distance * 0.0015;
            self.orbit.target += (-right * delta.x as f64 + up * delta.y as f64) * scale;
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y) as f64;
            self.orbit.distance = (self.orbit.distance * (-scroll * 0.002).exp()).clamp(0.3, 60.0);
        }
        if response.double_clicked() {
            self.orbit = Orbit::from_camera(&self.base_camera);
        }
        self.scene.camera = self.orbit.camera(&self.base_camera).fitted(w as f64 / h as f64);
        self.ensure_view(w, h);
        let view = self.view.as_ref().expect("view just made");
        self.renderer.write_uniforms(&self.gpu_scene, &self.scene, &view.target, &self.settings);
        self.frame_ms = Some(self.timer.frame(&mut self.renderer, &self.gpu_scene, &view.target, &self.settings));
        let mut shown = view.texture;
        let analytic = shadelab_model::study::is_analytic(&self.scene);
        if self.difference.enabled && analytic {
            let ctx = ui.ctx().clone();
            if let Some(t) =
                self.difference.update(&ctx, &mut self.renderer, &self.gpu_scene, &self.scene, &self.settings, (w, h))
            {
                shown = t;
            }
        }
        let painter = ui.painter_at(rect);
        painter.image(shown, rect, Rect::from_min_max(pos2(0.0, 0.0), pos2(1.0, 1.0)), Color32::WHITE);
        if self.difference.enabled && analytic {
            let mode = format!("{} shading, {} specular", self.settings.shading, self.settings.specular);
            self.difference.overlay(&painter, rect, &mode, self.frame_ms, self.show_live_numbers);
            return; // the light markers would hide the error map
        }
        // Where the lights are: a marker at each point or spot light, and at the far point a
        // directional light comes from.
        let vp = self.scene.camera.projection(w as f64 / h as f64) * self.scene.camera.view();
        for (i, l) in self.scene.lights.iter().enumerate() {
            let p = match l.kind {
                LightKind::Point | LightKind::Spot => l.position,
                LightKind::Directional => self.orbit.target - l.direction * 4.0,
            };
            let clip = vp * p.extend(1.0);
            // Behind the eye the projection flips: divide by |w| so the marker keeps its side.
            let (x, y) = (clip.x / clip.w.abs().max(1e-9), clip.y / clip.w.abs().max(1e-9));
            let at = pos2(
                rect.left() + ((x + 1.0) * 0.5) as f32 * rect.width(),
                rect.top() + ((1.0 - y) * 0.5) as f32 * rect.height(),
            );
            let c = l.color.map(|c| (c.clamp(0.0, 1.0) * 255.0) as u8);
            let color = Color32::from_rgb(c[0], c[1], c[2]);
            let inner = rect.shrink(12.0);
            let on_view = clip.w > 0.0 && inner.contains(at);
            // A light off the view is pinned to the view's edge and drawn hollow.
            let at = if on_view { at } else { inner.clamp(at) };
            if on_view {
                painter.circle(at, 6.0, color, egui::Stroke::new(1.5, Color32::BLACK));
            } else {
                painter.circle_stroke(at, 6.0, egui::Stroke::new(2.5, color));
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

    fn panel(&mut self, ui: &mut egui::Ui) {
        ui.heading("shadelab");
        if let Some((msg, err)) = &self.message {
            let text = egui::RichText::new(msg).color(if *err { Color32::LIGHT_RED } else { Color32::LIGHT_GREEN });
            ui.label(if *err { text.monospace() } else { text });
        }
        let mut scene_choice = self.scene_name.clone();
        egui::ComboBox::from_label("scene").selected_text(&scene_choice).show_ui(ui, |ui| {
            for name in BUILTIN_SCENES {
                ui.selectable_value(&mut scene_choice, name.to_string(), *name);
            }
        });
        if scene_choice != self.scene_name {
            self.load_scene(&scene_choice);
        }
        if self.cameras.len() > 1 {
            let mut choice = self.camera_choice;
            egui::ComboBox::from_label("camera").selected_text(&self.cameras[choice].0).show_ui(ui, |ui| {
                for (i, (name, _)) in self.cameras.iter().enumerate() {
                    ui.selectable_value(&mut choice, i, name);
                }
            });
            if choice != self.camera_choice {
                self.choose_camera(choice);
            }
        }
        ui.horizontal(|ui| {
            ui.add(
                egui::TextEdit::singleline(&mut self.file_field).desired_width(170.0).hint_text("scene.gltf / .glb"),
            )
            .on_hover_text("a glTF 2.0 file to open (or drop a file on the window)");
            if ui.button("open").on_hover_text("open the file named in the field").clicked() {
                let p = PathBuf::from(self.file_field.trim());
                self.open_file(&p);
            }
            if ui.button("save scene").on_hover_text("write the scene as shown to this .gltf/.glb path").clicked() {
                let name = self.file_field.trim();
                let p = if name.is_empty() { PathBuf::from("shadelab-scene.gltf") } else { PathBuf::from(name) };
                self.save_scene(&p);
            }
        });
        ui.horizontal(|ui| {
            let idle = self.picking.is_none();
            if ui
                .add_enabled(idle, egui::Button::new("open…"))
                .on_hover_text("choose a glTF file in a dialog")
                .clicked()
            {
                self.ask_for_file(FileRequest::Open);
            }
            if ui
                .add_enabled(idle, egui::Button::new("save as…"))
                .on_hover_text("choose where to save the scene as shown (.gltf or .glb)")
                .clicked()
            {
                self.ask_for_file(FileRequest::Save);
            }
            if !idle {
                ui.spinner();
            }
        });
        ui.horizontal(|ui| {
            ui.label("shading");
            for (i, (name, mode)) in ShadingMode::ALL.iter().enumerate() {
                ui.selectable_value(&mut self.settings.shading, *mode, *name).on_hover_text(format!(
                    "{} (key {})",
                    shading_meaning(*mode),
                    i + 1
                ));
            }
        });
        ui.horizontal(|ui| {
            ui.label("specular");
            ui.selectable_value(&mut self.settings.specular, SpecularModel::Phong, "Phong (V·R)^h")
                .on_hover_text("Phong specular: (V·R)^h, the light's colour (key S toggles)");
            ui.selectable_value(&mut self.settings.specular, SpecularModel::CookTorrance, "Cook–Torrance")
                .on_hover_text(
                    "Cook–Torrance: Beckmann D(m), geometric G, exact Fresnel F(μ) per channel (key S toggles)",
                );
        });
        ui.checkbox(&mut self.settings.debug_nonfinite, "paint non-finite pixels magenta");
        let analytic = shadelab_model::study::is_analytic(&self.scene);
        ui.add_enabled(analytic, egui::Checkbox::new(&mut self.difference.enabled, "difference from reference"))
            .on_hover_text(format!(
                "FLIP error map of this mode against the f64 ray-cast reference of the exact surface \
                 (at most {} px wide), with RMSE and the GPU time; only for scenes of analytic shapes",
                crate::difference::DIFFERENCE_MAX_WIDTH
            ))
            .on_disabled_hover_text(
                "only for scenes made of analytic shapes (the reference knows their exact surface)",
            );
        ui.separator();
        self.material_ui(ui);
        ui.separator();
        self.lights_ui(ui);
        ui.separator();
        self.stats_ui(ui);
    }

    fn material_ui(&mut self, ui: &mut egui::Ui) {
        let names: Vec<String> = self.scene.materials.iter().map(|m| m.name.clone()).collect();
        self.selected_material = self.selected_material.min(names.len().saturating_sub(1));
        egui::ComboBox::from_label("material").selected_text(&names[self.selected_material]).show_ui(ui, |ui| {
            for (i, n) in names.iter().enumerate() {
                ui.selectable_value(&mut self.selected_material, i, n);
            }
        });
        let mat = &mut self.scene.materials[self.selected_material];
        ui.horizontal_wrapped(|ui| {
            ui.label("μ presets:");
            for p in PRESETS {
                let tip = format!("μ = ({:.3}, {:.3}, {:.3}) — {}", p.mu[0], p.mu[1], p.mu[2], p.source);
                if ui.button(p.name).on_hover_text(tip).clicked() {
                    mat.mu = p.mu;
                    mat.color = p.color;
                    mat.r_d = if p.metal { 0.1 } else { 0.8 };
                }
            }
        });
        ui.small(format!("μ = ({:.3}, {:.3}, {:.3})", mat.mu[0], mat.mu[1], mat.mu[2]));
        slider(ui, &mut mat.m, &params::M, false);
        let mut mirror = mat.h.is_mirror();
        let mut h = mat.h.value();
        ui.horizontal(|ui| {
            ui.add_enabled(
                !mirror,
                egui::Slider::new(&mut h, params::H.min..=params::H.max).logarithmic(true).text("h"),
            )
            .on_hover_text(tooltip(&params::H));
            ui.checkbox(&mut mirror, "mirror").on_hover_text("h = ∞: a perfect mirror");
        });
        mat.h = if mirror { PhongExponent::Mirror } else { PhongExponent::Finite(h) };
        ui.checkbox(&mut self.mu_linked, "μ linked (one value for R, G, B)");
        if self.mu_linked {
            let mut v = mat.mu[0];
            if slider(ui, &mut v, &params::MU, false) {
                mat.mu = [v; 3];
            }
        } else {
            for (c, name) in mat.mu.iter_mut().zip(["μ R", "μ G", "μ B"]) {
                ui.add(egui::Slider::new(c, 0.0..=1.0).text(name)).on_hover_text(tooltip(&params::MU));
            }
        }
        ui.horizontal(|ui| {
            let mut c = mat.color.map(|v| v as f32);
            ui.label("C").on_hover_text("surface colour C (linear RGB)");
            if ui.color_edit_button_rgb(&mut c).changed() {
                mat.color = c.map(f64::from);
            }
        });
        for (v, name, meaning) in [
            (&mut mat.r_s, "r_s", "specular share r_s"),
            (&mut mat.r_d, "r_d", "diffuse share r_d"),
            (&mut mat.r_a, "r_a", "ambient reflectance r_a"),
        ] {
            ui.add(egui::Slider::new(v, 0.0..=1.0).text(name)).on_hover_text(meaning);
        }
        let mut amb = self.scene.ambient[0];
        if ui
            .add(egui::Slider::new(&mut amb, 0.0..=1.0).text("I_amb"))
            .on_hover_text("ambient intensity I_amb of the scene")
            .changed()
        {
            self.scene.ambient = [amb; 3];
        }
    }

    fn lights_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.strong(format!("lights ({}/{MAX_LIGHTS})", self.scene.lights.len()));
            if ui.add_enabled(self.scene.lights.len() < MAX_LIGHTS, egui::Button::new("add")).clicked() {
                self.scene.lights.push(Light::point(DVec3::new(2.0, 2.5, 2.0), [1.0; 3], 1.0, 0.05));
            }
        });
        let mut remove = None;
        for (i, l) in self.scene.lights.iter_mut().enumerate() {
            egui::CollapsingHeader::new(format!("L{} — {}", i + 1, l.kind.name())).id_salt(i).show(ui, |ui| {
                ui.horizontal(|ui| {
                    let mut kind = l.kind;
                    ui.selectable_value(&mut kind, LightKind::Directional, "directional");
                    ui.selectable_value(&mut kind, LightKind::Point, "point");
                    ui.selectable_value(&mut kind, LightKind::Spot, "spot")
                        .on_hover_text("a point light that lights only a cone (glTF's spot light)");
                    l.set_kind(kind);
                    if ui.button("remove").clicked() {
                        remove = Some(i);
                    }
                });
                let positional = l.kind != LightKind::Directional;
                if positional {
                    vec3_row(ui, "position", &mut l.position);
                }
                if l.kind != LightKind::Point {
                    vec3_row(ui, if positional { "axis" } else { "direction" }, &mut l.direction);
                    l.direction = l.direction.normalize_or(DVec3::NEG_Y);
                }
                ui.horizontal(|ui| {
                    let mut c = l.color.map(|v| v as f32);
                    if ui.color_edit_button_rgb(&mut c).changed() {
                        l.color = c.map(f64::from);
                    }
                    slider(ui, &mut l.intensity, &params::INTENSITY, true);
                });
                if positional {
                    ui.horizontal(|ui| {
                        ui.selectable_value(&mut l.falloff_form, FalloffForm::Quadratic, "1/(1+αd²)");
                        ui.selectable_value(&mut l.falloff_form, FalloffForm::Linear, "1/(d+d0)");
                    });
                    match l.falloff_form {
                        FalloffForm::Quadratic => slider(ui, &mut l.falloff_alpha, &params::FALLOFF, true),
                        FalloffForm::Linear => slider(ui, &mut l.d0, &params::D0, true),
                    };
                    ui.horizontal(|ui| {
                        let mut ends = l.range.is_some();
                        ui.checkbox(&mut ends, "range")
                            .on_hover_text("the light ends at this distance, fading as glTF's 1 − (d/range)⁴");
                        let mut r = l.range.unwrap_or(10.0);
                        if ends {
                            ui.add(egui::Slider::new(&mut r, 0.1..=100.0).logarithmic(true))
                                .on_hover_text(tooltip(&params::RANGE));
                        }
                        l.range = ends.then_some(r);
                    });
                }
                if l.kind == LightKind::Spot {
                    // Degrees on the panel, radians in the model; the inner cone stays inside the outer.
                    let mut outer = l.outer_cone.to_degrees();
                    let mut inner = l.inner_cone.to_degrees();
                    ui.add(egui::Slider::new(&mut outer, 0.5..=90.0).text("outer cone °"))
                        .on_hover_text("half-angle beyond which the spot gives no light");
                    ui.add(egui::Slider::new(&mut inner, 0.0..=outer - 0.5).text("inner cone °"))
                        .on_hover_text("half-angle within which the spot gives its full light");
                    l.outer_cone = outer.to_radians();
                    l.inner_cone = inner.min(outer - 0.5).max(0.0).to_radians();
                }
            });
        }
        if let Some(i) = remove {
            self.scene.lights.remove(i);
        }
    }

    fn stats_ui(&mut self, ui: &mut egui::Ui) {
        let source = match self.timer.source() {
            TimeSource::GpuTimestamps => "GPU, timestamps",
            TimeSource::CpuSubmitWait => "CPU, submit+wait",
        };
        if self.show_live_numbers {
            if let Some(ms) = self.frame_ms {
                ui.label(format!("scene pass: {ms:.2} ms ({source})"));
            }
            let dt = ui.input(|i| i.unstable_dt).max(1e-6);
            ui.label(format!("frame interval: {:.1} ms ({:.0} fps)", dt * 1e3, 1.0 / dt));
        } else {
            ui.label(format!("scene pass: — ms ({source})"));
        }
        ui.label(format!(
            "{} triangles, {} lights, {} pipelines built",
            self.gpu_scene.triangle_count,
            self.scene.lights.len(),
            self.renderer.pipeline_builds
        ));
        ui.checkbox(&mut self.continuous, "render continuously (for live timing)");
        // The same analysis as `render --explain`: what this scene calls for, and why.
        let analysis = shadelab_model::effects::analyze(&self.scene, self.settings.specular);
        let drawn = self.gpu_scene.effects();
        if self.renderer.building() {
            ui.label(
                egui::RichText::new(format!("compiling pipeline [{}]… drawn with the uber pipeline", drawn.label()))
                    .color(Color32::YELLOW),
            );
            ui.ctx().request_repaint_after(std::time::Duration::from_millis(50));
        } else if let Some((key, took)) = self.renderer.last_build
            && self.show_live_numbers
        {
            ui.small(format!("last pipeline built: [{}] in {:.0} ms", key.effects.label(), took.as_secs_f64() * 1e3));
        }
        egui::CollapsingHeader::new("effects called for").default_open(false).show(ui, |ui| {
            ui.small(format!("pipeline [{}]", analysis.key.label()));
            ui.small(shading_meaning(self.settings.shading));
            for line in analysis.lines() {
                ui.label(format!("• {line}"));
            }
        });
        ui.horizontal(|ui| {
            if ui.button("screenshot (F12)").on_hover_text("save the view as PNG at its resolution").clicked() {
                self.save_view_png();
            }
            if ui.button("reset camera").on_hover_text("or double-click the view").clicked() {
                self.orbit = Orbit::from_camera(&self.base_camera);
            }
        });
        ui.small("drag: orbit · right/middle drag: pan · wheel: zoom · 1/2/3: shading · S: specular · F12: screenshot");
    }

    /// `--screenshot` / `--exit-after-frames`: grab the whole window, then close.
    fn scripted_exit(&mut self, ctx: &egui::Context) {
        let shot_at = self.exit_after.unwrap_or(SCREENSHOT_DEFAULT_FRAME);
        if let Some(path) = &self.screenshot_path {
            if self.frames >= shot_at && !self.screenshot_requested {
                let slot = self.screenshot_slot.clone();
                ctx.request_screenshot(move |img| *slot.lock().unwrap() = Some(img));
                self.screenshot_requested = true;
            }
            let taken = self.screenshot_slot.lock().unwrap().take();
            if let Some(img) = taken {
                let [w, h] = img.size;
                let rgba = image::RgbaImage::from_raw(w as u32, h as u32, img.as_raw().to_vec());
                match rgba.map(|i| i.save(path)) {
                    Some(Ok(())) => log::info!("saved {}", path.display()),
                    _ => eprintln!("error: --screenshot: could not write {}", path.display()),
                }
                self.screenshot_path = None;
                if self.exit_after.is_some() {
                    ctx.send_viewport_cmd(egui::ViewportCommand::Close);
                }
            }
            ctx.request_repaint();
        } else if let Some(n) = self.exit_after {
            if self.frames >= n {
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
            ctx.request_repaint();
        }
    }
}

impl eframe::App for Viewer {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if self.shader_dir.is_some() {
            self.poll_shaders();
            ctx.request_repaint_after(std::time::Duration::from_millis(500));
        }
        self.keyboard(&ctx);
        self.dropped_files(&ctx);
        self.poll_file_dialog(&ctx);
        egui::Panel::right("parameters").resizable(true).default_size(340.0).show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| self.panel(ui));
        });
        egui::CentralPanel::default().show(ui, |ui| self.viewport(ui));
        self.frames += 1;
        self.scripted_exit(&ctx);
        if self.continuous {
            ctx.request_repaint();
        }
    }
}

/// A row of three drag values for a vector (a light's position or direction).
fn vec3_row(ui: &mut egui::Ui, label: &str, v: &mut DVec3) {
    ui.horizontal(|ui| {
        ui.label(label);
        for c in [&mut v.x, &mut v.y, &mut v.z] {
            ui.add(egui::DragValue::new(c).speed(0.05).range(-50.0..=50.0));
        }
    });
}

fn tooltip(r: &ParamRange) -> String {
    format!("{} — {}, in [{}, {}]", r.symbol, r.meaning, r.min, r.max)
}

/// A slider over a parameter's allowed range, with its symbol and meaning as tooltip.
fn slider(ui: &mut egui::Ui, v: &mut f64, r: &ParamRange, log: bool) -> bool {
    ui.add(egui::Slider::new(v, r.min..=r.max).logarithmic(log).text(r.symbol)).on_hover_text(tooltip(r)).changed()
}

fn shading_meaning(m: ShadingMode) -> &'static str {
    match m {
        ShadingMode::Flat => "flat: one normal and one colour per face, lit at its centroid",
        ShadingMode::Gouraud => "Gouraud: lit at the vertices, colour interpolated",
        ShadingMode::Phong => "Phong shading: normals interpolated and renormalized, lit per pixel",
    }
}
