// One job per intent, driven through `generate` with the network stubbed: a double click
// sends one POST /api/jobs, the same request while it runs sends none, a changed request
// cancels the running job and starts its own; the job's URL is pushed for a reload.
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { FakeSocket, loadStudio as studio, stubPage, unstubPage } from "./test/fakeStudioPage";

let calls: { method: string; url: string; headers: Record<string, string> }[] = [];
let jobs = 0;

beforeEach(() => {
  calls = [];
  jobs = 0;
  stubPage();
  vi.stubGlobal(
    "fetch",
    vi.fn(async (url: string, init?: RequestInit) => {
      calls.push({ method: init?.method ?? "GET", url, headers: (init?.headers ?? {}) as Record<string, string> });
      await new Promise((r) => setTimeout(r, 5)); // the POST takes a moment: a second click comes meanwhile
      if (init?.method === "POST" && url === "/api/jobs") {
        jobs++;
        const body = { job_id: `job${jobs}`, motion_id: `motion${jobs}`, stream: `/api/jobs/job${jobs}/stream`, seed: 1 };
        return new Response(JSON.stringify(body), { status: 201 });
      }
      if (init?.method === "DELETE") return new Response(JSON.stringify({ cancelled: true }), { status: 200 });
      return new Response(JSON.stringify({ motions: [] }), { status: 200 });
    }),
  );
});

afterEach(unstubPage);

const posts = () => calls.filter((c) => c.method === "POST" && c.url === "/api/jobs");

describe("generate: one job per intent", () => {
  it("a double click sends one job, with this browser's id; the URL names the job", async () => {
    const { generate, generateBlocked, useStudio } = await studio();
    const first = generate();
    expect(generateBlocked()).toBe(true); // starting: the button is disabled at once
    await Promise.all([first, generate()]);
    expect(posts()).toHaveLength(1);
    expect(posts()[0].headers["X-Interplay-Client"]).toMatch(/^[A-Za-z0-9_-]{22}$/);
    expect(window.history.pushState).toHaveBeenCalledWith(null, "", "/?job=job1&motion=motion1");
    expect(useStudio.getState().stream).toMatchObject({ phase: "connecting", jobId: "job1" });
    // running: the same request again sends nothing
    expect(generateBlocked()).toBe(true);
    await generate();
    expect(posts()).toHaveLength(1);
  });

  it("a changed request cancels the running job and starts its own", async () => {
    const { generate, generateBlocked, useStudio } = await studio();
    await generate();
    useStudio.setState({ prompt: "a person jumps" });
    expect(generateBlocked()).toBe(false);
    await generate();
    expect(posts()).toHaveLength(2);
    expect(calls.some((c) => c.method === "DELETE" && c.url === "/api/jobs/job1")).toBe(true);
    expect(useStudio.getState().stream.jobId).toBe("job2");
  });

  it("done: the job's URL becomes the motion's; cancelled: the plain studio, no badges", async () => {
    const { generate, generateBlocked, useStudio } = await studio();
    await generate();
    const ws = FakeSocket.opened.at(-1)!;
    ws.send({ type: "plan", plan: { segments: [{ prompt: "a person walks forward", start: 0, end: 40, persons: [0] }] } });
    ws.send({ type: "segment", index: 0, status: "generating", generator: "spam" });
    ws.send({ type: "error", message: "cancelled", cancelled: true });
    expect(useStudio.getState().stream).toMatchObject({ phase: "error", plan: null, agent: {} });
    expect(window.location.pathname + window.location.search).toBe("/");
    expect(generateBlocked()).toBe(false);
    await generate();
    const ws2 = FakeSocket.opened.at(-1)!;
    ws2.send({ type: "done", motion_id: "motion2", frames: 40 });
    expect(window.location.pathname + window.location.search).toBe("/m/motion2");
    expect(useStudio.getState().motionId).toBe("motion2");
  });
});
