"""Contact sheets of the motion primitives (generators/primitives): one row per primitive,
frames sampled across it, drawn as stick figures from the side or the front, written as a PNG
with numpy and zlib only (no imaging library in the environment).

    .venv/bin/python scripts/primitive_sheet.py out.png push_up sit_up nod
"""

from __future__ import annotations

import struct
import sys
import zlib

import numpy as np

from interplay.generators.primitives.registry import PRIMITIVES, build
from interplay.motion import skeleton as sk

CELL = 160
COLOURS = {"left_upper": (40, 110, 220), "right_upper": (220, 110, 60),
           "left_lower": (40, 160, 100), "right_lower": (180, 60, 180)}


def _png(img: np.ndarray) -> bytes:
    h, w, _ = img.shape
    raw = b"".join(b"\x00" + img[y].tobytes() for y in range(h))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def _line(img, a, b, colour, r=1, box=None):
    n = int(max(abs(b[0] - a[0]), abs(b[1] - a[1]))) + 1
    x0, y0, x1, y1 = box or (0, 0, img.shape[1], img.shape[0])
    for k in range(n + 1):
        x = int(round(a[0] + (b[0] - a[0]) * k / n))
        y = int(round(a[1] + (b[1] - a[1]) * k / n))
        if x0 + r <= x < x1 - r and y0 + r <= y < y1 - r:
            img[y - r:y + r + 1, x - r:x + r + 1] = colour


def draw(img, joints, ox, oy, axis_x, scale, centre):
    def p(v):
        return (ox + CELL / 2 + scale * float((v - centre) @ axis_x), oy + CELL - 12 - scale * float(v[1]))
    _line(img, (ox + 5, oy + CELL - 12), (ox + CELL - 5, oy + CELL - 12), (150, 150, 150))
    box = (ox, oy, ox + CELL, oy + CELL)
    for c, par in sk.BONES:
        _line(img, p(joints[par]), p(joints[c]), COLOURS[sk.JOINT_PART[c]], box=box)
    _line(img, p(joints[sk.NECK]), p(joints[sk.HEAD]), (0, 0, 0), 2, box=box)


def sheet(names: list[str], columns: int = 8, view: str = "side") -> np.ndarray:
    img = np.full((CELL * len(names), CELL * columns, 3), 255, np.uint8)
    for r, name in enumerate(names):
        j = build(PRIMITIVES[name], {})
        fwd = j[0, sk.NECK] - j[0, sk.PELVIS]
        fwd[1] = 0.0
        left = j[0, sk.LEFT_HIP] - j[0, sk.RIGHT_HIP]
        left[1] = 0
        left /= np.linalg.norm(left)
        side = np.cross(left, [0.0, 1.0, 0.0])           # forward on the floor
        axis_x = side if view == "side" else left
        centre = j[0, sk.PELVIS] * [1, 0, 1]
        span = max(1.9, float(np.ptp(j[..., 1])) + 0.2)
        scale = (CELL - 24) / span
        zoom = PRIMITIVES[name].parts == ("head",)
        if zoom:                                              # the head's rows: neck and head close up
            scale = (CELL - 24) / 0.5
            centre = j[0, sk.NECK] * [1, 0, 1]
        for c, f in enumerate(np.linspace(0, len(j) - 1, columns).astype(int)):
            if PRIMITIVES[name].posture == "walk":           # a walk: follow the pelvis
                centre = j[f, sk.PELVIS] * [1, 0, 1]
            draw(img, j[f] - ([0, j[0, sk.NECK, 1] - 0.3, 0] if zoom else 0), c * CELL, r * CELL,
                 axis_x, scale, centre)
            img[r * CELL:(r + 1) * CELL, c * CELL] = 200
        img[r * CELL, :] = 120
    return img


if __name__ == "__main__":
    out, *names = sys.argv[1:]
    view = "side"
    if names and names[0] in ("--front", "--side"):
        view, names = names[0][2:], names[1:]
    with open(out, "wb") as f:
        f.write(_png(sheet(names, view=view)))
