//! The browser tests of `cargo xtask test`: build the site, serve it on loopback and drive
//! headless Chromium through Playwright (`tests/web/browser_tests.mjs`), holding the page to the
//! native renderer. Chromium, Node.js and playwright-core are installed when missing (Debian/Ubuntu
//! as root; otherwise the commands are printed).

use crate::web::{build_site, root, serve};
use crate::{Count, apt_install, run, run_counting};
use std::path::Path;
use std::process::Command;

/// The Playwright driver, pinned: it only drives the system's Chromium (no browser download).
const PLAYWRIGHT_CORE: &str = "playwright-core@1.65.1";
const CHROMIUM: &str = "/usr/bin/chromium";

fn on_path(tool: &str) -> bool {
    Command::new("sh").arg("-c").arg(format!("command -v {tool}")).output().is_ok_and(|o| o.status.success())
}

/// Chromium, Node.js and playwright-core (in `target/web-node`), installed where missing.
fn ensure_browser_tools(node_dir: &Path) -> Result<(), String> {
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

/// Build, serve and test the web build; each browser test counts as one test.
pub fn browser_tests(icd: &Path, count: &mut Count) {
    let root = root();
    let node_dir = root.join("target/web-node");
    let site = root.join("target/web-site");
    let prepared = ensure_browser_tools(&node_dir).and_then(|()| build_site(&site)).and_then(|()| serve(&site, 0));
    let address = match prepared {
        Ok(a) => a,
        Err(e) => return count.check("web build and browser tools", Err(e)),
    };
    eprintln!("xtask: the web build is served on {address}");
    let mut cmd = Command::new("node");
    cmd.arg(root.join("tests/web/browser_tests.mjs"))
        .current_dir(&root)
        .env("SHADELAB_URL", &address)
        .env("SHADELAB_BIN", root.join("target/release/shadelab"))
        .env("SHADELAB_ROOT", &root)
        .env("SHADELAB_OUT", root.join("target/web-test"))
        .env("PLAYWRIGHT", &node_dir)
        .env("CHROMIUM", CHROMIUM)
        // The native renders the page is held to run on lavapipe, like every other test.
        .env("VK_DRIVER_FILES", icd)
        .env("VK_ICD_FILENAMES", icd)
        .env("SHADELAB_ADAPTER", "lavapipe");
    let (ok, c) = run_counting(&mut cmd);
    count.passed += c.passed;
    count.failed += c.failed;
    if !ok && c.failed == 0 {
        count.check("browser tests", Err("tests/web/browser_tests.mjs failed before its tests ran".into()));
    }
}
