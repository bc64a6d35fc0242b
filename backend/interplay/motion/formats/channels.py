"""BVH rotation channels: which Euler order each joint is written in, and how far its
channels jump from frame to frame (numpy only).

    channel_order("left_shoulder", local)     # "ZXY", or another where that one nears lock
    channel_jumps(local, order)               # (T-1,) degrees: largest channel change a frame
"""

from __future__ import annotations

import numpy as np

from interplay.motion.rotations import matrix_to_euler

# Rotation channel order of each joint we write. A Tait–Bryan order locks when its middle
# angle nears ±90° (the outer two channels then swing far for a small turn), so the middle
# axis should be one that turns little: by default, for the root yaw is outermost (people
# face any way) and pitch sits in the middle; spine, neck and legs put flexion (X) outermost
# and side bend/abduction (Z) in the middle; arms, whose bones lie along X, put their twist
# (X) in the middle. Z-up files use the same axes, renamed (Y-up's Y is Z-up's Z and its Z is
# Z-up's -Y). No one order suits every motion (an arm raised overhead puts any shoulder order
# near lock somewhere in the library), so each file picks per joint: the default where its
# middle angle stays within SAFE_MIDDLE on every frame, else the order whose largest middle
# angle is smallest (`interplay export-channels` measures both on the library).
SAFE_MIDDLE = np.deg2rad(60.0)
_ORDERS = ("XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX")


def _write_order(name: str, up: str = "y") -> str:
    if name == "pelvis":
        order = "YXZ"
    elif name.split("_")[-1] in ("collar", "shoulder", "elbow", "wrist"):
        order = "ZXY"
    else:
        order = "XZY"
    return order if up == "y" else order.translate(str.maketrans("YZ", "ZY"))


def channel_order(name: str, local: np.ndarray, up: str = "y") -> str:
    """The rotation order for a joint's local rotations (T, 3, 3) in a file: `_write_order`'s
    unless its middle angle passes SAFE_MIDDLE, then the order farthest from gimbal lock."""
    default = _write_order(name, up)

    def middle(order: str) -> float:
        return float(np.abs(matrix_to_euler(local, order)[:, 1]).max())

    if middle(default) <= SAFE_MIDDLE:
        return default
    return min(_ORDERS, key=middle)


def channel_jumps(local: np.ndarray, order: str) -> tuple[np.ndarray, np.ndarray]:
    """For local rotations (T, 3, 3) written in `order`: the largest change (T-1,) of any of
    the three channels between frames (degrees, unwrapped as the writer does) and the true
    turn (T-1,) (the geodesic angle between the frames' rotations). Their difference is what
    the order adds: near gimbal lock a small turn swings the outer channels far."""
    e = np.rad2deg(np.unwrap(matrix_to_euler(local, order), axis=0))
    jump = np.abs(np.diff(e, axis=0)).max(axis=1)
    rel = np.swapaxes(local[:-1], -1, -2) @ local[1:]
    cos = (np.trace(rel, axis1=-2, axis2=-1) - 1) / 2
    return jump, np.rad2deg(np.arccos(np.clip(cos, -1.0, 1.0)))
