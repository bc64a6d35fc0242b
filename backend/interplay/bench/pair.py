"""The pair section of `interplay bench` (`--only pair`): wall and process CPU time of a
two-person CODA generation (`CodaRuntime.generate`: text → masked decoding of both people's
tokens with CFG → decode → bones and floor) for 2, 6 and 10 s, on onnxruntime in this process
(sessions built once, two intra-op threads; text embeddings cached after the warm-up, as in the
server), the 6 s generation with the studio's finishing pass (`pair_finish`: feet held,
the prompt's contact refined) as the product streams it; and the product default for two
people (`run_default_pair_bench`: composition, the penetration pass and review, as a job runs
them)."""

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


def run_default_pair_bench(runs: int = 10, warmup: int = 2, router=None) -> dict:
    """The product default for two people, 6 s, as a job runs it (`orchestrate`: plan →
    composition or retrieve-then-edit → the penetration pass → review rounds → trajectories),
    on the handshake, hug and salsa prompts: {"rows": {prompt: row}, "all": row}."""
    from interplay.generators.base import Request
    from interplay.generators.router import load_generator
    from interplay.pipeline.orchestrator import default_evaluator, orchestrate
    router = router or load_generator()
    evaluator = default_evaluator()
    report: dict[str, Any] = {"load_avg_1m": round(os.getloadavg()[0], 2), "rows": {},
                              "target_ms": TARGET_MS}
    made = {}

    def job(prompt, i):
        out = orchestrate(router, Request(prompt, persons=2, seconds=6.0, seed=i), lambda e: None,
                          lambda s, c: None, evaluator=evaluator)
        made[prompt] = out.plan.generator

    for prompt in PROMPTS:
        times = _timed(lambda i, p=prompt: job(p, i), runs, warmup)
        report["rows"][prompt] = {"generator": made[prompt], **_row(times, 120)}
    report["load_avg_1m_after"] = round(os.getloadavg()[0], 2)
    return report


def format_default_pair_table(report: dict) -> str:
    lines = [f"the product default for two people, 6 s through the job pipeline (plan, "
             f"generator, penetration pass, review; load average {report['load_avg_1m']:g} → "
             f"{report['load_avg_1m_after']:g})",
             f"{'prompt':<28}  {'generator':<13}  {'runs':>4}  {'p50':>8}  {'p95':>8}  {'CPU p50':>8}"]
    for prompt, r in report["rows"].items():
        lines.append(f"{prompt:<28}  {r['generator']:<13}  {r['runs']:>4}  {r['p50_ms']:>5.0f} ms  "
                     f"{r['p95_ms']:>5.0f} ms  {r['cpu_p50_ms']:>5.0f} ms")
    lines.append(f"target: 6 s two-person p50 ≤ {report['target_ms']['generate_6s_p50']:.0f} ms")
    return "\n".join(lines)
