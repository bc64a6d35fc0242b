"""The model section of `interplay bench`: wall time of `SpamRuntime.generate` for 2, 6 and 10 s
motions and of a one-part edit of a 6 s motion, on onnxruntime in this process (sessions built
once, one intra-op thread each, guided passes side by side on twin sessions), and frames
generated per second. Text embeddings are cached after
the warm-up, as in the server."""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np

PROMPTS = ["a person walks forward", "a person jogs in a circle", "a person jumps, then squats"]
EDIT_PROMPT = "the person raises the left arm above the head"
TARGETS_MS = {"generate_6s_p50": 150.0, "edit_p50": 100.0}


def _timed(fn, runs: int, warmup: int) -> tuple[list[float], list[float]]:
    """Wall and process CPU seconds (all threads) per timed call."""
    for i in range(warmup):
        fn(10_000 + i)
    wall, cpu = [], []
    for i in range(runs):
        t0, c0 = time.perf_counter(), time.process_time()
        fn(i)
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return wall, cpu


def _row(times: tuple[list[float], list[float]], frames: int) -> dict:
    wall, cpu = times
    p50, p95 = (float(np.percentile(wall, q)) for q in (50, 95))
    return {"frames": frames, "runs": len(wall), "p50_ms": round(p50 * 1000, 1),
            "p95_ms": round(p95 * 1000, 1), "frames_per_s": round(frames / p50, 1),
            # CPU time is what the work costs; wall time adds waiting for other processes
            "cpu_p50_ms": round(float(np.percentile(cpu, 50)) * 1000, 1)}


def run_model_bench(weights_dir: str | Path | None = None, runs: int = 10, warmup: int = 2,
                    seconds: tuple[float, ...] = (2.0, 6.0, 10.0), runtime=None) -> dict:
    """{"weights", "trained", "generate": [rows per length], "edit": row, "targets_ms"}, or
    {"error": why} when the weights do not load."""
    from interplay.generators.spam.runtime import DEFAULT_DIR, SpamRuntime
    from interplay.generators.weights import placeholder_reason
    weights_dir = Path(weights_dir or DEFAULT_DIR)
    t0 = time.perf_counter()
    try:
        rt = runtime or SpamRuntime.load(weights_dir)
    except Exception as exc:
        return {"weights": str(weights_dir), "error": f"{type(exc).__name__}: {exc}"}
    load_s = time.perf_counter() - t0
    report = {"weights": str(weights_dir), "trained": placeholder_reason(weights_dir, "SPAM") is None,
              "load_s": round(load_s, 3), "cpus": os.cpu_count(),
              "threads": rt.graphs["base"].session.get_session_options().intra_op_num_threads,
              "parallel_cfg": bool(rt.pairs),
              "load_avg_1m": round(os.getloadavg()[0], 2),   # other work on the shared CPUs
              "codes": rt.config.K, "layers": rt.config.Q, "steps": rt.config.steps,
              "generate": [], "targets_ms": TARGETS_MS}
    for s in seconds:
        frames = round(s * 20)
        times = _timed(lambda i, frames=frames: rt.generate(PROMPTS[i % len(PROMPTS)], frames, seed=i),
                       runs, warmup)
        report["generate"].append({"seconds": s, **_row(times, frames)})
    motion = rt.generate(PROMPTS[0], 120, seed=0)
    last = {}

    def edit(i):
        last["edit"] = rt.edit(motion, ["left_upper"], EDIT_PROMPT, seed=i, context=PROMPTS[0])
    times = _timed(edit, runs, warmup)
    report["edit"] = {"seconds": 6.0, "part": "left_upper", **_row(times, 120),
                      "steps": last["edit"].steps,
                      "untouched_change_cm": round(last["edit"].untouched_change_cm, 3)}
    report["load_avg_1m_after"] = round(os.getloadavg()[0], 2)
    return report


