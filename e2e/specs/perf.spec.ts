// Performance on this machine (software WebGL): first paint, playback frame rate of two people
// (light and full quality), JS heap across 20 generations. These MEASURE: the numbers go to
// e2e/test-results/perf.json and the report (docs/studio.md records them); timings are not
// asserted, since a shared CI machine's load decides them. Only behaviour is asserted.
// Playwright's trace recording is off here: its screencast captures every frame the page
// produces, which cost about a third of the light frame rate (41.7 vs 59.6 fps, quiet machine).
// Last recorded (docs/studio.md, 2026-12-02, this spec alone, load 1.8–2.6): light 60.0 fps,
// 12.8 ms CPU per frame, 0 % of refresh intervals over 20 ms; the skinned character
// (`?figure=character`) 60.0 fps, 13.3 ms, 0 %; full 14.0 fps; FCP 440 ms. Whole suite
// (2026-12-01, before the character): 54.5 fps, 8.3 % over 20 ms (load 4.5).
import { expect, test, type Page } from "@playwright/test";
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { loadavg } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { openStudio, startGeneration, waitDone } from "./studio";
import { samplePlayback } from "../tools/playback-sample.mjs";
import { chromiumCpu, perFrame } from "../tools/proc-cpu.mjs";

test.use({ trace: "off" });

// INTERPLAY_PERF_OUT: elsewhere (every Playwright run on this machine empties e2e/test-results/)
const OUT = process.env.INTERPLAY_PERF_OUT ?? join(dirname(fileURLToPath(import.meta.url)), "..", "test-results", "perf.json");
const results: Record<string, unknown> = {};

function save(): void {
  mkdirSync(dirname(OUT), { recursive: true });
  let old: Record<string, unknown> = {};
  try {
    old = JSON.parse(readFileSync(OUT, "utf8"));
  } catch {
    /* first run */
  }
  writeFileSync(OUT, JSON.stringify({ ...old, ...results }, null, 2));
}

interface Playback {
  fps: number;
  frameMs: number;
  /** Refreshes the page got (requestAnimationFrame callbacks) per second. */
  rafFps: number;
  /** CPU ms per rendered frame, all Chromium processes, and the GPU process and renderer's. */
  cpuMsPerFrame: number;
  gpuMsPerFrame: number;
  rendererMsPerFrame: number;
  /** The pixel ratio drawn at when the measurement ended (light: dynamic resolution). */
  renderScale: number;
  /** Percentiles of the interval between refreshes (requestAnimationFrame times), ms. */
  intervalMs: { p50: number; p95: number; p99: number };
  /** Share of those intervals over 20 ms: a 60 Hz refresh went by without a frame. */
  missed: number;
}

/** Frames rendered per second of wall time while playing (performance.now over `ms`), and the
 * browser's CPU time per rendered frame (/proc of the processes this worker launched). */
async function playbackFps(page: Page, ms = 4000): Promise<Playback> {
  const c0 = chromiumCpu();
  const m = await page.evaluate(samplePlayback, ms);
  const cpu = perFrame(c0, chromiumCpu(), m.renders);
  return {
    fps: (m.renders * 1000) / m.dt,
    frameMs: m.dt / Math.max(1, m.renders),
    rafFps: (m.raf * 1000) / m.dt,
    cpuMsPerFrame: cpu.total,
    gpuMsPerFrame: cpu.per.gpu ?? 0,
    rendererMsPerFrame: cpu.per.renderer ?? 0,
    renderScale: m.scale ?? 0,
    intervalMs: m.intervalMs,
    missed: m.missed,
  };
}

test("first paint from the local server is measured", async ({ page }, info) => {
  await page.goto("/");
  await page.waitForFunction(() => performance.getEntriesByName("first-contentful-paint").length > 0);
  const t = await page.evaluate(() => ({
    fcp: performance.getEntriesByName("first-contentful-paint")[0].startTime,
    fp: performance.getEntriesByName("first-paint")[0]?.startTime ?? null,
    domContentLoaded: performance.getEntriesByType("navigation")[0]
      ? (performance.getEntriesByType("navigation")[0] as PerformanceNavigationTiming).domContentLoadedEventEnd
      : null,
  }));
  results.firstPaint = t;
  save();
  info.annotations.push({ type: "first paint", description: `${t.fcp.toFixed(0)} ms (target < 1500 ms)` });
  expect(t.fcp).toBeGreaterThan(0);
});

