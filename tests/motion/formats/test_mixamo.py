"""--names mixamo onto a Mixamo-named armature: every bone we write (BVH and GLB) is a bone of
Mixamo's standard rig with the same parent, the GLB's bones rest with their Y axis along the
bone (as Mixamo's do), and a Mixamo armature's bones posed by name from our GLB's rotations
follow the motion; Blender's own importers, where Blender is installed, in
test_blender_import.py."""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh, write_bvh
from interplay.motion.formats.gltf import write_glb
from interplay.motion.rig import rig_positions
from interplay.motion.rotations import quat_to_matrix
from tests.helpers.gltf_files import accessor, fixture_people, load, rigs_of

# Mixamo's standard skeleton (as Mixamo's FBX downloads name it), child: parent, without the
# fingers; its leaves end in *_End bones.
MIXAMO_RIG = {
    "Spine": "Hips", "Spine1": "Spine", "Spine2": "Spine1", "Neck": "Spine2", "Head": "Neck",
    "HeadTop_End": "Head",
    "LeftShoulder": "Spine2", "LeftArm": "LeftShoulder", "LeftForeArm": "LeftArm", "LeftHand": "LeftForeArm",
    "RightShoulder": "Spine2", "RightArm": "RightShoulder", "RightForeArm": "RightArm", "RightHand": "RightForeArm",
    "LeftUpLeg": "Hips", "LeftLeg": "LeftUpLeg", "LeftFoot": "LeftLeg", "LeftToeBase": "LeftFoot",
    "LeftToe_End": "LeftToeBase",
    "RightUpLeg": "Hips", "RightLeg": "RightUpLeg", "RightFoot": "RightLeg", "RightToeBase": "RightFoot",
    "RightToe_End": "RightToeBase",
}


def _tree(doc) -> dict[str, str | None]:
    parent: dict[str, str | None] = {}
    for node in doc.nodes:
        for c in node.children or []:
            parent[doc.nodes[c].name] = node.name
    return {n.name: parent.get(n.name) for n in doc.nodes}


def test_every_bone_is_mixamos_with_mixamos_parent():
    people = fixture_people("spam_wave")
    doc, _ = load(write_glb(people, names="mixamo", mesh=False))
    tree = _tree(doc)
    bones = [doc.nodes[n].name for n in doc.skins[0].joints]
    assert all(b.startswith("mixamorig:") for b in bones)
    checked = 0
    for b in bones:
        name = b.removeprefix("mixamorig:")
        if name in ("LeftHand_End", "RightHand_End"):      # Mixamo's hands go on to fingers
            continue
        if name == "Hips":
            assert tree[b] == "person1"
            continue
        assert "mixamorig:" + MIXAMO_RIG[name] == tree[b], b
        checked += 1
    assert checked == len(MIXAMO_RIG)
    # The BVH: the same names and parents (End Sites for the end bones).
    bvh = read_bvh(write_bvh(people[0][:10], names="mixamo"))
    for j, name in enumerate(bvh.names):
        p = bvh.parents[j]
        if p >= 0:
            assert "mixamorig:" + MIXAMO_RIG[name.removeprefix("mixamorig:")] == bvh.names[p]


def test_bones_rest_along_their_y_axis_and_a_mixamo_armature_follows_by_name():
    people = fixture_people("spam_wave")
    doc, blob = load(write_glb(people, names="mixamo"))
    skin = doc.skins[0]
    nodes = [doc.nodes[n] for n in skin.joints]
    ibm = accessor(doc, blob, skin.inverseBindMatrices).reshape(-1, 4, 4).transpose(0, 2, 1)
    bind = np.linalg.inv(ibm)                                  # world rest transforms
    by_name = {n.name: k for k, n in enumerate(nodes)}
    for k, node in enumerate(nodes):
        kids = [doc.nodes[c].name for c in node.children or []]
        child = "mixamorig:Spine" if node.name == "mixamorig:Hips" else \
            "mixamorig:Neck" if node.name == "mixamorig:Spine2" else (kids[0] if kids else None)
        if child is None:
            continue
        bone = bind[by_name[child], :3, 3] - bind[k, :3, 3]
        y = bind[k, :3, 1]
        assert bone @ y / np.linalg.norm(bone) > 0.999, node.name
    # A Mixamo armature (its own rest axes: ours here) posed by name from the file's keys: the
    # world positions FK gives are the motion's (lifted off the floor where the mesh needs it).
    anim = doc.animations[0]
    local = {}
    root = None
    for ch in anim.channels:
        name = doc.nodes[ch.target.node].name
        values = accessor(doc, blob, anim.samplers[ch.sampler].output).astype(np.float64)
        if ch.target.path == "rotation":
            local[name] = quat_to_matrix(values[:, [3, 0, 1, 2]])
        else:
            root = values
    tree = _tree(doc)
    t = len(root)
    glob: dict[str, np.ndarray] = {}
    pos: dict[str, np.ndarray] = {}
    for node in nodes[:sk.NUM_JOINTS]:                         # parents first
        parent = tree[node.name]
        rest = np.asarray(node.translation)
        if parent == "person1":
            glob[node.name], pos[node.name] = local[node.name], root
        else:
            glob[node.name] = glob[parent] @ local[node.name]
            pos[node.name] = pos[parent] + np.einsum("tij,j->ti", glob[parent], rest)
    got = np.stack([pos[n.name] for n in nodes[:sk.NUM_JOINTS]], axis=1)
    assert got.shape == (t, sk.NUM_JOINTS, 3)
    assert np.abs(got - rig_positions(rigs_of(people)[0])).max() < 1e-4


def test_the_bvh_rests_on_mixamos_axes_too(tmp_path):
    """The Mixamo BVH has the GLB's rest axes (issue 27): each joint's OFFSET lies along its
    parent's local +Y (the pelvis's to spine1, spine3's to the neck, the leaves' End Sites
    along their own), and a reader nobody here wrote (bvhio) gives the motion's joints back
    within 1 mm, Y up and Z up; the SMPL-named file keeps world-aligned axes."""
    from interplay.motion.formats.bvh import MIXAMO_NAMES, Z_UP, smpl22_positions
    from tests.helpers.bvh_readers import bvhio_positions
    people = fixture_people("spam_wave")
    joints = people[0][:30]
    for up in ("y", "z"):
        path = tmp_path / f"{up}.bvh"
        path.write_text(write_bvh(joints, names="mixamo", up=up))
        bvh = read_bvh(path)
        main = (sk.JOINT_INDEX["spine1"], sk.NECK)                 # the parents' bones' ends
        for j in range(1, sk.NUM_JOINTS):
            if j in main or len(sk.children(sk.PARENTS[j])) == 1:
                off = bvh.offsets[bvh.index(MIXAMO_NAMES[j])]
                assert off[1] / np.linalg.norm(off) > 0.999, MIXAMO_NAMES[j]
        for leaf, end in bvh.end_sites:
            assert end[1] / np.linalg.norm(end) > 0.999, bvh.names[leaf]
        got, _, _ = bvhio_positions(path, MIXAMO_NAMES)
        if up == "z":
            got = got @ Z_UP
        plain = read_bvh(write_bvh(joints, up="y"))
        assert np.abs(got - smpl22_positions(plain)).max() < 1e-3
    smpl = read_bvh(write_bvh(joints))
    knee = smpl.offsets[smpl.index("left_knee")]
    assert knee[1] < 0                                        # world-aligned: the thigh hangs down
