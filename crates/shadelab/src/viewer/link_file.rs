//! A link's model on the page's own site (`?file=models/duck.glb`): the page's fetch of the file
//! with the buffers and images a `.gltf` names, and the rest of the link
//! applied once the file has opened (the path's rule is `site_path.rs`). On the desktop the same
//! path is the link's `--scene`. `cargo xtask web --with FILE` puts models on the site.

use super::Viewer;
use super::link::Link;
use crate::cli;
use shadelab_model::gltf_io::LoadedScene;
use shadelab_render::SceneGpu;

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

    /// The file a link fetched has opened: its camera, flags and modes as the command line would
    /// apply them, then the rest of the link; the file's own scene is the base of the next link.
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
        let settled = cli::pick_camera(&c.scene, &mut loaded)
            .and_then(|()| cli::apply_flags(&c.scene, &mut loaded.scene))
            .and_then(|()| c.mode.settle(&mut loaded, &c.scene));
        self.show_loaded_on_gpu(loaded, gpu_scene, name);
        match settled {
            Ok(settings) => self.settings = settings,
            Err(f) => errors.push(format!("link: {}", f.message())),
        }
        self.set_difference_view(c.difference);
        self.link_file = link.file.clone().map(|f| (f, raw));
        self.apply_view(&link, errors);
    }
}
