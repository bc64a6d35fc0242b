"""Pose codes and automatic part captions on real capture clips (tests/fixtures/raw, made by
tests/fixtures/make_fixtures.py), plus the processed set when
it is built."""

import os
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR, Clip, default_clips
from interplay.motion.posecodes import caption_accuracy, caption_clip, describe, frame_codes
from interplay.motion.retarget.cmu_8action import load_cmu_8action
from interplay.motion.retarget.cmu_daz import load_cmu_bvh
from interplay.motion.retarget.hdm05 import load_hdm05
from interplay.motion.rotations import yaw_matrix

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw"
HDM05 = {
    "squat": "squat1Reps/HDM_bd_squat1Reps_003_120.amc",
    "kick": "kickLFront1Reps/HDM_bk_kickLFront1Reps_011_120.amc",
    "circle": "jogLeftCircle4StepsRstart/HDM_bd_jogLeftCircle4StepsRstart_001_120.amc",
    "grab": "grabHighR/HDM_bd_grabHighR_001_120.amc",
    "rotate": "rotateArmsBothBackward1Reps/HDM_bd_rotateArmsBothBackward1Reps_001_120.amc",
    "hop": "hopBothLegs1hops/HDM_bd_hopBothLegs1hops_001_120.amc",
}
CMU = {"walk": "07/07_01.bvh", "run": "09/09_05.bvh", "jump": "13/13_39.bvh"}
EIGHT = {"walk8": "walking/walking_4.txt", "run8": "running/running_5.txt"}
LABELS = {"squat": "squat1Reps", "kick": "kickLFront1Reps", "circle": "jogLeftCircle4StepsRstart",
          "grab": "grabHighR", "rotate": "rotateArmsBothBackward1Reps", "hop": "hopBothLegs1hops",
          "walk": "walk", "run": "run", "jump": "jump", "walk8": "walking", "run8": "running"}
MIRROR = [sk.JOINT_INDEX[n.replace("left", "@").replace("right", "left").replace("@", "right")]
          for n in sk.JOINT_NAMES]


@lru_cache(maxsize=None)
def clip(name: str) -> np.ndarray:
    if name in HDM05:
        path = RAW / "hdm05" / HDM05[name]
        actor = path.stem.split("_")[1]
        return load_hdm05(path, RAW / "hdm05" / "asf" / f"HDM_{actor}.asf")[0]
    if name in CMU:
        return load_cmu_bvh(RAW / "cmu-bvh" / CMU[name])[0]
    return load_cmu_8action(RAW / "cmu-8action" / "train" / EIGHT[name])[0]


def mirror(joints: np.ndarray) -> np.ndarray:
    """x → −x with left and right joints swapped: the same motion done by the other side."""
    out = joints[:, MIRROR].copy()
    out[..., 0] *= -1
    return out


def swap_sides(text: str) -> str:
    return text.replace("left", "@").replace("right", "left").replace("@", "right")


def texts(name: str, part: str) -> list[str]:
    return [c.text for c in caption_clip(clip(name)) if c.part == part]


def longest(name: str, part: str) -> str:
    caps = [c for c in caption_clip(clip(name)) if c.part == part]
    return max(caps, key=lambda c: c.end - c.start).text


@pytest.mark.parametrize("name", ["jump", "hop"])
def test_a_jump_says_jumps(name):
    assert any("jumps" in t for t in texts(name, "body")), texts(name, "body")
    codes = frame_codes(clip(name))
    assert codes["jumping"].any() and codes["airborne"].any()


@pytest.mark.parametrize("name", ["walk", "walk8"])
def test_a_walk_says_walks_forward(name):
    assert longest(name, "body") == "the person walks forward"
    assert "the left leg walks forward" in texts(name, "left_lower")
    codes = frame_codes(clip(name))
    assert 1.2 < np.median(codes["cadence"]) < 2.6                 # steps per second
    assert not codes["running"].any() and not codes["jumping"].any()


@pytest.mark.parametrize("name", ["run", "run8"])
def test_a_run_says_runs(name):
    assert longest(name, "body") == "the person runs forward"
    assert np.median(frame_codes(clip(name))["speed"]) > 2.5


def test_a_squat_says_squats():
    assert "the person squats" in texts("squat", "body")
    assert frame_codes(clip("squat"))["pelvis_height"].min() < 0.6


def test_grab_high_right_raises_the_right_arm_only():
    right, left = texts("grab", "right_upper"), texts("grab", "left_upper")
    assert any("right arm is raised" in t for t in right), right
    assert not any("raised" in t for t in left), left


def test_rotate_arms_backward_circles_both_arms():
    for side in ("left", "right"):
        assert f"the {side} arm circles backwards" in texts("rotate", f"{side}_upper")


