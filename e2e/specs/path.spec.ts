import { expect, test } from "@playwright/test";
import { drawOnGround, hook, motionOf, openStudio, shot, startGeneration, waitDone } from "./studio";

test("a drawn path: the generated person walks it and ends near its end", async ({ page }, info) => {
  await openStudio(page);
  await page.getByTestId("tool-path").click();
  // a curve off to the right, not where a plain forward walk goes (+Z)
  await drawOnGround(page, [
    [0, 0],
    [0.8, 1.0],
    [1.8, 1.6],
    [2.8, 1.4],
  ]);
  const path = await page.evaluate(() => window.__interplay.path);
  expect(path.points.length).toBeGreaterThan(5);
  const end = path.points[path.points.length - 1];
  expect(Math.hypot(end[0] - 2.8, end[1] - 1.4)).toBeLessThan(0.15); // the raycast lands where aimed
  await expect(page.getByTestId("path-summary")).toContainText("points");
  await shot(page, "f-path-drawn", info);

  // 3 s of walking ≈ the drawn 3.4 m: the API scales a drawn path to the distance walked
  // (trajectory.scale_to_motion), so the end lands on the drawn end only when they agree
  await startGeneration(page, "a person walks forward", 1, 3);
  const done = await waitDone(page);
  const motion = await motionOf(page, done.motionId!);
  expect(motion.plan.trajectory).toBeTruthy();
  const pelvis = motion.people[0].joints.map((f) => f[0]);
  const last = pelvis[pelvis.length - 1];
  // The API fits a drawn path's length to the distance walked (scaling it about its start;
  // see the report): the end is the drawn end scaled by walked / drawn length.
  const arc = (pts: number[][]) => pts.slice(1).reduce((n, p, i) => n + Math.hypot(p[0] - pts[i][0], p[1] - pts[i][1]), 0);
  const walked = arc(pelvis.filter((_, t) => t % 10 === 0 || t === pelvis.length - 1).map((p) => [p[0], p[2]]));
  const k = walked / arc(path.points);
  const [sx, sz] = path.points[0];
  const expected = [sx + (end[0] - sx) * k, sz + (end[1] - sz) * k];
  const scaled = path.points.map(([x, z]) => [sx + (x - sx) * k, sz + (z - sz) * k]);
  const toCurve = (x: number, z: number) =>
    Math.min(
      ...scaled.slice(1).map((q, i) => {
        const p = scaled[i];
        const [dx, dz] = [q[0] - p[0], q[1] - p[1]];
        const u = Math.max(0, Math.min(1, ((x - p[0]) * dx + (z - p[1]) * dz) / (dx * dx + dz * dz || 1)));
        return Math.hypot(x - p[0] - u * dx, z - p[1] - u * dz);
      }),
    );
  const miss = Math.hypot(last[0] - expected[0], last[2] - expected[1]);
  const off = Math.max(...pelvis.filter((_, t) => t % 5 === 0).map((p) => toCurve(p[0], p[2])));
  info.annotations.push({
    type: "path",
    description: `drawn end ${end}, scale ${k.toFixed(2)}, pelvis end ${last}, end miss ${miss.toFixed(2)} m, max off-curve ${off.toFixed(2)} m`,
  });
  // the pelvis stays on the (scaled) drawn curve all the way and ends near its scaled end
  expect(off, `pelvis leaves the drawn curve by ${off.toFixed(2)} m`).toBeLessThan(0.4);
  expect(miss, `pelvis ends at ${last}, expected ≈ ${expected} (scale ${k.toFixed(2)})`).toBeLessThan(0.75);
  // and heads where the path heads: to the right (+X), not straight ahead (+Z)
  const mid = pelvis[Math.floor(pelvis.length / 2)];
  expect(mid[0]).toBeGreaterThan(0.5);
  await shot(page, "f-path-walked", info);
});

test("a preset path applied to the current motion is a new version following it", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "a person walks forward", 1, 4);
  const first = await waitDone(page);
  await page.getByTestId("tool-path").click();
  await page.getByTestId("preset-circle").click();
  await page.getByTestId("path-size").fill("2");
  const circle = (await page.evaluate(() => window.__interplay.path)).points;
  expect(Math.max(...circle.map((p) => p[0]))).toBeCloseTo(2, 1); // regenerated at 2 m across
  await page.getByTestId("path-apply").click();
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  const h = await hook(page);
  expect(h.motionId).not.toBe(first.motionId);
  await expect(page).toHaveURL(new RegExp(`/m/${h.motionId}$`));
  const edited = await motionOf(page, h.motionId!);
  expect(edited.parent_id).toBe(first.motionId);
  // the root now leaves the straight line: it reaches the far side of the circle (x ≈ 2 m)
  const xs = edited.people[0].joints.map((f) => f[0][0]);
  expect(Math.max(...xs)).toBeGreaterThan(1.0);
  await shot(page, "f-path-preset-applied", info);
});
