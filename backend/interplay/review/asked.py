"""What a segment's words ask, checked on its motion by the benchmark's own named checks
(`motion/checks/named.py`, issue 14 item 6): the job pipeline gives the reviewer the specs a
segment's intent implies (a direction of travel, a side and count of kicks or punches, counts
of jumps, squats or steps, the posture at the start and the end); the reviewer fails a
segment that misses one and asks for it again, and keeps a correction only if it misses no
more of them. Two people: the pair checks of their interaction (`pipeline.pair_review`).

    specs = [{"check": "jump_count", "count": 2}]
    missed([joints], specs)          # [("jump_count", "jump_count: 1, asked count 2")]
"""

from __future__ import annotations

import numpy as np

from interplay.motion.checks.named import run_check


def _results(people: list[np.ndarray], asked: list[dict] | None):
    if not asked:
        return []
    return [(spec, run_check(list(people), spec)) for spec in asked]


def missed(people: list[np.ndarray], asked: list[dict] | None) -> list[tuple[str, str]]:
    """(check name, why) for each asked check the motion fails."""
    out = []
    for spec, r in _results(people, asked):
        if not r.passed:
            args = ", ".join(f"{k} {v}" for k, v in spec.items() if k != "check")
            out.append((spec["check"], f"{spec['check']}: {_value(r.value)}, asked {args}"))
    return out


def passed(people: list[np.ndarray], asked: list[dict] | None) -> int:
    return sum(r.passed for _, r in _results(people, asked))


def _value(v) -> str:
    if isinstance(v, float):
        return f"{v:.2f}"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {_value(x)}" for k, x in v.items()) + "}"
    return str(v)
