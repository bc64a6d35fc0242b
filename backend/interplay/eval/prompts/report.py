"""Running the prompt benchmark (`interplay eval-prompts`) and its table.

For every row, every prompt of the split it can serve (SPAM: one person, CODA: two; the others
both) and every seed (seed k is the request's seed, so a run repeats exactly), the output is
judged by the prompt's checks and by the plausibility checks every output gets
(`interplay.motion.checks.named`). Pass rates count checks: a category's rate is the share of
its prompts' checks that passed, per seed; the table shows the mean over seeds with a 95 %
interval (Student's t over the seeds: t(0.975, n−1) · sd / √n; none for one seed). "prompts"
is the share of prompts whose every check passed, "plausible" the share of outputs that pass
every plausibility check. A row that cannot serve a prompt shows n/a there and is counted only
on the prompts it can serve.

Written under `out`: report.json (the table and every result), results.jsonl (one line per
row, prompt and seed) and motions/<row>/<prompt id>-s<seed>.json (the Motion JSON with the
checks under "eval"), so any failure can be opened in the studio or with `interplay metrics`.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from interplay.eval.prompts.rows import Row, edited
from interplay.eval.prompts.suite import Prompt, category_labels, table_categories
from interplay.generators.base import Request
from interplay.motion.checks.named import plausibility, run_check
from interplay.motion.motion import Motion
from interplay.motion.skeleton import FPS

# Student's t(0.975, df) for the interval over seeds (df = seeds − 1).
T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262,
        10: 2.228, 15: 2.131, 20: 2.086, 30: 2.042}
GROUPS = ("one_person", "two_person_all", "all")


def t975(df: int) -> float:
    if df <= 0:
        return math.nan
    keys = sorted(T975)
    return T975[max(k for k in keys if k <= df)] if df < 30 else 1.96


def judge(prompt: Prompt, people: list[np.ndarray], base: list[np.ndarray] | None = None) -> dict:
    """The prompt's checks and the plausibility checks on one output (for a part edit: the
    edited motion, with the motion it was made from as `base`)."""
    checks = [run_check(people, spec, base=base).to_json() for spec in prompt.checks]
    plaus = [r.to_json() for r in plausibility(people, start=prompt.start, contact=prompt.contact)]
    return {"checks": checks, "plausibility": plaus,
            "passed": sum(c["passed"] for c in checks), "total": len(checks),
            "all_passed": all(c["passed"] for c in checks),
            "plausible": all(c["passed"] for c in plaus)}


def _error_result(prompt: Prompt, exc: Exception) -> dict:
    reason = f"{type(exc).__name__}: {exc}"
    return {"checks": [{"check": c["check"], "passed": False, "value": None, "bound": "",
                        "person": None} for c in prompt.checks],
            "plausibility": [], "passed": 0, "total": len(prompt.checks), "all_passed": False,
            "plausible": False, "error": reason}


def run(rows: list[Row], prompts: list[Prompt], seeds: int = 3, out: Path | None = None,
        log: Callable[[str], None] = lambda m: None) -> list[dict]:
    """Every (row, prompt, seed) judged; motions written under out/motions when `out`."""
    results = []
    for row in rows:
        t0 = time.monotonic()
        for prompt in prompts:
            if prompt.persons not in row.persons:
                continue
            for seed in range(seeds):
                req = Request(prompt.prompt, persons=prompt.persons, seconds=prompt.seconds, seed=seed)
                t = time.monotonic()
                try:
                    people, plan = row.make(req)
                    base = None
                    if prompt.edit is not None:    # the studio's edit of the base motion
                        base = people
                        people, plan = edited(row, prompt.prompt, people, plan, prompt.edit, seed)
                    verdict = judge(prompt, people, base)
                except Exception as exc:       # a crash is a failed output, reported as such
                    people, plan, verdict = None, {}, _error_result(prompt, exc)
                rec = {"row": row.name, "id": prompt.id, "category": prompt.category,
                       "persons": prompt.persons, "prompt": prompt.prompt, "seed": seed,
                       "seconds_taken": round(time.monotonic() - t, 3),
                       "generator": plan.get("generator"), **verdict}
                if out is not None and people is not None:
                    path = Path(out) / "motions" / row.name / f"{prompt.id}-s{seed}.json"
                    path.parent.mkdir(parents=True, exist_ok=True)
                    motion = Motion(people=[np.asarray(p, np.float32) for p in people], fps=FPS,
                                    plan=plan, prompt=prompt.prompt, seed=seed).to_json()
                    motion["eval"] = {k: rec[k] for k in ("row", "id", "category", "checks",
                                                          "plausibility")}
                    path.write_text(json.dumps(motion))
                    rec["motion"] = str(path.relative_to(out))
                results.append(rec)
        log(f"{row.name}: {sum(r['row'] == row.name for r in results)} outputs in "
            f"{time.monotonic() - t0:.0f} s")
    return results


def _rate(recs: list[dict], seeds: int) -> dict | None:
    """Mean over seeds of the share of checks passed, its 95 % half-width, and the same for
    whole prompts and plausible outputs."""
    if not recs:
        return None
    per_seed = []
    for s in range(seeds):
        r = [x for x in recs if x["seed"] == s]
        if r:
            per_seed.append((sum(x["passed"] for x in r) / max(sum(x["total"] for x in r), 1),
                             float(np.mean([x["all_passed"] for x in r])),
                             float(np.mean([x["plausible"] for x in r]))))
    arr = np.array(per_seed)
    n = len(arr)
    half = t975(n - 1) * arr.std(axis=0, ddof=1) / math.sqrt(n) if n > 1 else np.full(3, math.nan)
    keys = ("checks", "prompts", "plausible")
    return {**{k: float(arr[:, i].mean()) for i, k in enumerate(keys)},
            **{f"{k}_ci": (None if math.isnan(half[i]) else float(half[i])) for i, k in enumerate(keys)},
            "outputs": len(recs), "prompts_n": len({x["id"] for x in recs})}


def table(results: list[dict], rows: list[Row], prompts: list[Prompt], seeds: int) -> dict:
    """{row: {category or group: rate or None (n/a)}} plus the plausibility failures by check."""
    out: dict = {}
    for row in rows:
        mine = [r for r in results if r["row"] == row.name]
        cells: dict = {}
        for cat in table_categories(prompts):
            cells[cat] = _rate([r for r in mine if r["category"] == cat], seeds)
        cells["one_person"] = _rate([r for r in mine if r["persons"] == 1], seeds)
        cells["two_person_all"] = _rate([r for r in mine if r["persons"] == 2], seeds)
        cells["all"] = _rate(mine, seeds)
        fails: dict[str, int] = {}
        for r in mine:
            for c in r["plausibility"]:
                if not c["passed"]:
                    fails[c["check"]] = fails.get(c["check"], 0) + 1
        cells["plausibility_failures"] = {"outputs": len(mine), **dict(sorted(fails.items()))}
        cells["errors"] = sum("error" in r for r in mine)
        out[row.name] = cells
    return out


def _cell(rate: dict | None, key: str = "checks") -> str:
    if rate is None:
        return "n/a"
    ci = rate.get(f"{key}_ci")
    return f"{rate[key]:.2f}" + (f"±{ci:.2f}" if ci is not None else "")


SUMMARY = [("one_person", "1-person, all categories", "checks"),
           ("two_person_all", "2-person, all", "checks"),
           ("all", "all checks", "checks"), ("all", "prompts with every check passed", "prompts"),
           ("all", "outputs passing every plausibility check", "plausible")]


def format_table(report: dict, markdown: bool = False) -> str:
    """The pass-rate table: a line per category (prompts in the split, then per row the share of
    checks passed, mean ± 95 % CI over seeds, n/a where the row cannot serve the prompts), the
    summaries, then plausibility failures by check, skipped rows and what ran."""
    t = report["table"]
    names = list(t)
    head = [f"eval-prompts · split {report['split']} · {report['prompts']} prompts "
            f"({report['one_person_prompts']} one-person, {report['two_person_prompts']} two-person) "
            f"· seeds {report['seeds']} · share of checks passed, mean ± 95 % CI over seeds"]
    cols = ["category", "prompts"] + names
    labels = category_labels(report.get("split"))
    lines = [[labels[cat], str(count)] + [_cell(t[n].get(cat)) for n in names]
             for cat, count in report["categories"].items()]
    lines += [[label, ""] + [_cell(t[n][key], kind) for n in names] for key, label, kind in SUMMARY]
    if markdown:
        body = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
        body += ["| " + " | ".join(r) + " |" for r in lines]
    else:
        width = [max(len(str(x)) for x in col) for col in zip(cols, *lines)]
        body = ["  ".join(str(x).ljust(w) for x, w in zip(r, width)).rstrip() for r in [cols, *lines]]
    tail = []
    for name, cells in t.items():
        f = cells["plausibility_failures"]
        n = max(f["outputs"], 1)
        fails = ", ".join(f"{k} {v} ({v / n:.0%})" for k, v in f.items() if k != "outputs") or "none"
        tail.append(f"{name}: plausibility failures in {f['outputs']} outputs: {fails}"
                    + (f"; {cells['errors']} outputs raised" if cells["errors"] else ""))
    for name, why in report.get("skipped", {}).items():
        tail.append(f"{name}: skipped ({why})")
    for name, about in report.get("rows", {}).items():
        tail.append(f"{name}: {about}")
    data = report.get("data") or {}
    if data:
        tail.append(f"data: {data.get('clips')} clips ({', '.join(f'{k} {v}' for k, v in data.get('sources', {}).items())})")
    sep = ["", ""] if markdown else [""]
    return "\n".join(head + [""] + body + sep + (["- " + x for x in tail] if markdown else tail))


def build_report(rows: list[Row], skipped: dict, prompts: list[Prompt], results: list[dict],
                 split: str, seeds: int, elapsed_s: float, data: dict | None = None) -> dict:
    """The report: what ran (split, seeds, prompts per category, rows and skipped rows, the
    processed data the generators drew on) and the table."""
    return {"split": split, "seeds": seeds, "prompts": len(prompts), "data": data or {},
            "one_person_prompts": sum(p.persons == 1 for p in prompts),
            "two_person_prompts": sum(p.persons == 2 for p in prompts),
            "categories": {c: sum(p.category == c for p in prompts) for c in table_categories(prompts)},
            "rows": {r.name: r.about for r in rows}, "skipped": skipped,
            "elapsed_s": round(elapsed_s, 1),
            "table": table(results, rows, prompts, seeds)}


def write(out: Path, report: dict, results: list[dict]) -> None:
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "report.json").write_text(json.dumps({**report, "results": results}, indent=1))
    with (out / "results.jsonl").open("w") as f:
        for r in results:
            f.write(json.dumps(r) + "\n")
    (out / "table.md").write_text(format_table(report, markdown=True) + "\n")
