import { expect, test } from "@playwright/test";
import { makeMotion, openStudio, shot } from "./studio";

// Issue 26, point 8: exported files carried only the motion id. Now every download is
// interplay-<prompt words>-<id>.<ext> (slugified, bounded), the same in the API's
// Content-Disposition and in the page's download names.
test("exports are named after the prompt: interplay-<prompt words>-<id>.<ext>", async ({ page }, info) => {
  const prompt = "A person waves, then JUMPS — twice! And then walks off to the left across the whole stage";
  const id = await makeMotion(page.request, { prompt, persons: 1, seconds: 1, seed: 2 });
  const words = "a-person-waves-then-jumps-twice-and-then-walks"; // ≤ 48 characters, cut at a word
  expect(words.length).toBeLessThanOrEqual(48);
  await openStudio(page, `/m/${id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");

  for (const [testId, name] of [
    ["export-json", `interplay-${words}-${id}.json`],
    ["export-bvh-0", `interplay-${words}-${id}-person1.bvh`],
    ["export-glb", `interplay-${words}-${id}.glb`],
  ] as const) {
    await expect(page.getByTestId(testId)).toHaveAttribute("download", name);
    const download = page.waitForEvent("download");
    await page.getByTestId(testId).click();
    expect((await download).suggestedFilename()).toBe(name);
    // the API says the same to any client
    const href = (await page.getByTestId(testId).getAttribute("href"))!;
    const res = await page.request.get(href);
    expect(res.headers()["content-disposition"]).toBe(`attachment; filename="${name}"`);
  }
  // the form edited afterwards does not rename the shown motion's files
  await page.getByTestId("prompt").fill("something else entirely");
  await expect(page.getByTestId("export-json")).toHaveAttribute("download", `interplay-${words}-${id}.json`);
  await shot(page.getByTestId("export-json").locator(".."), "x-export-names", info);
});
