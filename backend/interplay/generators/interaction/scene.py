"""What every composed scene shares: the cast (the seed's random generator, the clip
library, the script, the frames, each person's text and what the scene records), two
standing people, clearing two bodies apart, and the last steps every scene's people go
through (back on the shared bones, on the floor, the first person at the origin facing +Z on
frame 0). numpy only.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from interplay.catalogue.words import words
from interplay.generators.interaction import moves as mv
from interplay.generators.interaction.bodies import ground, refit
from interplay.generators.interaction.kinds import Script
from interplay.generators.interaction.library import Library
from interplay.motion import skeleton as sk
from interplay.motion.checks.contact import riding
from interplay.motion.kinematics import facing_angle
from interplay.motion.pair.placement import BODY_MARGIN, body_gap
from interplay.motion.rotations import yaw_matrix


def idle_role(role: str) -> bool:
    """A role that only waits: "a person stands still.", "waits there" (the catalogue's
    `compose_idle` words, the whole role)."""
    role = role.strip()
    return words("compose_idle", ignore_case=True).whole(role[:-1] if role.endswith(".") else role)


@dataclass
class Cast:
    rng: np.random.Generator
    lib: Library
    script: Script
    frames: int
    texts: list[str]                       # what each person does (their role, else the prompt)
    report: dict = field(default_factory=dict)
    sources: list[list[dict]] = field(default_factory=lambda: [[], []])
    # one person's motion for a text and seed ((frames, 22, 3), its plan's sources): what
    # "together" plays for each of the two
    solo: Callable[[str, int], tuple[np.ndarray, list[dict]]] | None = None

    def source(self, person: int, src: dict, use: str) -> None:
        """Record a clip a person's motion is made of, and what for."""
        self.sources[person].append({**src, "use": use})

    def walk_text(self, person: int) -> str:
        return self.texts[person]

    def used(self) -> set[str]:
        """The clips used so far (a partner gets another walk when there is one)."""
        return {s["clip"] for person in self.sources for s in person}


def standing_pair(c: Cast) -> list[np.ndarray]:
    """Two people standing quietly (real standing clips), each facing +Z, pelvis centred."""
    out = []
    for p in (0, 1):
        s = mv.standing(c.rng, c.lib.pool, c.frames)
        c.source(p, s.source, "stand")
        out.append(s.joints)
    return out


def clear(a: np.ndarray, b: np.ndarray, margin: float = BODY_MARGIN) -> tuple[np.ndarray, float]:
    """b moved away from a (along the line between their pelvises, on average) until their
    bodies, arms aside, are `margin` apart on every frame; returns (b, metres moved)."""
    d = (b[:, sk.PELVIS] - a[:, sk.PELVIS]).mean(axis=0) * np.array([1.0, 0.0, 1.0])
    d = d / max(float(np.linalg.norm(d)), 1e-9)
    moved = 0.0
    for _ in range(8):
        gap = body_gap(a, b)
        if gap >= margin:
            break
        step = margin - gap + 0.005
        b = b + step * d
        moved += step
    return b, moved


def finish(people: list[np.ndarray]) -> list[np.ndarray]:
    """Both on the shared bones and the floor; the first person's pelvis at the origin on
    frame 0, facing +Z there (or, when they travel more than a metre, travelling along +Z),
    one transform for both. A person riding on the other's back (`contact.riding`) is not
    set on the floor but moved up or down with the one who carries them."""
    fitted = [refit(p) for p in people]
    grounded = [ground(p) for p in fitted]
    if len(people) == 2:
        for rider in (0, 1):
            if riding(fitted[rider], fitted[1 - rider]).mean() > 0.3:
                carrier = 1 - rider
                grounded[rider] = fitted[rider] + (grounded[carrier] - fitted[carrier])[:1, :1]
    people = grounded
    travel = (people[0][-1, sk.PELVIS] - people[0][0, sk.PELVIS])[[0, 2]]
    if float(np.linalg.norm(travel)) > 1.0:
        yaw = -float(np.arctan2(travel[0], travel[1]))
    else:
        yaw = -float(facing_angle(people[0][0]))
    rot = yaw_matrix(yaw)
    shift = (people[0][0, sk.PELVIS] @ rot.T) * np.array([1.0, 0.0, 1.0])
    return [p @ rot.T - shift for p in people]
