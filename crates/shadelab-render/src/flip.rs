//! The LDR FLIP image-difference metric (Andersson et al., "FLIP: A Difference Evaluator for
//! Alternating Images", HPG 2020) in plain Rust, so that it also runs on wasm32 where the C++
//! `nv-flip` crate cannot be built. It follows NVIDIA's reference implementation step by step,
//! with the same f32 operations in the same order, so its error maps match `nv-flip`'s to within
//! a few float roundings.
//!
//! Both images go from sRGB to YCxCz, are low-pass filtered by the contrast sensitivity of the
//! eye (CSF), and give a colour difference per pixel (Hunt-adjusted HyAB in L*a*b*). Edges and
//! points detected on the luminance of each give a feature difference, which raises the colour
//! difference towards 1: `error = colour ^ (1 - feature)`.

/// Pixels per degree of visual angle, nv-flip's default: a 0.7 m wide 3840-pixel monitor seen
/// from 0.7 m.
pub const DEFAULT_PIXELS_PER_DEGREE: f32 = 67.0;

/// Exponent applied to the HyAB colour difference (the paper's q_c).
const COLOR_EXPONENT: f32 = 0.7;
/// Share of the largest colour difference where the error mapping bends (p_c).
const COLOR_KNEE_SHARE: f32 = 0.4;
/// Error given to a colour difference at the knee (p_t): below it the error rises steeply.
const COLOR_KNEE_ERROR: f32 = 0.95;
/// Width of the edge and point detectors, in degrees of visual angle (w).
const FEATURE_WIDTH_DEGREES: f32 = 0.082;
/// Exponent applied to the feature difference (q_f).
const FEATURE_EXPONENT: f32 = 0.5;

/// Amplitude `a` and scale `b` (degrees²) of the CSF Gaussians: one each for Y and Cx, a sum of
/// two for Cz.
const CSF_Y: (f32, f32) = (1.0, 0.0047);
const CSF_CX: (f32, f32) = (1.0, 0.0053);
const CSF_CZ_1: (f32, f32) = (34.1, 0.04);
const CSF_CZ_2: (f32, f32) = (13.5, 0.025);
/// The largest CSF scale, which sets the filter radius (the reference takes the maximum over all
/// its Gaussians, including unused ones of scale 1e-5).
const CSF_MAX_SCALE: f32 = 0.04;
/// The filter reaches this many standard deviations of its widest Gaussian.
const FILTER_RADIUS_SIGMAS: f32 = 3.0;

/// The reference's value of π² in f32 (π squared in f32 arithmetic).
const PI_SQ: f32 = std::f32::consts::PI * std::f32::consts::PI;

/// D65 white point (XYZ) and its inverse, with the reference's digits.
#[allow(clippy::excessive_precision)]
const WHITE: [f32; 3] = [0.950428545, 1.0, 1.088900371];
#[allow(clippy::excessive_precision)]
const INV_WHITE: [f32; 3] = [1.052156925, 1.0, 0.918357670];

/// Linear sRGB (D65) to XYZ, as exact ratios (rounded to f32 as in the reference).
#[allow(clippy::excessive_precision)]
const RGB_TO_XYZ: [[f32; 3]; 3] = [
    [10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0],
    [2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0],
    [1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0],
];
/// XYZ to linear sRGB (D65).
#[allow(clippy::excessive_precision)]
const XYZ_TO_RGB: [[f32; 3]; 3] = [
    [3.241003275, -1.537398934, -0.498615861],
    [-0.969224334, 1.875930071, 0.041554224],
    [0.055639423, -0.204011202, 1.057148933],
];

/// sRGB transfer function: below this encoded value the curve is linear with this slope.
const SRGB_LINEAR_KNEE: f32 = 0.04045;
const SRGB_LINEAR_SLOPE: f32 = 12.92;
/// Offset, scale and exponent of the sRGB power segment.
const SRGB_OFFSET: f32 = 0.055;
const SRGB_SCALE: f32 = 1.055;
const SRGB_GAMMA: f32 = 2.4;

