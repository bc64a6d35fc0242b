"""The GLB export checked by readers nobody here wrote, run in Node by gltf_node.mjs beside this
file: the Khronos glTF Validator (npm `gltf-validator`) finds no errors and no warnings, for one
and two people, with and without the mesh, and in the front end's humanoid.glb; three.js's
GLTFLoader + AnimationMixer put every joint where the motion has it, and skin every vertex
where linear blend skinning of the rig does, within 1 mm, at several times."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.formats.gltf import write_glb
from interplay.motion.formats.humanoid import humanoid, on_skeleton
from interplay.motion.rig import global_rotations, rig_positions
from tests.helpers.gltf_files import ASSET, fixture_people, rigs_of
from tests.helpers.paths import REPO as ROOT

SCRIPT = Path(__file__).with_name("gltf_node.mjs")
NODE = shutil.which("node")
MODULES = [ROOT / "node_modules" / m / "package.json" for m in ("three", "gltf-validator")]
MM = 1e-3

pytestmark = [
    pytest.mark.skipif(NODE is None, reason="node is not installed (the GLB readers run in Node)"),
    pytest.mark.skipif(not all(p.is_file() for p in MODULES),
                       reason="three / gltf-validator are not installed: run `npm ci` at the repo root"),
]


def node(*args: str) -> dict:
    out = subprocess.run([NODE, str(SCRIPT), *args], capture_output=True, text=True, timeout=300,
                         cwd=ROOT)
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout)


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    out = tmp_path_factory.mktemp("glb")
    one, two = fixture_people("spam_walk_jump"), fixture_people("coda_hug")
    paths = {}
    for label, people in (("one", one), ("two", two)):
        for mesh in (True, False):
            path = out / f"{label}{'' if mesh else '-skeleton'}.glb"
            path.write_bytes(write_glb(people, fps=20, mesh=mesh))
            paths[label, mesh] = (path, people)
    return paths


def test_the_khronos_validator_finds_no_errors_or_warnings(files):
    paths = [str(p) for p, _ in files.values()] + [str(ASSET)]
    reports = node("validate", *paths)
    for path in paths:
        r = reports[path]
        assert r["errors"] == 0 and r["warnings"] == 0, (path, r["messages"])
        # The one note allowed: the animation-only file's skins, which no mesh uses (they
        # are what makes Blender build an armature).
        assert {m["code"] for m in r["messages"]} <= {"UNUSED_OBJECT"}, (path, r["messages"])


def _skinned(rig, frame: int) -> np.ndarray:
    """Linear blend skinning of the humanoid by the rig at one frame, numpy."""
    mesh = humanoid()
    glob, pos = global_rotations(rig)[frame], rig_positions(rig)[frame]
    rest = sk.rest_joints(rig.offsets)
    v = on_skeleton(mesh, rig.offsets).astype(np.float64)
    out = np.zeros_like(v)
    for s in range(4):
        j, w = mesh.joints[:, s], mesh.weights[:, s].astype(np.float64)
        out += w[:, None] * (np.einsum("vij,vj->vi", glob[j], v - rest[j]) + pos[j])
    return out


@pytest.mark.parametrize("label", ["one", "two"])
def test_threejs_plays_the_joints_and_skins_the_mesh_within_a_millimetre(files, label):
    path, people = files[label, True]
    frames = [0, 13, len(people[0]) // 2, len(people[0]) - 1]
    got = node("sample", str(path), *[str(f / 20) for f in frames])
    assert got["clips"] == [{"name": "motion", "duration": pytest.approx((len(people[0]) - 1) / 20),
                             "tracks": 23 * len(people)}]
    assert len(got["people"]) == len(people)
    for person, rig in zip(got["people"], rigs_of(people)):
        played = np.asarray(person["joints"])                       # (times, 22, 3)
        # The motion's joints, lifted where the mesh would go under the floor.
        err = np.linalg.norm(played - rig_positions(rig)[frames], axis=-1).max()
        assert err < MM, f"joints {err * 1000:.3f} mm off"
        verts = np.asarray(person["vertices"])                      # (times, V, 3)
        for i, f in enumerate(frames):
            err = np.linalg.norm(verts[i] - _skinned(rig, f), axis=-1).max()
            assert err < MM, f"frame {f}: vertices {err * 1000:.3f} mm off"


def test_threejs_plays_the_animation_only_variant(files):
    path, people = files["two", False]
    got = node("sample", str(path), "0.5", "1.45")
    for person, rig in zip(got["people"], rigs_of(people)):
        assert person["vertices"] is None
        played = np.asarray(person["joints"])
        assert np.linalg.norm(played - rig_positions(rig)[[10, 29]], axis=-1).max() < MM


def test_threejs_plays_the_mixamo_rig_at_24_fps_in_centimetres(tmp_path):
    """The presets (--fps 24 --units cm --names mixamo): bones with Mixamo's rest axes (each
    bone's Y along it) and end bones, keyed at 24 fps with the last pose kept; three.js puts
    every joint and vertex where the resampled rig does, in centimetres, within 1 mm."""
    people = fixture_people("coda_hug")
    path = tmp_path / "mixamo.glb"
    path.write_bytes(write_glb(people, fps=20, out_fps=24, units="cm", names="mixamo"))
    report = node("validate", str(path))[str(path)]
    assert report["errors"] == 0 and report["warnings"] == 0, report["messages"]
    rigs = rigs_of(people, 24)
    frames = rigs[0].frames
    assert frames == int(np.ceil((len(people[0]) - 1) / 20 * 24 - 1e-6)) + 1
    keys = [0, 7, frames // 2, frames - 1]
    # The last key a hair early: a looping AnimationMixer at exactly the clip's (float32)
    # duration wraps round to the first frame.
    got = node("sample", str(path), *[str(min(f / 24, (frames - 1) / 24 - 1e-5)) for f in keys])
    assert got["clips"][0]["duration"] == pytest.approx((frames - 1) / 24, abs=1e-4)
    for person, rig in zip(got["people"], rigs):
        # three.js drops the ':' from node names (PropertyBinding.sanitizeNodeName).
        assert person["names"][0].endswith("mixamorigHips") and len(person["names"]) == 27
        played = np.asarray(person["joints"])[:, :22] / 100
        assert np.linalg.norm(played - rig_positions(rig)[keys], axis=-1).max() < MM
        verts = np.asarray(person["vertices"]) / 100
        for i, f in enumerate(keys):
            assert np.linalg.norm(verts[i] - _skinned(rig, f), axis=-1).max() < MM
    # The last key is the motion's last pose (lifted off the floor at most).
    last = rig_positions(rigs[0])[-1] - people[0][-1]
    assert np.abs(last[:, [0, 2]]).max() < MM and np.ptp(last[:, 1]) < MM
