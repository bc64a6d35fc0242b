// A job's stream that drops is followed again (api/retry.ts, studio's reconnect → resumeJob),
// with the network stubbed and the back-off on fake timers. The page never stays "connecting"
// with nothing left to wait on: not when the server cannot be reached at the moment it is asked
// again, not when the job ended meanwhile without a motion, not when a new Generate replaced
// the job; and a retry of an earlier job never takes the stage back from a newer Generate.
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { FakeSocket, loadStudio as studio, stubPage, unstubPage } from "./test/fakeStudioPage";

type Answer = { status: number; body: unknown } | "unreachable" | Promise<{ status: number; body: unknown }>;
/** GET /api/jobs/{id}: the answers to give, in turn (the last one again when they run out). */
let jobAnswers: Record<string, Answer[]> = {};
/** GET /api/motions/{id}: the stored motions. */
let motions: Record<string, object> = {};
let calls: { method: string; url: string }[] = [];
let jobs = 0;

const running = (id: string) => ({ status: 200, body: { job_id: id, motion_id: `m-${id}`, status: "running", events: 3, stream: `/api/jobs/${id}/stream`, attempts: 1 } });
const motion = (id: string) => ({
  id, prompt: "a person walks forward", persons: 1, seconds: 0.1, seed: 1, fps: 20, skeleton: "smpl22",
  people: [{ joints: [Array.from({ length: 22 }, () => [0, 1, 0])] }],
  plan: null, metrics: null, highlights: null, parent_id: null, edit: null, review: null, created_at: null,
});
const ended = (id: string, status: "failed" | "cancelled", reason: string) => ({ status: 200, body: { ...running(id).body, status, reason } });

beforeEach(() => {
  vi.useFakeTimers();
  calls = [];
  jobs = 0;
  jobAnswers = {};
  motions = {};
  stubPage();
  vi.stubGlobal(
    "fetch",
    vi.fn(async (url: string, init?: RequestInit) => {
      const method = init?.method ?? "GET";
      calls.push({ method, url });
      if (method === "POST" && url === "/api/jobs") {
        jobs++;
        const body = { job_id: `job${jobs}`, motion_id: `m-job${jobs}`, stream: `/api/jobs/job${jobs}/stream`, seed: 1 };
        return new Response(JSON.stringify(body), { status: 201 });
      }
      if (method === "DELETE") return new Response(JSON.stringify({ cancelled: true }), { status: 200 });
      const job = /^\/api\/jobs\/(\w+)$/.exec(url)?.[1];
      const stored = /^\/api\/motions\/([\w-]+)$/.exec(url)?.[1];
      if (stored) return new Response(JSON.stringify(motions[stored] ?? { detail: "no motion" }), { status: motions[stored] ? 200 : 404 });
      if (job) {
        const queue = jobAnswers[job] ?? [{ status: 404, body: { detail: "no job" } }];
        const answer = await (queue.length > 1 ? queue.shift()! : queue[0]);
        if (answer === "unreachable") throw new TypeError("Failed to fetch");
        return new Response(JSON.stringify(answer.body), { status: answer.status });
      }
      return new Response(JSON.stringify({ motions: [], jobs: [] }), { status: 200 });
    }),
  );
});

afterEach(() => {
  vi.useRealTimers();
  unstubPage();
});

/** Let the retry loop's timers and the stubbed requests run. */
const settle = (ms = 20_000) => vi.advanceTimersByTimeAsync(ms);

