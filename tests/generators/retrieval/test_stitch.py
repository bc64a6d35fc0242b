import numpy as np

from interplay.generators.retrieval.stitch import FADE, Piece, Stitcher, crossfade, heading
from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle, fit_offsets
from tests.helpers.synthetic_motion import fk_motion


def _piece(joints, offsets, start, end):
    return Piece(joints[start:end], joints[end:end + FADE], offsets)


def _wrap(a):
    return (a + np.pi) % (2 * np.pi) - np.pi


def test_walks_of_two_performers_join_smoothly_on_the_first_ones_bones():
    a, off_a = fk_motion(80, "walk", speed=1.3)
    b, off_b = fk_motion(80, "walk", speed=1.2, yaw=1.4, scale=1.08, phase=2.0)  # turned, taller
    st = Stitcher(1)
    out = np.concatenate([st.add_single(0, _piece(a, off_a, 5, 50)),
                          st.add_single(0, _piece(b, off_b, 10, 60))])
    assert out.shape == (95, 22, 3) and out.dtype == np.float32
    bones = sk.bone_lengths(out)
    np.testing.assert_allclose(bones, np.broadcast_to(sk.bone_lengths(sk.rest_joints(off_a)), bones.shape),
                               atol=1e-4)
    step = np.linalg.norm(np.diff(out[:, sk.PELVIS, [0, 2]], axis=0), axis=1)
    assert step[44] < 0.1 and step.max() < 0.1          # seam between frames 44 and 45
    assert step[40:50].min() > 0.03                      # …and the person keeps walking through it
    # The second walk continues in the first one's direction although it was captured turned.
    yaw = facing_angle(out)
    assert np.abs(_wrap(yaw - yaw[0])).max() < np.radians(20)
    travel = out[-1, sk.PELVIS] - out[0, sk.PELVIS]
    assert travel[2] > 1.1 * 4.5 and abs(travel[0]) < 0.5


def test_first_piece_is_placed_where_asked():
    a, off = fk_motion(40, "walk", yaw=2.0)
    out = Stitcher(2).add_single(1, _piece(a, off, 0, 40), (np.array([0.75, 0.0, 0.0]), -np.pi / 2))
    np.testing.assert_allclose(out[0, sk.PELVIS, [0, 2]], [0.75, 0.0], atol=1e-5)
    h = heading(out[:5])
    np.testing.assert_allclose(h, [-1.0, 0.0, 0.0], atol=0.05)
    assert out[-1, sk.PELVIS, 0] < 0.75 - 0.8            # walks towards -X


def test_pair_pieces_move_as_one_and_keep_their_spacing():
    a, off_a = fk_motion(100, "dance")
    b, off_b = fk_motion(100, "dance", yaw=np.pi, scale=0.93, phase=np.pi)
    b[..., 2] += 0.7
    st = Stitcher(2)
    first = st.add_pair([_piece(a, off_a, 0, 50), _piece(b, off_b, 0, 50)])
    second = st.add_pair([_piece(a, off_a, 30, 80), _piece(b, off_b, 30, 80)])
    people = [np.concatenate([f, s]) for f, s in zip(first, second)]
    gap = np.linalg.norm(people[0][:, sk.PELVIS] - people[1][:, sk.PELVIS], axis=1)
    captured = np.linalg.norm(a[:, sk.PELVIS] - b[:, sk.PELVIS], axis=1)
    assert np.abs(gap - np.median(captured)).max() < 0.1
    np.testing.assert_allclose(people[0][0, sk.PELVIS, [0, 2]], 0.0, atol=1e-5)
    for p in people:
        assert np.linalg.norm(np.diff(p[:, sk.PELVIS], axis=0), axis=1).max() < 0.1
        bones = sk.bone_lengths(p)
        assert np.ptp(bones, axis=0).max() < 1e-4


def test_crossfade_starts_near_the_old_motion_and_ends_on_the_new():
    a, _ = fk_motion(30, "walk")
    b, _ = fk_motion(30, "jump")
    out = crossfade(a, b)
    assert np.abs(out[0] - a[0]).max() < np.abs(b[0] - a[0]).max() * 0.1
    np.testing.assert_array_equal(out[FADE:], b[FADE:])
    assert np.abs(out[FADE - 1] - b[FADE - 1]).max() < np.abs(a[FADE - 1] - b[FADE - 1]).max() * 0.1
    assert fit_offsets(out).shape == (22, 3)
