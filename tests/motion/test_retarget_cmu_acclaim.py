"""CMU's original Acclaim files (cmu-asfamc) → SMPL-22 with HDM05's joint map, on a committed
cut of CMU 11_01 (soccer kick, its first 4 s)."""

from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_direction
from interplay.motion.retarget.cmu_acclaim import find_asf, load_cmu_acclaim, trial_of

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw" / "cmu-asfamc"
KICK = RAW / "fairmotion-tests" / "11_01.amc"


def test_names_and_skeleton_lookup():
    assert trial_of(KICK) == (11, 1) and trial_of("135_06-martialArts.amc") == (135, 6)
    assert find_asf(KICK).name == "11.asf"


def test_soccer_kick_on_cmus_own_skeleton():
    joints, offsets, meta = load_cmu_acclaim(KICK)
    assert meta["source_fps"] == 120 and meta["fps_estimate"] == 120 and meta["defects"] == []
    assert len(joints) == (480 - 1) // 6 + 1
    first = joints[0]
    assert facing_direction(first)[2] > 0.99 and np.allclose(first[sk.PELVIS, [0, 2]], 0)
    assert first[sk.LEFT_HIP, 0] > first[sk.RIGHT_HIP, 0]
    assert 1.35 < first[sk.HEAD, 1] < 1.75 and 0.85 < first[sk.PELVIS, 1] < 1.15
    assert meta["metres_per_unit"] == pytest.approx(0.0254 / 0.45)
    # The kick (3.2–3.8 s): the right foot swings half a metre up, the left stays planted.
    lift = joints[:, [sk.LEFT_FOOT, sk.RIGHT_FOOT], 1].max(axis=0)
    assert lift[1] > 0.4 and lift[0] < 0.2
