"""Measuring the reviewer on CoMA's 40 Table 8 prompts (`interplay review-eval`): each prompt
runs the whole job (orchestrator, the generator the server would load) with seed = its id,
and per segment the first review (before any correction) is compared with the last (after
at most K rounds): alignment score, share of planned part edits the captions confirm, and
every commonsense metric. The table says which generator and which score ran.

    python -m interplay.cli.main review-eval --json
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np

from interplay.eval.data import TABLE8
from interplay.generators.base import Editor
from interplay.pipeline.orchestrator import OrchestratorConfig, default_evaluator, orchestrate

METRICS = ("bone_deviation", "com_lean", "skating_ratio", "foot_skating", "ground_penetration",
           "floating")


def table8_prompts(path: Path = TABLE8) -> list[dict]:
    return json.loads(path.read_text())["prompts"]


def _side(reviews: list[dict]) -> dict:
    planned = sum(len(r["confirmed"]) for r in reviews)
    return {"score": float(np.mean([r["score"] for r in reviews])),
            "confirmed": sum(sum(r["confirmed"].values()) for r in reviews),
            "planned_parts": planned,
            "metrics": {k: float(np.mean([r["checks"]["metrics"][k] for r in reviews]))
                        for k in METRICS},
            "failed_checks": sum(len(r["checks"]["failed"]) for r in reviews)}


def run(generator, prompts: list[dict], seconds: float = 8.0, rounds: int = 2,
        log=lambda m: None) -> dict:
    """Per-prompt rows and the table (means over segments; confirmed share over planned parts)."""
    from interplay.generators.base import Request
    evaluator = default_evaluator()
    cfg = OrchestratorConfig(rounds=rounds)
    rows, t0 = [], time.monotonic()
    for item in prompts:
        req = Request(item["prompt"], persons=1, seconds=seconds, seed=int(item["id"]))
        out = orchestrate(generator, req, lambda e: None, lambda s, c: None,
                          evaluator=evaluator, cfg=cfg)
        segs = out.review["segments"]
        first = [s["reviews"][0] for s in segs]
        last = [s["reviews"][-1] for s in segs]
        corr = [c for s in segs for c in s["corrections"]]
        rows.append({"id": item["id"], "prompt": item["prompt"], "segments": len(segs),
                     "generator": out.plan.generator,
                     "before": _side(first), "after": _side(last),
                     "instructions": [i["kind"] for r in first for i in r["instructions"]],
                     "applied": sum(c["score_after"] is not None for c in corr),
                     "accepted": sum(c["accepted"] for c in corr)})
        before, after = rows[-1]["before"]["score"], rows[-1]["after"]["score"]
        log(f"{item['id']:>2} {before:.3f} → {after:.3f}  {item['prompt'][:60]}")
    return {"prompts": len(rows), "seconds": seconds, "rounds": rounds,
            "generator": sorted({r["generator"] for r in rows}),
            "generator_reason": generator.reason if isinstance(generator, Editor) else None,
            "score_kind": "evaluator" if evaluator is not None else "caption_agreement",
            "elapsed_s": round(time.monotonic() - t0, 1),
            "table": table(rows), "rows": rows}


def table(rows: list[dict]) -> dict:
    def agg(side: str) -> dict:
        segs = sum(r["segments"] for r in rows)
        planned = sum(r[side]["planned_parts"] for r in rows)
        return {"score": float(np.mean([r[side]["score"] for r in rows])),
                "confirmed_share": (sum(r[side]["confirmed"] for r in rows) / planned
                                    if planned else None),
                "failed_checks_per_segment": sum(r[side]["failed_checks"] for r in rows) / segs,
                **{k: float(np.mean([r[side]["metrics"][k] for r in rows])) for k in METRICS}}
    kinds: dict[str, int] = {}
    for r in rows:
        for k in r["instructions"]:
            kinds[k] = kinds.get(k, 0) + 1
    return {"before": agg("before"), "after": agg("after"), "instructions": kinds,
            "corrections_applied": sum(r["applied"] for r in rows),
            "corrections_accepted": sum(r["accepted"] for r in rows),
            "planned_parts": sum(r["before"]["planned_parts"] for r in rows)}


def format_table(report: dict) -> str:
    t = report["table"]
    lines = [f"{report['prompts']} prompts × {report['seconds']:g} s, K = {report['rounds']}, "
             f"generator {'/'.join(report['generator'])}, score: {report['score_kind']}",
             f"{'':28}{'before':>12}{'after':>12}"]
    for k in ("score", "confirmed_share", "failed_checks_per_segment", *METRICS):
        b, a = t["before"][k], t["after"][k]
        cells = ["—" if v is None else f"{v:.4f}" for v in (b, a)]
        lines.append(f"{k:28}{cells[0]:>12}{cells[1]:>12}")
    lines.append(f"instructions (first review): {t['instructions']}; corrections applied "
                 f"{t['corrections_applied']}, accepted {t['corrections_accepted']}")
    return "\n".join(lines)


# -- honesty: does the verdict agree with the benchmark's checks? ----------------------------
VERDICT_ORDER = ("ok", "unconfirmed", "correct", "not_covered", "failed")     # worst last


def output_verdict(review: dict) -> str:
    """One output's verdict: the worst of its segments' last reviews (for two people the last
    segment's last one is the interaction's last round: `correct` there means it still misses
    what they do together, counted as failed). A one-person `correct` is polish left undone."""
    segs = [s for s in review.get("segments", []) if s["reviews"]]
    last = [s["reviews"][-1]["verdict"] for s in segs]
    if segs and segs[-1]["reviews"][-1].get("score_kind") == "interaction_checks" \
            and last[-1] == "correct":
        last[-1] = "failed"
    return max(last, key=VERDICT_ORDER.index, default="ok")


def why_failed(review: dict) -> list[str]:
    """The failed checks and the instructions left of an output's segments that end failed."""
    out = []
    for s in review.get("segments", []):
        last = s["reviews"][-1] if s["reviews"] else None
        if last is not None and last["verdict"] in ("failed", "correct"):
            out += [*last["checks"]["failed"], *(i["kind"] for i in last["instructions"])]
    return sorted(set(out))


