import { expect, test, type Page } from "@playwright/test";
import { openStudio, shot, showFrame, startGeneration, waitDone } from "./studio";

// The hover highlight, checked in pixels: with the part tool on, pointing at the left elbow paints
// the whole left arm (collar to wrist) in the hover colour, and the legs keep theirs.
const LEFT_ARM = [13, 16, 18, 20];
const LEGS = [4, 5, 7, 8, 10, 11];

/** A screen box (client px) around some joints of person 0 at the frame shown, padded. */
async function boxAround(page: Page, joints: number[], pad = 10) {
  const pts = await page.evaluate((js) => js.map((j) => window.__interplay.project(0, j)!), joints);
  const xs = pts.map((p) => p[0]);
  const ys = pts.map((p) => p[1]);
  const x = Math.floor(Math.min(...xs) - pad);
  const y = Math.floor(Math.min(...ys) - pad);
  return { x, y, width: Math.ceil(Math.max(...xs) + pad) - x, height: Math.ceil(Math.max(...ys) + pad) - y };
}

/** Pixels of a page region [r, g, b], read from a screenshot decoded in the page. */
async function pixels(page: Page, clip: { x: number; y: number; width: number; height: number }): Promise<number[][]> {
  const png = await page.screenshot({ clip });
  return page.evaluate(async (b64) => {
    // decoded without fetch(data:): the page's CSP allows connections to its own origin only
    const blob = new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))], { type: "image/png" });
    const bmp = await createImageBitmap(blob);
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const ctx = c.getContext("2d")!;
    ctx.drawImage(bmp, 0, 0);
    const d = ctx.getImageData(0, 0, bmp.width, bmp.height).data;
    const out: number[][] = [];
    for (let i = 0; i < d.length; i += 4) out.push([d[i], d[i + 1], d[i + 2]]);
    return out;
  }, png.toString("base64"));
}

// the hover colour (#fff3c4, glowing): bright in every channel, warm; the arm's own colour
// (#4f9dde) and its joints' are blue, with a dark red channel
const hoverLike = ([r, g, b]: number[]) => Math.min(r, g, b) > 165 && r >= b;
const changed = (a: number[][], b: number[][]) => a.filter((p, i) => p.some((v, k) => Math.abs(v - b[i][k]) > 24)).length / a.length;

test("hovering the left arm paints it in the hover colour, the legs keep theirs", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "a person walks forward", 1, 2);
  await waitDone(page);
  await showFrame(page, 10);
  await page.getByTestId("tool-part").click();

  const arm = await boxAround(page, LEFT_ARM);
  const legs = await boxAround(page, LEGS);
  const [armBefore, legsBefore] = [await pixels(page, arm), await pixels(page, legs)];
  expect(armBefore.filter(hoverLike).length).toBeLessThan(5);

  const elbow = (await page.evaluate(() => window.__interplay.project(0, 18)))!;
  await page.mouse.move(elbow[0], elbow[1]);
  await page.waitForFunction(() => window.__interplay.renderCount > 0); // the pointer handler ran
  await page.waitForTimeout(300); // a render tick
  const [armAfter, legsAfter] = [await pixels(page, arm), await pixels(page, legs)];
  const lit = armAfter.filter(hoverLike).length;
  info.annotations.push({ type: "hover", description: `${lit} hover-coloured px of ${armAfter.length} around the left arm; ${(changed(legsBefore, legsAfter) * 100).toFixed(1)} % of leg px changed` });
  expect(lit).toBeGreaterThan(200);
  expect(changed(armBefore, armAfter)).toBeGreaterThan(0.04);
  expect(changed(legsBefore, legsAfter)).toBeLessThan(0.01);
  await shot(page, "g-left-arm-hovered", info);

  // pointing away from the body clears it
  await page.mouse.move(arm.x + arm.width + 150, arm.y - 80);
  await page.waitForTimeout(300);
  expect((await pixels(page, arm)).filter(hoverLike).length).toBeLessThan(5);
});
