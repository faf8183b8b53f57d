//! `cargo xtask test`: make sure lavapipe (Mesa's CPU Vulkan driver) is installed, force it as
//! the only Vulkan driver, and run every test of the workspace on it.
//!
//! On Debian/Ubuntu as root, a missing lavapipe is installed (`mesa-vulkan-drivers`); otherwise
//! the one command to install it is printed. `.ci/run` calls this same command. It then builds
//! the web version and tests it in headless Chromium (`web_test.rs`); `cargo xtask web` builds
//! and serves that site (`web.rs`). Last, every fuzz target runs for a short, fixed time
//! (`fuzz.rs`; `cargo xtask fuzz` runs them longer).

mod background;
// The floor plan in docs/architecture.md held against the tree (a test only).
#[cfg(test)]
mod floor_plan;
mod fuzz;
mod suite;
mod web;
mod web_test;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

const ICD_DIRS: &[&str] = &["/usr/share/vulkan/icd.d", "/etc/vulkan/icd.d", "/usr/local/share/vulkan/icd.d"];
/// Debian packages of lavapipe and the Vulkan loader.
const LAVAPIPE_PACKAGES: &[&str] = &["mesa-vulkan-drivers", "libvulkan1"];

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("test") => test(&args[1..]),
        Some("fuzz") => match fuzz::main(&args[1..]) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("xtask: {e}");
                ExitCode::FAILURE
            }
        },
        Some("web") => match web::main(&args[1..]) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("xtask: {e}");
                ExitCode::FAILURE
            }
        },
        _ => {
            eprintln!(
                "usage: cargo xtask test [CARGO TEST ARGS] [-- TEST ARGS]\n       cargo xtask web [--out DIR] [--port N] | --bench\n       cargo xtask fuzz [--seconds N]"
            );
            ExitCode::from(2)
        }
    }
}

/// The lavapipe ICD manifest, if installed.
fn lavapipe_icd() -> Option<PathBuf> {
    ICD_DIRS.iter().flat_map(|d| std::fs::read_dir(d).into_iter().flatten().flatten()).map(|e| e.path()).find(|p| {
        p.file_name().and_then(|n| n.to_str()).is_some_and(|n| n.starts_with("lvp_icd") && n.ends_with(".json"))
    })
}

fn is_root() -> bool {
    Command::new("id").arg("-u").output().is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
}

/// Run `cmd` to its end (on the background thread: niced, into its log); whether it succeeded.
fn run(cmd: &mut Command) -> bool {
    let note = format!("xtask: running {cmd:?}");
    match background::niced(cmd, &note) {
        Some(mut niced) => niced.status(),
        None => cmd.status(),
    }
    .is_ok_and(|s| s.success())
}

/// Install Debian packages for something missing: as root on Debian/Ubuntu, `apt-get update`
/// then `apt-get install`; otherwise the error is the one command to run.
fn apt_install(what: &str, packages: &[&str]) -> Result<(), String> {
    let command = format!("sudo apt-get install {}", packages.join(" "));
    if !(Path::new("/etc/debian_version").exists() && is_root()) {
        return Err(format!("{what} is not installed; install it with:\n    {command}"));
    }
    eprintln!("xtask: {what} is missing; installing {}", packages.join(" "));
    let apt = |args: &[&str]| run(Command::new("apt-get").args(args).env("DEBIAN_FRONTEND", "noninteractive"));
    let ok =
        apt(&["update", "-q"]) && apt(&[&["install", "-y", "-q", "--no-install-recommends"][..], packages].concat());
    if ok { Ok(()) } else { Err(format!("installing {what} failed; install it with:\n    {command}")) }
}

pub(crate) fn ensure_lavapipe() -> Result<PathBuf, String> {
    if let Some(icd) = lavapipe_icd() {
        return Ok(icd);
    }
    apt_install("lavapipe (Mesa's CPU Vulkan driver)", LAVAPIPE_PACKAGES)?;
    lavapipe_icd().ok_or_else(|| "mesa-vulkan-drivers is installed but no lavapipe ICD was found".into())
}

