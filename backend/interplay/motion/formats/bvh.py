"""BVH (Biovision hierarchy) import and export, numpy only.

Reading accepts any hierarchy: one or more ROOTs, JOINTs with any number of channels in any
order (position channels on non-root joints too), End Sites, tabs/spaces, CRLF line ends.
A joint's local transform is T(translation) · R(rotation channels, in file order), with the
translation being its OFFSET, or — for the axes it has position channels for — the channel
values (position channels *replace* the offset, as Blender's importer reads them; every file
in our data and every file we write has a zero ROOT offset and no position channels below
the root, where all readers agree).

Writing targets our 22-joint skeleton: the rotations of `rig.solve_rig` (continuous, knees
and elbows as hinges) → local Euler angles, a standard HIERARCHY/MOTION text that Blender and
three.js's BVHLoader read, with presets: frame rate (resampled: root positions linearly,
rotations by slerp), units (m or cm), up axis (Y, or Z with the character facing -Y as in
Blender) and joint names (SMPL's, or Mixamo-style for rigs that map bones by name).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.channels import channel_order
from interplay.motion.formats.presets import (
    FPS_CHOICES as FPS_CHOICES,
)
from interplay.motion.formats.presets import (
    MIXAMO_NAMES,
    MIXAMO_PREFIX,
    UNITS,
    bone_axes,
    check_fps_units_names,
    export_rigs,
    joint_names,
    on_bone_axes,
)
from interplay.motion.formats.presets import (
    NAMINGS as NAMINGS,
)
from interplay.motion.kinematics import forward_kinematics
from interplay.motion.rig import end_sites
from interplay.motion.rotations import axis_rotation, euler_to_matrix, matrix_to_euler


def _channel(name: str) -> tuple[str, str] | None:
    """A channel name's (axis, kind): "Xposition" → ("X", "position"), any case; None if not one."""
    axis, kind = name[:1].upper(), name[1:].lower()
    return (axis, kind) if axis in ("X", "Y", "Z") and kind in ("position", "rotation") else None


def _section(text: str, word: str) -> tuple[int, int] | None:
    """(start, end) of the first line that holds only `word` (any case, spaces around it)."""
    at = 0
    for line in text.split("\n"):
        if line.strip().upper() == word:
            return at, at + len(line)
        at += len(line) + 1
    return None


def _after(text: str, *words: str) -> str | None:
    """The text after `words` at its start (any case; spaces before the first, at least one
    between the others, any after the last), or None when it does not start so."""
    for i, word in enumerate(words):
        if i and not text[:1].isspace():
            return None
        text = text.lstrip()
        if text[:len(word)].lower() != word.lower():
            return None
        text = text[len(word):]
    return text.lstrip()


def _digits(text: str) -> str:
    """The digits `text` starts with."""
    return text[:next((i for i, c in enumerate(text) if not c.isdecimal()), len(text))]


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
                match = _channel(c)
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


def _read_text(text_or_path: str | Path) -> str:
    if isinstance(text_or_path, Path):
        return text_or_path.read_text()
    if "HIERARCHY" in text_or_path[:256].upper():
        return text_or_path
    path = Path(text_or_path)
    if not path.is_file():
        raise ValueError(f"not BVH text and no such file: {text_or_path[:80]!r}")
    return path.read_text()


