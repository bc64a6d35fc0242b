"""formats/channels.py: BVH Euler orders picked per joint and file, away from gimbal lock, on
the library's two-person dances (where a shoulder's fixed order swung its channels 100° for
a 20° turn); files with the picked orders read back in bvhio (`interplay export-channels`
measures the whole library)."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.formats.bvh import read_bvh, smpl22_positions, write_bvh
from interplay.motion.formats.channels import SAFE_MIDDLE, _write_order, channel_jumps, channel_order
from interplay.motion.kinematics import fit_to_skeleton, floor_height
from interplay.motion.rig import solve_rig
from interplay.motion.rotations import matrix_to_euler
from tests.helpers.bvh_readers import bvhio_positions


@pytest.fixture(scope="module")
def dances():
    pairs = [c for c in default_clips() if len(c.people) == 2]
    assert len(pairs) >= 5
    out = []
    for clip in pairs[:8]:
        people = [np.asarray(p, np.float64) for p in clip.people]
        floor = floor_height(people)
        out += [(clip.id, p, solve_rig(p, floor=floor).matrices()) for p in people]
    return out


def test_picked_orders_keep_the_channels_to_the_true_turn(dances):
    before = after = 0.0
    for _, _, local in dances:
        for j, name in enumerate(sk.JOINT_NAMES):
            order = channel_order(name, local[:, j])
            # The pick never comes nearer lock than the default.
            mid = [np.abs(matrix_to_euler(local[:, j], o)[:, 1]).max() for o in (order, _write_order(name))]
            assert mid[0] <= max(mid[1], SAFE_MIDDLE) + 1e-9
            for k, o in enumerate((_write_order(name), order)):
                jump, turn = channel_jumps(local[:, j], o)
                excess = float((jump - turn).max())
                before, after = (max(before, excess), after) if k == 0 else (before, max(after, excess))
    assert before > 60.0           # the fixed orders swing far somewhere in the dances …
    assert after < 0.5 * before    # … the picked ones much less


def test_a_file_with_picked_orders_reads_back_in_bvhio(dances, tmp_path):
    # The dance whose fixed orders come nearest lock.
    def nearest(item):
        local = item[2]
        return max(np.abs(matrix_to_euler(local[:, j], _write_order(n))[:, 1]).max()
                   for j, n in enumerate(sk.JOINT_NAMES))
    _, joints, _ = max(dances, key=nearest)
    joints, _ = fit_to_skeleton(joints[:200])
    path = tmp_path / "dance.bvh"
    path.write_text(write_bvh(joints))
    bvh = read_bvh(path.read_text())
    orders = {"".join(c[0] for c in ch[-3:]) for ch in bvh.channels}
    assert len(orders) > 3                       # more than the three defaults
    got, _, _ = bvhio_positions(path, sk.JOINT_NAMES)
    ours = smpl22_positions(bvh)
    assert np.abs(got - ours).max() < 1e-3
    assert np.abs(ours[:, :, [0, 2]] - joints[:, :, [0, 2]]).max() < 1e-3
