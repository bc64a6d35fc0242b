import { describe, expect, it } from "vitest";
import { MAX_TRIES, retryStream, type RetryHooks } from "./retry";
import { reduceStream, startStream } from "./stream";
import { describeProgress } from "./progress";

function hooks(answerAt: number, current = () => true) {
  const log: string[] = [];
  let asked = 0;
  let slept = 0;
  const h: RetryHooks = {
    current,
    show: (s) => log.push(s ? `${s.attempt}:${s.nextInS}` : "-"),
    reachable: async () => ++asked >= answerAt,
    resume: async () => void log.push("resume"),
    giveUp: () => void log.push("give up"),
    sleep: async () => void slept++,
  };
  return { h, log, asked: () => asked, slept: () => slept };
}

describe("retryStream", () => {
  it("backs off 1, 1, 2, 3 s … and resumes once the server answers", async () => {
    const t = hooks(4);
    await retryStream(t.h);
    expect(t.log).toEqual(["1:1", "1:0", "2:1", "2:0", "3:2", "3:1", "3:0", "4:3", "4:2", "4:1", "4:0", "-", "resume"]);
    expect(t.slept()).toBe(1 + 1 + 2 + 3);
  });

  it("stops when the page moved on, and gives up after MAX_TRIES", async () => {
    let n = 0;
    const moved = hooks(1, () => ++n < 2);
    await retryStream(moved.h);
    expect(moved.log).not.toContain("resume");
    const never = hooks(Infinity);
    await retryStream(never.h);
    expect(never.asked()).toBe(MAX_TRIES);
    expect(never.log.slice(-2)).toEqual(["-", "give up"]);
  });
});

describe("restart and replace events", () => {
  it("a restart drops what the dead attempt streamed; replace leaves the counts; progress says it is reconnecting", () => {
    let s = reduceStream(startStream(null, "job"), { type: "plan", plan: { segments: [{ prompt: "walk", start: 0, end: 40, persons: 1 }] } });
    s = reduceStream(s, { type: "frames", start: 0, total: 40, people: [[]] });
    s = reduceStream(s, { type: "segment", index: 0, status: "generating", generator: "retrieve_edit" });
    const replaced = reduceStream(s, { type: "replace", start: 0, people: [[]], cause: "correction", segment: 0 });
    expect(replaced).toBe(s);
    const again = reduceStream(s, { type: "restart", attempt: 2, reason: "the process … stopped" });
    expect(again).toMatchObject({ phase: "generating", plan: null, received: 0, agent: {}, jobId: "job", attempt: 2 });
    expect(describeProgress({ ...again, reconnecting: { attempt: 3, nextInS: 2 } }).label).toBe("The server is not answering — trying again in 2 s (try 3)");
  });
});