/// Every Debian package the steps need that is missing, installed in one `apt-get` run (the
/// background's builds then find their tools, and no two installs contend for dpkg's lock).
fn ensure_system_packages() -> Result<(), String> {
    let mut missing: Vec<(&str, &[&str])> = Vec::new();
    if lavapipe_icd().is_none() {
        missing.push(("lavapipe (Mesa's CPU Vulkan driver)", LAVAPIPE_PACKAGES));
    }
    if !has_xvfb() {
        missing.push(("Xvfb", X_PACKAGES));
    }
    if !Path::new(web_test::CHROMIUM).exists() {
        missing.push(("Chromium", &["chromium"]));
    }
    if !web_test::on_path("node") || !web_test::on_path("npm") {
        missing.push(("Node.js", &["nodejs", "npm"]));
    }
    if !web::rustup_has_wasm_std() && !web::debian_toolchain_present() {
        missing.push(("the web toolchain (rustc for wasm32)", web::WEB_PACKAGES));
    }
    if missing.is_empty() {
        return Ok(());
    }
    let what: Vec<&str> = missing.iter().map(|m| m.0).collect();
    let packages: Vec<&str> = missing.iter().flat_map(|m| m.1.iter().copied()).collect();
    apt_install(&what.join(", "), &packages)
}

/// `cargo xtask test [CARGO ARGS] [-- TEST ARGS]`: every step, timed; the summary names each
/// step's time and the slowest tests, and ends on the counts.
fn test(extra: &[String]) -> ExitCode {
    let (cargo_args, test_args) = match extra.iter().position(|a| a == "--") {
        Some(i) => (&extra[..i], &extra[i + 1..]),
        None => (extra, &[][..]),
    };
    let mut timings = suite::Timings::default();
    // A package that did not install fails only the steps that need it (each checks its own
    // tools again); without lavapipe nothing can run.
    let installed = timings.step("system packages", |_| {
        if let Err(msg) = ensure_system_packages() {
            eprintln!("xtask: {msg}");
        }
        ensure_lavapipe()
    });
    let icd = match installed {
        Ok(icd) => icd,
        Err(msg) => {
            eprintln!("xtask: {msg}");
            return ExitCode::FAILURE;
        }
    };
    eprintln!("xtask: lavapipe at {}", icd.display());
    let site = web::root().join("target/web-site");
    let background = background::start(site.clone(), web::root().join("target/web-node"), timings.since);
    let xdg = runtime_dir();
    // Only lavapipe is visible to the Vulkan loader (both variable names, old and new loaders),
    // and the tests and the binary ask for it by name as well.
    let env = [
        ("VK_DRIVER_FILES", icd.as_os_str()),
        ("VK_ICD_FILENAMES", icd.as_os_str()),
        ("SHADELAB_ADAPTER", "lavapipe".as_ref()),
        ("XDG_RUNTIME_DIR", xdg.as_os_str()),
    ];
    let mut count = Count::default();
    let binaries = match timings.step("build the tests", |_| suite::build(cargo_args, &env)) {
        Ok(b) => b,
        Err(msg) => {
            count.check("build the tests", Err(msg));
            Vec::new()
        }
    };
    let label = format!("run {} test binaries", binaries.len());
    let tests_ok = timings.step(&label, |t| suite::run(&binaries, test_args, &env, &mut count, t));
    let smoke = timings.step("viewer under Xvfb", |_| viewer_smoke_test(&icd, &xdg));
    count.check("viewer smoke test under Xvfb", smoke);
    let log = background.log.clone();
    let with_log = |r: Result<(), String>| {
        r.map_err(|e| format!("{e}; the end of {}:\n{}", log.display(), background::tail(&log, 30)))
    };
    // The browser tests start once the site is built; the fuzz targets go on building meanwhile.
    let site_built = timings.step("wait for the web build", |_| background.site.recv());
    let site_built = with_log(site_built.unwrap_or_else(|_| Err("the background's thread stopped".into())));
    web_test::browser_tests(&icd, &site, site_built, &mut count, &mut timings);
    let prepared = timings.step("wait for the fuzz targets' build", |_| background.rest.join());
    let fuzz_built = match prepared {
        Ok(p) => {
            timings.merge(p.timings);
            with_log(p.fuzz_targets)
        }
        Err(_) => Err("the background's thread panicked".into()),
    };
    let fuzzing = format!("every fuzz target for {} s on its seeds", fuzz::CI_SECONDS);
    let fuzzed = fuzz_built.and_then(|()| timings.step("fuzz targets: run", |_| fuzz::run_targets(fuzz::CI_SECONDS)));
    count.check(&fuzzing, fuzzed);
    let fresh = timings.step("`cargo run --release` is built", |_| viewer_build_is_fresh());
    count.check("`cargo run --release` reuses the test build", fresh);
    summary(&timings, &count, tests_ok)
}

