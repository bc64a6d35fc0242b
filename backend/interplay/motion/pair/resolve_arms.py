"""Penetration resolution's arm steps (`resolve.py`, steps 2 and 3): hands that touched the
partner follow the partner's shift, arm spheres inside the other body are pushed out by elbow
and wrist moves on fixed bones, and in a hug the hands stay behind the partner's torso plane.
numpy only; joints (T, 22, 3) each, metres, Y up.
"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as ms
from interplay.motion.ik import two_bone_ik
from interplay.motion.pair.body import HAND_SPHERES, SPHERE_FRACTION, SPHERE_PARENT, body_spheres

TOUCH_M = 0.03             # a hand this near the partner's body touched it (eval-pair's contact)
HUG_BEHIND_M = 0.02        # a hugging hand is kept this far behind the partner's torso plane
RELAX = 1.5                # the arms' moves over-relaxed a little
ARM_SMOOTH = 4             # frames: the arms' corrections eased in and out over ±this
J = sk.JOINT_INDEX
ARM = {s: (np.flatnonzero(SPHERE_PARENT == J[f"{s}_shoulder"]),      # upper arm …
            np.flatnonzero(SPHERE_PARENT == J[f"{s}_elbow"])) for s in ("left", "right")}


def envelope(x: np.ndarray, r: int) -> np.ndarray:
    """A smooth curve ≥ x (T,): the max over ±r frames, Hann-averaged over ±r frames."""
    dil = np.lib.stride_tricks.sliding_window_view(np.pad(x, r, mode="edge"), 2 * r + 1).max(axis=1)
    w = np.hanning(2 * r + 3)[1:-1]
    return np.convolve(np.pad(dil, r, mode="edge"), w / w.sum(), mode="valid")


def _solve_arm(j, side, wrist, pole, frames) -> np.ndarray:
    out = j.copy()
    if frames.any():
        out[frames] = two_bone_ik(j[frames], f"{side}_arm", wrist[frames], pole[frames])
    return out


def _hand(j: np.ndarray, side: str) -> np.ndarray:
    """The hand sphere's centre (T, 3) of one arm."""
    e, w = j[:, J[f"{side}_elbow"]], j[:, J[f"{side}_wrist"]]
    return e + SPHERE_FRACTION[ARM[side][1][-1]] * (w - e)


def keep_contacts(moved, orig, other, shift_self, shift_other, scales, taper):
    """Step 2 for one person: hands that touched the partner follow the partner's shift."""
    s_other = body_spheres(other, scales[1])
    hand_r = body_spheres(orig[:1], scales[0]).radii[ARM["left"][1][-1]]
    out = moved
    for side in ARM:
        g = np.linalg.norm(s_other.centres - _hand(orig, side)[:, None], axis=-1) - s_other.radii - hand_r
        touch = g.min(axis=1) <= TOUCH_M
        if touch.any():
            follow = np.where(np.isin(g.argmin(axis=1), HAND_SPHERES), 0.5, 1.0)
            delta = (follow * envelope(touch.astype(float), 3) * taper)[:, None] * (shift_other - shift_self)
            frames, goal = np.abs(delta).max(axis=1) > 1e-6, _hand(out, side) + delta
            wr, el = out[:, J[f"{side}_wrist"]] + delta, out[:, J[f"{side}_elbow"]] + 0.5 * delta
            for _ in range(3):      # the hand lies past the wrist: aim the wrist until it is there
                moved = _solve_arm(out, side, wr, el, frames)
                wr = wr + (goal - _hand(moved, side)) / SPHERE_FRACTION[ARM[side][1][-1]]
            out = moved
    return out


def _arm_moves(push: np.ndarray, nu: int, f: np.ndarray, ridge: float = 0.05):
    """Elbow and wrist moves (H, 3) that best give an arm's spheres the moves `push` (H, K, 3)
    (upper arm, first nu: f·elbow; forearm: (1 − f)·elbow + f·wrist), least squares over the
    spheres that must move, with a small ridge."""
    upper = np.arange(len(f)) < nu
    ce, cw = np.where(upper, f, 1.0 - f), np.where(upper, 0.0, f)
    m = (np.abs(push).sum(axis=-1) > 0).astype(np.float64)              # (H, K)
    see, sew, sww = m @ (ce * ce) + ridge, m @ (ce * cw), m @ (cw * cw) + ridge
    re, rw = np.einsum("k,hkd->hd", ce, push), np.einsum("k,hkd->hd", cw, push)
    det = (see * sww - sew * sew)[:, None]
    return (sww[:, None] * re - sew[:, None] * rw) / det, (see[:, None] * rw - sew[:, None] * re) / det


