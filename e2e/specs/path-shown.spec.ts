import { expect, test, type Page } from "@playwright/test";
import { drawOnGround, openStudio, pixelDifference, shot, showFrame, waitDone } from "./studio";

const shown = (page: Page) => page.evaluate(() => window.__interplay.shownPath);

/** A screenshot of the canvas around the projected points of the path shown (clipped to it). */
async function around(page: Page, points: [number, number][]): Promise<Buffer> {
  const px = await page.evaluate((pts) => pts.map(([x, z]) => window.__interplay.projectPoint(x, 0.02, z)!), points);
  const box = (await page.locator("canvas").first().boundingBox())!;
  const xs = px.map((p) => p[0]);
  const ys = px.map((p) => p[1]);
  const x0 = Math.max(box.x, Math.min(...xs) - 20);
  const y0 = Math.max(box.y, Math.min(...ys) - 20);
  const x1 = Math.min(box.x + box.width, Math.max(...xs) + 20);
  const y1 = Math.min(box.y + box.height, Math.max(...ys) + 20);
  return page.screenshot({ clip: { x: x0, y: y0, width: Math.max(4, x1 - x0), height: Math.max(4, y1 - y0) } });
}

// Issue 26, point 8: the drawn path vanished once the generation that followed it was done. Now
// it stays on the floor as the path the motion followed (not sent again), with a toggle, and
// comes back with the stored motion (its plan's path) after a reload.
test("the path a motion followed stays visible after generating, with a toggle", async ({ page }, info) => {
  await openStudio(page);
  await page.getByTestId("tool-path").click();
  await drawOnGround(page, [[0, 0], [0.5, 0.8], [1.2, 1.4], [2.0, 1.6]]);
  const drawn = (await shown(page)).points;
  expect(drawn.length).toBeGreaterThan(2);
  await page.getByTestId("tool-path").click(); // back to the orbit view
  await page.getByTestId("prompt").fill("a person walks forward");
  await page.getByTestId("seconds").fill("3");
  await page.getByTestId("generate").click();
  const done = await waitDone(page);

  // used up for the next Generate (no chip, no pending path) but still on the floor
  await expect(page.getByTestId("path-chip")).toHaveCount(0);
  expect(await page.evaluate(() => window.__interplay.path.points)).toEqual([]);
  expect(await shown(page)).toEqual({ person: 0, points: drawn, followed: true });
  const toggle = page.getByTestId("path-visible");
  await expect(toggle).toHaveAttribute("aria-pressed", "true");

  // drawn on the canvas: hiding it changes the pixels along it, showing it again brings them back
  await showFrame(page, 0);
  const on = await around(page, drawn);
  await shot(page, "ps-path-kept", info);
  await toggle.click();
  await expect(toggle).toHaveAttribute("aria-pressed", "false");
  expect((await shown(page)).points).toEqual([]);
  await page.waitForTimeout(200);
  const off = await around(page, drawn);
  expect(await pixelDifference(page, on, off)).toBeGreaterThan(0.01);
  await toggle.click();
  await page.waitForTimeout(200);
  expect(await pixelDifference(page, on, await around(page, drawn))).toBeLessThan(0.005);

  // the stored motion carries it: a reload of its link shows it again
  await page.reload();
  await page.waitForFunction((id) => window.__interplay.motionId === id && window.__interplay.phase === "done", done.motionId);
  const again = await shown(page);
  expect(again.followed).toBe(true);
  again.points.forEach(([x, z], i) => {
    expect(x).toBeCloseTo(drawn[i][0], 4);
    expect(z).toBeCloseTo(drawn[i][1], 4);
  });
  // the next Generate sends no path, and its motion (which followed none) shows none
  const sent = page.waitForRequest((r) => r.url().endsWith("/api/jobs") && r.method() === "POST");
  await page.getByTestId("prompt").fill("a person walks forward slowly");
  await page.getByTestId("generate").click();
  expect((await sent).postDataJSON().trajectory).toBeUndefined();
  await waitDone(page, { after: done.jobId }); // its own end, not the first job's "done"
  expect((await shown(page)).points).toEqual([]);
  await expect(page.getByTestId("path-visible")).toHaveCount(0);
});
