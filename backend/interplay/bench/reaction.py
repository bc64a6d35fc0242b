"""The reaction section of `interplay bench`: per-frame latency of the online ARFlow reactor
(`ReactionSession.step`: `steps` graph calls over the sliding window + guidance + bone fit;
`CachedReactionSession.step`: `steps` one-frame calls with cached keys/values) on
a held-out captured salsa actor, with and without penetration guidance (one session each,
first frames untimed; onnxruntime, one intra-op thread). Wall time on this shared CPU depends
on the other work running (the load average is reported); `cpu p50` is the CPU time the step's
thread used, close to the wall time on an idle core."""

from __future__ import annotations

import os
import time
from typing import Any

import numpy as np

TARGET_MS = 5.0


def run_reaction_bench(frames: int = 200, warmup: int = 20) -> dict:
    from interplay.motion.clip import default_clips
    from interplay.reaction.session import get_reaction_model
    try:
        model = get_reaction_model()
    except Exception as exc:
        return {"error": f"{type(exc).__name__}: {exc}"}
    clip = next(c for c in default_clips() if c.split == "test" and len(c.people) == 2
                and not c.synthetic)
    actor = np.asarray(clip.people[0][:frames + warmup], dtype=np.float64)
    report: dict[str, Any] = {
        "clip": clip.id, "window": model.window, "steps": model.sampling.steps,
        "cpus": os.cpu_count(), "load_avg_1m": round(os.getloadavg()[0], 2),
        "target_ms": TARGET_MS, "rows": []}
    from interplay.reaction.react import open_session
    for cache, guidance in ((False, False), (False, True), (True, False), (True, True)):
        if cache and model.step_session is None:
            continue
        s = open_session(model, seed=0, guidance=guidance, cache=cache)
        times, cpu = [], []
        for i, f in enumerate(actor):
            t0, c0 = time.perf_counter(), time.thread_time()
            s.step(f)
            if i >= warmup:
                times.append(time.perf_counter() - t0)
                cpu.append(time.thread_time() - c0)
        p50, p95 = (float(np.percentile(times, q)) * 1000 for q in (50, 95))
        report["rows"].append({"guidance": guidance, "cached": cache, "frames": len(times),
                               "p50_ms": round(p50, 2), "p95_ms": round(p95, 2),
                               "cpu_p50_ms": round(float(np.median(cpu)) * 1000, 2),
                               "frames_per_s": round(1000 / p50, 1)})
    report["load_avg_1m_after"] = round(os.getloadavg()[0], 2)
    return report


def format_reaction_table(report: dict) -> str:
    if "error" in report:
        return f"reaction: ARFlow weights did not load: {report['error']}"
    lines = [f"ARFlow reactor, online per frame ({report['cpus']} CPUs, window "
             f"{report['window']} frames, {report['steps']} steps, actor {report['clip']}; "
             f"load average {report['load_avg_1m']:g} → {report['load_avg_1m_after']:g})",
             f"{'task':<22}  {'frames':>6}  {'p50':>9}  {'p95':>9}  {'cpu p50':>9}  "
             f"{'frames/s':>8}"]
    for r in report["rows"]:
        name = ("cached" if r.get("cached") else "window") + (
            ", guidance" if r["guidance"] else ", no guidance")
        lines.append(f"{name:<22}  {r['frames']:>6}  {r['p50_ms']:>6.1f} ms  "
                     f"{r['p95_ms']:>6.1f} ms  {r['cpu_p50_ms']:>6.1f} ms  {r['frames_per_s']:>8.0f}")
    lines.append(f"target: per-frame p50 ≤ {report['target_ms']:g} ms")
    return "\n".join(lines)
