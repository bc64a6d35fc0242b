"""Directions of travel in the trajectory editor: backwards and sideways along a path never turn
the person round; the facing stays at the path's tangent rotated by the direction of travel.
Real walks from the processed set (the test-split clips prompted "a person walks forward")."""

import numpy as np
import pytest

from interplay.eval.trajectory import walk_clips
from interplay.motion.kinematics import facing_angle
from interplay.planner.trajectory_text import parse
from interplay.trajectory import apply as tj
from interplay.trajectory import curves as cv
from interplay.trajectory.travel import OFFSET, spec_travel


@pytest.fixture(scope="module")
def walk():
    return walk_clips()[0].people[0].astype(np.float64)


def wrap_deg(a):
    return np.degrees(np.abs((np.asarray(a) + np.pi) % (2 * np.pi) - np.pi))


def facing_vs_tangent(joints, curve):
    """Facing minus the curve's tangent heading at the nearest curve point, radians (T,)."""
    near = np.linalg.norm(joints[:, 0, [0, 2]][:, None] - curve[None], axis=-1).argmin(axis=1)
    tangent = np.gradient(curve, axis=0)[near]
    return facing_angle(joints) - np.arctan2(tangent[:, 0], tangent[:, 1])


def sideways(joints, left=True):
    """The walk with every frame's body turned 90° about its pelvis: the same path stepped
    sideways (to the left when the body faces 90° to the right of the path)."""
    rel = joints[..., [0, 2]] - joints[:, :1, [0, 2]]
    out = joints.copy()
    rot = np.stack([-rel[..., 1], rel[..., 0]], axis=-1) if left else \
        np.stack([rel[..., 1], -rel[..., 0]], axis=-1)
    out[..., [0, 2]] = joints[:, :1, [0, 2]] + rot
    return out


def test_the_planners_backwards_and_sideways_phrases_are_directions_of_travel():
    assert spec_travel(parse("walks backwards")) == "backward"
    assert spec_travel(parse("runs backwards 5 metres")) == "backward"
    assert spec_travel(parse("steps sideways to the left")) == "left"
    assert spec_travel(parse("side-steps to the right")) == "right"
    # A walk "to the left" turns and walks there; "walks back" may return: paths, not travel.
    assert spec_travel(parse("walks to the left")) is None
    assert spec_travel(parse("walks in a circle")) is None
    assert spec_travel({"shape": "circle", "travel": "backward"}) == "backward"
    with pytest.raises(ValueError, match="travel"):
        tj.map_trajectory(np.zeros((10, 22, 3)), cv.make_curve({"shape": "line"}), travel="up")


def test_a_backward_walk_on_the_planners_backward_line_is_not_turned(walk):
    back = walk[::-1].copy()                     # a forward walk played backwards: walks backwards
    out = tj.apply_trajectory(back, parse("walks backwards"))
    start = facing_angle(back[:10]).mean()
    assert np.median(wrap_deg(facing_angle(out) - start)) < 10      # faces where it faced
    ahead = np.array([np.sin(start), np.cos(start)])
    travelled = out[-1, 0, [0, 2]] - out[0, 0, [0, 2]]
    assert travelled @ ahead < -0.9 * np.linalg.norm(travelled)     # …and went behind itself


@pytest.mark.parametrize("shape", ["circle", "s_curve", "zigzag"])
def test_backward_travel_along_any_path_faces_away_from_the_tangent(walk, shape):
    back = walk[::-1].copy()
    r = tj.map_trajectory(back, cv.make_curve({"shape": shape}), travel="backward")
    off = facing_vs_tangent(r["joints"], r["curve"])
    assert np.median(wrap_deg(off - OFFSET["backward"])) < 15
    assert wrap_deg(r["facing_fix"]) < 15          # it walked backwards already: little to fix


def test_a_forward_walk_told_to_travel_backwards_is_never_turned_round(walk):
    # Without a direction of travel the editor turns a forward walk round to follow a line
    # behind it; with one it keeps it facing forward (the motion must then walk backwards
    # itself — this one does not, and the fix reports how far it was off).
    line = cv.make_curve({"shape": "line", "direction": "backward"})
    turned = tj.map_trajectory(walk, line)
    assert np.median(wrap_deg(turned["turn"])) > 150
    kept = tj.map_trajectory(walk, line, travel="backward")
    start = facing_angle(walk[:10]).mean()
    assert np.median(wrap_deg(facing_angle(kept["joints"]) - start)) < 15
    assert wrap_deg(kept["facing_fix"]) > 150


@pytest.mark.parametrize("left", [True, False])
def test_side_steps_along_a_path_face_across_it(walk, left):
    side = sideways(walk, left)
    way = "left" if left else "right"
    r = tj.map_trajectory(side, cv.make_curve({"shape": "arc"}), travel=way)
    off = facing_vs_tangent(r["joints"], r["curve"])
    assert np.median(wrap_deg(off - OFFSET[way])) < 15
    # The planner's "steps sideways to the left" line: stepped to the left, facing as it did.
    if left:
        out = tj.apply_trajectory(side, parse("steps sideways to the left"))
        start = facing_angle(side[:10]).mean()
        assert np.median(wrap_deg(facing_angle(out) - start)) < 15
        to_left = np.array([np.cos(start), -np.sin(start)])
        travelled = out[-1, 0, [0, 2]] - out[0, 0, [0, 2]]
        assert travelled @ to_left > 0.9 * np.linalg.norm(travelled)
