//! The one harness of the viewer's tests: the viewer on its built-in scene in an egui_kittest
//! window drawn by wgpu on lavapipe, and the waits and pixel counts the tests share.

use egui_kittest::Harness;
use shadelab::viewer::Viewer;
use std::time::{Duration, Instant};

pub type ViewerHarness = Harness<'static, Viewer>;

/// The viewer in a 1100×640 window, after its first two frames.
pub fn harness() -> ViewerHarness {
    harness_of_height(640.0)
}

/// The viewer in a window 1100 wide and `height` tall (taller shows more of the panel unscrolled),
/// after its first two frames.
pub fn harness_of_height(height: f32) -> ViewerHarness {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1100.0, height))
        .wgpu()
        .build_eframe(|cc| Viewer::new(cc, None, None).expect("viewer"));
    h.run_steps(2);
    h
}

/// Frames until `done` holds, at most `seconds` (readbacks, loads and references arrive in
/// later frames); what `done` returned.
pub fn run_until<T>(h: &mut ViewerHarness, what: &str, seconds: u64, done: impl Fn(&Viewer) -> Option<T>) -> T {
    let start = Instant::now();
    loop {
        h.run_steps(1);
        if let Some(t) = done(h.state()) {
            return t;
        }
        assert!(start.elapsed().as_secs() < seconds, "no {what} after {seconds} s");
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Frames until the file being opened is shown (or refused), at most 60 s.
pub fn wait_loaded(h: &mut ViewerHarness) -> u32 {
    let mut frames = 0;
    let start = Instant::now();
    while h.state().loading() && start.elapsed() < Duration::from_secs(60) {
        h.run_steps(1);
        frames += 1;
        std::thread::sleep(Duration::from_millis(10));
    }
    assert!(!h.state().loading(), "still loading after 60 s");
    frames
}

/// Pixels of the scene area (left of the panel) that differ by more than 8 in any channel.
pub fn changed_view_pixels(a: &image::RgbaImage, b: &image::RgbaImage) -> usize {
    let view_width = a.width() * 6 / 10;
    (0..a.height())
        .flat_map(|y| (0..view_width).map(move |x| (x, y)))
        .filter(|&(x, y)| (0..3).any(|c| a.get_pixel(x, y).0[c].abs_diff(b.get_pixel(x, y).0[c]) > 8))
        .count()
}
