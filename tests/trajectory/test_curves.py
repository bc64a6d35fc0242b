"""The trajectory editor's curve library: every shape's geometry and make_curve's spec handling."""

import numpy as np
import pytest

from interplay.planner.schema import TrajectorySpec
from interplay.trajectory import curves as cv


def heading(points, i=0):
    """Heading (radians, 0 along +Z, + towards +X) of the curve leaving point i."""
    d = points[i + 1] - points[i]
    return np.arctan2(d[0], d[1])


def on_segment(points, a, b, tol=1e-9):
    """Distance of each point to the segment a-b."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    t = np.clip((points - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1)
    return np.linalg.norm(points - (a + t[:, None] * (b - a)), axis=1)


def total_turn(points):
    d = np.diff(points, axis=0)
    d = d[np.linalg.norm(d, axis=1) > 1e-9]
    th = np.unwrap(np.arctan2(d[:, 0], d[:, 1]))
    return np.degrees(th[-1] - th[0])


@pytest.mark.parametrize("clockwise", [False, True])
def test_circle_has_its_radius_and_turns_the_right_way(clockwise):
    pts = cv.circle(1.5, clockwise=clockwise)
    centre = np.array([-1.5 if clockwise else 1.5, 0.0])     # left (+x) unless clockwise
    assert np.allclose(np.linalg.norm(pts - centre, axis=1), 1.5, atol=1e-9)
    assert np.allclose(pts[0], 0) and np.allclose(pts[-1], 0, atol=1e-9)
    assert abs(heading(pts)) < np.radians(1)
    assert cv.length(pts) == pytest.approx(2 * np.pi * 1.5, rel=1e-3)
    assert total_turn(pts) == pytest.approx(-360 if clockwise else 360, abs=2)


def test_two_turn_circle_goes_round_twice():
    pts = cv.circle(1.0, turns=2)
    assert cv.length(pts) == pytest.approx(4 * np.pi, rel=1e-3)
    assert np.allclose(pts[-1], 0, atol=1e-9)


def test_arc_ends_at_the_quarter_turn():
    pts = cv.arc(2.0, 90.0)
    assert np.allclose(pts[-1], [2.0, 2.0], atol=1e-9)
    assert np.allclose(cv.arc(2.0, 90.0, clockwise=True)[-1], [-2.0, 2.0], atol=1e-9)


@pytest.mark.parametrize("clockwise", [False, True])
def test_square_has_exact_corners_and_straight_sides(clockwise):
    pts = cv.square(2.0, clockwise=clockwise)
    sx = -1.0 if clockwise else 1.0
    corners = np.array([[0, 0], [0, 2], [2 * sx, 2], [2 * sx, 0], [0, 0]], dtype=float)
    for c in corners:
        assert np.linalg.norm(pts - c, axis=1).min() < 1e-12
    side = np.min([on_segment(pts, a, b) for a, b in zip(corners[:-1], corners[1:])], axis=0)
    assert side.max() < 1e-9                        # every point on one of the four sides
    assert cv.length(pts) == pytest.approx(8.0, rel=1e-9)
    assert abs(heading(pts)) < 1e-9


def test_figure_eight_crosses_itself_at_the_origin():
    pts = cv.figure_eight(4.0)
    n = len(pts)
    mid = n // 2
    for i in (0, mid, n - 1):
        assert np.linalg.norm(pts[i]) < 0.02
    # Two loops on opposite sides of the start heading, the first on the left.
    first, second = pts[: mid], pts[mid:]
    assert first[:, 0].max() > 1.0 and first[:, 0].min() > -0.05
    assert second[:, 0].min() < -1.0 and second[:, 0].max() < 0.05
    # A real crossing: through the middle the path leaves at a clear angle to where it started.
    angle = np.degrees(abs(heading(pts, mid) - heading(pts, 0)))
    assert 45 < angle < 135
    ends = pts[np.argsort(np.linalg.norm(pts, axis=1))[-2:]]
    assert np.linalg.norm(ends[0] - ends[1]) > 3.9     # the two loop tips are 4 m apart
    assert cv.figure_eight(4.0, clockwise=True)[n // 4, 0] < 0


def test_zigzag_amplitude_and_corners():
    pts = cv.zigzag(4.0, 0.5, segments=4)
    assert pts[:, 0].max() == pytest.approx(0.5) and pts[:, 0].min() == pytest.approx(-0.5)
    corners = np.array([[0.5, 0.5], [-0.5, 1.5], [0.5, 2.5], [-0.5, 3.5]])
    for c in corners:
        assert np.linalg.norm(pts - c, axis=1).min() < 1e-12
    assert np.allclose(pts[0], 0) and np.allclose(pts[-1], [0, 4])
    assert heading(pts) > 0                          # first leg to the left
    assert heading(cv.zigzag(4.0, 0.5, clockwise=True)) < 0


def test_s_curve_bulges_left_then_right():
    pts = cv.s_curve(4.0, 0.75)
    assert pts[:, 0].max() == pytest.approx(0.75, abs=1e-3)
    assert pts[:, 0].min() == pytest.approx(-0.75, abs=1e-3)
    assert np.argmax(pts[:, 0]) < np.argmin(pts[:, 0])
    assert np.allclose(pts[-1], [0, 4], atol=1e-9)


def test_heart_is_closed_with_its_width():
    pts = cv.heart(2.0)
    assert np.allclose(pts[0], 0) and np.linalg.norm(pts[-1]) < 1e-9
    assert abs(heading(pts)) < np.radians(1)
    # Width measured across the heart's axis, 45° to the left of the start heading.
    axis = np.array([np.sin(np.radians(45)), np.cos(np.radians(45))])
    across = np.array([axis[1], -axis[0]])
    assert np.ptp(pts @ across) == pytest.approx(2.0, rel=1e-3)
    # Mirror symmetric about its axis.
    mirrored = pts - 2 * np.outer(pts @ across, across)
    d = np.linalg.norm(mirrored[:, None] - pts[None], axis=-1).min(axis=1)
    assert d.max() < 0.02
    assert total_turn(pts) == pytest.approx(270, abs=5)      # the tip is the one corner not walked
    assert total_turn(cv.heart(2.0, clockwise=True)) == pytest.approx(-270, abs=5)


def test_spiral_grows_outwards():
    pts = cv.spiral(2.0, 0.5, start_radius=0.25)
    assert 720 < total_turn(pts) < 800
    # Radius of curvature (arc length per radian of turning) near the start and the end:
    # start_radius and start_radius + 2 turns * growth for an Archimedean spiral.
    d = np.diff(pts, axis=0)
    th = np.unwrap(np.arctan2(d[:, 0], d[:, 1]))
    step = np.linalg.norm(d, axis=1)

    def radius(i, n=40):
        return step[i:i + n].sum() / abs(th[i + n] - th[i])
    assert radius(1) == pytest.approx(0.25, rel=0.35)
    assert radius(len(th) - 42) == pytest.approx(1.25, rel=0.05)
    assert abs(heading(pts, 5)) < np.radians(5)
    assert total_turn(cv.spiral(2.0, 0.5, clockwise=True)) < -700


def test_polyline_starts_at_origin_through_waypoints():
    pts = cv.polyline([[0, 2], [-1.5, 3.5]])
    assert np.allclose(pts[0], 0) and np.allclose(pts[-1], [-1.5, 3.5])
    assert np.linalg.norm(pts - [0, 2], axis=1).min() < 1e-12
    assert cv.length(pts) == pytest.approx(2 + np.hypot(1.5, 1.5))


def test_free_curve_keeps_points_and_drops_repeats():
    pts = cv.free([[1, 1], [1, 1], [1.1, 1.5], [1.3, 2.0]])
    assert pts.shape == (3, 2) and np.allclose(pts[0], [1, 1])


# ---- make_curve ------------------------------------------------------------------------

def test_make_curve_sizes():
    circle = cv.make_curve({"shape": "circle", "size_m": 3.0})
    assert np.ptp(circle[:, 0]) == pytest.approx(3.0, rel=1e-3)          # size = diameter
    by_length = cv.make_curve({"shape": "circle", "distance_m": 5.0})
    assert cv.length(by_length) == pytest.approx(5.0, rel=1e-6)
    line = cv.make_curve({"shape": "line", "distance_m": 5.0})
    assert np.allclose(line[-1], [0, 5])
    square = cv.make_curve({"shape": "square", "size_m": 1.5, "clockwise": True})
    assert np.allclose(square[np.argmin(square[:, 0] - square[:, 1])], [-1.5, 1.5])
    zig = cv.make_curve({"shape": "zigzag", "size_m": 1.0, "distance_m": 6.0})
    assert np.ptp(zig[:, 0]) == pytest.approx(1.0) and np.allclose(zig[-1], [0, 6])
    spiral = cv.make_curve({"shape": "spiral", "size_m": 3.0, "turns": 2})
    assert 2.6 < np.ptp(spiral[:, 0]) < 3.4
    arc = cv.make_curve({"shape": "arc", "size_m": 4.0, "turns": 0.5})
    assert np.allclose(arc[-1], [4.0, 0.0], atol=1e-9)
    for shape in cv.SHAPES[:-2]:
        pts = cv.make_curve({"shape": shape, "clockwise": None})            # None = default
        assert pts.shape[1] == 2 and np.allclose(pts[0], 0)


def test_make_curve_turn_at_clock():
    right = cv.make_curve({"shape": "line", "distance_m": 4.0, "turn_at": {"clock": 3}})
    assert np.allclose(right[-1], [-2.0, 2.0], atol=1e-9)                  # right is -x
    back_left = cv.make_curve({"shape": "line", "distance_m": 4.0, "turn_at": {"clock": 8}})
    assert back_left[-1, 0] > 0 and back_left[-1, 1] < 2.0


def test_make_curve_turn_after_and_directions():
    late = cv.make_curve({"shape": "line", "distance_m": 5.0,
                          "turn_at": {"clock": 9, "side": "left", "after_m": 3.0}})
    assert np.allclose(late[-1], [2.0, 3.0], atol=1e-9)                    # 3 m ahead, 2 m left
    no_points = cv.make_curve({"shape": "polyline", "turn_at": {"clock": 3}, "distance_m": 2.0})
    assert np.allclose(no_points[-1], [-1.0, 1.0], atol=1e-9)
    assert np.allclose(cv.make_curve({"shape": "line", "direction": "backward"})[-1], [0, -4])
    assert np.allclose(cv.make_curve({"shape": "line", "direction": "right", "distance_m": 2})[-1],
                       [-2, 0])
    with pytest.raises(ValueError, match="direction"):
        cv.make_curve({"shape": "line", "direction": "up"})


def test_make_curve_takes_the_planners_trajectory_spec():
    schema = pytest.importorskip("interplay.planner.schema")
    spec = schema.TrajectorySpec(shape="circle", clockwise=True, size_m=3.0, text="in a circle")
    pts = cv.make_curve(spec)
    assert np.ptp(pts[:, 0]) == pytest.approx(3.0, rel=1e-3) and pts[len(pts) // 4, 0] < 0
    turn = schema.TrajectorySpec(shape="line", distance_m=4.0, turn_at={"clock": 3, "side": "right"})
    assert np.allclose(cv.make_curve(turn)[-1], [-2.0, 2.0], atol=1e-9)


def test_make_curve_accepts_the_planners_model():
    spec = TrajectorySpec(shape="polyline", waypoints=[(0.5, 0.5), (1.0, 1.0)])
    assert np.allclose(cv.make_curve(spec)[-1], [1, 1])
    with pytest.raises(ValueError, match="dict or a TrajectorySpec"):
        cv.make_curve(["polyline"])


@pytest.mark.parametrize("spec, message", [
    ({"shape": "triangle"}, "unknown trajectory shape"),
    ({}, "unknown trajectory shape"),
    ({"shape": "circle", "size_m": -1}, "size_m must be a positive"),
    ({"shape": "circle", "size_m": "big"}, "size_m must be a number"),
    ({"shape": "spiral", "turns": 0}, "turns must be a positive"),
    ({"shape": "circle", "clockwise": "yes"}, "clockwise must be true or false"),
    ({"shape": "polyline"}, "needs waypoints"),
    ({"shape": "polyline", "waypoints": [[0, 0]]}, "lead away from the origin"),
    ({"shape": "free", "waypoints": [[1, 2, 3]]}, "pairs"),
    ({"shape": "free", "waypoints": [[0, 0], [0, float("nan")]]}, "NaN"),
    ({"shape": "free", "waypoints": [[1, 1], [1, 1]]}, "two distinct points"),
    ({"shape": "line", "turn_at": {"clock": 13}}, "turn_at"),
    ("circle", "dict or a TrajectorySpec"),
])
def test_make_curve_rejects_bad_specs(spec, message):
    with pytest.raises(ValueError, match=message):
        cv.make_curve(spec)
