import numpy as np

from interplay.motion import kinematics as k
from interplay.motion import skeleton as sk
from interplay.motion.rotations import axis_angle_to_matrix, yaw_matrix


def random_motion(t=80, seed=0, scale=1.0):
    rng = np.random.default_rng(seed)
    # Smooth random rotations: cumulative small steps.
    aa = np.cumsum(rng.normal(0, 0.05, (t, sk.NUM_JOINTS, 3)), axis=0) * 0.5
    root = np.cumsum(rng.normal(0, 0.02, (t, 3)), axis=0) + [0, 0.95, 0]
    offsets = sk.REST_OFFSETS * scale
    joints, _ = k.forward_kinematics(axis_angle_to_matrix(aa), root, offsets)
    return joints, offsets


def test_rest_pose_faces_plus_z_with_left_on_plus_x():
    rest = sk.rest_joints()
    assert rest[sk.JOINT_INDEX["left_shoulder"], 0] > 0 > rest[sk.JOINT_INDEX["right_shoulder"], 0]
    fwd = k.facing_direction(rest)
    assert fwd[2] > 0.99
    assert abs(rest[sk.LEFT_FOOT, 1]) < 0.02  # soles on the floor in the rest pose


def test_ik_then_fk_reproduces_fk_motion_exactly():
    joints, offsets = random_motion(scale=1.08)
    fitted, fit_off = k.fit_to_skeleton(joints)
    assert np.abs(fitted - joints).max() < 1e-9
    assert np.allclose(sk.bone_lengths(sk.rest_joints(fit_off)), sk.bone_lengths(joints[0]))


def test_fit_makes_noisy_bones_rigid():
    joints, _ = random_motion(seed=3)
    noisy = joints + np.random.default_rng(4).normal(0, 0.01, joints.shape)
    fitted, _ = k.fit_to_skeleton(noisy)
    lengths = sk.bone_lengths(fitted)
    assert np.abs(lengths - lengths[0]).max() < 1e-9
    assert np.abs(sk.bone_lengths(noisy) - sk.bone_lengths(noisy)[0]).max() > 0.01


def test_canonicalize_shares_one_transform_between_people():
    a, _ = random_motion(seed=5)
    b = a @ yaw_matrix(0.7).T + [1.2, 0.0, -0.4]
    moved, info = k.canonicalize([a @ yaw_matrix(2.0).T + [3, 0.5, 4], b @ yaw_matrix(2.0).T + [3, 0.5, 4]])
    assert np.allclose(moved[0][0, sk.PELVIS, [0, 2]], 0, atol=1e-9)
    assert abs(k.facing_angle(moved[0][0])) < 1e-9
    # Their relation is kept: distances between the two people are unchanged.
    d_before = np.linalg.norm(a[:, None] - b[:, :, None], axis=-1)
    d_after = np.linalg.norm(moved[0][:, None] - moved[1][:, :, None], axis=-1)
    assert np.allclose(d_before, d_after, atol=1e-9)
    assert abs(k.floor_height(moved)) < 1e-9


def test_resample_keeps_duration_and_interpolates():
    x = np.arange(121, dtype=float)[:, None] * 0.01  # 1 s at 120 fps
    y = k.resample(x, 120, 20)
    assert y.shape[0] == 21
    assert np.allclose(y[:, 0], np.arange(21) * 0.06)


def test_continue_from_moves_later_frames_on_from_the_new_end():
    rng = np.random.default_rng(0)
    old = rng.normal(size=(30, 22, 3)) * 0.1
    old[:, :, 1] += 1.0
    new = old.copy()
    yaw = np.pi / 3
    c, s = np.cos(yaw), np.sin(yaw)
    rot = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    new[:10] = old[:10] @ rot.T + [2.0, 0.0, -1.0]
    moved = k.continue_from(new, old[9], 10)
    # Frame 10 relates to frame 9 as before: same step, turned with the end.
    step_old = old[10, 0] - old[9, 0]
    step_new = moved[10, 0] - moved[9, 0]
    assert np.allclose(np.linalg.norm(step_old[[0, 2]]), np.linalg.norm(step_new[[0, 2]]))
    assert np.isclose(k.facing_angle(moved[20]) - k.facing_angle(old[20]),
                      k.facing_angle(new[9]) - k.facing_angle(old[9]))
    assert np.allclose(moved[:10], new[:10]) and np.allclose(moved[10:, :, 1], old[10:, :, 1])
    assert k.continue_from(new, old[29], 30) is new      # nothing after the end to move
