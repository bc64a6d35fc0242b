"""Blender's own importers (run headless: `blender -b --python`) on the Mixamo presets: the BVH
(File → Import → Motion Capture) and the GLB (File → Import → glTF 2.0) each become an
armature whose bones carry Mixamo's names, the scene's frame range covers every frame, and
the bones' heads are where the motion has the joints (Blender works in metres, Z up).
Skipped, saying so, where Blender is not installed (Debian: `apt-get install blender`)."""

from __future__ import annotations

import json
import shutil
import subprocess
import textwrap

import numpy as np
import pytest

from interplay.motion.formats.bvh import MIXAMO_NAMES, write_bvh
from interplay.motion.formats.gltf import write_glb
from interplay.motion.rig import rig_positions
from tests.helpers.gltf_files import fixture_people, rigs_of

BLENDER = shutil.which("blender")
pytestmark = pytest.mark.skipif(BLENDER is None, reason="Blender is not installed (apt-get install "
                                                        "blender): its importers are not checked")
# Blender's frame: Z up, the motion's Y up turned by +90° about X, (x, y, z) → (x, -z, y).
Y_TO_Z = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])

SCRIPT = textwrap.dedent("""
    import bpy, json, sys
    path, kind, out, frames = sys.argv[-4], sys.argv[-3], sys.argv[-2], json.loads(sys.argv[-1])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = 20
    if kind == "bvh":
        # Debian's Blender 3.4.1 runs Python 3.11, where its BVH importer's open(path, "rU")
        # fails: the importer's open without the "U".
        import io_anim_bvh.import_bvh as importer
        importer.open = lambda f, mode="r", *a, **k: open(f, mode.replace("U", ""), *a, **k)
        bpy.ops.import_anim.bvh(filepath=path, axis_forward="-Z", axis_up="Y",
                                update_scene_fps=True, update_scene_duration=True)
    else:
        # … and its glTF importer uses np.bool, gone from Debian's numpy 1.24.
        import numpy
        numpy.bool = bool
        bpy.ops.import_scene.gltf(filepath=path)
    arm = next(o for o in scene.objects if o.type == "ARMATURE")
    action = arm.animation_data.action
    result = {"bones": [b.name for b in arm.data.bones], "range": list(action.frame_range),
              "fps": scene.render.fps, "heads": {}}
    for f in frames:
        scene.frame_set(f)
        result["heads"][str(f)] = {b.name: list(arm.matrix_world @ b.head) for b in arm.pose.bones}
    json.dump(result, open(out, "w"))
""")


def blender(tmp_path, path, kind: str, frames: list[int]) -> dict:
    script, out = tmp_path / "run.py", tmp_path / f"{kind}.json"
    script.write_text(SCRIPT)
    run = subprocess.run([BLENDER, "-b", "--factory-startup", "--python", str(script), "--",
                          str(path), kind, str(out), json.dumps(frames)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0 and out.is_file(), run.stderr[-3000:]
    return json.loads(out.read_text())


def test_blender_imports_the_mixamo_bvh_onto_a_mixamo_named_armature(tmp_path):
    (joints,) = fixture_people("spam_wave")
    path = tmp_path / "wave.bvh"
    path.write_text(write_bvh(joints, names="mixamo"))
    got = blender(tmp_path, path, "bvh", [1, 30])
    assert set(MIXAMO_NAMES) <= set(got["bones"])
    assert got["range"][1] - got["range"][0] + 1 >= len(joints)
    for f in (1, 30):
        heads = got["heads"][str(f)]
        want = joints[f - 1] @ Y_TO_Z.T
        for j, name in enumerate(MIXAMO_NAMES):
            assert np.linalg.norm(np.asarray(heads[name]) - want[j]) < 0.01, (f, name)


def test_blender_imports_the_mixamo_glb_with_its_end_bones(tmp_path):
    people = fixture_people("spam_wave")
    path = tmp_path / "wave.glb"
    path.write_bytes(write_glb(people, names="mixamo"))
    got = blender(tmp_path, path, "glb", [0, 20])
    assert set(MIXAMO_NAMES) | {"mixamorig:HeadTop_End", "mixamorig:LeftToe_End"} <= set(got["bones"])
    want = rig_positions(rigs_of(people)[0])
    heads = got["heads"]["20"]
    err = [np.linalg.norm(np.asarray(heads[n]) - want[20, j] @ Y_TO_Z.T) for j, n in enumerate(MIXAMO_NAMES)]
    assert max(err) < 0.01
