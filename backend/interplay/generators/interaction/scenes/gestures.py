"""Scenes of gestures made to each other from a distance: waves (together, or one waving back
after the other), bows, and one person mirroring the other's arm movements. Each person plays
a real clip of the gesture (`library` families: the clip shows it), turned to face the other
and timed against the other's; a clip shorter than the request is lengthened from its own
quiet start and end (`bodies.extend`). The mirror is the leader's clip reflected left to right
(`pair.windows.mirror`) and played a reaction time later. numpy only.
"""

from __future__ import annotations

import numpy as np

from interplay.catalogue import grammar as g
from interplay.catalogue.words import words
from interplay.generators.interaction.bodies import extend, facing_pair, on_shared, refit, turn_to
from interplay.generators.interaction.scene import Cast, clear
from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as m
from interplay.motion.clip import Clip
from interplay.motion.kinematics import facing_angle
from interplay.motion.pair.bases import face_forward
from interplay.motion.pair.windows import mirror as mirrored
from interplay.motion.rotations import yaw_matrix
from interplay.motion.skeleton import FPS

MIRROR_LAG = 1         # frame (0.05 s) the mirroring person trails the leader
TOGETHER_GAP_M = (1.0, 1.3)   # side by side, pelvis to pelvis, both doing the same action
FACE_GAP_M = (1.0, 1.3)       # face to face, pelvis to pelvis: across a small table
FACE_DRAWS = 3                # draws of each person's words; the one that stays put is kept …
FACE_WANDER_M = 0.6           # … and one still wandering further is held on its spot,
FACE_TURN_DEG = 45.0          # one turning further from its mean heading turned back to it
TOGETHER_LAG = 2              # frames the second trails the first when both play one clip


def solo_text(text: str) -> str:
    """One person's part of "two people jump together": "jump" (the planner's imperative)."""
    t = words("gesture_together", ignore_case=True).cut(g.GESTURE_WHO.sub("", text, count=1))
    return " ".join(t.split()).strip(" ,.") or text


def _clip(c: Cast, person: int, family: str) -> tuple[Clip, np.ndarray]:
    clip = c.lib.pick(c.rng, family, c.texts[person])
    j = face_forward(on_shared(clip.people[0], clip.offsets[0]))
    c.source(person, {"clip": clip.id, "start": 0, "end": clip.frames, "mirrored": False,
                      "licence": clip.licence}, family)
    return clip, j


def _timed(j: np.ndarray, onset: int, at: int, frames: int) -> np.ndarray:
    """`frames` frames of a clip whose event starts at its frame `onset`, placed so the event
    starts at output frame `at` (padded from the clip's quiet ends as needed)."""
    start = onset - at
    before, after = max(0, -start), max(0, start + frames - len(j))
    longer = extend(j, before, after)
    s = start + before
    return longer[s:s + frames]


def _wave_onset(j: np.ndarray) -> int:
    b = m.frame_of(j)
    starts = [s for side in m.SIDES for s, _, _ in m.waves(b, side, "shoulder")]
    return min(starts) if starts else len(j) // 3


def _bow_onset(j: np.ndarray) -> int:
    lean = m.torso_lean(m.frame_of(j))
    deep = np.flatnonzero(lean >= 20.0)
    return int(deep[0]) if len(deep) else len(j) // 3


def _gesture(c: Cast, family: str, onset_of, first_s: tuple[float, float],
             delay_s: tuple[float, float], distance: tuple[float, float]) -> list[np.ndarray]:
    rng, frames = c.rng, c.frames
    first = c.script.actor
    at = int(round(rng.uniform(*first_s) * FPS))
    delay = int(round(rng.uniform(*delay_s) * FPS))
    people: list[np.ndarray] = [np.zeros(0), np.zeros(0)]
    timing = {}
    for person, when in ((first, at), (1 - first, at + delay)):
        clip, j = _clip(c, person, family)
        onset = onset_of(j)
        people[person] = _timed(j, onset, when, frames)
        timing[str(person)] = {"clip_onset": onset, "at": when}
    dist = float(rng.uniform(*distance))
    a, b = facing_pair(people[0], people[1], dist)
    c.report[family] = {"onsets": timing, "first": first, "distance_m": round(dist, 3)}
    return [a, b]


