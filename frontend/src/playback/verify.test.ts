import { describe, expect, it } from "vitest";
import { frameDigest, motionDigest } from "../api/digest";
import type { Motion } from "../api/types";
import { FrameBuffer } from "./frameBuffer";
import { resetCopyCheck, verifyCopy } from "./verify";

const frame = (x: number) => Array.from({ length: 22 }, (_, j) => [x, j / 10, 0] as [number, number, number]);

function digests(people: ReturnType<typeof frame>[][]): string[] {
  const b = new FrameBuffer();
  b.reset(people.length);
  b.setFrames(0, people);
  return Array.from({ length: people[0].length }, (_, t) => frameDigest(b.positions, t));
}

describe("verifyCopy", () => {
  it("reloads exactly the frames that differ from the stored ones, then matches", async () => {
    const stored = [[frame(0), frame(0.1), frame(0.2)]];
    const buf = new FrameBuffer();
    buf.reset(1);
    buf.setFrames(0, [[frame(0), frame(0.15), frame(0.2)]]); // frame 1 stale
    const want = digests(stored);
    resetCopyCheck();
    let loads = 0;
    const check = await verifyCopy(buf, { type: "done", motion_id: "m", frames: 3, digest: motionDigest(want), frame_digests: want }, async () => {
      loads++;
      return { people: stored.map((joints) => ({ joints })), highlights: null } as unknown as Motion;
    });
    expect(loads).toBe(1);
    expect(check).toMatchObject({ motionId: "m", differing: 1, reloaded: 1, matches: true });
    expect(buf.framePeople(1)[0][0][0]).toBeCloseTo(0.1, 6);
  });

  it("loads nothing when the copy is the stored motion", async () => {
    const stored = [[frame(0), frame(0.1)]];
    const buf = new FrameBuffer();
    buf.reset(1);
    buf.setFrames(0, stored);
    const want = digests(stored);
    resetCopyCheck();
    const check = await verifyCopy(buf, { type: "done", motion_id: "m", frames: 2, digest: motionDigest(want), frame_digests: want }, () => {
      throw new Error("no load expected");
    });
    expect(check).toMatchObject({ differing: 0, reloaded: 0, matches: true });
  });
});