def format_model_table(report: dict) -> str:
    if "error" in report:
        return f"model: SPAM weights in {report['weights']} did not load: {report['error']}"
    state = "trained" if report["trained"] else "UNTRAINED placeholder"
    layout = ", guided passes side by side" if report.get("parallel_cfg") else ", CFG batched"
    lines = [f"SPAM on onnxruntime ({report['cpus']} CPUs, {report['threads']} thread(s) "
             f"per session{layout}, "
             f"{state} weights, K={report['codes']} Q={report['layers']}, "
             f"{report['steps']} steps, sessions {report['load_s']:.2f} s; "
             f"load average {report['load_avg_1m']:g} → {report['load_avg_1m_after']:g})",
             f"{'task':<16}  {'frames':>6}  {'runs':>4}  {'p50':>8}  {'p95':>8}  {'frames/s':>8}"
             f"  {'CPU p50':>8}"]
    rows = [(f"generate {r['seconds']:g} s", r) for r in report["generate"]]
    rows.append((f"edit 1 part {report['edit']['seconds']:g} s", report["edit"]))
    edit_steps = report["edit"].get("steps")
    for name, r in rows:
        lines.append(f"{name:<16}  {r['frames']:>6}  {r['runs']:>4}  {r['p50_ms']:>5.0f} ms  "
                     f"{r['p95_ms']:>5.0f} ms  {r['frames_per_s']:>8.0f}  {r['cpu_p50_ms']:>5.0f} ms")
    t = report["targets_ms"]
    if edit_steps:
        lines.append(f"(the edit decodes in {edit_steps} steps: its masked share of the window)")
    lines.append(f"targets: 6 s generate p50 ≤ {t['generate_6s_p50']:.0f} ms, "
                 f"edit p50 ≤ {t['edit_p50']:.0f} ms")
    return "\n".join(lines)


def run_default_bench(runs: int = 10, warmup: int = 2, seconds: tuple[float, ...] = (2.0, 6.0, 10.0),
                      router=None) -> dict:
    """The product default (the router's retrieve-then-edit: plan → clips → arm actions →
    floor) for 2, 6 and 10 s, and the router's one-part edit of a 6 s motion (an arm pose by
    IK): {"generate": [rows], "edit": row, "targets_ms"}."""
    from interplay.generators.base import Request, generate_motion
    from interplay.generators.router import load_generator
    router = router or load_generator()
    report: dict = {"generator": "retrieve_edit", "load_avg_1m": round(os.getloadavg()[0], 2),
                    "generate": [], "targets_ms": TARGETS_MS}
    for s in seconds:
        times = _timed(lambda i, s=s: generate_motion(
            router, Request(PROMPTS[i % len(PROMPTS)], seconds=s, seed=i)), runs, warmup)
        report["generate"].append({"seconds": s, **_row(times, round(s * 20))})
    base = np.asarray(generate_motion(router, Request(PROMPTS[0], seconds=6.0, seed=0)).people[0],
                      dtype=np.float64)
    last = {}

    def edit(i):
        last["entry"] = router.edit(base, "left_arm", EDIT_PROMPT, None, seed=i)[1]
    times = _timed(edit, runs, warmup)
    report["edit"] = {"seconds": 6.0, "part": "left_arm", "generator": last["entry"]["generator"],
                      **_row(times, 120)}
    report["load_avg_1m_after"] = round(os.getloadavg()[0], 2)
    return report


def format_default_table(report: dict) -> str:
    lines = [f"the product default ({report['generator']}: plan, captured clips, arm actions, "
             f"floor; load average {report['load_avg_1m']:g} → {report['load_avg_1m_after']:g})",
             f"{'task':<16}  {'frames':>6}  {'runs':>4}  {'p50':>8}  {'p95':>8}  {'frames/s':>8}"
             f"  {'CPU p50':>8}"]
    rows = [(f"generate {r['seconds']:g} s", r) for r in report["generate"]]
    rows.append((f"edit 1 part {report['edit']['seconds']:g} s", report["edit"]))
    for name, r in rows:
        lines.append(f"{name:<16}  {r['frames']:>6}  {r['runs']:>4}  {r['p50_ms']:>5.0f} ms  "
                     f"{r['p95_ms']:>5.0f} ms  {r['frames_per_s']:>8.0f}  {r['cpu_p50_ms']:>5.0f} ms")
    lines.append(f"(the edit ran as {report['edit']['generator']}; targets as above)")
    return "\n".join(lines)
