import { describe, expect, it } from "vitest";
import { walkFrames } from "../test/fixtures";
import { initialStream, parseEvent, reduceStream, startStream, type StreamState } from "./stream";
import type { StreamEvent } from "./types";

const plan = { segments: [{ prompt: "a person walks forward", start: 0, end: 3, persons: 1 }] };

function run(events: StreamEvent[], state: StreamState = startStream()): StreamState {
  return events.reduce(reduceStream, state);
}

describe("reduceStream", () => {
  it("follows plan → frames → metrics → done", () => {
    const s1 = run([{ type: "plan", plan }]);
    expect(s1.phase).toBe("generating");
    expect(s1.plan).toEqual(plan);
    const s2 = reduceStream(s1, { type: "frames", start: 0, total: 60, people: [walkFrames(20)] });
    expect([s2.received, s2.total]).toEqual([20, 60]);
    const s3 = run(
      [
        { type: "frames", start: 20, total: 60, people: [walkFrames(40, 0, 1.2, 20)] },
        { type: "metrics", metrics: { foot_skating: 0.1 } },
        { type: "done", motion_id: "abc", frames: 60 },
      ],
      s2,
    );
    expect(s3).toMatchObject({ phase: "done", received: 60, total: 60, motionId: "abc" });
    expect(s3.metrics).toEqual({ foot_skating: 0.1 });
  });

  it("counts the furthest chunk when chunks arrive out of order", () => {
    const s = run([
      { type: "frames", start: 10, total: 30, people: [walkFrames(10)] },
      { type: "frames", start: 0, total: 30, people: [walkFrames(10)] },
    ]);
    expect([s.received, s.total]).toEqual([20, 30]);
  });

  it("keeps highlights out of the state and ignores unknown events", () => {
    const s0 = run([{ type: "frames", start: 0, total: 2, people: [walkFrames(2)] }]);
    const hl: StreamEvent = { type: "highlights", start: 0, contacts: [[], []], penetration: [[], []], min_distance: null };
    expect(reduceStream(s0, hl)).toBe(s0);
    expect(reduceStream(s0, { type: "heartbeat" } as unknown as StreamEvent)).toBe(s0);
  });

  it("stops at an error and ignores what follows", () => {
    const s = run([
      { type: "plan", plan },
      { type: "error", message: "generator failed" },
      { type: "done", motion_id: "x", frames: 10 },
    ]);
    expect(s).toMatchObject({ phase: "error", error: "generator failed", motionId: null });
  });

  it("starts clean", () => {
    const s = startStream();
    expect(s).toEqual({ ...initialStream, phase: "connecting" });
  });
});

describe("parseEvent", () => {
  it("parses events and turns garbage into an error event", () => {
    expect(parseEvent('{"type":"done","motion_id":"a","frames":3}')).toEqual({ type: "done", motion_id: "a", frames: 3 });
    expect(parseEvent("not json").type).toBe("error");
    expect(parseEvent('{"no":"type"}').type).toBe("error");
  });
});
