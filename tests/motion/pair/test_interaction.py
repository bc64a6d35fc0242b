"""CODA's two-person geometry (joint distance map, Gaussian weights, part chains, AABB, eq. 6
and 7) on the real salsa pair 60_01/61_01 (tests/fixtures/raw, made by tests/fixtures/make_fixtures.py)."""


import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.pair import body, interaction
from interplay.motion.retarget.cmu_daz import load_salsa_pair
from tests.helpers.paths import RAW


@pytest.fixture(scope="module")
def salsa():
    return load_salsa_pair(RAW / "cmu-salsa" / "60" / "60_01_scaled.bvh",
                           RAW / "cmu-salsa" / "61" / "61_01_scaled.bvh")[0]


def test_segment_distance_matches_dense_sampling():
    rng = np.random.default_rng(1)
    p1, q1, p2, q2 = (rng.normal(0, 0.3, (60, 3)) for _ in range(4))
    q2[:10] = p2[:10] + 0.8 * (q1[:10] - p1[:10])       # parallel pairs
    q2[10:15] = p2[10:15] + 1e-4                         # nearly a point
    exact = interaction.segment_distances(p1, q1, p2, q2)
    s = np.linspace(0, 1, 201)
    a = p1[:, None] + s[None, :, None] * (q1 - p1)[:, None]          # (N, 201, 3)
    b = p2[:, None] + s[None, :, None] * (q2 - p2)[:, None]
    sampled = np.linalg.norm(a[:, :, None] - b[:, None], axis=-1).min(axis=(1, 2))
    assert np.all(exact <= sampled + 1e-12)
    assert np.allclose(exact, sampled, atol=5e-3)


def test_part_chains_and_their_distances(salsa):
    lead, follow = salsa
    assert interaction.PART_BONES.sum(axis=1).tolist() == [8, 8, 4, 4]
    d = interaction.part_min_distance(lead, follow)                  # (T, 4, 4)
    assert d.shape == (lead.shape[0], 4, 4) and np.all(d >= 0)
    # A chain's distance is at most the distance between any two of its joints.
    for i, pi in enumerate(sk.PART_NAMES):
        for j, pj in enumerate(sk.PART_NAMES):
            joints = np.linalg.norm(lead[:, sk.PART_JOINTS[pi], None] - follow[:, None, sk.PART_JOINTS[pj]],
                                    axis=-1).min(axis=(1, 2))
            assert np.all(d[:, i, j] <= joints + 1e-9)
    # Chains that come within 1 cm of each other have overlapping bounding boxes.
    boxes = interaction.part_box_overlap(lead, follow)
    assert np.all(boxes[d < 0.01])
    # Salsa arms meet (hand holds: wrist bones ~12 cm apart), legs keep further apart.
    assert d[:, :2, :2].min() < 0.15
    assert np.median(d[:, :2, :2], axis=0).max() < np.median(d[:, 2:, 2:], axis=0).min()
    # Moved 3 m apart, no box overlaps and no penalty applies.
    far = follow + [3.0, 0, 0]
    assert not interaction.part_box_overlap(lead, far).any()
    assert interaction.penetration_penalty(interaction.part_min_distance(lead, far), d,
                                           interaction.part_box_overlap(lead, far)) == 0.0


def test_penetration_penalty_punishes_chains_closer_than_the_target(salsa):
    lead, follow = salsa
    d_gt = interaction.part_min_distance(lead, follow)
    closer = follow + 0.3 * (lead[:, :1] - follow[:, :1]) * [1, 0, 1]
    d_pred = interaction.part_min_distance(lead, closer)
    overlap = interaction.part_box_overlap(lead, closer)
    assert interaction.penetration_penalty(d_gt, d_gt, overlap) == 0.0
    assert interaction.penetration_penalty(d_pred, d_gt, overlap) > 0.0


def test_gaussian_distance_map(salsa):
    lead, follow = salsa
    dist = interaction.joint_distance_map(lead, follow)
    assert dist.shape == (lead.shape[0], 22, 22)
    assert np.allclose(dist[:, 3, 7], np.linalg.norm(lead[:, 3] - follow[:, 7], axis=-1))
    w = interaction.gaussian_weights(dist)
    assert np.allclose(w, np.exp(-dist ** 2 / (2 * 0.5 ** 2)))
    assert interaction.gaussian_weights(np.array(0.0)) == 1.0
    # Eq. 6 against the capture itself is the weighted mean distance of close joints; a pair
    # pulled 0.5 m apart scores worse, and so does one pushed together.
    own = interaction.gdm_error((lead, follow), (lead, follow))
    step = (lead[:, :1] - follow[:, :1]) * [1, 0, 1]
    step /= np.linalg.norm(step, axis=-1, keepdims=True)
    apart = interaction.gdm_error((lead, follow - 0.5 * step), (lead, follow))
    together = interaction.gdm_error((lead, follow + 0.3 * step), (lead, follow))
    assert 0 < own < apart and own < together


def test_hand_gaps_see_the_salsa_hand_hold(salsa):
    a, b = (body.body_spheres(p) for p in salsa)
    gaps = interaction.hand_gaps(a, b)                              # (T, 2)
    assert gaps.shape == (salsa[0].shape[0], 2)
    assert (gaps.min(axis=1) <= 0.03).mean() > 0.05                # the lead's hands touch her
    # The same numbers from the full gap matrix.
    full = body.surface_gaps(a, b)[:, body.HAND_SPHERES].min(axis=2)
    assert np.allclose(gaps, full)
