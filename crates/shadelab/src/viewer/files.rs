//! The viewer's files: open and save glTF scenes (the path field, the file dialog on a worker
//! thread, files dropped on the window) and save the view as a PNG.

use super::Viewer;
#[cfg(not(target_arch = "wasm32"))]
use crate::image_file;
use eframe::egui;
use shadelab_render::Target;
use std::path::PathBuf;
use std::sync::Arc;

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
/// filtered to glTF files (and, to open, environment maps).
#[cfg(not(target_arch = "wasm32"))]
pub fn native_file_picker() -> FilePicker {
    Arc::new(|request| {
        let dialog = rfd::FileDialog::new().add_filter("glTF 2.0 scene", &["gltf", "glb"]);
        match request {
            FileRequest::Open => dialog
                .add_filter("environment map", &["hdr", "exr"])
                .set_title("Open a scene or an environment map")
                .pick_file(),
            FileRequest::Save => dialog.set_title("Save the scene").set_file_name("scene.gltf").save_file(),
        }
    })
}

/// In the browser the page's file input and downloads take the dialog's place (`web.rs`), so
/// this picker is never asked.
#[cfg(target_arch = "wasm32")]
pub fn native_file_picker() -> FilePicker {
    Arc::new(|_| None)
}

impl Viewer {
    /// The scene as shown (parameters, camera), with the modes the file records.
    fn scene_to_save(&self) -> (shadelab_model::Scene, shadelab_model::gltf_io::SceneSettings) {
        let settings = shadelab_model::gltf_io::SceneSettings {
            shading: Some(self.settings.shading),
            specular: Some(self.settings.specular),
        };
        let mut scene = self.scene.clone();
        scene.camera = self.orbit.camera(&self.base_camera);
        (scene, settings)
    }

    /// Download the scene as shown as one `.glb` (the browser's "save scene").
    #[cfg(target_arch = "wasm32")]
    pub(super) fn download_scene(&mut self) {
        let (scene, settings) = self.scene_to_save();
        let bytes = shadelab_model::gltf_io::scene_to_glb(&scene, &settings);
        self.message = Some(match super::web::download("shadelab-scene.glb", &bytes, "model/gltf-binary") {
            Ok(()) => ("downloaded shadelab-scene.glb".into(), false),
            Err(e) => (format!("save scene: {e}"), true),
        });
    }

    /// Write the scene as shown (parameters, camera, shading mode, specular model) to a glTF file.
    pub fn save_scene(&mut self, path: &std::path::Path) {
        let (scene, settings) = self.scene_to_save();
        self.message = Some(match shadelab_model::gltf_io::save_scene(&scene, &settings, path) {
            Ok(()) => (format!("saved {}", path.display()), false),
            Err(e) => (e.to_string(), true),
        });
    }

    /// Show a file dialog on a worker thread (one at a time); its answer is taken by
    /// [`Self::poll_file_dialog`].
    pub(super) fn ask_for_file(&mut self, request: FileRequest) {
        #[cfg(target_arch = "wasm32")]
        {
            // The page's file input (its files arrive in `poll_file_dialog`), or a download.
            match request {
                FileRequest::Open => super::web::choose_files(),
                FileRequest::Save => self.download_scene(),
            }
            return;
        }
        #[cfg_attr(target_arch = "wasm32", allow(unreachable_code))]
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
    pub(super) fn poll_file_dialog(&mut self, ctx: &egui::Context) {
        #[cfg(target_arch = "wasm32")]
        if let Some(files) = super::web::take_chosen_files() {
            self.open_files(files);
        }
        #[cfg(target_arch = "wasm32")]
        if let Some(e) = super::web::take_fetch_error() {
            self.pending_link = None;
            self.message = Some((e, true));
        }
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

    /// Files dropped on the window are opened (the last one, if several). In the browser they
    /// are read as bytes (asynchronously, `web.rs`) and a `.gltf` opens with the `.bin` and
    /// images dropped with it.
    pub(super) fn dropped_files(&mut self, ctx: &egui::Context) {
        let dropped: Vec<egui::DroppedFileHandle> = ctx.input(|i| i.raw.dropped_files.clone());
        if dropped.is_empty() {
            return;
        }
        #[cfg(target_arch = "wasm32")]
        super::web::read_dropped(dropped, ctx.clone());
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(p) = dropped.iter().map(|f| f.path().to_path_buf()).filter(|p| !p.as_os_str().is_empty()).last() {
            self.open_file(&p);
        }
    }

    /// Render the current view again at its resolution and download it as PNG once read back
    /// (the browser's maps complete between frames: `poll_screenshot` takes it).
    #[cfg(target_arch = "wasm32")]
    pub(super) fn save_view_png(&mut self) {
        let Some(view) = &self.view else { return };
        let (w, h) = (view.target.width, view.target.height);
        let target = Target::new(&self.renderer.device, w, h, shadelab_render::target::HDR_FORMAT);
        self.renderer.render(&mut self.gpu_scene, &self.scene, &target, &self.settings);
        self.screenshot_reading =
            Some(shadelab_render::target::start_read_back(&self.renderer.device, &self.renderer.queue, &target));
    }

    /// Download the screenshot once its image has been read back.
    #[cfg(target_arch = "wasm32")]
    pub(super) fn poll_screenshot(&mut self, ctx: &egui::Context) {
        let Some(reading) = &self.screenshot_reading else { return };
        let Some(image) = reading.try_take(&self.renderer.device) else {
            ctx.request_repaint();
            return;
        };
        self.screenshot_reading = None;
        self.saved_count += 1;
        let name = format!("shadelab-screenshot-{}.png", self.saved_count);
        let png = image.and_then(|image| {
            let mut bytes = std::io::Cursor::new(Vec::new());
            image::RgbImage::from_raw(image.width, image.height, image.to_srgb8())
                .ok_or_else(|| "image buffer size".to_string())?
                .write_to(&mut bytes, image::ImageFormat::Png)
                .map_err(|e| e.to_string())?;
            Ok(bytes.into_inner())
        });
        self.message = Some(match png.and_then(|png| super::web::download(&name, &png, "image/png")) {
            Ok(()) => (format!("downloaded {name}"), false),
            Err(e) => (format!("screenshot failed: {e}"), true),
        });
    }

    /// Render the current view again into a float target at the view's resolution and save it.
    #[cfg(not(target_arch = "wasm32"))]
    pub(super) fn save_view_png(&mut self) {
        let Some(view) = &self.view else { return };
        let (w, h) = (view.target.width, view.target.height);
        let target = Target::new(&self.renderer.device, w, h, shadelab_render::target::HDR_FORMAT);
        self.renderer.render(&mut self.gpu_scene, &self.scene, &target, &self.settings);
        let image = shadelab_render::target::read_back(&self.renderer.device, &self.renderer.queue, &target);
        self.saved_count += 1;
        let path = PathBuf::from(format!("shadelab-screenshot-{}.png", self.saved_count));
        self.message = Some(match image_file::save(&image, &path, image_file::ImageKind::Png) {
            Ok(()) => (format!("saved {} ({w}×{h})", path.display()), false),
            Err(e) => (format!("screenshot failed: {e:#}"), true),
        });
    }
}
