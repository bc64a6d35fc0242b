import { expect, test } from "@playwright/test";
import { readFileSync } from "node:fs";
import { hook, openStudio, shot, startGeneration, waitDone } from "./studio";

test("the share link opens the same motion in a fresh browser context", async ({ page, browser, context }, info) => {
  await context.grantPermissions(["clipboard-read", "clipboard-write"]);
  await openStudio(page);
  await startGeneration(page, "a person waves with the right hand", 1, 2);
  const done = await waitDone(page);

  await page.getByTestId("share").click();
  const url = await page.getByTestId("share-url").inputValue();
  expect(url).toMatch(new RegExp(`/m/${done.motionId}$`));
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(url);
  expect(done.motionId!.length).toBeGreaterThanOrEqual(22); // ≥ 128 bits, URL-safe base64

  const fresh = await browser.newContext();
  try {
    const other = await fresh.newPage();
    await openStudio(other, url);
    await other.waitForFunction(() => window.__interplay.phase === "done");
    const shared = await hook(other);
    expect(shared.motionId).toBe(done.motionId);
    expect(shared.frameCount).toBe(done.frameCount);
    await expect(other.getByTestId("prompt")).toHaveValue("a person waves with the right hand");

    const motion = await (await other.request.get(`/api/motions/${done.motionId}`)).json();
    expect(shared.firstFrame).toHaveLength(motion.people.length);
    motion.people.forEach((p: { joints: number[][][] }, i: number) => {
      const expected = p.joints[0];
      expect(shared.firstFrame[i]).toHaveLength(22);
      shared.firstFrame[i].forEach((xyz, j) => xyz.forEach((v, k) => expect(v).toBeCloseTo(expected[j][k], 4)));
    });
    await shot(other, "c-shared-page", info);
  } finally {
    await fresh.close();
  }
});

test("the exported BVH loads in three.js's BVHLoader", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "a person jumps", 1, 2);
  const done = await waitDone(page);

  const download = page.waitForEvent("download");
  await page.getByTestId("export-bvh-0").click();
  const file = await download;
  expect(file.suggestedFilename()).toMatch(/\.bvh$/);
  const text = readFileSync((await file.path())!, "utf8");
  expect(text.startsWith("HIERARCHY")).toBe(true);

  const errors: string[] = [];
  page.on("pageerror", (e) => errors.push(e.message));
  const bvh = await page.evaluate((t) => window.__interplay.parseBvh(t), text);
  expect(errors).toEqual([]);
  expect(bvh.joints).toHaveLength(22);
  expect(bvh.endSites).toBeGreaterThan(0);
  expect(bvh.bones).toBe(22 + bvh.endSites);
  expect(bvh.frames).toBe(done.frameCount);

  const json = page.waitForEvent("download");
  await page.getByTestId("export-json").click();
  const motion = JSON.parse(readFileSync((await (await json).path())!, "utf8"));
  expect(motion.fps).toBe(20);
  expect(motion.people[0].joints).toHaveLength(done.frameCount);
  await shot(page, "d-export-page", info);
});