def wave(c: Cast) -> list[np.ndarray]:
    far = "across" in " ".join(c.texts)
    return _gesture(c, "wave", _wave_onset, (0.2, 0.8), (0.0, 0.4), (3.0, 4.0) if far else (2.0, 3.0))


def wave_back(c: Cast) -> list[np.ndarray]:
    return _gesture(c, "wave", _wave_onset, (0.2, 0.6), (0.9, 1.5), (2.0, 3.0))


def bow(c: Cast) -> list[np.ndarray]:
    return _gesture(c, "bow", _bow_onset, (0.3, 0.8), (0.0, 0.4), (1.7, 2.1))


def mirror(c: Cast) -> list[np.ndarray]:
    """The leader (`actor`) moves the arms as a real clip does; the other mirrors it."""
    rng, frames = c.rng, c.frames
    lead = c.script.actor
    clip, j = _clip(c, lead, "arms")
    # A stretch of the clip where the arms move (near the most), padded when the clip is shorter.
    speed = np.linalg.norm(np.diff(j[:, [m.J["left_wrist"], m.J["right_wrist"]]], axis=0), axis=-1).sum(1)
    n = frames + MIRROR_LAG
    if len(j) > n:
        windows = np.convolve(speed, np.ones(n - 1), mode="valid")
        busy = np.flatnonzero(windows >= 0.85 * windows.max())
        s = int(busy[rng.integers(len(busy))])
        j = j[s:s + n]
    else:
        j = extend(j, 0, n - len(j))
    leader = j[MIRROR_LAG:]
    follower = mirrored(j[:frames])
    people = [leader, follower] if lead == 0 else [follower, leader]
    dist = float(rng.uniform(1.8, 2.4))
    a, b = facing_pair(people[0], people[1], dist)
    c.sources[1 - lead].append({**c.sources[lead][-1], "mirrored": True, "use": "mirror image"})
    c.report["mirror"] = {"leader": lead, "lag_frames": MIRROR_LAG, "distance_m": round(dist, 3)}
    return [a, b]


def together(c: Cast) -> list[np.ndarray]:
    """Both do what one person would for the words ("two people jump together"): each made
    by the one-person generator (`Cast.solo`, another seed each), both starting at once, side
    by side facing the same way a metre or so apart, moved apart where the bodies would meet."""
    if c.solo is None:
        raise ValueError("no one-person generator to play each person's part")
    texts = [solo_text(t) for t in c.texts]
    seed = int(c.rng.integers(2**31))
    people = []
    for person in (0, 1):
        joints, sources = c.solo(texts[person], seed + 7919 * person)
        j = refit(np.asarray(joints, np.float64)[:c.frames])
        people.append(turn_to(j, 0.0, np.zeros(2), 0, current=None))
        for src in sources:
            c.source(person, {**src, "mirrored": False}, "together")
    (counts0, onset0), (counts1, onset1) = (_events(p) for p in people)
    same_clip, shift = counts0 != counts1, 0
    if same_clip:   # a different number of jumps or squats is not together: the same, a beat later
        people[1] = _shifted(people[0], TOGETHER_LAG)
        c.sources[1] = [{**s, "use": "together (the other's clip, a beat later)"} for s in c.sources[0]]
    elif onset0 is not None and onset1 is not None:   # the second's first action onto the first's
        shift = int(np.clip(onset0 - onset1, -FPS, FPS))
        people[1] = _shifted(people[1], shift)
    gap = float(c.rng.uniform(*TOGETHER_GAP_M))
    a, b = people[0], people[1] + np.array([gap, 0.0, 0.0])
    b, moved = clear(a, b)
    c.report["together"] = {"text": texts[0], "gap_m": round(gap + moved, 3), "seed": seed,
                            "counts": [counts0, counts1], "same_clip": same_clip,
                            "shift_frames": shift}
    return [a, b]


