import { expect, test } from "@playwright/test";
import { hook, motionOf, openStudio, shot, startGeneration, waitDone } from "./studio";

const LONG = { prompt: "a person walks forward, then jumps, then dances, then sits down", persons: 1, seconds: 20 };

// A job in flight survives a reload: the URL holds its id (/?job=…&motion=…); the reloaded page
// reattaches to its stream (which replays every event from the start) and the motion appears.
// The server runs one job at a time: six long API jobs queued first keep the page's job waiting
// (one takes only seconds on a quiet machine), so the reload surely happens before it is done;
// once the page has reattached they are cancelled.
test("reload mid-generation: the page follows the job again and the motion appears", async ({ page }, info) => {
  await openStudio(page);
  const blockers: string[] = [];
  for (let i = 0; i < 6; i++) {
    const r = await page.request.post("/api/jobs", { data: LONG });
    expect(r.status()).toBe(201);
    blockers.push((await r.json()).job_id);
  }
  await startGeneration(page, "a person walks forward", 1, 2);
  await expect(page).toHaveURL(/\/\?job=[A-Za-z0-9_-]+&motion=[A-Za-z0-9_-]+$/);
  const url = new URL(page.url());
  const jobId = url.searchParams.get("job")!, motionId = url.searchParams.get("motion")!;
  expect((await hook(page)).phase).toMatch(/connecting|generating/);
  expect(["queued", "running"]).toContain((await (await page.request.get(`/api/jobs/${jobId}`)).json()).status);

  await page.reload();
  await expect(page.getByTestId("legend")).toBeVisible();
  // reattached to the same job, still in progress, with Cancel at hand
  await page.waitForFunction((id) => window.__interplay.jobId === id, jobId);
  expect((await hook(page)).phase).toMatch(/connecting|generating/);
  await expect(page.getByTestId("progress")).toBeVisible();
  await expect(page.getByTestId("generate")).toBeDisabled();
  await shot(page, "q-reattached", info);
  for (const b of blockers) await page.request.delete(`/api/jobs/${b}`); // let it run now

  const done = await waitDone(page);
  expect(done.motionId).toBe(motionId);
  expect(done.framesReceived).toBe(40);
  await expect(page).toHaveURL(new RegExp(`/m/${motionId}$`));
  const stored = await motionOf(page, motionId);
  expect(stored.people[0].joints[0][0][0]).toBeCloseTo(done.firstFrame[0][0][0], 4);
  await expect(page.locator(`[data-testid="library-item"][data-motion-id="${motionId}"]`)).toBeVisible();

  // the job's old URL, once it is done, opens the stored motion
  await page.goto(`/?job=${jobId}&motion=${motionId}`);
  await page.waitForFunction((id) => window.__interplay.motionId === id && window.__interplay.phase === "done", motionId);
  await expect(page).toHaveURL(new RegExp(`/m/${motionId}$`));
});

test("a job the server no longer knows: the page says so and shows My motions", async ({ page }, info) => {
  await openStudio(page, `/?job=${"g".repeat(22)}&motion=${"h".repeat(22)}`);
  await expect(page.getByTestId("library-notice")).toContainText("no longer on the server");
  await expect(page.getByTestId("library-toggle")).toHaveAttribute("aria-expanded", "true");
  await expect(page.getByTestId("my-motions")).toBeInViewport();
  await expect(page.getByTestId("library-empty")).toBeVisible(); // a fresh browser made none
  await expect(page).toHaveURL(/\/$/);
  await expect(page.getByTestId("error-banner")).toBeHidden();
  expect((await hook(page)).phase).toBe("idle");
  await shot(page, "q-job-gone", info);
});
