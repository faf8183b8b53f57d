// The web build in headless Chromium (WebGPU on SwiftShader), driven through Playwright, held to
// the native renderer on lavapipe. `cargo xtask test` runs it after building and serving the site:
//   node tests/web/browser_tests.mjs
// with SHADELAB_URL (the served site), SHADELAB_BIN (the native binary), PLAYWRIGHT (the folder
// holding node_modules/playwright-core), SHADELAB_ROOT, SHADELAB_SITE (the served folder, where a
// test puts a model for a link to name) and SHADELAB_OUT (where images go).
// It prints cargo's "test … ok" lines and one "test result:" line, which xtask counts.

import { env, launch } from "./browser.mjs";
import { execFileSync } from "child_process";
import fs from "fs";
import path from "path";

const URL_BASE = env("SHADELAB_URL");
const BIN = env("SHADELAB_BIN");
const ROOT = env("SHADELAB_ROOT");
const OUT = env("SHADELAB_OUT");
const SITE = env("SHADELAB_SITE");
const SAMPLES = path.join(ROOT, "../shared/gltf-samples");

// The web page against the native render of the same view: FLIP mean at most this. Measured at
// 940×520: 0.0047 on the default scene, 0.0061 on BoxTextured, nearly all of it the lights'
// markers the page draws over the view (a render has none) and a few edge pixels SwiftShader and
// llvmpipe rasterize differently. The nearest wrong picture, Gouraud for Phong shading, gives
// 0.056; the diffuse term alone for the whole model 0.139.
const MAX_FLIP_AGAINST_NATIVE = 0.02;
// The view (the page less the panel, 940×520) is wider than 16:9, so the viewer draws the scene's
// camera as it is, as `shadelab render` does (narrower views widen the field of view to keep the
// scene's width: `Camera::fitted`).
const VIEWPORT = { width: 1280, height: 520 };
// Waits, in seconds: the page's start (wasm compile on two cores), and the f64 reference traced a
// few rows a frame on the page's one thread.
const START_S = 120;
const REFERENCE_S = 300;

fs.mkdirSync(OUT, { recursive: true });
const browser = await launch();

function check(cond, what) {
  if (!cond) throw new Error(what);
}

const state = (page) => page.evaluate(() => window.shadelabState || null);

async function waitFor(page, what, pred, seconds) {
  const end = Date.now() + seconds * 1000;
  let last = null;
  while (Date.now() < end) {
    const status = await page.evaluate(() => window.shadelabStatus);
    check(status !== "failed" && status !== "no-webgpu", `the page did not start: ${status}`);
    last = await state(page);
    if (last && pred(last)) return last;
    await page.waitForTimeout(200);
  }
  throw new Error(`timed out waiting for ${what}; last state: ${JSON.stringify(last)?.slice(0, 600)}`);
}

// A page on `query`, its console errors collected, started and drawn.
async function open(query = "") {
  const page = await browser.newPage({ viewport: VIEWPORT });
  page.errors = [];
  page.on("console", (m) => m.type() === "error" && page.errors.push(m.text()));
  page.on("pageerror", (e) => page.errors.push(e.message));
  await page.goto(URL_BASE + query);
  await waitFor(page, "the first frames", (s) => s.frames >= 3 && !s.loading, START_S);
  return page;
}

// Two more frames drawn: the picture on screen is the state's. egui draws on input, so the pointer
// moves over an empty spot of the panel's foot to ask for them.
async function settle(page) {
  for (const dx of [0, 1]) {
    const f = (await state(page)).frames;
    await page.mouse.move(VIEWPORT.width - 4 - dx, VIEWPORT.height - 4);
    await waitFor(page, "another frame", (s) => s.frames > f, 30);
  }
  await page.waitForTimeout(100);
  return state(page);
}

async function click(page, mark) {
  const s = await state(page);
  const r = s.marks[mark];
  check(r, `no switch '${mark}' on the panel (marks: ${Object.keys(s.marks).join(", ")})`);
  await page.mouse.click(r[0] + r[2] / 2, r[1] + r[3] / 2);
}

// The view's pixels as a PNG.
async function shootView(page, name) {
  const s = await settle(page);
  const [x, y, w, h] = s.view.map(Math.round);
  const file = path.join(OUT, `${name}.png`);
  await page.screenshot({ path: file, clip: { x, y, width: w, height: h } });
  return { file, w, h };
}

