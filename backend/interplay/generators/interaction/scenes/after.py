"""What the two do after their interaction: "two people shake hands, then one walks away in a
circle", "they hug, then walk away from each other". The interaction is composed over the plan's
segments before the first one in which someone leaves (a role said with the catalogue's
`depart` words: away, off, leave, apart …); from there each who leaves does their own role by
the one-person generator, turned to face away from the other and joined to their last pose, and
the other stays where they are (their role, or standing still).

    part = departure(segments, kind)             # None, or Departure(frame, roles)
    people = depart(people, part, solo, seed)    # both (T, 22, 3), the leavers leaving

The join turns a leaver round over JOIN frames about their own pelvis while their pose blends
from the interaction's last frame into the walk's first (in each one's own facing, so a half
turn does not pass the body through itself), the feet stepping round, one after the other
(scenes/stepping.py), instead of swinging about the pelvis. numpy only.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from interplay.catalogue.words import words
from interplay.generators.interaction.bodies import yaw_of
from interplay.generators.interaction.scenes.stepping import stepped
from interplay.generators.retrieval.intent import intent
from interplay.motion import skeleton as sk
from interplay.motion.ik import ease
from interplay.motion.kinematics import facing_angle
from interplay.motion.rotations import yaw_matrix
from interplay.motion.skeleton import FPS
from interplay.planner.verbs import lookup

# Kinds made of walking already (their own leaving is their words), and the kinds whose
# response is the other's move (a push's stumble): no departure cut from them.
WALKING = ("side_by_side", "one_stops", "follow", "approach", "chase", "lead", "carry", "push")
MIN_BEFORE, MIN_AFTER = 30, 20     # frames: the interaction and the leaving, at least …
INTERACTION = 80                   # … and the interaction up to this many (4 s) where the plan
                                   # gives it less: a handshake cut to 0.85 s is no handshake
JOIN = 16                          # frames the turn and the blend into the walk take
STAY = "a person stands still"
LEAVE = "a person walks away"

Solo = Callable[[str, float, int], tuple[np.ndarray, list[dict]]]
Stand = Callable[[int, int], tuple[np.ndarray, list[dict]]]        # (frames, seed) → standing


@dataclass(frozen=True)
class Departure:
    frame: int                     # where the interaction ends and the leaving starts
    roles: tuple[str, str]         # each person's role from there (STAY for who stays)
    leaves: tuple[bool, bool]      # who leaves
    segment: int = 0               # the plan's segment in which someone leaves

    def to_json(self) -> dict:
        return {"frame": self.frame, "roles": list(self.roles), "leaves": list(self.leaves)}


def departure(segments, kind: str) -> Departure | None:
    """The first segment after the first in which someone's role leaves (see the module doc),
    for a kind that does not walk already; None when there is none or either part is short."""
    if kind in WALKING or len(segments) < 2:
        return None
    leaving = words("depart", ignore_case=True)
    for k, seg in enumerate(segments[1:], 1):
        roles = seg.roles or {}
        said = [str(roles.get(k) or "") for k in ("0", "1")]
        leaves = tuple(bool(t) and leaving.search(t) is not None for t in said)
        if any(leaves):
            total = segments[-1].end
            if seg.start < MIN_BEFORE or total - seg.start < MIN_AFTER:
                return None
            roles_out = tuple(t if t and (left or not _stays(t)) else STAY for t, left in zip(said, leaves))
            frame = max(int(seg.start), min(total - MIN_AFTER, INTERACTION))
            return Departure(frame, (roles_out[0], roles_out[1]), (leaves[0], leaves[1]), k)
    return None


def _moves(role: str) -> bool:
    """Whether a role says how the person moves off (a travel verb: walks, runs, jogs …)."""
    return any((hit := lookup(w)) is not None and hit[0].kind == "travel" for w in role.lower().split())


def _stays(role: str) -> bool:
    return words("compose_idle", ignore_case=True).search(role) is not None


def retimed(plan, part: Departure):
    """The plan with its segments re-timed so that the leaving segment starts at `part.frame`
    (those before it scaled into [0, frame), the rest into [frame, end)); the plan itself when
    it starts there already."""
    segs = plan.segments
    cut, total = segs[part.segment].start, segs[-1].end
    if cut == part.frame:
        return plan

    def at(f: int) -> int:
        if f <= cut:
            return int(round(f * part.frame / cut))
        return part.frame + int(round((f - cut) * (total - part.frame) / (total - cut)))
    new = []
    for s in segs:
        a, b = at(s.start), at(s.end)
        if b <= a:
            return plan
        new.append(s.model_copy(update={"start": a, "end": b, "seconds": (b - a) / FPS}))
    return plan.model_copy(update={"segments": new})


def depart(people: list[np.ndarray], part: Departure, solo: Solo, seed: int,
           total: int, stand: Stand) -> tuple[list[np.ndarray], list[list[dict]]]:
    """Both people (frames [0, part.frame) each) continued to `total` frames: each leaver by
    their role turned away from the other, the other by theirs where they stand; and the
    clips each continuation is made of (`stand`: a standing run for who only stays). A leaver
    turns in the interaction's last JOIN frames, so that their leaving starts facing the way it
    goes (a path laid on it from there, "in a circle", starts along their walk, not across it)."""
    rest = total - part.frame
    ends = [p[-1] for p in people]
    out, sources = [], []
    for person, (joints, role, leaves) in enumerate(zip(people, part.roles, part.leaves)):
        # who stays stands in a real standing run (a retrieved "stands still" may raise a hand);
        # who leaves with no way of moving said ("then leave", "part ways") walks away
        if leaves and not _moves(role):
            role = LEAVE
        more, src = stand(rest, seed + 7 * person) if role == STAY else solo(role, rest / FPS, seed + 7 * person)
        more = np.asarray(more, dtype=np.float64)[:rest]
        if len(more) < rest:
            more = np.concatenate([more, np.repeat(more[-1:], rest - len(more), axis=0)])
        end = ends[person]
        yaw = float(facing_angle(end[None])[0])
        if leaves:
            away = (end[sk.PELVIS] - ends[1 - person][sk.PELVIS])[[0, 2]]
            if np.linalg.norm(away) > 1e-6:
                yaw = float(np.arctan2(away[0], away[1]))
            if intent(role).travel == "backward":      # backing away: facing the other
                yaw += np.pi
        placed = _placed(more, end, yaw)
        n = min(JOIN, len(joints) - 1)
        out.append(stepped(np.concatenate([_turned(joints, placed[0]), placed]), len(joints) - n, len(joints)))
        sources.append(src)
    return out, sources


def _placed(more: np.ndarray, end: np.ndarray, yaw: float) -> np.ndarray:
    """`more` (T, 22, 3) turned to start facing `yaw` at `end`'s pelvis, on the floor."""
    rot = yaw_matrix(yaw - yaw_of(more[:5]))
    pivot = more[0, sk.PELVIS] * np.array([1.0, 0.0, 1.0])
    return (more - pivot) @ rot.T + end[sk.PELVIS] * np.array([1.0, 0.0, 1.0])


