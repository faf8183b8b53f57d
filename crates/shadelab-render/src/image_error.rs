//! The image-error metric: how far a rendered image is from the f64 reference of the exact
//! surface (RMSE, largest error, FLIP, share of pixels visibly off) and how far its cast shadows
//! are from the reference's exact ones (the share of pixels whose lit/shadowed state disagrees,
//! and a map of them), for the accuracy study and the viewer's "difference from reference" view.

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

/// Mean and largest |image − reference| over the channels of `pixels`, and where the largest is.
pub fn error_over(image: &LinearImage, reference: &ReferenceImage, pixels: &[(u32, u32)]) -> (f64, f64, (u32, u32)) {
    let (mut sum, mut max, mut worst) = (0.0f64, 0.0f64, (0, 0));
    for &(x, y) in pixels {
        let (g, r) = (image.get(x, y), reference.get(x, y));
        for c in 0..3 {
            let e = (g[c] as f64 - r[c]).abs();
            sum += e;
            if e > max {
                (max, worst) = (e, (x, y));
            }
        }
    }
    (sum / (3 * pixels.len().max(1)) as f64, max, worst)
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
    let (flip_mean, flip_map_rgb8) = flip_rgb8(&ref8, &test8, w, h);
    Comparison {
        stats: ErrorStats {
            rmse: (sum_sq / (n * 3).max(1) as f64).sqrt(),
            max_abs,
            flip_mean,
            share_off: off as f64 / n.max(1) as f64,
        },
        flip_map_rgb8,
    }
}

/// FLIP's mean and its map in magma colours: nv-flip's C++ on native targets, the same algorithm
/// in Rust ([`crate::flip`], held equal to nv-flip by its tests) on wasm32.
#[cfg(not(target_arch = "wasm32"))]
fn flip_rgb8(reference: &[u8], test: &[u8], w: u32, h: u32) -> (f64, Vec<u8>) {
    let err = nv_flip::flip(
        nv_flip::FlipImageRgb8::with_data(w, h, reference),
        nv_flip::FlipImageRgb8::with_data(w, h, test),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    );
    let mean = nv_flip::FlipPool::from_image(&err).mean() as f64;
    (mean, err.apply_color_lut(&nv_flip::magma_lut()).to_vec())
}

#[cfg(target_arch = "wasm32")]
fn flip_rgb8(reference: &[u8], test: &[u8], w: u32, h: u32) -> (f64, Vec<u8>) {
    let map = crate::flip::flip_map(reference, test, w as usize, h as usize, crate::flip::DEFAULT_PIXELS_PER_DEGREE);
    // nv-flip's pool sums in f32 in pixel order; the same sum keeps the two means equal.
    let mean = if map.is_empty() { 0.0 } else { map.iter().fold(0f32, |s, &e| s + e) / map.len() as f32 };
    (mean as f64, crate::flip::apply_magma(&map))
}

/// Compare two renders of the same size, `image` against `against` (as [`compare`] does against
/// the reference).
pub fn compare_images(image: &LinearImage, against: &LinearImage) -> Comparison {
    assert_eq!((image.width, image.height), (against.width, against.height), "image sizes differ");
    let pixels: Vec<[f64; 3]> = against.pixels.iter().map(|p| [p[0] as f64, p[1] as f64, p[2] as f64]).collect();
    let reference = ReferenceImage::from_pixels(against.width, against.height, pixels);
    compare(image, &reference)
}

/// nv-flip's magma colour scale, 256 RGB8 entries from FLIP error 0 to 1 (the colours of
/// [`Comparison::flip_map_rgb8`]), for drawing a legend.
pub fn magma_scale() -> Vec<[u8; 3]> {
    crate::flip::magma_lut().to_vec()
}

/// The reference as a linear image (to show it or save it like a render).
pub fn reference_image(reference: &ReferenceImage) -> LinearImage {
    LinearImage {
        width: reference.width,
        height: reference.height,
        // Alpha 0 where nothing was hit and the scene has no background (a term view).
        pixels: (reference.pixels.iter().zip(&reference.object))
            .map(|(p, o)| {
                let alpha = if o.is_none() && reference.background.is_none() { 0.0 } else { 1.0 };
                [p[0] as f32, p[1] as f32, p[2] as f32, alpha]
            })
            .collect(),
    }
}

/// A pixel is in a cast shadow where the image with shadows is darker than the same image
/// without them by more than this many display steps ([`DISPLAY_STEP`]) in some channel, both
/// encoded for display as 8-bit sRGB. It is the "visibly off" rule of [`ErrorStats::share_off`]:
/// a darkening of one step cannot be seen, and it covers what else differs between the two
/// renders (f32 rounding between two shader permutations is about 1e-7, far under a step). The
/// same rule on both sides means a hidden light too faint to show counts on neither.
pub const SHADOW_DARKENING_STEPS: u8 = 1;

