"""A digest of a motion's frames as a client holds them, so the studio can tell at `done`
whether its copy of the streamed frames is the stored motion, and which frames differ.

Each coordinate is taken as the stream and `GET /api/motions/{id}` carry it (float32 rounded
to 0.1 mm) and as an integer number of 0.1 mm (`round(x * 10000)`, exact for both sides: a
browser's Float32Array of the value gives the same integer). Per frame, 32-bit FNV-1a over
those integers as words, person by person, joint by joint, x y z: 8 hex digits. The motion's
digest is the same hash over the frames' digests. `frontend/src/api/digest.ts` is the
browser's copy; `tests/api/test_replace.py` checks both give the same values. `GET
/api/motions/{id}` carries the stored motion's digests too."""

from __future__ import annotations

import numpy as np

OFFSET, PRIME, MASK = 0x811C9DC5, 0x01000193, 0xFFFFFFFF


def _fnv(words: np.ndarray) -> np.ndarray:
    """FNV-1a over the last axis of uint32 words, one hash per row."""
    h = np.full(words.shape[0], OFFSET, dtype=np.uint64)
    for k in range(words.shape[1]):
        h = ((h ^ words[:, k]) * PRIME) & MASK
    return h


def frame_digests(people) -> list[str]:
    """One digest per frame of `people` (P arrays of (T, 22, 3))."""
    arr = np.stack([np.asarray(p, dtype=np.float32) for p in people]).astype(np.float64)
    q = np.rint(np.round(arr, 4) * 10000).astype(np.int64)          # (P, T, 22, 3)
    words = (np.moveaxis(q, 1, 0).reshape(q.shape[1], -1) & MASK).astype(np.uint64)
    return [f"{int(h):08x}" for h in _fnv(words)]


def motion_digest(frames: list[str]) -> str:
    """The motion's digest from its frames' digests."""
    words = np.array([[int(d, 16) for d in frames]], dtype=np.uint64)
    return f"{int(_fnv(words)[0]):08x}"
