//! The page's entry point: `index.html` loads this module and calls `start` with its canvas. The
//! viewer itself is `shadelab::viewer`, the same code as the desktop's.

#[cfg(target_arch = "wasm32")]
mod page {
    use wasm_bindgen::JsCast;
    use wasm_bindgen::prelude::*;

    /// Start shadelab on the canvas with this id. The promise rejects with the reason where the
    /// browser gives no WebGPU adapter; the page shows it.
    #[wasm_bindgen]
    pub async fn start(canvas_id: String) -> Result<(), JsValue> {
        let canvas = web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.get_element_by_id(&canvas_id))
            .ok_or_else(|| JsValue::from_str(&format!("no element with id '{canvas_id}'")))?
            .dyn_into::<web_sys::HtmlCanvasElement>()?;
        shadelab::viewer::web::start(canvas).await
    }
}