/// CIE L*a*b*: the cube-root segment starts at (6/29)³; below it f(t) = t / (3 δ²) + 4/29.
const LAB_DELTA: f32 = 6.0 / 29.0;
const LAB_DELTA_CUBE: f32 = LAB_DELTA * (LAB_DELTA * LAB_DELTA);
const LAB_LINEAR_SLOPE: f32 = 1.0 / (3.0 * (LAB_DELTA * LAB_DELTA));
const LAB_LINEAR_OFFSET: f32 = 4.0 / 29.0;
/// Scales of L* (and Y of YCxCz), a* (Cx) and b* (Cz), and the offset of L*.
const L_SCALE: f32 = 116.0;
const L_OFFSET: f32 = 16.0;
const A_SCALE: f32 = 500.0;
const B_SCALE: f32 = 200.0;
/// Hunt effect: chroma scaled by 0.01 L*, so dark colours count as less colourful.
const HUNT_FACTOR: f32 = 0.01;

/// The magma colour map, 256 RGB8 entries (flattened), as nv-flip rounds its float table.
#[rustfmt::skip]
const MAGMA: [u8; 768] = [
    0, 0, 4, 1, 0, 5, 1, 1, 6, 1, 1, 8, 2, 1, 9, 2, 2, 11,
    2, 2, 13, 3, 3, 15, 3, 3, 18, 4, 4, 20, 5, 4, 22, 6, 5, 24,
    6, 5, 26, 7, 6, 28, 8, 7, 30, 9, 7, 32, 10, 8, 34, 11, 9, 36,
    12, 9, 38, 13, 10, 41, 14, 11, 43, 16, 11, 45, 17, 12, 47, 18, 13, 49,
    19, 13, 52, 20, 14, 54, 21, 14, 56, 22, 15, 59, 24, 15, 61, 25, 16, 63,
    26, 16, 66, 28, 16, 68, 29, 17, 71, 30, 17, 73, 32, 17, 75, 33, 17, 78,
    34, 17, 80, 36, 18, 83, 37, 18, 85, 39, 18, 88, 41, 17, 90, 42, 17, 92,
    44, 17, 95, 45, 17, 97, 47, 17, 99, 49, 17, 101, 51, 16, 103, 52, 16, 105,
    54, 16, 107, 56, 16, 108, 57, 15, 110, 59, 15, 112, 61, 15, 113, 63, 15, 114,
    64, 15, 116, 66, 15, 117, 68, 15, 118, 69, 16, 119, 71, 16, 120, 73, 16, 120,
    74, 16, 121, 76, 17, 122, 78, 17, 123, 79, 18, 123, 81, 18, 124, 82, 19, 124,
    84, 19, 125, 86, 20, 125, 87, 21, 126, 89, 21, 126, 90, 22, 126, 92, 22, 127,
    93, 23, 127, 95, 24, 127, 96, 24, 128, 98, 25, 128, 100, 26, 128, 101, 26, 128,
    103, 27, 128, 104, 28, 129, 106, 28, 129, 107, 29, 129, 109, 29, 129, 110, 30, 129,
    112, 31, 129, 114, 31, 129, 115, 32, 129, 117, 33, 129, 118, 33, 129, 120, 34, 129,
    121, 34, 130, 123, 35, 130, 124, 35, 130, 126, 36, 130, 128, 37, 130, 129, 37, 129,
    131, 38, 129, 132, 38, 129, 134, 39, 129, 136, 39, 129, 137, 40, 129, 139, 41, 129,
    140, 41, 129, 142, 42, 129, 144, 42, 129, 145, 43, 129, 147, 43, 128, 148, 44, 128,
    150, 44, 128, 152, 45, 128, 153, 45, 128, 155, 46, 127, 156, 46, 127, 158, 47, 127,
    160, 47, 127, 161, 48, 126, 163, 48, 126, 165, 49, 126, 166, 49, 125, 168, 50, 125,
    170, 51, 125, 171, 51, 124, 173, 52, 124, 174, 52, 123, 176, 53, 123, 178, 53, 123,
    179, 54, 122, 181, 54, 122, 183, 55, 121, 184, 55, 121, 186, 56, 120, 188, 57, 120,
    189, 57, 119, 191, 58, 119, 192, 58, 118, 194, 59, 117, 196, 60, 117, 197, 60, 116,
    199, 61, 115, 200, 62, 115, 202, 62, 114, 204, 63, 113, 205, 64, 113, 207, 64, 112,
    208, 65, 111, 210, 66, 111, 211, 67, 110, 213, 68, 109, 214, 69, 108, 216, 69, 108,
    217, 70, 107, 219, 71, 106, 220, 72, 105, 222, 73, 104, 223, 74, 104, 224, 76, 103,
    226, 77, 102, 227, 78, 101, 228, 79, 100, 229, 80, 100, 231, 82, 99, 232, 83, 98,
    233, 84, 98, 234, 86, 97, 235, 87, 96, 236, 88, 96, 237, 90, 95, 238, 91, 94,
    239, 93, 94, 240, 95, 94, 241, 96, 93, 242, 98, 93, 242, 100, 92, 243, 101, 92,
    244, 103, 92, 244, 105, 92, 245, 107, 92, 246, 108, 92, 246, 110, 92, 247, 112, 92,
    247, 114, 92, 248, 116, 92, 248, 118, 92, 249, 120, 93, 249, 121, 93, 249, 123, 93,
    250, 125, 94, 250, 127, 94, 250, 129, 95, 251, 131, 95, 251, 133, 96, 251, 135, 97,
    252, 137, 97, 252, 138, 98, 252, 140, 99, 252, 142, 100, 252, 144, 101, 253, 146, 102,
    253, 148, 103, 253, 150, 104, 253, 152, 105, 253, 154, 106, 253, 155, 107, 254, 157, 108,
    254, 159, 109, 254, 161, 110, 254, 163, 111, 254, 165, 113, 254, 167, 114, 254, 169, 115,
    254, 170, 116, 254, 172, 118, 254, 174, 119, 254, 176, 120, 254, 178, 122, 254, 180, 123,
    254, 182, 124, 254, 183, 126, 254, 185, 127, 254, 187, 129, 254, 189, 130, 254, 191, 132,
    254, 193, 133, 254, 194, 135, 254, 196, 136, 254, 198, 138, 254, 200, 140, 254, 202, 141,
    254, 204, 143, 254, 205, 144, 254, 207, 146, 254, 209, 148, 254, 211, 149, 254, 213, 151,
    254, 215, 153, 254, 216, 154, 253, 218, 156, 253, 220, 158, 253, 222, 160, 253, 224, 161,
    253, 226, 163, 253, 227, 165, 253, 229, 167, 253, 231, 169, 253, 233, 170, 253, 235, 172,
    252, 236, 174, 252, 238, 176, 252, 240, 178, 252, 242, 180, 252, 244, 182, 252, 246, 184,
    252, 247, 185, 252, 249, 187, 252, 251, 189, 252, 253, 191,
];

