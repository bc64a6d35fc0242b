"""Acclaim ASF/AMC reader and forward kinematics (numpy only).

ASF holds the skeleton: `:units` (`length` scale, `angle deg|rad`), `:root` (channel order,
axis order, rest position/orientation), `:bonedata` (per bone: unit direction and length in
the global rest frame, `axis` angles + order giving the bone's local frame C, `dof`, `limits`)
and `:hierarchy`. AMC holds the motion: frame numbers, then one line per bone with its dofs.

Acclaim convention (as in CMU's and HDM05's data):
  * "XYZ" orders (axis, dofs) are application orders: rotate about X first, then Y, then Z,
    so on column vectors R = Rz · Ry · Rx. A bone's dofs compose the same way in the order
    the `dof` line lists them.
  * per bone: C = rotation from its `axis`, M = motion rotation from its dofs,
    L = C · M · C⁻¹, global rotation G = G_parent · L;
  * the bone's end = parent end + G · direction · length (the root's "end" is its position).
Lengths stay in file units; `Asf.metres_per_unit` converts (Vicon/CMU files are inches
times the `length` scale, so `length 0.45` means one unit is 1/0.45 inch).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from interplay.motion.rotations import axis_rotation

INCH = 0.0254
_ROT_DOFS = {"rx": "X", "ry": "Y", "rz": "Z"}
_TRANS_DOFS = {"tx": 0, "ty": 1, "tz": 2}


@dataclass(frozen=True)
class Bone:
    name: str
    direction: np.ndarray          # (3,) unit vector, global rest frame
    length: float                  # file units
    axis: np.ndarray               # (3,) radians, listed in axis_order
    axis_order: str                # e.g. "XYZ"
    dofs: tuple[str, ...]          # e.g. ("rx", "ry", "rz"); may be empty
    limits: tuple[tuple[float, float], ...]  # one (lo, hi) per dof, in the ASF angle unit


@dataclass(frozen=True)
class Asf:
    name: str
    length_scale: float            # `:units length` (file units per inch for Vicon/CMU files)
    angle_unit: str                # "deg" | "rad"
    root_order: tuple[str, ...]    # e.g. ("TX", "TY", "TZ", "RX", "RY", "RZ")
    root_axis: str                 # order of the root orientation angles, e.g. "XYZ"
    root_position: np.ndarray      # (3,) file units
    root_orientation: np.ndarray   # (3,) radians
    bones: dict[str, Bone]         # in parents-first order (root excluded)
    parents: dict[str, str]        # bone → parent ("root" for the root's children)

    @property
    def names(self) -> tuple[str, ...]:
        """Joint names of the FK output: "root", then every bone parents-first."""
        return ("root",) + tuple(self.bones)

    @property
    def metres_per_unit(self) -> float:
        return INCH / self.length_scale


@dataclass(frozen=True)
class Amc:
    values: dict[str, np.ndarray]  # bone (or "root") → (T, n_values) as written
    degrees: bool | None           # angle unit from the header (:DEGREES/:RADIANS), None if absent
    frame_numbers: np.ndarray      # (T,) as written

    @property
    def n_frames(self) -> int:
        return int(self.frame_numbers.shape[0])


def _read_text(source: str | Path) -> str:
    """A path or the file's text; Acclaim files may carry Latin-1 bytes in comments."""
    if isinstance(source, Path) or "\n" not in source:
        return Path(source).read_bytes().decode("latin-1")
    return source


def _sections(text: str) -> dict[str, list[str]]:
    """Keyword sections (":units", ":bonedata" …) → their lines, comments dropped."""
    out: dict[str, list[str]] = {}
    current = None
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith(":"):
            key, _, rest = line.partition(" ")
            current = key[1:].lower()
            out[current] = [rest.strip()] if rest.strip() else []
        elif current is not None:
            out[current].append(line)
    return out


