import { describe, expect, it } from "vitest";
import {
  agentFromReview,
  describeInstruction,
  describeVersionEdit,
  initialAgent,
  instructionOutcomes,
  plainReason,
  reduceAgent,
  roundBadge,
  segmentVerdict,
  type SegmentProgress,
} from "./agent";
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

  it("describes instructions in words", () => {
    expect(describeInstruction({ kind: "edit_part", part: "left_arm", prompt: "wave", frames: [10, 30] })).toBe(
      "left arm: “wave” (frames 10–30)",
    );
    expect(describeInstruction({ kind: "inbetween", frames: [51, 60] })).toBe("redraw frames 51–60");
    expect(describeInstruction({ kind: "regenerate" })).toBe("re-generate with a new seed");
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

// The reviewer's real wording (review/reviewer.py, review/checks.py).
const EDIT = {
  kind: "edit_part",
  part: "right_arm",
  prompt: "waves the right hand",
  reason: "the plan says 'waves the right hand', the caption says 'the right arm is raised above the head'",
};
const SKATE = { kind: "inbetween", frames: [51, 60] as [number, number], prompt: "a person walks", reason: "foot skating in frames 51–60" };
const TOUCH = { kind: "regenerate", prompt: "two people shake hands", reason: "'shake hands' needs a touch, but the hands never reach the other person" };
const round = (r: number, verdict: string, instructions: object[]) => ({ round: r, captions: {}, score: 0.2, verdict, instructions }) as SegmentProgress["reviews"][number];
const seg = (reviews: SegmentProgress["reviews"], corrections: SegmentProgress["corrections"] = [], status = "done"): SegmentProgress => ({ status, reviews, corrections });

describe("verdicts and outcomes in words", () => {
  it("says passed, corrected (with what was fixed) or failed (with why), never the raw 'correct'", () => {
    expect(segmentVerdict(seg([round(0, "ok", [])]), true)).toEqual({ kind: "passed", text: "passed" });
    const corrected = seg(
      [round(0, "correct", [SKATE]), round(1, "ok", [])],
      [{ round: 1, instruction: SKATE, accepted: true, scoreBefore: 0.12, scoreAfter: 0.16 }],
    );
    expect(segmentVerdict(corrected, true)).toEqual({ kind: "corrected", text: "corrected: frames 51–60 redrawn (foot skating)" });
    const failed = segmentVerdict(seg([round(0, "correct", [TOUCH])], [
      { round: 1, instruction: TOUCH, accepted: false, scoreBefore: 0.4, scoreAfter: 0.3, reason: "the score dropped" },
    ]), true);
    expect(failed.kind).toBe("failed");
    expect(failed.text).toBe("failed: hands never meet (“shake hands” needs a touch)");
    const partly = segmentVerdict(seg([round(0, "correct", [EDIT]), round(1, "correct", [EDIT])], [
      { round: 1, instruction: EDIT, accepted: true, scoreBefore: 0.21, scoreAfter: 0.24 },
    ]), true);
    expect(partly.text).toMatch(/^failed: asked for “waves the right hand”, the motion shows “the right arm is raised above the head” — after right arm edited/);
    for (const v of [failed, partly]) expect(v.text).not.toMatch(/\bcorrect\b/);
  });

  it("is pending while the segment is still being generated or corrected", () => {
    expect(segmentVerdict(seg([], [], "generating"), false)).toEqual({ kind: "pending", text: "generating…" });
    expect(segmentVerdict(seg([round(0, "correct", [EDIT])], [], "generating"), false).kind).toBe("pending");
  });

  it("gives each instruction its outcome: accepted, rejected and why, could not apply and why, not tried", () => {
    const r0 = round(0, "correct", [EDIT, SKATE]);
    const rejected = seg([r0], [
      { round: 1, instruction: EDIT, accepted: false, scoreBefore: 0.18, scoreAfter: 0.18, reason: "worse skating_ratio, foot_skating" },
    ]);
    expect(instructionOutcomes(rejected, r0, true).map((o) => o.outcome)).toEqual([
      { kind: "rejected", text: "rejected: it made foot skating worse (score 0.18 → 0.18)" },
      { kind: "not-tried", text: "not tried: an earlier correction in this round was rejected" },
    ]);
    const cannot = seg([r0], [
      { round: 1, instruction: EDIT, accepted: false, scoreBefore: 0.2, scoreAfter: null, reason: "edit_part needs the SPAM model for one person" },
      { round: 1, instruction: SKATE, accepted: true, scoreBefore: 0.2, scoreAfter: 0.25 },
    ]);
    expect(instructionOutcomes(cannot, r0, true).map((o) => o.outcome.text)).toEqual([
      "could not apply: edit_part needs the SPAM model for one person",
      "accepted (score 0.20 → 0.25)",
    ]);
    expect(instructionOutcomes(seg([r0]), r0, false)[0].outcome.kind).toBe("pending");
    expect(instructionOutcomes(seg([r0]), r0, true)[0].outcome.text).toBe("not tried: no correction rounds left");
  });

  it("keeps a correction's reason through the stream reducer and a stored review", () => {
    const a = agentFromReview({
      segments: [
        {
          segment: 0,
          reviews: [{ round: 0, captions: {}, score: 0.1, instructions: [TOUCH], verdict: "correct" }],
          corrections: [{ round: 1, instruction: TOUCH, accepted: false, score_before: 0.1, score_after: null, reason: "cannot" }],
        },
      ],
    });
    expect(a[0].corrections[0]).toMatchObject({ reason: "cannot", scoreAfter: null });
    expect(plainReason("worse skating_ratio, foot_skating, floating")).toBe("it made foot skating and floating worse");
    expect(plainReason("the captions ('a person stands') hardly agree with 'a person jumps'")).toBe(
      "the motion hardly matches “a person jumps” (it shows “a person stands”)",
    );
  });
});

describe("verdicts read honestly (issue 26.4)", () => {
  it("calls a kept correction that did not raise the score rejected, unless the review after it passed", () => {
    const r0 = round(0, "correct", [TOUCH]);
    const flat = { round: 1, instruction: TOUCH, accepted: true, scoreBefore: 0.26, scoreAfter: 0.26 };
    const still = seg([r0, round(1, "correct", [TOUCH])], [flat]);
    expect(instructionOutcomes(still, r0, true)[0].outcome).toEqual({ kind: "rejected", text: "rejected: the score did not improve (score 0.26 → 0.26)" });
    expect(segmentVerdict(still, true).text).not.toMatch(/after|corrected/); // no fix to name
    const passes = seg([r0, round(1, "ok", [])], [flat]);
    expect(instructionOutcomes(passes, r0, true)[0].outcome).toEqual({ kind: "accepted", text: "accepted: the review passes now (score 0.26 → 0.26)" });
    expect(segmentVerdict(passes, true)).toEqual({ kind: "corrected", text: "corrected: re-generated with a new seed" });
    // a gain too small for two places is shown with three
    const small = seg([r0, round(1, "correct", [TOUCH])], [{ ...flat, scoreBefore: 0.261, scoreAfter: 0.264 }]);
    expect(instructionOutcomes(small, r0, true)[0].outcome.text).toBe("accepted (score 0.261 → 0.264)");
  });

  it("shows failed and not_covered verdicts as such, with what was shown instead", () => {
    const failedRound = { ...round(1, "failed", [TOUCH]), summary: "the person stands still" };
    const failed = segmentVerdict(seg([round(0, "correct", [TOUCH]), failedRound]), false);
    expect(failed).toEqual({ kind: "failed", text: "failed: hands never meet (“shake hands” needs a touch) — it shows “the person stands still”" });
    const uncovered = seg([{ ...round(0, "not_covered", []), summary: "the person walks" }]);
    expect(segmentVerdict(uncovered, true, "a person skips rope (nearest capture)")).toEqual({
      kind: "not-covered",
      text: "not in the library — showing the nearest: a person skips rope (nearest capture)",
    });
    expect(segmentVerdict(uncovered, true).text).toBe("not in the library — showing the nearest: the person walks");
    expect(roundBadge("failed")).toEqual({ kind: "failed", text: "failed" });
    expect(roundBadge("not_covered")).toEqual({ kind: "not-covered", text: "not in the library" });
    expect(roundBadge("correct").text).toBe("needs correction");
    const unsure = seg([round(0, "correct", [TOUCH]), { ...round(1, "unconfirmed", []), summary: "the person hops" }]);
    expect(segmentVerdict(unsure, true)).toEqual({ kind: "unconfirmed", text: "unconfirmed: the reviewer cannot judge these words — it shows “the person hops”" });
    expect(roundBadge("unconfirmed")).toEqual({ kind: "unconfirmed", text: "unconfirmed" });
  });
});

describe("a version's own review (issue 26.3)", () => {
  it("keeps the parent's rounds where the edit changed nothing and names the edit where it did", () => {
    const a = agentFromReview({
      segments: [
        { segment: 0, reviews: [{ round: 0, captions: {}, score: 0.8, instructions: [], verdict: "ok" }], corrections: [] },
        {
          segment: 1,
          reviews: [{ round: 0, captions: {}, score: 0.5, instructions: [], verdict: "ok" }],
          corrections: [],
          edit: { kind: "edit", part: "left_arm", prompt: "raises the left arm", frames: [22, 40] },
        },
      ],
    });
    expect(a[0].edit).toBeUndefined();
    expect(a[1].edit && describeVersionEdit(a[1].edit)).toBe("left arm: “raises the left arm” (frames 22–40)");
    expect(describeVersionEdit({ kind: "rerun", segment: 1, seed: 11 })).toBe("re-run with a new seed (seed 11)");
    expect(describeVersionEdit({ kind: "edit", part: "whole_body", prompt: null, frames: [54, 84] })).toBe("redone in place (frames 54–84)");
  });
});
