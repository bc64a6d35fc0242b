"""Stitching retrieved capture pieces into one continuous motion per person.

Each next piece is turned about Y and moved on the ground so that its start continues the
motion so far (its first pelvis XZ one step ahead of the last output pelvis, its heading
equal to the last output heading), then cross-faded over ~0.5 s with the previous piece's own
continuation in its capture (root-relative pose and root path blended separately), then
re-posed by IK → FK on the person's fixed bones (`kinematics.fit_to_skeleton`), so bones keep
their lengths across pieces from different performers.

Pieces of a two-person capture move as one: they are aligned by the pair's frame (midpoint of
the pelvises, direction from person 0 to person 1), so the couple keeps its spacing.
Shapes: joints (T, 22, 3) float, metres, Y up, 20 fps.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_direction, fit_to_skeleton
from interplay.motion.rotations import yaw_matrix

FADE = 10      # cross-fade frames (0.5 s)
HEADING = 5    # frames averaged for a heading (a single frame sways with the gait)


@dataclass
class Piece:
    """Frames of one person cut from a capture: `core` is what plays; `tail` is the capture's
    own continuation after the core (≤ FADE frames, maybe empty), used only to cross-fade into
    whatever follows."""
    core: np.ndarray      # (n, 22, 3)
    tail: np.ndarray      # (k, 22, 3), k ≤ FADE
    offsets: np.ndarray   # (22, 3) rest offsets of the captured performer


def _angle(v: np.ndarray) -> float:
    """Yaw of a ground vector (x, z): 0 towards +Z, positive towards +X (as facing_angle)."""
    return float(np.arctan2(v[0], v[-1]))


def heading(joints: np.ndarray) -> np.ndarray:
    """Mean facing (3,) over a few frames (XZ unit vector, y = 0)."""
    f = facing_direction(joints).mean(axis=0)
    f[1] = 0.0
    n = np.linalg.norm(f)
    return f / n if n > 1e-6 else np.array([0.0, 0.0, 1.0])


def pair_frame(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(midpoint of the two pelvises on the first frame, mean direction a→b on the ground) of
    two people's frames (n, 22, 3); the direction falls back to a's facing when they overlap."""
    mid = (a[0, sk.PELVIS] + b[0, sk.PELVIS]) / 2
    d = (b[:, sk.PELVIS] - a[:, sk.PELVIS]).mean(axis=0)
    d[1] = 0.0
    n = np.linalg.norm(d)
    return mid, (d / n if n > 0.1 else heading(a))


def rigid_yaw(joints: np.ndarray, yaw: float, pivot: np.ndarray, target: np.ndarray) -> np.ndarray:
    """Turn joints (..., 3) by yaw about the vertical through pivot, then move pivot onto
    target on the ground (heights unchanged)."""
    rot = yaw_matrix(yaw)
    p = np.array([pivot[0], 0.0, pivot[2]])
    t = np.array([target[0], 0.0, target[2]])
    return (joints - p) @ rot.T + t


def leg_length(offsets: np.ndarray) -> float:
    """Thigh + shin length (mean of both legs) of a performer's rest offsets."""
    j = sk.JOINT_INDEX
    return float(np.mean([np.linalg.norm(offsets[j[f"{side}_knee"]]) + np.linalg.norm(offsets[j[f"{side}_ankle"]])
                          for side in ("left", "right")]))


def scale_root(piece: Piece, offsets: np.ndarray) -> Piece:
    """Scale a piece's root path to a performer with other legs (ratio of leg lengths), so
    strides and pelvis height suit the bones it will be refit to."""
    s = leg_length(offsets) / max(leg_length(piece.offsets), 1e-6)
    if abs(s - 1.0) < 1e-6:
        return piece

    def scaled(x: np.ndarray) -> np.ndarray:
        root = x[:, sk.PELVIS:sk.PELVIS + 1]
        return x - root + root * s
    return Piece(scaled(piece.core), scaled(piece.tail), piece.offsets)


