import { expect, test, type APIRequestContext, type Page } from "@playwright/test";
import { openStudio, shot, startGeneration, waitDone } from "./studio";

/** A finished motion made through the API as this page's browser (its client id header). */
async function make(request: APIRequestContext, client: string, prompt: string): Promise<string> {
  const r = await request.post("/api/jobs", { data: { prompt, persons: 1, seconds: 1 }, headers: { "X-Interplay-Client": client } });
  expect(r.status()).toBe(201);
  const job = await r.json();
  await expect
    .poll(async () => (await (await request.get(`/api/jobs/${job.job_id}`)).json()).status, { timeout: 120_000 })
    .toBe("done");
  return job.motion_id;
}

const listed = (page: Page) => page.getByTestId("library-item");

// "My motions": what this browser made, newest first, from the server — after a reload, in
// another tab, and nowhere else (another browser sees none); a click opens one.
test("My motions lists the last five motions after a reload; a click opens one", async ({ page, context, browser }, info) => {
  await openStudio(page);
  await expect(page.getByTestId("library-empty")).toBeVisible();
  await startGeneration(page, "a person waves", 1, 1); // through the UI: the page sends its id
  const first = await waitDone(page);
  await expect(listed(page).first()).toHaveAttribute("data-motion-id", first.motionId!);

  const client = await page.evaluate(() => localStorage.getItem("interplay-client"));
  expect(client).toMatch(/^[A-Za-z0-9_-]{22}$/);
  const prompts = ["a person walks forward", "a person jumps", "a person sits down", "a person runs forward", "a person kicks"];
  const ids: string[] = [];
  for (const p of prompts) ids.push(await make(page.request, client!, p));

  await page.reload();
  await expect(page.getByTestId("legend")).toBeVisible();
  await expect(listed(page)).toHaveCount(6);
  const newest = [...ids].reverse();
  for (let i = 0; i < 5; i++) {
    await expect(listed(page).nth(i)).toHaveAttribute("data-motion-id", newest[i]);
    await expect(listed(page).nth(i).getByTestId("library-prompt")).toHaveText(prompts[4 - i]);
    await expect(listed(page).nth(i)).toContainText("1.0 s · 1 person");
  }
  await expect(listed(page).nth(5)).toHaveAttribute("data-motion-id", first.motionId!);
  // each has a first-frame pose: 21 bones
  await expect(listed(page).first().locator("line")).toHaveCount(21);
  await shot(page, "l-my-motions", info);

  // a click opens it (and names it in the URL)
  await listed(page).nth(2).click();
  await page.waitForFunction((id) => window.__interplay.motionId === id && window.__interplay.phase === "done", newest[2]);
  await expect(page).toHaveURL(new RegExp(`/m/${newest[2]}$`));
  await expect(listed(page).nth(2)).toHaveAttribute("aria-current", "true");
  await shot(page, "l-opened", info);

  // another tab of this browser: the same list
  const tab = await context.newPage();
  await openStudio(tab);
  await expect(listed(tab)).toHaveCount(6);
  await expect(listed(tab).first()).toHaveAttribute("data-motion-id", newest[0]);
  await tab.close();

  // another browser: its own (empty) list, never this one's
  const other = await browser.newContext();
  const stranger = await other.newPage();
  await openStudio(stranger);
  await expect(stranger.getByTestId("library-empty")).toBeVisible();
  await expect(listed(stranger)).toHaveCount(0);
  await other.close();
});
