//! Opening a scene file without a freeze: a worker thread reads, parses and uploads it while the
//! viewer keeps drawing the old scene, with a progress bar and a cancel button in the panel. The
//! browser has no threads: there each stage runs in a frame of its own, so the bar is drawn
//! between them (a stage itself still holds the page while it runs).

use super::Viewer;
use eframe::egui;
use shadelab_model::gltf_io::{GltfError, LoadedScene};
use shadelab_render::{SceneGpu, Uploader};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, Sender, TryRecvError};
use web_time::Instant;

/// What the worker reports.
enum Report {
    /// A stage has begun: its name and the share of the work done before it.
    Stage(&'static str, f32),
    /// The scene read and on the GPU, or the one-line error.
    Done(Box<Result<(LoadedScene, SceneGpu), String>>),
}

/// Where a scene comes from: a file on disk, or files handed in together by name (the browser's
/// picker or a drop: a `.gltf` with its `.bin` and images, or a `.glb`).
pub enum Source {
    /// A file and whether its URIs may lead outside its folder.
    Path(PathBuf, bool),
    Files {
        main: String,
        files: Vec<(String, Vec<u8>)>,
    },
}

impl Source {
    /// The name errors and the panel give it.
    pub fn name(&self) -> String {
        match self {
            Source::Path(p, _) => p.display().to_string(),
            Source::Files { main, .. } => main.clone(),
        }
    }

    fn load(&self) -> Result<LoadedScene, GltfError> {
        match self {
            Source::Path(p, outside) => shadelab_model::gltf_io::load_scene_with(p, *outside),
            Source::Files { main, files } => shadelab_model::gltf_io::load_scene_from_files(main, files),
        }
    }

    /// Files handed in together: the scene file is the first `.glb` or `.gltf` among them.
    pub fn from_files(files: Vec<(String, Vec<u8>)>) -> Result<Source, String> {
        let is_scene = |n: &str| {
            let n = n.to_ascii_lowercase();
            n.ends_with(".gltf") || n.ends_with(".glb")
        };
        match files.iter().find(|(n, _)| is_scene(n)) {
            Some((main, _)) => Ok(Source::Files { main: main.clone(), files }),
            None => {
                let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
                Err(format!("no .gltf or .glb file among the files given: {}", names.join(", ")))
            }
        }
    }
}

/// A file being opened.
pub(super) struct Loading {
    name: String,
    started: Instant,
    stage: &'static str,
    fraction: f32,
    cancel: Arc<AtomicBool>,
    rx: Receiver<Report>,
    /// In the browser: the stages still to run, one a frame.
    #[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
    steps: Option<Steps>,
}

/// How much of the work each stage starts at: reading and parsing is most of it for a large file
/// (every accessor checked and converted), the upload the rest.
const UPLOAD_STARTS_AT: f32 = 0.7;

/// The stages of opening a file, run one at a time; each sends its reports.
struct Steps {
    source: Source,
    uploader: Uploader,
    parsed: Option<LoadedScene>,
    tx: Sender<Report>,
}

impl Steps {
    /// Run the next stage; false once the last has run (or the first failed).
    fn step(&mut self) -> bool {
        let Some(loaded) = self.parsed.take() else {
            // A send fails only when the viewer has stopped listening (cancelled): stop then.
            let _ = self.tx.send(Report::Stage("reading and parsing", 0.0));
            match self.source.load() {
                Ok(l) => {
                    self.parsed = Some(l);
                    return self.tx.send(Report::Stage("uploading", UPLOAD_STARTS_AT)).is_ok();
                }
                Err(e) => {
                    let _ = self.tx.send(Report::Done(Box::new(Err(e.to_string()))));
                    return false;
                }
            }
        };
        let name = self.source.name();
        let done = self.uploader.upload(&loaded.scene).map(|gpu| (loaded, gpu)).map_err(|e| format!("{name}: {e}"));
        let _ = self.tx.send(Report::Done(Box::new(done)));
        false
    }
}

/// Read, parse and upload `source`: on a worker thread, or in the browser a stage a frame
/// (`Viewer::poll_loading` runs them); `cancel` set stops it between stages.
fn start(source: Source, uploader: Uploader) -> Loading {
    let (tx, rx) = std::sync::mpsc::channel();
    let cancel = Arc::new(AtomicBool::new(false));
    let name = source.name();
    let mut steps = Steps { source, uploader, parsed: None, tx };
    let steps = if cfg!(target_arch = "wasm32") {
        Some(steps)
    } else {
        let stop = cancel.clone();
        std::thread::spawn(move || while !stop.load(Ordering::Relaxed) && steps.step() {});
        None
    };
    Loading { name, started: Instant::now(), stage: "starting", fraction: 0.0, cancel, rx, steps }
}

impl Viewer {
    /// Open a glTF 2.0 file (the path field, the dialog, or a file dropped on the window) on a
    /// worker thread; the current scene stays on show until the new one is ready. A bad file
    /// leaves it as it is and shows the loader's one-line error. A file opened while another
    /// loads replaces that one.
    pub fn open_file(&mut self, path: &Path) {
        // An environment map lights the scene on show instead of replacing it.
        if is_env_map(&path.to_string_lossy()) {
            self.use_env_map(shadelab_model::lighting::env_file::load_env_image(path));
            return;
        }
        self.open_source(Source::Path(path.to_path_buf(), self.allow_outside_paths));
    }

