import { describe, expect, it } from "vitest";
import { walkFrames } from "../test/fixtures";
import { reduceStream, startStream, type StreamState } from "../api/stream";
import type { StreamEvent } from "../api/types";
import { canReact, describeReaction, reactRequest } from "./react";

const done: StreamState = { ...startStream(), phase: "done", motionId: "actor1" };

describe("canReact", () => {
  it("offers a reactor for a finished one-person motion only", () => {
    const base = { stream: done, motionId: "actor1", motionPersons: 1, editing: false };
    expect(canReact(base)).toBe(true);
    expect(canReact({ ...base, motionPersons: 2 })).toBe(false);
    expect(canReact({ ...base, motionId: null })).toBe(false);
    expect(canReact({ ...base, editing: true })).toBe(false);
    expect(canReact({ ...base, stream: { ...done, phase: "generating" } })).toBe(false);
    expect(canReact({ ...base, stream: startStream(null, "job", "react", "actor1") })).toBe(false);
  });
});

describe("reactRequest", () => {
  it("sends the intent trimmed, and none when blank", () => {
    expect(reactRequest("a1", "  shake   hands ")).toEqual({ mode: "react", actor_motion_id: "a1", prompt: "shake hands" });
    expect(reactRequest("a1", "   ")).toEqual({ mode: "react", actor_motion_id: "a1" });
    expect(reactRequest("a1", "", 7)).toEqual({ mode: "react", actor_motion_id: "a1", seed: 7 });
    expect(reactRequest("a1", "x".repeat(600)).prompt).toHaveLength(500);
  });

  it("describes the version it makes", () => {
    expect(describeReaction("shake hands")).toBe("Person 2 reacts to Person 1: shake hands");
    expect(describeReaction(null)).toBe("Person 2 reacts to Person 1");
  });
});

describe("a react stream", () => {
  it("keeps its mode and actor through the pair's frames to done", () => {
    const pair = (n: number, start: number) => [walkFrames(n, 0, 1.2, start), walkFrames(n, 1, 1.2, start)];
    const events: StreamEvent[] = [
      { type: "plan", plan: { segments: [], mode: "react", prompt: "shake hands" } },
      { type: "segment", index: 0, status: "generating", generator: "arflow" },
      { type: "frames", start: 0, total: 20, people: pair(10, 0) },
      { type: "frames", start: 10, total: 20, people: pair(10, 10) },
      { type: "segment", index: 0, status: "done", generator: "arflow" },
      { type: "metrics", metrics: { intersection_frequency: 0 } },
      { type: "done", motion_id: "pair1", frames: 20 },
    ];
    const start = startStream(null, "job1", "react", "actor1");
    expect(start).toMatchObject({ phase: "connecting", mode: "react", actorId: "actor1", received: 0 });
    const mid = events.slice(0, 3).reduce(reduceStream, start);
    expect(mid).toMatchObject({ phase: "generating", mode: "react", received: 10, total: 20 });
    const end = events.reduce(reduceStream, start);
    expect(end).toMatchObject({ phase: "done", mode: "react", actorId: "actor1", motionId: "pair1", received: 20 });
    expect(startStream().mode).toBe("generate");
  });
});
