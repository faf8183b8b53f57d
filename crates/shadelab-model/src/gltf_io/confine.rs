//! Where a scene file's relative URIs may lead: inside the file's own folder, and only there,
//! unless the user allows more (`--allow-outside-paths`). Nothing in glTF makes a loader read
//! outside that folder, and a scene rendered by a pipeline that did not write it must not carry
//! another file's bytes out (as a texture or vertex colours).

use super::GltfError;
use super::scene_file::Cx;
use std::path::{Component, Path, PathBuf};

/// URI schemes that name another machine: refused, the loader never opens a connection.
const REMOTE_SCHEMES: [&str; 4] = ["http:", "https:", "ftp:", "file://"];

/// The file a relative URI names in `dir`, percent-decoded. A scheme is refused
/// ([`relative_uri`]), and with `confined`:
/// - an absolute path;
/// - a `..` that climbs above `dir`;
/// - a path whose real location (symbolic links followed) is outside `dir`'s.
pub(super) fn local_path(cx: &Cx, what: &str, uri: &str, dir: &Path, confined: bool) -> Result<PathBuf, GltfError> {
    relative_uri(cx, what, uri)?;
    let decoded = super::percent_decode(uri);
    let relative = Path::new(&decoded);
    if !confined {
        return Ok(dir.join(relative));
    }
    let allow = "(--allow-outside-paths reads it)";
    if relative.has_root() || decoded.starts_with(['/', '\\']) {
        return Err(cx.invalid(format!("{what}: '{uri}' is an absolute path, outside the scene's folder {allow}")));
    }
    let mut depth = 0i64;
    for c in relative.components() {
        match c {
            Component::ParentDir => depth -= 1,
            Component::Normal(_) => depth += 1,
            _ => {}
        }
        if depth < 0 {
            return Err(cx.invalid(format!("{what}: '{uri}' leaves the scene's folder through '..' {allow}")));
        }
    }
    let path = dir.join(relative);
    // Symbolic links: where the file really is must be inside where the folder really is. A
    // file that does not exist is left to the read, which names it.
    if let (Ok(real), Ok(root)) = (path.canonicalize(), dir.canonicalize())
        && !real.starts_with(&root)
    {
        return Err(
            cx.invalid(format!("{what}: '{uri}' is a link to {}, outside the scene's folder {allow}", real.display()))
        );
    }
    Ok(path)
}

/// Refuse a URI with a scheme (data: URIs are read before this): a remote one with its own line.
pub(super) fn relative_uri(cx: &Cx, what: &str, uri: &str) -> Result<(), GltfError> {
    let lower = uri.to_ascii_lowercase();
    // `file:///x` is a local absolute path in URI form: refused as a scheme below.
    if REMOTE_SCHEMES.iter().any(|s| lower.starts_with(s)) && !lower.starts_with("file:///") {
        return Err(cx.invalid(format!(
            "{what}: '{uri}' is a remote URI; shadelab never opens a network connection (put the file beside the scene)"
        )));
    }
    if uri.split(['/', '\\']).next().is_some_and(|first| first.contains(':')) {
        return Err(cx.invalid(format!("{what}: '{uri}' is neither a data: URI nor a relative file path")));
    }
    Ok(())
}
