"""The 45-sphere body and its intersection volume, on real CMU captures (tests/fixtures/raw,
made by tests/fixtures/make_fixtures.py): a walk and the salsa pair 60_01/61_01."""


import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.pair import body
from interplay.motion.retarget.cmu_daz import load_cmu_bvh, load_salsa_pair
from tests.helpers.paths import RAW


@pytest.fixture(scope="module")
def walk():
    return load_cmu_bvh(RAW / "cmu-bvh" / "02" / "02_01.bvh")[0]


@pytest.fixture(scope="module")
def salsa():
    return load_salsa_pair(RAW / "cmu-salsa" / "60" / "60_01_scaled.bvh",
                           RAW / "cmu-salsa" / "61" / "61_01_scaled.bvh")[0]


def test_spheres_sit_on_the_bones_of_a_captured_person(walk):
    s = body.body_spheres(walk)
    t = walk.shape[0]
    assert body.NUM_SPHERES == 45
    assert s.centres.shape == (t, 45, 3) and s.radii.shape == s.part.shape == s.joint.shape == (45,)
    assert np.all(s.radii > 0.02) and np.all(s.radii < 0.15)
    assert set(s.part.tolist()) == {0, 1, 2, 3}
    # Every sphere centre lies on the line of its bone, at its table fraction.
    p, c = walk[:, body.SPHERE_PARENT], walk[:, body.SPHERE_CHILD]
    assert np.allclose(s.centres, p + body.SPHERE_FRACTION[:, None] * (c - p))
    # Trunk spheres are thicker than forearm spheres; the hand spheres lie past the wrists.
    trunk = s.radii[np.isin(s.joint, [sk.JOINT_INDEX["spine2"], sk.JOINT_INDEX["spine3"]])]
    forearm = s.radii[(body.SPHERE_CHILD == sk.LEFT_HAND) & (body.SPHERE_FRACTION < 1)]
    assert trunk.min() > 2 * forearm.max()
    hands = s.centres[:, body.HAND_SPHERES]
    wrist, elbow = walk[:, [sk.LEFT_HAND, sk.RIGHT_HAND]], walk[:, [sk.LEFT_HAND - 2, sk.RIGHT_HAND - 2]]
    assert np.all(np.einsum("tkd,tkd->tk", hands - wrist, wrist - elbow) > 0)
    # The head sphere tops the body: above every other sphere's centre in every frame.
    head = np.flatnonzero(body.SPHERE_CHILD == sk.HEAD)
    assert head.size == 1 and np.all(s.centres[:, head[0], 1] >= s.centres[..., 1].max(axis=1) - 1e-9)


def test_radii_follow_the_persons_size(walk):
    scale = body.body_scale(walk)
    assert 0.85 < scale < 1.2                     # a captured adult is close to the template
    bigger = body.body_spheres(walk * 1.2)
    assert np.allclose(bigger.radii, body.body_spheres(walk).radii * 1.2)
    assert np.allclose(body.body_spheres(walk, scale=1.0).radii, body.SPHERE_RADII)


def test_lens_volume_matches_geometry():
    r1, r2 = 0.1, 0.06
    full = 4 / 3 * np.pi * r2 ** 3
    assert body.lens_volume(0.0, r1, r2) == pytest.approx(full)
    assert body.lens_volume(r1 - r2, r1, r2) == pytest.approx(full)          # internally tangent
    assert body.lens_volume(r1 + r2, r1, r2) == 0.0                          # externally tangent
    assert body.lens_volume(r1 + r2 - 1e-6, r1, r2) < 1e-12                  # continuous there
    d = np.linspace(0, 0.2, 81)
    v = body.lens_volume(d, r1, r2)
    assert np.all(np.diff(v) <= 1e-15) and np.allclose(v, body.lens_volume(d, r2, r1))
    # Monte Carlo estimate of one lens volume.
    rng = np.random.default_rng(0)
    pts = rng.uniform(-0.1, 0.1, (400_000, 3))
    dist = 0.09
    inside = (np.linalg.norm(pts, axis=1) < r1) & (np.linalg.norm(pts - [dist, 0, 0], axis=1) < r2)
    assert body.lens_volume(dist, r1, r2) == pytest.approx(inside.mean() * 0.2 ** 3, rel=0.05)


def test_intersection_volume_grows_as_one_dancer_steps_into_the_other(salsa):
    lead, follow = salsa
    a = body.body_spheres(lead)
    # Per frame, move the follower along the horizontal pelvis line: first 3 m away, then a
    # growing share of the way onto the lead (the pair is 0.5–2.2 m apart in this clip).
    gap = lead[:, sk.PELVIS] - follow[:, sk.PELVIS]
    gap[:, 1] = 0
    away = -3.0 * gap / np.linalg.norm(gap, axis=1, keepdims=True)
    volumes, flags = [], []
    for shift in [away] + [f * gap for f in (0.0, 0.25, 0.5, 0.75, 0.95)]:
        b = body.body_spheres(follow + shift[:, None])
        volumes.append(body.intersection_volume(a, b).sum())
        flags.append(body.overlap_flags(a, b).mean())
    assert volumes[0] == 0 and flags[0] == 0                 # far apart: nothing touches
    assert np.all(np.diff(volumes) > 0) and np.all(np.diff(flags) >= 0)
    assert flags[-1] == 1.0 and flags[1] < 0.2              # real salsa touches now and then


def test_a_body_fully_overlaps_itself(walk):
    s = body.body_spheres(walk)
    assert np.all(body.overlap_flags(s, s))
    # Each sphere shares its whole volume with itself: the sum counts at least that.
    own = (4 / 3 * np.pi * s.radii ** 3).sum()
    assert np.all(body.intersection_volume(s, s) >= own)
    assert np.all(body.part_penetration(s, s))


def test_penetrating_parts_agree_with_overlap_flags(salsa):
    a, b = (body.body_spheres(p) for p in salsa)
    flags = body.overlap_flags(a, b)
    parts = body.part_penetration(a, b)
    assert 0 < flags.mean() < 1                               # real salsa touches sometimes
    assert np.array_equal(parts.any(axis=1), flags)           # every sphere is in some part
    gaps = body.surface_gaps(a, b)
    assert np.array_equal(gaps.min(axis=(1, 2)) < 0, flags)
    assert np.array_equal(body.intersection_volume(a, b) > 0, flags)


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="shape"):
        body.body_spheres(np.zeros((5, 21, 3)))
    bad = np.zeros((5, 22, 3))
    bad[2, 3, 1] = np.nan
    with pytest.raises(ValueError, match="NaN"):
        body.body_spheres(bad)
    with pytest.raises(ValueError, match="frame counts"):
        body.centre_distances(body.body_spheres(np.zeros((5, 22, 3)) + sk.rest_joints()),
                              body.body_spheres(np.zeros((4, 22, 3)) + sk.rest_joints()))
