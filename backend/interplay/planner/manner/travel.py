"""Direction of travel: which way a moving body goes relative to where it faces (the segment's
`travel`), read from the words, and kept apart from the path.

    direction("walks backwards", VERBS["walk"])               → "backward"
    direction("steps sideways to the left", VERBS["step"])    → "left"
    direction("jogs forward", VERBS["jog"])                   → "forward"
    direction("walks to the left", VERBS["walk"])             → None   (a turn, then a walk: a path)
    direction("leans back", VERBS["lean"])                    → None   (the body does not travel)

Why apart: a backwards walk planned as a path behind the person is followed by the trajectory
stage by turning the person round and walking forward. As `travel` the body keeps facing
forward and moves backwards; `untangle` drops a straight path that only restates the direction
(its length still sets the segment's duration).
"""

from __future__ import annotations

from interplay.catalogue.words import lists, tokens, words
from interplay.planner.schema import TrajectorySpec, Travel
from interplay.planner.verbs import Verb

# The words it reads are words.toml's: `travel_moving` (whole-body verbs that travel as well),
# `travel_lateral` (verbs whose "to the left" is a step sideways), `travel_sides`, and
# `back_owners` ("on his back" is the body's).


def _backward(text: str) -> bool:
    """Does the (lower-case) text say to go backwards (words.toml's `travel_back`)?"""
    for found in words("travel_back").finditer(text):
        before = text[:found.start]
        owned = before[:-1].endswith(tuple(lists()["back_owners"]))
        if not (found.text == "back" and before[-1:].isspace() and owned):
            return True
    return False


def direction(text: str, verb: Verb | None) -> Travel | None:
    """The direction of travel a clause states for its body, or None (not stated, or a body
    that does not travel)."""
    if verb is None or not (verb.kind == "travel" or verb.base in lists()["travel_moving"]):
        return None
    t = text.lower()
    if _backward(t):
        return "backward"
    side = next((w.text for w in tokens(t) if w.text in lists()["travel_sides"]), None)     # "to the left", "leftwards"
    if side and (words("sideways").search(t) or verb.base in lists()["travel_lateral"]):
        return "left" if side.startswith("left") else "right"
    if words("sideways").search(t):
        return "left"            # "steps sideways", side unsaid: one side, said in `reasons`
    if words("forward").search(t):
        return "forward"
    return None


def untangle(trajectory: TrajectorySpec | None, travel: Travel | None
             ) -> tuple[TrajectorySpec | None, float | None]:
    """(trajectory to keep, metres it stated): a straight path that only says the direction
    of travel (a line or two-point polyline backwards or sideways) is dropped, so nothing
    turns the person round to follow it; a shape (circle, zigzag …) or a forward line stays."""
    if trajectory is None or travel in (None, "forward"):
        return trajectory, None
    straight = trajectory.shape == "line" or (
        trajectory.shape == "polyline" and trajectory.turn_at is None
        and len(trajectory.waypoints or []) == 2)
    if not straight or (trajectory.direction or "forward") != travel:
        return trajectory, None
    return None, trajectory.distance_m


def from_trajectory(trajectory: TrajectorySpec | None, travel: Travel | None
                    ) -> tuple[TrajectorySpec | None, Travel | None]:
    """An LLM's plan: a backwards line it wrote as a path becomes `travel` (the embedded
    planner never writes one)."""
    if travel is None and trajectory is not None and trajectory.direction == "backward":
        travel = "backward"
    kept, _ = untangle(trajectory, travel)
    return kept, travel
