//! Reading an environment map the user brings: an equirectangular Radiance HDR or OpenEXR file,
//! decoded by the `image` crate within bounds, so that a broken, huge or hostile file is one
//! clear line and never more memory than [`MAX_ENV_BYTES`].

use super::env_map::EnvImage;
use std::io::Read;
use std::path::Path;

/// The widest map read: 8192 texels (a 2:1 map of 8192 × 4096 is 0.04° a texel, finer than any
/// view here shows).
pub const MAX_ENV_SIDE: u32 = 8192;
/// The largest file read, 256 MiB: an uncompressed 8192 × 4096 RGB float EXR is 384 MiB, and the
/// common 4096 × 2048 HDR panoramas are 20–50 MiB.
pub const MAX_ENV_FILE_BYTES: u64 = 256 << 20;
/// The decoder's allocation bound, 512 MiB: a 4096 × 2048 map as RGBA f32 is 128 MiB, with room
/// for the decoder's own buffers; a file declaring more is refused before it is decoded.
pub const MAX_ENV_BYTES: u64 = 512 << 20;
/// Texels kept: 4096 × 2048. A larger map is averaged down by whole factors to fit, with a
/// warning, so the path tracer's sampling tables stay under 100 MiB.
pub const MAX_ENV_TEXELS: u64 = 4096 * 2048;

/// An environment map read from `path`, and the warnings it gave; one line on failure.
pub fn load_env_image(path: &Path) -> Result<(EnvImage, Vec<String>), String> {
    let name = path.display().to_string();
    let f = std::fs::File::open(path).map_err(|e| format!("environment map {name}: {e}"))?;
    let len = f.metadata().map_err(|e| format!("environment map {name}: {e}"))?.len();
    if len > MAX_ENV_FILE_BYTES {
        return Err(format!(
            "environment map {name}: {len} bytes, more than the limit of {MAX_ENV_FILE_BYTES} (MAX_ENV_FILE_BYTES)"
        ));
    }
    let mut bytes = Vec::with_capacity(len as usize);
    f.take(MAX_ENV_FILE_BYTES).read_to_end(&mut bytes).map_err(|e| format!("environment map {name}: {e}"))?;
    read_env_image(&bytes, &name)
}

/// An environment map decoded from `bytes` (HDR or EXR), named `name` in messages.
pub fn read_env_image(bytes: &[u8], name: &str) -> Result<(EnvImage, Vec<String>), String> {
    let fail = |what: String| format!("environment map {name}: {what}");
    let format = match image::guess_format(bytes) {
        Ok(f @ (image::ImageFormat::Hdr | image::ImageFormat::OpenExr)) => f,
        Ok(f) => {
            return Err(fail(format!(
                "{f:?} is not a radiance map: give a Radiance HDR (.hdr) or OpenEXR (.exr) file"
            )));
        }
        Err(_) => return Err(fail("not a Radiance HDR (.hdr) or OpenEXR (.exr) file".into())),
    };
    let reader = || image::ImageReader::with_format(std::io::Cursor::new(bytes), format);
    let (w, h) = reader().into_dimensions().map_err(|e| fail(e.to_string()))?;
    if w == 0 || h == 0 || w > MAX_ENV_SIDE || h > MAX_ENV_SIDE {
        return Err(fail(format!("{w}×{h} texels, outside 1..={MAX_ENV_SIDE} per side (MAX_ENV_SIDE)")));
    }
    let mut warnings = Vec::new();
    if w != 2 * h {
        warnings.push(fail(format!("{w}×{h} is not 2:1; read as equirectangular all the same")));
    }
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_ENV_SIDE);
    limits.max_image_height = Some(MAX_ENV_SIDE);
    limits.max_alloc = Some(MAX_ENV_BYTES);
    let mut r = reader();
    r.limits(limits);
    let rgb = r.decode().map_err(|e| fail(e.to_string()))?.into_rgb32f();
    let mut texels: Vec<[f32; 3]> = rgb.pixels().map(|p| p.0).collect();
    drop(rgb);
    let bad = texels.iter().filter(|t| t.iter().any(|v| !v.is_finite() || *v < 0.0)).count();
    if bad > 0 {
        warnings.push(fail(format!("{bad} texels negative, infinite or NaN: read as 0")));
        for t in &mut texels {
            *t = t.map(|v| if v.is_finite() && v > 0.0 { v } else { 0.0 });
        }
    }
    let (mut w, mut h) = (w, h);
    let mut factor = 1;
    while u64::from(w / factor) * u64::from(h / factor) > MAX_ENV_TEXELS {
        factor *= 2;
    }
    if factor > 1 {
        warnings.push(fail(format!("{w}×{h} texels averaged down {factor}× to fit MAX_ENV_TEXELS ({MAX_ENV_TEXELS})")));
        texels = shrink(&texels, w, h, factor);
        (w, h) = (w / factor, h / factor);
    }
    Ok((EnvImage { name: name.to_string(), width: w, height: h, texels }, warnings))
}

