//! The viewer in a browser page (wasm32 + WebGPU): its start on the page's canvas, the page's
//! file input standing in for the file dialog, files dropped on the page, downloads for "save",
//! and the page's address for links. Everything else is the desktop viewer's code.

use super::{Viewer, link};
use eframe::egui;
use eframe::egui_wgpu;
use std::cell::RefCell;
use std::sync::Arc;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;

/// The id of the page's hidden file input: "open…" clicks it; tests set its files.
pub const FILE_INPUT_ID: &str = "shadelab-file-input";

/// What a picked or dropped file is: its name and bytes.
type Files = Vec<(String, Vec<u8>)>;

thread_local! {
    /// Files read from the input or a drop, waiting for the viewer's next frame.
    static CHOSEN: RefCell<Option<Files>> = const { RefCell::new(None) };
    /// The page's egui context, to draw a frame once files have been read.
    static CONTEXT: RefCell<Option<egui::Context>> = const { RefCell::new(None) };
    /// Why a link's file could not be fetched, waiting for the viewer's next frame.
    static FETCH_ERROR: RefCell<Option<String>> = const { RefCell::new(None) };
}

fn js_error(e: JsValue) -> String {
    e.as_string().or_else(|| js_sys::JSON::stringify(&e).ok().and_then(|s| s.as_string())).unwrap_or_else(|| "?".into())
}

fn window() -> Result<web_sys::Window, JsValue> {
    web_sys::window().ok_or_else(|| JsValue::from_str("no window"))
}

/// Start the viewer on `canvas`, in the view the page's address describes. Fails (and the page
/// says why) where the browser gives no WebGPU adapter.
pub async fn start(canvas: web_sys::HtmlCanvasElement) -> Result<(), JsValue> {
    let _ = eframe::WebLogger::init(log::LevelFilter::Warn);
    install_file_input()?;
    let query = window()?.location().search()?;
    let link = link::parse_query(&query);
    let mut wgpu_options = egui_wgpu::WgpuConfiguration::default();
    if let egui_wgpu::WgpuSetup::CreateNew(create) = &mut wgpu_options.wgpu_setup {
        // WebGPU only: the renderer needs storage buffers and compute passes, which WebGL lacks.
        create.instance_descriptor.backends = wgpu::Backends::BROWSER_WEBGPU;
        create.device_descriptor = Arc::new(|adapter| wgpu::DeviceDescriptor {
            label: Some("shadelab web viewer"),
            required_features: shadelab_render::gpu::wanted_features(adapter),
            required_limits: adapter.limits(),
            ..Default::default()
        });
    }
    let options = eframe::WebOptions { wgpu_options, ..Default::default() };
    eframe::WebRunner::new()
        .start(
            canvas,
            options,
            Box::new(move |cc| {
                CONTEXT.with(|c| *c.borrow_mut() = Some(cc.egui_ctx.clone()));
                let mut viewer = Viewer::new(cc, None, None)?;
                viewer.clears_to_panel_fill = true;
                viewer.open_link(&link);
                Ok(Box::new(viewer) as Box<dyn eframe::App>)
            }),
        )
        .await
}

/// Files read since the last frame, if any.
pub fn take_chosen_files() -> Option<Files> {
    CHOSEN.with(|c| c.borrow_mut().take())
}

fn deliver(files: Files) {
    CHOSEN.with(|c| *c.borrow_mut() = Some(files));
    CONTEXT.with(|c| c.borrow().as_ref().map(|ctx| ctx.request_repaint()));
}

/// Why the last link's file could not be fetched, if it could not.
pub fn take_fetch_error() -> Option<String> {
    FETCH_ERROR.with(|c| c.borrow_mut().take())
}

/// `url` (relative to the page) as bytes; an error names it and the HTTP status.
async fn fetch_bytes(url: &str) -> Result<Vec<u8>, String> {
    let promise = window().map_err(js_error)?.fetch_with_str(url);
    let response: web_sys::Response = JsFuture::from(promise).await.map_err(js_error)?.dyn_into().map_err(js_error)?;
    if !response.ok() {
        return Err(format!("{url}: HTTP {}", response.status()));
    }
    let buffer = JsFuture::from(response.array_buffer().map_err(js_error)?).await.map_err(js_error)?;
    Ok(js_sys::Uint8Array::new(&buffer).to_vec())
}