type Color = [f32; 3];

/// Per-pixel LDR FLIP error of `test` against `reference`, both sRGB8 RGB, row-major,
/// `width * height * 3` bytes. Each error is in [0, 1] (0: no visible difference).
///
/// # Panics
/// If either slice is not `width * height * 3` bytes long.
pub fn flip_map(reference: &[u8], test: &[u8], width: usize, height: usize, pixels_per_degree: f32) -> Vec<f32> {
    let len = width * height * 3;
    assert_eq!(reference.len(), len, "reference is not width * height * 3 bytes");
    assert_eq!(test.len(), len, "test is not width * height * 3 bytes");
    let (w, h, ppd) = (width, height, pixels_per_degree);
    let reference: Vec<Color> = reference.chunks_exact(3).map(srgb8_to_ycxcz).collect();
    let test: Vec<Color> = test.chunks_exact(3).map(srgb8_to_ycxcz).collect();

    let csf = csf_kernel(ppd);
    let cmax = max_color_difference();
    let ref_lab = csf_filtered_lab(&reference, w, h, &csf);
    let test_lab = csf_filtered_lab(&test, w, h, &csf);

    let features = feature_kernel(ppd);
    let ref_features = feature_responses(&reference, w, h, &features);
    let test_features = feature_responses(&test, w, h, &features);

    let mut errors = Vec::with_capacity(w * h);
    for i in 0..w * h {
        let color = map_color_difference(hyab(ref_lab[i], test_lab[i]), cmax);
        let feature = feature_difference(ref_features[i], test_features[i]);
        errors.push(color.powf(1.0 - feature));
    }
    errors
}

