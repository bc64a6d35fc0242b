"""The trajectory editor on real walks from the processed set (test-split clips prompted
"a person walks forward"): end point, heading, foot skating, bone lengths, what is kept."""

from dataclasses import replace

import numpy as np
import pytest

from interplay.eval.trajectory import (
    EXAMPLE_SPECS,
    heading_error,
    markdown,
    measure,
    shape_table,
    walk_clips,
)
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.kinematics import facing_angle
from interplay.trajectory import apply as tj
from interplay.trajectory import bspline
from interplay.trajectory import curves as cv

LEG_JOINTS = {sk.JOINT_INDEX[f"{side}_{j}"] for side in ("left", "right")
              for j in ("knee", "ankle", "foot")}
UPPER = [j for j in range(sk.NUM_JOINTS) if j not in LEG_JOINTS]   # moved only with the frame


@pytest.fixture(scope="module")
def walks():
    clips = walk_clips()
    assert len(clips) >= 4
    return [c.people[0].astype(np.float64) for c in clips]


def wrap_deg(a):
    return np.degrees(np.abs((a + np.pi) % (2 * np.pi) - np.pi))


def test_walk_on_a_circle_ends_where_the_circle_does(walks):
    for joints in walks:
        r = tj.map_trajectory(joints, cv.make_curve({"shape": "circle"}))
        out = r["joints"]
        # A circle ends where it starts: at the walk's first pelvis position.
        assert np.linalg.norm(out[-1, 0, [0, 2]] - joints[0, 0, [0, 2]]) <= 0.05
        # The pelvis stays on the (scaled) circle, up to the walk's sideways sway.
        radius = 1.0 * r["scale"]                        # default circle: 2 m across
        centre = r["curve"].mean(axis=0)                 # evenly resampled closed circle
        ring = np.abs(np.linalg.norm(out[:, 0, [0, 2]] - centre, axis=1) - radius)
        assert ring.max() < 0.08, ring.max()
        assert np.median(heading_error(out, r["curve"])) <= 15


def test_skating_stays_within_20_percent_and_pinning_is_what_does_it(walks):
    before, unpinned, after = [], [], []
    for joints in walks:
        spec = cv.make_curve({"shape": "circle"})
        before.append(tj.skating(joints))
        after.append(tj.skating(tj.apply_trajectory(joints, spec)))
        unpinned.append(tj.skating(tj.map_trajectory(
            joints, spec, cfg=replace(tj.DEFAULT, pin_feet=False))["joints"]))
        assert after[-1] <= 1.2 * before[-1], (before[-1], after[-1])
    # Turning without pinning slides the planted feet round the pelvis.
    assert np.mean(unpinned) > 1.3 * np.mean(before)


def test_bones_keep_their_lengths_and_the_upper_body_moves_rigidly(walks):
    joints = walks[0]
    for name in ("circle", "square", "figure_eight"):
        out = tj.apply_trajectory(joints, {"shape": name})
        assert np.abs(sk.bone_lengths(out) - sk.bone_lengths(joints)).max() < 1e-9
        # Trunk, arms and head only turn with the frame: distances to the pelvis are kept.
        d0 = np.linalg.norm(joints[:, UPPER] - joints[:, :1], axis=-1)
        d1 = np.linalg.norm(out[:, UPPER] - out[:, :1], axis=-1)
        assert np.abs(d1 - d0).max() < 1e-9
        assert np.allclose(out[..., 1], joints[..., 1], atol=0.03)      # heights barely move


def test_with_offsets_the_result_is_refitted_on_them():
    clip = next(c for c in walk_clips())
    joints, offsets = clip.people[0].astype(np.float64), clip.offsets[0].astype(np.float64)
    out = tj.apply_trajectory(joints, {"shape": "circle"}, offsets=offsets)
    rest = sk.bone_lengths(sk.rest_joints(offsets))
    assert np.abs(sk.bone_lengths(out) - rest).max() < 1e-6
    assert tj.skating(out) <= 1.2 * tj.skating(joints)