def run_honesty(make, prompts, seeds: int = 1, log=lambda m: None) -> dict:
    """Every prompt × seed through `make(req) -> (people, review)`, judged by its checks
    (`eval.prompts.report.judge`) and compared with the reviewer's verdict."""
    from interplay.eval.prompts.report import judge
    from interplay.generators.base import Request
    rows, t0 = [], time.monotonic()
    for p in prompts:
        for seed in range(seeds):
            people, rv = make(Request(p.prompt, persons=p.persons, seconds=p.seconds, seed=seed))
            j = judge(p, people)
            failed = j["total"] - j["passed"]
            rows.append({"id": p.id, "split": p.split, "persons": p.persons, "seed": seed,
                         "prompt": p.prompt, "passed": j["passed"], "total": j["total"],
                         "verdict": output_verdict(rv),
                         "bad": j["total"] > 0 and failed >= j["total"] / 2,
                         "good": j["all_passed"], "why": why_failed(rv)})
            r = rows[-1]
            log(f"{p.id:>8} s{seed} {r['passed']}/{r['total']} {r['verdict']:>11}  {p.prompt[:50]}")
    return {"outputs": len(rows), "seeds": seeds, "elapsed_s": round(time.monotonic() - t0, 1),
            "table": honesty_table(rows), "rows": rows}


def honesty_table(rows: list[dict]) -> dict:
    out = {}
    for name, sel in (("one person", lambda r: r["persons"] == 1),
                      ("two people", lambda r: r["persons"] == 2), ("all", lambda r: True)):
        rs = [r for r in rows if sel(r)]
        bad, good = [r for r in rs if r["bad"]], [r for r in rs if r["good"]]
        out[name] = {"outputs": len(rs), "bad": len(bad), "bad_ok": sum(r["verdict"] == "ok" for r in bad),
                     "good": len(good), "good_failed": sum(r["verdict"] == "failed" for r in good),
                     "verdicts": {v: sum(r["verdict"] == v for r in rs) for v in VERDICT_ORDER}}
    return out


def format_honesty(report: dict) -> str:
    pct = lambda a, n: f"{a}/{n} = {a / n:.0%}" if n else "—"          # noqa: E731
    lines = [f"{report['outputs']} outputs ({report['seeds']} seed(s)), {report['elapsed_s']:.0f} s",
             f"{'':12}{'outputs':>8}  {'failing ≥ half of checks → ok':>30}  "
             f"{'passing all checks → failed':>28}  verdicts ok/unconfirmed/correct/not_covered/failed"]
    for name, t in report["table"].items():
        v = t["verdicts"]
        lines.append(f"{name:12}{t['outputs']:>8}  {pct(t['bad_ok'], t['bad']):>30}  "
                     f"{pct(t['good_failed'], t['good']):>28}  "
                     f"{v['ok']}/{v['unconfirmed']}/{v['correct']}/{v['not_covered']}/{v['failed']}")
    return "\n".join(lines)
