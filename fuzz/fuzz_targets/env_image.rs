//! Any bytes as an environment map file, through the reader of `--environment FILE` and a scene's
//! map (format sniffing, the declared size against MAX_ENV_SIDE and MAX_ENV_BYTES, decoding
//! Radiance HDR or OpenEXR, the non-finite texels): an `Err` or a warning is fine, a panic, an
//! abort or an allocation the bytes cannot back is a bug.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let _ = shadelab_model::lighting::env_file::read_env_image(data, "fuzz input");
});