/// Print the steps' times and the slowest tests, then the last line: every test binary's
/// results and xtask's own checks, together.
fn summary(timings: &suite::Timings, count: &Count, tests_ok: bool) -> ExitCode {
    for line in timings.summary(10) {
        println!("{line}");
    }
    println!("xtask: {} passed, {} failed", count.passed, count.failed);
    if tests_ok && count.failed == 0 { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}

/// Tests counted from `cargo test`'s "test result:" lines.
#[derive(Default, Debug, PartialEq)]
struct Count {
    passed: u64,
    failed: u64,
}

impl Count {
    /// Count one of xtask's own checks and say how it went.
    fn check(&mut self, name: &str, result: Result<(), String>) {
        match result {
            Ok(()) => {
                eprintln!("xtask: {name}: passed");
                self.passed += 1;
            }
            Err(msg) => {
                eprintln!("xtask: {name}: FAILED: {msg}");
                self.failed += 1;
            }
        }
    }

    /// Add one "test result: ok. 3 passed; 1 failed; …" line (other lines are ignored).
    fn add_line(&mut self, line: &str) {
        let Some(rest) = line.trim_start().strip_prefix("test result: ") else { return };
        for part in rest.split(';') {
            let words: Vec<&str> = part.split_whitespace().collect();
            let n = |w: &str| w.parse::<u64>().ok();
            match words.as_slice() {
                [.., a, "passed"] => self.passed += n(a).unwrap_or(0),
                [a, "failed"] => self.failed += n(a).unwrap_or(0),
                _ => {}
            }
        }
    }
}

/// Run `cmd`, passing its output through, and count its test results and their times (each
/// test's name after `prefix`). False also when it could not start.
fn run_counting(cmd: &mut Command, timings: &mut suite::Timings, prefix: &str) -> (bool, Count) {
    use std::io::BufRead;
    eprintln!("xtask: running {cmd:?}");
    let mut count = Count::default();
    let Ok(mut child) = cmd.stdout(std::process::Stdio::piped()).spawn() else {
        return (false, count);
    };
    if let Some(out) = child.stdout.take() {
        for line in std::io::BufReader::new(out).lines().map_while(Result::ok) {
            println!("{line}");
            count.add_line(&line);
            if let Some(mut t) = suite::test_time(&line) {
                t.name = format!("{prefix}{}", t.name);
                timings.tests.push(t);
            }
        }
    }
    (child.wait().is_ok_and(|s| s.success()), count)
}

/// `XDG_RUNTIME_DIR` for the tests: the caller's, or a private one (Mesa's window-system code
/// complains on every device open without one).
pub(crate) fn runtime_dir() -> PathBuf {
    if let Some(d) = std::env::var_os("XDG_RUNTIME_DIR") {
        return d.into();
    }
    let dir = std::env::temp_dir().join("shadelab-xdg");
    let _ = std::fs::create_dir_all(&dir);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let _ = std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700));
    }
    dir
}

