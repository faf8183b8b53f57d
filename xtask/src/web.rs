//! `cargo xtask web`: build the viewer for wasm32 + WebGPU into a static site (index.html, the
//! .wasm and its .js) and serve it on 127.0.0.1, or write it to `--out DIR` to host anywhere.
//!
//! The toolchain: rustup's `wasm32-unknown-unknown` target where it is installed; otherwise
//! Debian's `rustc-web` with its library source, std built for wasm32 (`-Zbuild-std`), linked by
//! `wasm-ld-22`. The JS glue comes from `wasm-bindgen-cli-support`, the library of the
//! `wasm-bindgen` command, at the version of the crate the page links.

use crate::{apt_install, run};
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::Command;

pub const WASM_TARGET: &str = "wasm32-unknown-unknown";
/// Debian's web toolchain: rustc and cargo for wasm32, std's source, and the wasm linker.
pub(crate) const WEB_PACKAGES: &[&str] = &["rustc-web", "cargo-web", "rust-web-src", "lld-22"];
const DEBIAN_RUSTC: &str = "/usr/bin/rustc";
const DEBIAN_CARGO: &str = "/usr/bin/cargo";
const DEBIAN_STD_SOURCE: &str = "/usr/lib/rustlib/src/rust/library";
const DEBIAN_WASM_LD: &str = "/usr/bin/wasm-ld-22";
/// The page and what it loads, as wasm-bindgen's web target names them.
pub const SITE_FILES: &[&str] = &["index.html", "shadelab_web.js", "shadelab_web_bg.wasm"];

pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

fn rustup_cargo() -> String {
    std::env::var("CARGO").unwrap_or_else(|_| "cargo".into())
}

/// Whether the rustc rustup runs has the wasm32 standard library.
pub(crate) fn rustup_has_wasm_std() -> bool {
    let Ok(out) = Command::new("rustc").args(["--print", "sysroot"]).output() else { return false };
    let sysroot = String::from_utf8_lossy(&out.stdout).trim().to_string();
    Path::new(&sysroot).join("lib/rustlib").join(WASM_TARGET).join("lib").is_dir()
}

pub(crate) fn debian_toolchain_present() -> bool {
    [DEBIAN_RUSTC, DEBIAN_CARGO, DEBIAN_STD_SOURCE, DEBIAN_WASM_LD].iter().all(|p| Path::new(p).exists())
        && Command::new(DEBIAN_RUSTC).arg("--version").output().is_ok_and(|o| o.status.success())
}

/// The cargo command that builds `shadelab-web` for wasm32, release, into `target/web`.
fn wasm_build_command() -> Result<Command, String> {
    let root = root();
    let mut cmd;
    if rustup_has_wasm_std() {
        cmd = Command::new(rustup_cargo());
        cmd.arg("build");
    } else {
        if !debian_toolchain_present() {
            apt_install("the web toolchain (rustc for wasm32)", WEB_PACKAGES)?;
        }
        cmd = Command::new(DEBIAN_CARGO);
        // Debian's cargo with Debian's rustc (rustup's proxies come first on PATH), std built
        // from Debian's library source, which needs the bootstrap switch for -Z.
        cmd.arg("build").arg("-Zbuild-std=std,panic_abort");
        cmd.env("RUSTC", DEBIAN_RUSTC).env("RUSTC_BOOTSTRAP", "1").env_remove("RUSTUP_TOOLCHAIN");
        cmd.env("CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER", DEBIAN_WASM_LD);
    }
    cmd.current_dir(&root)
        .args(["-p", "shadelab-web", "--release", "--target", WASM_TARGET, "--target-dir"])
        .arg(root.join("target/web"));
    // getrandom (pulled in by a dependency) reads the browser's crypto on wasm32.
    cmd.env("CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS", "--cfg getrandom_backend=\"wasm_js\"");
    Ok(cmd)
}

/// Build the site into `out`: the wasm module, its JS glue and the page.
pub fn build_site(out: &Path) -> Result<(), String> {
    let mut cmd = wasm_build_command()?;
    if !run(&mut cmd) {
        return Err("building shadelab-web for wasm32 failed".into());
    }
    let wasm = root().join("target/web").join(WASM_TARGET).join("release/shadelab_web.wasm");
    std::fs::create_dir_all(out).map_err(|e| format!("creating {}: {e}", out.display()))?;
    bindgen(&wasm, out)?;
    let page = root().join("crates/shadelab-web/static/index.html");
    std::fs::copy(&page, out.join("index.html")).map_err(|e| format!("copying {}: {e}", page.display()))?;
    Ok(())
}

