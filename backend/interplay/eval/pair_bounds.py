"""Issue 15's penetration bounds on what users type (`interplay eval-pair`'s bounds table): the
two-person prompts of the `eval-prompts` suite (its `contact` mark says whether the two are
asked to touch), `seeds` outputs each, for every row that generates pairs.

Per row: over the non-contact prompts, eval-pair's IF (share of frames where the two sphere
bodies overlap at all) — mean, worst output, and the share of outputs over 0.10; over the
contact prompts, eval-pair's penetration (mean depth of the deepest overlap per frame, cm) —
mean, worst, and the share of outputs over 3 cm. The product row (`default`) must keep every
output within both.
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from interplay.eval.pair import window_scores

IF_BOUND, DEPTH_BOUND_CM = 0.10, 3.0
IF_COL, DEPTH_COL = 1, 5       # window_scores' columns: "if", "penetration_cm"


def bounds_check(generators: dict, split: str = "test", seeds: int = 2, seed: int = 0,
                 log=None) -> dict[str, Any]:
    """{"split", "seeds", "prompts": {"contact": n, "none": n}, "rows": {row: {...}}}."""
    from interplay.eval.prompts.suite import load_suite, select
    from interplay.motion.skeleton import FPS
    prompts = [p for p in select(load_suite(), split) if p.persons == 2]
    out: dict[str, Any] = {"split": split, "seeds": seeds, "if_bound": IF_BOUND,
                           "depth_bound_cm": DEPTH_BOUND_CM,
                           "prompts": {"contact": sum(p.contact for p in prompts),
                                       "none": sum(not p.contact for p in prompts)},
                           "rows": {}}
    for name, gen in generators.items():
        if gen is None:
            continue
        t0 = time.perf_counter()
        vals: dict[bool, list[float]] = {True: [], False: []}
        for p in prompts:
            frames = int(round(p.seconds * FPS))
            for s in range(seeds):
                scores = window_scores(gen(p.prompt, frames, seed * 7919 + s))
                vals[p.contact].append(float(scores[DEPTH_COL if p.contact else IF_COL]))
        row = {}
        for contact, key, bound in ((False, "if", IF_BOUND), (True, "penetration_cm", DEPTH_BOUND_CM)):
            v = np.asarray(vals[contact])
            if len(v):
                row[key] = {"mean": float(v.mean()), "worst": float(v.max()),
                            "over": float((v > bound).mean()), "outputs": len(v)}
        out["rows"][name] = row
        if log:
            log(f"bounds {name}: {row} ({time.perf_counter() - t0:.1f} s)")
    return out


def format_bounds(b: dict) -> str:
    lines = [f"\npenetration bounds on the {b['split']} split's two-person prompts ({b['seeds']} "
             f"seeds; {b['prompts']['none']} without contact: IF ≤ {b['if_bound']}, "
             f"{b['prompts']['contact']} with contact: penetration ≤ {b['depth_bound_cm']:g} cm)",
             f"  {'row':<12}{'IF mean':>10}{'IF worst':>10}{'over':>8}"
             f"{'pen. cm mean':>14}{'pen. worst':>12}{'over':>8}"]
    for row, r in b["rows"].items():
        i, d = r.get("if"), r.get("penetration_cm")
        left = (f"{i['mean']:>10.3f}{i['worst']:>10.3f}{i['over']:>8.0%}" if i else f"{'-':>28}")
        right = (f"{d['mean']:>14.2f}{d['worst']:>12.2f}{d['over']:>8.0%}" if d else f"{'-':>34}")
        lines.append(f"  {row:<12}{left}{right}")
    return "\n".join(lines)
