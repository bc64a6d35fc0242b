// Helpers for driving the studio page through its UI and reading its test hook.
import { expect, type APIRequestContext, type Locator, type Page, type TestInfo } from "@playwright/test";
import { mkdirSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

export interface HookSnapshot {
  motionId: string | null;
  phase: string;
  /** The job streamed (or last streamed) on the stage; null for a motion opened from a link. */
  jobId: string | null;
  persons: number;
  frameCount: number;
  framesReceived: number;
  fps: number;
  firstFrame: number[][][];
  currentFrame: number;
  renderCount: number;
  quality: string;
}

interface BvhSummary {
  bones: number;
  joints: string[];
  endSites: number;
  frames: number;
  duration: number;
}

declare global {
  interface Window {
    __interplay: HookSnapshot & {
      parseBvh(text: string): Promise<BvhSummary>;
      streamMode: string;
      renderScale: number;
      path: { person: number; points: [number, number][] };
      versions: { ids: string[]; index: number };
      selected: { person: number; part: string } | null;
      range: [number, number] | null;
      playing: boolean;
      agentReviews: number;
      library: string[];
      shownPath: { person: number; points: [number, number][]; followed: boolean };
      glowing: number[][];
      frameJoints(person: number, frame: number): number[][] | null;
      project(person: number, joint: number): [number, number] | null;
      groundAt(x: number, y: number): [number, number] | null;
      projectPoint(x: number, y: number, z: number): [number, number] | null;
      view: { preset: string | null; moved: boolean; position: number[]; target: number[] };
      penetrationMarks: number[][];
    };
  }
}

// INTERPLAY_SHOTS moves them elsewhere: every Playwright run empties e2e/test-results/, so two
// runs at once on one machine would delete each other's screenshots.
const SHOTS = process.env.INTERPLAY_SHOTS ?? join(dirname(fileURLToPath(import.meta.url)), "..", "test-results", "screenshots");

/** Save a screenshot under e2e/test-results/screenshots/ (or $INTERPLAY_SHOTS) and attach it to
 * the report. */
export async function shot(target: Page | Locator, name: string, info: TestInfo): Promise<Buffer> {
  mkdirSync(SHOTS, { recursive: true });
  const path = join(SHOTS, `${name}.png`);
  const png = await target.screenshot({ path });
  await info.attach(name, { path, contentType: "image/png" });
  return png;
}

export function hook(page: Page): Promise<HookSnapshot> {
  return page.evaluate(() => {
    const h = window.__interplay;
    return {
      motionId: h.motionId,
      phase: h.phase,
      jobId: h.jobId,
      persons: h.persons,
      frameCount: h.frameCount,
      framesReceived: h.framesReceived,
      fps: h.fps,
      firstFrame: h.firstFrame,
      currentFrame: h.currentFrame,
      renderCount: h.renderCount,
      quality: h.quality,
    };
  });
}

/** Open the studio and wait until the skeleton is loaded and the empty scene has rendered. */
/** Make a motion through the API (POST a job, poll until the motion is stored); its id. */
export async function makeMotion(request: APIRequestContext, body: Record<string, unknown>,
                                 timeout = 150_000): Promise<string> {
  const res = await request.post("/api/jobs", { data: body });
  expect(res.status(), await res.text()).toBe(201);
  const { motion_id } = await res.json();
  await expect.poll(async () => (await request.get(`/api/motions/${motion_id}`)).status(), { timeout }).toBe(200);
  return motion_id as string;
}

export async function openStudio(page: Page, path = "/"): Promise<void> {
  await page.goto(path);
  await expect(page.getByTestId("legend")).toBeVisible();
  await page.waitForFunction(() => window.__interplay.renderCount > 0);
}

/** Fill the prompt bar and press Generate. */
export async function startGeneration(page: Page, prompt: string, persons: 1 | 2, seconds: number) {
  await page.getByTestId("prompt").fill(prompt);
  await page.getByTestId(`persons-${persons}`).click();
  await page.getByTestId("seconds").fill(String(seconds));
  await page.getByTestId("generate").click();
}

/** Wait for the stream to finish; fails with the page's error message if it did not.
 *
 * `after`: the job the stage showed before this Generate (a snapshot's `jobId`). Until the new
 * job's POST is answered the page still says "done" for that one, so without it a second
 * Generate on the same page is "done" at once, and the snapshot taken a moment later may
 * already say "connecting" (the CI flake of path-draw and path-shown, 6 Dec 2026). */
export async function waitDone(page: Page, { after, timeout = 150_000 }: { after?: string | null; timeout?: number } = {}): Promise<HookSnapshot> {
  await page.waitForFunction(
    (after) => ["done", "error"].includes(window.__interplay.phase) && (after === undefined || window.__interplay.jobId !== after),
    after,
    { timeout },
  );
  const h = await hook(page);
  if (h.phase !== "done") {
    // short: without a banner this would wait for one until the test's own timeout
    const banner = await page.getByTestId("error-banner").textContent({ timeout: 2_000 }).catch(() => null);
    throw new Error(`generation ended in ${h.phase}: ${banner}`);
  }
  return h;
}

/** Pause playback and show frame `frame` (through the scrubber, as a user would). */
export async function showFrame(page: Page, frame: number): Promise<void> {
  if ((await page.getByTestId("play").getAttribute("aria-label")) === "Pause") await page.getByTestId("play").click();
  await page.getByTestId("scrubber").fill(String(frame));
  await page.waitForFunction((f) => window.__interplay.currentFrame === f, frame);
  await page.waitForTimeout(150); // a render tick
}

/** Fraction of pixels that differ (any channel by more than 16) between two PNGs of one size,
 * decoded in the page. */
export async function pixelDifference(page: Page, a: Buffer, b: Buffer): Promise<number> {
  return page.evaluate(
    async ([a64, b64]) => {
      const decode = async (s: string) => {
        // decoded without fetch(data:): the page's CSP allows connections to its own origin only
        const blob = new Blob([Uint8Array.from(atob(s), (ch) => ch.charCodeAt(0))], { type: "image/png" });
        const bmp = await createImageBitmap(blob);
        const c = new OffscreenCanvas(bmp.width, bmp.height);
        const ctx = c.getContext("2d")!;
        ctx.drawImage(bmp, 0, 0);
        return ctx.getImageData(0, 0, bmp.width, bmp.height);
      };
      const [x, y] = [await decode(a64), await decode(b64)];
      if (x.width !== y.width || x.height !== y.height) return 1;
      let diff = 0;
      for (let i = 0; i < x.data.length; i += 4) {
        if (
          Math.abs(x.data[i] - y.data[i]) > 16 ||
          Math.abs(x.data[i + 1] - y.data[i + 1]) > 16 ||
          Math.abs(x.data[i + 2] - y.data[i + 2]) > 16
        )
          diff++;
      }
      return diff / (x.width * x.height);
    },
    [a.toString("base64"), b.toString("base64")],
  );
}

/** Drag the mouse along ground points (world x, z) on the viewport, as a user draws. */
export async function drawOnGround(page: Page, points: [number, number][], stepsPerLeg = 8): Promise<void> {
  const screen = await page.evaluate(
    (pts) => pts.map(([x, z]) => window.__interplay.projectPoint(x, 0, z)!),
    points,
  );
  await page.mouse.move(screen[0][0], screen[0][1]);
  await page.mouse.down();
  for (let i = 1; i < screen.length; i++) await page.mouse.move(screen[i][0], screen[i][1], { steps: stepsPerLeg });
  await page.mouse.up();
}

/** A stored motion from the API. */
export async function motionOf(page: Page, id: string, base = ""): Promise<{
  id: string;
  parent_id: string | null;
  people: { joints: number[][][] }[];
  highlights: { penetration: unknown[][]; min_distance: number[] | null } | null;
  plan: Record<string, unknown>;
}> {
  const res = await page.request.get(`${base}/api/motions/${id}`);
  expect(res.ok()).toBe(true);
  return res.json();
}