/// Which pixels are in a cast shadow: for each pixel, its colour with shadows and without
/// (linear RGB), darker with shadows by more than [`SHADOW_DARKENING_STEPS`]. A non-finite value
/// is displayed black (`linear_to_srgb`), so it counts as shadowed where the pixel is lit without.
pub fn shadowed_pixels(pairs: impl Iterator<Item = ([f64; 3], [f64; 3])>) -> Vec<bool> {
    pairs.map(|(on, off)| (0..3).any(|c| srgb8(off[c]).saturating_sub(srgb8(on[c])) > SHADOW_DARKENING_STEPS)).collect()
}

/// The GPU's lit/shadowed state: a render with shadows against the same render with them off.
pub fn gpu_shadow_state(shadowed: &LinearImage, unshadowed: &LinearImage) -> Vec<bool> {
    assert_eq!((shadowed.width, shadowed.height), (unshadowed.width, unshadowed.height), "image sizes differ");
    let f = |p: &[f32; 4]| [p[0] as f64, p[1] as f64, p[2] as f64];
    shadowed_pixels(shadowed.pixels.iter().zip(&unshadowed.pixels).map(|(a, b)| (f(a), f(b))))
}

/// The reference's lit/shadowed state, by the same rule as the GPU's: its image against its
/// image without cast shadows (`ReferenceImage::unshadowed`, from the same rays).
pub fn reference_shadow_state(reference: &ReferenceImage) -> Vec<bool> {
    shadowed_pixels(reference.pixels.iter().copied().zip(reference.unshadowed.iter().copied()))
}

/// One pixel of the shadow error map.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadowPixel {
    /// Lit on both sides.
    Lit,
    /// In a cast shadow on both sides.
    Shadowed,
    /// Shadowed by the GPU, lit in the reference: acne, a shadow too large or misplaced.
    FalseShadow,
    /// Lit by the GPU, shadowed in the reference: peter-panning, light leaking, a shadow too small.
    MissedShadow,
}

impl ShadowPixel {
    /// The map's colours: agreement dark (lit black, shadowed dark grey, so the shadows' shape
    /// shows), disagreement bright (false shadow red, missed shadow cyan).
    pub fn rgb8(self) -> [u8; 3] {
        match self {
            ShadowPixel::Lit => [0, 0, 0],
            ShadowPixel::Shadowed => [64, 64, 64],
            ShadowPixel::FalseShadow => [255, 40, 40],
            ShadowPixel::MissedShadow => [40, 230, 255],
        }
    }
}

/// How far the GPU's cast shadows are from the reference's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowStats {
    /// Share of pixels (0..=1) whose lit/shadowed state differs between the GPU and the reference.
    pub share_disagreeing: f64,
    /// Share of pixels shadowed by the GPU only ([`ShadowPixel::FalseShadow`]).
    pub share_false_shadow: f64,
    /// Share of pixels shadowed by the reference only ([`ShadowPixel::MissedShadow`]).
    pub share_missed_shadow: f64,
    /// Share of pixels in a cast shadow in the reference (what the disagreement is out of).
    pub share_shadowed_reference: f64,
}

/// A shadow comparison: the statistics and the error map, one [`ShadowPixel`] per pixel, rows
/// top to bottom.
pub struct ShadowComparison {
    pub stats: ShadowStats,
    pub map: Vec<ShadowPixel>,
}

impl ShadowComparison {
    /// The error map as RGB8 in [`ShadowPixel::rgb8`]'s colours, like [`Comparison::flip_map_rgb8`].
    pub fn map_rgb8(&self) -> Vec<u8> {
        self.map.iter().flat_map(|p| p.rgb8()).collect()
    }
}

/// Compare two lit/shadowed states of the same size pixel by pixel (`true`: in a cast shadow).
pub fn compare_shadow_states(gpu: &[bool], reference: &[bool]) -> ShadowComparison {
    assert_eq!(gpu.len(), reference.len(), "shadow states of different sizes");
    let map: Vec<ShadowPixel> = gpu
        .iter()
        .zip(reference)
        .map(|(&g, &r)| match (g, r) {
            (false, false) => ShadowPixel::Lit,
            (true, true) => ShadowPixel::Shadowed,
            (true, false) => ShadowPixel::FalseShadow,
            (false, true) => ShadowPixel::MissedShadow,
        })
        .collect();
    let n = map.len().max(1) as f64;
    let share = |want: &[ShadowPixel]| map.iter().filter(|p| want.contains(p)).count() as f64 / n;
    let stats = ShadowStats {
        share_disagreeing: share(&[ShadowPixel::FalseShadow, ShadowPixel::MissedShadow]),
        share_false_shadow: share(&[ShadowPixel::FalseShadow]),
        share_missed_shadow: share(&[ShadowPixel::MissedShadow]),
        share_shadowed_reference: share(&[ShadowPixel::Shadowed, ShadowPixel::MissedShadow]),
    };
    ShadowComparison { stats, map }
}

