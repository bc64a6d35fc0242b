// The timeline: the track (segments, marks, playhead) on the scrubber's pixel mapping, Home/End,
// and the shortcut sheet (`?`).
import { expect, test, type Page } from "@playwright/test";
import { hook, makeMotion, openStudio, shot } from "./studio";

const THUMB = 14; // px, frontend/src/playback/timeline.ts THUMB_PX (styles.css --thumb)

async function thumbX(page: Page, frame: number, total: number): Promise<number> {
  const box = (await page.getByTestId("scrubber").boundingBox())!;
  return box.x + THUMB / 2 + (frame / (total - 1)) * (box.width - THUMB);
}

async function centreX(page: Page, testId: string, nth = 0): Promise<number> {
  const box = (await page.getByTestId(testId).nth(nth).boundingBox())!;
  return box.x + box.width / 2;
}

let walkJump = "";
let hug = "";

test.beforeAll(async ({ request }) => {
  walkJump = await makeMotion(request, { prompt: "a person walks forward then jumps", seconds: 4, seed: 1 });
  hug = await makeMotion(request, { prompt: "two people hug", persons: 2, seconds: 4, seed: 4 });
});

test("Home and End jump to the first and last frame; the playhead follows, on the scrubber's mapping", async ({ page }, info) => {
  await openStudio(page, `/m/${walkJump}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  const total = (await hook(page)).frameCount;
  expect(total).toBe(80);

  await page.keyboard.press("End");
  await page.waitForFunction((t) => window.__interplay.currentFrame === t - 1, total);
  expect(await page.evaluate(() => window.__interplay.playing)).toBe(false);
  await expect(page.getByTestId("scrubber")).toHaveValue(String(total - 1));
  await expect(page.getByTestId("frame-counter")).toContainText(`${total} / ${total}`);
  await expect(page.getByTestId("playhead")).toHaveAttribute("data-frame", String(total - 1));
  expect(Math.abs((await centreX(page, "playhead")) - (await thumbX(page, total - 1, total)))).toBeLessThan(1.5);

  await page.keyboard.press("Home");
  await page.waitForFunction(() => window.__interplay.currentFrame === 0);
  await expect(page.getByTestId("scrubber")).toHaveValue("0");
  expect(Math.abs((await centreX(page, "playhead")) - (await thumbX(page, 0, total)))).toBeLessThan(1.5);

  // a frame in the middle: the playhead is over the browser's own thumb — clicking the scrubber
  // at the playhead's x lands on the same frame
  await page.keyboard.press("End");
  for (let i = 0; i < 3; i++) await page.keyboard.press("Shift+ArrowLeft"); // 79 - 30 = 49
  await page.waitForFunction(() => window.__interplay.currentFrame === 49);
  const x = await centreX(page, "playhead");
  expect(Math.abs(x - (await thumbX(page, 49, total)))).toBeLessThan(1.5);
  await page.keyboard.press("Home");
  const box = (await page.getByTestId("scrubber").boundingBox())!;
  await page.mouse.click(x, box.y + box.height / 2);
  await page.waitForFunction(() => window.__interplay.currentFrame !== 0);
  expect(Math.abs((await hook(page)).currentFrame - 49)).toBeLessThanOrEqual(1);

  // the plan's two segments sit on the same mapping: segment 2 starts above its first frame
  const plan = (await (await page.request.get(`/api/motions/${walkJump}`)).json()).plan;
  expect(plan.segments.length).toBe(2);
  const seg = page.getByTestId("track-segment-1");
  const segLeft = (await seg.boundingBox())!.x;
  expect(Math.abs(segLeft - (await thumbX(page, plan.segments[1].start, total)))).toBeLessThan(1.5);
  await shot(page.getByTestId("timeline"), "t-timeline-segments", info);

  // Home/End are the slider's own keys while it has focus (it jumps itself, same result)
  await page.getByTestId("scrubber").focus();
  await page.keyboard.press("End");
  await page.waitForFunction((t) => window.__interplay.currentFrame === t - 1, total);
});

test("contact and penetration marks sit over their frames on the scrubber", async ({ page }, info) => {
  await openStudio(page, `/m/${hug}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  const total = (await hook(page)).frameCount;
  const marks = page.locator('[data-testid^="mark-"]');
  expect(await marks.count(), "a hug has contact or penetration marks").toBeGreaterThan(0);
  for (let i = 0; i < (await marks.count()); i++) {
    const m = marks.nth(i);
    const frame = Number(await m.getAttribute("data-frame"));
    const left = (await m.boundingBox())!.x;
    expect(Math.abs(left - (await thumbX(page, frame, total))), `mark at frame ${frame}`).toBeLessThan(1.5);
  }
  // a mark's click goes to its frame, and the playhead with it
  const last = marks.last();
  const frame = Number(await last.getAttribute("data-frame"));
  await last.click();
  await page.waitForFunction((f) => window.__interplay.currentFrame === f, frame);
  expect(Math.abs((await centreX(page, "playhead")) - (await thumbX(page, frame, total)))).toBeLessThan(1.5);
  await shot(page.getByTestId("timeline"), "t-timeline-marks", info);
});

test("? opens the shortcut sheet (not while typing); Esc and the close button close it", async ({ page }, info) => {
  await openStudio(page);
  await expect(page.getByTestId("shortcuts")).toHaveCount(0);
  await page.keyboard.press("?");
  const sheet = page.getByTestId("shortcuts");
  await expect(sheet).toBeVisible();
  for (const k of ["Space", "Home", "End", "Ctrl + Z", "?"]) await expect(sheet).toContainText(k);
  await shot(page, "t-shortcuts", info);
  await page.keyboard.press("Escape");
  await expect(sheet).toHaveCount(0);
  // typing a question mark in the prompt is just text
  await page.getByTestId("prompt").fill("");
  await page.getByTestId("prompt").press("?");
  await expect(page.getByTestId("prompt")).toHaveValue("?");
  await expect(sheet).toHaveCount(0);
  // the header's ? button opens it too; ? again (off the field) closes it
  await page.getByTestId("shortcuts-button").click();
  await expect(sheet).toBeVisible();
  await page.keyboard.press("?");
  await expect(sheet).toHaveCount(0);
  await page.getByTestId("shortcuts-button").click();
  await page.getByRole("button", { name: "Close (Esc)" }).click();
  await expect(sheet).toHaveCount(0);
});
