"""Training data of the pair evaluator: pair windows of a split (both role orders, mirrored;
kept in world coordinates so a broken pair can be assembled from two windows), their
normalised features, interaction kinds and texts, and broken pairs.

Kinds: the composed clips' meta["kind"] (handshake, hug, push, wave, high_five,
walk_side_by_side) and "salsa" for the captured pairs. A window's text is a random prompt of its
kind among the split's prompts ("two people shake hands" and "two people greet each other
with a handshake" both describe a handshake window); windows of one kind are not negatives of
each other's texts.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.pair.windows import pair_windows
from interplay.review.pair_evaluator import PAIR_FEATURE_DIM, pair_features


def kind_of(clip) -> str:
    if clip.synthetic:
        return str(clip.meta.get("kind", clip.label))
    return "salsa" if clip.id.startswith("salsa") else clip.label


@dataclass
class PairSet:
    joints: np.ndarray       # (N, 2, L, 22, 3) float32, world frame (not canonicalised)
    features: np.ndarray     # (N, L, 293) float16, normalised
    kind: np.ndarray         # (N,) int index into kinds
    kinds: list[str]
    prompts: dict[str, list[str]]   # kind → the split's prompts of that kind
    later: np.ndarray        # (N, K) index of the same clip/role/mirror window k+1 strides on (-1: none)

    def __len__(self) -> int:
        return len(self.kind)


def raw_features(joints: np.ndarray) -> np.ndarray:
    """(N, L, 293) float32 pair features of world windows (N, 2, L, 22, 3)."""
    if not len(joints):
        return np.zeros((0, joints.shape[2], PAIR_FEATURE_DIM), np.float32)
    return np.stack([pair_features(w) for w in joints])


def build_set(clips, split: str, window: int, stride: int, mirror: bool = True,
              normalizer: tuple[np.ndarray, np.ndarray] | None = None,
              kinds: list[str] | None = None, max_shift: int = 6) -> tuple[PairSet, tuple]:
    """Windows of the split's two-person clips and the (mean, std) normaliser (fitted here on
    these windows when not given)."""
    clips = [c for c in clips if c.split == split and len(c.people) == 2]
    w = pair_windows(clips, window, stride, roles="both", mirror=mirror, canonical=False)
    by_id = {c.id: c for c in clips}
    names = [kind_of(by_id[i]) for i in w.clip_ids]
    kinds = kinds or sorted(set(names))
    prompts: dict[str, list[str]] = {k: [] for k in kinds}
    for c in clips:
        if c.prompt not in prompts.setdefault(kind_of(c), []):
            prompts[kind_of(c)].append(c.prompt)
    raw = raw_features(w.joints)
    if normalizer is None:
        flat = raw.reshape(-1, PAIR_FEATURE_DIM).astype(np.float64)
        normalizer = (flat.mean(0).astype(np.float32), np.maximum(flat.std(0), 1e-3).astype(np.float32))
    feats = ((raw - normalizer[0]) / normalizer[1]).astype(np.float16)
    # later[i, k-1]: the window k strides after i in the same clip, role order and mirroring
    key = {(cid, s, sw, m): i for i, (cid, s, sw, m)
           in enumerate(zip(w.clip_ids, w.starts, w.swapped, w.mirrored))}
    later = np.full((len(w), max_shift), -1, dtype=np.int64)
    for i, (cid, s, sw, m) in enumerate(zip(w.clip_ids, w.starts, w.swapped, w.mirrored)):
        for k in range(1, max_shift + 1):
            later[i, k - 1] = key.get((cid, s + k * stride, sw, m), -1)
    kind = np.array([kinds.index(n) if n in kinds else -1 for n in names], dtype=np.int64)
    return PairSet(w.joints, feats, kind, kinds, prompts, later), normalizer


def displaced(window: np.ndarray, distance: float, angle: float) -> np.ndarray:
    """The pair window (2, L, 22, 3) with the second person moved `distance` m horizontally."""
    out = np.array(window, dtype=np.float64)
    out[1, ..., 0] += distance * np.sin(angle)
    out[1, ..., 2] += distance * np.cos(angle)
    return out


def time_shifted(data: PairSet, i: int, k: int) -> np.ndarray | None:
    """Window i with its second person taken k strides later (None when the clip ends)."""
    j = data.later[i, k - 1]
    if j < 0:
        return None
    return np.stack([data.joints[i, 0], data.joints[j, 1]]).astype(np.float64)


def swapped_partner(data: PairSet, i: int, j: int) -> np.ndarray:
    """Window i's first person with window j's second person, placed where i's second person
    starts (pelvis on the floor plane at the first frame)."""
    other = np.array(data.joints[j, 1], dtype=np.float64)
    delta = data.joints[i, 1, 0, sk.PELVIS] - other[0, sk.PELVIS]
    other[..., [0, 2]] += delta[[0, 2]]
    return np.stack([data.joints[i, 0], other])


def broken_batch(data: PairSet, idx: np.ndarray, rng: np.random.Generator, displace: tuple,
                 shift_strides: tuple[int, int]) -> np.ndarray:
    """Broken world windows (K, 2, L, 22, 3) from windows idx: each displaced, time-shifted
    (when the clip goes on long enough, else displaced) or given another kind's partner, in
    turn."""
    out = []
    for n, i in enumerate(idx):
        mode = n % 3
        w = None
        if mode == 1:
            w = time_shifted(data, int(i), int(rng.integers(shift_strides[0], shift_strides[1] + 1)))
        elif mode == 2:
            others = np.flatnonzero(data.kind != data.kind[i])
            w = swapped_partner(data, int(i), int(rng.choice(others))) if len(others) else None
        if w is None:
            w = displaced(data.joints[i], rng.uniform(*displace), rng.uniform(0, 2 * np.pi))
        out.append(w)
    return np.stack(out)
