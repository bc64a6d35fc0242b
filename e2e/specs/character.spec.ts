// The skinned character (the GLB export's mesh, driven by the server's rotations) instead of
// the mannequin: toggled in the view controls and remembered; while a motion streams the
// mannequin stands in and the page says when the character comes; both people are drawn, on
// the floor where their joints are, and move with the motion. Screenshots: character-*.png.
import { expect, test, type Page } from "@playwright/test";
import { openStudio, shot, showFrame, startGeneration, waitDone } from "./studio";

interface Figure {
  figure: string;
  status: string;
  shown: string;
  characters: number;
}

const figure = (page: Page) => page.evaluate(() => (window.__interplay as unknown as { figure: Figure }).figure);

/** Screenshots decoded in the page from their bytes (a Blob: the page's CSP allows no data:
 * fetch): the colour of `png[0]`'s pixel at `at`, or the share of pixels that differ (a channel
 * by more than 16) between `png[0]` and `png[1]`. */
function inPage(page: Page, pngs: Buffer[], at: [number, number] | null): Promise<number[]> {
  return page.evaluate(
    async ([b64s, at]) => {
      const images = await Promise.all(b64s.map(async (b64) => {
        const bytes = Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0));
        const bmp = await createImageBitmap(new Blob([bytes], { type: "image/png" }));
        const c = new OffscreenCanvas(bmp.width, bmp.height);
        const ctx = c.getContext("2d")!;
        ctx.drawImage(bmp, 0, 0);
        return ctx.getImageData(0, 0, bmp.width, bmp.height);
      }));
      const [x, y] = images;
      if (at) {
        const i = 4 * (Math.round(at[1]) * x.width + Math.round(at[0]));
        return [x.data[i], x.data[i + 1], x.data[i + 2]];
      }
      if (x.width !== y.width || x.height !== y.height) return [1];
      let n = 0;
      for (let i = 0; i < x.data.length; i += 4) {
        if ([0, 1, 2].some((k) => Math.abs(x.data[i + k] - y.data[i + k]) > 16)) n++;
      }
      return [n / (x.width * x.height)];
    },
    [pngs.map((p) => p.toString("base64")), at] as const,
  );
}

/** Colour of the viewport screenshot's pixel under a client position. */
async function pixelAt(page: Page, png: Buffer, x: number, y: number): Promise<number[]> {
  const box = (await page.getByTestId("viewport").boundingBox())!;
  return inPage(page, [png], [x - box.x, y - box.y]);
}

async function difference(page: Page, a: Buffer, b: Buffer): Promise<number> {
  return (await inPage(page, [a, b], null))[0];
}

test("two people as skinned characters: toggled, remembered, on the floor and moving", async ({ page }, info) => {
  await openStudio(page);
  await page.getByTestId("figure-character").click();
  await expect(page.getByTestId("figure-character")).toHaveAttribute("aria-pressed", "true");

  // sample the page every animation frame while it streams: never a character before the
  // motion is stored, and the note says when it comes
  await page.evaluate(() => {
    const w = window as unknown as { __samples: { phase: string; shown: string; note: string }[] };
    w.__samples = [];
    const tick = () => {
      const h = window.__interplay as unknown as { phase: string; figure: Figure };
      w.__samples.push({ phase: h.phase, shown: h.figure.shown, note: document.querySelector("[data-testid=figure-note]")?.textContent ?? "" });
      if (w.__samples.length < 100_000) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  // a fixed seed: the pixels sampled below are the bodies' for this draw (an unseeded draw can
  // turn a dancer edge-on, its lower spine one pixel wide, behind the other)
  await page.getByTestId("seed").fill("3");
  await startGeneration(page, "two people dance salsa", 2, 4);
  const done = await waitDone(page);
  expect(done.persons).toBe(2);
  await page.waitForFunction(() => {
    const f = (window.__interplay as unknown as { figure: Figure }).figure;
    return f.shown === "character" && f.characters === 2;
  }, null, { timeout: 30_000 });
  const samples = await page.evaluate(() => (window as unknown as { __samples: { phase: string; shown: string; note: string }[] }).__samples);
  const streaming = samples.filter((s) => s.phase === "connecting" || s.phase === "generating");
  expect(streaming.length).toBeGreaterThan(0);
  expect(streaming.filter((s) => s.shown === "character")).toEqual([]);
  expect(streaming.some((s) => s.note === "The character appears when the motion is done.")).toBe(true);
  expect(await figure(page)).toMatchObject({ figure: "character", status: "ready", shown: "character", characters: 2 });
  await expect(page.getByTestId("figure-note")).toHaveCount(0);

  // paused at two frames: the people are drawn where their joints are, and they move
  const viewport = page.getByTestId("viewport");
  const frames = [10, Math.min(done.frameCount - 1, 50)];
  const pngs: Buffer[] = [];
  for (const [i, f] of frames.entries()) {
    await showFrame(page, f);
    const png = await shot(viewport, `character-frame${f}`, info);
    pngs.push(png);
    // the empty stage: the top right corner, above the horizon (the clear colour)
    const box = (await viewport.boundingBox())!;
    const empty = await pixelAt(page, png, box.x + box.width - 8, box.y + 8);
    for (const p of [0, 1]) {
      // the pelvis and the lower spine (spine1) are inside the body: not the empty stage's colour
      // (spine3, at the shoulders, is a body edge in a side view with an arm raised)
      for (const j of [0, 3]) {
        const at = await page.evaluate(([p, j]) => window.__interplay.project(p, j)!, [p, j]);
        const c = await pixelAt(page, png, ...at);
        expect(Math.max(...c.map((v, k) => Math.abs(v - empty[k]))), `frame ${f}, person ${p}, joint ${j}`).toBeGreaterThan(40);
      }
    }
    if (i === 0) {
      // the mannequin at the same frame draws the same people differently
      await page.getByTestId("figure-character").click();
      await page.waitForFunction(() => (window.__interplay as unknown as { figure: Figure }).figure.shown === "mannequin");
      await page.waitForTimeout(150);
      const mannequin = await shot(viewport, `character-frame${f}-mannequin`, info);
      expect(await difference(page, png, mannequin)).toBeGreaterThan(0.01);
      await page.getByTestId("figure-character").click();
      await page.waitForFunction(() => (window.__interplay as unknown as { figure: Figure }).figure.shown === "character");
      await page.waitForTimeout(150);
    }
  }
  expect(await difference(page, pngs[0], pngs[1])).toBeGreaterThan(0.005);

  // remembered across a reload (the share page shows the character straight away)
  await page.goto(`/m/${done.motionId}`);
  await expect(page.getByTestId("figure-character")).toHaveAttribute("aria-pressed", "true");
  await page.waitForFunction(() => (window.__interplay as unknown as { figure: Figure }).figure.shown === "character");
  await page.waitForTimeout(500);
  await shot(page, "character-page", info);
});
