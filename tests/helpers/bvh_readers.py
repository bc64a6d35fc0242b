"""BVH read back by a parser nobody here wrote: bvhio (PyPI, the dev extra)."""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk


def bvhio_positions(path, names: tuple[str, ...]) -> tuple[np.ndarray, int, float]:
    """Joints (T, 22, 3) in the file's units and axes as bvhio poses them, its frame count
    and Frame Time."""
    import bvhio
    container = bvhio.readAsBvh(str(path))
    root = bvhio.readAsHierarchy(str(path))
    joints = {j.Name: j for j, _, _ in root.layout()}
    out = np.zeros((container.FrameCount, sk.NUM_JOINTS, 3))
    for f in range(container.FrameCount):
        root.loadPose(f)
        for i, name in enumerate(names):
            p = joints[name].PositionWorld
            out[f, i] = (p.x, p.y, p.z)
    return out, container.FrameCount, container.FrameTime
