"""motion/rig.py's leaves (head, wrists, toes): rotations the moves imply, on real motions —
a stored wave turns the waving hand, a nod made by turning the neck→head bone pitches the
head — within 30° a frame; explicit rotations replace the derived; no hand tip under the floor."""

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import fit_to_skeleton
from interplay.motion.rig import (
    HAND_REACH,
    HAND_THICK,
    global_rotations,
    rig_positions,
    solve_rig,
)
from interplay.motion.rotations import axis_angle_to_matrix
from tests.helpers.gltf_files import fixture_people

J = sk.JOINT_INDEX


def angles(rot: np.ndarray) -> np.ndarray:
    """Angle (T,) in degrees of each quaternion (w, x, y, z) from identity."""
    return np.degrees(2 * np.arccos(np.clip(np.abs(rot[:, 0]), 0.0, 1.0)))


def steps(rot: np.ndarray) -> np.ndarray:
    """Angle (T-1,) in degrees between consecutive quaternions."""
    dot = np.abs(np.sum(rot[1:] * rot[:-1], axis=-1))
    return np.degrees(2 * np.arccos(np.clip(dot, 0.0, 1.0)))


def bone_step(joints: np.ndarray, a: int, b: int) -> np.ndarray:
    d = joints[:, b] - joints[:, a]
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    return np.degrees(np.arccos(np.clip(np.sum(d[1:] * d[:-1], axis=-1), -1.0, 1.0)))


@pytest.fixture(scope="module")
def wave():
    return fixture_people("spam_wave")[0]


def test_a_wave_turns_the_waving_hand_smoothly(wave):
    rig = solve_rig(wave)
    right, left = rig.rotations[:, J["right_wrist"]], rig.rotations[:, J["left_wrist"]]
    # The hand's turn a frame stays within 30°, or the forearm's own swing that frame.
    swing = bone_step(wave, J["right_elbow"], J["right_wrist"])
    assert np.all(steps(right) <= np.maximum(30.0, swing) + 1e-6)
    # While it waves (the first 2 s; the motion then drops both hands fast) the waving hand
    # turns, the idle one barely.
    assert np.ptp(angles(right[:40])) > 10.0 > 3.0 > np.ptp(angles(left[:40]))
    # Positions are still the motion's.
    assert np.abs(rig_positions(rig) - wave).max() < 1e-3   # the fixture rounds to 0.1 mm


def nod(joints: np.ndarray, degrees: float = 25.0, hz: float = 1.0) -> np.ndarray:
    """The motion with the head joint turned about the neck, pitching forward and back."""
    out = joints.copy()
    t = np.arange(len(joints)) / sk.FPS
    pitch = np.deg2rad(degrees) * np.sin(2 * np.pi * hz * t)
    side = joints[:, J["left_shoulder"]] - joints[:, J["right_shoulder"]]
    side /= np.linalg.norm(side, axis=-1, keepdims=True)
    turn = axis_angle_to_matrix(side * pitch[:, None])
    bone = joints[:, J["head"]] - joints[:, J["neck"]]
    out[:, J["head"]] = joints[:, J["neck"]] + np.einsum("tij,tj->ti", turn, bone)
    return out


def test_a_nod_pitches_the_head_with_the_neck(wave):
    still = np.repeat(wave[:1], 60, axis=0)
    nodding = nod(still)
    rig, rest = solve_rig(nodding), solve_rig(still)
    head = rig.rotations[:, J["head"]]
    assert np.ptp(angles(rest.rotations[:, J["head"]])) < 1e-6
    assert np.ptp(angles(head)) > 10.0
    assert steps(head).max() <= 30.0
    # The face (the head's forward axis) pitches more than the neck→head bone: 25° ± 5.
    face = global_rotations(rig)[:, J["head"], :, 2]
    pitch = np.degrees(np.arcsin(np.clip(face[:, 1], -1, 1)))
    assert np.ptp(pitch) > 2 * 25.0
    assert np.abs(rig_positions(rig) - nodding).max() < 1e-3


def test_explicit_rotations_replace_the_derived(wave):
    t = len(wave)
    angle = np.linspace(0, np.pi / 3, t)
    q = np.stack([np.cos(angle / 2), np.zeros(t), np.sin(angle / 2), np.zeros(t)], axis=1)  # a head turn
    rig = solve_rig(wave, leaves={"head": q})
    np.testing.assert_allclose(np.abs(np.sum(rig.rotations[:, J["head"]] * q, axis=-1)), 1.0, atol=1e-9)
    with pytest.raises(ValueError, match="explicit rotations"):
        solve_rig(wave, leaves={"left_knee": q})
    with pytest.raises(ValueError, match="rotations must be"):
        solve_rig(wave, leaves={"head": q[:3]})


def test_a_hand_on_the_floor_keeps_its_tip_above_it(wave):
    """The wave's right wrist brought down to 2 cm over the floor, the forearm pointing down:
    the hand bends up so its mesh tip does not go under."""
    low = wave.copy()
    floor = float(low[..., 1].min())
    shift = low[:, J["right_wrist"], 1] - (floor + 0.02)
    low[:, [J["right_elbow"], J["right_wrist"]], 1] -= shift[:, None]
    low, _ = fit_to_skeleton(low)
    rig = solve_rig(low, floor=floor)
    glob = global_rotations(rig)[:, J["right_wrist"]]
    along = rig.offsets[J["right_wrist"]] / np.linalg.norm(rig.offsets[J["right_wrist"]])
    tip = rig_positions(rig)[:, J["right_wrist"]] + HAND_REACH * np.einsum("tij,j->ti", glob, along)
    wrist_y = rig_positions(rig)[:, J["right_wrist"], 1]
    # The tip is no lower than the floor + the hand's thickness, or level with a wrist under it.
    assert np.all(tip[:, 1] >= np.minimum(floor + HAND_THICK, wrist_y) - 0.005)


# The library's steps (hands on the floor included): tests/motion/test_rig_steps.py.


def test_the_bvh_and_glb_carry_the_wrist_and_head_turns(wave):
    """The exports' head and wrist channels were 0 on every frame; now a wave's wrist and a
    nod's head channels move, in the BVH and in the GLB."""
    from interplay.motion.formats.bvh import read_bvh, write_bvh
    from interplay.motion.formats.gltf import write_glb
    from tests.helpers.gltf_files import accessor, load
    for joints, name in ((wave[:40], "right_wrist"), (nod(np.repeat(wave[:1], 60, axis=0)), "head")):
        bvh = read_bvh(write_bvh(joints))
        cols = bvh._channel_columns[bvh.index(name)]
        assert np.ptp(bvh.motion[:, cols], axis=0).max() > 5.0, name
        doc, blob = load(write_glb([joints], mesh=False))
        node = next(i for i, n in enumerate(doc.nodes) if n.name == name)
        ch = next(c for c in doc.animations[0].channels if c.target.node == node)
        q = accessor(doc, blob, doc.animations[0].samplers[ch.sampler].output)[:, [3, 0, 1, 2]]
        assert np.ptp(angles(q.astype(np.float64))) > 5.0, name
