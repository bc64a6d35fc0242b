// A prompt nothing in the library covers (issue 24, 1): typed as a user would, the studio's
// agent timeline says "not in the library — showing the nearest: …" for that segment, with what
// was shown, and never a green "ok"; the segment it does cover reads as usual.
import { expect, test } from "@playwright/test";
import { openStudio, shot, startGeneration, waitDone } from "./studio";

test("a person levitates and spins in the air: the levitating is not in the library, said so", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "a person levitates and spins in the air", 1, 5);
  await waitDone(page);
  const verdict = page.getByTestId("segment-verdict-0");
  await expect(verdict).toContainText("not in the library — showing the nearest: ");
  await expect(verdict).not.toHaveText(/not in the library — showing the nearest: $/); // what was shown is named
  await expect(page.getByTestId("segment-0").locator(".badge--not-covered").first()).toBeVisible();
  await expect(page.getByTestId("segment-verdict-1")).not.toContainText("not in the library");
  await page.getByTestId("segment-0").scrollIntoViewIfNeeded();
  await shot(page, "not-covered-levitates", info);
});