def push_arms(me, other, scales, tol, taper, active, fwd=None):
    """One round of step 3 for `me`'s arms against `other` on the frames `active` (indices):
    (joints, frames re-solved (T,)). `fwd` (T, 3), a hug: the partner's forward, forearm and
    hand pushes towards it are reflected backwards."""
    sm, so = body_spheres(me[active], scales[0]), body_spheres(other[active], scales[1])
    touched, out = np.zeros(len(me), bool), me
    for side, (upper, fore) in ARM.items():
        idx, nu = np.concatenate([upper, fore]), len(upper)
        c, o = sm.centres[:, idx], so.centres                            # (A, K, 3), (A, S, 3)
        d2 = (np.einsum("tkd,tkd->tk", c, c)[:, :, None] + np.einsum("tsd,tsd->ts", o, o)[:, None]
              - 2.0 * c @ o.transpose(0, 2, 1))
        dist = np.sqrt(np.maximum(d2, 0.0))                              # (A, K, S)
        viol = np.maximum(sm.radii[idx][:, None] + so.radii[None] - tol[idx] - dist, 0.0)
        hit = viol.any(axis=(1, 2))
        if not hit.any():
            continue
        rows, viol, c, o = active[hit], viol[hit], c[hit], o[hit]
        w = viol / np.maximum(dist[hit], 1e-9)                           # Σ viol · unit normal
        push = c * w.sum(axis=2)[..., None] - w @ o                      # (H, K, 3)
        norm = np.linalg.norm(push, axis=-1)
        push *= (np.minimum(norm, viol.max(axis=2)) / np.maximum(norm, 1e-12))[..., None]
        if fwd is not None:
            f = fwd[rows]
            push[:, nu:] -= 2.0 * np.maximum(np.einsum("hkd,hd->hk", push[:, nu:], f), 0.0)[..., None] * f[:, None]
        elbow_d, wrist_d = _arm_moves(push, nu, SPHERE_FRACTION[idx])
        most = 1.5 * np.linalg.norm(push, axis=-1).max(axis=1, keepdims=True)   # (H, 1)
        for d in (elbow_d, wrist_d):    # a linear fit: no joint moves much more than a sphere must
            d *= np.minimum(1.0, most / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-12))
        moves = np.zeros((2, len(me), 3))
        moves[:, rows] = np.stack([elbow_d, wrist_d]) * RELAX
        moves = np.stack([_eased(m, taper) for m in moves])   # no arm jumps in and out of place
        frames = np.abs(moves).max(axis=(0, 2)) > 1e-5
        out = _move_arm(out, side, moves[0], moves[1], frames)
        touched |= frames
    return out, touched


def _move_arm(j, side, elbow_d, wrist_d, frames) -> np.ndarray:
    """The arm with its elbow and wrist as near elbow + elbow_d, wrist + wrist_d as the bones
    allow: the elbow on its bone's sphere round the shoulder, the wrist on its bone's round the
    new elbow, solved by two-bone IK to that wrist with the new elbow as pole (exactly it)."""
    if not frames.any():
        return j
    s, e, w = (j[frames, J[f"{side}_{n}"]] for n in ("shoulder", "elbow", "wrist"))

    def on(centre, length, goal):
        return centre + length * goal / np.maximum(np.linalg.norm(goal, axis=1, keepdims=True), 1e-9)
    new_e = on(s, np.linalg.norm(e - s, axis=1, keepdims=True), e + elbow_d[frames] - s)
    new_w = on(new_e, np.linalg.norm(w - e, axis=1, keepdims=True), w + wrist_d[frames] - new_e)
    out = j.copy()
    out[frames] = two_bone_ik(j[frames], f"{side}_arm", new_w, new_e)
    return out


def _eased(d: np.ndarray, taper: np.ndarray) -> np.ndarray:
    """A move (T, 3) per frame averaged over ±ARM_SMOOTH frames (Gaussian): per-frame moves
    would make an arm jump in and out of place; what a frame then still lacks, the next round
    adds."""
    if not np.abs(d).any():
        return d
    k = np.exp(-0.5 * (np.arange(-ARM_SMOOTH, ARM_SMOOTH + 1) / (ARM_SMOOTH / 2)) ** 2)
    pad = np.pad(d, ((ARM_SMOOTH, ARM_SMOOTH), (0, 0)), mode="edge")
    g = np.stack([np.convolve(pad[:, i], k / k.sum(), mode="valid") for i in range(3)], axis=1)
    return g * taper[:, None]


def behind(me: np.ndarray, other: np.ndarray) -> dict:
    """Hug: `other`'s forward (T, 3) (`measures.frame_of`, as the hug check reads it) and per
    side the frames (T,) where `me`'s hand lies behind `other`'s torso plane (at spine3)."""
    fwd = ms.frame_of(other).forward
    ahead = {s: np.einsum("td,td->t", _hand(me, s) - other[:, J["spine3"]], fwd) for s in ARM}
    return {"forward": fwd, **{s: v < 0 for s, v in ahead.items()}}


def keep_behind(me, other, behind, taper) -> np.ndarray:
    """Hug: hands that were behind `other`'s torso plane and are now less than HUG_BEHIND_M
    behind it are moved back along `other`'s backward by IK (the move eased in time)."""
    out, fwd = me, behind["forward"]
    for side in ARM:
        ahead = np.einsum("td,td->t", _hand(out, side) - other[:, J["spine3"]], fwd)
        slip = np.where(behind[side], np.maximum(ahead + HUG_BEHIND_M, 0.0), 0.0)
        back = _eased(-slip[:, None] * fwd, taper)
        wr, el = out[:, J[f"{side}_wrist"]], out[:, J[f"{side}_elbow"]]
        out = _solve_arm(out, side, wr + back, el, np.abs(back).max(axis=1) > 1e-5)
    return out
