//! The browser tests of `cargo xtask test`: build the site, serve it on loopback and drive
//! headless Chromium through Playwright (`tests/web/browser_tests.mjs`), holding the page to the
//! native renderer. Chromium, Node.js and playwright-core are installed when missing (Debian/Ubuntu
//! as root; otherwise the commands are printed).

use crate::suite::Timings;
use crate::web::{build_site, root, serve};
use crate::{Count, apt_install, run, run_counting};
use std::path::Path;
use std::process::Command;

/// The Playwright driver, pinned: it only drives the system's Chromium (no browser download).
const PLAYWRIGHT_CORE: &str = "playwright-core@1.65.1";
pub(crate) const CHROMIUM: &str = "/usr/bin/chromium";

pub(crate) fn on_path(tool: &str) -> bool {
    Command::new("sh").arg("-c").arg(format!("command -v {tool}")).output().is_ok_and(|o| o.status.success())
}

/// Chromium, Node.js and playwright-core (in `target/web-node`), installed where missing.
pub(crate) fn ensure_browser_tools(node_dir: &Path) -> Result<(), String> {
    if !Path::new(CHROMIUM).exists() {
        apt_install("Chromium", &["chromium"])?;
    }
    if !on_path("node") || !on_path("npm") {
        apt_install("Node.js", &["nodejs", "npm"])?;
    }
    if node_dir.join("node_modules/playwright-core/package.json").exists() {
        return Ok(());
    }
    std::fs::create_dir_all(node_dir).map_err(|e| format!("creating {}: {e}", node_dir.display()))?;
    let ok = run(Command::new("npm")
        .args(["install", "--no-audit", "--no-fund", "--no-save", "--prefix"])
        .arg(node_dir)
        .arg(PLAYWRIGHT_CORE));
    if ok { Ok(()) } else { Err(format!("npm install {PLAYWRIGHT_CORE} failed")) }
}

/// `node tests/web/SCRIPT` on the site served at `address`, with what every script reads: the
/// native binary, the driver, the browser, where its images go (`out`, under the repository).
fn node_script(script: &str, address: &str, out: &str, icd: &Path) -> Command {
    let root = root();
    let mut cmd = Command::new("node");
    cmd.arg(root.join("tests/web").join(script))
        .current_dir(&root)
        .env("SHADELAB_URL", address)
        .env("SHADELAB_BIN", root.join("target/release/shadelab"))
        .env("SHADELAB_OUT", root.join(out))
        .env("PLAYWRIGHT", root.join("target/web-node"))
        .env("CHROMIUM", CHROMIUM)
        // The native renders the page is held to run on lavapipe, like every other test.
        .env("VK_DRIVER_FILES", icd)
        .env("VK_ICD_FILENAMES", icd)
        .env("SHADELAB_ADAPTER", "lavapipe");
    cmd
}

/// Serve and test the web build in `site` (built by then, or the error that stopped it); each
/// browser test counts as one test.
pub fn browser_tests(icd: &Path, site: &Path, built: Result<(), String>, count: &mut Count, timings: &mut Timings) {
    let root = root();
    let prepared = built.and_then(|()| serve(site, 0));
    let address = match prepared {
        Ok(a) => a,
        Err(e) => return count.check("web build and browser tools", Err(e)),
    };
    eprintln!("xtask: the web build is served on {address}");
    let mut cmd = node_script("browser_tests.mjs", &address, "target/web-test", icd);
    cmd.env("SHADELAB_ROOT", &root).env("SHADELAB_SITE", site);
    let (ok, c) = timings.step("browser tests", |t| run_counting(&mut cmd, t, ""));
    count.passed += c.passed;
    count.failed += c.failed;
    if !ok && c.failed == 0 {
        count.check("browser tests", Err("tests/web/browser_tests.mjs failed before its tests ran".into()));
    }
}

/// The median frame interval and scene pass the native viewer prints after a scripted run.
fn native_viewer_timing(summary: &str) -> Option<(f64, f64)> {
    let number_after = |key: &str| -> Option<f64> {
        let rest = &summary[summary.find(key)? + key.len()..];
        rest.split_whitespace().next()?.parse().ok()
    };
    Some((number_after("median frame interval ")?, number_after("median scene pass ")?))
}

/// `cargo xtask web --bench`: the web build's size, start and frame time, and its f64 reference,
/// against the native viewer (under Xvfb, lavapipe) on the same machine, in one run.
pub fn bench() -> Result<(), String> {
    let root = root();
    let icd = crate::ensure_lavapipe()?;
    let xdg = crate::runtime_dir();
    let node_dir = root.join("target/web-node");
    ensure_browser_tools(&node_dir)?;
    let site = root.join("target/web-site");
    build_site(&site)?;
    let native_build = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .current_dir(&root)
        .args(["build", "--release"])
        .status();
    if !native_build.is_ok_and(|s| s.success()) {
        return Err("cargo build --release failed".into());
    }
    // The viewer's default window is 1280×760, as the page's viewport in the bench.
    let out = crate::viewer_in_xvfb(&icd, &xdg, &["--exit-after-frames", "65"])?;
    let text = String::from_utf8_lossy(&out.stdout);
    let (frame, pass) = native_viewer_timing(&text).ok_or_else(|| format!("no timing summary in: {text}"))?;
    let address = serve(&site, 0)?;
    let ok = run(node_script("browser_bench.mjs", &address, "target/web-bench", &icd)
        .env("SHADELAB_SITE", &site)
        .env("NATIVE_VIEWER", format!("{{\"frame\":{frame},\"pass\":{pass}}}")));
    if ok { Ok(()) } else { Err("tests/web/browser_bench.mjs failed".into()) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_native_summary_is_read() {
        let line = "viewer: 60 frames after 5: median frame interval 39.12 ms, median scene pass 13.50 ms, frame / scene pass 2.90";
        assert_eq!(native_viewer_timing(line), Some((39.12, 13.5)));
        assert_eq!(native_viewer_timing("nothing"), None);
    }
}
