"""What the job stream has carried so far, frame by frame, so that every change the pipeline
makes to frames already streamed goes out again as a replacement, with its cause.

    sent = SentFrames(on_frames, on_replace)
    source.fill(b, sent)                           # first frames: on_frames(start, chunk)
    pair_pass.resolve_segment(…, sent.by("pair_pass", seg.index))
    sent.sync(people, "correction", segment=i)     # whatever differs from what was sent

A chunk whose frames were all sent before goes to `on_replace(start, chunk, cause, segment)`;
frames never sent go to `on_frames`. Frames are compared as the stream carries them (float32
rounded to 0.1 mm), so a change too small to reach a client is not sent."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from interplay.motion.skeleton import NUM_JOINTS

OnFrames = Callable[[int, list[np.ndarray]], None]
OnReplace = Callable[[int, list[np.ndarray], str, "int | None"], None]
CHUNK = 40
DECIMALS = 4      # as pipeline.motion_json.joints_list


def wire(people) -> np.ndarray:
    """Frames as a client receives them: float32 rounded to 0.1 mm, (P, n, 22, 3)."""
    arr = np.stack([np.asarray(p, dtype=np.float32) for p in people]).astype(np.float64)
    return np.round(arr, DECIMALS)


def runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """[a, b) runs of True in a 1-D boolean mask."""
    edges = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    return list(zip(np.nonzero(edges == 1)[0].tolist(), np.nonzero(edges == -1)[0].tolist()))


class SentFrames:
    def __init__(self, on_frames: OnFrames, on_replace: OnReplace | None = None):
        self.on_frames, self.on_replace = on_frames, on_replace
        self.frames: np.ndarray | None = None      # (P, T, 22, 3) as sent
        self.have = np.zeros(0, dtype=bool)

    def __call__(self, start: int, chunk: list[np.ndarray]) -> None:
        self.send(start, chunk)

    def by(self, cause: str, segment: int | None = None) -> OnFrames:
        """An on_frames whose re-sent frames name `cause` (and the segment)."""
        return lambda start, chunk: self.send(start, chunk, cause, segment)

    def _grow(self, persons: int, end: int) -> None:
        if self.frames is None:
            self.frames = np.zeros((persons, 0, NUM_JOINTS, 3))
        grow = end - self.frames.shape[1]
        if grow > 0:
            self.frames = np.concatenate(
                [self.frames, np.zeros((persons, grow, NUM_JOINTS, 3))], axis=1)
            self.have = np.concatenate([self.have, np.zeros(grow, dtype=bool)])

    def send(self, start: int, chunk: list[np.ndarray], cause: str | None = None,
             segment: int | None = None) -> None:
        n = len(chunk[0])
        if n == 0:
            return
        start = int(start)
        self._grow(len(chunk), start + n)
        assert self.frames is not None
        old = self.have[start:start + n].copy()
        self.frames[:, start:start + n] = wire(chunk)
        self.have[start:start + n] = True
        if self.on_replace is None or not old.any():
            self.on_frames(start, chunk)
            return
        for a, b in runs(old):
            self.on_replace(start + a, [c[a:b] for c in chunk], cause or "sync", segment)
        for a, b in runs(~old):
            self.on_frames(start + a, [c[a:b] for c in chunk])

    def changed(self, people) -> np.ndarray:
        """Per frame of `people` (P arrays of (n, 22, 3)): sent before and different now."""
        now = wire(people)
        n = min(now.shape[1], len(self.have))
        out = np.zeros(now.shape[1], dtype=bool)
        if n and self.frames is not None:
            out[:n] = self.have[:n] & np.any(now[:, :n] != self.frames[:, :n], axis=(0, 2, 3))
        return out

    def sync(self, people, cause: str, segment: int | None = None) -> int:
        """Send every frame of `people` that differs from what was sent, or was never sent
        (a re-drawn stream may be ahead of what was streamed), in runs of at most CHUNK
        frames; how many frames."""
        changed = self.changed(people)
        n = len(changed)
        unsent = np.ones(n, dtype=bool)
        unsent[:min(n, len(self.have))] = ~self.have[:n]
        changed |= unsent
        for a, b in runs(changed):
            for s in range(a, b, CHUNK):
                e = min(b, s + CHUNK)
                self.send(s, [np.asarray(p)[s:e] for p in people], cause, segment)
        return int(changed.sum())
