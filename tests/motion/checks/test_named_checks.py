"""Each named check on real captures of the processed data set (`default_clips()`: CMU, HDM05,
the captured salsa pairs and the pairs composed from real single-person motion), and a
synthetic violation of the same capture that it must catch."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as M
from interplay.motion.checks import named as N
from interplay.motion.clip import default_clips
from interplay.motion.ik import two_bone_ik
from interplay.motion.rotations import yaw_matrix

J = sk.JOINT_INDEX


def clips(source: str, label: str | None = None, prefix: str | None = None, persons: int = 1):
    out = [c for c in default_clips() if c.source == source and len(c.people) == persons
           and (label is None or c.label == label)
           and (prefix is None or c.label.startswith(prefix))]
    assert out, f"no {source} clips labelled {label or prefix}"
    return out


def one(people, spec: dict) -> N.Result:
    return N.run_check([np.asarray(p, np.float64) for p in people], spec)


def passes(people, **spec) -> bool:
    return one(people, spec).passed


def kind(kind_name: str):
    return [c for c in clips("composed", persons=2) if c.meta.get("kind") == kind_name]


def mirrored(j: np.ndarray) -> np.ndarray:
    """Left and right swapped, x negated (the same motion done with the other side)."""
    m = j[:, M.MIRROR_JOINTS].copy()
    m[..., 0] *= -1
    return m


def moved(j: np.ndarray, dx: float = 0.0, dy: float = 0.0, dz: float = 0.0,
          frames: slice = slice(None)) -> np.ndarray:
    out = np.asarray(j, np.float64).copy()
    out[frames] += np.array([dx, dy, dz])
    return out


def yawed(j: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Each frame turned about the vertical through its pelvis by angle[t] radians."""
    rot = yaw_matrix(np.asarray(angle))                                  # (T, 3, 3)
    c = j[:, [sk.PELVIS]] * np.array([1, 0, 1])
    return np.einsum("tij,tkj->tki", rot, j - c) + c


