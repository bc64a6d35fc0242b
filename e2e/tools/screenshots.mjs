// Screenshots of the studio's main views for a look by eye: a stored two-person motion playing
// (dark and light theme, 1280×720), a narrow window (390×844), the empty studio. Writes <out>/*.png (not under e2e/test-results: every Playwright run empties that).
//
//   node e2e/tools/screenshots.mjs --base http://127.0.0.1:8000 --motion <two-person id> [--out dir]
import { chromium } from "@playwright/test";
import { mkdirSync } from "node:fs";
import { join } from "node:path";

const args = process.argv.slice(2);
const opt = (name, dflt) => (args.includes(`--${name}`) ? args[args.indexOf(`--${name}`) + 1] : dflt);
const base = opt("base", "http://127.0.0.1:8000");
const motion = opt("motion", null);
const out = opt("out", "/tmp/interplay-look");
mkdirSync(out, { recursive: true });

const browser = await chromium.launch({
  executablePath: "/usr/bin/chromium",
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
});

async function view(name, path, { width = 1280, height = 720, theme = "dark" } = {}) {
  const ctx = await browser.newContext({ viewport: { width, height } });
  await ctx.addInitScript((t) => localStorage.setItem("interplay-theme", t), theme);
  const page = await ctx.newPage();
  await page.goto(`${base}${path}`);
  await page.waitForFunction(() => window.__interplay?.renderCount > 0);
  if (path !== "/") await page.waitForFunction(() => window.__interplay.phase === "done");
  await page.waitForTimeout(1500); // some playback for the picture
  await page.screenshot({ path: join(out, `${name}.png`), fullPage: width < 600 });
  console.log(name, await page.evaluate(() => ({ scale: window.__interplay.renderScale, theme: document.documentElement.dataset.theme })));
  await ctx.close();
}

await view("empty-dark", "/");
await view("empty-light", "/", { theme: "light" });
if (motion) {
  await view("two-dark", `/m/${motion}`);
  await view("two-light", `/m/${motion}`, { theme: "light" });
  await view("two-narrow", `/m/${motion}`, { width: 390, height: 844 });
  await view("two-narrow-light", `/m/${motion}`, { width: 390, height: 844, theme: "light" });
}
await browser.close();
