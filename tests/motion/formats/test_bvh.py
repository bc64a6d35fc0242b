import json
import shutil
import subprocess

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh, smpl22_positions, write_bvh
from interplay.motion.kinematics import fit_to_skeleton
from interplay.motion.retarget.cmu_daz import load_cmu_bvh, load_salsa_pair
from tests.helpers.bvh_readers import bvhio_positions
from tests.helpers.paths import REPO

RAW = REPO / "tests" / "fixtures" / "raw"

# Position channels interleaved with rotations on the root, a child with one rotation and a
# Y-only position channel, a "YXZ" joint, another ZXY branch, two End Sites; CRLF and tabs.
HAND_WRITTEN = "\r\n".join([
    "HIERARCHY",
    "ROOT Hips",
    "{",
    "\tOFFSET 0 0 0",
    "\tCHANNELS 6 Xrotation Zposition Yrotation Xposition Zrotation Yposition",
    "\tJOINT Slide",
    "\t{",
    "\t\tOFFSET 0.5 1 0",
    "\t\tCHANNELS 2 Zrotation Yposition",
    "\t\tJOINT Tip",
    "\t\t{",
    "\t\t  OFFSET   1 0 0",
    "\t\t  CHANNELS 3 Yrotation Xrotation Zrotation",
    "\t\t  End Site",
    "\t\t  {",
    "\t\t\tOFFSET 0 2 0",
    "\t\t  }",
    "\t\t}",
    "\t}",
    "\tJOINT Other",
    "\t{",
    "\t\tOFFSET 0 -1 0",
    "\t\tCHANNELS 3 Zrotation Xrotation Yrotation",
    "\t\tEnd Site",
    "\t\t{",
    "\t\t\tOFFSET 0 -1 0",
    "\t\t}",
    "\t}",
    "}",
    "MOTION",
    "Frames:\t2",
    "Frame Time:\t0.05",
    # Hips: Xrot Zpos Yrot Xpos Zrot Ypos | Slide: Zrot Ypos | Tip: Yrot Xrot Zrot | Other: Zrot Xrot Yrot
    "90 5 0 1 0 2   90 3   90 90 0   90 0 0",
    "0 0 0 0 0 0    0 1    0 0 0     0 0 0",
    "",
])

# Worked by hand: Rx(90) maps (x, y, z) → (x, -z, y), Rz(90) (x, y, z) → (-y, x, z),
# Ry(90) (x, y, z) → (z, y, -x). Frame 0: Hips at (1, 2, 5); Slide = Hips + Rx·(0.5, 3, 0)
# (its Y position channel replaces the offset's y); Tip = Slide + Rx·Rz·(1, 0, 0);
# Tip's End Site = Tip + Rx·Rz·Ry·Rx·(0, 2, 0); Other = Hips + Rx·(0, -1, 0); its End Site
# = Other + Rx·Rz·(0, -1, 0).
EXPECTED = np.array([
    # Hips        Slide          Tip            Other        Tip end         Other end
    [[1, 2, 5], [1.5, 2, 8], [1.5, 2, 9], [1, 2, 4], [1.5, 2, 11], [2, 2, 4]],
    [[0, 0, 0], [0.5, 1, 0], [1.5, 1, 0], [0, -1, 0], [1.5, 3, 0], [0, -2, 0]],
], dtype=float)


def test_reader_matches_hand_computed_positions():
    bvh = read_bvh(HAND_WRITTEN)
    assert bvh.names == ("Hips", "Slide", "Tip", "Other")
    assert bvh.parents == (-1, 0, 1, 0)
    assert bvh.channels[1] == ("Zrotation", "Yposition")
    assert bvh.fps == pytest.approx(20.0) and bvh.num_frames == 2
    assert bvh.end_site_names == ("Tip_end", "Other_end")
    assert np.allclose(bvh.positions(), EXPECTED[:, :4], atol=1e-12)
    assert np.allclose(bvh.positions(include_end_sites=True), EXPECTED, atol=1e-12)
    named = bvh.named_positions()
    assert np.allclose(named["Tip_end"], EXPECTED[:, 4], atol=1e-12)


