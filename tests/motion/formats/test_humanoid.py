"""The procedural humanoid: a closed, outward-facing surface of a person's size in the rest pose
(Y up, metres, facing +Z, left at +X), a moderate vertex count, skinned by distance to the
bones with at most four normalised weights, each body region on its own joints, and the same
mesh on a person's own rest offsets."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.formats.humanoid import body_distance, humanoid, on_skeleton

J = sk.JOINT_INDEX


@pytest.fixture(scope="module")
def mesh():
    return humanoid()


def test_arrays_have_the_documented_shapes_and_types(mesh):
    v = len(mesh.positions)
    assert 2000 <= v <= 6000 and 2 * v - 4 == len(mesh.triangles)   # closed genus-0 surface
    assert mesh.positions.shape == mesh.normals.shape == (v, 3)
    assert mesh.positions.dtype == mesh.normals.dtype == mesh.weights.dtype == np.float32
    assert mesh.joints.shape == mesh.weights.shape == (v, 4) and mesh.joints.dtype == np.uint8
    assert mesh.triangles.dtype == np.uint32 and mesh.triangles.max() == v - 1
    assert np.isfinite(mesh.positions).all()


def test_the_surface_is_closed_and_faces_outwards(mesh):
    tris = mesh.triangles.astype(np.int64)
    directed = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    # Every edge used once in each direction: a closed, consistently wound 2-manifold.
    assert len(np.unique(directed, axis=0)) == len(directed)
    reverse = {tuple(e) for e in directed[:, ::-1].tolist()}
    assert all(tuple(e) in reverse for e in directed.tolist())
    p = mesh.positions.astype(np.float64)
    a, b, c = p[tris[:, 0]], p[tris[:, 1]], p[tris[:, 2]]
    face = np.cross(b - a, c - a)
    assert (np.linalg.norm(face, axis=1) > 0).all()
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6
    assert 0.05 < volume < 0.09                                      # m³: an adult's 50–90 l
    vertex_normals = mesh.normals[tris].sum(axis=1)
    assert np.mean(np.einsum("ij,ij->i", face, vertex_normals) > 0) > 0.995
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-6)
    # On the implicit surface it was made from (within a millimetre).
    assert np.abs(body_distance(p)).max() < 1e-3


def test_rest_pose_is_a_person_standing_y_up_facing_plus_z(mesh):
    p = mesh.positions
    rest = sk.rest_joints()
    lo, hi = p.min(axis=0), p.max(axis=0)
    assert 1.7 < hi[1] - lo[1] < 1.85                                # height (m)
    assert abs(lo[1] - (rest[[sk.LEFT_FOOT, sk.RIGHT_FOOT], 1].min() - 0.01)) < 1e-3  # flat soles
    assert 1.6 < hi[0] - lo[0] < 1.9                                 # T-pose arm span
    # The toes and the nose point to +Z; the left hand is at +X.
    feet = p[:, 1] < 0.03
    assert p[feet, 2].max() > rest[sk.LEFT_FOOT, 2] + 0.03
    head = p[:, 1] > rest[sk.HEAD, 1] + 0.03
    assert p[head, 2].max() > 0.1 and p[head, 2].min() > -0.1
    left_hand = mesh.joints[np.arange(len(p)), mesh.weights.argmax(axis=1)] == sk.LEFT_HAND
    assert p[left_hand, 0].min() > 0.6


def test_weights_are_four_normalised_influences_on_the_nearby_joints(mesh):
    assert (mesh.weights >= 0).all() and (mesh.joints < sk.NUM_JOINTS).all()
    assert np.abs(mesh.weights.sum(axis=1, dtype=np.float64) - 1).max() < 1e-6
    assert (mesh.weights[:, 0] >= mesh.weights[:, 1:].max(axis=1) - 1e-6).all()   # largest first
    assert (mesh.joints[mesh.weights == 0] == 0).all()                      # unused slots
    used = mesh.weights > 0
    for row, mask in zip(mesh.joints, used):                                # no joint twice
        assert len(set(row[mask].tolist())) == mask.sum()
    dom = mesh.joints[:, 0]
    assert set(np.unique(dom)) == set(range(sk.NUM_JOINTS))                 # every joint drives
    p = mesh.positions
    # Regions: the left hand's tip, the right shin's middle, the top of the head.
    assert set(dom[p[:, 0] > 0.8]) == {sk.LEFT_HAND}
    shin = (np.abs(p[:, 1] - 0.27) < 0.03) & (p[:, 0] < 0)
    assert set(dom[shin]) == {J["right_knee"]}
    assert set(dom[p[:, 1] > 1.7]) == {sk.HEAD}
    # The left thigh never moves with the right leg.
    thigh = (np.abs(p[:, 1] - 0.65) < 0.05) & (p[:, 0] > 0.02)
    right_leg = [J[n] for n in ("right_hip", "right_knee", "right_ankle", "right_foot")]
    assert not np.isin(mesh.joints[thigh][mesh.weights[thigh] > 0], right_leg).any()


def test_it_is_the_same_mesh_every_time(mesh):
    from interplay.motion.formats.humanoid import build_humanoid
    again = build_humanoid()
    assert np.array_equal(again.triangles, mesh.triangles)
    assert np.array_equal(again.joints, mesh.joints)
    assert np.abs(again.positions - mesh.positions).max() < 1e-6


def test_on_skeleton_follows_a_persons_rest_offsets(mesh):
    assert np.array_equal(on_skeleton(mesh, sk.REST_OFFSETS), mesh.positions)
    taller = sk.REST_OFFSETS * 1.1
    moved = on_skeleton(mesh, taller)
    # A vertex bound to one joint alone moves exactly with it.
    shift = sk.rest_joints(taller) - sk.rest_joints()
    solo = mesh.weights[:, 0] == 1
    assert np.allclose(moved[solo] - mesh.positions[solo], shift[mesh.joints[solo, 0]], atol=1e-6)
    assert moved[:, 1].max() - moved[:, 1].min() > 1.08 * (mesh.positions[:, 1].max()
                                                            - mesh.positions[:, 1].min())
