"""Rotation conversions, vectorised over any leading shape (numpy only).

Matrices act on column vectors (v' = R @ v). Quaternions are (w, x, y, z).
"""

from __future__ import annotations

import numpy as np

_AXES = {"X": 0, "Y": 1, "Z": 2}


def axis_rotation(axis: str, angle: np.ndarray | float) -> np.ndarray:
    """Rotation matrices (..., 3, 3) about one principal axis by angle (radians)."""
    angle = np.asarray(angle, dtype=np.float64)
    c, s = np.cos(angle), np.sin(angle)
    out = np.zeros(angle.shape + (3, 3))
    i = _AXES[axis.upper()]
    j, k = (i + 1) % 3, (i + 2) % 3
    out[..., i, i] = 1.0
    out[..., j, j] = c
    out[..., k, k] = c
    out[..., k, j] = s
    out[..., j, k] = -s
    return out


def euler_to_matrix(angles: np.ndarray, order: str) -> np.ndarray:
    """Intrinsic Euler angles (..., 3) in radians, applied in `order` as BVH channels are:
    for channels "Zrotation Xrotation Yrotation" (order "ZXY") R = Rz @ Rx @ Ry."""
    angles = np.asarray(angles, dtype=np.float64)
    out = axis_rotation(order[0], angles[..., 0])
    for n in range(1, 3):
        out = out @ axis_rotation(order[n], angles[..., n])
    return out


def matrix_to_euler(mat: np.ndarray, order: str) -> np.ndarray:
    """Inverse of euler_to_matrix for any of the six Tait–Bryan orders (radians, (..., 3))."""
    i, j, k = (_AXES[a] for a in order.upper())
    # Sign of the permutation (i, j, k): +1 for cyclic orders (XYZ, YZX, ZXY).
    sign = 1.0 if (j - i) % 3 == 1 else -1.0
    mid = np.clip(sign * mat[..., i, k], -1.0, 1.0)
    b = np.arcsin(mid)
    a = np.arctan2(-sign * mat[..., j, k], mat[..., k, k])
    c = np.arctan2(-sign * mat[..., i, j], mat[..., i, i])
    # Gimbal lock: fold the first angle into the last.
    lock = np.abs(mid) > 1 - 1e-9
    if np.any(lock):
        a = np.where(lock, 0.0, a)
        c = np.where(lock, np.arctan2(sign * mat[..., j, i], mat[..., j, j]), c)
    return np.stack([a, b, c], axis=-1)


def axis_angle_to_matrix(aa: np.ndarray) -> np.ndarray:
    """Rodrigues: axis-angle / exponential map vectors (..., 3) → matrices (..., 3, 3)."""
    aa = np.asarray(aa, dtype=np.float64)
    theta = np.linalg.norm(aa, axis=-1, keepdims=True)
    axis = aa / np.maximum(theta, 1e-12)
    x, y, z = axis[..., 0], axis[..., 1], axis[..., 2]
    zero = np.zeros_like(x)
    k = np.stack([zero, -z, y, z, zero, -x, -y, x, zero], axis=-1).reshape(aa.shape[:-1] + (3, 3))
    t = theta[..., None]
    eye = np.broadcast_to(np.eye(3), k.shape)
    return eye + np.sin(t) * k + (1 - np.cos(t)) * (k @ k)


def matrix_to_quat(mat: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) → unit quaternions (..., 4), w ≥ 0."""
    m = np.asarray(mat, dtype=np.float64)
    tr = m[..., 0, 0] + m[..., 1, 1] + m[..., 2, 2]
    cand = np.stack([
        np.stack([1 + tr, m[..., 2, 1] - m[..., 1, 2], m[..., 0, 2] - m[..., 2, 0], m[..., 1, 0] - m[..., 0, 1]], -1),
        np.stack([m[..., 2, 1] - m[..., 1, 2], 1 + m[..., 0, 0] - m[..., 1, 1] - m[..., 2, 2], m[..., 0, 1] + m[..., 1, 0], m[..., 0, 2] + m[..., 2, 0]], -1),
        np.stack([m[..., 0, 2] - m[..., 2, 0], m[..., 0, 1] + m[..., 1, 0], 1 - m[..., 0, 0] + m[..., 1, 1] - m[..., 2, 2], m[..., 1, 2] + m[..., 2, 1]], -1),
        np.stack([m[..., 1, 0] - m[..., 0, 1], m[..., 0, 2] + m[..., 2, 0], m[..., 1, 2] + m[..., 2, 1], 1 - m[..., 0, 0] - m[..., 1, 1] + m[..., 2, 2]], -1),
    ], axis=-2)
    # Pick the numerically best-conditioned candidate per rotation.
    diag = np.stack([1 + tr, 1 + m[..., 0, 0] - m[..., 1, 1] - m[..., 2, 2],
                     1 - m[..., 0, 0] + m[..., 1, 1] - m[..., 2, 2], 1 - m[..., 0, 0] - m[..., 1, 1] + m[..., 2, 2]], -1)
    best = np.argmax(diag, axis=-1)
    q = np.take_along_axis(cand, best[..., None, None], axis=-2)[..., 0, :]
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    return q * np.where(q[..., :1] < 0, -1.0, 1.0)


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    q = np.asarray(q, dtype=np.float64)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([
        1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
        2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
        2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
    ], axis=-1).reshape(q.shape[:-1] + (3, 3))


def matrix_to_6d(mat: np.ndarray) -> np.ndarray:
    """Zhou et al.'s continuous 6D representation: the first two columns, (..., 6)."""
    return np.concatenate([mat[..., :, 0], mat[..., :, 1]], axis=-1)


def sixd_to_matrix(d6: np.ndarray) -> np.ndarray:
    """6D (..., 6) → rotation matrices by Gram–Schmidt (robust to unnormalised input)."""
    a1, a2 = d6[..., :3], d6[..., 3:]
    b1 = a1 / np.maximum(np.linalg.norm(a1, axis=-1, keepdims=True), 1e-12)
    b2 = a2 - np.sum(b1 * a2, axis=-1, keepdims=True) * b1
    b2 = b2 / np.maximum(np.linalg.norm(b2, axis=-1, keepdims=True), 1e-12)
    b3 = np.cross(b1, b2)
    return np.stack([b1, b2, b3], axis=-1)


def rotation_between(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Smallest rotations (..., 3, 3) taking direction u onto direction v."""
    u = u / np.maximum(np.linalg.norm(u, axis=-1, keepdims=True), 1e-12)
    v = v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-12)
    axis = np.cross(u, v)
    s = np.linalg.norm(axis, axis=-1, keepdims=True)
    c = np.sum(u * v, axis=-1, keepdims=True)
    angle = np.arctan2(s, c)
    # Antiparallel: any axis perpendicular to u.
    anti = (s[..., 0] < 1e-9) & (c[..., 0] < 0)
    if np.any(anti):
        perp = np.cross(u, np.array([1.0, 0.0, 0.0]))
        small = np.linalg.norm(perp, axis=-1, keepdims=True) < 1e-6
        perp = np.where(small, np.cross(u, np.array([0.0, 1.0, 0.0])), perp)
        axis = np.where(anti[..., None], perp, axis)
        s = np.where(anti[..., None], np.linalg.norm(axis, axis=-1, keepdims=True), s)
    return axis_angle_to_matrix(axis / np.maximum(s, 1e-12) * angle)


def yaw_matrix(angle: np.ndarray | float) -> np.ndarray:
    """Rotations about +Y (up) by angle (radians)."""
    return axis_rotation("Y", angle)