def test_reader_accepts_a_path_and_plain_newlines(tmp_path):
    path = tmp_path / "hand.bvh"
    path.write_text(HAND_WRITTEN.replace("\r\n", "\n"))
    assert np.allclose(read_bvh(path).positions(), read_bvh(str(path)).positions())
    assert np.allclose(read_bvh(path).positions(True), EXPECTED, atol=1e-12)


@pytest.mark.parametrize("broken,word", [
    (HAND_WRITTEN.replace("MOTION", "MOTIONS"), "MOTION"),
    (HAND_WRITTEN.replace("Yposition\r\n\t\tJOINT", "Yspin\r\n\t\tJOINT"), "CHANNELS"),
    (HAND_WRITTEN.replace("Frames:\t2", "Frames:\t3"), "3 frames"),
    (HAND_WRITTEN.replace("\t}\r\n\tJOINT Other", "\tJOINT Other"), "brace"),
    (HAND_WRITTEN.replace("0 0 0     0 0 0", "0 0 0     0 x 0"), "number"),
    ("just some text", "no such file"),
])
def test_reader_rejects_malformed_files_with_a_reason(broken, word):
    with pytest.raises(ValueError, match=word):
        read_bvh(broken)


def test_cmu_daz_file_has_the_expected_hierarchy():
    bvh = read_bvh(RAW / "cmu-bvh" / "02" / "02_01.bvh")
    assert bvh.names[:3] == ("hip", "abdomen", "chest") and len(bvh.names) == 43
    assert bvh.channels[0][:3] == ("Xposition", "Yposition", "Zposition")
    assert bvh.fps == pytest.approx(120, rel=1e-4) and bvh.num_frames == 344
    pos = bvh.named_positions()
    # Frame 0 is the converter's T-pose: hands level with the shoulders, 1.5 m eye height.
    assert abs(pos["lHand"][0, 1] - pos["lShldr"][0, 1]) < 2.0
    eyes = (pos["leftEye"][0, 1] + pos["rightEye"][0, 1]) / 2
    assert 145 < eyes - pos["lFoot_end"][0, 1] < 160


@pytest.fixture(scope="module")
def real_clips():
    walk = load_cmu_bvh(RAW / "cmu-bvh" / "02" / "02_01.bvh")[0]
    jump = load_cmu_bvh(RAW / "cmu-bvh" / "16" / "16_01.bvh")[0]
    (lead, follow), _, _ = load_salsa_pair(RAW / "cmu-salsa" / "60" / "60_01_scaled.bvh",
                                           RAW / "cmu-salsa" / "61" / "61_01_scaled.bvh")
    return {"walk": walk, "jump": jump, "lead": lead[:200], "follow": follow[:200]}


def assert_lifted(back: np.ndarray, joints: np.ndarray, most: float = 0.01) -> np.ndarray:
    """back (T, 22, 3) is joints within 1 mm but for a vertical lift of the whole body on
    some frames (the floor pass's), at most `most` metres; returns the lift (T,)."""
    diff = back - joints
    assert np.abs(diff[..., [0, 2]]).max() < 1e-3
    lift = np.median(diff[..., 1], axis=1)
    assert np.abs(diff[..., 1] - lift[:, None]).max() < 1e-3
    assert -1e-3 < lift.min() and lift.max() < most
    return lift


@pytest.mark.parametrize("name", ["walk", "jump", "lead", "follow"])
def test_write_then_read_reproduces_fitted_joints_within_1mm(real_clips, name):
    joints = real_clips[name]
    text = write_bvh(joints)
    back = smpl22_positions(read_bvh(text))
    assert back.shape == joints.shape
    # Exactly, but where a foot's joints or toe tip dip more than 8 mm under the floor (the
    # salsa capture's, by up to 1.3 cm): there the whole body is lifted out.
    lift = assert_lifted(back, joints)
    assert np.mean(lift > 1e-3) < 0.1
    # With the offsets given explicitly, too.
    fitted, offsets = fit_to_skeleton(joints)
    assert_lifted(smpl22_positions(read_bvh(write_bvh(joints, offsets=offsets))), fitted)


