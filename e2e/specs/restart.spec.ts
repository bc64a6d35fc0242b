// A server restart mid-job loses nothing (issue 26.2): this spec runs its own `interplay serve`
// (its own port and INTERPLAY_VAR_DIR; the real models, each 40-frame chunk slowed by 1.5 s so
// the job is surely running), starts a generation in the page, kill -9s the server once frames
// are on stage, and starts it again on the same port and data: the page keeps `?job=` in the
// address, says it is trying again, follows the job the new server runs again (attempt 2), and
// ends with the finished motion on screen, frame for frame the stored one.
import { expect, test } from "@playwright/test";
import { spawn, type ChildProcess } from "node:child_process";
import { mkdtempSync } from "node:fs";
import { createServer } from "node:net";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { shot } from "./studio";

const repo = resolve(dirname(fileURLToPath(import.meta.url)), "..", "..");

function freePort(): Promise<number> {
  return new Promise((ok, fail) => {
    const srv = createServer();
    srv.once("error", fail);
    srv.listen(0, "127.0.0.1", () => {
      const { port } = srv.address() as { port: number };
      srv.close(() => ok(port));
    });
  });
}

function serve(port: number, varDir: string): ChildProcess {
  return spawn(join(repo, ".venv", "bin", "interplay"), ["serve", "--host", "127.0.0.1", "--port", String(port)], {
    cwd: repo,
    stdio: "ignore",
    env: {
      ...process.env,
      INTERPLAY_VAR_DIR: varDir,
      PYTHONPATH: `${join(repo, "backend")}:${repo}`,
      INTERPLAY_GENERATOR_FACTORY: "tests.helpers.jobs:slow_real_generator",
      INTERPLAY_TEST_CHUNK_DELAY_S: "1.5",
    },
  });
}

async function up(base: string, timeout = 120_000): Promise<void> {
  const end = Date.now() + timeout;
  while (Date.now() < end) {
    try {
      if ((await fetch(`${base}/api/skeleton`)).ok) return;
    } catch {
      /* not yet */
    }
    await new Promise((ok) => setTimeout(ok, 250));
  }
  throw new Error(`the server at ${base} did not start`);
}

test("kill -9 the server mid-job and start it again: the page ends with the finished motion", async ({ page }, info) => {
  test.setTimeout(300_000);
  const port = await freePort();
  const base = `http://127.0.0.1:${port}`;
  const varDir = mkdtempSync(join(tmpdir(), "interplay-restart-"));
  let server = serve(port, varDir);
  try {
    await up(base);
    await page.goto(`${base}/`);
    await page.waitForFunction(() => window.__interplay.renderCount > 0);
    await page.getByTestId("prompt").fill("a person walks forward, then jumps, then sits down");
    await page.getByTestId("seconds").fill("6");
    await page.getByTestId("seed").fill("3");
    await page.getByTestId("generate").click();
    await expect(page).toHaveURL(/\?job=[A-Za-z0-9_-]+&motion=[A-Za-z0-9_-]+$/);
    const url = new URL(page.url());
    const jobId = url.searchParams.get("job")!;
    const motionId = url.searchParams.get("motion")!;
    await page.waitForFunction(() => window.__interplay.framesReceived > 0, null, { timeout: 60_000 });
    expect(await page.evaluate(() => window.__interplay.phase)).toBe("generating");

    server.kill("SIGKILL");
    await new Promise((ok) => server.once("exit", ok));
    // the page keeps the job and says the server is away, with no error
    await expect(page.getByTestId("progress-label")).toContainText("The server is not answering", { timeout: 30_000 });
    await expect(page).toHaveURL(new RegExp(`\\?job=${jobId}&motion=${motionId}$`));
    await expect(page.getByTestId("error-banner")).toBeHidden();
    await shot(page, "restart-away", info);

    server = serve(port, varDir);
    await up(base);
    await page.waitForFunction((id) => window.__interplay.phase === "done" && window.__interplay.motionId === id, motionId, { timeout: 120_000 });
    await expect(page).toHaveURL(new RegExp(`/m/${motionId}$`));
    const status = await (await fetch(`${base}/api/jobs/${jobId}`)).json();
    expect(status).toMatchObject({ status: "done", attempts: 2 });
    // the finished motion is on screen: every frame the stored one's, the page's digest check agrees
    await page.waitForFunction((id) => window.__interplay.copyCheck.motionId === id && window.__interplay.copyCheck.matches !== null, motionId);
    expect(await page.evaluate(() => window.__interplay.copyCheck.matches)).toBe(true);
    const differ = await page.evaluate(async (id) => {
      const m = await (await fetch(`/api/motions/${id}`)).json();
      let n = 0;
      m.people[0].joints.forEach((frame: number[][], t: number) => {
        const got = window.__interplay.frameJoints(0, t);
        if (!got || frame.some((xyz, j) => xyz.some((v, c) => Math.fround(v) !== got[j][c]))) n++;
      });
      return { n, frames: m.people[0].joints.length };
    }, motionId);
    expect(differ).toEqual({ n: 0, frames: 120 });
    await expect(page.getByTestId("error-banner")).toBeHidden();
    await expect(page.getByTestId("segment-verdict-2")).not.toHaveText(/waiting|generating/);
    await shot(page, "restart-done", info);
  } finally {
    server.kill("SIGKILL");
  }
});
