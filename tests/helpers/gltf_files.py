"""Reading GLB files back with pygltflib for the GLB export's tests, and the motions they
export: the stored behaviour fixtures (real generated motions)."""

from __future__ import annotations

import json

import numpy as np
import pygltflib as gl

from interplay.motion.formats.presets import export_rigs
from interplay.motion.rig import Rig
from tests.helpers.paths import REPO

FIXTURES = REPO / "tests" / "fixtures" / "behaviour"
ASSET = REPO / "frontend" / "public" / "humanoid.glb"
_DTYPES = {gl.FLOAT: np.float32, gl.UNSIGNED_BYTE: np.uint8, gl.UNSIGNED_SHORT: np.uint16,
           gl.UNSIGNED_INT: np.uint32}
_WIDTH = {gl.SCALAR: 1, gl.VEC2: 2, gl.VEC3: 3, gl.VEC4: 4, gl.MAT4: 16}


def fixture_people(name: str) -> list[np.ndarray]:
    """The joints of a stored behaviour fixture."""
    data = json.loads((FIXTURES / f"{name}.json").read_text())
    return [np.asarray(p["joints"], dtype=np.float64) for p in data["people"]]


def rigs_of(people: list[np.ndarray], out_fps: float | None = None) -> list[Rig]:
    """The rigs the GLB export writes: every person over the people's one floor, lifted where
    the mesh would go under it, resampled to out_fps."""
    return export_rigs(people, 20, out_fps, body="mesh")


def load(data: bytes) -> tuple[gl.GLTF2, bytes]:
    doc = gl.GLTF2.load_from_bytes(data)
    return doc, doc.binary_blob()


def accessor(doc: gl.GLTF2, blob: bytes, index: int) -> np.ndarray:
    """An accessor's elements, (count,) or (count, width)."""
    acc = doc.accessors[index]
    view = doc.bufferViews[acc.bufferView]
    width = _WIDTH[acc.type]
    a = np.frombuffer(blob, dtype=_DTYPES[acc.componentType], count=acc.count * width,
                      offset=view.byteOffset + (acc.byteOffset or 0))
    return a.reshape(acc.count, width) if width > 1 else a