def test_kick_left_front_kicks_with_the_left_leg():
    assert "the left leg kicks forward" in texts("kick", "left_lower")
    assert not any("kicks" in t for t in texts("kick", "right_lower"))
    assert "the person kicks with the left leg" in texts("kick", "body")


def test_jogging_in_a_left_circle_turns_left():
    body = texts("circle", "body")
    assert any("jogs" in t for t in body), body
    assert any(t.endswith(("turns left", "in a circle to the left")) for t in body), body
    assert not any("right" in t for t in body), body
    heading = frame_codes(clip("circle"))["heading"]
    assert np.degrees(heading[-1] - heading[0]) > 45


@pytest.mark.parametrize("name", ["circle", "grab", "kick", "walk", "rotate"])
def test_mirroring_swaps_left_and_right_captions(name):
    joints = clip(name)
    original = {(c.start, c.end, swap_sides(c.part), swap_sides(c.text)) for c in caption_clip(joints)}
    mirrored = {(c.start, c.end, c.part, c.text) for c in caption_clip(mirror(joints))}
    assert mirrored == original
    codes, flipped = frame_codes(joints), frame_codes(mirror(joints))
    for key, value in codes.items():
        if "left" in key or "right" in key:
            np.testing.assert_array_equal(flipped[swap_sides(key)], value, err_msg=key)
    np.testing.assert_allclose(flipped["heading"], -codes["heading"], atol=1e-9)


def test_positive_yaw_is_a_turn_to_the_persons_left():
    # A standing rest pose (left = +X, facing +Z) spun about +Y: +Z turns towards +X, i.e.
    # towards the person's left hand side.
    rest = sk.rest_joints()
    assert rest[sk.JOINT_INDEX["left_shoulder"], 0] > 0
    for sign, side in ((1.0, "left"), (-1.0, "right")):
        spin = yaw_matrix(sign * np.linspace(0.0, np.pi, 60))
        joints = np.einsum("tij,kj->tki", spin, rest)
        assert frame_codes(joints)[f"turning_{side}"][10:50].all()
        assert [c.text for c in caption_clip(joints) if c.part == "body"] == [f"the person turns {side}"]


def test_captions_tile_each_part_and_merge_equal_neighbours():
    joints = clip("walk")
    caps = caption_clip(joints, window=20)
    for part in ("body", "left_upper", "right_upper", "left_lower", "right_lower"):
        row = [c for c in caps if c.part == part]
        assert row[0].start == 0 and row[-1].end == len(joints)
        assert all(a.end == b.start and a.text != b.text for a, b in zip(row, row[1:]))


def test_describe_is_one_sentence_about_the_body():
    sentence = describe(clip("jump"))
    assert sentence[0].isupper() and sentence.endswith(".") and sentence.count(".") == 1
    assert "jumps" in sentence
    assert "walks forward" in describe(clip("walk"))


def test_bad_input_is_a_value_error():
    with pytest.raises(ValueError):
        frame_codes(np.zeros((10, 21, 3)))
    with pytest.raises(ValueError):
        frame_codes(np.zeros((1, 22, 3)))
    with pytest.raises(ValueError):
        caption_clip(np.full((5, 22, 3), np.nan))
    with pytest.raises(ValueError):
        caption_clip(clip("walk"), window=1)


def test_caption_accuracy_on_the_fixture_clips():
    clips = [Clip(id=n, source="fixture", people=[clip(n)], offsets=[np.zeros((22, 3))],
                  label=label, prompt="") for n, label in LABELS.items()]
    report = caption_accuracy(clips)
    # Families: squat, kick, jog + circle, grab, rotate, hop, walk ×2, run ×2, jump.
    assert report["pairs"] == 12 and report["unscored_items"] == 0
    assert report["any"] == 1.0 and report["dominant"] >= 0.9
    assert set(report["families"]) == {"squat", "kick", "jog", "circle", "grab", "rotate", "hop",
                                       "walk", "run", "jump"}


PROCESSED = Path(os.environ.get("INTERPLAY_DATA_DIR", DATA_DIR))   # models/data unless overridden


@pytest.mark.skipif(not (PROCESSED / "index.json").is_file(), reason="processed set not built")
def test_caption_accuracy_on_the_processed_set():
    clips = [c for c in default_clips(str(PROCESSED)) if not c.synthetic]
    report = caption_accuracy(clips)
    assert report["pairs"] >= 100
    assert report["any"] >= 0.85 and report["dominant"] >= 0.8
    for family in ("walk", "run", "jump", "squat", "kick"):
        assert report["families"][family]["any"] >= 0.8, (family, report["families"][family])
