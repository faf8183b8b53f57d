//! Helpers for the lavapipe tests: the shared device, golden-image comparison with nv-flip, and
//! measurements on pixels.

use shadelab_render::{Gpu, LinearImage};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The lavapipe device every test uses (picked explicitly, so images are deterministic even on a
/// machine with a GPU).
pub fn gpu() -> &'static Gpu {
    static GPU: OnceLock<Gpu> = OnceLock::new();
    GPU.get_or_init(|| {
        let gpu = Gpu::lavapipe().unwrap_or_else(|e| panic!("{e}"));
        assert!(shadelab_render::gpu::is_lavapipe(&gpu.adapter.get_info()));
        gpu
    })
}

/// The project's root (the workspace).
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// Where failing tests write their actual and difference images.
pub fn failure_dir() -> PathBuf {
    workspace_root().join("target").join("test-failures")
}

/// How far an image may be from its golden, in nv-flip's terms.
#[derive(Clone, Copy, Debug)]
pub struct FlipThresholds {
    /// Largest mean FLIP error over the image.
    pub mean: f32,
    /// (percentile, largest FLIP error at that percentile).
    pub percentile: (f32, f32),
}

/// FLIP statistics of one comparison.
#[derive(Clone, Copy, Debug)]
pub struct FlipStats {
    pub mean: f32,
    pub percentile: f32,
}

/// Compare two sRGB8 images of the same size with nv-flip; also returns the error map as RGB8
/// (magma colour scale).
pub fn flip_compare(reference: &[u8], test: &[u8], width: u32, height: u32, percentile: f32) -> (FlipStats, Vec<u8>) {
    let r = nv_flip::FlipImageRgb8::with_data(width, height, reference);
    let t = nv_flip::FlipImageRgb8::with_data(width, height, test);
    let err = nv_flip::flip(r, t, nv_flip::DEFAULT_PIXELS_PER_DEGREE);
    let mut pool = nv_flip::FlipPool::from_image(&err);
    let stats = FlipStats { mean: pool.mean(), percentile: pool.get_percentile(percentile, true) };
    (stats, err.apply_color_lut(&nv_flip::magma_lut()).to_vec())
}

fn save_rgb8(path: &Path, data: &[u8], w: u32, h: u32) {
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    image::RgbImage::from_raw(w, h, data.to_vec()).unwrap().save(path).unwrap();
}

/// Compare a rendered image with `tests/goldens/<name>.png`. A missing golden fails (it is never
/// created silently); `UPDATE_GOLDENS=1` writes the golden instead. On failure, writes
/// `target/test-failures/<name>-actual.png` and `<name>-difference.png`.
pub fn check_golden(name: &str, image: &LinearImage, t: FlipThresholds) -> FlipStats {
    let path = workspace_root().join("tests").join("goldens").join(format!("{name}.png"));
    let actual = image.to_srgb8();
    let (w, h) = (image.width, image.height);
    if std::env::var("UPDATE_GOLDENS").as_deref() == Ok("1") {
        save_rgb8(&path, &actual, w, h);
        eprintln!("updated golden {}", path.display());
        return FlipStats { mean: 0.0, percentile: 0.0 };
    }
    let fail_dir = failure_dir();
    let golden = match image::open(&path) {
        Ok(g) => g.to_rgb8(),
        Err(e) => {
            save_rgb8(&fail_dir.join(format!("{name}-actual.png")), &actual, w, h);
            panic!(
                "golden {} is missing or unreadable ({e}); look at {} and run with UPDATE_GOLDENS=1 to accept it",
                path.display(),
                fail_dir.join(format!("{name}-actual.png")).display()
            );
        }
    };
    assert_eq!((golden.width(), golden.height()), (w, h), "golden {name} has another size");
    let (stats, diff) = flip_compare(golden.as_raw(), &actual, w, h, t.percentile.0);
    if stats.mean > t.mean || stats.percentile > t.percentile.1 {
        save_rgb8(&fail_dir.join(format!("{name}-actual.png")), &actual, w, h);
        save_rgb8(&fail_dir.join(format!("{name}-difference.png")), &diff, w, h);
        panic!(
            "{name}: FLIP mean {:.5} (max {}), p{} {:.5} (max {}); actual and difference images in {}",
            stats.mean,
            t.mean,
            t.percentile.0 * 100.0,
            stats.percentile,
            t.percentile.1,
            fail_dir.display()
        );
    }
    stats
}

/// Rec. 709 luminance of a linear pixel.
pub fn luminance(p: [f32; 4]) -> f32 {
    0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]
}

/// Pixel coordinates (x right, y down) of a world point seen by the scene's camera.
pub fn project(camera: &shadelab_model::Camera, p: glam::DVec3, width: u32, height: u32) -> (f64, f64) {
    let clip = camera.projection(width as f64 / height as f64) * camera.view() * p.extend(1.0);
    let (x, y) = (clip.x / clip.w, clip.y / clip.w);
    ((x + 1.0) * 0.5 * width as f64, (1.0 - y) * 0.5 * height as f64)
}

/// Pixels of the disc of a sphere's silhouette, shrunk to `shrink` of its projected radius
/// (so that no silhouette pixel is included).
pub fn sphere_disc(
    camera: &shadelab_model::Camera,
    center: glam::DVec3,
    radius: f64,
    width: u32,
    height: u32,
    shrink: f64,
) -> Vec<(u32, u32)> {
    let (cx, cy) = project(camera, center, width, height);
    let right = (camera.target - camera.eye).cross(camera.up).normalize();
    let (rx, _) = project(camera, center + right * radius, width, height);
    let r = (rx - cx).abs() * shrink;
    let mut out = Vec::new();
    for y in 0..height {
        for x in 0..width {
            let (dx, dy) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
            if dx * dx + dy * dy <= r * r {
                out.push((x, y));
            }
        }
    }
    out
}

/// Pixels where the reference sees object `object` and so do all 8 neighbours (no silhouette).
pub fn interior(r: &shadelab_model::reference::ReferenceImage, object: usize) -> Vec<(u32, u32)> {
    r.interior(object)
}

pub use shadelab_render::image_error::error_over as error;
