import { describe, expect, it } from "vitest";
import { rest, skeleton } from "../test/fixtures";
import { MARK_RADIUS, MAX_MARKS, MARK_STRIDE, emptyMarks, findOverlaps } from "./overlaps";
import { NUM_SPHERES, placeSpheres, sphereLayout } from "./sphereBody";

const layout = sphereLayout(skeleton);
const spheresOf = (pose: number[][]) => placeSpheres(layout, Float32Array.from(pose.flat()), 1, new Float32Array(NUM_SPHERES * 4));
/** The rest pose turned to face the first (180° about y) and moved [0.05, 0, dz]. */
const facing = (dz: number) => rest.map(([x, y, z]) => [-x + 0.05, y, -z + dz]);

/** Overlapping sphere pairs [i, j], by brute force. */
function pairs(a: Float32Array, b: Float32Array): number[][] {
  const out: number[][] = [];
  for (let i = 0; i < NUM_SPHERES; i++) {
    for (let j = 0; j < NUM_SPHERES; j++) {
      const d = Math.hypot(a[4 * i] - b[4 * j], a[4 * i + 1] - b[4 * j + 1], a[4 * i + 2] - b[4 * j + 2]);
      if (d < a[4 * i + 3] + b[4 * j + 3]) out.push([i, j]);
    }
  }
  return out;
}

const inside = (s: Float32Array, p: ArrayLike<number>) =>
  Array.from({ length: NUM_SPHERES }, (_, i) => Math.hypot(s[4 * i] - p[0], s[4 * i + 1] - p[1], s[4 * i + 2] - p[2]) <= s[4 * i + 3] + 1e-6)
    .some(Boolean);

describe("penetration marks: where two sphere bodies overlap", () => {
  it("marks the middle of one lens, sized by it", () => {
    const marks = emptyMarks();
    const a = Float32Array.of(0, 1, 0, 0.1);
    expect(findOverlaps(a, Float32Array.of(0.15, 1, 0, 0.1), marks)).toBe(1);
    const [x, y, z, r, depth] = marks.data.subarray(0, MARK_STRIDE);
    // the overlap spans x 0.05 … 0.1; the surfaces meet on a circle of radius √(0.1² − 0.075²)
    expect([x, y, z]).toEqual([expect.closeTo(0.075, 6), 1, 0]);
    expect(depth).toBeCloseTo(0.05, 6);
    expect(r).toBeCloseTo(0.5 * Math.sqrt(0.01 - 0.075 ** 2), 6);
    expect(findOverlaps(a, Float32Array.of(0.2, 1, 0, 0.1), marks)).toBe(0); // touching is not overlapping
    expect(findOverlaps(a, Float32Array.of(0, 1, 0, 0.02), marks)).toBe(1); // one inside the other
    // the lens is the small sphere (radius 0.02): drawn at the smallest mark size
    expect(marks.data[3]).toBeCloseTo(MARK_RADIUS[0], 6);
  });

  it("finds the overlaps the Python model finds for a facing pair, and none where it finds none", () => {
    // body.surface_gaps(rest, facing(dz)) < 0 in Python: these pairs, and none from 0.28 m
    const python: [number, number[][]][] = [
      [0.2, [[2, 2], [5, 5], [10, 10]]],
      [0.25, [[10, 10]]],
      [0.28, []],
      [0.35, []],
    ];
    const a = spheresOf(rest);
    const marks = emptyMarks();
    for (const [dz, expected] of python) {
      const b = spheresOf(facing(dz));
      expect(pairs(a, b), `${dz} m`).toEqual(expected);
      const n = findOverlaps(a, b, marks);
      expect(n > 0, `${dz} m`).toBe(expected.length > 0);
      for (let k = 0; k < n; k++) {
        const p = marks.data.subarray(k * MARK_STRIDE, k * MARK_STRIDE + 3);
        expect(inside(a, p) && inside(b, p), `mark ${k} at ${dz} m is inside both bodies`).toBe(true);
      }
    }
  });

  it("shows a deep overlap as a few regions, not one mark per sphere pair", () => {
    const a = spheresOf(rest);
    const b = spheresOf(facing(0.15)); // Python: 22 overlapping pairs (pelvis, belly, chest, head, feet)
    const marks = emptyMarks();
    const n = findOverlaps(a, b, marks);
    expect(pairs(a, b).length).toBe(22);
    expect(n).toBeGreaterThan(2);
    expect(n).toBeLessThan(12);
    // the head's overlap is marked at head height, the feet's near the floor
    const heights = Array.from({ length: n }, (_, k) => marks.data[k * MARK_STRIDE + 1]);
    expect(Math.max(...heights)).toBeGreaterThan(1.6);
    expect(Math.min(...heights)).toBeLessThan(0.15);
    // one body inside the other: never more than MAX_MARKS
    expect(findOverlaps(a, spheresOf(rest), marks)).toBeLessThanOrEqual(MAX_MARKS);
  });
});
