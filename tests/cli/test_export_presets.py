"""`interplay export` (cli/files.py): the BVH presets as flags (--fps, --units, --up, --names),
read back by bvhio (a parser nobody here wrote), exit 2 on bad values, and the version-2
JSON with each person's rig."""

from __future__ import annotations

import json

import numpy as np
import pytest

from interplay.cli import main as cli
from interplay.motion.clip import default_clips
from interplay.motion.formats.bvh import UNITS, Z_UP, joint_names
from interplay.motion.kinematics import fit_to_skeleton
from interplay.motion.motion import Motion
from interplay.motion.rig import rig_from_json, rig_positions
from tests.helpers.bvh_readers import bvhio_positions
from tests.helpers.gltf_files import accessor, load, rigs_of


@pytest.fixture(scope="module")
def pair_file(tmp_path_factory):
    """A two-person motion file: a captured pair, on fixed bones, 2 s."""
    clip = next(c for c in default_clips() if len(c.people) == 2)
    people = [fit_to_skeleton(np.asarray(p[:40], dtype=np.float64))[0] for p in clip.people]
    path = tmp_path_factory.mktemp("export") / "pair.json"
    path.write_text(json.dumps(Motion(people=people, prompt=clip.prompt).to_json()))
    return path


@pytest.mark.parametrize("flags", [
    ["--fps", "24", "--units", "cm", "--up", "z", "--names", "mixamo", "--person", "1"],
    ["--fps", "60"], ["--fps", "30", "--up", "z"], []])
def test_bvh_presets_from_flags_read_back_in_bvhio(pair_file, tmp_path, flags):
    out = tmp_path / "p.bvh"
    assert cli.main(["export", str(pair_file), "--format", "bvh", "--out", str(out), *flags]) == 0
    opts = dict(zip(flags[::2], flags[1::2]))
    fps, units = int(opts.get("--fps", 20)), opts.get("--units", "m")
    got, frames, frame_time = bvhio_positions(out, joint_names(opts.get("--names", "smpl")))
    assert frames == int(np.ceil(39 / 20 * fps - 1e-6)) + 1 and abs(1 / frame_time - fps) < 1e-3
    if opts.get("--up") == "z":
        got = got @ Z_UP
    got = got / UNITS[units]
    joints = Motion.from_json(json.loads(pair_file.read_text())).people[int(opts.get("--person", 0))]
    every = fps // np.gcd(20, fps)
    shared = got[::every]
    want = joints[::20 // np.gcd(20, fps)][:len(shared)]
    assert np.abs(shared - want).max() < 1e-3


@pytest.mark.parametrize("flags,msg", [
    (["--format", "bvh", "--fps", "25"], "invalid choice"), (["--format", "bvh", "--units", "mm"], "invalid choice"),
    (["--format", "bvh", "--up", "x"], "invalid choice"), (["--format", "bvh", "--names", "ue"], "invalid choice"),
    (["--format", "json", "--fps", "30"], "--format bvh or glb only"),
    (["--format", "glb", "--up", "z"], "BVH only"), (["--format", "glb", "--fps", "25"], "invalid choice")])
def test_bad_presets_exit_2_with_a_message(pair_file, tmp_path, capsys, flags, msg):
    with pytest.raises(SystemExit) as exc:
        code = cli.main(["export", str(pair_file), "--out", str(tmp_path / "x"), *flags])
        raise SystemExit(code)
    assert exc.value.code == 2
    assert msg in capsys.readouterr().err


@pytest.mark.parametrize("fps", [24, 30, 60])
def test_glb_presets_from_flags_exact_length_cm_mixamo(pair_file, tmp_path, fps):
    out = tmp_path / "p.glb"
    flags = ["--fps", str(fps), "--units", "cm", "--names", "mixamo"]
    assert cli.main(["export", str(pair_file), "--format", "glb", "--out", str(out), *flags]) == 0
    doc, blob = load(out.read_bytes())
    # 40 frames at 20 fps last 1.95 s: at 24 fps 46.8 frame steps, rounded up to keep the end.
    frames = int(np.ceil(39 / 20 * fps - 1e-6)) + 1
    assert doc.extras["fps"] == fps and doc.extras["frames"] == frames and doc.extras["units"] == "cm"
    sampler = doc.animations[0].samplers[0]
    assert np.allclose(accessor(doc, blob, sampler.input), np.arange(frames) / fps)
    people = Motion.from_json(json.loads(pair_file.read_text())).people
    for k, (skin, rig) in enumerate(zip(doc.skins, rigs_of(people, fps))):
        names = [doc.nodes[n].name for n in skin.joints]
        # Mixamo's names, each person's apart, and its end bones.
        assert names[:22] == [f"person{k + 1}_{n}" for n in joint_names("mixamo")]
        assert f"person{k + 1}_mixamorig:HeadTop_End" in names and len(names) == 27
        hips = doc.nodes[skin.joints[0]]
        root = next(ch for ch in doc.animations[0].channels
                    if ch.target.node == skin.joints[0] and ch.target.path == "translation")
        # Centimetres: the root's keys are the (lifted, resampled) rig's × 100, the last is the
        # motion's last pose.
        keys = accessor(doc, blob, doc.animations[0].samplers[root.sampler].output)
        assert np.abs(keys - rig.root * 100).max() < 0.01
        assert np.abs(keys[-1, [0, 2]] - people[k][-1, 0, [0, 2]] * 100).max() < 0.1
        assert np.linalg.norm(hips.translation) > 50          # the hips' rest height, in cm


def test_json_export_is_version_2_and_reads_back(pair_file, tmp_path):
    out = tmp_path / "m.json"
    assert cli.main(["export", str(pair_file), "--format", "json", "--out", str(out)]) == 0
    d = json.loads(out.read_text())
    assert d["schema"] == "interplay.motion/2" and len(d["joint_names"]) == 22
    people = Motion.from_json(d).people
    for person, joints in zip(d["people"], people):
        assert np.abs(rig_positions(rig_from_json(person)) - joints).max() < 1e-3