@pytest.mark.parametrize("name", list(EXAMPLE_SPECS))
def test_every_shape_on_a_real_walk(walks, name):
    m = measure(walks[1], EXAMPLE_SPECS[name])
    assert m["end_error"] <= 0.05
    assert m["heading_error"] <= 15
    assert m["skating_after"] <= 1.2 * m["skating_before"]


def test_straight_walk_on_a_line_is_only_moved_rigidly(walks):
    joints = walks[0]
    out = tj.apply_trajectory(joints, {"shape": "line"})
    # Pairwise distances between all joints per frame stay (a straight walk needs almost no turning).
    pd = lambda j: np.linalg.norm(j[:, :, None] - j[:, None], axis=-1)
    assert np.abs(pd(out) - pd(joints)).max() < 0.03


def signed_tangent_offset(joints, curve):
    """Facing minus the curve's tangent heading at the nearest curve point, radians (T,)."""
    near = np.linalg.norm(joints[:, 0, [0, 2]][:, None] - curve[None], axis=-1).argmin(axis=1)
    tangent = np.gradient(curve, axis=0)[near]
    return facing_angle(joints) - np.arctan2(tangent[:, 0], tangent[:, 1])


def test_backwards_walk_keeps_walking_backwards(walks):
    back = walks[0][::-1].copy()            # a forward walk played backwards
    r = tj.map_trajectory(back, cv.make_curve({"shape": "circle"}))
    err = heading_error(r["joints"], r["curve"])     # facing vs direction of travel
    assert np.median(np.abs(err - 180)) < 15
    assert np.linalg.norm(r["joints"][-1, 0, [0, 2]] - back[0, 0, [0, 2]]) <= 0.05
    # The planner draws "walks backwards" behind the person (their start frame): a backwards
    # walk needs no turning to follow it, and ends 4 m behind where it faced.
    line = tj.map_trajectory(back, cv.make_curve({"shape": "line", "direction": "backward"}))
    assert np.median(wrap_deg(line["turn"])) < 10
    behind = -4.0 * np.array([np.sin(facing_angle(back[:10])).mean(), np.cos(facing_angle(back[:10])).mean()])
    end = line["joints"][-1, 0, [0, 2]] - back[0, 0, [0, 2]]
    assert np.linalg.norm(end / np.linalg.norm(end) - behind / 4.0) < 0.15


def test_forward_walk_told_to_go_left_turns_left(walks):
    joints = walks[0]
    r = tj.map_trajectory(joints, cv.make_curve({"shape": "line", "direction": "left"}))
    start = facing_angle(joints[:10]).mean()
    left = np.array([np.cos(start), -np.sin(start)])    # +X of the person's frame in the world
    end = r["joints"][-1, 0, [0, 2]] - joints[0, 0, [0, 2]]
    assert end @ left > 0.95 * np.linalg.norm(end)
    assert np.median(heading_error(r["joints"], r["curve"])) < 15


def test_side_step_keeps_its_offset(walks):
    joints = walks[0]
    # Turn every frame's body 90° about its pelvis: the same path walked sideways.
    rel = joints[..., [0, 2]] - joints[:, :1, [0, 2]]
    side = joints.copy()
    side[..., [0, 2]] = joints[:, :1, [0, 2]] + np.stack([rel[..., 1], -rel[..., 0]], axis=-1)
    offset = facing_angle(side) - tj.travel(side).heading          # about ±90°
    assert np.median(wrap_deg(offset)) > 60
    for anchor in ("facing", "travel"):
        r = tj.map_trajectory(side, cv.make_curve({"shape": "s_curve"}),
                              cfg=replace(tj.DEFAULT, anchor=anchor))
        kept = signed_tangent_offset(r["joints"], r["curve"])
        assert np.median(wrap_deg(kept - offset)) < 10


