//! The one harness of the viewer's tests: the viewer on its built-in scene in an egui_kittest
//! window drawn by wgpu on lavapipe, and the waits and pixel counts the tests share.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
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

/// The pixels of the scene area (the left 6/10 of the window, beside the panel).
fn view_pixels(image: &image::RgbaImage) -> impl Iterator<Item = (u32, u32)> {
    let view_width = image.width() * 6 / 10;
    (0..image.height()).flat_map(move |y| (0..view_width).map(move |x| (x, y)))
}

/// Pixels of the scene area that differ by more than 8 in any channel.
pub fn changed_view_pixels(a: &image::RgbaImage, b: &image::RgbaImage) -> usize {
    view_pixels(a).filter(|&(x, y)| (0..3).any(|c| a.get_pixel(x, y).0[c].abs_diff(b.get_pixel(x, y).0[c]) > 8)).count()
}

/// Pixels of the scene area whose RGB satisfies `test`.
pub fn view_pixels_where(image: &image::RgbaImage, test: impl Fn([u8; 3]) -> bool) -> usize {
    view_pixels(image)
        .filter(|&(x, y)| {
            let [r, g, b, _] = image.get_pixel(x, y).0;
            test([r, g, b])
        })
        .count()
}

/// Clicks the widget labelled `label` and runs three frames, enough for the change to be drawn.
pub fn click(h: &mut ViewerHarness, label: &str) {
    h.get_by_label(label).click();
    h.run_steps(3);
}

/// Scrolls the widget labelled `label` into view ([`scroll_to`]), then clicks it as [`click`] does.
pub fn scroll_click(h: &mut ViewerHarness, label: &str) {
    scroll_to(h, label);
    click(h, label);
}

/// Scrolls the widget labelled `label` into view and runs frames until it stands still.
pub fn scroll_to(h: &mut ViewerHarness, label: &str) {
    h.get_by_label(label).scroll_to_me();
    until_still(h, |h| h.get_by_label(label).rect());
}

/// [`scroll_to`] for the widget whose label contains `part`.
pub fn scroll_to_containing(h: &mut ViewerHarness, part: &str) {
    h.get_by_label_contains(part).scroll_to_me();
    until_still(h, |h| h.get_by_label_contains(part).rect());
}

/// Frames until `rect` (a widget's place) is the same in three frames running: a scroll has
/// ended. At most the 20 frames of the longest scroll, each drawing the scene.
fn until_still(h: &mut ViewerHarness, rect: impl Fn(&ViewerHarness) -> egui::Rect) {
    let mut places = Vec::new();
    while places.len() < 20 {
        h.run_steps(1);
        places.push(rect(h));
        if let [.., a, b, c] = places[..]
            && a == b
            && b == c
        {
            return;
        }
    }
}

/// Saves a frame under the test build's temporary folder (target/tmp/`name`), kept for a look.
pub fn keep_for_a_look(image: &image::RgbaImage, name: &str) {
    image.save(std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name)).expect("save the frame");
}

/// Press or release the primary button at `at`.
fn button(h: &mut ViewerHarness, at: egui::Pos2, pressed: bool) {
    let button = egui::PointerButton::Primary;
    h.input_mut().events.push(egui::Event::PointerButton { pos: at, button, pressed, modifiers: Default::default() });
    h.run_steps(1);
}

/// Drag across the view for `frames` frames, 4 points a frame: the orbit turns the camera. The
/// pointer then leaves the window, so no cursor is drawn over the view.
pub fn orbit(h: &mut ViewerHarness, frames: u32) {
    let mut at = egui::pos2(200.0, 300.0);
    h.input_mut().events.push(egui::Event::PointerMoved(at));
    h.run_steps(1);
    button(h, at, true);
    for _ in 0..frames {
        at.x += 4.0;
        h.input_mut().events.push(egui::Event::PointerMoved(at));
        h.run_steps(1);
    }
    button(h, at, false);
    h.input_mut().events.push(egui::Event::PointerGone);
    h.run_steps(1);
}