/// The GPU's cast shadows against the reference's: the GPU render with shadows and the same
/// render with them off, against a reference rendered with shadows (its own unshadowed image
/// comes with it). Both states by [`SHADOW_DARKENING_STEPS`].
pub fn shadow_disagreement(
    gpu_shadowed: &LinearImage,
    gpu_unshadowed: &LinearImage,
    reference: &ReferenceImage,
) -> ShadowComparison {
    assert_eq!(
        (gpu_shadowed.width, gpu_shadowed.height),
        (reference.width, reference.height),
        "image and reference sizes differ"
    );
    compare_shadow_states(&gpu_shadow_state(gpu_shadowed, gpu_unshadowed), &reference_shadow_state(reference))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reference(w: u32, h: u32, v: f64) -> ReferenceImage {
        ReferenceImage::uniform(w, h, [v; 3])
    }

    /// A 16 × 8 reference lit at 0.5 whose left `shadow_cols` columns are in a cast shadow (0.1).
    fn shadowed_reference(shadow_cols: u32) -> ReferenceImage {
        let mut r = reference(16, 8, 0.5);
        for (i, p) in r.pixels.iter_mut().enumerate() {
            if (i as u32 % 16) < shadow_cols {
                *p = [0.1; 3];
                r.hidden[i] = 1;
            }
        }
        r
    }

    #[test]
    fn matching_shadows_agree() {
        let r = shadowed_reference(4);
        let c = shadow_disagreement(&reference_image(&r), &reference_image(&reference(16, 8, 0.5)), &r);
        assert_eq!(c.stats.share_disagreeing, 0.0);
        assert_eq!(c.stats.share_shadowed_reference, 0.25);
        assert_eq!(c.map[0], ShadowPixel::Shadowed);
        assert_eq!(c.map[15], ShadowPixel::Lit);
        assert_eq!(c.map_rgb8().len(), 16 * 8 * 3);
    }

    #[test]
    fn a_shadow_too_wide_and_one_too_narrow() {
        let r = shadowed_reference(4);
        let off = reference_image(&reference(16, 8, 0.5));
        let wide = shadow_disagreement(&reference_image(&shadowed_reference(6)), &off, &r);
        assert_eq!(wide.stats.share_false_shadow, 2.0 / 16.0);
        assert_eq!(wide.stats.share_missed_shadow, 0.0);
        assert_eq!(wide.map[5], ShadowPixel::FalseShadow);
        let narrow = shadow_disagreement(&reference_image(&shadowed_reference(1)), &off, &r);
        assert_eq!(narrow.stats.share_missed_shadow, 3.0 / 16.0);
        assert_eq!(narrow.stats.share_disagreeing, 3.0 / 16.0);
        assert_eq!(narrow.map[2], ShadowPixel::MissedShadow);
        assert_eq!(ShadowPixel::MissedShadow.rgb8(), narrow.map_rgb8()[6..9]);
    }

    /// On a real reference the visible shadows are among the exactly hidden points, and the
    /// default scene's contact shadows show.
    #[test]
    fn the_reference_state_lies_within_its_exact_visibility() {
        use shadelab_model::{SpecularModel, scene::Scene};
        let r = shadelab_model::reference::render_reference(
            &Scene::builtin("default").unwrap(),
            SpecularModel::CookTorrance,
            160,
            90,
        );
        let state = reference_shadow_state(&r);
        assert!(state.iter().zip(&r.hidden).all(|(&s, &h)| !s || h != 0));
        let shown = state.iter().filter(|&&s| s).count();
        let hidden = r.hidden.iter().filter(|&&h| h != 0).count();
        assert!(shown > 500 && shown as f64 > 0.8 * hidden as f64, "{shown} shown of {hidden} hidden");
    }

    /// A darkening of one display step or less is no shadow (f32 noise between permutations, a
    /// light too faint to see); two steps is.
    #[test]
    fn darkening_below_the_threshold_is_lit() {
        let step = |k: f64| {
            let s = linear_to_srgb(0.5) as f64 - k / 255.0;
            if s <= 0.04045 { s / 12.92 } else { ((s + 0.055) / 1.055).powf(2.4) }
        };
        let (off, on1, on2) = ([0.5; 3], [step(1.0); 3], [step(2.0); 3]);
        assert_eq!(shadowed_pixels([(on1, off), (on2, off), (off, off)].into_iter()), [false, true, false]);
        // Brighter with shadows (impossible, but not a shadow either), and non-finite values.
        assert_eq!(shadowed_pixels([([0.9; 3], off), ([f64::NAN; 3], off)].into_iter()), [false, true]);
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
