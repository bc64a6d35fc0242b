// Each version keeps its review rounds (issue 26.3): after a segment re-run (the UI's button) the
// timeline of the new version still shows every segment's rounds — the re-run segment its own
// review, marked as such —, undo shows the parent's rounds again; a version made by a part edit
// shows the edit's own review on the segment it changed.
import { expect, test, type Page } from "@playwright/test";
import { makeMotion, openStudio, shot } from "./studio";

const PROMPT = "a person walks forward, then jumps, then sits down";

const rounds = (page: Page, i: number) => page.getByTestId(`segment-${i}`).getByTestId("review");

test("a re-run and a part edit keep every segment's rounds; the changed segment shows its own review", async ({ page, request }, info) => {
  const id = await makeMotion(request, { prompt: PROMPT, seconds: 6, seed: 1 });
  await openStudio(page, `/m/${id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  const before = await Promise.all([0, 1, 2].map((i) => rounds(page, i).allTextContents()));
  for (const r of before) expect(r.length).toBeGreaterThan(0);
  await expect(page.getByTestId("version-review-1")).toHaveCount(0);

  // Re-run segment 2 of 3 in the page: a new version
  await page.getByTestId("rerun-1").click();
  await page.waitForFunction((old) => window.__interplay.motionId !== old && window.__interplay.versions.ids.length === 2, id, { timeout: 60_000 });
  await expect(page.getByTestId("version-review-1")).toHaveText(/^This version's own review, after its edit: re-run with a new seed \(seed \d+\)$/);
  expect(await rounds(page, 0).allTextContents()).toEqual(before[0]); // untouched: the same rounds
  expect(await rounds(page, 2).allTextContents()).toEqual(before[2]);
  await expect(rounds(page, 1)).toHaveCount(1); // the re-run's own round
  await expect(page.getByTestId("segment-verdict-1")).not.toHaveText(/not reviewed|waiting/);
  await page.getByTestId("segment-1").scrollIntoViewIfNeeded();
  await shot(page, "vr-rerun", info);

  // undo: the parent's rounds again
  await page.keyboard.press("Control+z");
  await page.waitForFunction((old) => window.__interplay.motionId === old, id);
  await expect(page.getByTestId("version-review-1")).toHaveCount(0);
  expect(await rounds(page, 1).allTextContents()).toEqual(before[1]);

  // a part edit (through the API) opened as a version: the edited segment's own review
  const seg0 = (await (await request.get(`/api/motions/${id}`)).json()).plan.segments[0];
  const r = await request.post(`/api/motions/${id}/edit`, {
    data: { part: "left_arm", prompt: "raises the left arm", frames: [seg0.start + 2, seg0.end - 2], seed: 3 },
  });
  expect(r.status(), await r.text()).toBe(201);
  const edited = (await r.json()).id as string;
  await openStudio(page, `/m/${edited}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await expect(page.getByTestId("version-review-0")).toHaveText(`This version's own review, after its edit: left arm: “raises the left arm” (frames ${seg0.start + 2}–${seg0.end - 2})`);
  await expect(rounds(page, 0)).toHaveCount(1);
  expect(await rounds(page, 1).allTextContents()).toEqual(before[1]);
  expect(await rounds(page, 2).allTextContents()).toEqual(before[2]);
  await page.getByTestId("segment-0").scrollIntoViewIfNeeded();
  await shot(page, "vr-part-edit", info);
});
