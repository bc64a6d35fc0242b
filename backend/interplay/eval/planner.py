"""Measure the embedded planner on CoMA's 40 challenging prompts (Table 8, with the paper's
labels, in eval/data/table8_prompts.json): how often its segment count, part edits,
trajectories and repeats agree with the paper's marks, and how long a plan takes.

    python -m interplay.eval.planner [--json] [--table PATH] [--no-similarity]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path
from typing import Any

from interplay.eval.data import TABLE8
from interplay.planner.decompose import POSTURE_BASE
from interplay.planner.plan import embedded_plan


def _count_ok(label: str, n: int, tolerance: bool) -> bool:
    if label == "long":
        return n >= 3
    want = {"short": 1, "medium": 2}[label]
    return abs(n - want) <= (1 if tolerance and label == "short" else 0)


def _composed(segment) -> bool:
    """Spatially composed: a whole-body motion with part edits, or different edits for
    different parts (one arm waving on a standing body is a single part motion)."""
    edits = segment.edits.named()
    moving = segment.base not in POSTURE_BASE.values()
    return bool(edits) and (moving or len(set(edits.values())) > 1)


def measure(prompts: list[dict], vocabulary=None) -> dict:
    rows, times = [], []
    for item in prompts:
        t0 = time.perf_counter()
        plan = embedded_plan(item["prompt"], 1, None, vocabulary)
        times.append(time.perf_counter() - t0)
        segs = plan.segments
        rows.append({
            "id": item["id"], "temporal": item["temporal"], "segments": len(segs),
            "count_exact": _count_ok(item["temporal"], len(segs), False),
            "count_tolerant": _count_ok(item["temporal"], len(segs), True),
            "spatial": item["spatial"], "edits": any(_composed(s) for s in segs),
            "trajectory_mark": item["trajectory"], "trajectory": any(s.trajectory for s in segs),
            "repeated": item["repeated"],
            "repeat": any(s.repeat > 1 for s in segs) or len({s.prompt for s in segs}) < len(segs),
            "prompts": [s.prompt for s in segs]})
    summary: dict[str, Any] = {}
    for label in ("short", "medium", "long"):
        sub = [r for r in rows if r["temporal"] == label]
        summary[label] = {"prompts": len(sub), "exact": sum(r["count_exact"] for r in sub),
                          "tolerant": sum(r["count_tolerant"] for r in sub)}
    for mark, got in (("spatial", "edits"), ("trajectory_mark", "trajectory"), ("repeated", "repeat")):
        summary[mark] = {"marked": sum(r[mark] for r in rows),
                         "marked_and_planned": sum(r[mark] and r[got] for r in rows),
                         "unmarked_and_not_planned": sum(not r[mark] and not r[got] for r in rows),
                         "unmarked": sum(not r[mark] for r in rows)}
    summary["ms_per_plan_median"] = round(1000 * sorted(times)[len(times) // 2], 1)
    return {"summary": summary, "rows": rows}


def format_table(report: dict) -> str:
    s = report["summary"]
    lines = ["| paper label | prompts | segment count as the paper's | within short ±1 |",
             "|---|---|---|---|"]
    for label in ("short", "medium", "long"):
        r = s[label]
        lines.append(f"| {label} | {r['prompts']} | {r['exact']} | {r['tolerant']} |")
    lines += ["", "| paper mark | marked | marked → planned | unmarked → not planned |",
              "|---|---|---|---|"]
    for mark, name in (("spatial", "spatial composition → composed part edits"),
                       ("trajectory_mark", "explicit trajectory → trajectory"),
                       ("repeated", "repeated motion → repeat / repeated segments")):
        r = s[mark]
        lines.append(f"| {name} | {r['marked']} | {r['marked_and_planned']}/{r['marked']} | "
                     f"{r['unmarked_and_not_planned']}/{r['unmarked']} |")
    lines += ["", f"median time per plan: {s['ms_per_plan_median']} ms"]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m interplay.eval.planner")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--table", default=str(TABLE8))
    ap.add_argument("--no-similarity", action="store_true", help="plan without the MiniLM vocabulary")
    args = ap.parse_args(argv)
    prompts = json.loads(Path(args.table).read_text())["prompts"]
    vocab = None
    if not args.no_similarity:
        from interplay.planner.vocabulary import load_vocabulary
        vocab = load_vocabulary
    report = measure(prompts, vocab)
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