/// The files a `.gltf` names besides itself (its buffers' and images' URIs; data URIs are inside).
fn external_uris(json: &[u8]) -> Result<Vec<String>, String> {
    let v: serde_json::Value = serde_json::from_slice(json).map_err(|e| format!("not a glTF JSON file: {e}"))?;
    let mut uris = Vec::new();
    for key in ["buffers", "images"] {
        for item in v.get(key).and_then(|a| a.as_array()).into_iter().flatten() {
            if let Some(uri) = item.get("uri").and_then(|u| u.as_str())
                && !uri.starts_with("data:")
            {
                uris.push(uri.to_string());
            }
        }
    }
    Ok(uris)
}

/// A link's model from the page's site and, for a `.gltf`, the files it names beside it (each
/// held to the same rule as the link's path), named as the loader looks them up.
async fn fetch_model(file: &str) -> Result<Files, String> {
    let main = fetch_bytes(file).await?;
    let mut files = Vec::new();
    if file.to_ascii_lowercase().ends_with(".gltf") {
        let folder = file.rfind('/').map_or("", |i| &file[..=i]);
        for uri in external_uris(&main)? {
            let decoded = shadelab_model::gltf_io::percent_decode(&uri);
            super::site_path::relative_on_site(&decoded)?;
            let bytes = fetch_bytes(&format!("{folder}{uri}")).await?;
            files.push((decoded.rsplit('/').next().unwrap_or(&decoded).to_string(), bytes));
        }
    }
    files.insert(0, (file.rsplit('/').next().unwrap_or(file).to_string(), main));
    Ok(files)
}

/// Fetch a link's model from the page's site; it opens as picked files do, and a failure is one
/// line in the panel.
pub fn fetch_site_files(file: String) {
    wasm_bindgen_futures::spawn_local(async move {
        match fetch_model(&file).await {
            Ok(files) => deliver(files),
            Err(e) => {
                FETCH_ERROR.with(|c| *c.borrow_mut() = Some(format!("link parameter file={file}: {e}")));
                CONTEXT.with(|c| c.borrow().as_ref().map(|ctx| ctx.request_repaint()));
            }
        }
    });
}

/// Ask for files: the page's file input opens the browser's picker.
pub fn choose_files() {
    let input = window().ok().and_then(|w| w.document()).and_then(|d| d.get_element_by_id(FILE_INPUT_ID));
    if let Some(input) = input.and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok()) {
        input.click();
    }
}

/// The hidden `<input type=file multiple>` whose files open as one scene (a `.gltf` with its
/// `.bin` and images, or a `.glb`), or as the scene's environment (one `.hdr` or `.exr`).
fn install_file_input() -> Result<(), JsValue> {
    let document = window()?.document().ok_or_else(|| JsValue::from_str("no document"))?;
    let input: web_sys::HtmlInputElement = document.create_element("input")?.dyn_into()?;
    input.set_type("file");
    input.set_multiple(true);
    input.set_accept(".gltf,.glb,.bin,.png,.jpg,.jpeg,.hdr,.exr");
    input.set_id(FILE_INPUT_ID);
    input.set_attribute("style", "display:none")?;
    let target = input.clone();
    let on_change = Closure::<dyn FnMut()>::new(move || {
        let Some(list) = target.files() else { return };
        let files: Vec<web_sys::File> = (0..list.length()).filter_map(|i| list.get(i)).collect();
        // The same file chosen again must fire another change.
        target.set_value("");
        wasm_bindgen_futures::spawn_local(async move {
            let mut read = Vec::with_capacity(files.len());
            for f in files {
                match JsFuture::from(f.array_buffer()).await {
                    Ok(buf) => read.push((f.name(), js_sys::Uint8Array::new(&buf).to_vec())),
                    Err(e) => log::error!("reading {}: {}", f.name(), js_error(e)),
                }
            }
            deliver(read);
        });
    });
    input.set_onchange(Some(on_change.as_ref().unchecked_ref()));
    // The input lives as long as the page, and so does its handler.
    on_change.forget();
    document.body().ok_or_else(|| JsValue::from_str("no body"))?.append_child(&input)?;
    Ok(())
}