def joined(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """b played after a, shifted on the floor so its first pelvis is where a's last one is."""
    shift = (a[-1, sk.PELVIS] - b[0, sk.PELVIS]) * np.array([1, 0, 1])
    return np.concatenate([a, b + shift])


# ---- counts -------------------------------------------------------------------------------

def test_captured_squats_count_their_squats():
    squats = clips("hdm05", "squat1Reps")
    counts = [one([c.people[0]], {"check": "squat_count"}).value for c in squats]
    assert np.mean([n == 1 for n in counts]) >= 0.95, counts
    two = joined(squats[0].people[0], squats[1].people[0])
    assert passes([two], check="squat_count", count=2)
    assert not passes([two], check="squat_count", count=1)


def test_a_jump_is_not_a_squat_and_a_walk_is_neither():
    for c in clips("cmu-bvh", "jump"):
        assert one([c.people[0]], {"check": "squat_count"}).value == 0
        assert passes([c.people[0]], check="jump_count", count=1)
    walk = clips("cmu-bvh", "walk")[0].people[0]
    assert one([walk], {"check": "squat_count"}).value == 0
    assert one([walk], {"check": "jump_count"}).value == 0


def test_captured_jumps_count_their_jumps():
    hops = clips("hdm05", "hopBothLegs1hops")
    assert np.mean([passes([c.people[0]], check="jump_count", count=1) for c in hops]) >= 0.9
    jumping = next(c for c in clips("cmu-8action", "jumping") if c.id == "8action:test/jumping_1")
    assert passes([jumping.people[0][:80]], check="jump_count", count=3)    # three jumps by eye


def test_a_hover_is_not_a_jump():
    j = clips("cmu-bvh", "walk")[0].people[0][:60].astype(np.float64)
    lifted = j.copy()
    lifted[20:38, :, 1] += 0.25                     # lifted 25 cm for 0.9 s, no ballistic arc
    assert one([lifted], {"check": "jump_count"}).value == 0
    assert not N.grounded(lifted, M.frame_of(lifted))[0]


def test_kicks_know_which_leg():
    kicks = clips("hdm05", "kickLFront1Reps")
    left = [passes([c.people[0]], check="kick", leg="left", count=1) for c in kicks]
    assert np.mean(left) >= 0.9
    assert not any(passes([c.people[0]], check="kick", leg="right") for c in kicks)
    assert np.mean([passes([mirrored(c.people[0])], check="kick", leg="right", count=1) for c in kicks]) >= 0.9
    assert passes([kicks[0].people[0]], check="kick", leg="left", height=0.9)     # front kicks reach ~1.1 m


def test_a_knee_raise_is_not_a_kick():
    for c in clips("hdm05", prefix="elbowToKnee"):
        assert not passes([c.people[0]], check="kick")


def test_a_kick_held_low_is_not_a_high_kick():
    c = clips("hdm05", "kickLFront1Reps")[0]
    assert not passes([c.people[0]], check="kick", leg="left", height=1.5)


# ---- travel ---------------------------------------------------------------------------------

def test_a_captured_walk_goes_forwards_not_backwards():
    for c in clips("cmu-bvh", "walk")[:8]:
        j = c.people[0]
        assert passes([j], check="travel_direction", direction="forward")
        assert not passes([j], check="travel_direction", direction="backward")
        # The same walk played backwards in time: the body steps backwards facing forward.
        assert passes([j[::-1]], check="travel_direction", direction="backward")
        assert not passes([j[::-1]], check="travel_direction", direction="forward")


def test_a_walk_turned_sideways_travels_sideways():
    j = clips("cmu-bvh", "walk")[0].people[0].astype(np.float64)
    side = yawed(j, np.full(len(j), np.pi / 2))     # the body faces 90° off its path
    assert passes([side], check="travel_direction", direction="right") or passes(
        [side], check="travel_direction", direction="left")
    assert not passes([side], check="travel_direction", direction="forward")


def test_captured_speeds_land_in_their_bands():
    assert passes([clips("cmu-bvh", "run/jog")[0].people[0]], check="speed_band", band="jog")
    for c in clips("hdm05", "jogLeftCircle4StepsRstart")[:6]:
        assert passes([c.people[0]], check="speed_band", band="jog")
    for c in clips("cmu-bvh", "run"):
        assert passes([c.people[0]], check="speed_band", band="run")
    walks = clips("cmu-bvh", "walk")
    assert np.mean([passes([c.people[0]], check="speed_band", band="walk") for c in walks]) >= 0.9
    for c in clips("hdm05", "sneak2StepsLStart")[:6]:
        assert passes([c.people[0]], check="speed_band", band="slow")
    assert not passes([walks[0].people[0]], check="speed_band", band="jog")


def test_a_walk_played_three_times_faster_leaves_the_walk_band():
    j = clips("cmu-bvh", "walk")[0].people[0]
    assert passes([j], check="speed_band", band="walk")
    assert not passes([j[::3]], check="speed_band", band="walk")
    assert not passes([j[:5].repeat(12, axis=0)], check="speed_band", band="walk")   # standing


def test_a_captured_jog_circle_curves_left():
    for c in clips("hdm05", "jogLeftCircle4StepsRstart")[:5]:
        assert passes([c.people[0]], check="curves", direction="left", min_deg=45)
        assert not passes([c.people[0]], check="curves", direction="right", min_deg=45)
        assert passes([mirrored(c.people[0])], check="curves", direction="right", min_deg=45)


def test_turns_and_staying_in_place():
    squat = clips("hdm05", "squat1Reps")[0].people[0].astype(np.float64)
    assert passes([squat], check="stays_in_place")
    assert not passes([squat], check="turn", degrees=180)
    spun = yawed(squat, np.linspace(0, np.pi, len(squat)))
    assert passes([spun], check="turn", degrees=180, direction="left")
    assert not passes([spun], check="turn", degrees=180, direction="right")
    walk = clips("cmu-bvh", "walk")[0].people[0]
    assert passes([walk], check="travels", min_m=2.0)
    assert not passes([walk], check="stays_in_place")


def _walk_along(points: np.ndarray) -> np.ndarray:
    from interplay.trajectory.apply import apply_trajectory
    walks = [c.people[0].astype(np.float64) for c in clips("cmu-bvh", "walk")[:4]]
    walk = walks[0]
    for w in walks[1:]:
        walk = joined(walk, w)
    return apply_trajectory(walk, points)


@pytest.mark.parametrize("shape", ["circle", "square", "figure_eight", "triangle"])
def test_a_real_walk_along_a_shape_is_nearest_that_shape(shape):
    t = M._template(shape, 400) * 3.0
    path = np.concatenate([t[k:], t[:k + 1]]) if (k := 0) else np.concatenate([t, t[:1]])
    walked = _walk_along(path - path[0])
    assert passes([walked], check="path_shape", shape=shape)
    others = [s for s in M.CLOSED_SHAPES if s != shape]
    assert not any(passes([walked], check="path_shape", shape=s) for s in others)


def test_a_real_walk_round_a_circle_is_not_a_zigzag():
    t = M._template("circle", 400) * 2.0
    walked = _walk_along(np.concatenate([t, t[:1]]) - t[0])
    assert not passes([walked], check="path_shape", shape="zigzag")
    assert not passes([walked], check="path_shape", shape="line")


def test_a_straight_captured_walk_is_a_line_not_a_circle():
    walk = clips("cmu-bvh", "walk")[0].people[0]
    assert passes([walk], check="path_shape", shape="line")
    assert not passes([walk], check="path_shape", shape="circle")
    assert not passes([walk], check="path_shape", shape="zigzag")


def test_a_real_walk_along_a_zigzag_is_a_zigzag():
    z = np.array([[0, 0], [1, 1.5], [-1, 3], [1, 4.5], [-1, 6]], float)
    walked = _walk_along(z)
    assert passes([walked], check="path_shape", shape="zigzag")
    assert not passes([walked], check="path_shape", shape="line")


def test_steps_are_counted():
    for c in clips("hdm05", "sneak2StepsLStart")[:6]:
        assert passes([c.people[0]], check="step_count", count=2)
    walk = clips("cmu-bvh", "walk")[0].people[0]
    assert not passes([walk], check="step_count", count=1, tolerance=0)


# ---- arms and poses -------------------------------------------------------------------------

def test_a_captured_reach_is_a_raised_hand_but_not_a_wave():
    for c in clips("hdm05", "grabHighR")[:6]:
        assert passes([c.people[0]], check="hand_raised", hand="right", level="shoulder", min_s=0.2)
        assert not passes([c.people[0]], check="hand_raised", hand="left", level="shoulder", min_s=0.2)
        assert not passes([c.people[0]], check="hand_raised", hand="right", level="overhead", min_s=0.2)
        assert not passes([c.people[0]], check="wave")
    for c in clips("hdm05", prefix="rotateArms")[:6]:
        assert not passes([c.people[0]], check="wave")


def test_composed_waves_are_waves_and_a_frozen_arm_is_not():
    for c in kind("wave")[:6]:
        assert passes(c.people, check="wave", person="both")
    a = kind("wave")[0].people[0].astype(np.float64)
    held = a.copy()
    side = "left" if passes([a], check="wave", hand="left") else "right"
    arm = [J[f"{side}_{p}"] for p in ("elbow", "wrist")]
    held[:, arm] = held[40, arm] - held[40, [sk.PELVIS]] + held[:, [sk.PELVIS]]   # the arm held still up
    assert not passes([held], check="wave")
    assert passes([held], check="hand_raised", hand=side, level="shoulder", min_s=1.0)


def _arms_to(j: np.ndarray, where, elbows_out: bool = False) -> np.ndarray:
    """Both wrists moved by IK to where(joints, side) (targets (T, 3)); elbows_out bends the
    elbows out to the sides and back."""
    out = np.asarray(j, np.float64)
    fwd, left = _body_axes(out)
    for side in ("left", "right"):
        pole = None
        if elbows_out:
            lat = left if side == "left" else -left
            pole = out[:, J[f"{side}_shoulder"]] + 1.0 * lat - 0.2 * fwd - np.array([0, 0.2, 0])
        out = two_bone_ik(out, f"{side}_arm", where(out, side), pole=pole)
    return out


def _body_axes(j):
    f = M.frame_of(j)
    return f.forward, f.left


def test_t_pose_on_a_real_standing_body():
    stand = clips("hdm05", "squat1Reps")[0].people[0][:3].repeat(20, axis=0)
    fwd, left = _body_axes(stand)

    def out(j, side, down=0.0):
        sh = j[:, J[f"{side}_shoulder"]]
        reach = 0.98 * (np.linalg.norm(j[:, J[f"{side}_elbow"]] - sh, axis=1)
                        + np.linalg.norm(j[:, J[f"{side}_wrist"]] - j[:, J[f"{side}_elbow"]], axis=1))
        d = left if side == "left" else -left
        v = d * np.cos(down) + np.array([0, -1, 0]) * np.sin(down)
        return sh + v * reach[:, None]
    t = _arms_to(stand, out)
    assert passes([t], check="pose_held", pose="t_pose", min_s=2.0)
    assert not passes([stand], check="pose_held", pose="t_pose", min_s=0.1)
    drooping = _arms_to(stand, lambda j, s: out(j, s, down=np.radians(45)))
    assert not passes([drooping], check="pose_held", pose="t_pose", min_s=0.1)


def test_hands_on_hips_and_arms_crossed_on_a_real_standing_body():
    stand = clips("hdm05", "squat1Reps")[0].people[0][:3].repeat(20, axis=0)
    fwd, left = _body_axes(stand)
    hips = _arms_to(stand, lambda j, s: j[:, J[f"{s}_hip"]] + 0.07 * (left if s == "left" else -left)
                    + np.array([0, 0.18, 0]), elbows_out=True)
    assert passes([hips], check="pose_held", pose="hands_on_hips", min_s=2.0)
    assert not passes([stand], check="pose_held", pose="hands_on_hips", min_s=0.1)
    crossed = _arms_to(stand, lambda j, s: j[:, J[f"{'right' if s == 'left' else 'left'}_elbow"]] * 0
                       + j[:, J["spine3"]] + 0.22 * fwd + 0.10 * (-left if s == "left" else left)
                       - np.array([0, 0.05 if s == "left" else 0.1, 0]))
    assert passes([crossed], check="pose_held", pose="arms_crossed", min_s=2.0)
    assert not passes([hips], check="pose_held", pose="arms_crossed", min_s=0.1)


def test_one_leg_and_held_squat_on_real_captures():
    kick = clips("hdm05", "kickLFront1Reps")[0].people[0]
    assert not passes([kick], check="pose_held", pose="one_leg", min_s=1.5)   # a kick is brief
    squat = clips("hdm05", "squat1Reps")[0].people[0].astype(np.float64)
    bottom = int(np.argmin(squat[:, sk.PELVIS, 1]))
    held = np.concatenate([squat[:bottom], squat[bottom:bottom + 1].repeat(40, axis=0), squat[bottom:]])
    assert passes([held], check="pose_held", pose="squat", min_s=1.5)
    assert not passes([squat], check="pose_held", pose="squat", min_s=1.5)


# ---- postures --------------------------------------------------------------------------------

def test_a_captured_lie_down_ends_lying_and_starts_standing():
    lie = clips("hdm05", "lieDownFloor")
    assert all(passes([c.people[0]], check="posture_at_end", posture="lying") for c in lie)
    upright = [c for c in lie if passes([c.people[0]], check="posture_at_start", posture="standing")]
    assert len(upright) >= 0.6 * len(lie)          # some takes start already bending down
    for c in upright[:8]:
        j = c.people[0]
        assert not passes([j], check="posture_at_end", posture="standing")
        # Played backwards it is getting up: it starts lying and ends standing.
        assert passes([j[::-1]], check="posture_at_start", posture="lying")
        assert passes([j[::-1]], check="posture_at_end", posture="standing", seconds=0.1)
        assert not passes([j[::-1]], check="posture_at_end", posture="lying")
        assert not passes([j], check="crawl")


def test_sitting_kneeling_on_real_poses():
    lie = clips("hdm05", "lieDownFloor")[0].people[0].astype(np.float64)
    assert not passes([lie], check="posture_at_end", posture="sitting")
    squat = clips("hdm05", "squat1Reps")[0].people[0]
    assert not passes([squat], check="posture_at_end", posture="sitting")
    assert not passes([squat], check="posture_at_end", posture="kneeling")


def test_sequence_of_real_clips_in_order():
    squat = clips("hdm05", "squat1Reps")[0].people[0]
    jump = clips("cmu-bvh", "jump")[0].people[0]
    both = joined(squat, jump)
    assert passes([both], check="sequence", steps=["squat", "jump"])
    assert not passes([both], check="sequence", steps=["jump", "squat"])
    twice = joined(joined(squat, clips("hdm05", "squat1Reps")[1].people[0]), jump)
    assert passes([twice], check="sequence", steps=[{"event": "squat", "count": 2}, "jump"])
    assert not passes([both], check="sequence", steps=[{"event": "squat", "count": 2}, "jump"])
    lie = clips("hdm05", "lieDownFloor")[0].people[0]
    assert passes([joined(lie, lie[::-1])], check="sequence", steps=["lie", "stand"])


# ---- two people --------------------------------------------------------------------------------

def test_composed_handshakes_pass_and_hands_apart_fail():
    shakes = kind("handshake")
    assert np.mean([passes(c.people, check="handshake") for c in shakes]) >= 0.9
    a, b = shakes[0].people
    fwd = (a[0, sk.PELVIS] - b[0, sk.PELVIS]) * np.array([1, 0, 1])
    fwd /= np.linalg.norm(fwd)
    apart = moved(b, *(-0.3 * fwd))
    assert not passes([a, apart], check="handshake")
    for c in clips("cmu-salsa", persons=2)[:6]:
        assert not passes(c.people, check="handshake")


def test_composed_high_fives_pass_and_low_or_apart_fail():
    fives = kind("high_five")
    assert np.mean([passes(c.people, check="high_five") for c in fives]) >= 0.6
    c = next(c for c in fives if passes(c.people, check="high_five"))
    a, b = c.people
    d = (b[0, sk.PELVIS] - a[0, sk.PELVIS]) * np.array([1, 0, 1])
    assert not passes([a, moved(b, *(0.4 * d / np.linalg.norm(d)))], check="high_five")
    assert not any(passes(c.people, check="high_five") for c in kind("handshake"))


def test_composed_hugs_pass_and_a_partner_in_front_does_not():
    hugs = kind("hug")
    assert np.mean([passes(c.people, check="hug") for c in hugs]) >= 0.7
    a, b = next(c for c in hugs if passes(c.people, check="hug")).people
    d = (b[0, sk.PELVIS] - a[0, sk.PELVIS]) * np.array([1, 0, 1])
    assert not passes([a, moved(b, *(0.6 * d / np.linalg.norm(d)))], check="hug")
    for c in clips("cmu-salsa", persons=2)[:6]:
        assert not passes(c.people, check="hug")


def test_a_push_must_move_the_partner_away():
    pushes = kind("push")
    # The composed pushes barely move the partner (≤ 0.2 m): not a push by this measure.
    assert not any(passes(c.people, check="push") for c in pushes)
    for c in pushes[:5]:
        a, b = (p.astype(np.float64) for p in c.people)
        gap = np.min([M.hand_to_trunk(a, b, s) for s in M.SIDES], axis=0)
        first = int(np.flatnonzero(gap <= N.PUSH_CONTACT_M)[0])
        d = (b[first, sk.PELVIS] - a[first, sk.PELVIS]) * np.array([1, 0, 1])
        d /= np.linalg.norm(d)
        shove = b.copy()
        ramp = np.clip((np.arange(len(b)) - first) / 12.0, 0, 1)[:, None, None]
        shove += 0.7 * ramp * d                                   # knocked 0.7 m back in 0.6 s
        assert passes([a, shove], check="push")
        assert passes([shove, a], check="push")                   # whichever person pushes


def test_wave_back_needs_the_second_wave_later():
    a, b = kind("wave")[0].people
    late = np.concatenate([b[:1].repeat(20, axis=0), b[:-20]])     # b starts a second later
    assert passes([a, late], check="wave_back")
    assert not passes([a, a[:, :] * np.array([1, 1, 1]) + np.array([0, 0, 3.0])], check="wave_back")


def test_walks_side_by_side_and_one_stopping():
    walks = kind("walk_side_by_side")
    assert np.mean([passes(c.people, check="side_by_side") for c in walks]) >= 0.9
    a, b = walks[0].people
    assert not passes([a, b], check="one_stops")
    stopped = b.astype(np.float64).copy()
    stopped[-40:] = stopped[-41]                                   # b halts for the last 2 s
    assert passes([a, stopped], check="one_stops")
    assert not passes([a, moved(b, dx=3.0)], check="side_by_side")


def test_follows_on_a_real_walk():
    walk = clips("cmu-bvh", "walk")[0].people[0].astype(np.float64)
    lead = walk[20:]
    follow = walk[:-20]                                            # the same walk a second behind
    assert passes([lead, follow], check="follows")
    assert passes([follow, lead], check="follows")
    side = moved(lead, dx=0.8)
    assert not passes([lead, side], check="follows")


def test_mirrors_on_a_real_motion():
    j = clips("hdm05", "throwBasketball")[0].people[0].astype(np.float64)
    facing = yawed(mirrored(j), np.full(len(j), np.pi)) + np.array([0, 0, 2.0])
    facing[..., 0] += 2 * j[0, sk.PELVIS, 0]
    assert passes([j, facing], check="mirrors")
    other = clips("hdm05", "squat1Reps")[0].people[0][:len(j)]
    k = min(len(j), len(other))
    assert not passes([j[:k], other[:k] + np.array([0, 0, 2.0])], check="mirrors")


def test_salsa_dances_close_and_apart_does_not():
    for c in clips("cmu-salsa", persons=2)[:6]:
        a, b = c.people
        assert passes([a, b], check="close_together") or c.id == "salsa:10"
        assert passes([a, b], check="active", person="both")
        assert not passes([a, moved(b, dx=3.0)], check="close_together")


def test_approach():
    walk = clips("cmu-bvh", "walk")[0].people[0].astype(np.float64)
    stand = np.repeat(walk[-1:], len(walk), axis=0) + np.array([0, 0, 1.0])
    assert passes([walk, stand], check="approach", min_m=1.5)
    assert not passes([walk[::-1], stand], check="approach", min_m=1.5)
