import { describe, expect, it } from "vitest";
import { LIGHT_RESOLUTION, ResolutionController, type ResolutionPolicy } from "./resolution";

const policy: ResolutionPolicy = { ...LIGHT_RESOLUTION, window: 10, calm: 2, maxCalm: 8, settle: 3 };
const AT_RATE = 1000 / 60;
const SLOW = 25; // 40 fps

/** Feed `n` frames of `ms` each; the scales it changed to, in order. */
function feed(c: ResolutionController, ms: number, n: number): number[] {
  const out: number[] = [];
  for (let i = 0; i < n; i++) {
    const s = c.sample(ms);
    if (s !== null) out.push(s);
  }
  return out;
}

/** Frames of `ms` fed before the one that changes the scale (unbounded: the caller expects one). */
function framesBeforeChange(c: ResolutionController, ms: number): number {
  let k = 0;
  while (c.sample(ms) === null) k++;
  return k;
}

describe("ResolutionController", () => {
  it("starts at the policy's start level", () => {
    expect(new ResolutionController(policy).scale).toBe(0.75);
  });

  it("holds the scale while frames come at the display's rate, between the thresholds too", () => {
    const c = new ResolutionController({ ...policy, calm: 1000 });
    expect(feed(c, AT_RATE, 500)).toEqual([]);
    expect(feed(c, AT_RATE * 1.08, 500)).toEqual([]); // neither slow nor at the rate
    expect(c.scale).toBe(0.75);
  });

  it("steps down one level per slow window, after letting in-flight frames settle, to the floor", () => {
    const c = new ResolutionController(policy);
    expect(feed(c, SLOW, 10)).toEqual([0.625]);
    expect(feed(c, SLOW, 3 + 9)).toEqual([]); // 3 settle frames, then a window not yet full
    expect(feed(c, SLOW, 1)).toEqual([0.5]);
    expect(feed(c, SLOW, 200)).toEqual([]); // never below the floor
    expect(c.scale).toBe(0.5);
  });

  it("a mean decides, not one slow frame (a GC pause in a window at the rate)", () => {
    const c = new ResolutionController({ ...policy, calm: 1000 });
    feed(c, AT_RATE, 9);
    expect(c.sample(30)).toBeNull(); // mean (9 × 16.7 + 30) / 10 = 18 ms: above fast, below slow
    expect(c.scale).toBe(0.75);
  });

  it("a long interval is a pause, not a slow frame: the window restarts", () => {
    const c = new ResolutionController(policy);
    feed(c, SLOW, 9);
    expect(c.sample(1000)).toBeNull();
    expect(feed(c, AT_RATE, 9)).toEqual([]);
    expect(c.scale).toBe(0.75);
  });

  it("probes one level up after `calm` windows at the rate, never above the first level", () => {
    const c = new ResolutionController(policy);
    expect(feed(c, AT_RATE, 20)).toEqual([0.875]);
    expect(feed(c, AT_RATE, 3 + 20)).toEqual([1]);
    expect(feed(c, AT_RATE, 500)).toEqual([]);
    expect(c.scale).toBe(1);
  });

  it("a probe that turns out slow doubles the calm needed before the next one (no oscillation)", () => {
    const c = new ResolutionController(policy);
    // the machine holds 60 fps at 0.75 and below, not at 0.875: count the probes over a while
    const ms = () => (c.scale > 0.75 ? SLOW : AT_RATE);
    const changes: number[] = [];
    for (let i = 0; i < 3000; i++) {
      const s = c.sample(ms());
      if (s !== null) changes.push(s);
    }
    const probes = changes.filter((s) => s === 0.875).length;
    // calm 2, 4, 8, 8, … windows of 10 frames: far fewer probes than the 3000 / 20 = 150 that a
    // fixed calm would make, and it always comes back to 0.75
    expect(probes).toBeGreaterThan(2);
    expect(probes).toBeLessThan(3000 / (8 * 10) + 2);
    expect(changes.filter((s) => s === 0.625)).toEqual([]); // never lower than it needs
    expect(c.scale === 0.75 || c.scale === 0.875).toBe(true);
  });

  it("a slow window long after a good probe is load, not a failed probe: the calm is not doubled", () => {
    const c = new ResolutionController(policy);
    feed(c, AT_RATE, 3 + 40); // → 0.875 → 1
    feed(c, AT_RATE, 3 + 50); // calm at the top, five windows past the probe
    expect(c.scale).toBe(1);
    feed(c, SLOW, 10); // load arrives
    expect(c.scale).toBe(0.875);
    c.sample(1000); // a pause between the two (the window starts again)
    // back at the rate: up again after the settle frames and the base calm (2 windows), not 4
    const k = framesBeforeChange(c, AT_RATE);
    expect(c.scale).toBe(1);
    expect(k).toBe(3 + 2 * 10 - 1);
  });

  it("after a failed probe, the next probe waits twice as long", () => {
    const c = new ResolutionController(policy);
    feed(c, AT_RATE, 20); // probe → 0.875
    feed(c, SLOW, 3 + 10); // slow right after: failed, back to 0.75, calm needed 4
    expect(c.scale).toBe(0.75);
    const k = framesBeforeChange(c, AT_RATE);
    expect(c.scale).toBe(0.875);
    expect(k).toBe(3 + 4 * 10 - 1);
  });

  it("the floor is a pixel count too: a small canvas keeps the start level, a large one goes lower", () => {
    const small = new ResolutionController(policy);
    expect(small.fit(390 * 473)).toBeNull(); // a narrow window's canvas: 0.625 would be 72k px
    feed(small, SLOW, 200);
    expect(small.scale).toBe(0.75);
    const large = new ResolutionController(policy);
    expect(large.fit(960 * 540)).toBeNull(); // 0.5 draws 480 × 270: allowed
    feed(large, SLOW, 200);
    expect(large.scale).toBe(0.5);
    // the window shrinks while at the floor: back up to the new floor at once
    expect(large.fit(640 * 360)).toBe(0.75);
  });

  it("a probe that misses the rate a little (not slow) still steps back: it must hold the rate", () => {
    const c = new ResolutionController(policy);
    feed(c, AT_RATE, 20); // probe → 0.875
    expect(c.scale).toBe(0.875);
    expect(feed(c, AT_RATE * 1.06, 3 + 10)).toEqual([0.75]); // 56.6 fps: between fast and slow
    // and, long after a probe, the same frames only hold (hysteresis)
    const d = new ResolutionController({ ...policy, calm: 1000 });
    expect(feed(d, AT_RATE * 1.06, 500)).toEqual([]);
  });
});