def refit(joints: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """IK → FK onto fixed bones, then each frame raised or lowered so its lowest joint stays
    where the capture had it (other bone lengths would otherwise sink or lift the feet)."""
    if len(joints) == 0:
        return joints
    out, _ = fit_to_skeleton(joints, offsets)
    out[..., 1] += (joints[..., 1].min(axis=1) - out[..., 1].min(axis=1))[:, None]
    return out


def _continuation(prev: np.ndarray, tail: np.ndarray, n: int) -> np.ndarray:
    """n frames continuing prev (the last output frames): the capture's own tail, then its last
    pose held with the pelvis gliding on at its last ground velocity. (Tried instead: moving
    the held pose the way the new piece moves; it gave rougher pelvis paths at the seams.)"""
    tail = tail[:n]
    if len(tail) == n:
        return tail
    src = np.concatenate([prev[-2:], tail])
    vel = src[-1, sk.PELVIS] - src[-2, sk.PELVIS]
    vel[1] = 0.0
    steps = np.arange(1, n - len(tail) + 1)[:, None, None]
    held = src[-1][None] + steps * vel
    return np.concatenate([tail, held])


def crossfade(cont: np.ndarray, new: np.ndarray, fade: int = FADE) -> np.ndarray:
    """Blend the first `fade` frames of new (n, 22, 3) from cont (the old motion's
    continuation, same frames) to new: pelvis path and root-relative pose separately."""
    n = min(fade, len(new))
    if n == 0:
        return new
    out = new.copy()
    x = (np.arange(1, n + 1) / (n + 1))[:, None, None]
    w = x * x * (3 - 2 * x)                                     # smoothstep, (n, 1, 1)
    a, b = cont[:n], new[:n]
    root = (1 - w) * a[:, :1] + w * b[:, :1]                    # (n, 1, 3)
    rel = (1 - w) * (a - a[:, :1]) + w * (b - b[:, :1])         # (n, 22, 3)
    out[:n] = root + rel
    return out


class Stitcher:
    """Appends pieces person by person; keeps, per person, the output so far (last frames),
    the bones everything is refit to, and the aligned continuation of the last piece."""

    def __init__(self, persons: int):
        self.persons = persons
        self.offsets: list[np.ndarray | None] = [None] * persons
        self.last: list[np.ndarray | None] = [None] * persons   # last ≤ HEADING output frames
        self.tail: list[np.ndarray | None] = [None] * persons   # aligned continuation

    def started(self, person: int) -> bool:
        return self.last[person] is not None

    def _target(self, person: int) -> tuple[np.ndarray, np.ndarray]:
        """Where the next frame's pelvis goes (one step ahead) and the current heading."""
        last = self.last[person]
        assert last is not None, "only a started person has a target"
        step = last[-1, sk.PELVIS] - last[-2, sk.PELVIS] if len(last) > 1 else np.zeros(3)
        return last[-1, sk.PELVIS] + step, heading(last)

    def _finish(self, person: int, piece: Piece) -> np.ndarray:
        """Cross-fade (when continuing), refit to the person's bones, remember the end."""
        off = self.offsets[person]
        if off is None:
            off = self.offsets[person] = piece.offsets.astype(np.float64)
        core = piece.core.astype(np.float64)
        last, prev_tail = self.last[person], self.tail[person]
        if last is not None and prev_tail is not None:
            cont = _continuation(last, prev_tail, min(FADE, len(core)))
            core = crossfade(cont, core)
        out = refit(core, off)
        tail = refit(piece.tail.astype(np.float64), off)
        self.last[person] = np.concatenate([last, out])[-HEADING:] \
            if last is not None else out[-HEADING:]
        self.tail[person] = tail
        return out.astype(np.float32)

    def _prepared(self, person: int, piece: Piece) -> Piece:
        off = self.offsets[person]
        return scale_root(piece, off) if off is not None else piece

    def add_single(self, person: int, piece: Piece,
                   start: tuple[np.ndarray, float] | None = None) -> np.ndarray:
        """Append one person's piece; `start` = (pelvis XZ position, facing yaw) places the
        very first piece (default: origin, facing +Z). Returns the new output frames."""
        piece = self._prepared(person, piece)
        first = piece.core[:HEADING]
        if self.started(person):
            target, h = self._target(person)
            yaw = _angle(h) - _angle(heading(first))
        else:
            pos, facing = start if start is not None else (np.zeros(3), 0.0)
            target, yaw = np.asarray(pos, dtype=np.float64), facing - _angle(heading(first))
        pivot = piece.core[0, sk.PELVIS]
        moved = Piece(rigid_yaw(piece.core, yaw, pivot, target),
                      rigid_yaw(piece.tail, yaw, pivot, target), piece.offsets)
        return self._finish(person, moved)

    def hold(self, person: int, n: int) -> np.ndarray:
        """n frames of the person's last output pose, kept still (a posture reached and held:
        sat down, lying, the end of a counted action); what follows cross-fades from it."""
        last = self.last[person]
        if last is None:
            raise ValueError("only a started person can hold a pose")
        held = np.repeat(last[-1:], n, axis=0)
        self.last[person] = np.concatenate([last, held])[-HEADING:]
        self.tail[person] = np.repeat(last[-1:], FADE, axis=0)
        return held.astype(np.float32)

    def add_pair(self, pieces: list[Piece]) -> list[np.ndarray]:
        """Append a two-person piece (both people of one capture, same frames), moved as one."""
        pieces = [self._prepared(i, p) for i, p in enumerate(pieces)]
        a, b = (p.core for p in pieces)
        mid, d = pair_frame(a[:HEADING], b[:HEADING])
        last_a, last_b = self.last[0], self.last[1]
        if last_a is not None and last_b is not None:
            (ta, _), (tb, _) = self._target(0), self._target(1)
            _, d_out = pair_frame(last_a, last_b)
            target, yaw = (ta + tb) / 2, _angle(d_out) - _angle(d)
        else:
            # First piece: person 0's pelvis at the origin facing +Z (the canonical frame).
            yaw = -_angle(heading(a[:HEADING]))
            target = rigid_yaw(mid, yaw, a[0, sk.PELVIS], np.zeros(3))
        return [self._finish(i, Piece(rigid_yaw(p.core, yaw, mid, target),
                                      rigid_yaw(p.tail, yaw, mid, target), p.offsets))
                for i, p in enumerate(pieces)]
