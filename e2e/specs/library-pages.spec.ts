import { expect, test, type APIRequestContext } from "@playwright/test";
import { openStudio, shot, startGeneration, waitDone } from "./studio";

/** `prompts` made through the API as one browser (its client id), a few at a time (the server
 * queues at most 16 jobs); their motion ids, in the order made. */
async function makeMany(request: APIRequestContext, client: string, prompts: string[]): Promise<string[]> {
  const ids: string[] = [];
  for (let i = 0; i < prompts.length; i += 8) {
    const jobs = [];
    for (const prompt of prompts.slice(i, i + 8)) {
      // one at a time: the order made is the order listed
      const r = await request.post("/api/jobs", { data: { prompt, persons: 1, seconds: 1, seed: 1 }, headers: { "X-Interplay-Client": client } });
      expect(r.status(), await r.text()).toBe(201);
      jobs.push(await r.json());
    }
    for (const job of jobs) {
      await expect
        .poll(async () => (await (await request.get(`/api/jobs/${job.job_id}`)).json()).status, { timeout: 120_000 })
        .toBe("done");
      ids.push(job.motion_id);
    }
  }
  return ids;
}

const listed = (page: import("@playwright/test").Page) => page.getByTestId("library-item");

// Issue 26, points 6/7: My motions was the newest 20, silently, and only in this browser. Now it
// pages through everything stored for the browser's client id ("20 of 23 shown", "Show 3
// more"), and a link opens the same library in another browser, where what is made is added.
test("My motions pages through every motion and opens in another browser by link", async ({ page, browser }, info) => {
  await openStudio(page);
  await expect(page.getByTestId("library-empty")).toBeVisible();
  const client = await page.evaluate(() => localStorage.getItem("interplay-client"));
  expect(client).toMatch(/^[A-Za-z0-9_-]{22}$/);
  const ids = await makeMany(page.request, client!, Array.from({ length: 23 }, (_, i) => `a person walks ${i + 1} steps`));
  const newest = [...ids].reverse();

  await page.reload();
  await expect(listed(page)).toHaveCount(20);
  await expect(page.getByTestId("library-count")).toHaveText("20 of 23 shown");
  await expect(listed(page).first()).toHaveAttribute("data-motion-id", newest[0]);
  await page.getByTestId("library-more").click();
  await expect(listed(page)).toHaveCount(23);
  await expect(page.getByTestId("library-count")).toHaveText("All 23 shown");
  await expect(page.getByTestId("library-more")).toHaveCount(0);
  expect(await page.evaluate(() => window.__interplay.library)).toEqual(newest);
  await listed(page).last().scrollIntoViewIfNeeded();
  await shot(page, "lp-all-pages", info);
  // the oldest opens as any other
  await listed(page).last().click();
  await page.waitForFunction((id) => window.__interplay.motionId === id, ids[0]);

  // the link for another browser
  await page.getByTestId("library-link").click();
  const url = await page.getByTestId("library-link-url").inputValue();
  expect(url).toBe(`${new URL(page.url()).origin}/?library=${client}`);
  await shot(page, "lp-link", info);

  // another browser (its own storage) opens the link: the same library, the address bar cleaned
  const other = await browser.newContext();
  const there = await other.newPage();
  await there.goto(url);
  await expect(there.getByTestId("legend")).toBeVisible();
  await expect(listed(there)).toHaveCount(20);
  await expect(there.getByTestId("library-count")).toHaveText("20 of 23 shown");
  await expect(listed(there).first()).toHaveAttribute("data-motion-id", newest[0]);
  await expect(there.getByTestId("library-notice")).toContainText("now shows the library from the link");
  await expect(there).toHaveURL(/\/$/);
  expect(await there.evaluate(() => localStorage.getItem("interplay-client"))).toBe(client);
  await shot(there, "lp-other-browser", info);
  // what it makes there is added to the same library, and kept across its reloads
  await startGeneration(there, "a person waves from the other browser", 1, 1);
  const made = await waitDone(there);
  await expect(listed(there).first()).toHaveAttribute("data-motion-id", made.motionId!);
  await there.reload();
  await expect(there.getByTestId("library-count")).toHaveText("20 of 24 shown");
  await other.close();

  // … and shows in the first browser too
  await page.reload();
  await expect(listed(page).first()).toHaveAttribute("data-motion-id", made.motionId!);
  await expect(page.getByTestId("library-count")).toHaveText("20 of 24 shown");
});
