import { describe, expect, it } from "vitest";
import { agentFromReview, describeInstruction, initialAgent, reduceAgent } from "./agent";
import { reduceStream, startStream } from "./stream";
import type { StreamEvent } from "./types";

const plan = {
  segments: [
    { prompt: "a person walks", start: 0, end: 40, persons: 1 },
    { prompt: "then waves", start: 40, end: 80, persons: 1 },
  ],
};
const events: StreamEvent[] = [
  { type: "plan", plan },
  { type: "segment", index: 0, status: "generating", generator: "spam" },
  { type: "segment", index: 0, status: "done" } as StreamEvent, // tolerated without its generator
  {
    type: "review",
    segment: 0,
    round: 0,
    captions: { body: "a person walks", left_upper: "arm swings" },
    summary: "A person walks.",
    score: 0.41,
    score_kind: "caption_agreement",
    confirmed: { left_arm: false },
    checks: {},
    instructions: [{ kind: "edit_part", part: "left_arm", prompt: "wave", frames: [10, 30], reason: "no wave" }],
    verdict: "correct",
  },
  {
    type: "correction",
    segment: 0,
    round: 0,
    instruction: { kind: "edit_part", part: "left_arm", prompt: "wave" },
    accepted: true,
    score_before: 0.41,
    score_after: 0.66,
  },
  {
    type: "review",
    segment: 0,
    round: 1,
    captions: { body: "waves" },
    summary: "A person waves.",
    score: 0.66,
    score_kind: "caption_agreement",
    confirmed: { left_arm: true },
    checks: {},
    instructions: [],
    verdict: "ok",
  },
];

describe("reduceAgent", () => {
  it("collects segment status, review rounds and corrections in order", () => {
    const s = events.reduce(reduceStream, startStream());
    expect(s.phase).toBe("generating");
    const seg = s.agent[0];
    expect(seg.status).toBe("done");
    expect(seg.generator).toBe("spam"); // kept when a later event omits it
    expect(seg.reviews.map((r) => [r.round, r.verdict, r.score])).toEqual([
      [0, "correct", 0.41],
      [1, "ok", 0.66],
    ]);
    expect(seg.reviews[0].captions.left_upper).toBe("arm swings");
    expect(seg.corrections).toHaveLength(1);
    expect(seg.corrections[0]).toMatchObject({ accepted: true, scoreBefore: 0.41, scoreAfter: 0.66 });
    expect(s.agent[1]).toBeUndefined();
  });

  it("replaces a repeated round rather than duplicating it and ignores other events", () => {
    const review = events[3];
    const a = reduceAgent(reduceAgent(initialAgent, review), review);
    expect(a[0].reviews).toHaveLength(1);
    expect(reduceAgent(a, { type: "metrics", metrics: {} })).toBe(a);
  });

  it("marks a cancelled job", () => {
    const s = reduceStream(startStream(null, "job"), { type: "error", message: "cancelled", cancelled: true });
    expect(s).toMatchObject({ phase: "error", cancelled: true, jobId: "job" });
  });

  it("describes instructions", () => {
    expect(describeInstruction({ kind: "edit_part", part: "left_arm", prompt: "wave", frames: [10, 30] })).toBe(
      "edit left_arm: wave (frames 10–30)",
    );
    expect(describeInstruction({ kind: "regenerate" })).toBe("regenerate");
  });
});

describe("agentFromReview", () => {
  it("replays a stored review into the timeline state", () => {
    const review = {
      rounds: 2,
      segments: [
        {
          segment: 0,
          reviews: [{ segment: 0, round: 0, captions: { body: "walks" }, score: 0.85, instructions: [], verdict: "ok" }],
          corrections: [],
        },
      ],
    };
    const a = agentFromReview(review);
    expect(a[0].status).toBe("done");
    expect(a[0].reviews[0]).toMatchObject({ round: 0, score: 0.85, verdict: "ok", captions: { body: "walks" } });
    expect(agentFromReview(null)).toEqual({});
  });
});