def _parse_bone(tokens: list[str], to_rad: float) -> Bone:
    fields: dict[str, list[str]] = {}
    key = None
    for tok in tokens:
        low = tok.lower()
        if low in ("id", "name", "direction", "length", "axis", "dof", "limits", "bodymass", "cofmass"):
            key = low
            fields[key] = []
        elif key is not None:
            fields[key].append(tok)
    if "name" not in fields:
        raise ValueError(f"ASF bone without a name: {' '.join(tokens)[:80]!r}")
    name = fields["name"][0]
    try:
        direction = np.array([float(v) for v in fields.get("direction", ["0", "0", "0"])[:3]])
        length = float(fields.get("length", ["0"])[0])
        axis_tokens = fields.get("axis", ["0", "0", "0", "XYZ"])
        axis = np.array([float(v) for v in axis_tokens[:3]]) * to_rad
        axis_order = axis_tokens[3].upper() if len(axis_tokens) > 3 else "XYZ"
        dofs = tuple(d.lower() for d in fields.get("dof", []))
        nums = [float(v) for v in " ".join(fields.get("limits", [])).replace("(", " ").replace(")", " ").split()]
    except (ValueError, IndexError) as exc:
        raise ValueError(f"ASF bone {name!r}: malformed field ({exc})") from None
    limits = tuple((nums[2 * i], nums[2 * i + 1]) for i in range(len(nums) // 2))
    norm = np.linalg.norm(direction)
    if norm > 0:
        direction = direction / norm
    return Bone(name, direction, length, axis, axis_order, dofs, limits)


def read_asf(source: str | Path) -> Asf:
    """Parse an ASF file (path or text)."""
    sec = _sections(_read_text(source))
    for need in ("bonedata", "hierarchy"):
        if need not in sec:
            raise ValueError(f"ASF lacks a :{need} section")
    units = dict(line.split(None, 1) for line in sec.get("units", []) if len(line.split()) >= 2)
    angle_unit = units.get("angle", "deg").strip().lower()
    if angle_unit not in ("deg", "rad"):
        raise ValueError(f"ASF angle unit must be deg or rad, got {angle_unit!r}")
    to_rad = np.pi / 180 if angle_unit == "deg" else 1.0
    length_scale = float(units.get("length", "1").split()[0])
    if length_scale <= 0:
        raise ValueError(f"ASF length scale must be positive, got {length_scale}")

    root = {}
    for line in sec.get("root", []):
        key, *vals = line.split()
        root[key.lower()] = vals
    root_order = tuple(v.upper() for v in root.get("order", ["TX", "TY", "TZ", "RX", "RY", "RZ"]))
    root_axis = root.get("axis", ["XYZ"])[0].upper()
    root_position = np.array([float(v) for v in root.get("position", ["0", "0", "0"])[:3]])
    root_orientation = np.array([float(v) for v in root.get("orientation", ["0", "0", "0"])[:3]]) * to_rad

    bones: dict[str, Bone] = {}
    block: list[str] | None = None
    for line in sec["bonedata"]:
        word = line.split()[0].lower()
        if word == "begin":
            block = []
        elif word == "end":
            if block is None:
                raise ValueError("ASF :bonedata has 'end' without 'begin'")
            bone = _parse_bone(block, to_rad)
            bones[bone.name] = bone
            block = None
        elif block is not None:
            block.extend(line.split())

    parents: dict[str, str] = {}
    for line in sec["hierarchy"]:
        words = line.split()
        if words[0].lower() in ("begin", "end"):
            continue
        for child in words[1:]:
            parents[child] = words[0]
    order = _parents_first(parents)
    missing = [b for b in order if b not in bones]
    if missing:
        raise ValueError(f"ASF hierarchy names bones without bonedata: {missing}")
    return Asf(name=" ".join(sec.get("name", ["unnamed"])), length_scale=length_scale,
               angle_unit=angle_unit, root_order=root_order, root_axis=root_axis,
               root_position=root_position, root_orientation=root_orientation,
               bones={b: bones[b] for b in order}, parents=parents)


def _parents_first(parents: dict[str, str]) -> list[str]:
    kids: dict[str, list[str]] = {}
    for child, parent in parents.items():
        kids.setdefault(parent, []).append(child)
    order, queue = [], list(kids.get("root", []))
    while queue:
        bone = queue.pop(0)
        order.append(bone)
        queue.extend(kids.get(bone, []))
    if len(order) != len(parents):
        raise ValueError(f"ASF hierarchy is not a tree under root: {sorted(set(parents) - set(order))}")
    return order


def read_amc(source: str | Path) -> Amc:
    """Parse an AMC file (path or text): per bone, the values of every frame."""
    degrees = None
    rows: dict[str, list[list[float]]] = {}
    frames: list[int] = []
    for raw in _read_text(source).splitlines():
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        if line.startswith(":"):
            head = line.upper()
            if head.startswith(":RADIANS"):
                degrees = False
            elif head.startswith(":DEGREES"):
                degrees = True
            continue
        if line.isdecimal():                     # a frame number
            frames.append(int(line))
            continue
        if not frames:
            raise ValueError(f"AMC data before the first frame number: {line[:60]!r}")
        name, *vals = line.split()
        rows.setdefault(name, []).append([float(v) for v in vals])
    if not frames:
        raise ValueError("AMC has no frames")
    uneven = [n for n, r in rows.items() if len(r) != len(frames)]
    if uneven:
        raise ValueError(f"AMC bones missing from some frames: {uneven}")
    return Amc(values={n: np.array(r, dtype=np.float64) for n, r in rows.items()},
               degrees=degrees, frame_numbers=np.array(frames))


def ordered_rotation(angles: np.ndarray, order: str) -> np.ndarray:
    """Rotations (..., 3, 3) applying angles (..., k) (radians) about the axes of `order`
    in sequence: order "XYZ" gives Rz · Ry · Rx."""
    angles = np.asarray(angles, dtype=np.float64)
    out = np.broadcast_to(np.eye(3), angles.shape[:-1] + (3, 3)).copy()
    for i, ax in enumerate(order):
        out = axis_rotation(ax, angles[..., i]) @ out
    return out


def _bone_motion(bone: Bone, values: np.ndarray | None, t: int, to_rad: float) -> np.ndarray:
    """Motion rotations M (T, 3, 3) of one bone from its AMC values (T, n_dof)."""
    if not bone.dofs or values is None:
        return np.broadcast_to(np.eye(3), (t, 3, 3))
    if values.shape[1] != len(bone.dofs):
        raise ValueError(f"AMC bone {bone.name!r} has {values.shape[1]} values, ASF dofs {bone.dofs}")
    rot = [(i, _ROT_DOFS[d]) for i, d in enumerate(bone.dofs) if d in _ROT_DOFS]
    if not rot:
        return np.broadcast_to(np.eye(3), (t, 3, 3))
    cols = [i for i, _ in rot]
    return ordered_rotation(values[:, cols] * to_rad, "".join(a for _, a in rot))


def forward_kinematics(asf: Asf, amc: Amc) -> tuple[np.ndarray, tuple[str, ...]]:
    """Global positions (T, J, 3) in file units of the root and every bone's end, with
    their names (`asf.names`): L = C · M · C⁻¹, G = G_parent · L, end = parent end +
    G · direction · length. AMC angles are in the AMC header's unit, else the ASF's."""
    t = amc.n_frames
    degrees = amc.degrees if amc.degrees is not None else asf.angle_unit == "deg"
    to_rad = np.pi / 180 if degrees else 1.0
    if "root" not in amc.values:
        raise ValueError("AMC has no root line")
    root_vals = amc.values["root"]
    if root_vals.shape[1] != len(asf.root_order):
        raise ValueError(f"AMC root has {root_vals.shape[1]} values, ASF order {asf.root_order}")
    root_pos = np.broadcast_to(asf.root_position, (t, 3)).copy()
    rot_cols, rot_axes = [], ""
    for i, ch in enumerate(asf.root_order):
        low = ch.lower()
        if low in _TRANS_DOFS:
            root_pos[:, _TRANS_DOFS[low]] = root_vals[:, i]
        elif low in _ROT_DOFS:
            rot_cols.append(i)
            rot_axes += _ROT_DOFS[low]
    c_root = ordered_rotation(asf.root_orientation, asf.root_axis)
    m_root = ordered_rotation(root_vals[:, rot_cols] * to_rad, rot_axes)
    glob = {"root": c_root @ m_root @ c_root.T}
    pos = {"root": root_pos}
    for name, bone in asf.bones.items():
        parent = asf.parents[name]
        c = ordered_rotation(bone.axis, bone.axis_order)
        local = c @ _bone_motion(bone, amc.values.get(name), t, to_rad) @ c.T
        glob[name] = glob[parent] @ local
        pos[name] = pos[parent] + glob[name] @ (bone.direction * bone.length)
    return np.stack([pos[n] for n in asf.names], axis=1), asf.names


def load_acclaim(amc_path: str | Path, asf_path: str | Path) -> tuple[dict[str, np.ndarray], Asf, Amc]:
    """Named global positions {joint: (T, 3)} in file units, plus the parsed files."""
    asf, amc = read_asf(Path(asf_path)), read_amc(Path(amc_path))
    positions, names = forward_kinematics(asf, amc)
    return {n: positions[:, i] for i, n in enumerate(names)}, asf, amc
