//! The permutations' validation remembered between runs of the test binary: a module whose
//! source, the entry-point names it is checked for, naga (through the Cargo.lock the binary was
//! built with) and checks (the test's own source) are all the same as in a run that validated it
//! needs no second validation. A fresh clone has no record, so it validates every module; a
//! change to the WGSL revalidates the modules it changes.

use std::collections::HashSet;
use std::hash::{Hash, Hasher};
use std::path::PathBuf;

/// The crate versions this test binary was built with (naga's among them).
const CARGO_LOCK: &[u8] = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/../../Cargo.lock"));

/// What every module's check depends on besides the module and its entry points' names: the test
/// code that checks it and the crate versions.
pub(super) fn checks_digest(test_source: &str) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (test_source, CARGO_LOCK).hash(&mut h);
    h.finish()
}

/// One module's check: `digest` (the checks) and `module` (its source's hash, what its key
/// decides, and the names of the entry points it must or must not hold).
pub(super) fn check_hash(digest: u64, module: impl Hash) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (digest, module).hash(&mut h);
    h.finish()
}

/// The record, beside the test binary in the build's folder (`target/<profile>/`).
fn record_path() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    Some(exe.parent()?.parent()?.join("naga-validated-permutations"))
}

/// The checks a run before passed (none where there is no record or it cannot be read).
pub(super) fn load() -> HashSet<u64> {
    let Some(bytes) = record_path().and_then(|p| std::fs::read(p).ok()) else { return HashSet::new() };
    bytes.chunks_exact(8).map(|c| u64::from_le_bytes(c.try_into().expect("8 bytes"))).collect()
}

/// Keep `passed` (this run's checks, every one of which passed) as the record, replacing the old
/// one whole; a record that cannot be written only costs the next run its time.
pub(super) fn store(passed: &HashSet<u64>) {
    let Some(path) = record_path() else { return };
    let bytes: Vec<u8> = passed.iter().flat_map(|h| h.to_le_bytes()).collect();
    let part = path.with_extension(format!("part-{}", std::process::id()));
    if std::fs::write(&part, bytes).is_ok() {
        let _ = std::fs::rename(&part, &path);
    }
}

#[test]
fn a_check_changes_with_everything_it_depends_on() {
    let d = checks_digest("fn checks() {}");
    assert_ne!(d, checks_digest("fn other_checks() {}"), "the test's source");
    let eps = [("vs_a", "fs_a")];
    let base = check_hash(d, (1u64, (false, false), eps));
    assert_eq!(base, check_hash(d, (1u64, (false, false), eps)));
    assert_ne!(base, check_hash(d ^ 1, (1u64, (false, false), eps)), "the checks");
    assert_ne!(base, check_hash(d, (2u64, (false, false), eps)), "the source");
    assert_ne!(base, check_hash(d, (1u64, (false, true), eps)), "what the key decides");
    assert_ne!(base, check_hash(d, (1u64, (false, false), [("vs_a", "fs_b")])), "the entry points");
}
