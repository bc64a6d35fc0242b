import { expect, test } from "@playwright/test";
import { hook, openStudio, shot, startGeneration } from "./studio";

// Cancel from the progress state: DELETE /api/jobs/{id}, the stream ends cancelled, the studio is
// idle again with a message, and the API's job is cancelled and stored nothing. The server runs
// one job at a time: a long job sent through the API first keeps ours waiting in the queue, so
// Cancel is pressed while the generation is certainly still in progress.
test("Cancel stops a long generation: idle studio with a message, the API job cancelled", async ({ page }, info) => {
  await openStudio(page);
  const blocker = await page.request.post("/api/jobs", {
    data: { prompt: "a person walks forward, then jumps, then dances, then sits down", persons: 1, seconds: 20 },
  });
  expect(blocker.status()).toBe(201);

  await startGeneration(page, "two people dance salsa", 2, 20);
  await expect(page.getByTestId("progress")).toBeVisible();
  await expect(page.getByTestId("generate")).toBeDisabled();
  await shot(page, "k-generating", info);
  const deleted = page.waitForResponse((r) => r.request().method() === "DELETE" && /\/api\/jobs\/[^/]+$/.test(r.url()));
  await page.getByTestId("cancel").click();
  const res = await deleted;
  expect(res.status()).toBe(200);
  const jobId = res.url().split("/").pop()!;
  expect(await res.json()).toMatchObject({ job_id: jobId, cancelled: true });

  // the UI: no progress, a clear message, no error banner, nothing on the stage, Generate enabled
  await expect(page.getByTestId("cancelled-notice")).toContainText("Generation cancelled", { timeout: 60_000 });
  await expect(page.getByTestId("progress")).toBeHidden();
  await expect(page.getByTestId("error-banner")).toBeHidden();
  await expect(page.getByTestId("generate")).toBeEnabled();
  const h = await hook(page);
  expect(h.phase).toBe("error");
  expect(h.motionId).toBeNull();
  expect(h.framesReceived).toBe(0);
  await shot(page, "k-cancelled", info);

  // the API: the job ended cancelled (its stream's last event says so), no motion stored, and
  // its motion id says why instead of "not found"
  const job = await (await page.request.get(`/api/jobs/${jobId}`)).json();
  expect(job.status).toBe("cancelled");
  const again = await (await page.request.delete(`/api/jobs/${jobId}`)).json();
  expect(again).toMatchObject({ cancelled: true, status: "cancelled" });
  expect((await page.request.get(`/api/motions/${job.motion_id}`)).status()).toBe(409);

  // and the studio works on: the next generation plays
  await page.getByTestId("persons-1").click();
  await page.getByTestId("seconds").fill("2");
  await page.getByTestId("generate").click();
  await page.waitForFunction(() => window.__interplay.phase === "done", null, { timeout: 120_000 });
  await expect(page.getByTestId("cancelled-notice")).toBeHidden();
});
