"""BVH (Biovision hierarchy) import and export, numpy only: the parsed file (`Bvh`) and
`read_bvh` here, the text's parsing in `bvh_text.py`, writing in `bvh_write.py` (its names are
re-exported here, so callers import both from this module).

Reading accepts any hierarchy: one or more ROOTs, JOINTs with any number of channels in any
order (position channels on non-root joints too), End Sites, tabs/spaces, CRLF line ends.
A joint's local transform is T(translation) · R(rotation channels, in file order), with the
translation being its OFFSET, or — for the axes it has position channels for — the channel
values (position channels *replace* the offset, as Blender's importer reads them; every file
in our data and every file we write has a zero ROOT offset and no position channels below
the root, where all readers agree).

Writing (`bvh_write.write_bvh`) targets our 22-joint skeleton, with presets: frame rate,
units, up axis and joint names. `smpl22_positions` reads our joints back from a file we wrote.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh_text import (
    channel,
    digits,
    parse_hierarchy,
    read_text,
    section,
    words_after,
)
from interplay.motion.formats.bvh_write import UP_AXES as UP_AXES
from interplay.motion.formats.bvh_write import Z_UP as Z_UP
from interplay.motion.formats.bvh_write import check_preset as check_preset
from interplay.motion.formats.bvh_write import write_bvh as write_bvh
from interplay.motion.formats.presets import FPS_CHOICES as FPS_CHOICES
from interplay.motion.formats.presets import MIXAMO_NAMES as MIXAMO_NAMES
from interplay.motion.formats.presets import MIXAMO_PREFIX
from interplay.motion.formats.presets import NAMINGS as NAMINGS
from interplay.motion.formats.presets import UNITS as UNITS
from interplay.motion.formats.presets import joint_names as joint_names
from interplay.motion.kinematics import forward_kinematics
from interplay.motion.rotations import axis_rotation, euler_to_matrix


@dataclass(frozen=True, eq=False)
class Bvh:
    """A parsed BVH file. Joints are in file (depth-first) order, so parents come first."""
    names: tuple[str, ...]
    parents: tuple[int, ...]                        # -1 for a ROOT
    offsets: np.ndarray                             # (J, 3) OFFSET of each joint, file units
    channels: tuple[tuple[str, ...], ...]           # per joint, e.g. ("Zrotation", "Xrotation", …)
    end_sites: tuple[tuple[int, np.ndarray], ...]   # (parent joint, OFFSET (3,)) per End Site
    frame_time: float                               # seconds per frame, as the header says
    motion: np.ndarray                              # (T, C) channel values, C = total channels

    @property
    def fps(self) -> float:
        return 1.0 / self.frame_time

    @property
    def num_frames(self) -> int:
        return int(self.motion.shape[0])

    @property
    def end_site_names(self) -> tuple[str, ...]:
        """End Sites are unnamed in BVH; we call each "<parent>_end" (a second one "_end2" …)."""
        out: list[str] = []
        seen: dict[int, int] = {}
        for parent, _ in self.end_sites:
            n = seen[parent] = seen.get(parent, 0) + 1
            out.append(f"{self.names[parent]}_end" + (str(n) if n > 1 else ""))
        return tuple(out)

    def index(self, name: str) -> int:
        try:
            return self.names.index(name)
        except ValueError:
            raise ValueError(f"BVH has no joint {name!r}") from None

    @cached_property
    def _channel_columns(self) -> list[np.ndarray]:
        starts = np.cumsum([0] + [len(c) for c in self.channels])
        return [np.arange(starts[j], starts[j + 1]) for j in range(len(self.names))]

    def local_transforms(self) -> tuple[np.ndarray, np.ndarray]:
        """Local rotations (T, J, 3, 3) and translations (T, J, 3) of every joint."""
        t, n = self.num_frames, len(self.names)
        rot = np.tile(np.eye(3), (t, n, 1, 1))
        trans = np.tile(self.offsets, (t, 1, 1))
        # Group joints by rotation order so each group is one vectorised conversion.
        groups: dict[str, list[tuple[int, np.ndarray]]] = {}
        for j, (chans, cols) in enumerate(zip(self.channels, self._channel_columns)):
            order = ""
            rcols = []
            for c, col in zip(chans, cols):
                match = channel(c)
                assert match is not None                # parsing rejected any other channel
                axis, kind = match
                if kind.lower() == "position":
                    trans[:, j, "XYZ".index(axis.upper())] = self.motion[:, col]
                else:
                    order += axis.upper()
                    rcols.append(col)
            if order:
                groups.setdefault(order, []).append((j, np.array(rcols)))
        for order, members in groups.items():
            idx = np.array([j for j, _ in members])
            angles = np.deg2rad(self.motion[:, np.stack([c for _, c in members])])  # (T, n, k)
            if len(order) == 3:
                rot[:, idx] = euler_to_matrix(angles, order)
            else:  # fewer (or more) rotation channels: compose them in file order
                m = np.tile(np.eye(3), angles.shape[:2] + (1, 1))
                for k, axis in enumerate(order):
                    m = m @ axis_rotation(axis, angles[..., k])
                rot[:, idx] = m
        return rot, trans

    def positions(self, include_end_sites: bool = False) -> np.ndarray:
        """Global joint positions (T, J, 3) in file units (End Sites appended after the joints,
        in file order, when asked)."""
        rot, trans = self.local_transforms()
        t, n = rot.shape[:2]
        parents = list(self.parents)
        offsets = self.offsets.copy()
        if include_end_sites and self.end_sites:
            e = len(self.end_sites)
            parents += [p for p, _ in self.end_sites]
            offsets = np.concatenate([offsets, np.stack([o for _, o in self.end_sites])])
            rot = np.concatenate([rot, np.tile(np.eye(3), (t, e, 1, 1))], axis=1)
        # Shared FK with the static offsets (roots at the origin) …
        pos, glob = forward_kinematics(rot, np.zeros((t, 3)), offsets, parents)
        # … then each root's translation and each animated child translation, carried down
        # its subtree (FK is linear in the translations once rotations are fixed).
        moved = [j for j in range(n) if parents[j] < 0 or np.any(trans[:, j] != offsets[j])]
        if moved:
            below = _subtree_masks(parents)
            for j in moved:
                p = parents[j]
                delta = trans[:, j] if p < 0 else np.einsum("tij,tj->ti", glob[:, p], trans[:, j] - offsets[j])
                pos[:, below[j]] += delta[:, None]
        return pos

    def named_positions(self, include_end_sites: bool = True) -> dict[str, np.ndarray]:
        """{joint or End Site name: (T, 3)} in file units."""
        pos = self.positions(include_end_sites)
        names = self.names + (self.end_site_names if include_end_sites else ())
        return {name: pos[:, i] for i, name in enumerate(names)}


def _subtree_masks(parents: list[int]) -> np.ndarray:
    """(J, J) boolean: row j marks j and all its descendants (parents-first order)."""
    n = len(parents)
    mask = np.eye(n, dtype=bool)
    for i in range(n):
        p = parents[i]
        while p >= 0:
            mask[p, i] = True
            p = parents[p]
    return mask



def read_bvh(text_or_path: str | Path) -> Bvh:
    """Parse BVH text (or a path to a .bvh file)."""
    text = read_text(text_or_path)
    head, motion = section(text, "HIERARCHY"), section(text, "MOTION")
    if head is None or motion is None or motion[0] < head[1]:
        raise ValueError("not a BVH file: expected a HIERARCHY section followed by MOTION")
    names, parents, offsets, channels, end_sites = parse_hierarchy(text[head[1]:motion[0]].split())
    after = words_after(text[motion[1]:], "Frames:")
    count = digits(after or "")
    after = words_after(after[len(count):], "Frame", "Time:") if after and count else None
    if not after:
        raise ValueError("MOTION must start with 'Frames: N' and 'Frame Time: seconds'")
    value = after.split(maxsplit=1)[0]
    n_frames, frame_time, data = int(count), float(value), after[len(value):]
    if not frame_time > 0:
        raise ValueError(f"Frame Time must be positive, got {frame_time}")
    width = sum(len(c) for c in channels)
    try:
        values = np.array(data.split(), dtype=np.float64)
    except ValueError:
        raise ValueError("MOTION data holds something that is not a number") from None
    if values.size < n_frames * width:
        raise ValueError(f"BVH says {n_frames} frames of {width} channels but holds "
                         f"{values.size} values")
    return Bvh(names=tuple(names), parents=tuple(parents), offsets=np.array(offsets).reshape(-1, 3),
               channels=tuple(channels),
               end_sites=tuple((p, o) for p, o in end_sites), frame_time=frame_time,
               motion=values[:n_frames * width].reshape(n_frames, width))


def smpl22_positions(bvh: Bvh) -> np.ndarray:
    """Joints (T, 22, 3) in SMPL order, file units and axes, from a BVH whose joints carry
    our names, SMPL's or Mixamo-style (one we wrote)."""
    pos = bvh.positions()
    if MIXAMO_NAMES[0] in bvh.names:
        return pos[:, [bvh.index(n) for n in MIXAMO_NAMES]]
    if "Hips" in bvh.names:                       # written before the mixamorig: prefix
        return pos[:, [bvh.index(n.removeprefix(MIXAMO_PREFIX)) for n in MIXAMO_NAMES]]
    return pos[:, [bvh.index(n) for n in sk.JOINT_NAMES]]

