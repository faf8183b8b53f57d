//! A scripted run of the viewer (`--screenshot`, `--exit-after-frames`): count the frames, grab
//! the whole window (panel included) to a PNG at the chosen frame, then close.

use eframe::egui;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// Frames after which `--screenshot` alone takes its picture.
const SCREENSHOT_DEFAULT_FRAME: u32 = 5;

/// Frames of an `--exit-after-frames` run left out of its timing summary: the first frames build
/// pipelines (drawing with the uber pipeline meanwhile) and fill the timestamp ring.
const SUMMARY_WARMUP_FRAMES: u32 = 5;

/// What the command line asked the run to do, and how far it has got.
pub(super) struct Script {
    frames: u32,
    exit_after: Option<u32>,
    screenshot_path: Option<PathBuf>,
    screenshot_slot: Arc<Mutex<Option<Arc<egui::ColorImage>>>>,
    screenshot_requested: bool,
    /// When the last frame ended, and each measured frame's interval and scene pass, ms.
    last_frame: Option<web_time::Instant>,
    intervals_ms: Vec<f64>,
    scene_pass_ms: Vec<f64>,
}

impl Script {
    pub fn new(screenshot_path: Option<PathBuf>, exit_after: Option<u32>) -> Script {
        Script {
            frames: 0,
            exit_after,
            screenshot_path,
            screenshot_slot: Arc::new(Mutex::new(None)),
            screenshot_requested: false,
            last_frame: None,
            intervals_ms: Vec::new(),
            scene_pass_ms: Vec::new(),
        }
    }

    /// Record a frame's wall-clock interval since the previous one and the scene pass's time the
    /// panel shows (`None` until the ring reads one back).
    fn time_frame(&mut self, scene_pass_ms: Option<f64>) {
        let now = web_time::Instant::now();
        if let Some(last) = self.last_frame.replace(now)
            && self.frames > SUMMARY_WARMUP_FRAMES
        {
            self.intervals_ms.push((now - last).as_secs_f64() * 1e3);
            self.scene_pass_ms.extend(scene_pass_ms);
        }
    }

    /// The timing summary of a scripted run: what a frame costs against its scene pass.
    fn summary(&mut self) -> Option<String> {
        if self.intervals_ms.is_empty() || self.scene_pass_ms.is_empty() {
            return None;
        }
        let frame = shadelab_render::timing::median(&mut self.intervals_ms);
        let pass = shadelab_render::timing::median(&mut self.scene_pass_ms);
        Some(format!(
            "viewer: {} frames after {SUMMARY_WARMUP_FRAMES}: median frame interval {frame:.2} ms, median scene pass {pass:.2} ms, frame / scene pass {:.2}",
            self.intervals_ms.len(),
            frame / pass
        ))
    }

    /// Count a frame drawn; grab the window when its frame has come, then close.
    pub fn after_frame(&mut self, ctx: &egui::Context, scene_pass_ms: Option<f64>) {
        self.frames += 1;
        self.time_frame(scene_pass_ms);
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
                // The summary once, on the last frame (closing can take another frame or two).
                if self.frames == n
                    && let Some(line) = self.summary()
                {
                    println!("{line}");
                }
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
            ctx.request_repaint();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_summary_gives_the_medians_and_their_ratio() {
        let mut s = Script::new(None, Some(10));
        assert_eq!(s.summary(), None, "nothing timed yet");
        s.intervals_ms = vec![40.0, 38.0, 90.0];
        assert_eq!(s.summary(), None, "no scene pass read back yet");
        s.scene_pass_ms = vec![20.0, 19.0, 21.0];
        let line = s.summary().unwrap();
        assert!(
            line.contains("median frame interval 40.00 ms, median scene pass 20.00 ms, frame / scene pass 2.00"),
            "{line}"
        );
    }
}
