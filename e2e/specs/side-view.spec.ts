// Issue 26, point 8: the two-person Side view looked exactly along the line between the people,
// so one stood behind the other. Now it looks from Person 2's end turned off the line just
// enough (scene/framing.ts pairSideTurn) that both are framed and apart, through the motion.
import { expect, test, type Page } from "@playwright/test";
import { makeMotion, openStudio, shot, showFrame } from "./studio";

const UPPER = [0, 1, 2, 3, 6, 9, 12, 15, 16, 17]; // trunk, head, shoulders
const ALL = Array.from({ length: 22 }, (_, j) => j);

function boxes(page: Page, joints: number[]) {
  return page.evaluate((js) => {
    const h = window.__interplay;
    return Array.from({ length: h.persons }, (_, p) => {
      const pts = js.map((j) => h.project(p, j)!);
      const xs = pts.map((q) => q[0]);
      const ys = pts.map((q) => q[1]);
      return { x0: Math.min(...xs), x1: Math.max(...xs), y0: Math.min(...ys), y1: Math.max(...ys) };
    });
  }, joints);
}

test("the Side view frames both people of a pair, apart", async ({ page }, info) => {
  const id = await makeMotion(page.request, { prompt: "two people shake hands", persons: 2, seconds: 4, seed: 3 });
  await openStudio(page, `/m/${id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done" && window.__interplay.persons === 2);
  const frames = await page.evaluate(() => window.__interplay.frameCount);
  await showFrame(page, 0);
  await page.getByRole("button", { name: "Side view", exact: true }).click();
  await page.waitForFunction(() => window.__interplay.view.preset === "side");
  const canvas = (await page.getByTestId("viewport").boundingBox())!;
  const [p0, p1] = [0, 1].map((p) => page.evaluate((q) => window.__interplay.frameJoints(q, 0)![0], p));
  const [a0, a1] = [await p0, await p1];
  const line = [a1[0] - a0[0], a1[2] - a0[2]].map((v, _, arr) => v / Math.hypot(...arr));
  const v = await page.evaluate(() => window.__interplay.view);
  const dir = v.position.map((x, k) => x - v.target[k]);
  const along = (dir[0] * line[0] + dir[2] * line[1]) / Math.hypot(dir[0], dir[2]);
  expect(along, "seen from Person 2's end, off the line").toBeGreaterThan(0.4);
  expect(along).toBeLessThan(0.87);
  for (const f of [0, Math.floor(frames / 2), frames - 1]) {
    await showFrame(page, f);
    for (const [p, b] of (await boxes(page, ALL)).entries()) {
      expect(b.x0, `frame ${f}: person ${p + 1} inside (left)`).toBeGreaterThan(canvas.x + 2);
      expect(b.x1, `frame ${f}: person ${p + 1} inside (right)`).toBeLessThan(canvas.x + canvas.width - 2);
      expect(b.y0, `frame ${f}: person ${p + 1} inside (top)`).toBeGreaterThan(canvas.y + 2);
      expect(b.y1, `frame ${f}: person ${p + 1} inside (bottom)`).toBeLessThan(canvas.y + canvas.height - 2);
    }
    const [a, b] = await boxes(page, UPPER);
    expect(Math.max(b.x0 - a.x1, a.x0 - b.x1), `frame ${f}: trunks apart (px)`).toBeGreaterThan(4);
    if (f === Math.floor(frames / 2)) await shot(page, "sv-side-handshake", info);
  }
});
