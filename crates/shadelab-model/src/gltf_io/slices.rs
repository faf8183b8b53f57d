//! Reading a file in slices: the reader is an `async` function that ends a slice (returns
//! `Pending` once) between its stages, so a caller without threads (the browser) can run it a
//! few slices a frame and keep drawing. Nothing is awaited but those slice ends: the future never
//! waits for anything outside itself, and [`run_to_end`] drives it in one go where a thread or a
//! command line may block.
//!
//! A slice ends before the buffers are decoded, after each material, between the attribute
//! arrays of each primitive (positions, normals, texture coordinates, colours, tangents,
//! indices, triangles, generated tangents) and after each object. One slice is therefore at most
//! one pass over one array of one primitive, or the JSON text's parse (a `.glb`'s JSON is small;
//! a `.gltf` with a large embedded buffer parses its base64 text in one slice).

use super::{Externals, GltfError, LoadedScene};
use std::future::Future;
use std::path::PathBuf;
use std::pin::Pin;
use std::task::{Context, Poll, Waker};

/// Ends the running slice: `Pending` on its first poll, `Ready` on the next.
pub(super) fn slice_end() -> impl Future<Output = ()> {
    let mut ended = false;
    std::future::poll_fn(move |_| {
        if ended {
            Poll::Ready(())
        } else {
            ended = true;
            Poll::Pending
        }
    })
}

/// Run a reader to its end in one go (every slice, one after another).
pub(super) fn run_to_end<T>(f: impl Future<Output = T>) -> T {
    let mut f = std::pin::pin!(f);
    let mut cx = Context::from_waker(Waker::noop());
    loop {
        if let Poll::Ready(v) = f.as_mut().poll(&mut cx) {
            return v;
        }
    }
}

/// Where a sliced read takes its file from: it owns the bytes, so it can live across frames.
pub enum ParseSource {
    /// A file on disk, and whether its URIs may lead outside its folder.
    Path(PathBuf, bool),
    /// Files handed in together, the scene file `main` among them (`load_scene_from_files`).
    Files { main: String, files: Vec<(String, Vec<u8>)> },
}

impl ParseSource {
    /// The name errors and the viewer's panel give it.
    pub fn name(&self) -> String {
        match self {
            ParseSource::Path(p, _) => p.display().to_string(),
            ParseSource::Files { main, .. } => main.clone(),
        }
    }

    /// Files handed in together: the scene file is the first `.glb` or `.gltf` among them.
    pub fn from_files(files: Vec<(String, Vec<u8>)>) -> Result<ParseSource, String> {
        let is_scene = |n: &str| {
            let n = n.to_ascii_lowercase();
            n.ends_with(".gltf") || n.ends_with(".glb")
        };
        match files.iter().find(|(n, _)| is_scene(n)) {
            Some((main, _)) => Ok(ParseSource::Files { main: main.clone(), files }),
            None => {
                let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
                Err(format!("no .gltf or .glb file among the files given: {}", names.join(", ")))
            }
        }
    }
}

/// A scene file being read a slice at a time ([`SceneParse::step`]); the same result as
/// `load_scene_with` or `load_scene_from_files` on the same file.
pub struct SceneParse {
    /// `None` once it has answered.
    future: Option<Pin<Box<dyn Future<Output = Result<LoadedScene, GltfError>> + Send>>>,
    slices: usize,
}

impl SceneParse {
    /// Start reading `source`; nothing is read until the first step.
    pub fn new(source: ParseSource) -> SceneParse {
        let future: Pin<Box<dyn Future<Output = _> + Send>> = match source {
            ParseSource::Path(path, outside) => Box::pin(async move {
                let (bytes, file) = super::scene_file::read_file(&path)?;
                let dir = path.parent().unwrap_or(std::path::Path::new("."));
                let externals = if outside { Externals::Anywhere(dir) } else { Externals::Dir(dir) };
                super::scene_file::parse(&bytes, &file, externals).await
            }),
            ParseSource::Files { main, files } => Box::pin(async move {
                let bytes = super::scene_file::main_file(&main, &files)?;
                super::scene_file::parse(bytes, &main, Externals::Files(&files)).await
            }),
        };
        SceneParse { future: Some(future), slices: 0 }
    }

    /// Run one slice; the scene (or the file's error) once the last has run, and `None` from
    /// every step after that.
    pub fn step(&mut self) -> Option<Result<LoadedScene, GltfError>> {
        let future = self.future.as_mut()?;
        self.slices += 1;
        match future.as_mut().poll(&mut Context::from_waker(Waker::noop())) {
            Poll::Ready(r) => {
                self.future = None;
                Some(r)
            }
            Poll::Pending => None,
        }
    }

    /// Slices run so far.
    pub fn slices(&self) -> usize {
        self.slices
    }
}
