import { describe, expect, it } from "vitest";
import { differingRuns, frameDigest, motionDigest } from "./digest";

// The fixture tests/api/test_replace.py hashes with the server's code: 2 people, 3 frames,
// x = round(sin(7t + 3j + c + 11p) · 1.2345, 4), held in Float32Arrays as the page holds frames.
const FRAMES = ["3b12643e", "74d96d43", "47f804f3"];
const MOTION = "be7a39ef";

function fixture(): Float32Array[] {
  return [0, 1].map((p) => {
    const a = new Float32Array(3 * 66);
    for (let t = 0; t < 3; t++)
      for (let j = 0; j < 22; j++)
        for (let c = 0; c < 3; c++) a[t * 66 + j * 3 + c] = Math.round(Math.sin(7 * t + 3 * j + c + 11 * p) * 1.2345 * 1e4) / 1e4;
    return a;
  });
}

describe("frame digests", () => {
  it("are the server's for the shared fixture", () => {
    const people = fixture();
    const digests = [0, 1, 2].map((t) => frameDigest(people, t));
    expect(digests).toEqual(FRAMES);
    expect(motionDigest(digests)).toBe(MOTION);
  });

  it("find the frames that differ, and the ones not received, as runs", () => {
    const people = fixture();
    expect(differingRuns(people, 3, FRAMES)).toEqual([]);
    people[1][1 * 66 + 5] += 0.0001;
    expect(differingRuns(people, 3, FRAMES)).toEqual([[1, 2]]);
    expect(differingRuns(people, 1, FRAMES)).toEqual([[1, 3]]);
  });
});
