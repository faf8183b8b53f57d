//! Any bytes into the glTF loader: an `Err` is fine, a panic, an abort or an allocation of a
//! declared size the bytes cannot back (libFuzzer's -rss_limit_mb / -malloc_limit_mb) is a bug.
//!
//! Run: `cargo +nightly fuzz run load_scene ../tests/gltf-corpus` (from `fuzz/`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let _ = shadelab_model::gltf_io::load_scene_from_slice(data);
});
