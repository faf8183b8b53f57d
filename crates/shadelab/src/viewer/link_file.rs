//! A link's model on the page's own site (`?file=models/duck.glb`): the path's confinement, the
//! page's fetch of the file with the buffers and images a `.gltf` names, and the rest of the link
//! applied once the file has opened. On the desktop the same path is the link's `--scene`.
//! `cargo xtask web --with FILE` puts models on the site.

use super::Viewer;
use super::link::Link;
use crate::cli;
use shadelab_model::gltf_io::LoadedScene;
use shadelab_model::scene::Overrides;
use shadelab_model::{ModelChoice, Scene};
use shadelab_render::SceneGpu;

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

/// The scene a file's link writes its edits against: the file's scene as loaded, under the
/// link's model (as `ModeArgs::settle` gives it).
pub fn base(raw: &Scene, model: ModelChoice) -> Scene {
    let mut s = raw.clone();
    s.apply(&Overrides::for_model(model));
    s
}

impl Viewer {
    /// Fetch a link's file from the page's site; the rest of the link waits for it to open.
    pub(super) fn fetch_link_file(&mut self, file: &str, link: Link) {
        #[cfg(target_arch = "wasm32")]
        super::web::fetch_site_files(file.to_string());
        self.pending_link = Some(link);
        self.message = Some((format!("fetching {file}"), false));
    }

    /// Whether the file `name` that has opened is the one a waiting link fetched.
    pub(super) fn is_pending_link_file(&self, name: &str) -> bool {
        let file = self.pending_link.as_ref().and_then(|l| l.file.as_deref());
        file.is_some_and(|f| f.rsplit('/').next() == Some(name))
    }

    /// The file a link fetched has opened: its flags and modes as the command line would apply
    /// them, then the rest of the link; the file's own scene is the base of the next link.
    pub(super) fn finish_link_file(&mut self, mut loaded: LoadedScene, gpu_scene: SceneGpu, name: &str) {
        let Some(link) = self.pending_link.take() else { return };
        let mut errors = link.errors.clone();
        let raw = loaded.scene.clone();
        let c = match cli::parse_args(link.flag_args()) {
            Ok(c) => c,
            Err(e) => {
                errors.push(format!("link: {}", cli::one_line(&e)));
                self.show_loaded_on_gpu(loaded, gpu_scene, name);
                return self.apply_view(&link, errors);
            }
        };
        let settled = cli::apply_flags(&c.scene, &mut loaded.scene).and_then(|()| c.mode.settle(&mut loaded, &c.scene));
        self.show_loaded_on_gpu(loaded, gpu_scene, name);
        match settled {
            Ok(settings) => self.settings = settings,
            Err(crate::Failure::Usage(m)) => errors.push(format!("link: {m}")),
            Err(crate::Failure::Run(e)) => errors.push(format!("link: {e:#}")),
        }
        self.set_difference_view(c.difference);
        self.link_file = link.file.clone().map(|f| (f, raw));
        self.apply_view(&link, errors);
    }
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