/// Write the JS glue and the final module of `wasm` into `out`: what `wasm-bindgen --target web
/// --no-typescript` writes, made by the library it wraps.
#[cfg(feature = "bindgen")]
fn bindgen(wasm: &Path, out: &Path) -> Result<(), String> {
    wasm_bindgen_cli_support::Bindgen::new()
        .input_path(wasm)
        .web(true)
        .and_then(|b| b.typescript(false).omit_default_module_path(false).generate(out))
        .map_err(|e| format!("wasm-bindgen on {}: {e:#}", wasm.display()))
}

/// Without the library (xtask built by the workspace's test build, not by `cargo xtask`).
#[cfg(not(feature = "bindgen"))]
fn bindgen(_wasm: &Path, _out: &Path) -> Result<(), String> {
    Err("this xtask was built without its `bindgen` feature: run it as `cargo xtask`".into())
}

/// Serve `dir` on 127.0.0.1:`port` (0: any free port) on a thread; returns the address.
pub fn serve(dir: &Path, port: u16) -> Result<String, String> {
    let listener = std::net::TcpListener::bind(("127.0.0.1", port)).map_err(|e| format!("127.0.0.1:{port}: {e}"))?;
    let addr = listener.local_addr().map_err(|e| e.to_string())?;
    let dir = dir.to_path_buf();
    std::thread::spawn(move || {
        for stream in listener.incoming().flatten() {
            let dir = dir.clone();
            std::thread::spawn(move || {
                let _ = answer(stream, &dir);
            });
        }
    });
    Ok(format!("http://{addr}/"))
}

/// Answer one GET with a file of `dir` (the path's query ignored), or 404.
fn answer(mut stream: std::net::TcpStream, dir: &Path) -> std::io::Result<()> {
    let mut line = String::new();
    BufReader::new(&stream).read_line(&mut line)?;
    let path = line.split_whitespace().nth(1).unwrap_or("/");
    let path = path.split(['?', '#']).next().unwrap_or("/").trim_start_matches('/');
    let name = if path.is_empty() { "index.html" } else { path };
    let file = (!name.split('/').any(|p| p == ".." || p.is_empty())).then(|| dir.join(name));
    match file.and_then(|f| std::fs::read(&f).ok()) {
        Some(body) => {
            let kind = match name.rsplit('.').next() {
                Some("html") => "text/html; charset=utf-8",
                Some("js") => "text/javascript",
                Some("wasm") => "application/wasm",
                _ => "application/octet-stream",
            };
            write!(
                stream,
                "HTTP/1.1 200 OK\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
                body.len()
            )?;
            stream.write_all(&body)
        }
        None => stream.write_all(b"HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n"),
    }
}

/// `cargo xtask web [--out DIR] [--port N]`, or `--bench` (`web_test::bench`).
pub fn main(args: &[String]) -> Result<(), String> {
    let mut out = None;
    let mut port = 8000u16;
    if args.first().map(String::as_str) == Some("--bench") {
        return crate::web_test::bench();
    }
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--out" => out = Some(PathBuf::from(it.next().ok_or("--out needs a folder")?)),
            "--port" => {
                let v = it.next().ok_or("--port needs a number")?;
                port = v.parse().map_err(|_| format!("--port: '{v}' is not a port number in [0, 65535]"))?;
            }
            other => {
                return Err(format!("unknown option '{other}' (cargo xtask web [--out DIR] [--port N] | --bench)"));
            }
        }
    }
    if let Some(dir) = out {
        build_site(&dir)?;
        eprintln!(
            "xtask: wrote the site to {} ({}); host the folder on any static server",
            dir.display(),
            SITE_FILES.join(", ")
        );
        return Ok(());
    }
    let dir = root().join("target/web-site");
    build_site(&dir)?;
    let address = serve(&dir, port)?;
    println!("xtask: shadelab is served on {address} (Ctrl-C stops it); it needs a browser with WebGPU");
    loop {
        std::thread::park();
    }
}