function nativeRender(name, w, h, args) {
  const file = path.join(OUT, `${name}-native.png`);
  execFileSync(BIN, ["render", "--width", String(w), "--height", String(h), "--output", file, ...args]);
  return file;
}

// FLIP mean and the rest of `shadelab compare`'s line, reference first.
function compare(reference, test, name) {
  const map = path.join(OUT, `${name}-flip.png`);
  const line = execFileSync(BIN, ["compare", reference, test, "--map", map]).toString().trim();
  return { flip: parseFloat(line.split(" ")[2]), line };
}

async function matchesNative(page, name, args) {
  const shot = await shootView(page, name);
  const native = nativeRender(name, shot.w, shot.h, args);
  const c = compare(native, shot.file, name);
  console.log(`    ${name}: against the native render (${args.join(" ") || "defaults"}): ${c.line}`);
  check(c.flip <= MAX_FLIP_AGAINST_NATIVE, `${name}: FLIP ${c.flip} against native is above ${MAX_FLIP_AGAINST_NATIVE}`);
  return c.flip;
}

function noConsoleErrors(page) {
  check(page.errors.length === 0, `console errors: ${page.errors.join(" | ")}`);
}

// A height field of n×n vertices as one indexed `.glb` primitive (positions and normals as
// FLOAT, u32 indices), as a scanner writes a mesh: n = 470 is 10.6 MB.
function gridGlb(n) {
  const verts = n * n, tris = 2 * (n - 1) * (n - 1);
  const bin = Buffer.alloc(verts * 24 + tris * 12);
  const y = (x, z) => 0.15 * Math.sin(3 * x) * Math.cos(3 * z);
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      const [x, z] = [-1 + (2 * j) / (n - 1), -1 + (2 * i) / (n - 1)];
      const [dx, dz] = [0.45 * Math.cos(3 * x) * Math.cos(3 * z), -0.45 * Math.sin(3 * x) * Math.sin(3 * z)];
      const len = Math.hypot(dx, 1, dz);
      const k = i * n + j;
      [x, y(x, z), z].forEach((v, c) => bin.writeFloatLE(v, 12 * k + 4 * c));
      [-dx / len, 1 / len, -dz / len].forEach((v, c) => bin.writeFloatLE(v, verts * 12 + 12 * k + 4 * c));
    }
  }
  let at = verts * 24;
  for (let i = 0; i + 1 < n; i++) {
    for (let j = 0; j + 1 < n; j++) {
      const a = i * n + j;
      for (const v of [a, a + n, a + 1, a + 1, a + n, a + n + 1]) at = bin.writeUInt32LE(v, at);
    }
  }
  const gltf = {
    asset: { version: "2.0" },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0 }],
    meshes: [{ name: "grid", primitives: [{ attributes: { POSITION: 0, NORMAL: 1 }, indices: 2 }] }],
    buffers: [{ byteLength: bin.length }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: verts * 12 },
      { buffer: 0, byteOffset: verts * 12, byteLength: verts * 12 },
      { buffer: 0, byteOffset: verts * 24, byteLength: tris * 12 },
    ],
    accessors: [
      { bufferView: 0, componentType: 5126, count: verts, type: "VEC3", min: [-1, -0.15, -1], max: [1, 0.15, 1] },
      { bufferView: 1, componentType: 5126, count: verts, type: "VEC3" },
      { bufferView: 2, componentType: 5125, count: 3 * tris, type: "SCALAR" },
    ],
  };
  let json = Buffer.from(JSON.stringify(gltf));
  json = Buffer.concat([json, Buffer.alloc((4 - (json.length % 4)) % 4, 0x20)]);
  const header = Buffer.alloc(12);
  header.write("glTF", 0);
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + json.length + 8 + bin.length, 8);
  const chunk = (len, kind) => {
    const c = Buffer.alloc(8);
    c.writeUInt32LE(len, 0);
    c.write(kind, 4, "latin1");
    return c;
  };
  return Buffer.concat([header, chunk(json.length, "JSON"), json, chunk(bin.length, "BIN\0"), bin]);
}

