// My motions lists this browser's generations that made no motion — a cancelled one with Retry,
// a running one with Follow (issue 26.2): Retry sends the same request again and its motion
// appears in My motions.
import { expect, test } from "@playwright/test";
import { openStudio, shot, waitDone } from "./studio";

const LONG = { prompt: "a person walks forward, then jumps, then dances, then sits down", persons: 1, seconds: 20 };

test("a cancelled generation is listed with Retry, and Retry makes its motion", async ({ page }, info) => {
  await openStudio(page);
  const client = await page.evaluate(() => localStorage.getItem("interplay-client"));
  expect(client).toBeTruthy();
  const headers = { "X-Interplay-Client": client! };
  const post = async (data: object) => (await page.request.post("/api/jobs", { data, headers })).json();
  const first = await post(LONG);
  const second = await post({ ...LONG, prompt: "a person jumps twice", seconds: 3, seed: 7 });
  const third = await post(LONG);
  expect((await (await page.request.delete(`/api/jobs/${second.job_id}`)).json()).cancelled).toBe(true);
  await expect.poll(async () => (await (await page.request.get(`/api/jobs/${second.job_id}`)).json()).status).toBe("cancelled");
  await page.reload();
  const row = page.locator(`[data-testid="library-job"][data-job-id="${second.job_id}"]`);
  await expect(row).toContainText("a person jumps twice");
  await expect(row).toContainText("cancelled");
  await expect(row).toHaveAttribute("data-status", "cancelled");
  // the long ones are listed while they wait or run (Follow), and leave the list once done
  await expect(page.getByTestId("library-jobs")).toBeVisible();
  await shot(page.getByTestId("my-motions"), "j-my-jobs", info);
  for (const j of [first, third]) await expect.poll(async () => (await (await page.request.get(`/api/jobs/${j.job_id}`)).json()).status, { timeout: 120_000 }).toBe("done");

  await row.getByTestId("job-retry").click();
  const done = await waitDone(page);
  const stored = await (await page.request.get(`/api/motions/${done.motionId}`)).json();
  expect(stored).toMatchObject({ prompt: "a person jumps twice", seconds: 3, seed: 7 });
  await expect(page.locator(`[data-testid="library-item"][data-motion-id="${done.motionId}"]`)).toBeVisible();
  await expect(page.getByTestId("seed")).toHaveValue("7");
});
