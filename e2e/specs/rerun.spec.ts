import { expect, test } from "@playwright/test";
import { hook, motionOf, openStudio, shot, startGeneration, waitDone } from "./studio";

type Joints = number[][][];

const same = (a: Joints, b: Joints) => JSON.stringify(a) === JSON.stringify(b);
const maxDiff = (a: Joints, b: Joints) =>
  Math.max(...a.flatMap((f, t) => f.flatMap((j, k) => j.map((v, c) => Math.abs(v - b[t][k][c])))));

// "Re-run (new seed)" on segment 2 of 3 regenerates that segment in place: segments 1 and 3
// keep their joints exactly, the motion keeps its length, it is a new version (v2 / 2) whose
// parent is the original, and undo brings the old segment 2 back.
test("re-running segment 2 of 3 keeps segments 1 and 3; undo restores the old segment 2", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "a person walks forward, then jumps, then sits down", 1, 6);
  const v1 = await waitDone(page);
  const old = await motionOf(page, v1.motionId!);
  const segs = (old.plan.segments as { start: number; end: number }[]).map((s) => [s.start, s.end]);
  // three segments over the 120 frames, in order (the planner gives the walk the most time)
  expect(segs.length).toBe(3);
  expect(segs[0][0]).toBe(0);
  expect(segs[2][1]).toBe(120);
  expect(segs[1][0]).toBe(segs[0][1]);
  expect(segs[2][0]).toBe(segs[1][1]);
  const [a1, b1] = segs[1];
  await expect(page.getByTestId("version-label")).toHaveText("v1 / 1");

  // what the progress says meanwhile (the re-run may be over before an assertion could look)
  await page.evaluate(() => {
    const w = window as unknown as { __labels: string[] };
    w.__labels = [];
    new MutationObserver(() => {
      const t = document.querySelector('[data-testid="progress-label"]')?.textContent;
      if (t && w.__labels.at(-1) !== t) w.__labels.push(t);
    }).observe(document.body, { subtree: true, childList: true, characterData: true });
  });
  const rerun = page.waitForResponse((r) => r.request().method() === "POST" && /\/segments\/1\/rerun$/.test(r.url()));
  await page.getByTestId("rerun-1").click();
  expect((await rerun).status()).toBe(201);
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  const v2 = await hook(page);
  expect(v2.motionId).not.toBe(v1.motionId);
  expect(v2.frameCount).toBe(120);
  await expect(page).toHaveURL(new RegExp(`/m/${v2.motionId}$`));
  await expect(page.getByTestId("version-edit")).toContainText("segment 2 generated again");
  const labels = await page.evaluate(() => (window as unknown as { __labels: string[] }).__labels);
  expect(labels.some((l) => l.startsWith("Re-running segment 2 of 3 with a new seed"))).toBe(true);

  const now = await motionOf(page, v2.motionId!);
  expect(now.parent_id).toBe(v1.motionId);
  const a = old.people[0].joints, b = now.people[0].joints;
  expect(b).toHaveLength(120);
  expect(same(a.slice(0, a1), b.slice(0, a1))).toBe(true); // segment 1: the same joints
  expect(same(a.slice(b1), b.slice(b1))).toBe(true); // segment 3: the same joints
  expect(maxDiff(a.slice(a1 + 2, b1 - 2), b.slice(a1 + 2, b1 - 2))).toBeGreaterThan(0.01); // segment 2: new
  // the page plays the new version: its frames are the stored ones
  for (const t of [30, 75, 105]) {
    const shown = await page.evaluate((t) => window.__interplay.frameJoints(0, t), t);
    expect(maxDiff([shown!], [b[t]])).toBeLessThan(1e-4);
  }
  await shot(page, "s-rerun-segment-2", info);

  // undo: the old segment 2 is back (the page's frames and the URL)
  await page.getByTestId("undo").click();
  await expect(page.getByTestId("version-label")).toHaveText("v1 / 2");
  await expect(page).toHaveURL(new RegExp(`/m/${v1.motionId}$`));
  expect((await hook(page)).motionId).toBe(v1.motionId);
  for (const t of [a1 + 5, Math.round((a1 + b1) / 2), b1 - 5]) {
    const shown = await page.evaluate((t) => window.__interplay.frameJoints(0, t), t);
    expect(maxDiff([shown!], [a[t]])).toBeLessThan(1e-4);
  }
  // and redo the re-run
  await page.getByTestId("redo").click();
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  expect((await hook(page)).motionId).toBe(v2.motionId);
});