/// Read files dropped on the page (the browser reads them asynchronously); they open together at
/// the next frame.
pub fn read_dropped(dropped: Vec<egui::DroppedFileHandle>, ctx: egui::Context) {
    wasm_bindgen_futures::spawn_local(async move {
        let mut read = Vec::with_capacity(dropped.len());
        for f in &dropped {
            let name = f.path().to_string_lossy().into_owned();
            match f.bytes_async().await {
                Ok(bytes) => read.push((name, bytes)),
                Err(e) => log::error!("reading {name}: {e}"),
            }
        }
        deliver(read);
        ctx.request_repaint();
    });
}

/// Offer `bytes` as a download named `name`.
pub fn download(name: &str, bytes: &[u8], mime: &str) -> Result<(), String> {
    let run = || -> Result<(), JsValue> {
        let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
        let bag = web_sys::BlobPropertyBag::new();
        bag.set_type(mime);
        let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &bag)?;
        let url = web_sys::Url::create_object_url_with_blob(&blob)?;
        let document = window()?.document().ok_or_else(|| JsValue::from_str("no document"))?;
        let a: web_sys::HtmlAnchorElement = document.create_element("a")?.dyn_into()?;
        a.set_href(&url);
        a.set_download(name);
        a.click();
        web_sys::Url::revoke_object_url(&url)
    };
    run().map_err(js_error)
}

/// The page's address without its query: the base of a link.
pub fn page_address() -> String {
    window().and_then(|w| Ok(format!("{}{}", w.location().origin()?, w.location().pathname()?))).unwrap_or_default()
}

/// Publish the viewer's state to the page as `window.shadelabState` (a JSON object), each frame:
/// what scripts on the page and the browser tests read (the adapter, the modes, the message, the
/// difference numbers, where the view and the main switches are).
pub fn publish_state(v: &Viewer) {
    use serde_json::json;
    let rect = |r: &egui::Rect| json!([r.min.x, r.min.y, r.width(), r.height()]);
    let marks: serde_json::Map<String, serde_json::Value> = v.marks.iter().map(|(k, r)| (k.clone(), rect(r))).collect();
    let difference = v
        .difference
        .stats()
        .map(|s| json!({ "flip_mean": s.flip_mean, "rmse": s.rmse, "max_abs": s.max_abs, "share_off": s.share_off }));
    let model = shadelab_model::ModelChoice::of(v.scene.illumination, v.settings.specular);
    use shadelab_model::params::NamedValue;
    let state = json!({
        "frames": v.frames,
        "adapter": v.adapter,
        "timestamps": v.ring.timed(),
        "scene": v.scene_name,
        "shading": v.settings.shading.name(),
        "specular": v.settings.specular.name(),
        "model": model.name(),
        "term": v.term.name(),
        "textures": v.scene.textures.len(),
        "message": v.message.as_ref().map(|(m, _)| m.clone()),
        "message_is_error": v.message.as_ref().is_some_and(|(_, e)| *e),
        "loading": v.loading.is_some(),
        "last_load": v.last_load.map(|l| json!({
            "parse_ms": l.parse_ms,
            "slices": l.slices,
            "frames_during_parse": l.frames_during_parse,
            "longest_hold_ms": l.longest_hold_ms,
            "upload_ms": l.upload_ms,
        })),
        "difference_on": v.difference.enabled,
        "difference": difference,
        "computing_reference": v.difference.computing(),
        "reference_ms": v.difference.traced_ms,
        "reference_size": v.difference.reference_size().map(|(w, h)| [w, h]),
        "coarse_map": v.difference.coarse_on_show(),
        "truth": v.difference.truth().map(|p| [p.bounces, p.spp]),
        "scene_pass_ms": v.frame_ms,
        "link": v.copied_link.as_ref().map(|(l, _)| l.clone()),
        "shadow_maps": (0..v.scene.lights.len()).map(|i| v.shadow_map_shown(i)).collect::<Vec<_>>(),
        "view": v.view_rect.as_ref().map(rect),
        "marks": marks,
    });
    if let Ok(window) = window()
        && let Ok(value) = js_sys::JSON::parse(&state.to_string())
    {
        let _ = js_sys::Reflect::set(&window, &JsValue::from_str("shadelabState"), &value);
    }
}
