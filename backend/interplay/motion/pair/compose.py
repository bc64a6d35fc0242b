"""Synthetic two-person clips composed from real single-person motion, with contact solved by
two-bone IK (`ik.py`). numpy only. Every composed clip is labelled `synthetic=True`, source
"composed"; its meta records the kind, the bases (clip, frames, mirrored), the placement, and
the contact window and hands.

Recipe (CODA's interaction cues: hand contact where the prompt needs it, no interpenetration
of the bodies, a plausible distance and relative facing):
  1. bases: two real motions of the split (quiet standing stretched to length, or two walks,
     `bases.py`), each optionally left/right mirrored;
  2. placement: facing each other at a kind-specific distance (or side by side for walks),
     pushed apart until their trunks, heads and legs (every sphere of `body.py` except the
     arms') clear each other by a margin;
  3. contact: the contact arms follow IK to targets on the partner — the other's hand, back
     or chest — with eased weights over a window (reach, hold, release); every other joint
     stays as captured.

Kinds (prompts vary per seed):
  handshake        right hand to right hand at mid-distance, a small vertical shake
  high_five        right hand to the other's right or left hand above shoulder height
  hug              both wrists of each person to points behind the partner's spine3
  push             both hands of the first to the second's chest, the second's pelvis then
                   pushed back (legs re-solved by IK so the feet stay planted)
  wave             no contact: each waves one arm (procedural wrist oscillation via IK)
  walk_side_by_side  two real walks ~0.8 m apart, same heading and speed, hands held or not
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import Clip
from interplay.motion.ik import ease, reach, two_bone_ik, window_weights
from interplay.motion.kinematics import canonicalize, resample
from interplay.motion.pair import placement as pl
from interplay.motion.pair.bases import face_forward, refit
from interplay.motion.pair.body import body_scale
from interplay.motion.pair.placement import SPINE3, UP, Pool, pool_of

KINDS = ("handshake", "high_five", "hug", "push", "wave", "walk_side_by_side")
PROMPTS = {
    "handshake": ("two people shake hands", "two people greet each other with a handshake"),
    "high_five": ("two people give each other a high five", "two people high-five"),
    "hug": ("two people hug each other", "two people embrace"),
    "push": ("one person pushes the other away with both hands", "a person pushes another person"),
    "wave": ("two people wave at each other", "two people greet each other with a wave"),
    "walk_side_by_side": ("two people walk side by side", "two people walk next to each other"),
}
HELD_PROMPT = "two people walk side by side holding hands"
HUG_CLEARANCE = 0.005  # m from the surface of the partner's chest sphere to a hugging wrist
CHEST_RADIUS = 0.110   # body.py's chest sphere (spine3 → neck at 0.3), template build


# ---- kinds ---------------------------------------------------------------------------------

def _handshake(rng, pool, frames):
    a, b = pl.standing(rng, pool, frames), pl.standing(rng, pool, frames)
    c0, c1, r_in, r_out = pl.timing(rng, frames, (1.2, 1.8), (0.6, 0.8))
    w = window_weights(frames, c0, c1, r_in, r_out)
    # Right hands meet on the centre line at about elbow height, each arm at 75–90% reach.
    # The wrists stop 4.5 cm short of the meeting point: the hands (past the wrists) clasp there.
    y = 0.5 * (a.joints[:, sk.PELVIS, 1] + b.joints[:, sk.PELVIS, 1]).mean() + rng.uniform(0.08, 0.18)
    za, zb = (pl.forward_at(p.joints, "right", 0.0, y, rng.uniform(0.8, 0.92)) + 0.045 for p in (a, b))
    place = pl.oppose(rng, a, b, za + zb)
    meet = np.array([0.0, y, 0.5 * (za + place["distance"] - zb)])
    t = (np.arange(frames) - c0) / sk.FPS
    shake = rng.uniform(0.02, 0.04) * np.sin(2 * np.pi * rng.uniform(2.0, 3.0) * t) * w
    towards = np.array([0.0, 0.0, 1.0])
    for p, sign in ((a, -1.0), (b, 1.0)):
        target = meet + sign * 0.045 * towards + shake[:, None] * UP
        pl.arm_ik(p, "right", target, w, pl.pole(p.joints, "right", 0.15, 0.4, 0.1))
    hands = [[0, "right_wrist"], [1, "right_wrist"]]
    return a, b, place, pl.contact(c0, c1, r_in, r_out, hands), PROMPTS["handshake"]


def _high_five(rng, pool, frames):
    a, b = pl.standing(rng, pool, frames), pl.standing(rng, pool, frames)
    c0, c1, r_in, r_out = pl.timing(rng, frames, (0.1, 0.2), (0.5, 0.7), lead=(0.2, 1.2))
    w = window_weights(frames, c0, c1, r_in, r_out)
    side_b = "right" if rng.random() < 0.5 else "left"
    sa, sb = sk.RIGHT_SHOULDER, sk.JOINT_INDEX[f"{side_b}_shoulder"]
    # Above the higher shoulder; laterally between the two hands' shoulders (b faces -Z, so
    # a world x is -x in b's own frame).
    x = 0.5 * (a.joints[:, sa, 0].mean() - b.joints[:, sb, 0].mean())
    y = max(a.joints[:, sa, 1].max(), b.joints[:, sb, 1].max()) + rng.uniform(0.12, 0.25)
    za = pl.forward_at(a.joints, "right", x, y, rng.uniform(0.8, 0.92))
    zb = pl.forward_at(b.joints, side_b, -x, y, rng.uniform(0.8, 0.92))
    place = pl.oppose(rng, a, b, za + zb)
    meet = np.array([x, y, 0.5 * (za + place["distance"] - zb)])
    towards = np.array([0.0, 0.0, 1.0])
    for p, side, sign in ((a, "right", -1.0), (b, side_b, 1.0)):
        pl.arm_ik(p, side, meet + sign * 0.035 * towards, w, pl.pole(p.joints, side, 0.3, 0.3, 0.0))
    hands = [[0, "right_wrist"], [1, f"{side_b}_wrist"]]
    return a, b, place, pl.contact(c0, c1, r_in, r_out, hands), PROMPTS["high_five"]


def hug_targets(me: np.ndarray, other: np.ndarray, arm: str, height: float,
                window: slice, clearance: float = HUG_CLEARANCE) -> np.ndarray:
    """Wrist targets (T, 3) on the partner's upper back, `clearance` off the surface of their
    chest sphere, as far round behind them (from the arm's side, 20°–90° off straight
    behind) as the arm reaches within 95% of its length over the contact window (also used
    by the two-person contact refinement, `agents.contact_refine`)."""
    fwd = pl.axes(other)[0]
    centre = other[:, SPINE3] + 0.3 * (other[:, sk.NECK] - other[:, SPINE3]) + height * UP
    side = pl.out_of(me, arm)
    shoulder = me[:, sk.JOINT_INDEX[f"{arm}_shoulder"]]
    limit = 0.95 * reach(me, f"{arm}_arm")
    radius = CHEST_RADIUS * body_scale(other) + clearance
    for deg in range(20, 91, 10):
        th = np.radians(deg)
        target = centre + radius * (np.cos(th) * -fwd + np.sin(th) * side)
        if np.all(np.linalg.norm(target - shoulder, axis=1)[window] <= limit[window]):
            break
    return target


def _hug(rng, pool, frames):
    a, b = pl.standing(rng, pool, frames), pl.standing(rng, pool, frames)
    # Heads pass each other: b shifted to a's left or right.
    place = pl.oppose(rng, a, b, rng.uniform(0.26, 0.3), rng.choice([-1.0, 1.0]) * rng.uniform(0.08, 0.12))
    c0, c1, r_in, r_out = pl.timing(rng, frames, (1.2, 2.0), (0.7, 0.9))
    w = window_weights(frames, c0, c1, r_in, r_out)
    hands = []
    # One person's arms over (upper back), the other's a little lower.
    for me, other, pid, height in ((a, b, 0, rng.uniform(-0.02, 0.05)), (b, a, 1, rng.uniform(-0.14, -0.08))):
        for arm in ("left", "right"):
            target = hug_targets(me.joints, other.joints, arm, height, slice(c0, c1))
            pl.arm_ik(me, arm, target, w, pl.pole(me.joints, arm, 0.45, 0.15, 0.1))
            hands.append([pid, f"{arm}_wrist"])
    return a, b, place, pl.contact(c0, c1, r_in, r_out, hands), PROMPTS["hug"]


def _push(rng, pool, frames):
    a, b = pl.standing(rng, pool, frames), pl.standing(rng, pool, frames)
    # Hands start on the chest with the arms bent (65–75% of their reach).
    chest_z = b.joints[:, SPINE3, 2].mean() + 0.13
    chest_y = b.joints[:, SPINE3, 1].mean() + rng.uniform(0.02, 0.1)
    spread = rng.uniform(0.09, 0.13)
    frac = rng.uniform(0.65, 0.75)
    za = max(pl.forward_at(a.joints, arm, sign * spread, chest_y, frac)
             for arm, sign in (("left", 1.0), ("right", -1.0)))
    place = pl.oppose(rng, a, b, za + chest_z)
    c0, c1, r_in, r_out = pl.timing(rng, frames, (0.6, 0.9), (0.5, 0.7), lead=(0.2, 0.6))
    # The second person's pelvis moves back by `dist` from just after contact, feet planted.
    dist, dur = rng.uniform(0.12, 0.22), int(round(rng.uniform(0.4, 0.6) * sk.FPS))
    t = np.arange(frames)
    back = -pl.axes(b.joints)[0][c0:c1].mean(axis=0)
    shift = ease((t - (c0 + 2)) / dur)[:, None] * dist * back             # (T, 3)
    before = b.joints.copy()
    moved = b.joints + shift[:, None]
    drop = np.zeros(frames)
    for leg, hip in (("left_leg", sk.LEFT_HIP), ("right_leg", sk.RIGHT_HIP)):
        d = moved[:, hip] - before[:, sk.JOINT_INDEX[leg.replace("leg", "ankle")]]
        room = np.square(0.995 * reach(before, leg)) - np.square(d[:, [0, 2]]).sum(axis=1)
        drop = np.maximum(drop, d[:, 1] - np.sqrt(np.maximum(room, 0.0)))
    moved[..., 1] -= drop[:, None]
    for leg, ankle in (("left_leg", sk.LEFT_ANKLE), ("right_leg", sk.RIGHT_ANKLE)):
        knee_hint = moved[:, sk.JOINT_INDEX[leg.replace("leg", "knee")]] + 0.3 * pl.axes(before)[0]
        moved = two_bone_ik(moved, leg, before[:, ankle], pole=knee_hint, carry="keep")
    b.joints = moved
    # The first person's hands on the second's chest, following it back while in reach.
    chest = b.joints[:, SPINE3] + 0.13 * pl.axes(b.joints)[0] + (chest_y - b.joints[:, SPINE3, 1].mean()) * UP
    targets = {arm: chest + spread * pl.out_of(a.joints, arm) for arm in ("left", "right")}
    ok = np.all([np.linalg.norm(targets[s] - a.joints[:, sk.JOINT_INDEX[f"{s}_shoulder"]], axis=1)
                 < 0.97 * reach(a.joints, f"{s}_arm") for s in targets], axis=0)
    lost = np.flatnonzero(~ok[c0:c1])
    c1 = c0 + int(lost[0]) if len(lost) else c1
    if c1 - c0 < 3:
        raise ValueError("the chest is out of reach")
    w = window_weights(frames, c0, c1, r_in, r_out)
    for arm, target in targets.items():
        pl.arm_ik(a, arm, target, w, pl.pole(a.joints, arm, 0.2, 0.35, 0.15))
    place.update({"push_distance": float(dist), "pelvis_drop_max": float(drop.max())})
    hands = [[0, "left_wrist"], [0, "right_wrist"]]
    return a, b, place, pl.contact(c0, c1, r_in, r_out, hands), PROMPTS["push"]


def _wave(rng, pool, frames):
    a, b = pl.standing(rng, pool, frames), pl.standing(rng, pool, frames)
    place = pl.oppose(rng, a, b, rng.uniform(1.8, 3.0), rng.uniform(-0.3, 0.3))
    waves = []
    delay = 0
    for pid, p in enumerate((a, b)):
        arm = "right" if rng.random() < 0.7 else "left"
        c0, c1, r_in, r_out = pl.timing(rng, frames - delay, (2.0, 2.8), (0.4, 0.5), lead=(0.0, 0.3))
        c0, c1 = c0 + delay, c1 + delay
        w = window_weights(frames, c0, c1, r_in, r_out)
        out, fwd = pl.out_of(p.joints, arm), pl.axes(p.joints)[0]
        t = (np.arange(frames) - c0) / sk.FPS
        # The hand stays well within reach (≤ ~0.45 m from the shoulder) so that it swings
        # sideways, and only while the arm is up (a rising hand is not a wave).
        swing = (rng.uniform(0.1, 0.15) * np.sin(2 * np.pi * rng.uniform(1.4, 2.2) * t)
                 * window_weights(frames, c0 + 3, c1 - 3, 3, 3))
        shoulder = p.joints[:, sk.JOINT_INDEX[f"{arm}_shoulder"]]
        target = (shoulder + rng.uniform(0.25, 0.32) * UP + (rng.uniform(0.08, 0.14) + swing)[:, None] * out
                  + rng.uniform(0.05, 0.12) * fwd)
        pl.arm_ik(p, arm, target, w, pl.pole(p.joints, arm, 0.4, 0.3, 0.0))
        waves.append({"person": pid, "hand": f"{arm}_wrist", "start": c0, "end": c1})
        delay = int(round(rng.uniform(0.0, 0.6) * sk.FPS))
    place["waves"] = waves
    return a, b, place, None, PROMPTS["wave"]


def _walk_side_by_side(rng, pool, frames):
    first = pool.walk[rng.integers(len(pool.walk))]
    a = pl.walker(rng, first, frames)
    # A partner walk within ±25% of the first's speed, time-warped to match it exactly.
    for _ in range(20):
        second = pool.walk[rng.integers(len(pool.walk))]
        ratio = pl.walk_speed(a.joints) / pl.walk_speed(second.clip.people[0].astype(np.float64))
        if 0.8 <= ratio <= 1.25 and (second is not first or len(pool.walk) == 1):
            break
    b = pl.walker(rng, second, int(np.ceil(frames * ratio)) + 2)
    b.joints = refit(resample(b.joints, sk.FPS, sk.FPS / ratio)[:frames], b.offsets)
    b.base["time_scale"] = float(ratio)
    for p in (a, b):
        heading = p.joints[-1, sk.PELVIS] - p.joints[0, sk.PELVIS]
        p.joints = face_forward(p.joints, heading)
        p.joints = p.joints - p.joints[0, sk.PELVIS] * np.array([1.0, 0.0, 1.0])
    side = 1.0 if rng.random() < 0.5 else -1.0        # b on a's left (+X) or right
    gap = float(rng.uniform(0.7, 0.9))
    b.joints = b.joints + np.array([side * gap, 0.0, rng.uniform(-0.1, 0.1)])
    gap += pl.separate(a, b, np.array([side, 0.0, 0.0]))
    place = {"lateral": side * gap, "held": bool(rng.random() < 0.5)}
    contact = None
    if place["held"]:
        arm_a, arm_b = ("left", "right") if side > 0 else ("right", "left")
        sa, sb = (sk.JOINT_INDEX[f"{s}_shoulder"] for s in (arm_a, arm_b))
        mid = 0.5 * (a.joints[:, sa] + b.joints[:, sb])
        mid[:, 1] = 0.5 * (a.joints[:, sk.PELVIS, 1] + b.joints[:, sk.PELVIS, 1]) - rng.uniform(0.0, 0.08)
        across = np.array([side, 0.0, 0.0])
        w = np.ones(frames)
        pl.arm_ik(a, arm_a, mid - 0.035 * across, w, pl.pole(a.joints, arm_a, 0.1, 0.4, 0.1))
        pl.arm_ik(b, arm_b, mid + 0.035 * across, w, pl.pole(b.joints, arm_b, 0.1, 0.4, 0.1))
        contact = pl.contact(0, frames, 0, 0, [[0, f"{arm_a}_wrist"], [1, f"{arm_b}_wrist"]])
    return a, b, place, contact, (HELD_PROMPT,) if place["held"] else PROMPTS["walk_side_by_side"]


_COMPOSERS = {"handshake": _handshake, "high_five": _high_five, "hug": _hug, "push": _push,
              "wave": _wave, "walk_side_by_side": _walk_side_by_side}


# ---- public --------------------------------------------------------------------------------

# Kinds whose hands must not touch the partner before the reach starts: two bases can stand
# so close (short arms, hands held in front) that a wrist already meets the other body.
HANDS_APART_FIRST = ("handshake", "high_five")


def _check_hands_apart(a: np.ndarray, b: np.ndarray, contact: dict) -> None:
    from interplay.motion.metrics import frame_highlights

    before = contact["start"] - contact["ramp_in"]
    hits = frame_highlights([a[:before], b[:before]])["contacts"] if before > 0 else []
    if any(j in (sk.LEFT_HAND, sk.RIGHT_HAND) for f in hits for _, j in f):
        raise ValueError("a hand touches the partner before the reach")


def _licence(bases: list[dict]) -> str:
    names = sorted({b["licence"] for b in bases})
    return " + ".join(names)


def compose(kind: str, seed: int, seconds: float = 4.0, clips=None, split: str = "train",
            pool: Pool | None = None) -> Clip:
    """One composed two-person clip of `kind` (see KINDS) from the bases of `split` among
    `clips` (default: the processed set's real clips). Deterministic for a seed."""
    if kind not in _COMPOSERS:
        raise ValueError(f"unknown kind {kind!r}; expected one of {KINDS}")
    frames = int(round(seconds * sk.FPS))
    if frames < 40:
        raise ValueError(f"composed clips need at least 2 s, got {seconds} s")
    if pool is None:
        from interplay.motion.clip import default_clips
        pool = pool_of(default_clips() if clips is None else clips, split)
    if not pool.can(kind):
        raise ValueError(f"no {'walk' if kind == 'walk_side_by_side' else 'standing'} bases "
                         f"in the {pool.split} split for {kind}")
    rng = np.random.default_rng([seed, KINDS.index(kind)])
    for attempt in range(8):      # a draw can fail (a chest out of reach, hands touching early): draw again
        try:
            a, b, place, contact, prompts = _COMPOSERS[kind](rng, pool, frames)
            if kind in HANDS_APART_FIRST:
                _check_hands_apart(a.joints, b.joints, contact)
            break
        except ValueError:
            if attempt == 7:
                raise
    people, transform = canonicalize([a.joints, b.joints])
    bases = [dict(a.base, role="person 1"), dict(b.base, role="person 2")]
    meta = {"kind": kind, "seed": int(seed), "contact": contact, "placement": place,
            "bases": bases, "source_fps": 20, "transform": transform}
    return Clip(id=f"composed:{pool.split}/{kind}/{seed}", source="composed",
                people=[p.astype(np.float32) for p in people], offsets=[a.offsets, b.offsets],
                label=f"composed {kind}", prompt=str(prompts[int(rng.integers(len(prompts)))]),
                split=pool.split, synthetic=True, licence=_licence(bases), meta=meta)


def compose_set(n_per_kind: int, seed: int, clips=None, split: str = "train",
                seconds: float = 4.0, kinds=KINDS) -> list[Clip]:
    """n_per_kind composed clips of every kind the split has bases for (kinds without bases
    are skipped), with consecutive seeds from `seed`."""
    if clips is None:
        from interplay.motion.clip import default_clips
        clips = default_clips()
    pool = pool_of(clips, split)
    out = []
    for kind in kinds:
        if not pool.can(kind):
            continue
        for i in range(n_per_kind):
            out.append(compose(kind, seed + i, seconds, split=split, pool=pool))
    return out
