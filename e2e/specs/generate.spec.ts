import { expect, test } from "@playwright/test";
import { hook, openStudio, pixelDifference, shot, showFrame, startGeneration, waitDone } from "./studio";

test("a person walks forward: frames stream in and play on a non-blank canvas", async ({ page }, info) => {
  const seconds = 3;
  await openStudio(page);
  const canvas = page.getByTestId("viewport");
  const empty = await shot(canvas, "a-empty-scene", info);

  // record what the progress indicator says while the stream runs (it may be brief)
  await page.evaluate(() => {
    const seen: string[] = ((window as unknown as { __progress: string[] }).__progress = []);
    new MutationObserver(() => {
      const text = document.querySelector('[data-testid="progress"]')?.textContent;
      if (text && seen[seen.length - 1] !== text) seen.push(text);
    }).observe(document.body, { subtree: true, childList: true, characterData: true });
  });
  await startGeneration(page, "a person walks forward", 1, seconds);
  await page.waitForFunction(() => window.__interplay.framesReceived > 0);
  const streaming = await hook(page);
  expect(streaming.persons).toBe(1);
  // headless chromium renders with SwiftShader: the light settings
  expect(streaming.quality).toBe("light");
  const done = await waitDone(page);

  // the timeline is as long as asked for
  expect(done.fps).toBe(20);
  expect(done.frameCount).toBe(seconds * 20);
  expect(done.framesReceived).toBe(seconds * 20);
  await expect(page.getByTestId("frame-counter")).toContainText(`/ ${seconds * 20}`);
  await expect(page.getByTestId("frame-counter")).toContainText(`${seconds.toFixed(2)} s`);
  await expect(page).toHaveURL(new RegExp(`/m/${done.motionId}$`));
  const progress = await page.evaluate(() => (window as unknown as { __progress: string[] }).__progress);
  expect(progress.some((t) => new RegExp(`\\d+ / ${seconds * 20} frames`).test(t)), progress.join(" | ")).toBe(true);
  await expect(page.getByTestId("progress")).toHaveCount(0); // gone when done

  // the mannequin is drawn: the canvas differs from the empty scene
  await showFrame(page, 30);
  const drawn = await shot(canvas, "a-walk-frame30", info);
  expect(await pixelDifference(page, empty, drawn)).toBeGreaterThan(0.005);
  // and it moves: another frame looks different again
  await showFrame(page, 0);
  const first = await shot(canvas, "a-walk-frame0", info);
  expect(await pixelDifference(page, first, drawn)).toBeGreaterThan(0.001);
  await shot(page, "a-walk-page", info);

  // walking forward: the pelvis travels
  const motion = await (await page.request.get(`/api/motions/${done.motionId}`)).json();
  const pelvis = motion.people[0].joints.map((f: number[][]) => f[0]);
  const [a, b] = [pelvis[0], pelvis[pelvis.length - 1]];
  expect(Math.hypot(b[0] - a[0], b[2] - a[2])).toBeGreaterThan(0.5);
});

test("two people dance salsa: two mannequins and the metrics panel", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "two people dance salsa", 2, 4);
  const done = await waitDone(page);
  expect(done.persons).toBe(2);
  expect(done.firstFrame).toHaveLength(2);
  expect(done.frameCount).toBe(80);

  const metrics = page.getByTestId("metrics");
  for (const key of ["intersection_volume", "intersection_frequency", "contact_frames", "foot_skating", "bone_deviation"]) {
    const value = metrics.getByTestId(`metric-${key}`).locator("dd");
    await expect(value).toHaveText(/^-?[0-9]/);
  }
  await expect(page.getByTestId("legend")).toContainText("Person 2");
  await expect(page.getByTestId("export-bvh-0")).toBeVisible();
  await expect(page.getByTestId("export-bvh-1")).toBeVisible();
  await showFrame(page, 40);
  await shot(page, "b-salsa-page", info);
});

test("an empty prompt is not sent: the form says why in plain words", async ({ page }, info) => {
  await openStudio(page);
  const posts: string[] = [];
  page.on("request", (r) => r.method() === "POST" && r.url().endsWith("/api/jobs") && posts.push(r.url()));
  await page.getByTestId("prompt").fill("   ");
  await page.getByTestId("generate").click();
  const problems = page.getByTestId("form-problems");
  await expect(problems).toHaveText("Type what the people do first.");
  await expect(problems).not.toContainText(/HTTP|object Object|undefined|Input should/);
  expect((await hook(page)).phase).toBe("idle");
  await shot(page, "e-empty-prompt", info);

  // an out-of-range duration is said as it is typed, and not sent either
  await page.getByTestId("prompt").fill("a person walks forward");
  await page.getByTestId("seconds").fill("25");
  await expect(problems).toHaveText("The length must be from 1 to 20 seconds; 25 is too long.");
  await page.getByTestId("generate").click();
  expect(posts).toEqual([]);
});
