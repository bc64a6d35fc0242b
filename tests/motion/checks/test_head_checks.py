"""The head and edit checks (`motion/checks/heads.py`) on real captures: no captured clip of the
processed set (none of which nods or shakes its head) passes the nod or the shake, and the same
captures with the head turned about the neck joint — nodding, shaking, looking up or down, as
a head edit would make them — pass exactly the check that names it."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.checks import heads as H
from interplay.motion.checks import measures as M
from interplay.motion.checks.named import run_check
from interplay.motion.clip import default_clips

J = sk.JOINT_INDEX


def standing() -> list[np.ndarray]:
    """Bandai captures of a person standing and talking, pointing the way or waving goodbye,
    those whose body is calm (`heads.calm`) in ≥ 90 % of the frames."""
    out = [np.asarray(c.people[0], np.float64) for c in default_clips()
           if c.source == "bandai-namco" and c.label.split(" (")[0] in ("respond", "guide", "bye")
           and len(c.people) == 1]
    out = [j for j in out if H.calm(M.frame_of(j)).mean() >= 0.9]
    assert len(out) >= 10
    return out


def _rotate(v: np.ndarray, axis: np.ndarray, deg: np.ndarray) -> np.ndarray:
    """Rodrigues: vectors v (T, 3) turned about unit axes (T, 3) by deg (T,)."""
    a = np.radians(deg)[:, None]
    return (v * np.cos(a) + np.cross(axis, v) * np.sin(a)
            + axis * (axis * v).sum(1, keepdims=True) * (1 - np.cos(a)))


def head_turned(j: np.ndarray, pitch_up: np.ndarray | float = 0.0,
                yaw_left: np.ndarray | float = 0.0) -> np.ndarray:
    """The capture with the head joint turned about the neck joint: up about the shoulders'
    axis (+ looks up), then left about the vertical (+ to the person's left)."""
    t = len(j)
    pitch, yaw = np.broadcast_to(pitch_up, (t,)), np.broadcast_to(yaw_left, (t,))
    left = j[:, J["left_shoulder"]] - j[:, J["right_shoulder"]]
    left /= np.linalg.norm(left, axis=1, keepdims=True)
    vertical = np.broadcast_to(np.array([0.0, 1.0, 0.0]), (t, 3))
    bone = j[:, sk.HEAD] - j[:, sk.NECK]
    bone = _rotate(bone, -left, pitch)             # about −left: the head tips back
    bone = _rotate(bone, vertical, yaw)
    out = j.copy()
    out[:, sk.HEAD] = j[:, sk.NECK] + bone
    return out


def wave(j: np.ndarray, amplitude: float, hz: float) -> np.ndarray:
    return amplitude * np.sin(2 * np.pi * hz * np.arange(len(j)) / sk.FPS)


def check(j, base=None, **spec):
    return run_check([j], spec, base=None if base is None else [base])


def test_no_captured_clip_nods_or_shakes_its_head():
    one = [np.asarray(c.people[0], np.float64) for c in default_clips() if len(c.people) == 1]
    assert len(one) > 900
    nods = sum(check(j, check="head_nod").passed for j in one)
    shakes = sum(check(j, check="head_shake").passed for j in one)
    # None nods; two (Bandai's youthful waves, whose head goes with the waving hand) pass as
    # shakes.
    assert nods == 0 and shakes <= 0.002 * len(one), (nods, shakes)


def test_a_nod_made_on_a_capture_is_a_nod_and_no_shake():
    for j in standing():
        nodding = head_turned(j, pitch_up=wave(j, 15.0, 1.5))         # ±15° at 1.5 Hz
        assert check(nodding, check="head_nod").passed
        assert not check(nodding, check="head_shake").passed
        assert not check(j, check="head_nod").passed


def test_a_shake_made_on_a_capture_is_a_shake():
    # Only where the neck → head bone leans enough for a turn to move the head joint (see
    # heads.py): those of these captures with ≥ 3 cm of horizontal part.
    leaning = [j for j in standing()
               if np.median(np.hypot(*(j[:, sk.HEAD] - j[:, sk.NECK])[:, [0, 2]].T)) >= 0.03]
    assert len(leaning) >= 3
    for j in leaning:
        shaking = head_turned(j, yaw_left=wave(j, 35.0, 1.2))         # ±35° at 1.2 Hz
        assert check(shaking, check="head_shake").passed
        assert not check(j, check="head_shake").passed
        small = head_turned(j, yaw_left=wave(j, 8.0, 1.2))            # a 16° glance is no shake
        assert not check(small, check="head_shake").passed
    # Not tested: that a shake is no nod. These captures' head bones lean sideways (their
    # shoulders tilt ~15°), so a turn about the vertical also tips the bone in the chest's
    # front-to-back plane, and the nod check cannot tell the two apart there.


@pytest.mark.parametrize("deg,up,down", [(35.0, True, False), (-35.0, False, True),
                                         (10.0, False, False), (0.0, False, False)])
def test_looking_up_or_down_is_measured_against_the_base(deg, up, down):
    for j in standing()[:5]:
        edited = head_turned(j, pitch_up=deg)
        assert check(edited, j, check="head_pitch_over_base", direction="up").passed is up
        assert check(edited, j, check="head_pitch_over_base", direction="down").passed is down
        assert check(edited, j, check="rest_unchanged", part="head").passed


def test_the_rest_of_the_body_must_stay_where_the_base_had_it():
    j = standing()[0]
    shifted = j + np.array([0.05, 0.0, 0.0])                          # the whole body 5 cm over
    assert not check(shifted, j, check="rest_unchanged", part="head").passed
    arm = j.copy()
    arm[:, [J["right_elbow"], J["right_wrist"]]] += np.array([0.0, 0.2, 0.0])
    assert check(arm, j, check="rest_unchanged", part="right_arm").passed
    assert not check(arm, j, check="rest_unchanged", part="head").passed
    assert not check(arm, j, check="rest_unchanged", part="left_arm").passed


def test_edit_checks_need_their_base():
    j = standing()[0]
    with pytest.raises(ValueError, match="base"):
        check(j, check="rest_unchanged")
    with pytest.raises(ValueError, match="shape"):
        check(j[:-5], j, check="head_pitch_over_base")
    assert H.head_pitch(M.frame_of(j)).shape == (len(j),)
