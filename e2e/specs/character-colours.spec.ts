// Issue 26, point 8: orange (the right arm's colour) bled onto the skinned character's chest and
// back — the chest's vertices took the bone of the collar weighing most in them. Now the chest
// and back keep the trunk's colour, on the page as drawn.
import { expect, test, type Page } from "@playwright/test";
import { makeMotion, openStudio, shot, showFrame } from "./studio";

interface Figure { figure: string; status: string; shown: string; characters: number }
const figure = (page: Page) => page.evaluate(() => (window.__interplay as unknown as { figure: Figure }).figure);

/** The mean colour (0–255) of a 6 × 6 px square of the page at a client point. */
async function colourAt(page: Page, [x, y]: [number, number]): Promise<[number, number, number]> {
  const png = await page.screenshot({ clip: { x: x - 3, y: y - 3, width: 6, height: 6 } });
  return page.evaluate(async (b64) => {
    const blob = new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))], { type: "image/png" });
    const bmp = await createImageBitmap(blob);
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const ctx = c.getContext("2d")!;
    ctx.drawImage(bmp, 0, 0);
    const d = ctx.getImageData(0, 0, bmp.width, bmp.height).data;
    const sum = [0, 0, 0];
    for (let i = 0; i < d.length; i += 4) for (let k = 0; k < 3; k++) sum[k] += d[i + k];
    return sum.map((s) => s / (d.length / 4)) as [number, number, number];
  }, png.toString("base64"));
}

test("the character's chest keeps the trunk's colour: no orange from the right arm", async ({ page }, info) => {
  const id = await makeMotion(page.request, { prompt: "a person stands still", persons: 1, seconds: 2, seed: 1 });
  await openStudio(page, `/m/${id}?figure=character`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await expect.poll(async () => (await figure(page)).shown, { timeout: 60_000 }).toBe("character");
  await showFrame(page, 0);
  await page.getByRole("button", { name: "Front view", exact: true }).click();
  await page.waitForFunction(() => window.__interplay.view.preset === "front");
  await page.waitForTimeout(300);
  // points on the chest: between spine3 and the neck, and a third of the way towards the right
  // collar (the right side of the chest, where the orange was)
  const [spine3, neck, rcollar, lcollar] = await page.evaluate(() => [9, 12, 14, 13].map((j) => window.__interplay.project(0, j)!));
  const mid: [number, number] = [(spine3[0] + neck[0]) / 2, (spine3[1] + neck[1]) / 2];
  const towards = (c: [number, number], f: number): [number, number] => [mid[0] + (c[0] - mid[0]) * f, mid[1] + (c[1] - mid[1]) * f + 4];
  await shot(page, "cc-character-front", info);
  for (const [what, at] of [["chest, right side", towards(rcollar, 0.35)], ["chest, middle", mid], ["chest, left side", towards(lcollar, 0.35)]] as const) {
    const [r, g, b] = await colourAt(page, at);
    // the trunk is blue (#4f9dde lit); the right arm's orange (#e0875a) has red over blue
    expect(b, `${what}: blue, not orange (rgb ${r.toFixed(0)}, ${g.toFixed(0)}, ${b.toFixed(0)})`).toBeGreaterThan(r + 20);
  }
});