/// The map averaged over `factor × factor` blocks (edge texels past a whole block dropped).
fn shrink(texels: &[[f32; 3]], w: u32, h: u32, factor: u32) -> Vec<[f32; 3]> {
    let (nw, nh) = (w / factor, h / factor);
    let k = (factor * factor) as f32;
    let mut out = Vec::with_capacity((nw * nh) as usize);
    for y in 0..nh {
        for x in 0..nw {
            let mut sum = [0.0f32; 3];
            for dy in 0..factor {
                for dx in 0..factor {
                    let t = texels[((y * factor + dy) * w + x * factor + dx) as usize];
                    for c in 0..3 {
                        sum[c] += t[c];
                    }
                }
            }
            out.push(sum.map(|s| s / k));
        }
    }
    out
}

/// `texels` written as an EXR file's bytes (the viewer's and the tests' way to make a map).
pub fn write_env_exr(img: &EnvImage) -> Result<Vec<u8>, String> {
    let flat: Vec<f32> = img.texels.iter().flatten().copied().collect();
    let buf = image::Rgb32FImage::from_raw(img.width, img.height, flat).ok_or("texel count")?;
    let mut out = std::io::Cursor::new(Vec::new());
    image::DynamicImage::ImageRgb32F(buf)
        .write_to(&mut out, image::ImageFormat::OpenExr)
        .map_err(|e| format!("environment map {}: {e}", img.name))?;
    Ok(out.into_inner())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(w: u32, h: u32) -> EnvImage {
        let texels = (0..w * h).map(|i| [i as f32, 1.0, 0.5]).collect();
        EnvImage { name: "m".into(), width: w, height: h, texels }
    }

    #[test]
    fn exr_round_trips() {
        let m = map(8, 4);
        let (back, warnings) = read_env_image(&write_env_exr(&m).unwrap(), "m").unwrap();
        assert!(warnings.is_empty(), "{warnings:?}");
        assert_eq!(back, m);
    }

    /// Broken and hostile files are one line each, never a panic: not an image, a PNG, a truncated
    /// EXR, a header declaring a huge map, an empty file.
    #[test]
    fn bad_files_are_one_line() {
        let exr = write_env_exr(&map(8, 4)).unwrap();
        let huge_hdr = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n".to_vec();
        let png = {
            let mut out = std::io::Cursor::new(Vec::new());
            image::RgbImage::new(2, 1).write_to(&mut out, image::ImageFormat::Png).unwrap();
            out.into_inner()
        };
        for (what, bytes) in [
            ("text", b"hello".to_vec()),
            ("empty", Vec::new()),
            ("png", png),
            ("truncated exr", exr[..exr.len() / 2].to_vec()),
            ("huge hdr", huge_hdr),
        ] {
            let e = read_env_image(&bytes, what).unwrap_err();
            assert!(e.starts_with(&format!("environment map {what}: ")) && !e.contains('\n'), "{what}: {e}");
        }
    }

    #[test]
    fn non_finite_texels_are_zero_with_a_warning() {
        let mut m = map(4, 2);
        m.texels[3] = [f32::NAN, -1.0, f32::INFINITY];
        let (back, warnings) = read_env_image(&write_env_exr(&m).unwrap(), "m").unwrap();
        assert_eq!(back.texels[3], [0.0; 3]);
        assert!(warnings.iter().any(|w| w.contains("1 texels")), "{warnings:?}");
    }
}
