"""Penetration resolution for two people that keeps the contact a prompt asks for (issue 15).
numpy only; joints (T, 22, 3) each, metres, Y up; the spheres of `body.py`.

Bounds (`pair_bounds`), the benchmark's measures: IF, the share of frames where a sphere of one
body sinks > 2 cm into the other (`checks.named.no_interpenetration`: hands never count, forearms
neither with contact) ≤ 0.10; without contact eval-pair's IF (any overlap) ≤ 0.10 too; with
contact eval-pair's penetration (mean of `measures.deepest_overlap`) ≤ 3 cm. Contact: "none";
"hands" (handshake, high five, push, held hands, a couple dancing: hands and forearms may touch);
"hug" (arms round the partner, hands on the back).

A pair within its bounds comes back unchanged (bit for bit). Otherwise:
  1. separation: both move apart on the ground, half each, along the (smoothed, rate-limited)
     line between their pelvises, by the least distance (solved per frame and sphere pair) that
     leaves no trunk, head or leg sphere more than the tolerance inside the other's, dilated
     and Hann-smoothed over time (pelvis steps change by millimetres: no_pops allows 10 cm);
     planted feet stay put through it (legs re-solved by IK);
  2. contacts kept: a hand that touched the partner (within 3 cm) follows the partner's shift
     (half of it when it held the partner's hand), by two-bone IK;
  3. arms: arm spheres inside the other body beyond the tolerance are pushed out along the
     surface normals; the elbow and wrist moves that best give those pushes (least squares,
     eased in time) are made on fixed bones (`motion.ik`), ARM_ROUNDS rounds; in a hug the
     forearms and hands are never pushed towards the partner's front, and hands that were
     behind the partner's torso plane stay behind it;
  4. if the bound still fails, a separation that counts the arms too (not hands and forearms
     with contact), the feet moving with the bodies.
Bones keep their length. `free_start` / `free_end` False ease every change to zero at that end.
Steps 2 and 3 (the arms) are `resolve_arms.py`.

    a, b, report = resolve_pair(a, b, "hug")   # report: applied, before/after, moved_m, frames …
"""

from __future__ import annotations

import time

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as ms
from interplay.motion.checks.named import OVERLAP_DEPTH_M, OVERLAP_SHARE
from interplay.motion.footlock import stance
from interplay.motion.ik import ease, two_bone_ik
from interplay.motion.kinematics import facing_angle
from interplay.motion.pair.body import (
    HAND_SPHERES,
    SPHERE_PARENT,
    body_scale,
    body_spheres,
    surface_gaps,
)
from interplay.motion.pair.resolve_arms import (
    ARM,
    behind,
    envelope,
    keep_behind,
    keep_contacts,
    push_arms,
)
from interplay.motion.signals import runs, smooth

CONTACTS = ("none", "hands", "hug")
CONTACT_DEPTH_M = 0.03     # mean deepest overlap allowed where contact is asked
TARGET_M = 0.012           # with contact: what is left of an overlap the IF counts (< 2 cm)
ARM_TARGET_M = 0.022       # … of a touching hand's or forearm's (< 3 cm)
CLEAR_M = -0.005           # without contact: every sphere pair left 5 mm apart
SMOOTH = 10                # frames (0.5 s): separation ramps, direction smoothing
FOOT_BLEND = 6             # frames: a held foot's correction fades out into a long swing
FOOT_HOLD_M = 0.08         # … and is at most this long (legs cannot lean far)
TURN_DEG = 6.0             # the separation's direction turns at most this much a frame
MAX_SEPARATION_M = 1.5
ARM_ROUNDS = 4             # arm rounds (`resolve_arms.push_arms`)
J, S = sk.JOINT_INDEX, len(SPHERE_PARENT)
BODY = np.setdiff1d(np.arange(S), np.concatenate([u for p in ARM.values() for u in p]))


