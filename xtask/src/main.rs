//! `cargo xtask test`: make sure lavapipe (Mesa's CPU Vulkan driver) is installed, force it as
//! the only Vulkan driver, and run every test of the workspace on it.
//!
//! On Debian/Ubuntu as root, a missing lavapipe is installed (`mesa-vulkan-drivers`); otherwise
//! the one command to install it is printed. `.ci/run` calls this same command.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

const ICD_DIRS: &[&str] = &[
    "/usr/share/vulkan/icd.d",
    "/etc/vulkan/icd.d",
    "/usr/local/share/vulkan/icd.d",
];
const INSTALL: &str = "sudo apt-get install mesa-vulkan-drivers";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("test") => test(&args[1..]),
        _ => {
            eprintln!("usage: cargo xtask test [-- <cargo test args>]");
            ExitCode::from(2)
        }
    }
}

/// The lavapipe ICD manifest, if installed.
fn lavapipe_icd() -> Option<PathBuf> {
    ICD_DIRS
        .iter()
        .flat_map(|d| std::fs::read_dir(d).into_iter().flatten().flatten())
        .map(|e| e.path())
        .find(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("lvp_icd") && n.ends_with(".json"))
        })
}

fn is_root() -> bool {
    Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
}

fn run(cmd: &mut Command) -> bool {
    eprintln!("xtask: running {cmd:?}");
    cmd.status().is_ok_and(|s| s.success())
}

fn ensure_lavapipe() -> Result<PathBuf, String> {
    if let Some(icd) = lavapipe_icd() {
        return Ok(icd);
    }
    let debian = Path::new("/etc/debian_version").exists();
    if !(debian && is_root()) {
        return Err(format!(
            "lavapipe (Mesa's CPU Vulkan driver) is not installed; install it with:\n    {INSTALL}"
        ));
    }
    eprintln!("xtask: lavapipe is missing; installing mesa-vulkan-drivers");
    let ok = run(Command::new("apt-get")
        .args(["update", "-q"])
        .env("DEBIAN_FRONTEND", "noninteractive"))
        && run(Command::new("apt-get")
            .args([
                "install",
                "-y",
                "-q",
                "--no-install-recommends",
                "mesa-vulkan-drivers",
                "libvulkan1",
            ])
            .env("DEBIAN_FRONTEND", "noninteractive"));
    match (ok, lavapipe_icd()) {
        (true, Some(icd)) => Ok(icd),
        _ => Err(format!(
            "installing lavapipe failed; install it with:\n    {INSTALL}"
        )),
    }
}

fn test(extra: &[String]) -> ExitCode {
    let icd = match ensure_lavapipe() {
        Ok(icd) => icd,
        Err(msg) => {
            eprintln!("xtask: {msg}");
            return ExitCode::FAILURE;
        }
    };
    eprintln!("xtask: lavapipe at {}", icd.display());
    let mut cmd = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
    cmd.args(["test", "--release", "--workspace"]).args(extra);
    // Only lavapipe is visible to the Vulkan loader (both variable names, old and new loaders),
    // and the tests and the binary ask for it by name as well.
    cmd.env("VK_DRIVER_FILES", &icd)
        .env("VK_ICD_FILENAMES", &icd)
        .env("SHADELAB_ADAPTER", "lavapipe");
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        // Mesa's window-system code complains on every device open without one.
        let dir = std::env::temp_dir().join("shadelab-xdg");
        let _ = std::fs::create_dir_all(&dir);
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let _ = std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700));
        }
        cmd.env("XDG_RUNTIME_DIR", dir);
    }
    if run(&mut cmd) {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