    /// Open files handed in together ([`Source::from_files`]) as [`Self::open_file`] does.
    pub fn open_files(&mut self, files: Vec<(String, Vec<u8>)>) {
        if let [(name, bytes)] = &files[..]
            && is_env_map(name)
        {
            self.use_env_map(shadelab_model::lighting::env_file::read_env_image(bytes, name));
            return;
        }
        match Source::from_files(files) {
            Ok(source) => self.open_source(source),
            Err(e) => self.message = Some((e, true)),
        }
    }

    fn open_source(&mut self, source: Source) {
        self.cancel_loading(false);
        self.loading = Some(start(source, self.renderer.uploader()));
    }

    /// Whether a file is being opened.
    pub fn loading(&self) -> bool {
        self.loading.is_some()
    }

    /// Stop opening the file being opened; the scene on show stays. `say`: tell the panel.
    pub fn cancel_loading(&mut self, say: bool) {
        if let Some(l) = self.loading.take() {
            l.cancel.store(true, Ordering::Relaxed);
            if say {
                self.message = Some((format!("cancelled opening {}", l.name), false));
            }
        }
    }

    /// Take the worker's reports; show the scene once it is ready.
    pub(super) fn poll_loading(&mut self, ctx: &egui::Context) {
        let Some(l) = &mut self.loading else { return };
        if let Some(steps) = &mut l.steps
            && !steps.step()
        {
            l.steps = None;
        }
        let done = loop {
            match l.rx.try_recv() {
                Ok(Report::Stage(stage, fraction)) => (l.stage, l.fraction) = (stage, fraction),
                Ok(Report::Done(result)) => break Some(*result),
                Err(TryRecvError::Empty) => break None,
                Err(TryRecvError::Disconnected) => {
                    break Some(Err(format!("{}: the loader stopped", l.name)));
                }
            }
        };
        let Some(result) = done else {
            // Draw the bar again soon: the reports come from outside egui's events.
            ctx.request_repaint_after(std::time::Duration::from_millis(50));
            return;
        };
        let name = l.name.clone();
        self.loading = None;
        match result {
            Ok((loaded, gpu_scene)) if self.is_pending_link_file(&name) => {
                self.finish_link_file(loaded, gpu_scene, &name)
            }
            Ok((loaded, gpu_scene)) => {
                let mut text = format!("opened {name}");
                for w in &loaded.warnings {
                    text.push_str(&format!("\nwarning: {w}"));
                }
                let settings = loaded.settings;
                self.show_loaded_on_gpu(loaded, gpu_scene, &name);
                if let Some(m) = settings.shading {
                    self.settings.shading = m;
                }
                if let Some(m) = settings.specular {
                    self.settings.specular = m;
                }
                self.message = Some((text, false));
            }
            Err(e) => {
                self.pending_link = None;
                self.message = Some((e, true));
            }
        }
    }

    /// The progress bar and its cancel button, while a file is being opened.
    pub(super) fn loading_ui(&mut self, ui: &mut egui::Ui) {
        let Some(l) = &self.loading else { return };
        let name = Path::new(&l.name).file_name().map_or_else(|| l.name.clone(), |n| n.to_string_lossy().into());
        let text = format!("{name}: {} ({:.1} s)", l.stage, l.started.elapsed().as_secs_f64());
        let bar = egui::ProgressBar::new(l.fraction).text(text).animate(true);
        let mut cancel = false;
        ui.horizontal(|ui| {
            ui.add(bar.desired_width(ui.available_width() - 60.0));
            cancel = ui.button("cancel").on_hover_text("stop opening this file; the scene on show stays").clicked();
        });
        if cancel {
            self.cancel_loading(true);
        }
    }
}

/// Whether `name` is an environment map's (`.hdr` or `.exr`), which the files row opens as the
/// scene's environment.
pub fn is_env_map(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    lower.ends_with(".hdr") || lower.ends_with(".exr")
}