def pair_bounds(a: np.ndarray, b: np.ndarray, contact: str = "none") -> dict:
    """{"if", "if_any", "depth_cm", "ok", "bound"} under `contact` (module doc), from one
    sphere-gap array (the same numbers as `measures.body_overlap` / `deepest_overlap`)."""
    if contact not in CONTACTS:
        raise ValueError(f"contact must be one of {CONTACTS}, got {contact!r}")
    touching = contact != "none"
    gaps = surface_gaps(body_spheres(a), body_spheres(b))                # (T, S, S)
    keep = np.ones(S, bool)
    keep[ms.REACH_SPHERES if touching else HAND_SPHERES] = False
    share = float((gaps[:, keep][:, :, keep] < -OVERLAP_DEPTH_M).any(axis=(1, 2)).mean())
    deepest = np.maximum(0.0, -gaps.min(axis=(1, 2)))
    share_any, depth = float((deepest > 0).mean()), float(deepest.mean())
    if touching:
        ok, bound = (share <= OVERLAP_SHARE and depth <= CONTACT_DEPTH_M,
                     f"IF ≤ {OVERLAP_SHARE}, depth ≤ {CONTACT_DEPTH_M * 100:.0f} cm")
    else:
        ok, bound = (max(share, share_any) <= OVERLAP_SHARE,
                     f"IF ≤ {OVERLAP_SHARE} (at {OVERLAP_DEPTH_M * 100:.0f} cm and at any depth)")
    return {"if": round(share, 3), "if_any": round(share_any, 3), "depth_cm": round(depth * 100, 2),
            "ok": bool(ok), "bound": bound}


def _tolerances(contact: str) -> np.ndarray:
    """(S, S) overlap each sphere pair may keep (negative: a gap it must keep)."""
    if contact == "none":
        return np.full((S, S), CLEAR_M)
    free = np.isin(np.arange(S), ms.REACH_SPHERES)
    return np.where(free[:, None] | free[None, :], ARM_TARGET_M, TARGET_M)


def _taper(t: int, free_start: bool, free_end: bool) -> np.ndarray:
    """(T,) 1, eased to 0 over SMOOTH frames at an end that is not free."""
    f, w = np.arange(t, dtype=np.float64), np.ones(t)
    if not free_start:
        w = np.minimum(w, ease(f / SMOOTH))
    if not free_end:
        w = np.minimum(w, ease((t - 1 - f) / SMOOTH))
    return w


