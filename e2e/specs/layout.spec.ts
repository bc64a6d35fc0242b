import { expect, test } from "@playwright/test";
import { openStudio, shot } from "./studio";

for (const size of [
  { width: 1280, height: 720 },
  { width: 390, height: 844 },
]) {
  test(`the studio fits a ${size.width}×${size.height} window`, async ({ page }, info) => {
    await page.setViewportSize(size);
    await openStudio(page);
    for (const id of ["prompt", "persons-2", "seconds", "generate", "viewport", "play", "scrubber", "metrics"]) {
      const box = await page.getByTestId(id).boundingBox();
      expect(box, id).not.toBeNull();
      expect(box!.x, id).toBeGreaterThanOrEqual(0);
      expect(box!.x + box!.width, id).toBeLessThanOrEqual(size.width + 0.5);
    }
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    expect(overflow).toBeLessThanOrEqual(0);
    await shot(page, `layout-${size.width}x${size.height}`, info);
  });
}