def _local(pose: np.ndarray) -> tuple[np.ndarray, float]:
    """A pose (22, 3) about its pelvis in its own facing, and that facing's yaw."""
    yaw = float(facing_angle(pose[None])[0])
    return (pose - pose[sk.PELVIS]) @ yaw_matrix(-yaw).T, yaw


def _turned(joints: np.ndarray, goal: np.ndarray) -> np.ndarray:
    """The interaction's frames with their last JOIN turned round into `goal` (22, 3): each
    pose blended in its own facing, the facing turned the shorter way, the pelvis moved (who
    stays blends into their staying role's first pose the same way, with next to no turn)."""
    out = joints.copy()
    n = min(JOIN, len(joints) - 1)
    goal_local, goal_yaw = _local(goal)
    start = _local(joints[len(joints) - n])[1]
    # one way round for the whole turn (a half turn wrapped frame by frame would flip sides)
    to = start + _wrap(goal_yaw - start)
    for i in range(n):
        f = len(joints) - n + i
        a = float(ease(np.asarray((i + 1) / n)))
        here_local, here_yaw = _local(joints[f])
        here = start + _wrap(here_yaw - start)
        pelvis = (1 - a) * joints[f, sk.PELVIS] + a * goal[sk.PELVIS]
        out[f] = ((1 - a) * here_local + a * goal_local) @ yaw_matrix(here + a * (to - here)).T + pelvis
    return out


def _wrap(angle: float) -> float:
    return float((angle + np.pi) % (2 * np.pi) - np.pi)
