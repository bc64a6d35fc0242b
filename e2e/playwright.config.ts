// End-to-end tests against the real app: `interplay serve` on a free port with a throwaway
// var dir (database), serving the built front end (frontend/dist), driven in Debian's chromium.
import { defineConfig } from "@playwright/test";
import { existsSync, mkdtempSync } from "node:fs";
import { createServer } from "node:net";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const repo = resolve(here, "..");

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

// The config is evaluated again in every worker: keep the first choice in the environment,
// which workers inherit.
process.env.INTERPLAY_E2E_PORT ??= String(await freePort());
process.env.INTERPLAY_E2E_VAR ??= mkdtempSync(join(tmpdir(), "interplay-e2e-"));
const port = Number(process.env.INTERPLAY_E2E_PORT);
const baseURL = `http://127.0.0.1:${port}`;

if (!existsSync(join(repo, "frontend", "dist", "index.html"))) {
  throw new Error("frontend/dist is missing: run `npm run build --workspace frontend` (or `make test`) first");
}

export default defineConfig({
  testDir: "specs",
  outputDir: "test-results",
  // Generation is CPU bound and the server runs one job at a time: one worker.
  workers: 1,
  fullyParallel: false,
  // In CI a failed spec runs once more, and a pass on the second run is reported as flaky, not
  // hidden. The flake of 6 Dec 2026 (path-draw's "a path applies to the next Generate only",
  // path-shown after it) was waitDone taking the previous job's "done": see `after` there.
  retries: process.env.CI ? 1 : 0,
  timeout: 180_000,
  expect: { timeout: 20_000 },
  reporter: [["list"]],
  use: {
    baseURL,
    browserName: "chromium",
    viewport: { width: 1280, height: 720 },
    acceptDownloads: true,
    screenshot: "only-on-failure",
    trace: "retain-on-failure",
    launchOptions: {
      // Debian's chromium, never a downloaded browser; WebGL through SwiftShader (no GPU).
      executablePath: "/usr/bin/chromium",
      args: [
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--use-gl=angle",
        "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader",
        "--enable-precise-memory-info",
      ],
    },
  },
  webServer: [
    {
      command: `${join(repo, ".venv", "bin", "interplay")} serve --host 127.0.0.1 --port ${port}`,
      cwd: repo,
      url: `${baseURL}/api/skeleton`,
      reuseExistingServer: false,
      timeout: 120_000,
      stdout: "ignore",
      stderr: "pipe",
      env: { INTERPLAY_VAR_DIR: process.env.INTERPLAY_E2E_VAR },
    },
  ],
});