def _direction(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Unit ground vectors (T, 3) from a's pelvis towards b's, averaged over ±SMOOTH frames
    with weights that vanish as the pelvises meet, turning at most TURN_DEG a frame (people
    who cross would otherwise flip the direction, and the separation with it, in one frame);
    where the pelvises stay together: a's facing."""
    d = (b[:, sk.PELVIS] - a[:, sk.PELVIS])[:, [0, 2]]
    n = np.linalg.norm(d, axis=1, keepdims=True)
    acc = smooth(d / np.maximum(n, 1e-9) * np.clip(n, 0.0, 0.3), 2 * SMOOTH + 1)
    angle = np.arctan2(acc[:, 0], acc[:, 1])
    known = np.linalg.norm(acc, axis=1) > 1e-6
    yaw = np.empty(len(d))
    yaw[0] = angle[known][0] if known.any() else float(facing_angle(a[:1])[0])
    step = np.radians(TURN_DEG)
    for t in range(1, len(d)):
        turn = (angle[t] - yaw[t - 1] + np.pi) % (2 * np.pi) - np.pi if known[t] else 0.0
        yaw[t] = yaw[t - 1] + np.clip(turn, -step, step)
    return np.stack([np.sin(yaw), np.zeros_like(yaw), np.cos(yaw)], axis=-1)


def _separation(ca, cb, ra, rb, ia, ib, u, tol) -> np.ndarray:
    """Least σ (T,) ≥ 0 such that b moved by σu relative to a leaves no sphere ia of a deeper
    than `tol` in one ib of b. With d a centre offset, |d + σu|² = |d|² + 2σ d·u + σ²: each
    round raises σ past the far root of every pair still inside."""
    pa, pb = ca[:, ia], cb[:, ib]                                        # (T, I, 3), (T, J, 3)
    du0 = np.einsum("tjk,tk->tj", pb, u)[:, None] - np.einsum("tik,tk->ti", pa, u)[:, :, None]
    dd0 = (np.einsum("tik,tik->ti", pa, pa)[:, :, None] + np.einsum("tjk,tjk->tj", pb, pb)[:, None]
           - 2.0 * pa @ pb.transpose(0, 2, 1))                           # (T, I, J)
    reach2 = np.maximum(ra[ia][:, None] + rb[ib][None] - tol[np.ix_(ia, ib)], 0.0) ** 2
    sigma = np.zeros(len(u))
    rows = np.flatnonzero((dd0 < reach2).any(axis=(1, 2)))
    for _ in range(12):
        if not len(rows):
            break
        s = sigma[rows, None, None]
        du, dd = du0[rows] + s, dd0[rows] + 2.0 * s * du0[rows] + s * s
        inside = dd < reach2
        hit = inside.any(axis=(1, 2))
        rows, du, dd, inside = rows[hit], du[hit], dd[hit], inside[hit]
        far = -du + np.sqrt(np.maximum(du * du - dd + reach2, 0.0))
        sigma[rows] = np.minimum(sigma[rows] + np.where(inside, far, 0.0).max(axis=(1, 2)) + 1e-4,
                                 MAX_SEPARATION_M)
    return sigma


def _separate(a, b, scales, spheres, tol, taper, hold=True):
    """(a, b, shifts (T, 3) of a and of b): steps 1 / 4 (feet held through the shift if `hold`).
    The eased separation exceeds what some frames need, which can bring spheres that were
    beside each other (a hand behind the other's arm) together: up to three passes."""
    u = _direction(a, b)
    radii = [body_spheres(p[:1], s).radii for p, s in zip((a, b), scales)]
    total = np.zeros(len(a))
    for _ in range(3):
        ca, cb = (body_spheres(p + sg * 0.5 * total[:, None, None] * u[:, None], s).centres
                  for p, s, sg in zip((a, b), scales, (-1.0, 1.0)))
        sigma = _separation(ca, cb, radii[0], radii[1], spheres, spheres, u, tol)
        if not sigma.any():
            break
        total = np.minimum(total + envelope(sigma, SMOOTH) * taper, MAX_SEPARATION_M)
    if not total.any():
        return a, b, np.zeros_like(u), np.zeros_like(u)
    half = 0.5 * total[:, None] * u
    a2, b2 = a - half[:, None], b + half[:, None]
    if hold:
        a2, b2 = _hold_feet(a2, a, -half), _hold_feet(b2, b, half)
    return a2, b2, -half, half


def _hold_feet(moved: np.ndarray, orig: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """Feet planted in `orig` (a lift of ≤ 2·FOOT_BLEND frames bridged) keep, through one
    person's `shift` (T, 3), the shift of their stance's middle frame, by at most FOOT_HOLD_M;
    faded out over FOOT_BLEND frames into each swing (a kicking leg moves with the body); the
    legs re-solved by two-bone IK (knees bending as they did; a leg that cannot reach stops
    short); nothing changes where the shift is zero."""
    plant, t, out = stance(orig), np.arange(len(orig)), moved
    moving = np.abs(shift).any(axis=1)
    for leg, side in enumerate(("left", "right")):
        for a, b in runs(~plant[:, leg]):              # a brief lift is no new stance
            if b - a <= 2 * FOOT_BLEND and a > 0 and b < len(t):
                plant[a:b, leg] = True
        spans = runs(plant[:, leg])
        if not spans or not moving.any():
            continue
        known = np.concatenate([t[a:b] for a, b in spans])
        held = np.concatenate([shift[(a + b - 1) // 2] - shift[a:b] for a, b in spans])
        weight = plant[:, leg].astype(float)          # 1 in stance, eased out and in over swings
        for a, b in runs(~plant[:, leg]):
            f = np.arange(a, b)
            weight[a:b] = np.maximum(ease(1 - (f - a + 1) / FOOT_BLEND) * (a > 0),
                                     ease(1 - (b - f) / FOOT_BLEND) * (b < len(t)))
        corr = weight[:, None] * np.stack([np.interp(t, known, held[:, 0]), np.zeros(len(t)),
                                           np.interp(t, known, held[:, 2])], axis=1)
        length = np.linalg.norm(corr, axis=1, keepdims=True)
        corr *= np.minimum(1.0, FOOT_HOLD_M / np.maximum(length, 1e-12))    # a foot slides beyond
        frames = moving & (np.abs(corr).max(axis=1) > 1e-9)
        ankle, knee = out[:, J[f"{side}_ankle"]], out[:, J[f"{side}_knee"]]
        if frames.any():
            out = out.copy()
            out[frames] = two_bone_ik(out[frames], f"{side}_leg", (ankle + corr)[frames],
                                      knee[frames], carry="keep")
    return out


def resolve_pair(a: np.ndarray, b: np.ndarray, contact: str = "none", free_start: bool = True,
                 free_end: bool = True) -> tuple[np.ndarray, np.ndarray, dict]:
    """(a, b, report): the two people with their overlap resolved (module doc), unchanged
    within the bounds. report: applied, reason, contact, before / after (`pair_bounds`),
    moved_m (largest pelvis move), frames (with any joint moved), arm_frames (arms re-solved
    by step 3), ms."""
    t0 = time.perf_counter()
    a0, b0 = (np.asarray(x, dtype=np.float64) for x in (a, b))
    if a0.shape != b0.shape or a0.ndim != 3 or a0.shape[1:] != (sk.NUM_JOINTS, 3):
        raise ValueError(f"expected two (T, 22, 3) arrays of one length, got {a0.shape}, {b0.shape}")
    before = pair_bounds(a0, b0, contact)
    report: dict = {"applied": False, "reason": "within the bound", "contact": contact,
                    "before": before, "after": before, "moved_m": 0.0, "frames": 0, "arm_frames": 0}
    if before["ok"] or len(a0) < 2:
        report.update(reason=report["reason"] if before["ok"] else "too short",
                      ms=round((time.perf_counter() - t0) * 1000, 1))
        return a0.copy(), b0.copy(), report
    sc = (body_scale(a0), body_scale(b0))
    taper, tol = _taper(len(a0), free_start, free_end), _tolerances(contact)
    a, b, sha, shb = _separate(a0, b0, sc, BODY, tol, taper)
    if contact != "none":
        a = keep_contacts(a, a0, b0, sha, shb, sc, taper)
        b = keep_contacts(b, b0, a0, shb, sha, sc[::-1], taper)
    hug = (behind(a0, b0), behind(b0, a0)) if contact == "hug" else None
    fa, fb = (hug[0]["forward"], hug[1]["forward"]) if hug else (None, None)
    arm_frames, active = np.zeros(len(a0), bool), np.arange(len(a0))
    for _ in range(ARM_ROUNDS):
        a, ta = push_arms(a, b, sc, tol, taper, active, fa)
        b, tb = push_arms(b, a, sc[::-1], tol, taper, active, fb)
        arm_frames |= ta | tb
        active = np.flatnonzero(ta | tb)        # the other frames are clear
        if not len(active):
            break
    if hug:
        a, b = keep_behind(a, b, hug[0], taper), keep_behind(b, a, hug[1], taper)
    after = pair_bounds(a, b, contact)
    if not after["ok"]:                         # step 4
        spheres = np.setdiff1d(np.arange(S), ms.REACH_SPHERES if contact != "none" else [])
        a, b, _, _ = _separate(a, b, sc, spheres, tol, taper, hold=False)
        after = pair_bounds(a, b, contact)
    moved = np.maximum(np.abs(a - a0).max(axis=(1, 2)), np.abs(b - b0).max(axis=(1, 2)))
    pelvis = max(np.linalg.norm((x - x0)[:, sk.PELVIS], axis=1).max() for x, x0 in ((a, a0), (b, b0)))
    report.update(applied=True, after=after, moved_m=round(float(pelvis), 3),
                  frames=int((moved > 1e-6).sum()), arm_frames=int(arm_frames.sum()),
                  reason="resolved" if after["ok"] else "the bound is still not met",
                  ms=round((time.perf_counter() - t0) * 1000, 1))
    return a, b, report
