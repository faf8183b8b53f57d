//! Opening a scene file without a freeze: a worker thread reads, parses and uploads it while the
//! viewer keeps drawing the old scene, with a progress bar and a cancel button in the panel. The
//! browser has no threads: there the parse runs in slices (`gltf_io::SceneParse`), as many a
//! frame as fit in `PARSE_BUDGET`, and the upload in a frame of its own.

use super::Viewer;
use eframe::egui;
use shadelab_model::gltf_io::{LoadedScene, SceneParse};
use shadelab_render::{SceneGpu, Uploader};
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, Sender, TryRecvError};
use web_time::{Duration, Instant};

/// Where a scene comes from: a file on disk, or files handed in together by name (the browser's
/// picker or a drop: a `.gltf` with its `.bin` and images, or a `.glb`).
pub use shadelab_model::gltf_io::ParseSource as Source;

/// Parse time a frame spends on the page: as long as the rest of the frame before took, within
/// these bounds. So frames keep coming at half their rate or better, and the parse takes at most
/// about twice its own time. The least is half of a 60 Hz frame; the most, a quarter second, is
/// the longest a click waits on the parse where drawing is slow (a CPU adapter).
const PARSE_BUDGET: (Duration, Duration) = (Duration::from_millis(8), Duration::from_millis(250));

/// What the worker reports.
enum Report {
    /// A stage has begun: its name, the share of the work done before it, and the parse's
    /// slices so far.
    Stage(&'static str, f32, usize),
    /// The scene read and on the GPU, or the one-line error.
    Done(Box<Result<(LoadedScene, SceneGpu), String>>),
}

/// How the last file opened went: what the page publishes and the browser test reads.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct LoadStats {
    /// Wall time of the parse, from the open to the upload's start.
    pub(super) parse_ms: f64,
    /// Slices the parse ran in.
    pub(super) slices: usize,
    /// Viewer frames drawn while the parse ran.
    pub(super) frames_during_parse: u32,
    /// Wall time of the upload after it.
    pub(super) upload_ms: f64,
    /// Longest a frame spent on the parse's slices (the browser; 0 where a worker parses).
    pub(super) longest_hold_ms: f64,
}

/// A file being opened.
pub(super) struct Loading {
    name: String,
    started: Instant,
    stage: &'static str,
    fraction: f32,
    cancel: Arc<AtomicBool>,
    rx: Receiver<Report>,
    /// In the browser: the parse's slices and the upload still to run.
    #[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
    steps: Option<Steps>,
    stats: LoadStats,
    /// When the last slices of the parse ended (the browser).
    slices_ended: Option<Instant>,
}

/// How much of the work each stage starts at: reading and parsing is most of it for a large file
/// (every accessor checked and converted), the upload the rest.
const UPLOAD_STARTS_AT: f32 = 0.7;

/// The stages of opening a file: the parse a slice at a time, then the upload; each sends its
/// reports.
struct Steps {
    name: String,
    parse: SceneParse,
    uploader: Uploader,
    parsed: Option<LoadedScene>,
    tx: Sender<Report>,
}

impl Steps {
    /// Run the parse's next slice, or the upload once the parse is done; false once the last has
    /// run (or the parse failed).
    fn step(&mut self) -> bool {
        let Some(loaded) = self.parsed.take() else {
            // A send fails only when the viewer has stopped listening (cancelled): stop then.
            return match self.parse.step() {
                None => true,
                Some(Ok(l)) => {
                    self.parsed = Some(l);
                    self.tx.send(Report::Stage("uploading", UPLOAD_STARTS_AT, self.parse.slices())).is_ok()
                }
                Some(Err(e)) => {
                    let _ = self.tx.send(Report::Done(Box::new(Err(e.to_string()))));
                    false
                }
            };
        };
        let name = &self.name;
        let done = self.uploader.upload(&loaded.scene).map(|gpu| (loaded, gpu)).map_err(|e| format!("{name}: {e}"));
        let _ = self.tx.send(Report::Done(Box::new(done)));
        false
    }

    fn parsing(&self) -> bool {
        self.parsed.is_none()
    }
}

/// Read, parse and upload `source`: on a worker thread, or in the browser in slices
/// (`Viewer::poll_loading` runs them); `cancel` set stops it between slices.
fn start(source: Source, uploader: Uploader) -> Loading {
    let (tx, rx) = std::sync::mpsc::channel();
    let cancel = Arc::new(AtomicBool::new(false));
    let name = source.name();
    let _ = tx.send(Report::Stage("reading and parsing", 0.0, 0));
    let mut steps = Steps { name: name.clone(), parse: SceneParse::new(source), uploader, parsed: None, tx };
    let steps = if cfg!(target_arch = "wasm32") {
        Some(steps)
    } else {
        let stop = cancel.clone();
        std::thread::spawn(move || while !stop.load(Ordering::Relaxed) && steps.step() {});
        None
    };
    Loading {
        name,
        started: Instant::now(),
        stage: "starting",
        fraction: 0.0,
        cancel,
        rx,
        steps,
        stats: LoadStats::default(),
        slices_ended: None,
    }
}

impl Loading {
    /// In the browser: the parse's slices until this frame's share (`PARSE_BUDGET`) is spent,
    /// or the upload.
    fn run_steps(&mut self) {
        let Some(steps) = &mut self.steps else { return };
        let now = Instant::now();
        let rest_of_frame = self.slices_ended.map_or(PARSE_BUDGET.0, |t| now - t);
        let until = now + rest_of_frame.clamp(PARSE_BUDGET.0, PARSE_BUDGET.1);
        let more = loop {
            let more = steps.step();
            if !more || !steps.parsing() || Instant::now() >= until {
                break more;
            }
        };
        if !more {
            self.steps = None;
        }
        let ended = Instant::now();
        self.stats.longest_hold_ms = self.stats.longest_hold_ms.max((ended - now).as_secs_f64() * 1e3);
        self.slices_ended = Some(ended);
    }

    /// Count this frame if the parse is running.
    fn count_frame(&mut self) {
        if self.stage == "reading and parsing" {
            self.stats.frames_during_parse += 1;
        }
    }
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
        l.run_steps();
        let done = loop {
            match l.rx.try_recv() {
                Ok(Report::Stage(stage, fraction, slices)) => {
                    if stage != "reading and parsing" {
                        l.stats.parse_ms = l.started.elapsed().as_secs_f64() * 1e3;
                        l.stats.slices = slices;
                    }
                    (l.stage, l.fraction) = (stage, fraction);
                }
                Ok(Report::Done(result)) => break Some(*result),
                Err(TryRecvError::Empty) => break None,
                Err(TryRecvError::Disconnected) => {
                    break Some(Err(format!("{}: the loader stopped", l.name)));
                }
            }
        };
        l.count_frame();
        let Some(result) = done else {
            if l.steps.is_some() {
                // The next slices run in the next frame.
                ctx.request_repaint();
            } else {
                // Draw the bar again soon: the reports come from outside egui's events.
                ctx.request_repaint_after(std::time::Duration::from_millis(50));
            }
            return;
        };
        l.stats.upload_ms = l.started.elapsed().as_secs_f64() * 1e3 - l.stats.parse_ms;
        self.last_load = Some(l.stats);
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