/// The magma colour map as 256 RGB8 entries (nv-flip's `magma_lut`), from error 0 to 1.
pub fn magma_lut() -> [[u8; 3]; 256] {
    std::array::from_fn(|i| [MAGMA[3 * i], MAGMA[3 * i + 1], MAGMA[3 * i + 2]])
}

/// Map errors through magma to RGB8 as nv-flip's `apply_color_lut` does: index
/// `(e * 255 + 0.5)` truncated, modulo 256 (so values above 1 wrap, as there; negative and NaN
/// values, out of bounds in the reference, give entry 0).
pub fn apply_magma(errors: &[f32]) -> Vec<u8> {
    let mut out = Vec::with_capacity(errors.len() * 3);
    for &e in errors {
        let i = ((e * 255.0 + 0.5) as usize) % 256;
        out.extend_from_slice(&MAGMA[3 * i..3 * i + 3]);
    }
    out
}

/// An sRGB8 pixel in YCxCz (the linear counterpart of L*a*b*).
fn srgb8_to_ycxcz(p: &[u8]) -> Color {
    let linear = [0, 1, 2].map(|c| srgb_to_linear(p[c] as f32 / 255.0));
    xyz_to_ycxcz(mat3_mul(&RGB_TO_XYZ, linear))
}

fn srgb_to_linear(c: f32) -> f32 {
    if c <= SRGB_LINEAR_KNEE { c / SRGB_LINEAR_SLOPE } else { ((c + SRGB_OFFSET) / SRGB_SCALE).powf(SRGB_GAMMA) }
}

fn mat3_mul(m: &[[f32; 3]; 3], v: Color) -> Color {
    m.map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2])
}

fn xyz_to_ycxcz(xyz: Color) -> Color {
    let [x, y, z] = [xyz[0] * INV_WHITE[0], xyz[1] * INV_WHITE[1], xyz[2] * INV_WHITE[2]];
    [L_SCALE * y - L_OFFSET, A_SCALE * (x - y), B_SCALE * (y - z)]
}

fn ycxcz_to_xyz(c: Color) -> Color {
    let y = (c[0] + L_OFFSET) / L_SCALE;
    let (cx, cz) = (c[1] / A_SCALE, c[2] / B_SCALE);
    [(y + cx) * WHITE[0], y * WHITE[1], (y - cz) * WHITE[2]]
}

fn xyz_to_lab(xyz: Color) -> Color {
    let f = |t: f32| if t > LAB_DELTA_CUBE { t.powf(1.0 / 3.0) } else { LAB_LINEAR_SLOPE * t + LAB_LINEAR_OFFSET };
    let [x, y, z] = [f(xyz[0] * INV_WHITE[0]), f(xyz[1] * INV_WHITE[1]), f(xyz[2] * INV_WHITE[2])];
    [L_SCALE * y - L_OFFSET, A_SCALE * (x - y), B_SCALE * (y - z)]
}

/// Hunt-adjusted L*a*b*: a* and b* scaled by 0.01 L*.
fn hunt(lab: Color) -> Color {
    [lab[0], HUNT_FACTOR * lab[0] * lab[1], HUNT_FACTOR * lab[0] * lab[2]]
}

/// HyAB distance: city-block in lightness plus Euclidean in the chroma plane.
fn hyab(a: Color, b: Color) -> f32 {
    let (da, db) = (a[1] - b[1], a[2] - b[2]);
    (a[0] - b[0]).abs() + (da * da + db * db).sqrt()
}

/// The largest colour difference after the exponent: Hunt-adjusted HyAB from pure green to
/// pure blue.
fn max_color_difference() -> f32 {
    let lab = |rgb: Color| hunt(xyz_to_lab(mat3_mul(&RGB_TO_XYZ, rgb)));
    hyab(lab([0.0, 1.0, 0.0]), lab([0.0, 0.0, 1.0])).powf(COLOR_EXPONENT)
}

