import { expect, test } from "@playwright/test";
import { hook, openStudio, shot, startGeneration, waitDone } from "./studio";

test("the agent timeline shows the plan, then review rounds as they stream; a segment re-runs", async ({ page }, info) => {
  await openStudio(page);
  // count review cards as they appear, before the stream is done
  await page.evaluate(() => {
    const w = window as unknown as { __reviewsBeforeDone: number };
    w.__reviewsBeforeDone = -1;
    new MutationObserver(() => {
      if (window.__interplay.phase === "generating")
        w.__reviewsBeforeDone = document.querySelectorAll('[data-testid="review"]').length;
    }).observe(document.body, { subtree: true, childList: true });
  });
  await startGeneration(page, "a person walks forward then jumps", 1, 4);
  await expect(page.getByTestId("segment-0")).toBeVisible();
  const done = await waitDone(page);
  const reviews = page.getByTestId("review");
  await expect(reviews.first()).toBeVisible();
  expect(await page.evaluate(() => window.__interplay.agentReviews)).toBeGreaterThan(0);
  expect(await page.evaluate(() => (window as unknown as { __reviewsBeforeDone: number }).__reviewsBeforeDone)).toBeGreaterThan(0);
  await expect(reviews.first()).toContainText(/score \d\.\d\d/);
  await expect(reviews.first()).toContainText("body:");
  await expect(page.getByTestId("segment-status-0")).toContainText("done");
  await shot(page, "h-agent-timeline", info);

  // the stored motion shows the same rounds in a fresh page (from its stored review)
  await page.reload();
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await expect(page.getByTestId("review").first()).toBeVisible();

  // re-run the first segment: a new job with its prompt
  // (the page still says "done" for the old motion until the new job is created: wait for the
  // new motion, not just for "done")
  await page.getByTestId("rerun-0").click();
  await page.waitForFunction((old) => window.__interplay.motionId !== old && ["done", "error"].includes(window.__interplay.phase), done.motionId, { timeout: 150_000 });
  const again = await waitDone(page);
  expect(again.motionId).not.toBe(done.motionId);
  expect((await hook(page)).phase).toBe("done");
});