def test_standing_motion_is_left_in_place():
    squat = next(c for c in default_clips() if "squats" in c.prompt).people[0].astype(np.float64)
    r = tj.map_trajectory(squat, cv.make_curve({"shape": "circle"}))
    assert not r["moving"]
    assert np.abs(r["joints"] - squat).max() < 1e-9
    # Anchored to the world it is moved to the curve's start, facing along it.
    world = tj.map_trajectory(squat, [[2.0, 1.0], [1.0, 1.0], [0.0, 1.0]],
                              cfg=replace(tj.DEFAULT, anchor="world"))
    assert np.allclose(world["joints"][0, 0, [0, 2]], [2.0, 1.0], atol=1e-6)
    assert wrap_deg(facing_angle(world["joints"][:1])[0] + np.pi / 2) < 1


def test_keeping_the_curve_size_keeps_the_speed(walks):
    joints = walks[0]
    walked = tj.travel(joints).s[-1]
    big = {"shape": "circle", "size_m": 4.0}                 # 12.6 m round, longer than the walk
    r = tj.map_trajectory(joints, cv.make_curve(big), cfg=replace(tj.DEFAULT, scale_to_motion=False))
    assert r["scale"] == 1.0
    pelvis = r["joints"][:, 0, [0, 2]]
    centre = r["curve"][np.argmax(np.linalg.norm(r["curve"] - r["curve"][0], axis=1))] / 2 \
        + r["curve"][0] / 2
    assert np.abs(np.linalg.norm(pelvis - centre, axis=1) - 2.0).max() < 0.08
    # It stops short of the circle's end, after walking its own distance along it.
    along = np.linalg.norm(r["curve"] - pelvis[-1], axis=1).argmin() * tj.DEFAULT.spacing
    assert along == pytest.approx(walked, abs=0.1)
    # Its speed per frame is the original's.
    v0 = np.linalg.norm(np.diff(joints[:, 0, [0, 2]], axis=0), axis=1)
    v1 = np.linalg.norm(np.diff(pelvis, axis=0), axis=1)
    assert np.abs(v1 - v0).mean() < 0.01


def test_world_anchor_puts_the_walk_on_a_drawn_path(walks):
    joints = walks[2]
    drawn = [[2.0 - 0.5 * i, 1.0 + 0.1 * np.sin(i)] for i in range(12)]   # heading -X
    r = tj.map_trajectory(joints, drawn, cfg=replace(tj.DEFAULT, anchor="world"))
    assert np.linalg.norm(r["joints"][0, 0, [0, 2]] - [2.0, 1.0]) < 0.05
    assert np.linalg.norm(r["joints"][-1, 0, [0, 2]] - r["curve"][-1]) < 0.05
    assert np.median(heading_error(r["joints"], r["curve"])) < 15


@pytest.mark.parametrize("stretch", [0.6, 1.7])
def test_a_drawn_path_is_walked_to_its_end_at_its_own_size(walks, stretch):
    # The studio's drawn paths: world coordinates, kept size, the walk retimed to cover them.
    joints = walks[1]
    walked = tj.travel(joints).s[-1]
    xs = np.linspace(0.0, 1.0, 15)
    drawn = np.stack([3.0 * xs, 1.5 * np.sin(np.pi * xs)], axis=1)
    drawn *= stretch * walked / np.linalg.norm(np.diff(drawn, axis=0), axis=1).sum()
    cfg = replace(tj.DEFAULT, anchor="world", scale_to_motion=False, retime=True)
    r = tj.map_trajectory(joints, drawn, cfg=cfg)
    assert r["scale"] == 1.0 and r["speed"] == pytest.approx(stretch, rel=0.1)
    # Ends at the drawn end; a much faster walk's planted feet may hold the root back a little
    # (footlock's bounded root shift), so the bound is the shift's, not the curve's.
    assert np.linalg.norm(r["joints"][-1, 0, [0, 2]] - drawn[-1]) <= 0.15
    assert np.linalg.norm(r["joints"][0, 0, [0, 2]] - drawn[0]) <= 0.15
    assert np.median(heading_error(r["joints"], r["curve"])) < 15
    unpinned = tj.map_trajectory(joints, drawn, cfg=replace(cfg, pin_feet=False))
    assert np.linalg.norm(unpinned["joints"][-1, 0, [0, 2]] - drawn[-1]) <= 0.05
    assert np.linalg.norm(unpinned["joints"][0, 0, [0, 2]] - drawn[0]) <= 0.05
    assert np.allclose(sk.bone_lengths(r["joints"]), sk.bone_lengths(joints), atol=1e-6)


