import numpy as np
import pytest

from interplay.motion import rotations as r

ORDERS = ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"]


@pytest.mark.parametrize("order", ORDERS)
def test_euler_round_trip(order):
    rng = np.random.default_rng(1)
    angles = rng.uniform(-1.4, 1.4, (200, 3))
    mat = r.euler_to_matrix(angles, order)
    back = r.euler_to_matrix(r.matrix_to_euler(mat, order), order)
    assert np.abs(back - mat).max() < 1e-9


def test_euler_order_is_intrinsic_like_bvh():
    # "ZXY" channels mean R = Rz @ Rx @ Ry: rotating (0,0,1) by Ry(90°) first gives +X,
    # then Rx leaves it, then Rz(90°) turns +X into +Y.
    mat = r.euler_to_matrix(np.radians([90.0, 0.0, 90.0]), "ZXY")
    assert np.allclose(mat @ [0, 0, 1], [0, 1, 0], atol=1e-12)


def test_quaternion_6d_axis_angle_agree():
    rng = np.random.default_rng(2)
    aa = rng.normal(0, 1.0, (100, 3))
    mat = r.axis_angle_to_matrix(aa)
    assert np.allclose(mat @ np.swapaxes(mat, -1, -2), np.eye(3), atol=1e-12)
    assert np.allclose(r.quat_to_matrix(r.matrix_to_quat(mat)), mat, atol=1e-12)
    assert np.allclose(r.sixd_to_matrix(r.matrix_to_6d(mat)), mat, atol=1e-12)


def test_rotation_between_including_antiparallel():
    u = np.array([[1.0, 0, 0], [0, 1.0, 0], [0.3, -0.2, 0.9]])
    v = np.array([[0, 0, 2.0], [0, -1.0, 0], [-0.3, 0.2, -0.9]])
    mat = r.rotation_between(u, v)
    got = np.einsum("nij,nj->ni", mat, u)
    want = v / np.linalg.norm(v, axis=1, keepdims=True) * np.linalg.norm(u, axis=1, keepdims=True)
    assert np.allclose(got, want, atol=1e-9)
