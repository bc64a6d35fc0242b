import { expect, test, type APIRequestContext } from "@playwright/test";
import { hook, openStudio, shot } from "./studio";

/** Make a motion through the API (POST a job, poll until it is stored); returns its id. */
async function makeMotion(request: APIRequestContext, prompt: string, persons: 1 | 2, seconds: number) {
  const res = await request.post("/api/jobs", { data: { prompt, persons, seconds } });
  expect(res.status()).toBe(201);
  const { motion_id } = await res.json();
  await expect
    .poll(async () => (await request.get(`/api/motions/${motion_id}`)).status(), { timeout: 120_000 })
    .toBe(200);
  return motion_id as string;
}

let motionId = "";

test.beforeAll(async ({ request }) => {
  motionId = await makeMotion(request, "two people dance salsa", 2, 3);
});

for (const size of [
  { width: 1280, height: 720 },
  { width: 390, height: 844 },
]) {
  test(`the studio fits a ${size.width}×${size.height} window`, async ({ page }, info) => {
    await page.setViewportSize(size);
    await openStudio(page, `/m/${motionId}`);
    await page.waitForFunction(() => window.__interplay.phase === "done");
    expect((await hook(page)).persons).toBe(2);
    for (const id of [
      "prompt", "persons-2", "seconds", "generate", "viewport", "play", "scrubber", "legend", "metrics",
      "tool-path", "tool-part", "undo", "copy-link", "theme", "track", "export-bvh-both",
    ]) {
      const box = await page.getByTestId(id).boundingBox();
      expect(box, id).not.toBeNull();
      expect(box!.x, id).toBeGreaterThanOrEqual(0);
      expect(box!.x + box!.width, id).toBeLessThanOrEqual(size.width + 0.5);
    }
    // the legend does not cover the canvas on a narrow screen
    if (size.width < 900) {
      const canvas = (await page.getByTestId("viewport").boundingBox())!;
      const legend = (await page.getByTestId("legend").boundingBox())!;
      expect(legend.y).toBeGreaterThanOrEqual(canvas.y + canvas.height - 0.5);
    }
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    expect(overflow).toBeLessThanOrEqual(0);
    await shot(page, `layout-${size.width}x${size.height}`, info);
  });
}

test("full quality (MSAA, shadow map) renders too", async ({ page }, info) => {
  await openStudio(page, `/m/${motionId}?quality=full`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  expect((await hook(page)).quality).toBe("full");
  await shot(page.getByTestId("viewport"), "layout-quality-full", info);
});

test("the light theme is applied and remembered; the empty studio says what to do", async ({ page }, info) => {
  await openStudio(page);
  await expect(page.getByTestId("empty-state")).toBeVisible();
  const bg = () => page.evaluate(() => getComputedStyle(document.body).backgroundColor);
  const dark = await bg();
  await page.getByTestId("theme").click();
  expect(await page.evaluate(() => document.documentElement.dataset.theme)).toBe("light");
  expect(await bg()).not.toBe(dark);
  await shot(page, "layout-light-empty", info);
  await page.reload();
  await expect(page.getByTestId("theme")).toBeVisible();
  expect(await page.evaluate(() => document.documentElement.dataset.theme)).toBe("light");
  await openStudio(page, `/m/${motionId}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await shot(page, "layout-light-salsa", info);
});
