import { expect, test } from "@playwright/test";
import { hook, makeMotion, openStudio, shot, showFrame } from "./studio";

// Issue 26, point 8: every edit restarted playback near frame 0. Now an edit (and undo / redo
// between the versions) keeps the playhead where it was, paused or playing.
test("an edit keeps the playhead; undo and redo keep it too", async ({ page }, info) => {
  const id = await makeMotion(page.request, { prompt: "a person walks forward", persons: 1, seconds: 4, seed: 5 });
  await openStudio(page, `/m/${id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");

  // paused at frame 50: a path edit (a new version) shows frame 50, still paused
  await showFrame(page, 50);
  await page.getByTestId("tool-path").click();
  await page.getByTestId("preset-s").click();
  await page.getByTestId("path-apply").click();
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  const edited = await hook(page);
  expect(edited.motionId).not.toBe(id);
  expect(edited.currentFrame).toBe(50);
  expect(await page.evaluate(() => window.__interplay.playing)).toBe(false);
  await expect(page.getByTestId("frame-counter")).toContainText("51 / 80");
  await shot(page, "ph-kept-after-edit", info);

  // undo and redo: the same frame of the other version
  await page.getByTestId("tool-path").click(); // leave path mode
  await page.getByTestId("undo").click();
  await expect(page.getByTestId("version-label")).toHaveText("v1 / 2");
  expect((await hook(page)).currentFrame).toBe(50);
  await page.getByTestId("redo").click();
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  expect((await hook(page)).currentFrame).toBe(50);

  // playing (at a quarter speed: 5 frames a second) from frame 60: the new version goes on
  // from where playback was when it arrived, not from near 0
  await page.getByTestId("speed").selectOption("0.25");
  await showFrame(page, 60);
  await page.getByTestId("play").click();
  await page.waitForFunction(() => window.__interplay.playing);
  await page.getByTestId("tool-path").click();
  await page.getByTestId("preset-circle").click();
  const started = Date.now();
  await page.getByTestId("path-apply").click();
  // the frame shown at the first animation frame after the new version is there
  const at = await (await page.waitForFunction(() => {
    const h = window.__interplay;
    return h.versions.ids.length === 3 && h.versions.index === 2 ? { frame: h.currentFrame, playing: h.playing } : null;
  }, null, { polling: "raf", timeout: 60_000 })).jsonValue();
  const seconds = (Date.now() - started) / 1000;
  expect(at!.playing).toBe(true);
  if (seconds < 3.5) expect(at!.frame).toBeGreaterThanOrEqual(60); // 20 frames left at 5 a second: no wrap yet
  else expect(at!.frame).toBeGreaterThan(1); // a slow machine: wrapped, but not restarted
  await expect(page.getByTestId("version-label")).toHaveText("v3 / 3");
});