def _parse_hierarchy(tokens: list[str]):
    names: list[str] = []
    parents: list[int] = []
    offsets: list[np.ndarray] = []
    channels: list[tuple[str, ...]] = []
    end_sites: list[list] = []             # [parent joint, offset]
    stack: list[tuple[str, int]] = []      # open blocks: ("joint", j) or ("end", e)
    pending: tuple[str, int] | None = None
    i = 0
    while i < len(tokens):
        tok, key = tokens[i], tokens[i].upper()
        if key in ("ROOT", "JOINT"):
            if i + 1 >= len(tokens):
                raise ValueError(f"{tok} without a name")
            joints_open = [j for kind, j in stack if kind == "joint"]
            if key == "JOINT" and not joints_open:
                raise ValueError(f"JOINT {tokens[i + 1]} outside any ROOT")
            if key == "ROOT" and stack:
                raise ValueError(f"ROOT {tokens[i + 1]} inside another joint")
            names.append(tokens[i + 1])
            parents.append(joints_open[-1] if key == "JOINT" else -1)
            offsets.append(np.zeros(3))
            channels.append(())
            pending = ("joint", len(names) - 1)
            i += 2
        elif key == "END":
            if i + 1 >= len(tokens) or tokens[i + 1].upper() != "SITE" or not stack or stack[-1][0] != "joint":
                raise ValueError("End Site must follow 'End' and sit inside a joint")
            end_sites.append([stack[-1][1], np.zeros(3)])
            pending = ("end", len(end_sites) - 1)
            i += 2
        elif tok == "{":
            if pending is None:
                raise ValueError("'{' without a ROOT/JOINT/End Site before it")
            stack.append(pending)
            pending = None
            i += 1
        elif tok == "}":
            if not stack:
                raise ValueError("unbalanced '}' in HIERARCHY")
            stack.pop()
            i += 1
        elif key == "OFFSET":
            if not stack:
                raise ValueError("OFFSET outside a joint")
            try:
                value = np.array([float(v) for v in tokens[i + 1:i + 4]])
            except ValueError:
                raise ValueError(f"bad OFFSET {tokens[i + 1:i + 4]}") from None
            if value.shape != (3,):
                raise ValueError("OFFSET needs three numbers")
            kind, k = stack[-1]
            if kind == "joint":
                offsets[k] = value
            else:
                end_sites[k][1] = value
            i += 4
        elif key == "CHANNELS":
            if not stack or stack[-1][0] != "joint":
                raise ValueError("CHANNELS outside a joint")
            try:
                count = int(tokens[i + 1])
            except (IndexError, ValueError):
                raise ValueError("CHANNELS needs a count") from None
            chans = tuple(tokens[i + 2:i + 2 + count])
            bad = [c for c in chans if not _channel(c)]
            if len(chans) != count or bad:
                raise ValueError(f"bad CHANNELS for {names[stack[-1][1]]}: {chans}")
            channels[stack[-1][1]] = chans
            i += 2 + count
        else:
            raise ValueError(f"unexpected token {tok!r} in HIERARCHY")
    if stack:
        raise ValueError("HIERARCHY ends with unclosed braces")
    if not names:
        raise ValueError("HIERARCHY has no ROOT")
    return names, parents, offsets, channels, end_sites


def read_bvh(text_or_path: str | Path) -> Bvh:
    """Parse BVH text (or a path to a .bvh file)."""
    text = _read_text(text_or_path)
    head, motion = _section(text, "HIERARCHY"), _section(text, "MOTION")
    if head is None or motion is None or motion[0] < head[1]:
        raise ValueError("not a BVH file: expected a HIERARCHY section followed by MOTION")
    names, parents, offsets, channels, end_sites = _parse_hierarchy(text[head[1]:motion[0]].split())
    after = _after(text[motion[1]:], "Frames:")
    count = _digits(after or "")
    after = _after(after[len(count):], "Frame", "Time:") if after and count else None
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


# Export presets (the CLI's flags and the API's query parameters offer these), shared with
# the GLB (`formats/presets.py`); the up axis is BVH's alone.
UP_AXES: tuple[str, ...] = ("y", "z")
# Y-up → Z-up: +90° about X, (x, y, z) → (x, -z, y): up +Y becomes +Z, forward +Z becomes
# -Y (Blender's front view looks along +Y at a character facing -Y).
Z_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def smpl22_positions(bvh: Bvh) -> np.ndarray:
    """Joints (T, 22, 3) in SMPL order, file units and axes, from a BVH whose joints carry
    our names, SMPL's or Mixamo-style (one we wrote)."""
    pos = bvh.positions()
    if MIXAMO_NAMES[0] in bvh.names:
        return pos[:, [bvh.index(n) for n in MIXAMO_NAMES]]
    if "Hips" in bvh.names:                       # written before the mixamorig: prefix
        return pos[:, [bvh.index(n.removeprefix(MIXAMO_PREFIX)) for n in MIXAMO_NAMES]]
    return pos[:, [bvh.index(n) for n in sk.JOINT_NAMES]]


def _fmt(values: np.ndarray, digits: int) -> str:
    # Round, then add 0.0 so that -0.0 prints as 0.
    return " ".join(f"{v:.{digits}f}" for v in np.round(values, digits) + 0.0)