test("two people play back at a measured frame rate, light and full quality, mannequin and character", async ({ page }, info) => {
  const load0 = loadavg().map((x) => +x.toFixed(2));
  await openStudio(page);
  await startGeneration(page, "two people dance salsa", 2, 6);
  const done = await waitDone(page);
  await page.waitForTimeout(1000); // let dynamic resolution settle in (it adapts while playing)
  const light = await playbackFps(page);
  // the skinned character (`?figure=character`: this page only, not remembered), light quality
  await page.goto(`/m/${done.motionId}?figure=character`);
  await page.waitForFunction(() => (window.__interplay as unknown as { figure: { shown: string } }).figure.shown === "character");
  await page.waitForTimeout(1000);
  const character = await playbackFps(page);
  await page.goto(`/m/${done.motionId}?quality=full`);
  await page.waitForFunction(() => window.__interplay.phase === "done" && window.__interplay.quality === "full");
  const full = await playbackFps(page);
  results.playback = { persons: 2, light, character, full, loadAverage: { start: load0, end: loadavg().map((x) => +x.toFixed(2)) } };
  save();
  const line = (p: Playback) => `${p.fps.toFixed(1)} fps (${p.cpuMsPerFrame} ms CPU, scale ${p.renderScale}, ${(100 * p.missed).toFixed(1)} % of refresh intervals over 20 ms)`;
  info.annotations.push({ type: "fps", description: `light ${line(light)}, character ${line(character)}, full ${full.fps.toFixed(1)} fps` });
  // It plays (frames are rendered in every mode); the rates themselves are recorded, not asserted.
  expect(light.fps).toBeGreaterThan(0);
  expect(character.fps).toBeGreaterThan(0);
  expect(full.fps).toBeGreaterThan(0);
});

// 20 generations take ~2 min here: run with INTERPLAY_E2E_PERF=1 (`npm run test:perf`) so the
// default suite stays under 5 min.
test("the JS heap does not grow across 20 generations", async ({ page }, info) => {
  test.skip(!process.env.INTERPLAY_E2E_PERF, "set INTERPLAY_E2E_PERF=1 to run the 20-generation heap test");
  test.setTimeout(300_000);
  const cdp = await page.context().newCDPSession(page);
  await openStudio(page);
  const heap: number[] = [];
  for (let i = 0; i < 20; i++) {
    // wait for THIS generation: until its job exists the page still says "done" for the last
    const prev = await page.evaluate(() => window.__interplay.jobId);
    await startGeneration(page, i % 2 ? "a person jumps" : "a person walks forward", 1, 1);
    await page.waitForFunction((prev) => window.__interplay.jobId !== prev, prev);
    await waitDone(page);
    await cdp.send("HeapProfiler.collectGarbage");
    heap.push(await page.evaluate(() => (performance as unknown as { memory: { usedJSHeapSize: number } }).memory.usedJSHeapSize));
  }
  const mb = heap.map((b) => b / 2 ** 20);
  // least-squares slope over the last 15 (the first few warm caches up)
  const ys = mb.slice(5);
  const xm = (ys.length - 1) / 2;
  const ym = ys.reduce((a, b) => a + b, 0) / ys.length;
  const slope = ys.reduce((a, y, x) => a + (x - xm) * (y - ym), 0) / ys.reduce((a, _, x) => a + (x - xm) ** 2, 0);
  results.memory = { heapMB: mb.map((m) => +m.toFixed(2)), slopeMBPerGeneration: +slope.toFixed(3) };
  save();
  info.annotations.push({ type: "heap", description: `${mb[0].toFixed(1)} → ${mb[19].toFixed(1)} MB, slope ${slope.toFixed(3)} MB/gen` });
  expect(slope).toBeLessThan(0.25);
  expect(mb[19] - Math.min(...mb.slice(0, 5))).toBeLessThan(8);
});
