"""Arm actions laid over a captured motion: held poses (T-pose, arms up, arms forward, hands on
hips, arms crossed, one hand raised) and a wave, each as a wrist target and an elbow hint in
the person's own frame (the torso's left / up / forward axes, `bodyframe`), solved per frame by
two-bone IK on the performer's bones (`ik.two_bone_ik`: lengths kept exactly, the hand turned
with the forearm) and blended in and out with eased weights.

Why targets in the torso frame rather than a copied arm: the base motion keeps its gait, turns
and lean, and the held arm moves with the chest the way a real held arm does; the wrist target
is placed where the benchmark's pose measures (motion/checks/measures.py) look for that pose,
which is also where a person holds it (arms horizontal for a T-pose, wrists on the hip bones
with the elbows out for hands on hips, …).

Shapes: joints (T, 22, 3) metres, Y up, 20 fps; weights (T,) in [0, 1].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.bodyframe import body_frame
from interplay.motion.ik import ease, two_bone_ik

J = sk.JOINT_INDEX
POSES = ("t_pose", "arm_up", "arm_forward", "hand_on_hip", "arm_crossed", "wave")
BLEND_S = 0.35          # ease in / out of a pose
WAVE_PERIOD_S = 0.7     # one side-to-side swing and back (a wave is 1–2 Hz)
WAVE_SWING_M = 0.11     # the hand's lateral swing either side of its centre


@dataclass(frozen=True)
class ArmAction:
    """One arm's action over frames [start, end) of a motion."""
    side: str            # "left" | "right"
    pose: str            # one of POSES
    start: int
    end: int


def _axes(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The torso's (left, up, forward) unit axes per frame (T, 3) each."""
    b = body_frame(joints, sk.FPS) if len(joints) > 1 else body_frame(
        np.concatenate([joints, joints]), sk.FPS)
    t = len(joints)
    up = np.broadcast_to(np.array([0.0, 1.0, 0.0]), (t, 3))
    return b.left[:t], up, b.forward[:t]


def _lengths(joints: np.ndarray, side: str) -> tuple[float, float]:
    sh, el, wr = (joints[:, J[f"{side}_{p}"]] for p in ("shoulder", "elbow", "wrist"))
    return (float(np.median(np.linalg.norm(el - sh, axis=1))),
            float(np.median(np.linalg.norm(wr - el, axis=1))))


def targets(joints: np.ndarray, side: str, pose: str, frames: np.ndarray
            ) -> tuple[np.ndarray, np.ndarray]:
    """(wrist target, elbow hint), each (T, 3), for one arm holding `pose` over all frames of
    joints; `frames` (T,) are frame numbers in the action (the wave's phase)."""
    if pose not in POSES:
        raise ValueError(f"unknown arm pose {pose!r}; expected one of {', '.join(POSES)}")
    left, up, fwd = _axes(joints)
    s = 1.0 if side == "left" else -1.0
    out = s * left                                   # away from the body on this side
    sh = joints[:, J[f"{side}_shoulder"]]
    hip = joints[:, J[f"{side}_hip"]]
    neck = joints[:, sk.NECK]
    upper, fore = _lengths(joints, side)
    reach = 0.985 * (upper + fore)                   # nearly straight, never locked
    if pose == "t_pose":
        wrist = sh + reach * out + 0.02 * up
        elbow = sh + upper * out - 0.2 * fwd
    elif pose == "arm_up":
        wrist = sh + reach * (0.96 * up + 0.2 * out + 0.15 * fwd)
        elbow = sh + upper * out + 0.2 * fwd
    elif pose == "arm_forward":
        wrist = sh + reach * fwd
        elbow = sh + upper * fwd - 0.3 * up
    elif pose == "hand_on_hip":
        # On the side of the hip bone (the hip joint sits inside the pelvis), high enough
        # that the elbow bends to ~90° and points out to the side.
        wrist = hip + 0.10 * out + 0.12 * up - 0.01 * fwd
        elbow = sh + 0.35 * out - 0.15 * up - 0.1 * fwd
    elif pose == "arm_crossed":
        # The forearms stacked in front of the chest, each wrist past the other arm's elbow;
        # the right forearm lies above the left one so the two do not pass through each other.
        chest = neck - (0.22 if side == "left" else 0.17) * up
        wrist = chest + 0.14 * fwd - 0.13 * out
        elbow = sh + 0.25 * out - 0.3 * up + 0.2 * fwd
    else:   # wave: upper arm out and up, forearm near vertical, the hand swinging sideways
        phase = np.sin(2 * np.pi * np.asarray(frames, dtype=np.float64) / (WAVE_PERIOD_S * sk.FPS))
        centre = sh + 0.75 * upper * out + (0.5 * upper + 0.85 * fore) * up + 0.12 * fwd
        wrist = centre + (WAVE_SWING_M * phase)[:, None] * out
        elbow = sh + upper * out - 0.1 * up
    return wrist, elbow


def weights(frames: int, start: int, end: int, ease_in: bool = True, ease_out: bool = True
            ) -> np.ndarray:
    """(frames,) eased weight: 0 outside [start, end), ramps of BLEND_S at the borders that are
    eased (a pose held from the first frame starts at full weight)."""
    ramp = max(1, int(round(BLEND_S * sk.FPS)))
    w = np.zeros(frames)
    w[start:end] = 1.0
    idx = np.arange(frames)
    if ease_in and start > 0:
        into = (idx >= start) & (idx < start + ramp)
        w[into] = ease((idx[into] - start + 1) / (ramp + 1))
    if ease_out and end < frames:
        out = (idx >= end - ramp) & (idx < end)
        w[out] = np.minimum(w[out], ease((end - idx[out]) / (ramp + 1)))
    return w


def apply(joints: np.ndarray, actions: list[ArmAction]) -> np.ndarray:
    """Joints (T, 22, 3) with each arm action laid over its frames (later actions of the same
    arm win where they overlap). The input is not modified; untouched arms and every other
    joint stay exactly as they were."""
    out = np.asarray(joints, dtype=np.float64).copy()
    t = len(out)
    for a in actions:
        s, e = max(0, a.start), min(t, a.end)
        if e <= s:
            continue
        w = weights(t, s, e)
        on = w > 0                                  # frames outside stay bit for bit
        wrist, elbow = targets(out, a.side, a.pose, np.arange(t) - s)
        out[on] = two_bone_ik(out[on], f"{a.side}_arm", wrist[on], pole=elbow[on], weight=w[on])
    return out
