// Per-frame motion data for the render loop: flat Float32Arrays per person (frame-major,
// 22 joints × xyz) plus per-frame highlights. Lives outside React state on purpose.
import type { Highlights, Motion, PersonFrames, StreamEvent } from "../api/types";

export const NUM_JOINTS = 22;
const STRIDE = NUM_JOINTS * 3;

type HighlightsEvent = Extract<StreamEvent, { type: "highlights" }>;

export class FrameBuffer {
  persons = 0;
  /** Frames expected (capacity). */
  total = 0;
  /** Number of leading frames that have all arrived (playable prefix). */
  received = 0;
  /** A version that changes with every write, so views know to redraw. */
  version = 0;
  /** Changes with every reset: a new motion (views rebuild their people). */
  generation = 0;
  positions: Float32Array[] = [];
  private filled = new Uint8Array(0);
  contacts: ([number, number][] | undefined)[] = [];
  penetration: ([number, string][] | undefined)[] = [];
  minDistance: (number | undefined)[] = [];

  reset(persons: number, total = 0): void {
    this.persons = persons;
    this.total = 0;
    this.received = 0;
    this.positions = Array.from({ length: persons }, () => new Float32Array(0));
    this.filled = new Uint8Array(0);
    this.contacts = [];
    this.penetration = [];
    this.minDistance = [];
    this.grow(total);
    this.version++;
    this.generation++;
  }

  private grow(total: number): void {
    if (total <= this.total) return;
    this.positions = this.positions.map((old) => {
      const next = new Float32Array(total * STRIDE);
      next.set(old);
      return next;
    });
    const filled = new Uint8Array(total);
    filled.set(this.filled);
    this.filled = filled;
    this.total = total;
  }

  /** Write frames [start, start + n) for every person (shape: persons × n × 22 × 3). */
  setFrames(start: number, people: PersonFrames[], total = 0): void {
    if (people.length !== this.persons) {
      throw new Error(`expected ${this.persons} people in a frames chunk, got ${people.length}`);
    }
    const n = people[0]?.length ?? 0;
    this.grow(Math.max(total, start + n));
    people.forEach((frames, p) => {
      if (frames.length !== n) throw new Error("people in a frames chunk differ in length");
      const dst = this.positions[p];
      for (let t = 0; t < n; t++) {
        const frame = frames[t];
        if (frame.length !== NUM_JOINTS) throw new Error(`expected ${NUM_JOINTS} joints per frame`);
        let o = (start + t) * STRIDE;
        for (let j = 0; j < NUM_JOINTS; j++) {
          dst[o++] = frame[j][0];
          dst[o++] = frame[j][1];
          dst[o++] = frame[j][2];
        }
      }
    });
    this.filled.fill(1, start, start + n);
    while (this.received < this.total && this.filled[this.received]) this.received++;
    this.version++;
  }

  setHighlights(ev: Pick<HighlightsEvent, "start" | "contacts" | "penetration" | "min_distance">): void {
    ev.contacts.forEach((c, i) => (this.contacts[ev.start + i] = c));
    ev.penetration.forEach((c, i) => (this.penetration[ev.start + i] = c));
    ev.min_distance?.forEach((d, i) => (this.minDistance[ev.start + i] = d ?? undefined));
    this.version++;
  }

  /** Fill from a stored motion (GET /api/motions/{id}). */
  loadMotion(motion: Pick<Motion, "people" | "highlights">): void {
    const people = motion.people.map((p) => p.joints);
    this.reset(people.length, people[0]?.length ?? 0);
    this.setFrames(0, people);
    const h: Highlights | null = motion.highlights;
    if (h) this.setHighlights({ start: 0, ...h });
  }

  /** Joints of one person at one frame: a view of 66 floats (no copy). */
  frame(person: number, t: number): Float32Array {
    return this.positions[person].subarray(t * STRIDE, (t + 1) * STRIDE);
  }

  /** Frame t as plain nested arrays (persons × 22 × 3), for tests and the test hook. */
  framePeople(t: number): number[][][] {
    if (t >= this.received) return [];
    return this.positions.map((_, p) => {
      const f = this.frame(p, t);
      return Array.from({ length: NUM_JOINTS }, (_, j) => [f[3 * j], f[3 * j + 1], f[3 * j + 2]]);
    });
  }
}
