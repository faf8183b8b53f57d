//! The image-error metric: how far a rendered image is from the f64 reference of the exact
//! surface (RMSE, largest error, FLIP, share of pixels visibly off), for the accuracy study and
//! the viewer's "difference from reference" view.

use crate::target::{LinearImage, linear_to_srgb};
use shadelab_model::reference::ReferenceImage;

/// One display step of an 8-bit sRGB image: a pixel "visibly off" differs by more than this in
/// some channel after both images are encoded for display.
pub const DISPLAY_STEP: f64 = 1.0 / 255.0;

/// Error of an image against its reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStats {
    /// Root mean square error over all pixels and the three channels, linear RGB (unclamped:
    /// highlights above 1 count with their full value).
    pub rmse: f64,
    /// Largest absolute error of any channel, linear RGB.
    pub max_abs: f64,
    /// Mean FLIP error (nv-flip, LDR, default 67 pixels per degree) of the display-encoded images.
    pub flip_mean: f64,
    /// Share of pixels (0..=1) whose display-encoded 8-bit sRGB value differs by more than
    /// [`DISPLAY_STEP`] in some channel.
    pub share_off: f64,
}

/// A comparison: the statistics and, per pixel, the FLIP error map in nv-flip's magma colour
/// scale (RGB8, rows top to bottom).
pub struct Comparison {
    pub stats: ErrorStats,
    pub flip_map_rgb8: Vec<u8>,
}

/// Encode a linear value for display as 8-bit sRGB, the same rounding as the PNG output.
fn srgb8(x: f64) -> u8 {
    (linear_to_srgb(x as f32) * 255.0 + 0.5) as u8
}

/// Compare a rendered image with the reference of the same size.
///
/// Non-finite rendered values count as an error of `f64::INFINITY` in RMSE and max (a NaN must
/// never look accurate).
pub fn compare(image: &LinearImage, reference: &ReferenceImage) -> Comparison {
    assert_eq!((image.width, image.height), (reference.width, reference.height), "image and reference sizes differ");
    let n = image.pixels.len();
    let (mut sum_sq, mut max_abs, mut off) = (0.0f64, 0.0f64, 0usize);
    let mut test8 = Vec::with_capacity(n * 3);
    let mut ref8 = Vec::with_capacity(n * 3);
    for (p, r) in image.pixels.iter().zip(&reference.pixels) {
        let mut pixel_off = false;
        for c in 0..3 {
            let v = p[c] as f64;
            let e = if v.is_finite() { (v - r[c]).abs() } else { f64::INFINITY };
            sum_sq += e * e;
            max_abs = max_abs.max(e);
            let (a, b) = (srgb8(v), srgb8(r[c]));
            pixel_off |= (a as f64 - b as f64).abs() / 255.0 > DISPLAY_STEP * 1.0001;
            test8.push(a);
            ref8.push(b);
        }
        off += pixel_off as usize;
    }
    let (w, h) = (image.width, image.height);
    let err = nv_flip::flip(
        nv_flip::FlipImageRgb8::with_data(w, h, &ref8),
        nv_flip::FlipImageRgb8::with_data(w, h, &test8),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    );
    let flip_mean = nv_flip::FlipPool::from_image(&err).mean() as f64;
    Comparison {
        stats: ErrorStats {
            rmse: (sum_sq / (n * 3).max(1) as f64).sqrt(),
            max_abs,
            flip_mean,
            share_off: off as f64 / n.max(1) as f64,
        },
        flip_map_rgb8: err.apply_color_lut(&nv_flip::magma_lut()).to_vec(),
    }
}

/// nv-flip's magma colour scale, 256 RGB8 entries from FLIP error 0 to 1 (the colours of
/// [`Comparison::flip_map_rgb8`]), for drawing a legend.
pub fn magma_scale() -> Vec<[u8; 3]> {
    nv_flip::magma_lut().to_vec().chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
}

/// The reference as a linear image (to show it or save it like a render).
pub fn reference_image(reference: &ReferenceImage) -> LinearImage {
    LinearImage {
        width: reference.width,
        height: reference.height,
        pixels: reference.pixels.iter().map(|p| [p[0] as f32, p[1] as f32, p[2] as f32, 1.0]).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reference(w: u32, h: u32, v: f64) -> ReferenceImage {
        ReferenceImage {
            width: w,
            height: h,
            pixels: vec![[v; 3]; (w * h) as usize],
            object: vec![None; (w * h) as usize],
        }
    }

    #[test]
    fn identical_images_have_no_error() {
        let r = reference(16, 8, 0.3);
        let c = compare(&reference_image(&r), &r);
        assert_eq!(c.stats.share_off, 0.0);
        assert!(c.stats.rmse < 1e-7 && c.stats.max_abs < 1e-7, "{:?}", c.stats);
        assert_eq!(c.stats.flip_mean, 0.0);
        assert_eq!(c.flip_map_rgb8.len(), 16 * 8 * 3);
    }

    #[test]
    fn one_wrong_pixel() {
        let r = reference(10, 10, 0.5);
        let mut img = reference_image(&r);
        img.pixels[0] = [1.0, 0.5, 0.5, 1.0];
        let s = compare(&img, &r).stats;
        assert!((s.max_abs - 0.5).abs() < 1e-6);
        assert!((s.rmse - (0.25f64 / 300.0).sqrt()).abs() < 1e-6);
        assert_eq!(s.share_off, 0.01);
        assert!(s.flip_mean > 0.0);
    }

    #[test]
    fn a_nan_is_never_accurate() {
        let r = reference(4, 4, 0.5);
        let mut img = reference_image(&r);
        img.pixels[5][1] = f32::NAN;
        let s = compare(&img, &r).stats;
        assert!(s.rmse.is_infinite() && s.max_abs.is_infinite());
    }

    #[test]
    fn a_one_step_difference_is_not_off() {
        // 0.5 and the next 8-bit step differ by exactly one step: not "more than 1/255".
        let r = reference(4, 4, 0.5);
        let mut img = reference_image(&r);
        let step_up = (1.0f64 / 255.0 + linear_to_srgb(0.5) as f64).powf(2.2) as f32; // ≈ one step
        img.pixels[0] = [step_up, 0.5, 0.5, 1.0];
        let a = srgb8(step_up as f64) as i32 - srgb8(0.5) as i32;
        let s = compare(&img, &r).stats;
        assert_eq!(s.share_off > 0.0, a.abs() > 1, "step {a}");
    }
}
