"""A leg's kick as a part edit (issue 14 item 5: SPAM's edit of a right-leg kick on a standing
body shuffled the body 3 m and never kicked), on real captures: the named leg kicks as the
benchmark's kick check measures it, the other leg does not, every joint outside the leg stays
bit for bit, the leg's bones keep their lengths, and a frame-range edit changes only its frames."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.retrieve_edit.leg_edit import leg_edit
from interplay.generators.router import load_generator
from interplay.motion import skeleton as sk
from interplay.motion.checks.named import run_check

SEEDS = (0, 1)
RIGHT = [sk.JOINT_INDEX[f"right_{p}"] for p in ("knee", "ankle", "foot")]
LEFT = [sk.JOINT_INDEX[f"left_{p}"] for p in ("knee", "ankle", "foot")]


@pytest.fixture(scope="module")
def router():
    return load_generator(use_spam=False)


def _captured(router, prompt: str, seconds: float, seed: int = 0) -> np.ndarray:
    return np.asarray(router.retrieval.generate(Request(prompt, seconds=seconds, seed=seed)).people[0],
                      dtype=np.float64)


def _bones(j):
    return np.linalg.norm(j[:, 1:] - j[:, list(sk.PARENTS[1:])], axis=-1)


def test_a_standing_body_kicks_with_the_right_leg_and_nothing_else_moves(router):
    stand = _captured(router, "a person stands still", 4.0)
    for seed in SEEDS:
        edit, entry = router.edit(stand, "right_leg", "kick with the right leg", None, seed=seed)
        out = np.asarray(edit.joints, np.float64)
        assert entry["generator"] == "captured_kick" and entry["parts"] == ["right_lower"]
        assert run_check([out], {"check": "kick", "leg": "right", "at_least": 1}).passed
        assert not run_check([out], {"check": "kick", "leg": "left", "at_least": 1}).passed
        keep = [j for j in range(sk.NUM_JOINTS) if j not in RIGHT]
        assert np.array_equal(out[:, keep], stand[:, keep])
        assert np.abs(_bones(out) - _bones(stand)).max() < 1e-6


def test_a_frame_range_kick_changes_only_its_frames(router):
    walk = _captured(router, "a person walks forward", 6.0, seed=1)
    out, entry = leg_edit(walk, "left_leg", "kick twice with the left leg", (30, 110), router.retrieval, 2)
    assert np.array_equal(out[:30], walk[:30]) and np.array_equal(out[110:], walk[110:])
    assert entry["kicks"] == 2 and all(30 <= f < 110 for f in entry["kick_frames"])
    assert entry["edited_change_cm"] > 10 and entry["untouched_change_cm"] == 0.0
    assert np.abs(out[30:110][:, LEFT] - walk[30:110][:, LEFT]).max() > 0.3


def test_other_leg_edits_are_left_to_spam(router):
    stand = _captured(router, "a person stands still", 3.0)
    assert leg_edit(stand, "right_leg", "bend the right knee", None, router.retrieval, 0) is None
    assert leg_edit(stand, "left_arm", "kick with the left leg", None, router.retrieval, 0) is None
    assert leg_edit(stand, "right_leg", "kick", (0, 10), router.retrieval, 0) is None   # too short
