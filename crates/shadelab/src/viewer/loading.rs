//! Opening a scene file without a freeze: a worker thread reads, parses and uploads it while the
//! viewer keeps drawing the old scene, with a progress bar and a cancel button in the panel.

use super::Viewer;
use eframe::egui;
use shadelab_model::gltf_io::LoadedScene;
use shadelab_render::{SceneGpu, Uploader};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError};
use std::time::Instant;

/// What the worker reports.
enum Report {
    /// A stage has begun: its name and the share of the work done before it.
    Stage(&'static str, f32),
    /// The scene read and on the GPU, or the one-line error.
    Done(Box<Result<(LoadedScene, SceneGpu), String>>),
}

/// A file being opened.
pub(super) struct Loading {
    path: PathBuf,
    started: Instant,
    stage: &'static str,
    fraction: f32,
    cancel: Arc<AtomicBool>,
    rx: Receiver<Report>,
}

/// How much of the work each stage starts at: reading and parsing is most of it for a large file
/// (every accessor checked and converted), the upload the rest.
const UPLOAD_STARTS_AT: f32 = 0.7;

/// Read, parse and upload `path` on a worker thread; `cancel` set stops it between stages.
fn start(path: PathBuf, uploader: Uploader) -> Loading {
    let (tx, rx) = std::sync::mpsc::channel();
    let cancel = Arc::new(AtomicBool::new(false));
    let stop = cancel.clone();
    let file = path.clone();
    std::thread::spawn(move || {
        // A send fails only when the viewer has stopped listening (cancelled): stop then.
        let _ = tx.send(Report::Stage("reading and parsing", 0.0));
        let loaded = match shadelab_model::gltf_io::load_scene(&file) {
            Ok(l) => l,
            Err(e) => {
                let _ = tx.send(Report::Done(Box::new(Err(e.to_string()))));
                return;
            }
        };
        if stop.load(Ordering::Relaxed) || tx.send(Report::Stage("uploading", UPLOAD_STARTS_AT)).is_err() {
            return;
        }
        let done =
            uploader.upload(&loaded.scene).map(|gpu| (loaded, gpu)).map_err(|e| format!("{}: {e}", file.display()));
        if !stop.load(Ordering::Relaxed) {
            let _ = tx.send(Report::Done(Box::new(done)));
        }
    });
    Loading { path, started: Instant::now(), stage: "starting", fraction: 0.0, cancel, rx }
}

impl Viewer {
    /// Open a glTF 2.0 file (the path field, the dialog, or a file dropped on the window) on a
    /// worker thread; the current scene stays on show until the new one is ready. A bad file
    /// leaves it as it is and shows the loader's one-line error. A file opened while another
    /// loads replaces that one.
    pub fn open_file(&mut self, path: &Path) {
        self.cancel_loading(false);
        self.loading = Some(start(path.to_path_buf(), self.renderer.uploader()));
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
                self.message = Some((format!("cancelled opening {}", l.path.display()), false));
            }
        }
    }

    /// Take the worker's reports; show the scene once it is ready.
    pub(super) fn poll_loading(&mut self, ctx: &egui::Context) {
        let Some(l) = &mut self.loading else { return };
        let done = loop {
            match l.rx.try_recv() {
                Ok(Report::Stage(stage, fraction)) => (l.stage, l.fraction) = (stage, fraction),
                Ok(Report::Done(result)) => break Some(*result),
                Err(TryRecvError::Empty) => break None,
                Err(TryRecvError::Disconnected) => {
                    break Some(Err(format!("{}: the loader stopped", l.path.display())));
                }
            }
        };
        let Some(result) = done else {
            // Draw the bar again soon: the reports come from outside egui's events.
            ctx.request_repaint_after(std::time::Duration::from_millis(50));
            return;
        };
        let path = l.path.clone();
        self.loading = None;
        match result {
            Ok((loaded, gpu_scene)) => {
                let mut text = format!("opened {}", path.display());
                for w in &loaded.warnings {
                    text.push_str(&format!("\nwarning: {w}"));
                }
                let settings = loaded.settings;
                self.show_loaded_on_gpu(loaded, gpu_scene, &path.display().to_string());
                if let Some(m) = settings.shading {
                    self.settings.shading = m;
                }
                if let Some(m) = settings.specular {
                    self.settings.specular = m;
                }
                self.message = Some((text, false));
            }
            Err(e) => self.message = Some((e, true)),
        }
    }

    /// The progress bar and its cancel button, while a file is being opened.
    pub(super) fn loading_ui(&mut self, ui: &mut egui::Ui) {
        let Some(l) = &self.loading else { return };
        let name = l.path.file_name().map_or_else(|| l.path.display().to_string(), |n| n.to_string_lossy().into());
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