/// Raise the colour difference to [`COLOR_EXPONENT`] and map it into [0, 1]: linearly up to
/// [`COLOR_KNEE_ERROR`] at the knee, then linearly to 1 at `cmax`.
fn map_color_difference(hyab: f32, cmax: f32) -> f32 {
    let knee = COLOR_KNEE_SHARE * cmax;
    let d = hyab.powf(COLOR_EXPONENT);
    if d < knee {
        d * (COLOR_KNEE_ERROR / knee)
    } else {
        COLOR_KNEE_ERROR + ((d - knee) / (cmax - knee)) * (1.0 - COLOR_KNEE_ERROR)
    }
}

/// CSF Gaussian in the paper's form a √(π/b) exp(−π² x² / b), `x2` in degrees².
fn csf_gaussian(x2: f32, (a, b): (f32, f32)) -> f32 {
    a * (std::f32::consts::PI / b).sqrt() * (-PI_SQ * x2 / b).exp()
}

/// The square root of the amplitude of [`csf_gaussian`]: the sum of two Gaussians for Cz is
/// separable only as a pair of 1D passes each carrying √a.
fn csf_gaussian_sqrt(x2: f32, (a, b): (f32, f32)) -> f32 {
    (a * (std::f32::consts::PI / b).sqrt()).sqrt() * (-PI_SQ * x2 / b).exp()
}

/// The separable 1D CSF kernel; each tap is [Y, Cx, Cz first Gaussian, Cz second Gaussian].
/// Y and Cx sum to 1; the two Cz parts together have unit norm.
fn csf_kernel(ppd: f32) -> Vec<[f32; 4]> {
    let radius = (FILTER_RADIUS_SIGMAS * (CSF_MAX_SCALE / (2.0 * PI_SQ)).sqrt() * ppd).ceil() as i32;
    let step = 1.0 / ppd;
    let mut taps = Vec::with_capacity(2 * radius as usize + 1);
    let mut sums = [0.0f32; 4];
    for i in -radius..=radius {
        let x = i as f32 * step;
        let x2 = x * x;
        let tap = [
            csf_gaussian(x2, CSF_Y),
            csf_gaussian(x2, CSF_CX),
            csf_gaussian_sqrt(x2, CSF_CZ_1),
            csf_gaussian_sqrt(x2, CSF_CZ_2),
        ];
        sums.iter_mut().zip(tap).for_each(|(s, t)| *s += t);
        taps.push(tap);
    }
    let norm = [1.0 / sums[0], 1.0 / sums[1]];
    let norm_cz = 1.0 / (sums[2] * sums[2] + sums[3] * sums[3]).sqrt();
    for t in &mut taps {
        *t = [t[0] * norm[0], t[1] * norm[1], t[2] * norm_cz, t[3] * norm_cz];
    }
    taps
}

/// One pass of a separable convolution with clamp-to-edge borders: channel `c` of each tap
/// filters channel `c` of `src` (`w` × `h`, row-major), along x or along y.
fn convolve(src: &[[f32; 4]], w: usize, h: usize, kernel: &[[f32; 4]], along_x: bool) -> Vec<[f32; 4]> {
    let radius = (kernel.len() / 2) as isize;
    let mut out = Vec::with_capacity(src.len());
    for y in 0..h {
        for x in 0..w {
            let mut acc = [0.0f32; 4];
            for (k, tap) in kernel.iter().enumerate() {
                let offset = k as isize - radius;
                let i = if along_x {
                    y * w + (x as isize + offset).clamp(0, w as isize - 1) as usize
                } else {
                    (y as isize + offset).clamp(0, h as isize - 1) as usize * w + x
                };
                let v = &src[i];
                acc.iter_mut().zip(tap.iter().zip(v)).for_each(|(a, (t, v))| *a += t * v);
            }
            out.push(acc);
        }
    }
    out
}

