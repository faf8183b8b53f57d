//! A scripted run of the viewer (`--screenshot`, `--exit-after-frames`): count the frames, grab
//! the whole window (panel included) to a PNG at the chosen frame, then close.

use eframe::egui;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// Frames after which `--screenshot` alone takes its picture.
const SCREENSHOT_DEFAULT_FRAME: u32 = 5;

/// What the command line asked the run to do, and how far it has got.
pub(super) struct Script {
    frames: u32,
    exit_after: Option<u32>,
    screenshot_path: Option<PathBuf>,
    screenshot_slot: Arc<Mutex<Option<Arc<egui::ColorImage>>>>,
    screenshot_requested: bool,
}

impl Script {
    pub fn new(screenshot_path: Option<PathBuf>, exit_after: Option<u32>) -> Script {
        Script {
            frames: 0,
            exit_after,
            screenshot_path,
            screenshot_slot: Arc::new(Mutex::new(None)),
            screenshot_requested: false,
        }
    }

    /// Count a frame drawn; grab the window when its frame has come, then close.
    pub fn after_frame(&mut self, ctx: &egui::Context) {
        self.frames += 1;
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
