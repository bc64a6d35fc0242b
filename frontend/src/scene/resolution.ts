// Dynamic resolution: the render scale (pixel ratio) that holds the display's rate. Pure: the
// render loop feeds it the interval between consecutive rendered frames (performance.now) and
// applies the scale it answers. Policy:
// - frames are judged a window at a time (their mean interval against the target interval);
// - a window slower than `slow` × target steps the scale down one level (never below the
//   floor: the last level), at once;
// - `calm` windows in a row at the target step it up one level again (a probe), never above
//   the first level; a probe must hold the rate: a window off the rate (above fast × target)
//   within `calm` windows of it steps back down, and the calm needed for the next probe
//   doubles (up to `maxCalm` windows), so the scale does not oscillate;
// - after any change, `settle` frames are ignored (frames already in flight at the old size);
// - an interval longer than `gap` ms is a pause (playback stopped, tab hidden), not a slow
//   frame: the window starts again;
// - the floor is also a pixel count: a level that would draw fewer than `minPixels` is not
//   used (a small canvas — a narrow window — keeps at least the start level: its few pixels
//   are not what the frame time is spent on, and fewer would be illegible).

export interface ResolutionPolicy {
  /** Render scales from the highest to the floor (the lowest legible one). */
  levels: number[];
  /** Level to start at. */
  start: number;
  /** Target interval between frames, ms (the display's refresh: 1000 / 60). */
  targetMs: number;
  /** Frames per window. */
  window: number;
  /** A window whose mean interval is above slow × target is too slow. */
  slow: number;
  /** A window whose mean interval is at most fast × target holds the rate. */
  fast: number;
  /** Windows in a row at the rate before probing one level up. */
  calm: number;
  maxCalm: number;
  settle: number;
  gap: number;
  /** The fewest drawing-buffer pixels a level below the start may draw (legibility). */
  minPixels: number;
}

export const LIGHT_RESOLUTION: ResolutionPolicy = {
  levels: [1, 0.875, 0.75, 0.625, 0.5],
  start: 2,
  targetMs: 1000 / 60,
  window: 30,
  slow: 1.12,
  fast: 1.02,
  calm: 4,
  maxCalm: 64,
  settle: 6,
  gap: 250,
  minPixels: 480 * 270,
};

export class ResolutionController {
  private level: number;
  private sum = 0;
  private n = 0;
  private skip = 0;
  private calmWindows = 0;
  private need: number;
  /** Windows since the last step up (a slow window soon after it marks the probe failed). */
  private sinceRaise = Infinity;
  /** The lowest level allowed (an index into levels; fit() sets it from the canvas size). */
  private floor: number;

  constructor(readonly policy: ResolutionPolicy = LIGHT_RESOLUTION) {
    this.level = Math.min(Math.max(0, policy.start), policy.levels.length - 1);
    this.floor = policy.levels.length - 1;
    this.need = policy.calm;
  }

  /** The canvas is `cssPixels` CSS pixels now: levels that would draw fewer than minPixels go
   * (never the start level or above). Returns the new scale when the current one went. */
  fit(cssPixels: number): number | null {
    const { levels, minPixels } = this.policy;
    let floor = levels.length - 1;
    while (floor > this.policy.start && levels[floor] ** 2 * cssPixels < minPixels) floor--;
    this.floor = floor;
    return this.level > floor ? this.move(floor - this.level) : null;
  }

  get scale(): number {
    return this.policy.levels[this.level];
  }

  /** One rendered frame `intervalMs` after the previous rendered one. Returns the new scale when
   * it changed, else null. */
  sample(intervalMs: number): number | null {
    const p = this.policy;
    if (!(intervalMs > 0) || intervalMs > p.gap) {
      this.sum = this.n = 0;
      return null;
    }
    if (this.skip > 0) {
      this.skip--;
      return null;
    }
    this.sum += intervalMs;
    this.n++;
    if (this.n < p.window) return null;
    const mean = this.sum / this.n;
    this.sum = this.n = 0;
    this.sinceRaise++;
    const probing = this.sinceRaise <= p.calm;
    if (mean > p.slow * p.targetMs || (probing && mean > p.fast * p.targetMs)) {
      this.calmWindows = 0;
      if (probing) {
        this.need = Math.min(p.maxCalm, this.need * 2); // a failed probe
        this.sinceRaise = Infinity;
      }
      return this.move(+1);
    }
    if (mean <= p.fast * p.targetMs) {
      if (++this.calmWindows >= this.need) {
        this.calmWindows = 0;
        const changed = this.move(-1);
        if (changed !== null) this.sinceRaise = 0;
        return changed;
      }
    } else this.calmWindows = 0; // between the two: hold
    return null;
  }

  private move(by: number): number | null {
    const next = Math.min(Math.max(0, this.level + by), this.floor);
    if (next === this.level) return null;
    this.level = next;
    this.skip = this.policy.settle;
    this.sum = this.n = 0;
    return this.scale;
  }
}
