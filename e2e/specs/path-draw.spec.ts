// Drawing a path: the top view, the length while drawing, a short stroke stays short (the camera
// no longer follows the walking person under the pointer; floor hits near the horizon are not
// taken), and the "next Generate" chip with its remove button.
import { expect, test, type Page } from "@playwright/test";
import { drawOnGround, openStudio, shot, waitDone } from "./studio";

const length = (pts: [number, number][]) => pts.slice(1).reduce((n, p, i) => n + Math.hypot(p[0] - pts[i][0], p[1] - pts[i][1]), 0);
const path = (page: Page) => page.evaluate(() => window.__interplay.path.points);

/** Screen pixels per metre along x and along z at a ground point (how the floor is seen). */
async function pixelsPerMetre(page: Page, x: number, z: number): Promise<[number, number]> {
  return page.evaluate(([x, z]) => {
    const p = window.__interplay.projectPoint;
    const [a, bx, bz] = [p(x, 0, z)!, p(x + 1, 0, z)!, p(x, 0, z + 1)!];
    return [Math.hypot(bx[0] - a[0], bx[1] - a[1]), Math.hypot(bz[0] - a[0], bz[1] - a[1])];
  }, [x, z]);
}

let walk = "";

test.beforeAll(async ({ request }) => {
  const res = await request.post("/api/jobs", { data: { prompt: "a person walks forward", seconds: 8, seed: 2 } });
  expect(res.status()).toBe(201);
  walk = (await res.json()).motion_id;
  await expect.poll(async () => (await request.get(`/api/motions/${walk}`)).status(), { timeout: 150_000 }).toBe(200);
});

test("the path tool looks down on the floor; a short stroke drawn while the person walks stays short", async ({ page }, info) => {
  await openStudio(page, `/m/${walk}`);
  await page.waitForFunction(() => window.__interplay.phase === "done" && window.__interplay.playing);
  // measured where the camera looks (it follows the walk): the canvas centre's floor point
  const look = () =>
    page.evaluate(() => {
      const r = document.querySelector('[data-testid="viewport"]')!.getBoundingClientRect();
      return window.__interplay.groundAt(r.left + r.width / 2, r.top + r.height / 2)!;
    });
  const [sx, sz] = await pixelsPerMetre(page, ...(await look()));
  expect(sz / sx, "the orbit view sees the floor foreshortened").toBeLessThan(0.7);

  await page.getByTestId("tool-path").click();
  await expect(page.getByTestId("top-view")).toHaveAttribute("aria-pressed", "true");
  await page.waitForTimeout(200);
  const [tx, tz] = await pixelsPerMetre(page, ...(await look()));
  expect(tz / tx, "the top view sees the floor square").toBeGreaterThan(0.9);
  expect(tz / tx).toBeLessThan(1.1);
  expect(await page.evaluate(() => window.__interplay.playing), "the walk keeps playing").toBe(true);

  // a 1 m stroke drawn slowly (about 1.5 s) while the person walks on
  const centre = await page.evaluate(() => window.__interplay.groundAt(innerWidth / 3, innerHeight / 2)!);
  const [x0, z0] = centre;
  const screen = await page.evaluate(
    ([x0, z0]) => [0, 0.25, 0.5, 0.75, 1].map((u) => window.__interplay.projectPoint(x0 + u, 0, z0)!),
    [x0, z0],
  );
  await page.mouse.move(screen[0][0], screen[0][1]);
  await page.mouse.down();
  for (let i = 1; i < screen.length; i++) {
    await page.mouse.move(screen[i][0], screen[i][1], { steps: 6 });
    await page.waitForTimeout(300);
    if (i === 2) await expect(page.getByTestId("path-length-live")).toHaveText(/^drawing · 0\.\d m$/);
  }
  await page.mouse.up();
  const drawn = await path(page);
  const metres = length(drawn);
  info.annotations.push({ type: "stroke", description: `1 m stroke while walking → ${metres.toFixed(2)} m path` });
  expect(metres, "the drawn path is as long as the stroke").toBeGreaterThan(0.85);
  expect(metres).toBeLessThan(1.15);
  await expect(page.getByTestId("path-length-live")).toHaveText(`${metres.toFixed(1)} m`);
  await expect(page.getByTestId("path-chip")).toContainText(`${metres.toFixed(1)} m path · next Generate`);
  await shot(page, "p-top-view-drawn", info);

  // the chip's × removes the path
  await page.getByTestId("path-chip-remove").click();
  expect(await path(page)).toEqual([]);
  await expect(page.getByTestId("path-chip")).toHaveCount(0);

  // in the 3D view a stroke up towards the horizon takes no floor beyond 25 m from the camera
  await page.getByTestId("top-view").click();
  await expect(page.getByTestId("top-view")).toHaveAttribute("aria-pressed", "false");
  await page.waitForTimeout(200);
  const far = await page.evaluate(() => window.__interplay.projectPoint(0, 0, -200));
  expect(far![1], "the far point is on screen").toBeGreaterThan(0);
  await drawOnGround(page, [[0, 0], [0, -10], [0, -40], [0, -200]], 12);
  const toHorizon = await path(page);
  expect(toHorizon.length).toBeGreaterThan(2);
  const farthest = Math.max(...toHorizon.map(([x, z]) => Math.hypot(x, z)));
  expect(farthest, "no point near the horizon").toBeLessThan(30);
});

test("a path applies to the next Generate only: the chip says so, and it is used up", async ({ page }, info) => {
  await openStudio(page);
  await page.getByTestId("tool-path").click();
  await drawOnGround(page, [[0, 0], [0.5, 0.8], [1.2, 1.4], [2.0, 1.6]]);
  const drawn = await path(page);
  await expect(page.getByTestId("path-chip")).toBeVisible();
  await page.getByTestId("tool-path").click(); // back to the orbit view
  await page.getByTestId("prompt").fill("a person walks forward");
  await page.getByTestId("seconds").fill("3");
  const sent = page.waitForRequest((r) => r.url().endsWith("/api/jobs") && r.method() === "POST");
  await page.getByTestId("generate").click();
  const body = (await sent).postDataJSON();
  expect(body.trajectory.points).toEqual(drawn);
  const done = await waitDone(page);
  await expect(page.getByTestId("path-chip")).toHaveCount(0);
  expect(await path(page)).toEqual([]);
  const motion = await (await page.request.get(`/api/motions/${done.motionId}`)).json();
  expect(motion.plan.trajectory).toBeTruthy();
  expect(motion.plan.trajectory.person).toBe(0); // "Person 1" on the page
  // the next Generate sends no path
  const again = page.waitForRequest((r) => r.url().endsWith("/api/jobs") && r.method() === "POST");
  await page.getByTestId("prompt").fill("a person walks forward slowly");
  await page.getByTestId("generate").click();
  expect((await again).postDataJSON().trajectory).toBeUndefined();
  // this Generate's own end, not the first job's "done" still on the stage
  const next = await waitDone(page, { after: done.jobId });
  expect(next.motionId).not.toBe(done.motionId);
  await shot(page, "p-path-used-up", info);
});
