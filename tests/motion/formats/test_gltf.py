"""The GLB export read back with pygltflib: one scene of people (joint nodes named as the
skeleton, a skin of 22 joints with the rest pose's inverse bind matrices, a skinned body per
person, or none in the animation-only variant), one animation whose keys are seconds at the
motion's rate, the root's translation and every joint's rotation (x, y, z, w) from
`rig.solve_rig`; the front end's committed humanoid.glb is what the generator makes."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.formats.gltf import humanoid_glb, write_glb
from interplay.motion.formats.humanoid import humanoid, on_skeleton
from tests.helpers.gltf_files import ASSET, accessor, fixture_people, load, rigs_of


@pytest.fixture(scope="module")
def pair():
    people = fixture_people("coda_hug")
    return people, load(write_glb(people, fps=20, name="two people hug"))


def test_a_two_person_glb_has_a_skinned_body_and_skeleton_per_person(pair):
    people, (doc, blob) = pair
    assert doc.asset.version == "2.0" and doc.extras["fps"] == 20.0
    assert len(doc.skins) == len(doc.meshes) == 2 and len(doc.animations) == 1
    roots = [doc.nodes[n].name for n in doc.scenes[doc.scene].nodes]
    assert roots == ["person1", "person1_body", "person2", "person2_body"]
    mesh = humanoid()
    for k, (skin, rig) in enumerate(zip(doc.skins, rigs_of(people))):
        names = [doc.nodes[n].name for n in skin.joints]
        # Two people: each one's bones named apart ("person1_pelvis", "person2_pelvis").
        assert names == [f"person{k + 1}_{n}" for n in sk.JOINT_NAMES] and skin.skeleton == skin.joints[0]
        for j, n in enumerate(skin.joints):                 # the tree is the skeleton's
            kids = [skin.joints.index(c) for c in doc.nodes[n].children]
            assert kids == sk.children(j)
        offsets = np.array([doc.nodes[n].translation for n in skin.joints])
        assert np.allclose(offsets, rig.offsets, atol=1e-6)
        ibm = accessor(doc, blob, skin.inverseBindMatrices).reshape(22, 4, 4)   # column-major
        assert np.allclose(ibm[:, :3, :3], np.eye(3)) and np.allclose(ibm[:, 3, :3],
                                                                      -sk.rest_joints(rig.offsets))
        body = [doc.nodes[n] for n in doc.scenes[0].nodes if doc.nodes[n].mesh is not None][k]
        assert body.skin == k
        prim = doc.meshes[body.mesh].primitives[0]
        positions = accessor(doc, blob, prim.attributes.POSITION)
        assert np.allclose(positions, on_skeleton(mesh, rig.offsets), atol=1e-6)
        assert np.array_equal(accessor(doc, blob, prim.attributes.JOINTS_0), mesh.joints)
        assert np.array_equal(accessor(doc, blob, prim.attributes.WEIGHTS_0), mesh.weights)
        assert np.array_equal(accessor(doc, blob, prim.indices).reshape(-1, 3), mesh.triangles)
        assert doc.accessors[prim.attributes.POSITION].min == pytest.approx(
            positions.min(axis=0).tolist())


def test_the_animation_keys_seconds_root_translation_and_every_rotation(pair):
    people, (doc, blob) = pair
    (anim,) = doc.animations
    assert anim.name == "two people hug" and len(anim.channels) == 2 * 23
    frames = len(people[0])
    for skin, rig in zip(doc.skins, rigs_of(people)):
        node_joint = {n: j for j, n in enumerate(skin.joints)}
        seen = set()
        for ch in anim.channels:
            if ch.target.node not in node_joint:
                continue
            j = node_joint[ch.target.node]
            sampler = anim.samplers[ch.sampler]
            assert sampler.interpolation == "LINEAR"
            times = accessor(doc, blob, sampler.input)
            assert np.allclose(times, np.arange(frames) / 20.0)
            assert doc.accessors[sampler.input].max == pytest.approx([(frames - 1) / 20.0])
            values = accessor(doc, blob, sampler.output)
            if ch.target.path == "translation":
                assert j == sk.PELVIS and np.allclose(values, rig.root, atol=1e-6)
            else:
                assert ch.target.path == "rotation"
                assert np.allclose(np.linalg.norm(values, axis=1), 1.0, atol=1e-6)
                assert np.allclose(values, rig.rotations[:, j][:, [1, 2, 3, 0]], atol=1e-6)
            seen.add((j, ch.target.path))
        assert seen == {(0, "translation")} | {(j, "rotation") for j in range(22)}


def test_the_animation_only_variant_has_skeletons_and_no_mesh():
    people = fixture_people("coda_hug")
    doc, blob = load(write_glb(people, mesh=False))
    assert doc.meshes == [] and doc.materials == [] and len(doc.skins) == 2
    assert [doc.nodes[n].name for n in doc.scenes[0].nodes] == ["person1", "person2"]
    assert len(doc.animations[0].channels) == 46


def test_one_person(tmp_path):
    (person,) = fixture_people("spam_walk_jump")
    doc, _ = load(write_glb([person]))
    assert len(doc.skins) == 1 and len(doc.meshes) == 1 and len(doc.animations[0].channels) == 23


def test_people_of_different_lengths_are_refused():
    a, b = fixture_people("coda_hug")
    with pytest.raises(ValueError, match="different lengths"):
        write_glb([a, b[:-1]])
    with pytest.raises(ValueError, match="at least one"):
        write_glb([])


def test_the_front_ends_humanoid_glb_is_what_the_generator_makes():
    """Fails after a change to formats/humanoid.py until the asset is written again:
    .venv/bin/python frontend/scripts/humanoid_asset.py"""
    doc, blob = load(ASSET.read_bytes())
    fresh, fresh_blob = load(humanoid_glb())
    assert doc.animations == [] and len(doc.skins) == 1
    (prim,) = doc.meshes[0].primitives
    (new,) = fresh.meshes[0].primitives
    for attr in ("POSITION", "NORMAL", "JOINTS_0", "WEIGHTS_0"):
        a = accessor(doc, blob, getattr(prim.attributes, attr))
        b = accessor(fresh, fresh_blob, getattr(new.attributes, attr))
        assert a.shape == b.shape and np.allclose(a, b, atol=1e-5), attr
    assert np.array_equal(accessor(doc, blob, prim.indices), accessor(fresh, fresh_blob, new.indices))
