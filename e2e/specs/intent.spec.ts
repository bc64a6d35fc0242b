import { expect, test, type Page } from "@playwright/test";
import { openStudio, shot, startGeneration, waitDone } from "./studio";

/** Count POST /api/jobs requests the page sends. */
function countJobs(page: Page): { n: number } {
  const c = { n: 0 };
  page.on("request", (r) => {
    if (r.method() === "POST" && new URL(r.url()).pathname === "/api/jobs") c.n++;
  });
  return c;
}

/** Record every text the progress label shows, as it changes. */
async function recordLabels(page: Page): Promise<void> {
  await page.evaluate(() => {
    const w = window as unknown as { __labels: string[] };
    w.__labels = [];
    new MutationObserver(() => {
      const t = document.querySelector('[data-testid="progress-label"]')?.textContent?.replace(/ · \d+ s$/, "");
      if (t && w.__labels.at(-1) !== t) w.__labels.push(t);
    }).observe(document.body, { subtree: true, childList: true, characterData: true });
  });
}

// One job per intent: a double click on Generate sends one job; while it runs, Generate (and
// Enter) for the same request send nothing; the progress says what each stage is doing.
test("a double click on Generate sends one job; every stage says what it is doing", async ({ page }, info) => {
  await openStudio(page);
  const jobs = countJobs(page);
  await recordLabels(page);
  await page.getByTestId("prompt").fill("a person walks forward, then jumps, then sits down");
  await page.getByTestId("persons-1").click();
  await page.getByTestId("seconds").fill("6");
  await page.getByTestId("generate").dblclick();
  await expect(page.getByTestId("progress")).toBeVisible();
  await expect(page.getByTestId("generate")).toBeDisabled();
  await page.getByTestId("prompt").press("Enter"); // the same request again: nothing
  await page.waitForTimeout(500);
  expect(jobs.n).toBe(1);
  await shot(page, "j-one-job", info);
  await waitDone(page);
  expect(jobs.n).toBe(1);
  const labels = await page.evaluate(() => (window as unknown as { __labels: string[] }).__labels);
  info.annotations.push({ type: "progress labels", description: labels.join(" | ") });
  expect(labels.some((l) => /^Generating segment 1 of 3 · \d+ \/ 120 frames$/.test(l))).toBe(true);
  expect(labels.some((l) => /^Generating segment 3 of 3/.test(l))).toBe(true);
  expect(labels.some((l) => /^Reviewing segment \d of 3 · round \d$/.test(l))).toBe(true);
  // a changed request may go (it would replace a running one); the same one again is a new job
  await expect(page.getByTestId("generate")).toBeEnabled();
});

// Cancel while the job is running (a segment already says "generating"): every badge goes.
test("cancel clears every badge of the running job", async ({ page }, info) => {
  await openStudio(page);
  // Captured clips make a segment in tens of milliseconds and this job's eight segments, each
  // reviewed, take about a second: Cancel is pressed from the page itself the moment a
  // segment's badge says "generating" (a test driver's round trip could come after the end).
  await page.evaluate(() => {
    const w = window as unknown as { __cancelledAt: string | null };
    w.__cancelledAt = null;
    const seen = new MutationObserver(() => {
      const badge = document.querySelector(".badge--generating");
      const cancel = document.querySelector<HTMLButtonElement>('[data-testid="cancel"]');
      if (badge && cancel && !w.__cancelledAt) {
        w.__cancelledAt = badge.getAttribute("data-testid");
        cancel.click();
        seen.disconnect();
      }
    });
    seen.observe(document.body, { subtree: true, childList: true, characterData: true, attributes: true });
  });
  await startGeneration(page, "a person walks forward, then jumps, then dances, then sits down, then stands up, " +
    "then runs in a circle, then crawls, then waves with the right hand", 1, 20);
  await page.waitForFunction(() => (window as unknown as { __cancelledAt: string | null }).__cancelledAt !== null,
    null, { timeout: 60_000 });
  await expect(page.getByTestId("cancelled-notice")).toBeVisible({ timeout: 60_000 });
  await expect(page.locator('[data-testid^="segment-status-"]')).toHaveCount(0);
  await expect(page.locator(".badge--generating")).toHaveCount(0);
  await expect(page.getByTestId("progress")).toBeHidden();
  await expect(page.getByTestId("generate")).toBeEnabled();
  await expect(page).toHaveURL(/\/$/);
  await shot(page, "j-cancelled-no-badges", info);
});
