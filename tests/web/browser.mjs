// What the browser scripts share: their environment (set by xtask) and headless Chromium with
// WebGPU on SwiftShader.

import { createRequire } from "module";
import path from "path";

/// A variable xtask sets; its absence means the script was not run through xtask.
export const env = (k) => {
  const v = process.env[k];
  if (!v) throw new Error(`${k} is not set (run through cargo xtask test or cargo xtask web --bench)`);
  return v;
};

// Chromium's WebGPU runs on SwiftShader only when headless; these flags select it (without the
// last three, presenting to a canvas loses the device).
const CHROMIUM_ARGS = [
  "--no-sandbox", "--disable-background-networking", "--disable-component-update", "--disable-sync",
  "--enable-unsafe-webgpu", "--enable-features=Vulkan", "--use-vulkan=swiftshader", "--use-angle=swiftshader",
];

/// Debian's Chromium, driven by the playwright-core xtask installed.
export async function launch() {
  const { chromium } = createRequire(path.join(env("PLAYWRIGHT"), "/"))("playwright-core");
  return chromium.launch({ executablePath: process.env.CHROMIUM || "/usr/bin/chromium", args: CHROMIUM_ARGS });
}