// A link to a model on the site opens it (named `scene`), copy link writes the same query, and
// the page's picture is `render --link`'s in the site's folder within the native bound. Returns
// the page's state.
async function linkedModelMatchesRender(query, scene, name) {
  const page = await open(query);
  let s = await waitFor(page, `the linked ${scene}`, (s) => s.scene === scene && !s.loading, 60);
  check(!s.message_is_error, `message: ${s.message}`);
  await click(page, "copy link");
  s = await waitFor(page, "the copied link", (s) => s.link !== null, 30);
  check(s.link.endsWith(query), `the copied link ${s.link} is not the one opened, ${query}`);
  const shot = await shootView(page, name);
  const native = path.join(OUT, `${name}-native.png`);
  execFileSync(BIN, ["render", "--width", String(shot.w), "--height", String(shot.h), "--output", native,
    "--link", query], { cwd: SITE });
  const c = compare(native, shot.file, name);
  console.log(`    ${name}: against render --link in the site's folder: ${c.line}`);
  check(c.flip <= MAX_FLIP_AGAINST_NATIVE, `${name}: FLIP ${c.flip} against native is above ${MAX_FLIP_AGAINST_NATIVE}`);
  noConsoleErrors(page);
  await page.close();
  return s;
}

const tests = {
  async the_adapter_is_webgpu() {
    const page = await open();
    const s = await state(page);
    check(s.adapter.startsWith("BrowserWebGpu"), `adapter: ${s.adapter}`);
    noConsoleErrors(page);
    await page.close();
  },

  async the_default_scene_matches_the_native_render() {
    const page = await open();
    await matchesNative(page, "default", []);
    noConsoleErrors(page);
    await page.close();
  },

  async clicks_on_shading_model_and_term_change_the_picture_as_on_the_desktop() {
    const page = await open();
    const before = await shootView(page, "click-before");
    await click(page, "shading:gouraud");
    await waitFor(page, "Gouraud shading", (s) => s.shading === "gouraud", 30);
    const gouraud = await matchesNative(page, "click-gouraud", ["--shading", "gouraud"]);
    check(compare(before.file, path.join(OUT, "click-gouraud.png"), "click-changed").flip > gouraud,
      "the picture after the click is closer to the native Gouraud render than to the one before");
    await click(page, "term:diffuse");
    await waitFor(page, "the diffuse term", (s) => s.term === "diffuse", 30);
    const diffuse = await matchesNative(page, "click-diffuse", ["--shading", "gouraud", "--term", "diffuse"]);
    check(compare(path.join(OUT, "click-gouraud.png"), path.join(OUT, "click-diffuse.png"), "click-term").flip > diffuse,
      "the term click changed the picture towards the native diffuse term");
    await click(page, "model");
    await settle(page);
    await click(page, "model:lambert");
    await waitFor(page, "the Lambert rule", (s) => s.model === "lambert", 30);
    await matchesNative(page, "click-lambert", ["--shading", "gouraud", "--model", "lambert", "--term", "diffuse"]);
    noConsoleErrors(page);
    await page.close();
  },

  async a_textured_file_through_the_file_input_shows_its_texture() {
    const file = path.join(SAMPLES, "BoxTextured.gltf");
    const page = await open();
    await page.setInputFiles("#shadelab-file-input", file);
    const s = await waitFor(page, "BoxTextured opened", (s) => s.scene === "BoxTextured.gltf" && !s.loading, 60);
    check(s.textures === 1 && !s.message_is_error, `textures ${s.textures}, message ${s.message}`);
    // The file has no camera: the scene as shown, saved by the page's "save as…" (a download),
    // is what the native render draws.
    const download = page.waitForEvent("download");
    await click(page, "save");
    const saved = path.join(OUT, "textured-saved.glb");
    await (await download).saveAs(saved);
    await matchesNative(page, "textured", ["--scene", saved]);
    noConsoleErrors(page);
    await page.close();
  },

  async files_dropped_on_the_page_open_together() {
    // A .gltf with its buffer in a file of its own, dropped with it: the page matches them by name.
    const gltf = JSON.parse(fs.readFileSync(path.join(SAMPLES, "BoxTextured.gltf"), "utf8"));
    const bin = Buffer.from(gltf.buffers[0].uri.split(",")[1], "base64");
    gltf.buffers[0].uri = "box.bin";
    const files = [
      { name: "dropped.gltf", b64: Buffer.from(JSON.stringify(gltf)).toString("base64") },
      { name: "box.bin", b64: bin.toString("base64") },
    ];
    const page = await open();
    const data = await page.evaluateHandle((files) => {
      const dt = new DataTransfer();
      for (const f of files) {
        dt.items.add(new File([Uint8Array.from(atob(f.b64), (c) => c.charCodeAt(0))], f.name));
      }
      return dt;
    }, files);
    for (const type of ["dragenter", "dragover", "drop"]) {
      await page.dispatchEvent("#shadelab", type, { dataTransfer: data });
    }
    const s = await waitFor(page, "the dropped scene", (s) => s.scene === "dropped.gltf" && !s.loading, 60);
    check(s.textures === 1 && !s.message_is_error, `textures ${s.textures}, message ${s.message}`);
    noConsoleErrors(page);
    await page.close();
  },

  async a_hostile_file_is_one_line_and_the_next_file_opens() {
    const page = await open();
    await page.setInputFiles("#shadelab-file-input", path.join(ROOT, "tests/gltf-corpus/index-past-vertex-count.gltf"));
    const bad = await waitFor(page, "the error", (s) => s.message_is_error && !s.loading, 60);
    check(bad.message.includes("index-past-vertex-count.gltf") && !bad.message.includes("\n"), `message: ${bad.message}`);
    check(bad.scene === "default", `the scene on show stays: ${bad.scene}`);
    await page.setInputFiles("#shadelab-file-input", path.join(ROOT, "assets/material-board.gltf"));
    const good = await waitFor(page, "the next file", (s) => s.scene === "material-board.gltf" && !s.loading, 60);
    check(!good.message_is_error, `message: ${good.message}`);
    noConsoleErrors(page);
    await page.close();
  },

  async the_difference_view_completes_with_its_numbers() {
    const page = await open();
    await click(page, "difference");
    const t0 = Date.now();
    const s = await waitFor(page, "the difference numbers", (s) => s.difference !== null, REFERENCE_S);
    const d = s.difference;
    console.log(`    difference view after ${((Date.now() - t0) / 1000).toFixed(1)} s: ${JSON.stringify(d)}`);
    check(d.flip_mean > 0 && d.flip_mean < 0.2 && d.rmse > 0 && d.rmse < 0.1, `numbers: ${JSON.stringify(d)}`);
    // The same comparison natively: the page's and lavapipe's errors against the same reference.
    const [, , w, h] = s.view.map(Math.round);
    const dw = Math.min(w, 480), dh = Math.round((h * dw) / w);
    const out = execFileSync(BIN, ["render", "--difference", "--width", String(dw), "--height", String(dh),
      "--output", path.join(OUT, "difference-native.png")]).toString();
    const native = parseFloat(out.match(/mean FLIP ([0-9.]+)/)[1]);
    console.log(`    native mean FLIP at ${dw}×${dh}: ${native}`);
    check(Math.abs(native - d.flip_mean) < 0.01, `page ${d.flip_mean} against native ${native}`);
    noConsoleErrors(page);
    await page.close();
  },

  async a_link_opens_its_state_and_names_a_bad_parameter() {
    let page = await open("?scene=glass&shading=gouraud&term=diffuse&boundary=on");
    let s = await state(page);
    check(s.scene === "glass" && s.shading === "gouraud" && s.term === "diffuse", `state: ${JSON.stringify(s).slice(0, 300)}`);
    check(!s.message_is_error, `message: ${s.message}`);
    await click(page, "copy link");
    s = await waitFor(page, "the copied link", (s) => s.link !== null, 30);
    check(s.link.includes("scene=glass") && s.link.includes("shading=gouraud") && s.link.includes("term=diffuse")
      && s.link.includes("boundary=on"), `link: ${s.link}`);
    noConsoleErrors(page);
    await page.close();
    page = await open("?shading=toon&scene=glass&m=-1");
    s = await state(page);
    check(s.scene === "glass", `the good parameters still apply: ${s.scene}`);
    check(s.message_is_error && s.message.includes("shading=toon") && s.message.includes("[0, 1]"), `message: ${s.message}`);
    noConsoleErrors(page);
    await page.close();
  },

  // A view with edited materials, lights, camera and environment: the page opens it, writes the
  // same link back (every float to the bit) and draws what `render --link` draws natively.
  async a_link_carries_materials_lights_camera_and_environment() {
    const query = "?scene=default&shading=phong&model=cook-torrance"
      + "&orbit=0,0.35,-0.4,-0.36,0.3028848683749714,5.867069114984074&Ia=0,0,0"
      + "&mat0.m=0.123456789&mat1.mu=0.9,0.5,0.25&lights=3&light0.I=0.7&light1.filter=pcss"
      + "&light2.pos=-2,3,1&light2.C=0.2,0.4,1&light2.I=0.8&light2.alpha=0.1&env=sky&env.T=4";
    const page = await open(query);
    let s = await state(page);
    check(!s.message_is_error, `message: ${s.message}`);
    await click(page, "copy link");
    s = await waitFor(page, "the copied link", (s) => s.link !== null, 30);
    check(s.link.endsWith(query), `the copied link ${s.link} is not the one opened, ${query}`);
    await settle(page);
    await matchesNative(page, "link-edited", ["--link", query]);
    noConsoleErrors(page);
    await page.close();
  },

  // A model on the site opens from a link (`?file=`), the buffer its .gltf names fetched beside
  // it, with the link's edits over it, through the camera the link picks; copy link names it
  // again; another origin is refused.
  async a_link_opens_a_model_on_the_site() {
    // On the site as `cargo xtask web --with` puts it: BoxTextured with its buffer in a file.
    const gltf = JSON.parse(fs.readFileSync(path.join(SAMPLES, "BoxTextured.gltf"), "utf8"));
    fs.mkdirSync(path.join(SITE, "models"), { recursive: true });
    fs.writeFileSync(path.join(SITE, "models/box.bin"), Buffer.from(gltf.buffers[0].uri.split(",")[1], "base64"));
    gltf.buffers[0].uri = "box.bin";
    fs.writeFileSync(path.join(SITE, "models/box.gltf"), JSON.stringify(gltf));
    const query = "?file=models/box.gltf&shading=phong&model=cook-torrance&mat0.r_s=0.7&mat0.m=0.3";
    let s = await linkedModelMatchesRender(query, "box.gltf", "link-file");
    check(s.textures === 1, `textures ${s.textures}`);
    // A file's second camera travels as camera=1: the page looks through it as render does.
    gltf.cameras = [0.8, 0.4].map((yfov) => ({ type: "perspective", perspective: { yfov, znear: 0.1, zfar: 100 } }));
    gltf.nodes.push({ camera: 0, translation: [0, 0, 4] }, { camera: 1, translation: [0.4, 0.3, 4] });
    gltf.scenes[0].nodes.push(gltf.nodes.length - 2, gltf.nodes.length - 1);
    fs.writeFileSync(path.join(SITE, "models/two-cameras.gltf"), JSON.stringify(gltf));
    const cameraQuery = "?file=models/two-cameras.gltf&shading=phong&model=cook-torrance&camera=1";
    await linkedModelMatchesRender(cameraQuery, "two-cameras.gltf", "link-camera");
    const page = await open("?file=https://example.org/duck.glb&shading=gouraud");
    s = await state(page);
    check(s.scene === "default" && s.shading === "gouraud", `the rest of the link applies: ${s.scene}, ${s.shading}`);
    check(s.message_is_error && s.message.includes("file=https://example.org/duck.glb") && s.message.includes("refused"),
      `message: ${s.message}`);
    await page.close();
  },

  // A 10 MB file parses in slices between frames: the viewer counts the frames it drew while
  // the parse ran (a parse in one frame draws none), and the model opens. On SwiftShader a frame
  // takes hundreds of ms, so each frame's share of the parse is near its 250 ms most, and the
  // parse (about 170 ms of slices) may end in the frame after its first: how many frames it
  // spans depends on the machine's frame time, not on the code.
  async a_ten_megabyte_file_parses_while_frames_keep_coming() {
    fs.mkdirSync(path.join(SITE, "models"), { recursive: true });
    const file = path.join(SITE, "models/grid.glb");
    fs.writeFileSync(file, gridGlb(470));
    const mb = fs.statSync(file).size / 1e6;
    check(mb >= 10, `grid.glb is ${mb} MB`);
    const page = await open("?file=models/grid.glb");
    const s = await waitFor(page, "the 10 MB model", (s) => s.scene === "grid.glb" && !s.loading, 300);
    check(!s.message_is_error, `message: ${s.message}`);
    const l = s.last_load;
    console.log(`    grid.glb, ${mb.toFixed(1)} MB: parsed in ${l.parse_ms.toFixed(0)} ms, ${l.slices} slices, `
      + `${l.frames_during_parse} frames drawn meanwhile, a frame held at most ${l.longest_hold_ms.toFixed(0)} ms; `
      + `uploaded in ${l.upload_ms.toFixed(0)} ms`);
    // The frame that ends the parse is not counted: a parse in one frame counts none.
    check(l.frames_during_parse >= 1, `no frame drawn during the parse`);
    check(l.slices >= 12, `${l.slices} slices`);
    await shootView(page, "grid-10mb");
    noConsoleErrors(page);
    await page.close();
  },

  // The lights' shadow-map views read back on the page without a wait: a link ticks L1's and
  // L2's boxes, both maps arrive (the sun's cascade, the point light's cube face), and copy link
  // keeps them.
  async the_shadow_map_views_read_back_on_the_page() {
    const page = await open("?scene=default&shadow-maps=0,1");
    let s = await waitFor(page, "both maps", (s) => s.shadow_maps[0] !== null && s.shadow_maps[1] !== null, 60);
    for (const [w, h] of s.shadow_maps) {
      check(w === h && w >= 256 && (w & (w - 1)) === 0, `a map of ${w}×${h}`);
    }
    check(!s.message_is_error, `message: ${s.message}`);
    await click(page, "copy link");
    s = await waitFor(page, "the copied link", (s) => s.link !== null, 30);
    check(s.link.includes("shadow-maps=0,1"), `link: ${s.link}`);
    noConsoleErrors(page);
    await page.close();
  },

  // The FLIP map against the path-traced truth at the link's vertices and paths: a coarse map
  // first, then the full one with its numbers; copy link writes the same query.
  async the_difference_view_compares_with_the_path_traced_truth() {
    const query = "?scene=default&shading=phong&model=cook-torrance&difference=on&reference=truth&bounces=2&spp=1";
    const page = await open(query);
    const t0 = Date.now();
    let s = await waitFor(page, "the coarse map", (s) => s.coarse_map, 90);
    check(s.truth[0] === 2 && s.truth[1] === 1, `truth: ${s.truth}`);
    s = await waitFor(page, "the full map", (s) => s.difference !== null, REFERENCE_S);
    console.log(`    against the truth (2 vertices, 1 path): the full map after ${((Date.now() - t0) / 1000).toFixed(1)} s, `
      + `RMSE ${s.difference.rmse.toExponential(3)}, reference ${s.reference_size}`);
    check(s.difference.rmse > 0 && s.reference_size[0] > 120, `state: ${JSON.stringify(s).slice(0, 300)}`);
    await page.screenshot({ path: path.join(OUT, "difference-truth-page.png") });
    await click(page, "copy link");
    s = await waitFor(page, "the copied link", (s) => s.link !== null, 30);
    check(s.link.endsWith(query), `the copied link ${s.link} is not the one opened, ${query}`);
    noConsoleErrors(page);
    await page.close();
  },

  // The ambient error map on the page comes coarse first (a quarter of the side, a sixteenth of
  // the full map's paths), within seconds, while the full map is traced behind it.
  async the_ambient_error_map_shows_a_coarse_map_first() {
    const page = await open("?scene=default&difference=on&error-map=ambient");
    const t0 = Date.now();
    const s = await waitFor(page, "the coarse ambient map", (s) => s.coarse_map, 90);
    console.log(`    the coarse map after ${((Date.now() - t0) / 1000).toFixed(1)} s, reference ${s.reference_size}`);
    const [w, h] = s.reference_size;
    check(w <= 120 && h >= 1, `state: ${JSON.stringify(s).slice(0, 300)}`);
    await waitFor(page, "the full map traced behind the coarse one", (s) => s.coarse_map && s.computing_reference, 30);
    await shootView(page, "ambient-coarse");
    noConsoleErrors(page);
    await page.close();
  },
};

let passed = 0, failed = 0;
const only = process.argv[2];
for (const [name, run] of Object.entries(tests)) {
  if (only && !name.includes(only)) continue;
  const t0 = Date.now();
  try {
    await run();
    passed++;
    console.log(`test web::${name} ... ok (${((Date.now() - t0) / 1000).toFixed(1)} s)`);
  } catch (e) {
    failed++;
    console.log(`test web::${name} ... FAILED\n    ${e.message}`);
  }
}
await browser.close();
console.log(`test result: ${failed ? "FAILED" : "ok"}. ${passed} passed; ${failed} failed`);
process.exit(failed ? 1 : 0);
