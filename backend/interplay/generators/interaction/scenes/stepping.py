"""Feet that step through a turn on the spot.

A turn made by blending poses about the pelvis (an interaction's last frames turned into a
walk that leaves the other way) swings both planted feet round it: a half turn in 0.8 s slides
each foot some 0.3 m, which the reviewer rightly calls foot skating. Here, over the turn's
frames, each foot stays exactly where it stood, then steps — lifted in an arc, turning with
the body — to where the pose after the turn puts it, and stays there: one foot after the
other, the one with further to go first (it opens the turn, the other closes it) unless the
other is already in the air after the turn (it steps last, on into its stride). A foot that
hardly moves (under MIN_STEP and MIN_TURN) is not lifted but carried there over the whole
turn, slower than anything the skating check counts. The legs are re-posed by footlock's
two-bone IK, bones keeping their lengths.

    joints = stepped(joints, a, b)      # frames [a, b) turn between frame a-1 and frame b

numpy only.
"""

from __future__ import annotations

import numpy as np

from interplay.motion.footlock import LEGS, apply_foot_corrections

LIFT = 0.08        # m: a step's highest point above the line from lift-off to landing
MIN_STEP = 0.03    # m: a foot moving less than this …
MIN_TURN = 0.2     # rad: … and turning less than this slides (slowly) instead of stepping
SWING = 0.7        # share of a step's frames in which the lifted foot travels


def _ease(w: np.ndarray) -> np.ndarray:
    return w * w * (3 - 2 * w)


def _wrap(angle):
    return (np.asarray(angle) + np.pi) % (2 * np.pi) - np.pi


def _yaw(joints: np.ndarray, ankle: int, toe: int) -> np.ndarray:
    """Yaw (...) of the foot's ankle-to-toe direction, 0 along +Z, positive towards +X."""
    d = joints[..., toe, :] - joints[..., ankle, :]
    return np.arctan2(d[..., 0], d[..., 2])


def stepped(joints: np.ndarray, a: int, b: int, lift: float = LIFT) -> np.ndarray:
    """Joints (T, 22, 3) with the legs in frames [a, b) stepping from the feet of frame a-1 to
    those of frame b (module doc); every other frame, and the upper body, unchanged. `joints`
    as it is where there is no frame before a or after b, or fewer than 4 frames to step in."""
    t = len(joints)
    if a < 1 or b >= t or b - a < 4:
        return joints
    out = np.asarray(joints, dtype=np.float64)
    before, after, window = out[a - 1], out[b], out[a:b]
    n = b - a
    # the body's turn over the window (unwrapped): a foot turns the way the body does
    feet = [(ankle, toe) for (_, _, ankle, toe) in LEGS]
    body = sum(float(_wrap(_yaw(after, *f) - _yaw(before, *f))) for f in feet) / 2
    moves = [float(np.linalg.norm((after[ank] - before[ank])[[0, 2]])) for ank, _ in feet]
    # a foot already in the air after the turn (a walk's first frame mid-stride) steps last,
    # straight on into its stride; otherwise the one with further to go opens the turn
    lifted = [float(after[ank, 1]) for ank, _ in feet]
    first = int(np.argmin(lifted)) if abs(lifted[0] - lifted[1]) > MIN_STEP else int(np.argmax(moves))
    x = (np.arange(n) + 1) / (n + 1)                      # (n,) through the window, open at both ends
    window = window.copy()
    corr = np.zeros((n, 2, 3))
    height = np.zeros((n, 2))
    for leg, (ankle, toe) in enumerate(feet):
        turn = float(_wrap(_yaw(after, ankle, toe) - _yaw(before, ankle, toe)))
        if abs(turn) > 2.5 and np.sign(turn) != np.sign(body):
            turn -= 2 * np.pi * np.sign(turn)           # a half turn goes round with the body
        if moves[leg] < MIN_STEP and abs(turn) < MIN_TURN:
            w, arc = _ease(x), np.zeros(n)
        else:
            lo, hi = (0.0, 0.5) if leg == first else (0.5, 1.0)
            s = np.clip((x - lo) / (hi - lo), 0.0, 1.0)
            # the foot leaves the floor before it moves across it and lands after (the
            # middle SWING of the step carries it), and a foot that ends (or starts) in the
            # air rises (falls) that much less over the arc, LIFT / 2 at least
            rise = abs(float(after[ankle, 1] - before[ankle, 1]))
            edge = (1 - SWING) / 2
            w = _ease(np.clip((s - edge) / SWING, 0.0, 1.0))
            arc = max(lift - rise, lift / 2) * np.sin(np.pi * s)
        # the foot's pitch goes from one stance's to the other's with the step, not the blend's
        pitch = (1 - w) * (before[toe] - before[ankle])[1] + w * (after[toe] - after[ankle])[1]
        window[:, toe, 1] = window[:, ankle, 1] + pitch
        goal = (1 - w)[:, None] * before[ankle] + w[:, None] * after[ankle]          # (n, 3)
        corr[:, leg, :2] = (goal - window[:, ankle])[:, [0, 2]]
        yaw = _yaw(before, ankle, toe) + w * turn
        corr[:, leg, 2] = _wrap(yaw - _yaw(window, ankle, toe))
        height[:, leg] = goal[:, 1] + arc - window[:, ankle, 1]
    out = out.copy()
    out[a:b] = apply_foot_corrections(window, corr, height)
    return out
