import { expect, test, type Page } from "@playwright/test";
import { hook, openStudio, shot, startGeneration, waitDone } from "./studio";

/** Every POST /api/jobs the page sends from now on. */
function jobPosts(page: Page): unknown[] {
  const posts: unknown[] = [];
  page.on("request", (r) => {
    if (r.method() === "POST" && new URL(r.url()).pathname === "/api/jobs") posts.push(r.postDataJSON());
  });
  return posts;
}

// Issue 26, point 5: the form keeps to the API's limits (read from its schema) on the page —
// a long prompt is kept and said to be too long (never cut), seconds out of 1–20 are said as
// typed, an empty prompt is never sent — and whatever error arrives is plain sentences, gone
// once the form is edited.
test("the prompt form keeps to the API's limits and says why in plain words", async ({ page }, info) => {
  await openStudio(page);
  const posts = jobPosts(page);
  const problems = page.getByTestId("form-problems");
  const count = page.getByTestId("prompt-count");
  await expect(count).toHaveText("0 / 500");
  await expect(problems).toHaveCount(0); // a fresh page points nothing out

  // an empty prompt: nothing sent, one sentence
  await page.getByTestId("generate").click();
  await expect(problems).toHaveText("Type what the people do first.");

  // 10,000 characters pasted: kept as they are (not cut to 500), the counter and the sentence say so
  const long = "a person walks forward and waves ".repeat(304).slice(0, 10_000);
  await page.getByTestId("prompt").fill(long);
  expect((await page.getByTestId("prompt").inputValue()).length).toBe(10_000);
  await expect(count).toHaveText("10,000 / 500");
  await expect(count).toHaveClass(/prompt-count--over/);
  await expect(problems).toHaveText("The prompt is 10,000 characters long; the limit is 500. Shorten it by 9,500.");
  await expect(page.getByTestId("prompt")).toHaveAttribute("aria-invalid", "true");
  await page.getByTestId("generate").click();
  await shot(page, "lim-long-prompt", info);

  // seconds 0, −3, 999: said as typed, never sent
  await page.getByTestId("prompt").fill("a person walks forward");
  await expect(problems).toHaveCount(0);
  for (const [typed, words] of [["0", "0 is too short"], ["-3", "-3 is too short"], ["999", "999 is too long"]]) {
    await page.getByTestId("seconds").fill(typed);
    await expect(problems).toHaveText(`The length must be from 1 to 20 seconds; ${words}.`);
    await expect(page.getByTestId("seconds")).toHaveAttribute("aria-invalid", "true");
    await page.getByTestId("generate").click();
  }
  await shot(page, "lim-seconds", info);
  await page.getByTestId("seconds").fill("1");
  await expect(problems).toHaveCount(0);
  expect(posts).toEqual([]);
  expect((await hook(page)).phase).toBe("idle");

  // the API's own 422 is plain words too (for API clients), and the banner makes sentences of it
  const api = await page.request.post("/api/jobs", { data: { prompt: "a person walks", seconds: 999, persons: 3 } });
  expect(api.status()).toBe(422);
  const detail = (await api.json()).detail;
  expect(detail).toBe("persons must be 1 or 2 (got 3); seconds must be at most 20 (got 999)");
  // whatever error arrives (here that one, answered to the page's own Generate) is sentences
  await page.route("**/api/jobs", (route) =>
    route.request().method() === "POST" ? route.fulfill({ status: 422, contentType: "application/json", body: JSON.stringify({ detail }) }) : route.fallback(),
  );
  await page.getByTestId("generate").click();
  const banner = page.getByTestId("error-banner");
  await expect(banner).toHaveText("!The number of people must be 1 or 2 (got 3). The length in seconds must be at most 20 (got 999).×");
  await shot(page, "lim-banner", info);
  // an older server's pydantic wording is reworded the same way
  await page.unroute("**/api/jobs");
  await page.route("**/api/jobs", (route) =>
    route.request().method() === "POST"
      ? route.fulfill({ status: 422, contentType: "application/json", body: JSON.stringify({ detail: "seconds: Input should be less than or equal to 20" }) })
      : route.fallback(),
  );
  await page.getByTestId("prompt").fill("a person walks forward slowly");
  await expect(banner).toHaveCount(0); // editing the form clears the stale banner
  await page.getByTestId("generate").click();
  await expect(banner).toContainText("The length in seconds must be at most 20.");
  await expect(banner).not.toContainText("Input should");

  // a valid prompt typed: the old banner goes at once, and the next Generate runs
  await page.unroute("**/api/jobs");
  await startGeneration(page, "a person waves", 1, 1);
  await expect(banner).toHaveCount(0);
  await waitDone(page);
  expect(posts.at(-1)).toMatchObject({ prompt: "a person waves", persons: 1, seconds: 1 });
});