def face_to_face(c: Cast) -> list[np.ndarray]:
    """Each does their own part of the words (their role, made by the one-person generator,
    `Cast.solo`, another seed each), the two facing each other FACE_GAP_M apart, moved apart
    where the bodies would meet: two people at something together that no kind names
    (chatting, a board game, feeding, teaching)."""
    if c.solo is None:
        raise ValueError("no one-person generator to play each person's part")
    seed = int(c.rng.integers(2**31))
    people = []
    for person in (0, 1):
        # the draw of the words that keeps its spot and heading best (a nearest clip may walk off)
        draws = [c.solo(solo_text(c.texts[person]), seed + 7919 * person + 104729 * k)
                 for k in range(FACE_DRAWS)]
        joints, sources = min(draws, key=lambda d: _unsettled(np.asarray(d[0])[:c.frames]))
        j = refit(np.asarray(joints, np.float64)[:c.frames])
        if _wander(j) > FACE_WANDER_M:        # still off: kept on its spot …
            j = j - (j[:, sk.PELVIS] - j[:1, sk.PELVIS])[:, None] * np.array([1.0, 0.0, 1.0])
        j = _steady(j)                         # … and its heading
        people.append(j)
        for src in sources:
            c.source(person, {**src, "mirrored": False}, "face to face")
    gap = float(c.rng.uniform(*FACE_GAP_M))
    a, b = facing_pair(people[0], people[1], gap)
    b, moved = clear(a, b)
    c.report["face_to_face"] = {"texts": [solo_text(t) for t in c.texts], "gap_m": round(gap + moved, 3),
                                "seed": seed}
    return [a, b]


def _wander(joints: np.ndarray) -> float:
    """How far (m) the pelvis gets on the floor from where it starts."""
    d = (joints[:, sk.PELVIS] - joints[:1, sk.PELVIS])[:, [0, 2]]
    return float(np.linalg.norm(d, axis=1).max())


def _steady(joints: np.ndarray) -> np.ndarray:
    """Joints turned back, frame by frame about the pelvis, to their mean heading where the
    facing strays more than FACE_TURN_DEG from it (someone turning away from the partner)."""
    a = facing_angle(joints)
    mean = float(np.arctan2(np.sin(a).mean(), np.cos(a).mean()))
    off = np.angle(np.exp(1j * (a - mean)))
    if np.degrees(np.abs(off)).max() <= FACE_TURN_DEG:
        return joints
    pivot = joints[:, sk.PELVIS] * np.array([1.0, 0.0, 1.0])
    rot = yaw_matrix(-off)                                   # (T, 3, 3)
    return np.einsum("tij,tkj->tki", rot, joints - pivot[:, None]) + pivot[:, None]


def _unsettled(joints: np.ndarray) -> float:
    """How far a draw leaves its spot and its heading: metres wandered plus the facing's
    largest turn from its mean (radians, as half a metre each): one facing a partner keeps both."""
    a = facing_angle(np.asarray(joints, np.float64))
    mean = np.arctan2(np.sin(a).mean(), np.cos(a).mean())
    turn = float(np.abs(np.angle(np.exp(1j * (a - mean)))).max())
    return _wander(joints) + 0.5 * turn


def _events(joints: np.ndarray) -> tuple[tuple[int, int, int], int | None]:
    """((jumps, squats, kicks), the frame of the first of them or None): what two people doing
    it together must agree on, and when it starts."""
    b = m.frame_of(joints)
    jumps = [(s + e) // 2 for s, e in m.jumps(b)]
    squats = [mid for _, mid, _ in m.squats(b)]
    kicks = [f for side in m.SIDES for f, _ in m.kicks(b, side)]
    at = jumps + squats + kicks
    return (len(jumps), len(squats), len(kicks)), (min(at) if at else None)


def _shifted(joints: np.ndarray, by: int) -> np.ndarray:
    """The motion `by` frames later (earlier when negative), its ends held to the same length."""
    if by > 0:
        return np.concatenate([np.repeat(joints[:1], by, 0), joints[:len(joints) - by]])
    if by < 0:
        return np.concatenate([joints[-by:], np.repeat(joints[-1:], -by, 0)])
    return joints
