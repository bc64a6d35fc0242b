import { describe, expect, it } from "vitest";
import { rest, walkFrames } from "../test/fixtures";
import { FrameBuffer } from "./frameBuffer";

describe("FrameBuffer", () => {
  it("stores chunks and exposes the contiguous playable prefix", () => {
    const b = new FrameBuffer();
    b.reset(2);
    b.setFrames(20, [walkFrames(10, 0, 1, 20), walkFrames(10, 1, 1, 20)], 40);
    expect([b.total, b.received]).toEqual([40, 0]);
    b.setFrames(0, [walkFrames(20), walkFrames(20, 1)], 40);
    expect(b.received).toBe(30);
    // person 1, frame 25, joint 0 (pelvis): x offset 1, z = 25 / 20
    const f = b.frame(1, 25);
    expect(f.length).toBe(66);
    expect(f[0]).toBeCloseTo(rest[0][0] + 1);
    expect(f[2]).toBeCloseTo(rest[0][2] + 25 / 20);
    expect(b.framePeople(0)[0][15]).toEqual(rest[15].map((v) => Math.fround(v)));
  });

  it("grows when frames run past the announced total", () => {
    const b = new FrameBuffer();
    b.reset(1, 5);
    b.setFrames(0, [walkFrames(8, 0, 1)]);
    expect([b.total, b.received]).toEqual([8, 8]);
    expect(b.frame(0, 7)[2]).toBeCloseTo(rest[0][2] + 7 / 20);
  });

  it("replaces frames when a chunk repeats a start (refinement)", () => {
    const b = new FrameBuffer();
    b.reset(1);
    b.setFrames(0, [walkFrames(10, 0, 1)], 10);
    const v = b.version;
    b.setFrames(5, [walkFrames(2, 3, 1, 5)], 10);
    expect(b.version).toBeGreaterThan(v);
    expect([b.total, b.received]).toEqual([10, 10]);
    expect(b.frame(0, 5)[0]).toBeCloseTo(rest[0][0] + 3);
    expect(b.frame(0, 7)[0]).toBeCloseTo(rest[0][0]);
  });

  it("rejects chunks of the wrong shape", () => {
    const b = new FrameBuffer();
    b.reset(2);
    expect(() => b.setFrames(0, [walkFrames(3)])).toThrow(/2 people/);
    expect(() => b.setFrames(0, [walkFrames(3), walkFrames(2)])).toThrow(/differ/);
    const bad = walkFrames(1).map((f) => f.slice(0, 21));
    expect(() => b.setFrames(0, [bad, bad])).toThrow(/22 joints/);
  });

  it("loads a stored motion with its highlights and marks a new generation", () => {
    const b = new FrameBuffer();
    const g = b.generation;
    b.loadMotion({
      people: [{ joints: walkFrames(3) }, { joints: walkFrames(3, 1) }],
      highlights: {
        contacts: [[[0, 20]], [], [[1, 21]]],
        penetration: [[], [[0, "left_upper"]], []],
        min_distance: [0.5, 0.1, 0.3],
      },
    });
    expect(b.generation).toBe(g + 1);
    expect([b.persons, b.total, b.received]).toEqual([2, 3, 3]);
    expect(b.contacts[2]).toEqual([[1, 21]]);
    expect(b.penetration[1]).toEqual([[0, "left_upper"]]);
    expect(b.minDistance[1]).toBe(0.1);
  });
});