def test_written_file_is_a_standard_hierarchy(real_clips):
    text = write_bvh(real_clips["walk"], fps=20)
    lines = text.splitlines()
    assert lines[0] == "HIERARCHY" and lines[1] == "ROOT pelvis"
    assert sum(line.strip().startswith("JOINT ") for line in lines) == 21
    assert sum(line.strip() == "End Site" for line in lines) == 5
    assert sum("CHANNELS 3 " in line for line in lines) == 21
    assert "\tCHANNELS 6 Xposition Yposition Zposition" in text
    assert "Frame Time: 0.05000000" in text and f"Frames: {len(real_clips['walk'])}" in text
    assert all(not line.startswith(" ") for line in lines)           # tabs only
    assert "nan" not in text and "-0.000000 " not in text and "e-" not in text
    bvh = read_bvh(text)
    assert set(bvh.names) == set(sk.JOINT_NAMES)
    assert np.allclose(bvh.offsets[0], 0)                              # root OFFSET 0
    # Head, wrists and toes end the chains.
    ends = {bvh.names[p] for p, _ in bvh.end_sites}
    assert ends == {"head", "left_wrist", "right_wrist", "left_foot", "right_foot"}


@pytest.mark.parametrize("bad,word", [
    (np.zeros((10, 21, 3)), "22"), (np.zeros((0, 22, 3)), "T ≥ 1"),
    (np.full((4, 22, 3), np.nan), "NaN"),
])
def test_writer_rejects_bad_input(bad, word):
    with pytest.raises(ValueError, match=word):
        write_bvh(bad)


THREE = REPO / "node_modules" / "three"
NODE_CHECK = """
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
const [three, { BVHLoader }] = await Promise.all([
  import(pathToFileURL(process.argv[2] + '/build/three.module.js').href),
  import(pathToFileURL(process.argv[2] + '/examples/jsm/loaders/BVHLoader.js').href)]);
const result = new BVHLoader().parse(readFileSync(process.argv[3], 'utf8'));
const bones = result.skeleton.bones, mixer = new three.AnimationMixer(bones[0]);
const action = mixer.clipAction(result.clip);
action.setLoop(three.LoopOnce); action.clampWhenFinished = true; action.play();
const out = {}, v = new three.Vector3();
for (let f = 0; f < Number(process.argv[4]); f++) {
  mixer.setTime(f * Number(process.argv[5]));
  bones[0].updateMatrixWorld(true);
  for (const b of bones) if (b.name !== 'ENDSITE') (out[b.name] ??= []).push(b.getWorldPosition(v).toArray());
}
console.log(JSON.stringify(out));
"""


@pytest.mark.skipif(shutil.which("node") is None or not THREE.is_dir(),
                    reason="node or three (npm workspace) not installed")
