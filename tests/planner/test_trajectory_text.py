"""Trajectory phrases → TrajectorySpec: shapes, turning sense, distances, clock turns, and no
trajectory for free or in-place motion."""

import pytest

from interplay.planner.trajectory_text import parse, path_length


@pytest.mark.parametrize("text,shape,clockwise", [
    ("walks in a circle clockwise", "circle", True),
    ("runs in a clockwise circle", "circle", True),
    ("walks in a circle counterclockwise", "circle", False),
    ("walks in a counter-clockwise circle", "circle", False),
    ("jogs in an anticlockwise circle", "circle", False),
    ("walks in a circle to the right", "circle", True),
    ("walks around in circles", "circle", None),
    ("runs in a zigzag pattern", "zigzag", None),
    ("walks in a zig-zag", "zigzag", None),
    ("walks in an S shape", "s_curve", None),
    ("walks along an s-curve", "s_curve", None),
    ("walks in the shape of a heart", "heart", None),
    ("runs in a figure eight", "figure_eight", None),
    ("walks in a figure 8", "figure_eight", None),
    ("walks in a square", "square", None),
    ("jogs in a spiral", "spiral", None),
    ("walks in a semicircle to the left", "arc", False),
    ("slides on the knees in a straight line", "line", None),
])
def test_shapes_and_their_turning_sense(text, shape, clockwise):
    spec = parse(text)
    assert spec.shape == shape and spec.clockwise == clockwise


@pytest.mark.parametrize("text,distance,end", [
    ("walks 5 metres forward", 5.0, None),
    ("walks 5 meters forward", 5.0, None),
    ("runs 3 m", 3.0, None),
    ("walks 10 steps forward", 7.0, None),
    ("walks 2 metres to the left", 2.0, (2.0, 0.0)),       # the person's left is +x
    ("walks 3 m to the right", 3.0, (-3.0, 0.0)),
    ("walks 4 metres backwards", 4.0, (0.0, -4.0)),
])
def test_distances_and_directions(text, distance, end):
    spec = parse(text)
    assert spec.distance_m == pytest.approx(distance)
    if end is None:
        assert spec.shape == "line" and spec.direction == "forward"
    else:
        assert spec.shape == "polyline" and tuple(spec.waypoints[-1]) == pytest.approx(end)
    assert path_length(spec) == pytest.approx(distance)


def test_sideways_and_backwards_without_a_distance_and_sizes():
    left, back = parse("walks to the left"), parse("walks backwards")
    assert left.direction == "left" and left.waypoints[-1][0] > 0
    assert back.direction == "backward" and back.waypoints[-1][1] < 0
    assert parse("walks in a 3 m circle").size_m == 3.0
    assert parse("walks in a circle of radius 1.5 m").size_m == 3.0
    assert parse("walks 2 m in a circle").distance_m == 2.0
    assert parse("walks in a square with 2 m sides").size_m == 2.0
    assert path_length(parse("walks in a 3 m circle")) == pytest.approx(3.0 * 3.14159, rel=1e-3)


@pytest.mark.parametrize("text,clock,side", [
    ("turn right at 3 o'clock", 3, "right"),
    ("walks 5 metres and turns right at 3 o'clock", 3, "right"),
    ("turns left towards 9 oclock", 9, "left"),
    ("turns to 2 o'clock", 2, "right"),
])
def test_clock_turns(text, clock, side):
    spec = parse(text)
    assert spec.shape == "line" and spec.turn_at.clock == clock and spec.turn_at.side == side


@pytest.mark.parametrize("text", ["walks forward", "runs", "swings the right arm in circles",
                                  "spins around on one foot", "stands back up", "leans back",
                                  "jumps"])
def test_free_or_in_place_motion_has_no_trajectory(text):
    assert parse(text) is None
