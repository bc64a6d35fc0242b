import { expect, test } from "@playwright/test";
import { hook, motionOf, openStudio, shot, startGeneration, waitDone } from "./studio";

// Part edits run SPAM: the server loads the trained weights in models/weights/spam (see their
// MODEL_CARD.md); with missing or placeholder weights it would answer 503 and this spec fails.
const LEFT_ARM = [13, 16, 18, 20];
const LEGS = [1, 2, 4, 5, 7, 8, 10, 11];

function meanMove(a: number[][][], b: number[][][], joints: number[], from: number, to: number): number {
  let sum = 0;
  let n = 0;
  for (let t = from; t < to; t++)
    for (const j of joints) {
      sum += Math.hypot(a[t][j][0] - b[t][j][0], a[t][j][1] - b[t][j][1], a[t][j][2] - b[t][j][2]);
      n++;
    }
  return sum / n;
}

test("click the left arm, edit it over a range: the arm changes, the legs stay", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "a person walks forward", 1, 3);
  const done = await waitDone(page);

  await page.getByTestId("tool-part").click();
  await page.getByTestId("play").click(); // pause, so the arm stays where we aim
  const elbow = await page.evaluate(() => window.__interplay.project(0, 18));
  await page.mouse.move(elbow![0], elbow![1]);
  await page.mouse.click(elbow![0], elbow![1]);
  await expect(page.getByTestId("selected-part")).toHaveText("Left arm");
  await shot(page, "g-left-arm-selected", info);

  // drag on the timeline track: frames ≈ 10 … 50
  const track = (await page.getByTestId("track").boundingBox())!;
  const x = (f: number) => track.x + (f / 59) * track.width;
  await page.mouse.move(x(10), track.y + track.height / 2);
  await page.mouse.down();
  await page.mouse.move(x(50), track.y + track.height / 2, { steps: 6 });
  await page.mouse.up();
  const range = (await page.evaluate(() => window.__interplay.range))!;
  expect(range[0]).toBeGreaterThanOrEqual(8);
  expect(range[1]).toBeLessThanOrEqual(53);
  await expect(page.getByTestId("part-range")).toContainText(`Frames ${range[0]}`);

  await page.getByTestId("part-prompt").fill("wave");
  await page.getByTestId("part-apply").click();
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2", { timeout: 90_000 });
  const edited = await hook(page);
  const [before, after] = [await motionOf(page, done.motionId!), await motionOf(page, edited.motionId!)];
  expect(after.parent_id).toBe(done.motionId);
  const a = before.people[0].joints;
  const b = after.people[0].joints;
  expect(b).toHaveLength(a.length);
  const arm = meanMove(a, b, LEFT_ARM.slice(1), range[0], range[1]);
  const legs = meanMove(a, b, LEGS, 0, a.length);
  const outside = meanMove(a, b, LEFT_ARM, 0, range[0]);
  info.annotations.push({ type: "edit", description: `left arm moved ${(arm * 100).toFixed(1)} cm, legs ${(legs * 100).toFixed(2)} cm` });
  expect(arm).toBeGreaterThan(0.02); // the arm moved in the range
  expect(legs).toBeLessThan(0.01); // the legs stayed (IK round trip only)
  expect(outside).toBeLessThan(0.01); // and so did the arm before the range
  await expect(page.getByTestId("part-editor")).toBeVisible();
  await shot(page, "g-left-arm-edited", info);
});
