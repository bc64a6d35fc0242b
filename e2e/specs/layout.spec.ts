import { expect, test, type Page } from "@playwright/test";
import { hook, makeMotion, openStudio, shot } from "./studio";

async function meanLuma(page: Page, png: Buffer): Promise<number> {
  return page.evaluate(async (b64) => {
    const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const bmp = await createImageBitmap(new Blob([bytes], { type: "image/png" }));
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const ctx = c.getContext("2d")!;
    ctx.drawImage(bmp, 0, 0);
    const d = ctx.getImageData(0, 0, bmp.width, bmp.height).data;
    let sum = 0;
    for (let i = 0; i < d.length; i += 4) sum += 0.2126 * d[i] + 0.7152 * d[i + 1] + 0.0722 * d[i + 2];
    return sum / (d.length / 4);
  }, png.toString("base64"));
}

let motionId = "";

test.beforeAll(async ({ request }) => {
  motionId = await makeMotion(request, { prompt: "two people dance salsa", persons: 2, seconds: 3 }, 120_000);
});

/** The header's controls, each one box (the path chip shows: a path is set). */
const HEADER = [
  "brand", "prompt", "persons", "seconds", "seed", "new-seed", "path-chip", "generate",
  "undo", "redo", "version-label", "copy-link", "theme", "shortcuts-button",
];
const TIMELINE = ["play", "scrubber", "track", "frame-counter", "speed", "loop-toggle"];

type Box = { x: number; y: number; width: number; height: number };
const intersect = (a: Box, b: Box) =>
  a.x < b.x + b.width - 0.5 && b.x < a.x + a.width - 0.5 && a.y < b.y + b.height - 0.5 && b.y < a.y + a.height - 0.5;

/** Every pair of boxes that overlaps, named. */
function overlaps(boxes: Record<string, Box>): string[] {
  const names = Object.keys(boxes);
  const out: string[] = [];
  for (let i = 0; i < names.length; i++)
    for (let j = i + 1; j < names.length; j++) if (intersect(boxes[names[i]], boxes[names[j]])) out.push(`${names[i]} × ${names[j]}`);
  return out;
}

for (const size of [
  { width: 1440, height: 900 },
  { width: 1280, height: 720 },
  { width: 1024, height: 700 },
  { width: 390, height: 844 },
]) {
  test(`the studio fits a ${size.width}×${size.height} window; header controls do not overlap`, async ({ page }, info) => {
    await page.setViewportSize(size);
    await openStudio(page, `/m/${motionId}`);
    await page.waitForFunction(() => window.__interplay.phase === "done");
    expect((await hook(page)).persons).toBe(2);
    // a path set (its chip sits beside Generate), then back to the plain view
    await page.getByTestId("tool-path").click();
    await page.getByTestId("preset-circle").click();
    await page.getByTestId("tool-path").click();
    await expect(page.getByTestId("path-chip")).toBeVisible();
    for (const id of [
      ...HEADER.filter((id) => id !== "persons"), "persons-1", "persons-2", "viewport", "play", "scrubber", "legend", "metrics",
      "tool-path", "tool-part", "track", "export-bvh-both",
    ]) {
      const box = await page.getByTestId(id).boundingBox();
      expect(box, id).not.toBeNull();
      expect(box!.x, id).toBeGreaterThanOrEqual(0);
      expect(box!.x + box!.width, id).toBeLessThanOrEqual(size.width + 0.5);
    }
    // the 1 person / 2 people buttons are one segmented control (they share a border)
    const at = (id: string) => (id === "persons" ? page.getByRole("group", { name: "Persons" }) : page.getByTestId(id));
    const boxes = async (ids: string[]) =>
      Object.fromEntries(await Promise.all(ids.map(async (id) => [id, (await at(id).boundingBox())!] as const)));
    // no two header controls share a pixel (at 1024 px Generate used to cover Undo)
    expect(overlaps(await boxes(HEADER)), "overlapping header controls").toEqual([]);
    // nor the timeline's (the track and the scrubber are one lane: stacked, not overlapping)
    expect(overlaps(await boxes(TIMELINE)), "overlapping timeline controls").toEqual([]);
    // the track and the scrubber share their x extent (one mapping)
    const [track, scrubber] = [await page.getByTestId("track").boundingBox(), await page.getByTestId("scrubber").boundingBox()];
    expect(Math.abs(track!.x - scrubber!.x)).toBeLessThan(0.5);
    expect(Math.abs(track!.width - scrubber!.width)).toBeLessThan(0.5);
    // the play controls are above the fold, without scrolling (a phone too)
    for (const id of ["play", "scrubber"]) {
      const box = (await page.getByTestId(id).boundingBox())!;
      expect(box.y + box.height, `${id} bottom at ${size.width}×${size.height}`).toBeLessThanOrEqual(size.height);
    }
    // the legend does not cover the canvas on a narrow screen
    if (size.width < 900) {
      const canvas = (await page.getByTestId("viewport").boundingBox())!;
      const legend = (await page.getByTestId("legend").boundingBox())!;
      expect(legend.y).toBeGreaterThanOrEqual(canvas.y + canvas.height - 0.5);
    }
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    expect(overflow).toBeLessThanOrEqual(0);
    await page.waitForTimeout(200);
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
  const darkStage = await meanLuma(page, await page.getByTestId("viewport").screenshot());
  await page.getByTestId("theme").click();
  expect(await page.evaluate(() => document.documentElement.dataset.theme)).toBe("light");
  expect(await bg()).not.toBe(dark);
  // the viewport follows the theme: a light floor and background, not the dark stage
  await page.waitForTimeout(300);
  const lightStage = await meanLuma(page, await page.getByTestId("viewport").screenshot());
  info.annotations.push({ type: "stage luma", description: `dark ${darkStage.toFixed(0)} → light ${lightStage.toFixed(0)}` });
  expect(darkStage).toBeLessThan(60);
  expect(lightStage).toBeGreaterThan(170);
  await shot(page, "layout-light-empty", info);
  await page.reload();
  await expect(page.getByTestId("theme")).toBeVisible();
  expect(await page.evaluate(() => document.documentElement.dataset.theme)).toBe("light");
  await openStudio(page, `/m/${motionId}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await shot(page, "layout-light-salsa", info);
});
