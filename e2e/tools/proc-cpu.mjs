// CPU time of Chromium's processes under a process (the Playwright worker, or a script that
// launched the browser), by Chromium process type, from /proc/<pid>/stat (Linux only).
import { readdirSync, readFileSync } from "node:fs";

const TICK = 100; // USER_HZ: /proc times are in 1/100 s

function stat(path) {
  const s = readFileSync(path, "utf8");
  return { name: s.slice(s.indexOf("(") + 1, s.lastIndexOf(")")), f: s.slice(s.lastIndexOf(")") + 2).split(" ") };
}

function children() {
  const kids = new Map();
  for (const d of readdirSync("/proc")) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const ppid = Number(stat(`/proc/${d}/stat`).f[1]);
      if (!kids.has(ppid)) kids.set(ppid, []);
      kids.get(ppid).push(Number(d));
    } catch {
      /* gone */
    }
  }
  return kids;
}

/** CPU seconds (user + system) of the Chromium processes under `root`, keyed gpu / renderer /
 * utility / browser; with `threads`, also "gpu:<thread name>" and "renderer:<thread name>". */
export function chromiumCpu(root = process.pid, threads = false) {
  const kids = children();
  const out = {};
  const stack = [...(kids.get(root) ?? [])];
  while (stack.length) {
    const pid = stack.pop();
    stack.push(...(kids.get(pid) ?? []));
    try {
      const cmd = readFileSync(`/proc/${pid}/cmdline`, "utf8");
      if (!cmd.includes("chrom")) continue;
      const { f } = stat(`/proc/${pid}/stat`);
      const type = /--type=([\w-]+)/.exec(cmd)?.[1] ?? "browser";
      const key = type === "gpu-process" ? "gpu" : type === "renderer" ? "renderer" : type === "utility" ? "utility" : "browser";
      out[key] = (out[key] ?? 0) + (Number(f[11]) + Number(f[12])) / TICK;
      if (!threads || (key !== "gpu" && key !== "renderer")) continue;
      for (const t of readdirSync(`/proc/${pid}/task`)) {
        try {
          const ts = stat(`/proc/${pid}/task/${t}/stat`);
          const k = `${key}:${ts.name.replace(/\d+$/, "#")}`;
          out[k] = (out[k] ?? 0) + (Number(ts.f[11]) + Number(ts.f[12])) / TICK;
        } catch {
          /* gone */
        }
      }
    } catch {
      /* gone */
    }
  }
  return out;
}

/** CPU ms per frame between two chromiumCpu() readings: total (processes only) and per key. */
export function perFrame(before, after, frames) {
  const n = Math.max(1, frames);
  const per = {};
  for (const k of Object.keys(after)) per[k] = +((((after[k] ?? 0) - (before[k] ?? 0)) * 1000) / n).toFixed(1);
  const total = Object.keys(per).filter((k) => !k.includes(":")).reduce((a, k) => a + per[k], 0);
  return { total: +total.toFixed(1), per };
}
