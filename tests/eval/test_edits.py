"""Part-edit fidelity measures on real captures: what the captioner confirms and how far the
untouched joints move."""

import numpy as np
import pytest

from interplay.eval.edits import CASES, EditCase, confirmed_share, edit_fidelity, measure, untouched_cm
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.posecodes import caption_clip


@pytest.fixture(scope="module")
def clips():
    return default_clips()


def test_untouched_change_counts_only_joints_outside_the_edited_part(clips):
    walk = next(c for c in clips if c.prompt == "a person walks forward").people[0].astype(float)
    moved = walk.copy()
    moved[:, sk.PART_JOINTS["left_upper"]] += 0.5             # the whole left upper part moves
    assert untouched_cm(walk, moved, ["left_upper"]) == 0.0
    assert untouched_cm(walk, moved, ["left_arm"]) == 0.0      # aliases accepted
    moved[:, sk.JOINT_INDEX["right_knee"]] += np.array([0.0, 0.0, 0.11])
    keep = sk.NUM_JOINTS - len(sk.PART_JOINTS["left_upper"])
    assert untouched_cm(walk, moved, ["left_upper"]) == pytest.approx(11.0 / keep)


RAISED = "the right arm is raised above the head"


@pytest.fixture(scope="module")
def raised(clips):
    """A real single-person capture the captioner describes with the right arm overhead."""
    return next(c for c in clips if len(c.people) == 1 and not c.synthetic and c.frames <= 120
                and any(cap.text == RAISED for cap in c.captions)).people[0].astype(float)


def test_confirmed_share_agrees_with_the_captions_of_a_real_capture(raised):
    caps = [c for c in caption_clip(raised) if c.part == "right_upper" and c.text == RAISED]
    share = confirmed_share(raised, "right_upper", RAISED)
    assert share == pytest.approx(sum(c.end - c.start for c in caps) / len(raised))
    assert 0 < share <= 1
    assert confirmed_share(raised, "left_upper", RAISED) == 0.0


def test_measure_and_edit_fidelity_with_captures_as_the_model(clips, raised):
    """A stand-in 'model' whose edit returns a real capture with the arm overhead: the
    captioner sees the raised arm after and not before, and the untouched joints moved."""
    n = len(raised)
    walk = next(c for c in clips if c.prompt == "a person walks forward" and c.frames >= n)
    case = EditCase("a person walks forward", "right_upper", RAISED, "right_hand_above_head")

    def generate(text, frames, seed):
        return walk.people[0][:frames].astype(float)

    contexts = []

    def edit(joints, parts, prompt, seed, context):
        contexts.append(context)
        return raised[:len(joints)]

    out = edit_fidelity(generate, edit, seeds=2, cases=[case], frames=n)[0]
    assert out["seeds"] == 2 and out["part"] == "right_upper"
    assert contexts == [case.base, case.base]
    assert out["code_share"] > out["base_code_share"] == 0.0
    assert out["confirmed"] > 0
    assert out["untouched_cm"] > 1.0
    same = measure(case, generate("", n, 0), generate("", n, 0))
    assert same["untouched_cm"] == 0.0 and same["code_share"] == same["base_code_share"]
    with pytest.raises(ValueError, match="shape"):
        measure(case, walk.people[0][:n].astype(float), walk.people[0][:n - 5].astype(float))


def test_every_case_names_a_real_part_and_pose_code(clips):
    from interplay.motion.posecodes import frame_codes
    codes = frame_codes(clips[0].people[0].astype(float))
    for case in CASES:
        assert case.part in sk.PART_NAMES and case.code in codes
