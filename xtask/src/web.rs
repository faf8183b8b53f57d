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
/// The URIs a `.gltf`'s text names (`"uri": "…"`), as written; the loader checks the rest.
fn gltf_uris(text: &str) -> Vec<String> {
    let mut uris = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("\"uri\"") {
        rest = rest[i + 5..].trim_start();
        let Some(after) = rest.strip_prefix(':').map(str::trim_start).and_then(|r| r.strip_prefix('"')) else {
            continue;
        };
        let end = after.find('"').unwrap_or(after.len());
        uris.push(after[..end].to_string());
        rest = &after[end..];
    }
    uris
}

/// Whether a path may stand as it is under the site: relative, with no `..`, scheme or `\`.
fn stays_under(path: &str) -> bool {
    !path.is_empty()
        && !path.starts_with('/')
        && !path.contains([':', '\\', '?', '#'])
        && !path.split('/').any(|s| s == "..")
}

/// Copy each model into `site` for links to name (`?file=PATH`): under the path it was given
/// where that is relative and stays below (else under its file name), a `.gltf` with the files
/// it names beside it. Returns the site path of each.
pub fn copy_models(site: &Path, models: &[PathBuf]) -> Result<Vec<String>, String> {
    let mut written = Vec::new();
    for model in models {
        let given = model.to_string_lossy().replace('\\', "/");
        let lower = given.to_ascii_lowercase();
        if !(lower.ends_with(".glb") || lower.ends_with(".gltf")) {
            return Err(format!("--with {given}: not a .glb or .gltf file"));
        }
        let bytes = std::fs::read(model).map_err(|e| format!("--with {given}: {e}"))?;
        let name = model.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let at = if stays_under(&given) { given.trim_start_matches("./").to_string() } else { name };
        let dest = site.join(&at);
        let copy = |from: &Path, to: &Path, what: &str| -> Result<(), String> {
            std::fs::create_dir_all(to.parent().unwrap_or(site)).map_err(|e| format!("{}: {e}", to.display()))?;
            std::fs::copy(from, to).map(|_| ()).map_err(|e| format!("--with {given}: {what}: {e}"))
        };
        copy(model, &dest, "copying")?;
        if lower.ends_with(".gltf") {
            let text = String::from_utf8_lossy(&bytes);
            let beside = model.parent().unwrap_or(Path::new("."));
            for uri in gltf_uris(&text).into_iter().filter(|u| !u.starts_with("data:")) {
                if !stays_under(&uri) {
                    return Err(format!("--with {given}: '{uri}' is not a file beside it, which a site can serve"));
                }
                copy(&beside.join(&uri), &dest.parent().unwrap_or(site).join(&uri), &uri)?;
            }
        }
        written.push(at);
    }
    Ok(written)
}

pub fn main(args: &[String]) -> Result<(), String> {
    let mut out = None;
    let mut with = Vec::new();
    let mut port = 8000u16;
    if args.first().map(String::as_str) == Some("--bench") {
        return crate::web_test::bench();
    }
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--out" => out = Some(PathBuf::from(it.next().ok_or("--out needs a folder")?)),
            "--with" => with.push(PathBuf::from(it.next().ok_or("--with needs a .glb or .gltf file")?)),
            "--port" => {
                let v = it.next().ok_or("--port needs a number")?;
                port = v.parse().map_err(|_| format!("--port: '{v}' is not a port number in [0, 65535]"))?;
            }
            other => {
                return Err(format!(
                    "unknown option '{other}' (cargo xtask web [--out DIR] [--with FILE]… [--port N] | --bench)"
                ));
            }
        }
    }
    let models = |dir: &Path| -> Result<(), String> {
        for at in copy_models(dir, &with)? {
            eprintln!("xtask: {at} is on the site: a link opens it with ?file={at}");
        }
        Ok(())
    };
    if let Some(dir) = out {
        build_site(&dir)?;
        models(&dir)?;
        eprintln!(
            "xtask: wrote the site to {} ({}); host the folder on any static server",
            dir.display(),
            SITE_FILES.join(", ")
        );
        return Ok(());
    }
    let dir = root().join("target/web-site");
    build_site(&dir)?;
    models(&dir)?;
    let address = serve(&dir, port)?;
    println!("xtask: shadelab is served on {address} (Ctrl-C stops it); it needs a browser with WebGPU");
    loop {
        std::thread::park();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `--with`: a `.gltf` goes under its relative path with the buffer it names beside it; a
    /// path that climbs out goes under its file name; a missing file or a URI out of the folder
    /// is one line.
    #[test]
    fn models_are_copied_with_the_files_they_name() {
        let tmp = std::env::temp_dir().join(format!("xtask-with-{}", std::process::id()));
        let (src, site) = (tmp.join("src/models"), tmp.join("site"));
        std::fs::create_dir_all(&src).unwrap();
        std::fs::write(src.join("m.gltf"), r#"{"buffers": [{"uri" : "m.bin"}, {"uri": "data:,x"}]}"#).unwrap();
        std::fs::write(src.join("m.bin"), b"1234").unwrap();
        std::fs::write(src.join("out.gltf"), r#"{"images": [{"uri": "../secret.png"}]}"#).unwrap();
        let at = copy_models(&site, &[src.join("m.gltf")]).unwrap();
        let name = "m.gltf".to_string();
        assert_eq!(at, [name], "an absolute path goes under its file name");
        assert_eq!(std::fs::read(site.join("m.bin")).unwrap(), b"1234");
        assert!(copy_models(&site, &[src.join("out.gltf")]).unwrap_err().contains("not a file beside it"));
        assert!(copy_models(&site, &[src.join("none.glb")]).unwrap_err().starts_with("--with "));
        assert!(copy_models(&site, &[src.join("m.bin")]).unwrap_err().contains("not a .glb or .gltf"));
        assert_eq!(gltf_uris(r#"{"uri":"a b.bin","x":{"uri" :  "c.png"}}"#), ["a b.bin", "c.png"]);
        assert!(stays_under("models/duck.glb") && !stays_under("../x.glb") && !stays_under("/x.glb"));
        std::fs::remove_dir_all(&tmp).unwrap();
    }
}