/// CSF-filter a YCxCz image, clamp it to the sRGB gamut in linear RGB, and return it as
/// Hunt-adjusted L*a*b*.
fn csf_filtered_lab(image: &[Color], w: usize, h: usize, csf: &[[f32; 4]]) -> Vec<Color> {
    let channels: Vec<[f32; 4]> = image.iter().map(|c| [c[0], c[1], c[2], c[2]]).collect();
    let filtered = convolve(&convolve(&channels, w, h, csf, true), w, h, csf, false);
    let clamp01 = |v: f32| {
        let v = if v > 0.0 { v } else { 0.0 };
        if v > 1.0 { 1.0 } else { v }
    };
    let to_lab = |f: &[f32; 4]| {
        let rgb = mat3_mul(&XYZ_TO_RGB, ycxcz_to_xyz([f[0], f[1], f[2] + f[3]])).map(clamp01);
        hunt(xyz_to_lab(mat3_mul(&RGB_TO_XYZ, rgb)))
    };
    filtered.iter().map(to_lab).collect()
}

/// The 1D feature kernel: taps [Gaussian, 1st derivative, 2nd derivative] of standard deviation
/// half the detector width. The Gaussian sums to 1; the positive and negative weights of each
/// derivative sum to +1 and −1.
fn feature_kernel(ppd: f32) -> Vec<Color> {
    let sigma = 0.5 * FEATURE_WIDTH_DEGREES * ppd;
    let radius = (FILTER_RADIUS_SIGMAS * sigma).ceil() as i32;
    let (mut g_sum, mut pos, mut neg) = (0.0f32, [0.0f32; 2], [0.0f32; 2]);
    let mut taps = Vec::with_capacity(2 * radius as usize + 1);
    for i in -radius..=radius {
        let x = i as f32;
        let g = (-(x * x) / (2.0 * sigma * sigma)).exp();
        let derivatives = [-x * g, (x * x / (sigma * sigma) - 1.0) * g];
        g_sum += g;
        for (d, v) in derivatives.into_iter().enumerate() {
            if v > 0.0 { pos[d] += v } else { neg[d] -= v }
        }
        taps.push([g, derivatives[0], derivatives[1]]);
    }
    let scale = |v: f32, d: usize| v / if v > 0.0 { pos[d] } else { neg[d] };
    taps.iter().map(|t| [t[0] / g_sum, scale(t[1], 0), scale(t[2], 1)]).collect()
}

/// Edge and point responses of an image's luminance (Y normalised to [0, 1]), per pixel:
/// [d/dx, d²/dx², d/dy, d²/dy²] of the Gaussian-smoothed luminance.
fn feature_responses(image: &[Color], w: usize, h: usize, kernel: &[Color]) -> Vec<[f32; 4]> {
    const Y_NORM_SCALE: f32 = 1.0 / L_SCALE;
    const Y_NORM_OFFSET: f32 = L_OFFSET / L_SCALE;
    let luminance: Vec<[f32; 4]> = image.iter().map(|c| [c[0] * Y_NORM_SCALE + Y_NORM_OFFSET; 4]).collect();
    // Along x: derivatives for the x responses, the Gaussian for the y ones; along y the reverse.
    let along_x: Vec<[f32; 4]> = kernel.iter().map(|t| [t[1], t[2], t[0], t[0]]).collect();
    let along_y: Vec<[f32; 4]> = kernel.iter().map(|t| [t[0], t[0], t[1], t[2]]).collect();
    convolve(&convolve(&luminance, w, h, &along_x, true), w, h, &along_y, false)
}

