"""A user's part edit that asks one leg to kick ("kick with the right leg", on a standing or
walking body) made from a real captured kick instead of by re-generating the leg with SPAM:
retrieval draws a capture that kicks with that leg (`RetrievalGenerator`, its draws checked by
the benchmark's kick check), and the kicking leg's bone directions over the kick — in the
capture's own pelvis frame — are laid onto the edited motion's leg, turned to its pelvis's
facing and put on its own bone lengths. The kicks are spread over the edited span and eased
in and out (bone directions blended, then re-normalised: the bones never change length);
every joint outside that leg stays exactly where it was.

    leg_edit(joints, "right_leg", "kick with the right leg", (10, 60), retrieval, seed)
        → (joints, entry) | None
"""

from __future__ import annotations

import numpy as np

from interplay.catalogue.grammar import words_rx
from interplay.catalogue.load import catalogue
from interplay.catalogue.words import words
from interplay.generators.base import Request
from interplay.generators.retrieval.intent import count_of
from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as ms
from interplay.motion.kinematics import facing_angle
from interplay.motion.rotations import yaw_matrix

CHAIN = ("hip", "knee", "ankle", "foot")
HALF_S = 0.75            # the kick laid over ±this around the capture's peak
BLEND = 5                # frames eased in and out at each kick's borders


def _side(part: str | None, prompt: str) -> str | None:
    key = (part or "").strip().lower().replace("-", "_")
    for side in ("left", "right"):
        if key in (f"{side}_leg", f"{side}_lower", f"{side}_foot"):
            return side
    named = [f.text.split()[0] for f in words("side_leg").finditer(prompt.lower())]
    return named[0] if len(set(named)) == 1 and key in ("", "whole_body", "body") else None


def _chain(side: str) -> list[int]:
    return [sk.JOINT_INDEX[f"{side}_{p}"] for p in CHAIN]


def _in_pelvis_frame(joints: np.ndarray, chain: list[int]) -> np.ndarray:
    """(T, 3, 3) unit bone directions hip→knee→ankle→foot, un-turned by the pelvis's yaw."""
    yaw = facing_angle(joints)
    d = joints[:, chain[1:]] - joints[:, chain[:-1]]
    d = d / np.maximum(np.linalg.norm(d, axis=-1, keepdims=True), 1e-9)
    return np.einsum("tij,tbj->tbi", np.stack([yaw_matrix(-y) for y in yaw]), d)


def _kick_window(retrieval, side: str, seed: int) -> np.ndarray | None:
    """A captured kick's leg directions (n, 3, 3), the peak in the middle, or None."""
    req = Request(f"a person kicks with the {side} leg", 1, 3.0, seed)
    plan = retrieval.plan(req)
    k = np.concatenate([c[0] for _, c in retrieval.stream(req, plan)]).astype(np.float64)
    peaks = ms.kicks(ms.frame_of(k), side)
    if not peaks:
        return None
    f, h = max(peaks, key=lambda p: p[1])
    half = int(round(HALF_S * sk.FPS))
    lo, hi = max(0, f - half), min(len(k), f + half + 1)
    return _in_pelvis_frame(k[lo:hi], _chain(side))


def leg_edit(joints: np.ndarray, part: str | None, prompt: str,
             frames: tuple[int, int] | None, retrieval, seed: int
             ) -> tuple[np.ndarray, dict] | None:
    """(edited joints (T, 22, 3), plan entry), or None when the edit is not one leg's kick or
    no captured kick of that leg was found."""
    said = catalogue().get("kick")               # the catalogue's words for a kick
    if said is None or not words_rx(said.words, said.not_before).search(prompt or ""):
        return None
    side = _side(part, prompt)
    if side is None:
        return None
    j = np.asarray(joints, dtype=np.float64)
    a, b = frames or (0, len(j))
    kick = _kick_window(retrieval, side, seed)
    if kick is None:
        return None
    n, count = len(kick), count_of(prompt) or 1
    span = b - a
    if span < n:
        return None
    chain = _chain(side)
    lengths = np.linalg.norm(j[:, chain[1:]] - j[:, chain[:-1]], axis=-1)       # (T, 3)
    own = _in_pelvis_frame(j, chain)
    mixed = own.copy()
    starts = [a + int(round((i + 0.5) * span / count - n / 2)) for i in range(count)]
    for s in starts:
        s = int(np.clip(s, a, b - n))
        w = np.ones(n)
        ramp = (1 - np.cos(np.linspace(0, np.pi, BLEND + 2)[1:-1])) / 2
        w[:BLEND], w[-BLEND:] = ramp, ramp[::-1]
        mixed[s:s + n] = (1 - w)[:, None, None] * own[s:s + n] + w[:, None, None] * kick
    mixed /= np.maximum(np.linalg.norm(mixed, axis=-1, keepdims=True), 1e-9)
    yaw = facing_angle(j)
    world = np.einsum("tij,tbj->tbi", np.stack([yaw_matrix(y) for y in yaw]), mixed)
    out = j.copy()
    for k in range(1, len(chain)):        # only the edited frames are rebuilt (bit for bit outside)
        out[a:b, chain[k]] = out[a:b, chain[k - 1]] + lengths[a:b, k - 1, None] * world[a:b, k - 1]
    moved = np.linalg.norm(out - j, axis=-1)
    leg = np.isin(np.arange(sk.NUM_JOINTS), chain)
    entry = {"generator": "captured_kick", "part": part or f"{side}_leg", "leg": f"{side}_leg",
             "prompt": prompt.strip(), "frames": [a, b], "kicks": count,
             "kick_frames": [int(np.clip(s, a, b - n)) + n // 2 for s in starts],
             "untouched_change_cm": round(float(moved[:, ~leg].mean() * 100), 3),
             "edited_change_cm": round(float(moved[a:b][:, leg].mean() * 100), 3)}
    return out, entry