describe("a dropped stream followed again", () => {
  it("follows the job again from its first event", async () => {
    const { generate, useStudio } = await studio();
    await generate();
    jobAnswers.job1 = [running("job1")];
    FakeSocket.opened[0].drop();
    expect(useStudio.getState().stream.reconnecting).toEqual({ attempt: 1, nextInS: 1 });
    await settle();
    expect(FakeSocket.opened).toHaveLength(2);
    expect(FakeSocket.opened[1].url).toBe("ws://studio/api/jobs/job1/stream");
    FakeSocket.opened[1].send({ type: "plan", plan: { segments: [] } });
    expect(useStudio.getState().stream).toMatchObject({ phase: "generating", jobId: "job1" });
    expect(useStudio.getState().stream.reconnecting ?? null).toBeNull();
  });

  it("the server unreachable when the job is asked for again: it keeps trying, it does not stop at 'connecting'", async () => {
    const { generate, useStudio } = await studio();
    await generate();
    // answers the retry's first question, is gone for the follow-up, then back
    jobAnswers.job1 = [running("job1"), "unreachable", running("job1")];
    FakeSocket.opened[0].drop();
    await settle();
    expect(useStudio.getState().error).toBeNull();
    expect(FakeSocket.opened).toHaveLength(2);
    FakeSocket.opened[1].send({ type: "plan", plan: { segments: [] } });
    expect(useStudio.getState().stream.phase).toBe("generating");
  });

  it("the job ended meanwhile without a motion: the stage stops waiting, the library says why", async () => {
    const { generate, useStudio } = await studio();
    const { useLibrary } = await import("./library");
    await generate();
    jobAnswers.job1 = [ended("job1", "failed", "out of memory")];
    FakeSocket.opened[0].drop();
    await settle();
    expect(useStudio.getState().stream.phase).toBe("idle");
    expect(useLibrary.getState().notice).toContain("out of memory");
    expect(window.location.pathname + window.location.search).toBe("/");
  });

  it("the job sent with the drawn path found done: its motion is shown and the path is used up", async () => {
    const { generate, useStudio } = await studio();
    const points: [number, number][] = [[0, 0], [1, 1], [2, 1]];
    useStudio.getState().setPath({ points });
    await generate();
    expect(useStudio.getState().path.points).toBe(points); // pending until the job is done
    jobAnswers.job1 = [{ status: 200, body: { ...running("job1").body, status: "done" } }];
    motions["m-job1"] = motion("m-job1");
    FakeSocket.opened[0].drop();
    await settle();
    expect(useStudio.getState().stream).toMatchObject({ phase: "done", motionId: "m-job1" });
    expect(useStudio.getState().path.points).toEqual([]);
    expect(window.location.pathname).toBe("/m/m-job1");
  });

  it("a new Generate while the earlier job is asked for again: the new job keeps the stage", async () => {
    const { generate, useStudio } = await studio();
    await generate();
    let answer!: (a: { status: number; body: unknown }) => void;
    const late = new Promise<{ status: number; body: unknown }>((ok) => (answer = ok));
    jobAnswers.job1 = [running("job1"), late];
    FakeSocket.opened[0].drop();
    await settle(1_500); // the retry asked (the server answers) and follows it: its question hangs
    useStudio.setState({ prompt: "a person jumps" });
    await generate();
    expect(useStudio.getState().stream).toMatchObject({ phase: "connecting", jobId: "job2" });
    answer(running("job1")); // the earlier job's answer comes in after the new job started
    await settle();
    expect(useStudio.getState().stream).toMatchObject({ phase: "connecting", jobId: "job2" });
    const job2 = FakeSocket.opened.find((s) => s.url.endsWith("/job2/stream"))!;
    expect(job2.closed).toBe(false);
    expect(FakeSocket.opened.filter((s) => s.url.endsWith("/job1/stream"))).toHaveLength(1);
    expect(window.location.search).toBe("?job=job2&motion=m-job2");
    job2.send({ type: "plan", plan: { segments: [] } });
    expect(useStudio.getState().stream).toMatchObject({ phase: "generating", jobId: "job2" });
  });

  it("a changed request whose POST fails: the job it cancelled does not stay 'generating'", async () => {
    const { generate, useStudio } = await studio();
    await generate();
    FakeSocket.opened[0].send({ type: "plan", plan: { segments: [] } });
    vi.mocked(fetch).mockImplementationOnce(async (url, init) => {
      calls.push({ method: init?.method ?? "GET", url: String(url) });
      return new Response(JSON.stringify({ ok: true }), { status: 200 });
    }); // the cancel
    vi.mocked(fetch).mockImplementationOnce(async () => new Response(JSON.stringify({ detail: "16 jobs are already waiting" }), { status: 429 }));
    useStudio.setState({ prompt: "a person jumps" });
    await generate();
    expect(calls.some((c) => c.method === "DELETE" && c.url === "/api/jobs/job1")).toBe(true);
    expect(["connecting", "generating"]).not.toContain(useStudio.getState().stream.phase);
    expect(useStudio.getState().error).toBe("16 jobs are already waiting");
  });
});
