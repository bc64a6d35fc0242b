"""Long and multi-segment SPAM motions: how tokens are split into pieces the transformers can
take (≤ max_tokens each) with blended transitions between them, and how the pieces' features
become one continuous stream of joints.

Everything is counted in tokens (4 frames): the motion has ⌈frames/4⌉ tokens and only the end
is trimmed, so every piece and transition starts on a token boundary. A transition of t tokens
between two pieces takes ⌊t/2⌋ tokens from the piece before and the rest from the one after,
so the total stays exactly the requested length.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterator

import numpy as np

from interplay.motion import features as F
from interplay.motion.footlock import ground, lock_feet

TRANSITION = 4   # tokens (0.8 s) of blended transition between pieces, at most
CHUNK = 40       # frames per yielded chunk at most (the generator's streaming unit)


@dataclass(frozen=True)
class Piece:
    segment: int        # which input segment's text it uses
    tokens: int         # tokens generated for the piece itself
    transition: int     # tokens of the transition decoded before it (0 for the first)


def layout(frames: list[int], max_tokens: int, downsample: int = 4,
           transition: int = TRANSITION) -> list[Piece]:
    """Pieces for consecutive segments of `frames` each: segment boundaries rounded to tokens,
    segments longer than max_tokens split evenly, transitions between every two pieces."""
    if not frames or any(int(f) < 1 for f in frames):
        raise ValueError(f"every segment needs at least one frame, got {frames}")
    total = -(-sum(int(f) for f in frames) // downsample)
    bounds = np.round(np.cumsum(frames) / downsample).astype(int)
    bounds[-1] = total
    sizes, owners, start = [], [], 0
    for seg, end in enumerate(bounds):
        n = int(end) - start
        if n <= 0:                      # a segment shorter than half a token: folded away
            continue
        k = -(-n // max_tokens)
        for part in np.diff(np.round(np.linspace(0, n, k + 1)).astype(int)):
            sizes.append(int(part))
            owners.append(seg)
        start = int(end)
    trans = [min(transition, a // 2, b // 2) for a, b in zip(sizes, sizes[1:])]
    own = list(sizes)
    for j, t in enumerate(trans):
        own[j] -= t // 2
        own[j + 1] -= t - t // 2
    return [Piece(segment=owners[j], tokens=own[j], transition=trans[j - 1] if j else 0)
            for j in range(len(sizes))]


class Assembler:
    """Turns consecutive feature stretches (n, 239) into joints on the rest skeleton (or
    `offsets`), the first frame at the origin facing +Z, each stretch continuing the root path
    of the one before; yields (start frame, joints ≤ CHUNK frames) and stops at `total`.
    lock: each stretch is put on the floor (`footlock.ground`) and its planted feet are held in
    place (`footlock.lock_feet`)."""

    def __init__(self, total: int, offsets: np.ndarray | None = None, lock: bool = False):
        self.total, self.offsets, self.lock = int(total), offsets, lock
        self.done = 0
        self._last: tuple[np.ndarray, np.ndarray] | None = None   # (features row, (x, z, heading))

    def add(self, feats: np.ndarray) -> Iterator[tuple[int, np.ndarray]]:
        feats = np.asarray(feats, dtype=np.float64)
        take = min(len(feats), self.total - self.done)
        if take <= 0:
            return
        if self._last is None:
            # The model's pelvis rotation may keep a little yaw of its own: start the heading
            # so that the first decoded pose faces +Z exactly.
            start = np.array([0.0, 0.0, -F.heading(F.decode(feats[:1], self.offsets))[0]])
            rows, skip = feats, 0
        else:
            row, start = self._last
            rows, skip = np.concatenate([row[None], feats]), 1
        joints = F.decode(rows, self.offsets, start)
        # The integrated heading at the last frame (decode's own sum), for the next stretch.
        theta = start[2] + rows[:-1, F.SLICES["root_angvel"]].sum()
        end = joints[-1, 0]
        self._last = (rows[-1], np.array([end[0], end[2], theta]))
        if self.lock:      # on the floor, planted feet held (both fade out at the ends)
            joints = lock_feet(ground(joints, fade_start=skip == 1))
        joints = joints[skip:skip + take]
        for a in range(0, take, CHUNK):
            yield self.done + a, joints[a:a + CHUNK]
        self.done += take
