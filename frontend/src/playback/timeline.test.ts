import { describe, expect, it } from "vitest";
import { THUMB_PX, advance, blendAt, formatSeconds, frameIndex, framePercent, frameToX, playFrom, scrubFrame, xToFrame } from "./timeline";

const ctx = { fps: 20, speed: 1, loop: false, available: 60, total: 60 };

describe("timeline", () => {
  it("advances by wall time × fps × speed", () => {
    expect(advance({ pos: 0, playing: true }, 0.5, ctx).pos).toBeCloseTo(10);
    expect(advance({ pos: 0, playing: true }, 0.5, { ...ctx, speed: 2 }).pos).toBeCloseTo(20);
    expect(advance({ pos: 7, playing: false }, 0.5, ctx)).toEqual({ pos: 7, playing: false });
  });

  it("waits at the last received frame while streaming", () => {
    const s = advance({ pos: 18, playing: true }, 1, { ...ctx, available: 20 });
    expect(s).toEqual({ pos: 19, playing: true });
  });

  it("stops at the end, or wraps when looping", () => {
    expect(advance({ pos: 59, playing: true }, 0.2, ctx)).toEqual({ pos: 59, playing: false });
    const looped = advance({ pos: 59, playing: true }, 0.2, { ...ctx, loop: true });
    expect(looped.playing).toBe(true);
    expect(looped.pos).toBeCloseTo(3);
  });

  it("maps positions, scrubber fractions and durations", () => {
    expect(frameIndex(12.9, 60)).toBe(12);
    expect(frameIndex(80, 60)).toBe(59);
    expect(frameIndex(-1, 60)).toBe(0);
    expect(scrubFrame(0.5, 61)).toBe(30);
    expect(scrubFrame(2, 60)).toBe(59);
    expect(formatSeconds(60, 20)).toBe("3.00 s");
    expect(playFrom(59, 60, 60)).toBe(0);
    expect(playFrom(30, 60, 60)).toBe(30);
  });

  it("blends towards the next frame while inside the clip, never past its end", () => {
    expect(blendAt(3.25, 10)).toEqual({ frame: 3, next: 4, weight: 0.25 });
    expect(blendAt(9.5, 10)).toEqual({ frame: 9, next: 9, weight: 0 });
    expect(blendAt(4, 10)).toEqual({ frame: 4, next: 5, weight: 0 });
    expect(blendAt(0.5, 1)).toEqual({ frame: 0, next: 0, weight: 0 });
  });
});

describe("one pixel mapping for the scrubber and the track", () => {
  it("puts the first frame half a thumb in from the left and the last half a thumb in from the right", () => {
    expect(frameToX(0, 81, 100, 614)).toBe(100 + THUMB_PX / 2);
    expect(frameToX(80, 81, 100, 614)).toBe(100 + 614 - THUMB_PX / 2);
    expect(frameToX(40, 81, 100, 614)).toBe(100 + 614 / 2);
    expect(framePercent(20, 81)).toBe("25%");
    expect(framePercent(0, 1)).toBe("0%");
  });

  it("maps x back to the same frame, clamped to the clip", () => {
    for (const f of [0, 1, 17, 40, 79, 80]) expect(xToFrame(frameToX(f, 81, 12, 500), 81, 12, 500)).toBe(f);
    expect(xToFrame(0, 81, 12, 500)).toBe(0);
    expect(xToFrame(10_000, 81, 12, 500)).toBe(80);
    expect(xToFrame(50, 1, 12, 500)).toBe(0);
  });
});
