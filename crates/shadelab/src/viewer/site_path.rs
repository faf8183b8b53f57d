//! A path on the page's own site, as a link's `file=` and the URIs of the `.gltf` it names must
//! be (docs/web.md, "A model from a link"): relative to the page, so it stays on its origin and
//! below its folder.

/// The longest path a link's file may have: far past any site's folder depth, short enough to
/// keep the link's own length in bounds.
const SITE_PATH_MAX: usize = 512;

/// Whether `path` stays on the page's origin, under the page's folder: relative, with no scheme,
/// no leading `/`, no `\`, no `..` segment, no query or fragment and no control character.
pub fn relative_on_site(path: &str) -> Result<(), String> {
    let why = if path.is_empty() {
        "it is empty"
    } else if path.len() > SITE_PATH_MAX {
        "it is longer than 512 characters (SITE_PATH_MAX)"
    } else if path.contains(':') {
        "it names a scheme or another origin"
    } else if path.starts_with('/') {
        "it is not relative to the page"
    } else if path.contains('\\') || path.contains('?') || path.contains('#') || path.chars().any(char::is_control) {
        "it holds \\, ?, # or a control character"
    } else if path.split('/').any(|seg| seg == "..") {
        "it climbs out of the page's folder (..)"
    } else {
        return Ok(());
    };
    Err(format!("'{path}' is refused: only a path relative to the page, on its own site ({why})"))
}

/// A link's `file=`: a `.glb` or `.gltf` path relative to the page ([`relative_on_site`]).
pub fn site_path(path: &str) -> Result<String, String> {
    relative_on_site(path)?;
    let lower = path.to_ascii_lowercase();
    if !(lower.ends_with(".glb") || lower.ends_with(".gltf")) {
        return Err(format!("'{path}' is not a .glb or .gltf file"));
    }
    Ok(path.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_relative_model_paths_on_the_site_are_taken() {
        for good in ["duck.glb", "models/Duck.GLTF", "a/b/c d.glb", "./x.glb"] {
            assert_eq!(site_path(good).as_deref(), Ok(good), "{good}");
        }
        let bad = [
            ("https://evil.example/x.glb", "scheme"),
            ("//evil.example/x.glb", "not relative"),
            ("/x.glb", "not relative"),
            ("../x.glb", "climbs out"),
            ("a/../../x.glb", "climbs out"),
            ("a\\x.glb", "\\"),
            ("x.glb?y", "?"),
            ("data:model/gltf-binary;base64,AAAA.glb", "scheme"),
            ("", "empty"),
            ("x.png", "not a .glb or .gltf"),
        ];
        for (path, says) in bad {
            let e = site_path(path).expect_err(path);
            assert!(e.contains(says) && !e.contains('\n'), "{path}: {e}");
        }
        assert!(site_path(&"a/".repeat(300)).is_err());
    }
}
