// What the web build costs, measured in headless Chromium (WebGPU on SwiftShader) beside the
// native viewer on lavapipe: `cargo xtask web --bench` runs it with the same variables as
// browser_tests.mjs and prints a Markdown table. Medians of RUNS page loads, and of the frame
// intervals over FRAME_SECONDS of continuous rendering.

import { env, launch } from "./browser.mjs";
import { execFileSync } from "child_process";
import fs from "fs";
import path from "path";
import zlib from "zlib";

const URL_BASE = env("SHADELAB_URL");
const BIN = env("SHADELAB_BIN");
const SITE = env("SHADELAB_SITE");
const OUT = env("SHADELAB_OUT");
// The native viewer's default window, so both draw a view of the same size.
const VIEWPORT = { width: 1280, height: 760 };
const RUNS = 5;
const FRAME_SECONDS = 10;

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
fs.mkdirSync(OUT, { recursive: true });

const wasm = fs.readFileSync(path.join(SITE, "shadelab_web_bg.wasm"));
const js = fs.readFileSync(path.join(SITE, "shadelab_web.js"));
const gz = (b) => zlib.gzipSync(b, { level: 9 }).length;

const browser = await launch();
const version = browser.version();

async function waitFor(page, pred, seconds) {
  const end = Date.now() + seconds * 1000;
  while (Date.now() < end) {
    const s = await page.evaluate(() => window.shadelabState || null);
    if (s && pred(s)) return s;
    await page.waitForTimeout(20);
  }
  throw new Error("timed out");
}

// Opening the page to its first frame: from navigation to the first published state, fresh
// browser context each time (no cached compile).
const firstFrame = [];
for (let i = 0; i < RUNS; i++) {
  const context = await browser.newContext({ viewport: VIEWPORT });
  const page = await context.newPage();
  const t0 = Date.now();
  await page.goto(URL_BASE);
  await waitFor(page, (s) => s.frames >= 1, 120);
  firstFrame.push(Date.now() - t0);
  await context.close();
}

// Frame intervals and scene passes with continuous rendering, from the page's own clock.
const page = await browser.newPage({ viewport: VIEWPORT });
await page.goto(URL_BASE + "?continuous=on");
await waitFor(page, (s) => s.frames >= 10, 120);
const frames = await page.evaluate((seconds) => new Promise((done) => {
  const out = [];
  let last = window.shadelabState.frames, lastT = performance.now();
  const end = lastT + seconds * 1000;
  const tick = (t) => {
    const s = window.shadelabState;
    if (s.frames !== last) {
      out.push({ dt: (t - lastT) / (s.frames - last), pass: s.scene_pass_ms });
      last = s.frames;
      lastT = t;
    }
    if (t < end) requestAnimationFrame(tick); else done(out);
  };
  requestAnimationFrame(tick);
}), FRAME_SECONDS);
const webFrame = median(frames.map((f) => f.dt));
const webPass = median(frames.map((f) => f.pass).filter((p) => p !== null));
const view = (await page.evaluate(() => window.shadelabState)).view;

// The f64 reference of the difference view, traced on the page's thread, against the same size
// natively (one thread both). A view wider than 16:9 keeps the scene's camera as `render` has it,
// so both trace the same pixels.
await page.setViewportSize({ width: 1280, height: 520 });
await page.goto(URL_BASE + "?difference=on");
const ref = await waitFor(page, (s) => s.reference_ms !== null && s.difference !== null, 600);
const [rw, rh] = ref.reference_size;
await browser.close();
const nativeRef = [];
for (let i = 0; i < 3; i++) {
  // One thread, as the page has: the native reference otherwise takes every core.
  const out = execFileSync(BIN, ["render", "--reference", "--width", String(rw), "--height", String(rh),
    "--output", path.join(OUT, "bench-reference.png")], { env: { ...process.env, RAYON_NUM_THREADS: "1" } }).toString();
  nativeRef.push(parseFloat(out.match(/in ([0-9.]+) ms/)[1]));
}

const ms = (x) => x.toFixed(1);
console.log(`Chromium ${version} (WebGPU on SwiftShader) against the native viewer (lavapipe)`);
console.log(`| measure | web | native | web / native |`);
console.log(`|---|---:|---:|---:|`);
console.log(`| wasm size | ${(wasm.length / 1e6).toFixed(2)} MB raw, ${(gz(wasm) / 1e6).toFixed(2)} MB gzipped | | |`);
console.log(`| JS glue | ${(js.length / 1e3).toFixed(0)} kB raw, ${(gz(js) / 1e3).toFixed(0)} kB gzipped | | |`);
console.log(`| opening the page to its first frame (median of ${RUNS}) | ${ms(median(firstFrame))} ms | | |`);
const native = process.env.NATIVE_VIEWER ? JSON.parse(process.env.NATIVE_VIEWER) : null;
const cell = (w, n) => (n ? `| ${ms(w)} ms | ${ms(n)} ms | ${(w / n).toFixed(2)} |` : `| ${ms(w)} ms | | |`);
console.log(`| frame interval, default scene, view ${Math.round(view[2])}×${Math.round(view[3])} (median of ${frames.length}) ${cell(webFrame, native?.frame)}`);
console.log(`| scene pass (GPU timestamps) ${cell(webPass, native?.pass)}`);
console.log(`| f64 reference ${rw}×${rh}, one thread | ${ms(ref.reference_ms)} ms | ${ms(median(nativeRef))} ms | ${(ref.reference_ms / median(nativeRef)).toFixed(2)} |`);
console.log(JSON.stringify({ firstFrame, webFrame, webPass, view, reference: { web: ref.reference_ms, native: nativeRef, size: [rw, rh] } }));
