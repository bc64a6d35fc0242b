import { expect, test } from "@playwright/test";
import { hook, motionOf, openStudio, shot, startGeneration, waitDone } from "./studio";

test("undo / redo between versions, the URL follows, the copied link reproduces the version", async ({ page, browser, context }, info) => {
  await context.grantPermissions(["clipboard-read", "clipboard-write"]);
  await openStudio(page);
  await startGeneration(page, "a person walks forward", 1, 3);
  const v1 = await waitDone(page);
  await expect(page.getByTestId("undo")).toBeDisabled();

  // an edit: the walk follows an S preset (a trajectory edit)
  await page.getByTestId("tool-path").click();
  await page.getByTestId("preset-s").click();
  await page.getByTestId("path-apply").click();
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  const v2 = await hook(page);
  await expect(page.getByTestId("version-edit")).toContainText("path (Person 1)");
  const m1 = await motionOf(page, v1.motionId!);
  const m2 = await motionOf(page, v2.motionId!);
  const end = (m: typeof m1) => m.people[0].joints[m.people[0].joints.length - 1][0];
  expect(Math.hypot(end(m1)[0] - end(m2)[0], end(m1)[2] - end(m2)[2])).toBeGreaterThan(0.1);

  // keyboard undo (not while typing: focus the prompt first and check nothing happens)
  await page.getByTestId("prompt").focus();
  await page.keyboard.press("Control+z");
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  await page.getByTestId("tool-path").click(); // leave path mode
  await page.keyboard.press("Control+z");
  await expect(page.getByTestId("version-label")).toHaveText("v1 / 2");
  await expect(page).toHaveURL(new RegExp(`/m/${v1.motionId}$`));
  const undone = await hook(page);
  expect(undone.motionId).toBe(v1.motionId);
  // the previous joints are back
  m1.people[0].joints[0].forEach((xyz, j) => xyz.forEach((v, k) => expect(undone.firstFrame[0][j][k]).toBeCloseTo(v, 4)));

  await page.keyboard.press("Control+Shift+Z");
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  await expect(page).toHaveURL(new RegExp(`/m/${v2.motionId}$`));

  // space pauses, arrows step a frame
  await page.keyboard.press("Space");
  await page.waitForFunction(() => !window.__interplay.playing);
  const f0 = (await hook(page)).currentFrame;
  await page.keyboard.press("ArrowRight");
  await page.waitForFunction((f) => window.__interplay.currentFrame === f, Math.min(f0 + 1, 59));

  await page.getByTestId("copy-link").click();
  const url = await page.evaluate(() => navigator.clipboard.readText());
  expect(url).toMatch(new RegExp(`/m/${v2.motionId}$`));
  await shot(page, "j-versions", info);

  const fresh = await browser.newContext();
  try {
    const other = await fresh.newPage();
    await openStudio(other, url);
    await other.waitForFunction(() => window.__interplay.phase === "done");
    await expect(other.getByTestId("version-label")).toHaveText("v2 / 2"); // history from the API
    const shared = await hook(other);
    expect(shared.motionId).toBe(v2.motionId);
    m2.people[0].joints[0].forEach((xyz, j) => xyz.forEach((v, k) => expect(shared.firstFrame[0][j][k]).toBeCloseTo(v, 4)));
    await other.getByTestId("undo").click();
    await expect(other).toHaveURL(new RegExp(`/m/${v1.motionId}$`));
    await shot(other, "j-shared-version", info);
  } finally {
    await fresh.close();
  }
});