def test_free_drawn_noisy_points_are_smoothed_and_evenly_resampled():
    rng = np.random.default_rng(3)
    t = np.cumsum(rng.uniform(0.2, 1.8, 150))
    t = t / t[-1] * 1.5 * np.pi
    true = np.stack([1.5 * np.cos(t), 1.5 * np.sin(t)], axis=1)
    noisy = true + rng.normal(0.0, 0.03, true.shape)
    noisy = np.concatenate([noisy[:40], np.repeat(noisy[40:41], 4, axis=0), noisy[40:]])
    curve = tj.smooth_curve(cv.free(noisy))
    off = lambda p: np.linalg.norm(p, axis=1) - 1.5        # distance from the true circle
    assert np.sqrt(np.mean(off(curve.points) ** 2)) < 0.6 * np.sqrt(np.mean(off(noisy) ** 2))
    step = np.linalg.norm(np.diff(curve.points, axis=0), axis=1)
    raw_step = np.linalg.norm(np.diff(noisy, axis=0), axis=1)
    assert step.std() / step.mean() < 0.01 < raw_step.std() / raw_step.mean()
    assert step.mean() == pytest.approx(tj.DEFAULT.spacing, rel=0.01)
    assert np.allclose(curve.points[[0, -1]], noisy[[0, -1]])           # ends kept exactly
    # The drawn path's jitter is gone from the heading: it turns smoothly, ~1.5π in total.
    assert np.degrees(np.abs(np.diff(curve.heading))).max() < 3
    assert curve.heading[-1] - curve.heading[0] == pytest.approx(-1.5 * np.pi, rel=0.1)


def test_resampled_analytic_curves_keep_their_shape():
    circle = tj.resample_curve(cv.circle(1.0))
    assert np.abs(np.linalg.norm(circle - [1.0, 0.0], axis=1) - 1.0).max() < 0.01
    square = tj.resample_curve(cv.square(2.0))
    # Corners are rounded into short turns; the sides stay straight.
    assert 0.03 < np.linalg.norm(square - [0.0, 2.0], axis=1).min() < 0.15
    assert np.abs(square[(square[:, 1] > 0.5) & (square[:, 1] < 1.5) & (square[:, 0] < 1), 0]).max() < 0.005


def test_bspline_reproduces_a_cubic_and_its_derivative():
    u = np.linspace(0, 1, 200)
    y = 2 * u ** 3 - u ** 2 + 0.5
    coef = bspline.fit(u, y, 5, penalty=0.0)
    assert np.abs(bspline.evaluate(coef, u) - y).max() < 1e-8
    assert np.abs(bspline.evaluate(coef, u, 1) - (6 * u ** 2 - 2 * u)).max() < 1e-6
    assert np.allclose(bspline.basis(u, 7).sum(axis=1), 1.0)


@pytest.mark.parametrize("args, message", [
    ((np.zeros((10, 21, 3)), [[0, 0], [0, 1]]), "shape"),
    ((np.full((10, 22, 3), np.nan), [[0, 0], [0, 1]]), "NaN"),
])
def test_bad_input_raises(args, message):
    with pytest.raises(ValueError, match=message):
        tj.map_trajectory(*args)


def test_bad_curve_and_anchor_raise(walks):
    with pytest.raises(ValueError, match="two distinct points"):
        tj.map_trajectory(walks[0], [[0, 0], [0, 0]])
    with pytest.raises(ValueError, match="anchor"):
        tj.map_trajectory(walks[0], [[0, 0], [0, 1]], cfg=replace(tj.DEFAULT, anchor="moon"))
    with pytest.raises(ValueError, match="unknown trajectory shape"):
        tj.apply_trajectory(walks[0], {"shape": "moon"})


def test_report_table(walks):
    clips = walk_clips()[:1]
    rows = shape_table(clips, {"circle": {"shape": "circle"}})
    assert rows[0]["walks"] == 1 and rows[0]["end_cm_max"] <= 5
    assert "| circle | 1 |" in markdown(rows)
