// Frame cost of playback in headless Chromium (SwiftShader), as docs/studio.md measures it:
// frames rendered per second (the page's render counter over performance.now()) and the CPU
// time of the browser's processes (/proc/<pid>/stat of its process tree, by process type)
// divided by the frames rendered, for one or more URL variants of a stored motion, run in turn.
//
//   node e2e/tools/frame-cost.mjs --base http://127.0.0.1:8000 --motion <id> \
//     [--seconds 6] [--repeat 3] [--size 1280x720] [--threads] [--css "<extra CSS>"] "?quality=light" "?quality=light&dynres=0"
//
// One JSON line per run: fps (frames rendered), rafFps (refreshes the page got), CPU ms per
// rendered frame in all (gpu + renderer + browser) and per process, the render scale at the end,
// the percentiles of the interval between refreshes (requestAnimationFrame times; 16.7 ms at
// 60 Hz) and `missed`: the share of intervals over 20 ms (a refresh went by without a frame);
// --threads adds the GPU and renderer processes' threads (SwiftShader's workers are Thread<n>).
//
// Needs a running `interplay serve` (the motion must be stored there). Run under the CPU lock.
import { chromium } from "@playwright/test";
import { samplePlayback } from "./playback-sample.mjs";
import { chromiumCpu, perFrame } from "./proc-cpu.mjs";

const args = process.argv.slice(2);
const opt = (name, dflt) => {
  const i = args.indexOf(`--${name}`);
  if (i < 0) return dflt;
  const v = args[i + 1];
  args.splice(i, 2);
  return v;
};
const base = opt("base", "http://127.0.0.1:8000");
const motion = opt("motion", null);
const seconds = Number(opt("seconds", "6"));
const repeat = Number(opt("repeat", "3"));
const [width, height] = opt("size", "1280x720").split("x").map(Number);
const css = opt("css", null); // extra CSS for every variant, e.g. ".legend{display:none}"
const threads = args.includes("--threads") ? (args.splice(args.indexOf("--threads"), 1), true) : false;
const variants = args.length ? args : ["?quality=light"];
if (!motion) throw new Error("--motion <id> is required");

const browser = await chromium.launch({
  executablePath: "/usr/bin/chromium",
  args: [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--enable-precise-memory-info",
  ],
});
const page = await browser.newPage({ viewport: { width, height } });
for (let r = 0; r < repeat; r++) {
  for (const v of variants) {
    await page.goto(`${base}/m/${motion}${v}`);
    await page.waitForFunction(() => window.__interplay?.phase === "done" && window.__interplay.renderCount > 0);
    // the skinned character comes after the motion (its rig, the mesh): measure it, not the mannequin
    if (/[?&]figure=character/.test(v)) await page.waitForFunction(() => window.__interplay.figure?.shown === "character");
    if (css) await page.addStyleTag({ content: css });
    await page.waitForTimeout(1000);
    const c0 = chromiumCpu(process.pid, threads);
    const m = await page.evaluate(samplePlayback, seconds * 1000);
    const c1 = chromiumCpu(process.pid, threads);
    const cpu = perFrame(c0, c1, m.renders);
    const row = {
      variant: v,
      fps: +((m.renders * 1000) / m.dt).toFixed(1),
      rafFps: +((m.raf * 1000) / m.dt).toFixed(1),
      cpuMsPerFrame: cpu.total,
      gpu: cpu.per.gpu ?? 0,
      renderer: cpu.per.renderer ?? 0,
      browser: cpu.per.browser ?? 0,
      scale: m.scale,
      intervalMs: m.intervalMs,
      missed: m.missed,
    };
    if (threads) {
      row.threads = Object.fromEntries(
        Object.entries(cpu.per).filter(([k, ms]) => k.includes(":") && ms >= 0.2).sort((a, b) => b[1] - a[1]),
      );
    }
    console.log(JSON.stringify(row));
  }
}
await browser.close();
