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

  // The API keeps a drawn path's size and retimes the walk to cover it, so the person ends
  // where the path ends (trajectory.retime).
  await startGeneration(page, "a person walks forward", 1, 3);
  const done = await waitDone(page);
  const motion = await motionOf(page, done.motionId!);
  expect(motion.plan.trajectory).toBeTruthy();
  const pelvis = motion.people[0].joints.map((f) => f[0]);
  const last = pelvis[pelvis.length - 1];
  const expected = end;
  const drawn = path.points;
  const toCurve = (x: number, z: number) =>
    Math.min(
      ...drawn.slice(1).map((q, i) => {
        const p = drawn[i];
        const [dx, dz] = [q[0] - p[0], q[1] - p[1]];
        const u = Math.max(0, Math.min(1, ((x - p[0]) * dx + (z - p[1]) * dz) / (dx * dx + dz * dz || 1)));
        return Math.hypot(x - p[0] - u * dx, z - p[1] - u * dz);
      }),
    );
  const miss = Math.hypot(last[0] - expected[0], last[2] - expected[1]);
  const off = Math.max(...pelvis.filter((_, t) => t % 5 === 0).map((p) => toCurve(p[0], p[2])));
  info.annotations.push({
    type: "path",
    description: `drawn end ${end}, pelvis end ${last}, end miss ${miss.toFixed(2)} m, max off-curve ${off.toFixed(2)} m`,
  });
  // the pelvis stays on the drawn curve all the way and ends near the drawn end
  expect(off, `pelvis leaves the drawn curve by ${off.toFixed(2)} m`).toBeLessThan(0.3);
  expect(miss, `pelvis ends at ${last}, expected ≈ ${expected}`).toBeLessThan(0.3);
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
