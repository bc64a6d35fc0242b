"""formats/floor.py on every library clip that goes low (acrobatics, kneeling, crawling, lying
down: a wrist or knee within 25 cm of the floor): no hand, knee or foot of the exports' body —
the GLB's skinned mesh, the BVH's joints and end sites — more than 1 cm under the floor, at
the motion's rate and resampled to 30 fps; the lift is smooth and only where needed.
`interplay export-floor` prints the same as a table."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion.clip import default_clips
from interplay.motion.formats.floor import TOLERANCE, depths, floor_pass, goes_low, worst
from interplay.motion.formats.presets import export_rigs
from interplay.motion.kinematics import floor_height
from interplay.motion.rig import solve_rig


@pytest.fixture(scope="module")
def low_clips():
    out = []
    for clip in default_clips():
        people = [np.asarray(p, np.float64) for p in clip.people]
        if goes_low(people, floor_height(people)):
            out.append((clip.id, people))
    # The library's acrobatics and floor work: rolls, cartwheels, crawls, lying down.
    assert len(out) >= 40 and any("roll" in c for c, _ in out) and any("crawl" in c for c, _ in out)
    return out


@pytest.mark.parametrize("body", ["mesh", "joints"])
def test_no_hand_knee_or_foot_under_the_floor_in_any_low_library_clip(low_clips, body):
    deepest_before = 0.0
    for clip_id, people in low_clips:
        floor = floor_height(people)
        for rig in export_rigs(people, body=body):
            got = worst(rig, floor, body)
            assert max(got.values()) <= TOLERANCE, (clip_id, got)
        deepest_before = max(deepest_before, *worst(solve_rig(people[0], floor=floor), floor, body).values())
    # The pass had work to do: without it, something went deeper than 1 cm.
    assert deepest_before > 2 * TOLERANCE


def test_resampled_exports_stay_above_the_floor_too(low_clips):
    for clip_id, people in low_clips[::4]:
        floor = floor_height(people)
        for rig in export_rigs(people, 20, 30, body="mesh"):
            assert max(worst(rig, floor, "mesh").values()) <= TOLERANCE, clip_id


def test_the_lift_is_smooth_and_only_where_needed(low_clips):
    for clip_id, people in low_clips:
        floor = floor_height(people)
        rig = solve_rig(people[0], floor=floor)
        lifted, lift = floor_pass(rig, floor, "mesh")
        need = np.max(np.stack(list(depths(rig, floor, "mesh").values())), axis=0)
        assert np.all(lift >= 0)
        # Nothing lifted more than 2 frames away from a frame that needed it.
        needed = need > 0.004
        near = np.convolve(needed.astype(float), np.ones(9), mode="same") > 0
        assert not np.any((lift > 1e-9) & ~near), clip_id
        # The lift eases in and out: at most 3 cm a frame (a fall onto the knees is faster).
        assert np.abs(np.diff(lift)).max() < 0.03 + np.abs(np.diff(need)).max(), clip_id
        assert np.array_equal(lifted.rotations, rig.rotations)
