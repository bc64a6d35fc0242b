// The in-page half of a playback measurement, shared by e2e/specs/perf.spec.ts and
// tools/frame-cost.mjs: passed to `page.evaluate(samplePlayback, ms)`, so it must stay
// self-contained (Playwright sends its source to the page). Over `ms` of playback it counts the
// studio's renders (window.__interplay.renderCount) and the display refreshes
// (requestAnimationFrame), and sorts the intervals between refreshes.
export async function samplePlayback(ms) {
  const h = window.__interplay;
  const r0 = h.renderCount;
  let raf = 0;
  let on = true;
  let last = -1;
  const gaps = [];
  const count = (t) => {
    raf++;
    if (last >= 0) gaps.push(t - last);
    last = t;
    if (on) requestAnimationFrame(count);
  };
  requestAnimationFrame(count);
  const t0 = performance.now();
  await new Promise((ok) => setTimeout(ok, ms));
  on = false;
  const dt = performance.now() - t0;
  gaps.sort((a, b) => a - b);
  const pct = (p) => +(gaps[Math.min(gaps.length - 1, Math.floor((p / 100) * gaps.length))] ?? 0).toFixed(1);
  // an interval over 20 ms means at least one 60 Hz refresh went by without a frame
  const missed = +(gaps.filter((g) => g > 20).length / Math.max(1, gaps.length)).toFixed(3);
  return {
    dt,
    renders: h.renderCount - r0,
    raf,
    scale: h.renderScale ?? null,
    intervalMs: { p50: pct(50), p95: pct(95), p99: pct(99) },
    missed,
  };
}
