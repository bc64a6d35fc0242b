import { describe, expect, it } from "vitest";
import { walkFrames } from "../test/fixtures";
import { describeProgress } from "./progress";
import { reduceStream, startStream, type StreamState } from "./stream";
import type { Instruction, StreamEvent } from "./types";

const plan = {
  segments: [
    { prompt: "a person walks forward", start: 0, end: 60, persons: [0] },
    { prompt: "a person jumps", start: 60, end: 90, persons: [0] },
    { prompt: "a person sits down", start: 90, end: 120, persons: [0] },
  ],
};
const review = (segment: number, round: number, verdict: string, instructions: Instruction[] = []): StreamEvent => ({
  type: "review",
  segment,
  round,
  captions: {},
  summary: "",
  score: 0.5,
  score_kind: "caption_agreement",
  confirmed: {},
  checks: {},
  instructions,
  verdict,
});
const frames = (start: number, n: number): StreamEvent => ({ type: "frames", start, total: 120, people: [walkFrames(n, 0, 1, start)] });
const seg = (index: number, status: "generating" | "done"): StreamEvent => ({ type: "segment", index, status, generator: "spam" });

/** The progress after each event of a whole job, in order. */
function replay(events: StreamEvent[], path = false): { label: string; fraction: number; busy: boolean }[] {
  let s: StreamState = startStream(null, "job");
  const out = [describeProgress(s, path)];
  for (const ev of events) {
    s = reduceStream(s, ev);
    out.push(describeProgress(s, path));
  }
  return out;
}

const job: StreamEvent[] = [
  { type: "plan", plan },
  seg(0, "generating"),
  frames(0, 40),
  frames(40, 20),
  review(0, 0, "ok"),
  seg(0, "done"),
  seg(1, "generating"),
  frames(60, 30),
  review(1, 0, "correct", [{ kind: "edit_part", part: "left_arm", prompt: "raise the left arm" }]),
  { type: "correction", segment: 1, round: 1, instruction: { kind: "edit_part", part: "left_arm", prompt: "raise the left arm" }, accepted: true, score_before: 0.4, score_after: 0.6 },
  frames(60, 30),
  review(1, 1, "ok"),
  seg(1, "done"),
  seg(2, "generating"),
  frames(90, 30),
  review(2, 0, "ok"),
  seg(2, "done"),
  { type: "metrics", metrics: { foot_skating: 0.1 } },
];

describe("describeProgress", () => {
  it("says what each stage of a job is doing", () => {
    const labels = replay(job).map((p) => p.label);
    expect(labels[0]).toBe("Planning the motion…");
    expect(labels[2]).toBe("Generating segment 1 of 3 · 0 / 120 frames");
    expect(labels[3]).toBe("Generating segment 1 of 3 · 40 / 120 frames");
    expect(labels[4]).toBe("Reviewing segment 1 of 3 · round 1"); // all its frames in, no review yet
    expect(labels[8]).toBe("Reviewing segment 2 of 3 · round 1");
    expect(labels[9]).toMatch(/^Correcting segment 2 of 3 · round 1: /);
    expect(labels[10]).toBe("Reviewing segment 2 of 3 · round 2"); // the correction tried: checked again
    expect(labels[15]).toBe("Reviewing segment 3 of 3 · round 1");
    expect(labels[17]).toBe("Measuring the motion…");
    expect(labels[18]).toBe("Storing the motion…");
  });

  it("names the path stage when the job has one", () => {
    expect(replay(job.slice(0, 17), true).at(-1)!.label).toBe("Applying the path…");
  });

  it("moves forward and never back, and shows activity where no frames count", () => {
    const views = replay(job);
    const f = views.map((v) => v.fraction);
    for (let i = 1; i < f.length; i++) expect(f[i]).toBeGreaterThanOrEqual(f[i - 1] - 1e-9);
    expect(f.at(-1)!).toBeGreaterThan(0.9);
    expect(f.at(-1)!).toBeLessThan(1);
    expect(new Set(f).size).toBeGreaterThan(8);
    expect(views[3].busy).toBe(false); // frames arriving
    expect(views[4].busy).toBe(true); // reviewing
  });

  it("keeps the reactor's own words", () => {
    const s = { ...startStream(null, "j", "react", "actor") };
    expect(describeProgress(s).label).toBe("Starting the reactor…");
    const t = reduceStream(reduceStream(s, { type: "plan", plan: { segments: [] } }), frames(0, 10));
    expect(describeProgress(t).label).toBe("Person 2 reacting · 10 / 120 frames");
  });
});

describe("the end of a stream", () => {
  const running: StreamState = job.slice(0, 8).reduce(reduceStream, startStream(null, "job"));
  it("cancelled: the plan and every badge go", () => {
    const s = reduceStream(running, { type: "error", message: "cancelled", cancelled: true });
    expect(s).toMatchObject({ phase: "error", cancelled: true, plan: null, agent: {} });
  });
  it("failed: the plan stays, no segment says it is still generating", () => {
    const s = reduceStream(running, { type: "error", message: "generation failed at review: x", stage: "review" });
    expect(s.plan).toEqual(plan);
    expect(Object.values(s.agent).map((a) => a.status)).toEqual(["done", "stopped"]);
  });
});
