"""The pair section of `interplay bench` (`--only pair`): wall and process CPU time of a
two-person CODA generation (`CodaRuntime.generate`: text → masked decoding of both people's
tokens with CFG → decode → bones and floor) for 2, 6 and 10 s, on onnxruntime in this process
(sessions built once, two intra-op threads; text embeddings cached after the warm-up, as in the
server), and the 6 s generation with the studio's finishing pass (`pair_finish`: feet held,
the prompt's contact refined) as the product streams it."""

from __future__ import annotations

import os
import time
from pathlib import Path
from typing import Any

from interplay.bench.model import _row, _timed

PROMPTS = ["two people shake hands", "two people hug each other", "two people dance salsa"]
TARGET_MS = {"generate_6s_p50": 400.0}


def run_pair_bench(weights_dir: str | Path | None = None, runs: int = 10, warmup: int = 2,
                   seconds: tuple[float, ...] = (2.0, 6.0, 10.0), runtime=None) -> dict:
    """{"weights", "trained", "generate": [rows], "target_ms"} or {"error": why}."""
    from interplay.generators.coda.files import DEFAULT_DIR
    from interplay.generators.coda.runtime import CodaRuntime
    from interplay.generators.weights import placeholder_reason
    weights_dir = Path(weights_dir or DEFAULT_DIR)
    t0 = time.perf_counter()
    try:
        rt = runtime or CodaRuntime.load(weights_dir, threads=2)
    except Exception as exc:
        return {"weights": str(weights_dir), "error": f"{type(exc).__name__}: {exc}"}
    c = rt.config
    report: dict[str, Any] = {
        "weights": str(weights_dir), "trained": placeholder_reason(weights_dir, "CODA") is None,
        "load_s": round(time.perf_counter() - t0, 3), "cpus": os.cpu_count(), "threads": 2,
        "load_avg_1m": round(os.getloadavg()[0], 2), "codes": c.codes,
        "steps": c.steps, "cfg": c.cfg, "window_tokens": c.window_tokens, "generate": [],
        "target_ms": TARGET_MS}
    for s in seconds:
        frames = round(s * 20)
        times = _timed(lambda i, s=s: rt.generate(PROMPTS[i % len(PROMPTS)], s, seed=i), runs, warmup)
        report["generate"].append({"seconds": s, **_row(times, frames)})
    from interplay.generators.coda.finish import finish_pair

    def product(i):
        prompt = PROMPTS[i % len(PROMPTS)]
        finish_pair(rt.generate(prompt, 6.0, seed=i), prompt)
    report["product"] = {"seconds": 6.0, **_row(_timed(product, runs, warmup), 120)}
    report["load_avg_1m_after"] = round(os.getloadavg()[0], 2)
    return report


def format_pair_table(report: dict) -> str:
    if "error" in report:
        return f"pair: CODA weights in {report['weights']} did not load: {report['error']}"
    state = "trained" if report["trained"] else "UNTRAINED placeholder"
    lines = [f"CODA (two people) on onnxruntime ({report['cpus']} CPUs, {report['threads']} "
             f"threads, {state} weights, K={report['codes']}, {report['steps']} steps, cfg "
             f"{report['cfg']:g}, window {report['window_tokens']} tokens, sessions "
             f"{report['load_s']:.2f} s; load average {report['load_avg_1m']:g} → "
             f"{report['load_avg_1m_after']:g})",
             f"{'task':<16}  {'frames':>6}  {'runs':>4}  {'p50':>8}  {'p95':>8}  {'frames/s':>8}"
             f"  {'CPU p50':>8}"]
    rows = [("generate " + format(r["seconds"], "g") + " s", r) for r in report["generate"]]
    if "product" in report:
        rows.append(("+ finish 6 s", report["product"]))
    for name, r in rows:
        lines.append(f"{name:<16}  {r['frames']:>6}  "
                     f"{r['runs']:>4}  {r['p50_ms']:>5.0f} ms  {r['p95_ms']:>5.0f} ms  "
                     f"{r['frames_per_s']:>8.0f}  {r['cpu_p50_ms']:>5.0f} ms")
    lines.append(f"target: 6 s two-person generate p50 ≤ "
                 f"{report['target_ms']['generate_6s_p50']:.0f} ms ('+ finish': the same with "
                 "the studio's feet and contact pass)")
    return "\n".join(lines)