def test_threejs_bvhloader_reads_our_file_to_the_same_joints(real_clips, tmp_path):
    joints = real_clips["jump"][:40]
    (tmp_path / "a.bvh").write_text(write_bvh(joints))
    (tmp_path / "check.mjs").write_text(NODE_CHECK)
    run = subprocess.run(["node", str(tmp_path / "check.mjs"), str(THREE), str(tmp_path / "a.bvh"),
                          str(len(joints)), "0.05"], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    out = json.loads(run.stdout)
    got = np.stack([np.array(out[n]) for n in sk.JOINT_NAMES], axis=1)
    assert np.abs(got - joints).max() < 1e-3


# --- Presets, read back by a parser nobody here wrote (bvhio, a dev dependency) ------------

PRESETS = [  # fps, units, up, names: every value of each at least once
    (20, "m", "y", "smpl"), (24, "cm", "z", "mixamo"), (30, "m", "z", "smpl"),
    (60, "cm", "y", "mixamo"), (24, "m", "y", "smpl"),
]


@pytest.mark.parametrize("fps,units,up,names", PRESETS)
def test_each_preset_reads_back_in_bvhio_within_1mm(real_clips, tmp_path, fps, units, up, names):
    from interplay.motion.formats.bvh import UNITS, Z_UP, joint_names
    from interplay.motion.formats.presets import resample_rig
    from interplay.motion.rig import rig_positions, solve_rig
    joints, _ = fit_to_skeleton(real_clips["jump"][:60])          # on fixed bones, 20 fps
    path = tmp_path / "a.bvh"
    path.write_text(write_bvh(joints, out_fps=fps, units=units, up=up, names=names))
    got, frames, frame_time = bvhio_positions(path, joint_names(names))
    # The requested rate: frames over the same duration, rounded up so that the last pose
    # is kept (the last frame holds it), and the header's Frame Time.
    assert frames == int(np.ceil((len(joints) - 1) / 20 * fps - 1e-6)) + 1
    assert np.abs(got[-1] / UNITS[units] @ (Z_UP if up == "z" else np.eye(3)) - joints[-1]).max() < 1e-3
    assert abs(1.0 / frame_time - fps) < 1e-3
    # Undo units and up axis: back to metres, Y up (v_y = Z_UP^T v_z).
    if up == "z":
        got = got @ Z_UP
    got = got / UNITS[units]
    # At the times both rates share (every 20/gcd-th source frame) the file is the motion.
    step = 20 // np.gcd(20, fps)
    shared = got[::fps // np.gcd(20, fps)]
    assert np.abs(shared - joints[::step][:len(shared)]).max() < 1e-3
    # Every frame is the resampled rig (rotations slerped), and near the straight-line blend.
    want = rig_positions(resample_rig(solve_rig(joints), 20, fps))
    assert np.abs(got - want).max() < 1e-3
    t = np.minimum(np.arange(frames) / fps * 20, len(joints) - 1)
    lo = np.minimum(np.floor(t + 1e-9).astype(int), len(joints) - 1)
    hi = np.minimum(lo + 1, len(joints) - 1)
    w = (t - lo)[:, None, None]
    assert np.abs(got - (joints[lo] * (1 - w) + joints[hi] * w)).max() < 0.03


def test_mixamo_names_map_the_smpl_joints(real_clips):
    from interplay.motion.formats.bvh import MIXAMO_NAMES
    text = write_bvh(real_clips["walk"][:5], names="mixamo")
    bvh = read_bvh(text)
    assert bvh.names[0] == "mixamorig:Hips" and set(bvh.names) == set(MIXAMO_NAMES)
    by = {s: m.removeprefix("mixamorig:") for s, m in zip(sk.JOINT_NAMES, MIXAMO_NAMES)}
    assert [by[n] for n in ("left_collar", "left_shoulder", "left_elbow", "left_wrist")] == \
        ["LeftShoulder", "LeftArm", "LeftForeArm", "LeftHand"]
    assert [by[n] for n in ("right_hip", "right_knee", "right_ankle", "right_foot")] == \
        ["RightUpLeg", "RightLeg", "RightFoot", "RightToeBase"]
    assert [by[n] for n in ("spine1", "spine2", "spine3", "neck", "head")] == \
        ["Spine", "Spine1", "Spine2", "Neck", "Head"]
    # Parents agree: the hierarchy is the same tree under other names.
    for j, p in enumerate(sk.PARENTS):
        if p >= 0:
            assert bvh.parents[bvh.index(MIXAMO_NAMES[j])] == bvh.index(MIXAMO_NAMES[p])
    # The same joints (on Mixamo's rest axes the channels are other angles, each rounded to
    # 1e-4°: a few µm down a limb).
    np.testing.assert_allclose(smpl22_positions(bvh), smpl22_positions(read_bvh(write_bvh(real_clips["walk"][:5]))),
                               atol=1e-5)


def test_z_up_stands_on_z_and_faces_minus_y(real_clips):
    joints = real_clips["walk"][:5]
    pos = smpl22_positions(read_bvh(write_bvh(joints, up="z", units="cm")))
    assert pos[0, sk.HEAD, 2] - pos[0, sk.LEFT_FOOT, 2] > 100        # cm, up along +Z
    np.testing.assert_allclose(pos[..., 2], joints[..., 1] * 100, atol=1e-3)
    np.testing.assert_allclose(pos[..., 1], -joints[..., 2] * 100, atol=1e-3)


@pytest.mark.parametrize("kwargs,word", [
    ({"out_fps": 0}, "fps"), ({"units": "mm"}, "units"), ({"up": "x"}, "up axis"),
    ({"names": "unreal"}, "joint names")])
def test_bad_presets_are_refused_with_the_choices(real_clips, kwargs, word):
    with pytest.raises(ValueError, match=word):
        write_bvh(real_clips["walk"][:5], **kwargs)