/// Build what `cargo run --release` builds (the default member, release) and fail if any crate
/// compiled: after the tests it must start at once. A crate whose features differ between the two
/// builds compiles twice; `crates/shadelab/Cargo.toml` aligns them.
fn viewer_build_is_fresh() -> Result<(), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf();
    let mut cmd = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
    cmd.current_dir(&root).args(["build", "--release", "--message-format", "json"]);
    // The user's `cargo run` comes from a plain shell: without the variables `cargo run` set
    // for xtask (the user's own CARGO_HOME, CARGO_TARGET_DIR and the like stay).
    for (k, _) in std::env::vars_os() {
        let set_for_xtask =
            ["CARGO_PKG_", "CARGO_MANIFEST_", "CARGO_CRATE_NAME", "CARGO_BIN_NAME", "CARGO_PRIMARY_PACKAGE"];
        if k.to_str().is_some_and(|k| set_for_xtask.iter().any(|p| k.starts_with(p))) {
            cmd.env_remove(k);
        }
    }
    eprintln!("xtask: running {cmd:?}");
    let out = cmd.stderr(std::process::Stdio::inherit()).output().map_err(|e| format!("running cargo: {e}"))?;
    if !out.status.success() {
        return Err(format!("cargo build --release exited with {}", out.status));
    }
    let compiled = compiled_units(&String::from_utf8_lossy(&out.stdout));
    if compiled.is_empty() {
        Ok(())
    } else {
        Err(format!("it compiled {} crate(s) again: {}", compiled.len(), compiled.join(", ")))
    }
}

/// The package ids of the units cargo's JSON messages report as compiled rather than fresh.
fn compiled_units(json_lines: &str) -> Vec<String> {
    json_lines
        .lines()
        .filter(|l| l.contains("\"reason\":\"compiler-artifact\"") && l.contains("\"fresh\":false"))
        .filter_map(|l| {
            let rest = &l[l.find("\"package_id\":\"")? + "\"package_id\":\"".len()..];
            Some(rest[..rest.find('"')?].to_string())
        })
        .collect()
}

/// Debian packages the real window needs under Xvfb (the X server, and the X libraries winit
/// loads at run time).
const X_PACKAGES: &[&str] =
    &["xvfb", "xauth", "libx11-xcb1", "libxcursor1", "libxrandr2", "libxi6", "libxkbcommon-x11-0"];

fn has_xvfb() -> bool {
    Command::new("sh").args(["-c", "command -v Xvfb"]).output().is_ok_and(|o| o.status.success())
}

