import { expect, test } from "@playwright/test";
import { motionOf, openStudio, shot, startGeneration, waitDone } from "./studio";

test("two people hug: penetration marks on the timeline jump to their frame; distance plot drawn", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "two people hug", 2, 4);
  const done = await waitDone(page);
  const motion = await motionOf(page, done.motionId!);
  const penetrating = motion.highlights!.penetration.flatMap((p, t) => (p.length ? [t] : []));
  expect(penetrating.length, "the hug overlaps somewhere").toBeGreaterThan(0);

  const marks = page.getByTestId("mark-penetration");
  await expect(marks.first()).toBeVisible();
  // one mark per run of consecutive penetrating frames, at its first frame
  const starts = await marks.evaluateAll((els) => els.map((e) => Number((e as HTMLElement).dataset.frame)));
  const runStarts = penetrating.filter((t, i) => i === 0 || penetrating[i - 1] !== t - 1);
  expect(starts).toEqual(runStarts);

  const target = starts[starts.length - 1];
  await marks.last().click();
  await page.waitForFunction((f) => window.__interplay.currentFrame === f, target);
  expect(await page.evaluate(() => window.__interplay.playing)).toBe(false);

  // the min-distance plot has ink
  const inked = await page.getByTestId("distance-plot").evaluate((c) => {
    const canvas = c as HTMLCanvasElement;
    const d = canvas.getContext("2d")!.getImageData(0, 0, canvas.width, canvas.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++;
    return n;
  });
  expect(inked).toBeGreaterThan(50);
  await page.waitForTimeout(200);
  await shot(page, "i-hug-penetration", info);
});