/// The feature difference in [0, 1] from the two images' responses: the larger of the edge and
/// point magnitude differences, normalised and raised to [`FEATURE_EXPONENT`].
fn feature_difference(r: [f32; 4], t: [f32; 4]) -> f32 {
    let magnitudes = |d: [f32; 4]| ((d[0] * d[0] + d[2] * d[2]).sqrt(), (d[1] * d[1] + d[3] * d[3]).sqrt());
    let ((edge_r, point_r), (edge_t, point_t)) = (magnitudes(r), magnitudes(t));
    let (edge, point) = ((edge_r - edge_t).abs(), (point_r - point_t).abs());
    let largest = if edge > point { edge } else { point };
    (1.0 / 2.0f32.sqrt() * largest).powf(FEATURE_EXPONENT)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Image sizes for the tests, down to a single pixel, row and column.
    const SIZES: [(usize, usize); 8] = [(1, 1), (2, 1), (1, 2), (3, 2), (200, 1), (1, 50), (37, 23), (64, 48)];

    /// A 64-bit linear congruential generator (Knuth's MMIX constants): reproducible noise.
    struct Lcg(u64);

    impl Lcg {
        fn next_u8(&mut self) -> u8 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (self.0 >> 33) as u8
        }
    }

    fn noise(w: usize, h: usize, seed: u64) -> Vec<u8> {
        let mut rng = Lcg(seed);
        (0..w * h * 3).map(|_| rng.next_u8()).collect()
    }

    /// `image` with each channel moved by up to ±`amplitude`.
    fn perturbed(image: &[u8], seed: u64, amplitude: u8) -> Vec<u8> {
        let mut rng = Lcg(seed);
        let span = 2 * amplitude as u16 + 1;
        image
            .iter()
            .map(|&v| (v as i16 + (rng.next_u8() as u16 % span) as i16 - amplitude as i16).clamp(0, 255) as u8)
            .collect()
    }

    /// Red ramps along x, green along y, blue along the diagonal shifted by `phase`.
    fn gradient(w: usize, h: usize, phase: f32) -> Vec<u8> {
        let ramp = |i: usize, n: usize| if n > 1 { i as f32 / (n - 1) as f32 } else { 0.0 };
        let mut out = Vec::with_capacity(w * h * 3);
        for y in 0..h {
            for x in 0..w {
                let (fx, fy) = (ramp(x, w), ramp(y, h));
                out.extend([fx, fy, (fx + fy + phase).fract()].map(|v| (v * 255.0) as u8));
            }
        }
        out
    }

    fn checkerboard(w: usize, h: usize, square: usize) -> Vec<u8> {
        (0..w * h).flat_map(|i| [if (i % w / square + i / w / square) % 2 == 1 { 255 } else { 0 }; 3]).collect()
    }

    /// 3×3 box blur with clamped borders.
    fn box_blur(image: &[u8], w: usize, h: usize) -> Vec<u8> {
        let mut out = Vec::with_capacity(image.len());
        for y in 0..h {
            for x in 0..w {
                for c in 0..3 {
                    let mut sum = 0u32;
                    for (dx, dy) in (0..9).map(|k| (k % 3, k / 3)) {
                        let xx = (x + dx).saturating_sub(1).min(w - 1);
                        let yy = (y + dy).saturating_sub(1).min(h - 1);
                        sum += image[(yy * w + xx) * 3 + c] as u32;
                    }
                    out.push((sum / 9) as u8);
                }
            }
        }
        out
    }

    /// Reference/test pairs of one size: gradients, a checkerboard against its blur, unrelated
    /// noise, noise against a slightly perturbed copy, black against white, green against blue.
    fn pairs(w: usize, h: usize) -> Vec<(&'static str, Vec<u8>, Vec<u8>)> {
        let board = checkerboard(w, h, 4);
        let grain = noise(w, h, 3);
        let solid = |rgb: [u8; 3]| rgb.repeat(w * h);
        vec![
            ("gradient", gradient(w, h, 0.0), gradient(w, h, 0.3)),
            ("checkerboard/blur", box_blur(&board, w, h), board),
            ("noise", noise(w, h, 1), noise(w, h, 2)),
            ("noise/perturbed", perturbed(&grain, 4, 6), grain),
            ("black/white", solid([0; 3]), solid([255; 3])),
            ("green/blue", solid([0, 255, 0]), solid([0, 0, 255])),
        ]
    }

    /// The mean as nv-flip's `FlipPool::mean` takes it: an f32 running sum in pixel order over
    /// the count (so its rounding, up to ~1e-5 on a few thousand pixels, is the same).
    fn pool_mean(errors: &[f32]) -> f32 {
        errors.iter().fold(0.0f32, |sum, &e| sum + e) / errors.len() as f32
    }

    #[test]
    fn identical_images_have_zero_error() {
        for (w, h) in SIZES {
            for (_, image, _) in pairs(w, h) {
                assert!(flip_map(&image, &image, w, h, DEFAULT_PIXELS_PER_DEGREE).iter().all(|&e| e == 0.0));
            }
        }
    }

    #[test]
    fn errors_are_finite_and_within_unit_range() {
        for (w, h) in SIZES {
            for (name, reference, test) in pairs(w, h) {
                for ppd in [10.0, DEFAULT_PIXELS_PER_DEGREE, 120.0] {
                    let errors = flip_map(&reference, &test, w, h, ppd);
                    assert_eq!(errors.len(), w * h);
                    let bad = errors.iter().find(|e| !(0.0..=1.0).contains(*e));
                    assert!(bad.is_none(), "{name} {w}x{h} at {ppd} ppd: error {bad:?}");
                }
            }
        }
    }

    #[test]
    fn empty_image_gives_empty_map() {
        assert!(flip_map(&[], &[], 0, 0, DEFAULT_PIXELS_PER_DEGREE).is_empty());
        assert!(flip_map(&[], &[], 0, 5, DEFAULT_PIXELS_PER_DEGREE).is_empty());
    }

    #[test]
    fn magma_runs_from_black_to_pale_yellow() {
        let lut = magma_lut();
        assert_eq!((lut[0], lut[255]), ([0, 0, 4], [252, 253, 191]));
        assert_eq!(apply_magma(&[0.0, 1.0, 0.5]), [lut[0], lut[255], lut[128]].concat());
    }

    /// nv-flip's error map, its pool mean and its magma colouring.
    #[cfg(not(target_arch = "wasm32"))]
    fn nv_flip_reference(reference: &[u8], test: &[u8], w: usize, h: usize, ppd: f32) -> (Vec<f32>, f32, Vec<u8>) {
        let image = |data: &[u8]| nv_flip::FlipImageRgb8::with_data(w as u32, h as u32, data);
        let errors = nv_flip::flip(image(reference), image(test), ppd);
        let mean = nv_flip::FlipPool::from_image(&errors).mean();
        (errors.to_vec(), mean, errors.apply_color_lut(&nv_flip::magma_lut()).to_vec())
    }

    /// The same f32 operations run in the same order as in the C++, so the maps come out
    /// bit-identical except for last-place differences between libm and LLVM's lowering of
    /// `powf` (measured at most 6e-8); 1e-4 leaves room for another platform's libm. The means
    /// are f32 running sums of near-identical values on both sides, hence 1e-5.
    #[cfg(not(target_arch = "wasm32"))]
    #[test]
    fn matches_nv_flip() {
        const PIXEL_TOLERANCE: f32 = 1e-4;
        const MEAN_TOLERANCE: f32 = 1e-5;
        for (w, h) in [(64, 48), (37, 23), (3, 2), (200, 1)] {
            for (name, reference, test) in pairs(w, h) {
                for ppd in [DEFAULT_PIXELS_PER_DEGREE, 30.0, 120.0] {
                    let ours = flip_map(&reference, &test, w, h, ppd);
                    let (theirs, their_mean, their_colors) = nv_flip_reference(&reference, &test, w, h, ppd);
                    let worst = ours.iter().zip(&theirs).map(|(a, b)| (a - b).abs()).fold(0.0f32, f32::max);
                    assert!(worst <= PIXEL_TOLERANCE, "{name} {w}x{h} at {ppd} ppd: pixel off by {worst}");
                    let mean_error = (pool_mean(&ours) - their_mean).abs();
                    assert!(mean_error <= MEAN_TOLERANCE, "{name} {w}x{h} at {ppd} ppd: mean off by {mean_error}");
                    // An error within a rounding of a colour-map step may pick the next entry.
                    let colors_off =
                        apply_magma(&ours).chunks(3).zip(their_colors.chunks(3)).filter(|(a, b)| a != b).count();
                    assert!(colors_off <= ours.len() / 100, "{name} {w}x{h} at {ppd} ppd: {colors_off} colours differ");
                }
            }
        }
    }

    #[cfg(not(target_arch = "wasm32"))]
    #[test]
    fn constants_match_nv_flip() {
        assert_eq!(DEFAULT_PIXELS_PER_DEGREE, nv_flip::DEFAULT_PIXELS_PER_DEGREE);
        assert_eq!(magma_lut().concat(), nv_flip::magma_lut().to_vec());
    }
}