/// Run the real `shadelab` viewer with `args` in an Xvfb window (installed when missing), on
/// lavapipe; its output once it has exited.
pub(crate) fn viewer_in_xvfb(icd: &Path, xdg: &Path, args: &[&str]) -> Result<std::process::Output, String> {
    if !has_xvfb() {
        apt_install("Xvfb", X_PACKAGES)?;
        if !has_xvfb() {
            return Err("the Xvfb packages are installed but Xvfb is not on PATH".into());
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf();
    let display = format!(":{}", 90 + std::process::id() % 100);
    let mut xvfb = Command::new("Xvfb")
        .args([display.as_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .map_err(|e| format!("starting Xvfb: {e}"))?;
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let out = Command::new("timeout")
        .arg("300")
        .arg(root.join("target/release/shadelab"))
        .args(args)
        .env("DISPLAY", &display)
        .env("VK_DRIVER_FILES", icd)
        .env("VK_ICD_FILENAMES", icd)
        .env("XDG_RUNTIME_DIR", xdg)
        .env_remove("WAYLAND_DISPLAY")
        .stderr(std::process::Stdio::inherit())
        .output();
    let _ = xvfb.kill();
    let _ = xvfb.wait();
    match out {
        Ok(o) if o.status.success() => Ok(o),
        Ok(o) => Err(format!("the viewer exited with {}", o.status)),
        Err(e) => Err(format!("running the viewer: {e}")),
    }
}

/// Start the real `shadelab` viewer in an Xvfb window, let it render a few frames, save the
/// window (panel included) and check the picture is not blank.
fn viewer_smoke_test(icd: &Path, xdg: &Path) -> Result<(), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf();
    let shot = root.join("target").join("xvfb-smoke.png");
    let _ = std::fs::remove_file(&shot);
    viewer_in_xvfb(icd, xdg, &["--screenshot", shot.to_str().unwrap(), "--exit-after-frames", "5"])?;
    let img = image::open(&shot).map_err(|e| format!("reading {}: {e}", shot.display()))?.to_rgb8();
    let distinct: std::collections::HashSet<[u8; 3]> = img.pixels().map(|p| p.0).collect();
    // The panel's text and the shaded scene give thousands of colours; a blank or one-colour
    // window gives a handful.
    if distinct.len() < 500 {
        return Err(format!("{} looks blank: {} distinct colours", shot.display(), distinct.len()));
    }
    panel_stands_on_its_fill(&img).map_err(|e| format!("{}: {e}", shot.display()))?;
    eprintln!("xtask: {} is {}×{} with {} distinct colours", shot.display(), img.width(), img.height(), distinct.len());
    Ok(())
}

/// egui's dark panel fill, which the window is cleared to where the panel paints none.
const PANEL_FILL: [u8; 3] = [27, 27, 27];

/// The panel's strip (the right fifth of the window) is mostly its fill: the window's clear
/// stands in for the fill the panel no longer paints, and a wrong clear shows here.
fn panel_stands_on_its_fill(img: &image::RgbImage) -> Result<(), String> {
    let strip = (img.width() * 4 / 5..img.width()).flat_map(|x| (0..img.height()).map(move |y| (x, y)));
    let (mut fill, mut all) = (0u64, 0u64);
    for (x, y) in strip {
        fill += u64::from(img.get_pixel(x, y).0 == PANEL_FILL);
        all += 1;
    }
    // Text, buttons and sliders cover well under half of the panel.
    if fill * 2 < all {
        return Err(format!("only {fill} of the panel's {all} pixels are its fill {PANEL_FILL:?}"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_result_lines_are_counted() {
        let mut c = Count::default();
        c.add_line("test result: ok. 24 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 1.2s");
        c.add_line("test result: FAILED. 3 passed; 2 failed; 0 ignored; 0 measured; 0 filtered out");
        c.add_line("running 5 tests");
        c.add_line("test a ... ok");
        assert_eq!(c, Count { passed: 27, failed: 2 });
    }

    #[test]
    fn a_panel_without_its_fill_is_found() {
        let mut img = image::RgbImage::from_pixel(100, 40, image::Rgb(PANEL_FILL));
        assert_eq!(panel_stands_on_its_fill(&img), Ok(()));
        // eframe's own clear colour where the panel's fill should be.
        for x in 80..100 {
            for y in 0..40 {
                img.put_pixel(x, y, image::Rgb([12, 12, 12]));
            }
        }
        assert!(panel_stands_on_its_fill(&img).is_err());
    }

    #[test]
    fn compiled_units_are_the_artifacts_not_fresh() {
        let json = concat!(
            r#"{"reason":"compiler-artifact","package_id":"registry+x#serde_core@1.0.229","fresh":true}"#,
            "\n",
            r#"{"reason":"compiler-artifact","package_id":"path+file:///w/crates/shadelab#0.1.0","fresh":false}"#,
            "\n",
            r#"{"reason":"build-finished","success":true}"#,
        );
        assert_eq!(compiled_units(json), vec!["path+file:///w/crates/shadelab#0.1.0".to_string()]);
    }
}