def _write_joint(j: int, depth: int, offsets: np.ndarray, local: np.ndarray, ends: dict,
                 names: tuple[str, ...], up: str, lines: list[str], columns: list[np.ndarray]) -> None:
    """Append joint j's HIERARCHY block (with its subtree) to lines and its Euler angles
    (T, 3) in degrees to columns, in the same depth-first order."""
    name, tab = names[j], "\t" * depth
    order = channel_order(sk.JOINT_NAMES[j], local[:, j], up)
    rot_channels = " ".join(f"{a}rotation" for a in order)
    root = j == sk.PELVIS
    lines += [f"{tab}{'ROOT' if root else 'JOINT'} {name}", f"{tab}{{",
              f"{tab}\tOFFSET {_fmt(np.zeros(3) if root else offsets[j], 6)}",
              f"{tab}\tCHANNELS {'6 Xposition Yposition Zposition' if root else '3'} {rot_channels}"]
    # Unwrapping keeps each angle continuous over time (same rotations, smoother curves).
    columns.append(np.rad2deg(np.unwrap(matrix_to_euler(local[:, j], order), axis=0)))
    for c in sk.children(j):
        _write_joint(c, depth + 1, offsets, local, ends, names, up, lines, columns)
    if j in ends:
        lines += [f"{tab}\tEnd Site", f"{tab}\t{{", f"{tab}\t\tOFFSET {_fmt(ends[j], 6)}", f"{tab}\t}}"]
    lines.append(f"{tab}}}")


def check_preset(out_fps: float | None = None, units: str = "m", up: str = "y",
                 names: str = "smpl") -> None:
    """ValueError naming the choices when a BVH preset value is not one we write."""
    check_fps_units_names(out_fps, units, names)
    if up not in UP_AXES:
        raise ValueError(f"up axis must be one of {', '.join(UP_AXES)}, got {up!r}")


def write_bvh(joints: np.ndarray, fps: float = sk.FPS, offsets: np.ndarray | None = None, *,
              out_fps: float | None = None, units: str = "m", up: str = "y", names: str = "smpl",
              floor: float | None = None, leaves: Mapping[str, np.ndarray] | None = None) -> str:
    """One person's joints (T, 22, 3) (metres, Y up, `fps` frames a second) → BVH text: our 22
    joints as a standard hierarchy (6 channels on the root, 3 rotation channels elsewhere,
    End Sites at head, wrists and toes), rest pose = the offsets (fitted from the motion when
    not given), the rig of `presets.export_rigs` (floor: the ground no hand, knee or foot
    goes under, for two people the shared one). Presets: out_fps (default fps; resampled over
    the same duration keeping the last pose, root linearly, rotations by slerp), units "m" or
    "cm", up "y" or "z", names "smpl" or "mixamo" (with Mixamo's rest axes: every OFFSET along
    its parent's local Y, `presets.on_bone_axes`). Re-reading reproduces joints that lie on
    those bone lengths, in those units and axes, up to the floor pass's lift of the root.
    leaves: explicit head / wrist rotations (`Motion.leaves_of`), in place of the derived."""
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or joints.shape[0] < 1:
        raise ValueError(f"joints must be (T, {sk.NUM_JOINTS}, 3) with T ≥ 1, got {joints.shape}")
    if not np.all(np.isfinite(joints)):
        raise ValueError("joints contain NaN or infinite values")
    if not fps > 0:
        raise ValueError(f"fps must be positive, got {fps}")
    check_preset(out_fps, units, up, names)
    if offsets is not None:
        offsets = np.asarray(offsets, dtype=np.float64)
        if offsets.shape != (sk.NUM_JOINTS, 3):
            raise ValueError(f"offsets must be ({sk.NUM_JOINTS}, 3), got {offsets.shape}")
    rate = fps if out_fps is None else float(out_fps)
    (rig,) = export_rigs([joints], fps, rate, [offsets], floor, body="joints", leaves=[leaves])
    local, root, offs = rig.matrices(), rig.root, rig.offsets
    ends = end_sites(offs)
    if names == "mixamo":
        # Mixamo's rest axes, as the GLB's: every frame is its bone's, so Z up turns the root only.
        local, offs, ends = on_bone_axes(local, offs, ends, bone_axes(offs, ends))
        if up == "z":
            local[:, sk.PELVIS] = Z_UP @ local[:, sk.PELVIS]
            root = root @ Z_UP.T
    elif up == "z":
        local = Z_UP @ local @ Z_UP.T
        root, offs = root @ Z_UP.T, offs @ Z_UP.T
        ends = {j: Z_UP @ e for j, e in ends.items()}
    scale = UNITS[units]
    root, offs = root * scale, offs * scale
    ends = {j: e * scale for j, e in ends.items()}

    lines, columns = ["HIERARCHY"], [root]
    _write_joint(sk.PELVIS, 0, offs, local, ends, joint_names(names), up, lines, columns)
    lines += ["MOTION", f"Frames: {rig.frames}", f"Frame Time: {1.0 / rate:.8f}"]
    data = np.concatenate(columns, axis=1)                        # (T, 3 + 22 * 3)
    lines += [_fmt(row[:3], 6) + " " + _fmt(row[3:], 4) for row in data]
    return "\n".join(lines) + "\n"
