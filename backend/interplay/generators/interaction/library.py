"""The real single-person clips a scene is built from, found in the retrieval index's clips:
quiet standing runs and level walks (`pair.bases`), walks backwards, waves, bows and arm
movements done in place, punches and kicks thrown in place (sparring), runs (a chase) and
get-ups from the floor (helping someone up). numpy only (plus the index's text encoder).

Each family is the clips whose label names the action and whose motion shows it (a wave
clip must contain a wave by `checks.measures.waves`, a bow a bow, an arm clip arms that keep
moving while the feet stay, a walk backwards steps), from the train split when it has any (test captures stay unseen).
Within a family the clip is chosen by the text encoder: the clips whose labels are nearest the
person's text (their role, else the prompt), within MARGIN of the best, one drawn by the seed.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as m
from interplay.motion.checks.named import run_check
from interplay.motion.clip import Clip
from interplay.motion.pair import placement as pl
from interplay.motion.pair.bases import Base, standing_bases, walk_bases

MARGIN = 0.05          # clips within this cosine similarity of the best are all candidates
TOP_K = 4
# Quiet standing (stricter than pair.bases' standing runs, which let a hand rise slowly):
QUIET_HEAD_M = 0.06    # the head rises and falls at most this (more is someone bending)
QUIET_WRIST_M = 0.08   # each wrist rises and falls at most this
HANDS_LOW_M = 0.10     # each wrist on average at most this over the pelvis
FEET_LEVEL_M = 0.04    # both feet down (their lowest points level within this)
SWAY_M = 0.03          # the pelvis stays within this of where it stands
STANCE_M = 0.35        # the ankles at most this far apart (not a wide stance)


def _travel(j: np.ndarray) -> float:
    p = j[:, sk.PELVIS][:, [0, 2]]
    return float(np.linalg.norm(p - p[0], axis=1).max())


def _waves(c: Clip) -> bool:
    b = m.frame_of(c.people[0].astype(np.float64))
    return any(len(m.waves(b, s, "shoulder")) > 0 for s in m.SIDES) and _travel(c.people[0]) < 0.4


def _bows(c: Clip) -> bool:
    return run_check([c.people[0].astype(np.float64)], {"check": "bow"}).passed


def _arms(c: Clip) -> bool:
    """Arms that keep moving (wrists ≥ 0.5 m/s relative to the pelvis on average) in place
    (the pelvis within 0.4 m), upright and at least 2 s long."""
    j = c.people[0].astype(np.float64)
    if c.frames < 40 or _travel(j) > 0.4:
        return False
    rel = j[:, [sk.LEFT_HAND, sk.RIGHT_HAND]] - j[:, [sk.PELVIS]]
    wrist = float(np.linalg.norm(np.diff(rel, axis=0), axis=-1).mean() * sk.FPS)
    b = m.frame_of(j)
    return wrist >= 0.5 and bool(m.standing(b).mean() > 0.9)


def _steps_back(c: Clip) -> bool:
    """A walk backwards that steps (feet lifted and put down, ≥ 1 step a second) at ≥ 0.7 m/s:
    some captured ones shuffle, their feet never leaving the floor."""
    if c.frames < 40:
        return False
    b = m.frame_of(c.people[0].astype(np.float64))
    seconds = c.frames / sk.FPS
    return m.steps(b) >= seconds and m.path_length(b) / seconds >= 0.7


def _strikes(kind: str):
    """Clips with at least two punches (or kicks) of their own, done in place (a sparring
    partner's blows: `checks.named.events`)."""
    def ok(c: Clip) -> bool:
        from interplay.motion.checks.named import events
        j = c.people[0].astype(np.float64)
        return c.frames >= 40 and _travel(j) < 1.0 and len(events(m.frame_of(j))[kind]) >= 2
    return ok


def _runs(c: Clip) -> bool:
    """A run ahead: ≥ 2 m/s over the clip, feet stepping, at least 1.5 s (a loopable gait)."""
    j = c.people[0].astype(np.float64)
    return c.frames >= 30 and _travel(j) / (c.frames / sk.FPS) >= 2.0 and m.steps(m.frame_of(j)) >= 2


def _gets_up(c: Clip) -> bool:
    """From the floor (pelvis under 40 % of where it ends) to standing at the end."""
    y = c.people[0][:, sk.PELVIS, 1].astype(np.float64) - c.people[0][..., 1].min()
    return bool(y[:5].mean() < 0.4 * y[-5:].mean()) and bool(m.standing(m.frame_of(c.people[0].astype(np.float64)))[-1])


FAMILIES = {
    "wave": (r"wave", _waves),
    "punch": (r"punch", _strikes("punch")),
    "kick": (r"kick", _strikes("kick")),
    "run": (r"runs", _runs),
    "getup": (r"gets up", _gets_up),
    "bow": (r"bows", _bows),
    "walk_back": (r"walks backwards", _steps_back),
    "arms": (r"", _arms),
}


class Library:
    def __init__(self, clips: list[Clip], encoder, prompt_embeddings: np.ndarray | None = None):
        self.clips = [c for c in clips if not c.synthetic and len(c.people) == 1]
        self.encoder = encoder
        self._emb = prompt_embeddings
        self._pool: pl.Pool | None = None
        self._families: dict[str, list[int]] = {}

    @classmethod
    def of_index(cls, index) -> Library:
        """The library over a RetrievalIndex's clips, reusing its label embeddings."""
        lib = cls(index.clips, index.encoder)
        rows = index.embeddings[index.clip_prompt_win]
        keep = [i for i, c in enumerate(index.clips) if not c.synthetic and len(c.people) == 1]
        lib._emb = rows[keep]
        return lib

    # -- text ------------------------------------------------------------------------------
    def embeddings(self) -> np.ndarray:
        if self._emb is None:
            self._emb = np.asarray(self.encoder.encode([c.prompt for c in self.clips]))
        return self._emb

    def choose(self, rng, members: list[int], text: str) -> int:
        """One of `members` (indices into self.clips) whose label is nearest `text`."""
        if not members:
            raise ValueError("no clip to choose from")
        q = np.asarray(self.encoder.encode([text]))[0]
        sims = self.embeddings()[members] @ q
        order = np.argsort(-sims, kind="stable")
        near = [members[i] for i in order[:TOP_K] if sims[i] >= sims[order[0]] - MARGIN]
        return near[int(rng.integers(len(near)))]

    # -- families ---------------------------------------------------------------------------
    def family(self, name: str) -> list[int]:
        """Indices of the clips of a family (train split when it has any)."""
        if name not in self._families:
            word, ok = FAMILIES[name]
            found = [i for i, c in enumerate(self.clips) if word in c.prompt and ok(c)]
            train = [i for i in found if self.clips[i].split == "train"]
            self._families[name] = train or found
        return self._families[name]

    def pick(self, rng, name: str, text: str) -> Clip:
        members = self.family(name)
        if not members:
            raise ValueError(f"no {name} clips in the data")
        return self.clips[self.choose(rng, members, text)]

    # -- standing and walking -----------------------------------------------------------------
    @property
    def pool(self) -> pl.Pool:
        if self._pool is None:
            pool = pl.pool_of(self.clips, "train")
            if not pool.stand or not pool.walk:
                pool = pl.Pool("all", standing_bases(self.clips), walk_bases(self.clips))
            quiet = [b for b in pool.stand if _quiet(b)]
            self._pool = pl.Pool(pool.split, quiet if len(quiet) >= 3 else pool.stand, pool.walk)
        return self._pool

    def walk_base(self, rng, text: str, exclude: set[str] | frozenset[str] = frozenset()) -> Base:
        """A level walk ahead whose label is nearest `text` (another than `exclude`'s clips
        when there is one)."""
        walks = self.pool.walk
        if not walks:
            raise ValueError("no walk clips in the data")
        ids = {c.id: i for i, c in enumerate(self.clips)}
        members = sorted({ids[b.clip.id] for b in walks if b.clip.id in ids})
        members = [i for i in members if self.clips[i].id not in exclude] or members
        pick = self.clips[self.choose(rng, members, text)] if members else walks[0].clip
        return next(b for b in walks if b.clip.id == pick.id)


def _quiet(b: Base) -> bool:
    """A standing run with both arms and the head still, hands low, both feet down, close
    together, and the pelvis in place (see the bounds above)."""
    j = b.clip.people[0][b.start:b.end]
    wy = j[:, [sk.LEFT_HAND, sk.RIGHT_HAND], 1]
    head = j[:, sk.HEAD, 1]
    sway = np.linalg.norm(j[:, sk.PELVIS][:, [0, 2]] - j[:, sk.PELVIS][:, [0, 2]].mean(axis=0), axis=1)
    feet = [np.minimum(j[:, sk.JOINT_INDEX[f"{s}_ankle"], 1] - 0.055, j[:, sk.JOINT_INDEX[f"{s}_foot"], 1]).mean()
            for s in ("left", "right")]
    stance = np.linalg.norm((j[:, sk.LEFT_ANKLE] - j[:, sk.RIGHT_ANKLE])[:, [0, 2]], axis=1).max()
    return bool(float((wy.max(0) - wy.min(0)).max()) <= QUIET_WRIST_M and float(stance) <= STANCE_M
                and float(wy.mean(0).max() - j[:, sk.PELVIS, 1].mean()) <= HANDS_LOW_M
                and float(head.max() - head.min()) <= QUIET_HEAD_M and float(sway.max()) <= SWAY_M
                and abs(feet[0] - feet[1]) <= FEET_LEVEL_M)
