"""Planned steps → the Plan's timed segments: durations fitted to the requested seconds (or
their sum), each segment's prompt, roles for two people, travel and timing.

    timed("walk, then jump", 1, 6.0, [Step(walk…), Step(jump…)], reasons) → Plan (2 segments)

A Step is one action of the plan before it has frames: who does it (`actors`), what everyone
else does (`idle`: their role text), who moves at all (`active`), and for two-person exchanges
(`pair/roles.py`) the prompt and `timing` it was given.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from interplay.motion.skeleton import FPS
from interplay.planner.decompose import Action
from interplay.planner.durations import Need, fit, fits, need
from interplay.planner.schema import Coverage, Plan, TrajectorySpec, Travel
from interplay.planner.verbs import lookup

MAX_SECONDS = 60.0


@dataclass
class Step:
    action: Action
    repeat: int
    actors: list[int]
    trajectory: TrajectorySpec | None
    group: tuple[int, int] | None
    idle: dict[int, str]        # role text of each person not in `actors` (two people)
    active: list[int]           # everyone who moves (actors, and others told what to do)
    travel: Travel | None = None
    metres: float | None = None      # a straight path dropped for `travel`: its length
    hold: bool = False               # keeps its pose (or posture) to the end
    timing: dict | None = None       # schema.RoleTiming as a dict (exchanges)
    prompt: str | None = None        # the segment prompt an exchange gave it
    coverage: Coverage | None = None  # how well the words were understood (planner/coverage.py)


def prompt_of(step: Step, persons: int) -> str:
    """The segment's prompt: "a person …", "two people …", "one person … while the other …"."""
    text = step.action.text
    if step.prompt is not None:
        return step.prompt
    if persons == 1:
        return f"a person {text}"
    if step.actors == [0, 1]:
        first = text.split(" ", 1)
        hit = lookup(first[0])
        verb = hit[0].base if hit else first[0]
        return f"two people {verb} {first[1] if len(first) > 1 else ''}".strip()
    idle = step.idle[1 - step.actors[0]]
    return f"one person {text} while the other {idle.removeprefix('a person ')}"


def _need(s: Step) -> Need:
    return need(s.action.verb, s.trajectory, s.repeat, s.action.text, s.metres,
                sideways=s.travel in ("backward", "left", "right"), hold=s.hold)


def _fold(steps: list[Step], needs: list[Need], total: int, reasons: list[str]
          ) -> tuple[list[Step], list[Need]]:
    """Too short for every step at ≥ 0.5 s each: the last ones become one segment."""
    keep = fits(total)
    if len(steps) <= keep:
        return steps, needs
    reasons.append(f"durations: {len(steps)} steps do not fit in {total / FPS:g} s at "
                   f"≥ 0.5 s each; the last {len(steps) - keep + 1} are one segment")
    tail, rest = steps[keep - 1:], needs[keep - 1:]
    merged = tail[0]
    merged.action.text = ", then ".join(s.action.text for s in tail)
    merged.prompt = None if merged.prompt is None else ", then ".join(
        s.prompt or s.action.text for s in tail)
    merged.timing, merged.travel = None, None
    together = Need(sum(n.want for n in rest), sum(n.least for n in rest),
                    any(n.elastic for n in rest))
    return steps[:keep - 1] + [merged], needs[:keep - 1] + [together]


def _roles(s: Step) -> dict[str, str]:
    return {str(p): (f"a person {s.action.text}" if p in s.actors else s.idle[p]) for p in range(2)}


def timed(prompt: str, persons: int, seconds: float | None, steps: list[Step], reasons) -> Plan:
    """The validated Plan of `steps`, `seconds` long (None: the sum of what they need)."""
    needs = [_need(s) for s in steps]
    wanted = sum(n.want for n in needs)
    total = max(1, round((seconds if seconds is not None else min(wanted, MAX_SECONDS)) * FPS))
    steps, needs = _fold(steps, needs, total, reasons)
    frames = fit(needs, total)
    if seconds is not None:       # (the wording of the proportional planner, kept for stored plans)
        reasons.append(f"durations: estimated {wanted:.1f} s, scaled to {total / FPS:g} s")
        if len(needs) > 1 and sum(n.least for n in needs) <= total / FPS < wanted:
            reasons.append(f"durations: each step at least what it needs "
                           f"({', '.join(f'{n.least:g}' for n in needs)} s)")
        elif len(needs) > 1 and total / FPS > wanted and any(n.elastic for n in needs):
            reasons.append("durations: the spare time to the steps that can last longer")
    segments: list[dict[str, Any]] = []
    start = 0
    for i, (s, n) in enumerate(zip(steps, frames)):
        segments.append({
            "index": i, "prompt": prompt_of(s, persons), "base": s.action.base,
            "edits": s.action.edits, "trajectory": s.trajectory, "seconds": n / FPS,
            "start": start, "end": start + n, "persons": s.active,
            "roles": _roles(s) if persons == 2 else None, "repeat": s.repeat,
            "travel": s.travel, "timing": s.timing if persons == 2 else None,
            "coverage": s.coverage})
        start += n
    rewritten = ", then ".join(seg["prompt"] for seg in segments)
    # Validated from plain data: `persons` and the segments are checked by the Plan schema.
    return Plan.model_validate({"prompt": prompt, "rewritten": rewritten, "persons": persons,
                                "seconds": total / FPS, "segments": segments,
                                "reasons": reasons, "planner": "embedded"})
