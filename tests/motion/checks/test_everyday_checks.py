"""The everyday-action checks (`motion/checks/everyday.py`) on real captures of the processed
data: each passes on captures that do the thing and fails on captures that do not (or on the
same capture changed so that it no longer does)."""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import everyday as E
from interplay.motion.checks import measures as M
from interplay.motion.checks.named import run_check
from interplay.motion.clip import default_clips


def people(source: str, label: str) -> list[np.ndarray]:
    out = [np.asarray(c.people[0], np.float64) for c in default_clips()
           if c.source == source and c.label == label and len(c.people) == 1]
    assert out, f"no {source} clips labelled {label}"
    return out


def check(j: np.ndarray, **spec):
    return run_check([j], spec)


WALKS = people("cmu-bvh", "walk") + people("bandai-namco", "walk (normal)")


def test_hands_meet_counts_the_hands_coming_together():
    wash = people("cmu-iclone", "wash self")[0]                 # soaping hands and arms
    assert check(wash, check="hands_meet", at_least=2).passed
    signals = people("cmu-8action", "basketball_signal")        # a referee's two-hand signals
    assert np.mean([check(j, check="hands_meet").passed for j in signals]) >= 0.6
    assert not any(check(j, check="hands_meet").passed for j in WALKS)   # hands apart
    # The same capture with the left hand's arm held 30 cm further out: they never meet.
    apart = wash.copy()
    left = [sk.JOINT_INDEX[n] for n in ("left_elbow", "left_wrist")]
    apart[:, left] += 0.3 * M.frame_of(wash).left[:, None]
    assert check(apart, check="hands_meet").value == 0


def test_a_hand_at_the_face_is_held_not_passed_through():
    assert check(people("cmu-iclone", "wash self")[0], check="hand_to_face", min_s=1.0).passed
    guards = people("bandai-namco", "punch (normal)")           # a boxer's guard at the chin
    assert all(check(j, check="hand_to_face", min_s=1.0).passed for j in guards)
    # Raising both hands sweeps them past the face without stopping there; walks never come near.
    raised = people("bandai-namco", "raise-up-both-hands (normal)")
    assert not any(check(j, check="hand_to_face", min_s=1.0).passed for j in raised + WALKS)


def test_hand_pumps_are_strokes_in_place_not_an_arm_swung_by_the_gait():
    window = people("cmu-8action", "washwindow")[0]             # scrubbing a window
    traffic = people("cmu-8action", "directing_traffic")[0]     # waving cars on
    assert check(window, check="hand_pumps", hand="right", axis="up").passed
    assert check(window, check="hand_pumps", hand="right", axis="side").passed
    assert not check(window, check="hand_pumps", hand="left", axis="up").passed   # it holds still
    assert check(traffic, check="hand_pumps", axis="up").passed
    runs = people("bandai-namco", "run (normal)")
    squats = people("hdm05", "squat1Reps")[:10]
    for j in WALKS + runs + squats:
        for axis in ("up", "side", "forward"):
            assert not check(j, check="hand_pumps", axis=axis).passed, axis


def test_lying_face_down_or_up_needs_the_torso_flat_and_low():
    crawl = people("deepmimic", "crawl")[0]
    facedown = people("deepmimic", "getup_facedown")[0]
    assert check(crawl, check="lies_on", side="front").passed
    assert check(facedown, check="lies_on", side="front", min_s=0.5).passed
    assert not check(facedown, check="lies_on", side="back", min_s=0.5).passed
    lie_downs = people("hdm05", "lieDownFloor")                 # they end on their backs
    assert np.mean([check(j, check="lies_on", side="back").passed for j in lie_downs]) >= 0.9
    assert not any(check(j, check="lies_on", side="front").passed for j in lie_downs)
    assert check(people("deepmimic", "getup_faceup")[0], check="lies_on", side="back").passed
    # Reaching down to the floor tips the torso flat but keeps the pelvis up: not lying.
    deposits = people("hdm05", "depositFloorR")
    assert not any(check(j, check="lies_on", side="front").passed for j in deposits)
    assert not any(check(j, check="lies_on", side=s).passed for j in WALKS for s in ("front", "back"))


def _sit_up() -> np.ndarray:
    """Captured DeepMimic get-up from lying on the back, cut where the torso is upright and the
    pelvis still on the floor, then played back to lying: one sit-up of real motion."""
    j = people("deepmimic", "getup_faceup")[0]
    b = M.frame_of(j)
    top = int(np.flatnonzero((b.tilt <= 20) & (M.pelvis_ratio(b) < 0.3))[0])
    return np.concatenate([j[:top + 1], j[top::-1]])


def test_sit_ups_count_curls_from_lying_back_to_lying():
    one = _sit_up()
    assert check(one, check="sit_ups", count=1).passed
    assert check(np.concatenate([one, one]), check="sit_ups", count=2).passed
    # Getting up from the back never lies back down; a lie-down never curls up.
    assert check(people("deepmimic", "getup_faceup")[0], check="sit_ups").value == 0
    assert not any(check(j, check="sit_ups").passed for j in people("hdm05", "lieDownFloor"))
    assert not any(check(j, check="sit_ups").passed for j in WALKS)


def _limping(j: np.ndarray) -> np.ndarray:
    """A captured walk with every frame in which the right foot is planted and the left is not
    played twice: the body stays twice as long on the right foot alone."""
    b = M.frame_of(j)
    right = b.foot_height("right") < M.AIRBORNE_M
    left = b.foot_height("left") < M.AIRBORNE_M
    return np.repeat(j, np.where(right & ~left, 2, 1), axis=0)


NORMAL_WALKS = ("walk (normal)", "walk-turn-left (normal)", "walk-turn-right (normal)",
                "walk-left (normal)", "walk-right (normal)")


def test_an_uneven_gait_is_less_time_on_one_foot_than_the_other():
    normal = [j for label in NORMAL_WALKS for j in people("bandai-namco", label)]
    results = [check(j, check="uneven_gait") for j in normal]
    assert not any(r.passed for r in results)                   # level captured walks
    measured = [j for j, r in zip(normal, results) if not isinstance(r.value, dict)]
    assert len(measured) >= 8                                   # long enough to compare
    assert all(check(_limping(j), check="uneven_gait").passed for j in measured)
    assert not check(np.asarray(WALKS[0][:20]), check="uneven_gait").passed   # too short to say


def test_single_support_leaves_out_stretches_cut_by_the_clip():
    b = M.frame_of(people("bandai-namco", "walk (normal)")[0])
    for side in M.SIDES:
        times = E.single_support(b, side)
        assert len(times) >= 3 and all(0.1 < t < 0.8 for t in times)   # a step on one foot
