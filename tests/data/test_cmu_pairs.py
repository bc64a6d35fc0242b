"""CMU's two-person trials in the MotionBuilder-named conversion (una-dinosauria/cmu-mocap's
layout, figures made up here): read as Acclaim bones, paired by trial, labelled by CMU's
index, contact windows measured, and the staged build's clear message when the files are absent."""

import json

import numpy as np
import pytest

from interplay.data import build
from interplay.data.cmu_pairs import build_cmu_pairs, pair_kind
from interplay.motion import skeleton as sk
from interplay.motion.clip import load_clips
from interplay.motion.retarget.cmu_daz import load_cmu_bvh

# name, parent, offset in Acclaim units (inches / 0.45); End Sites after the leaves.
SIDE = [("HipJoint", "Hips", (0, 0, 0)), ("UpLeg", "HipJoint", (1.3, -1.9, 0.65)), ("Leg", "UpLeg", (0, -7.5, 0)),
        ("Foot", "Leg", (0, -7.5, 0)), ("ToeBase", "Foot", (0, -0.4, 2.1)),
        ("Shoulder", "Spine1", (0, 0, 0)), ("Arm", "Shoulder", (3.0, 1.3, 0)), ("ForeArm", "Arm", (5.5, 0, 0)),
        ("Hand", "ForeArm", (3.6, 0, 0))]
ENDS = {"ToeBase": (0, 0, 1.0), "Hand": (1.0, 0, 0), "Head": (0, 1.8, 0)}


def _joints():
    out = [("Hips", None, (0, 0, 0)), ("LowerBack", "Hips", (0, 0, 0)), ("Spine", "LowerBack", (0, 2.07, 0)),
           ("Spine1", "Spine", (0, 2.09, 0)), ("Neck", "Spine1", (0, 0, 0)), ("Neck1", "Neck", (0, 1.8, 0)),
           ("Head", "Neck1", (0, 1.79, 0))]
    for side, sign in (("Left", 1), ("Right", -1)):
        for name, parent, (x, y, z) in SIDE:
            full = ("L" if side == "Left" else "R") + name if name == "HipJoint" else side + name
            par = parent if parent in ("Hips", "Spine1") else (
                ("L" if side == "Left" else "R") + parent if parent == "HipJoint" else side + parent)
            out.append((full, par, (sign * x, y, z)))
    return out


def _bvh(x: float, frames: int = 240) -> str:
    joints = _joints()
    kids: dict = {}
    for name, parent, _ in joints:
        kids.setdefault(parent, []).append(name)
    offsets = {n: o for n, _, o in joints}
    lines, order = ["HIERARCHY"], []

    def emit(name, depth):
        pad = "\t" * depth
        chans = "6 Xposition Yposition Zposition Zrotation Yrotation Xrotation" if depth == 0 else \
            "3 Zrotation Yrotation Xrotation"
        lines.extend([f"{pad}{'ROOT' if depth == 0 else 'JOINT'} {name}", f"{pad}{{",
                      f"{pad}\tOFFSET {' '.join(map(str, offsets[name]))}", f"{pad}\tCHANNELS {chans}"])
        order.append(name)
        for k in kids.get(name, []):
            emit(k, depth + 1)
        leaf = name[4:] if name.startswith("Left") else name[5:] if name.startswith("Right") else name
        if leaf in ENDS:
            ex, ey, ez = ENDS[leaf]
            ex = -ex if name.startswith("Right") else ex
            lines.extend([f"{pad}\tEnd Site", f"{pad}\t{{", f"{pad}\t\tOFFSET {ex} {ey} {ez}", f"{pad}\t}}"])
        lines.append(f"{pad}}}")

    emit("Hips", 0)
    lines += ["MOTION", f"Frames: {frames}", "Frame Time: .0083333"]
    for t in range(frames):
        row = [x + 0.3 * np.sin(t / 40.0), 17.8, 0.0] + [0.0] * (3 + 3 * (len(order) - 1))
        lines.append(" ".join(f"{v:.4f}" for v in row))
    return "\n".join(lines) + "\n"


@pytest.fixture
def raw(tmp_path):
    """Subjects 18 and 19 side by side, their near hands touching (x in Acclaim units)."""
    pairs = tmp_path / "cmu-pairs"
    for subject, x in ((18, 0.0), (19, 25.5)):
        folder = pairs / f"{subject:03d}"
        folder.mkdir(parents=True)
        (folder / f"{subject}_01.bvh").write_text(_bvh(x))
    index = tmp_path / "cmu-index"
    index.mkdir()
    (index / "cmu_index.csv").write_text(
        'Subject,Trial #,Motion Description,framerate\n'
        '18,1,"walk, shake hands (2 subjects - subject A)",120\n'
        '19,1,"walk, shake hands (2 subjects - subject B)",120\n')
    return tmp_path


def test_the_motionbuilder_named_conversion_reads_as_acclaim_bones(raw):
    joints, offsets, meta = load_cmu_bvh(raw / "cmu-pairs" / "018" / "18_01.bvh", fps=120)
    assert meta["skeleton"] == "cmu-acclaim" and joints.shape[1:] == (sk.NUM_JOINTS, 3)
    assert 1.4 < meta["rest_height_m"] < 2.0
    j = sk.JOINT_INDEX
    assert joints[0, j["head"], 1] > joints[0, j["neck"], 1] > joints[0, j["pelvis"], 1] > joints[0, j["left_knee"], 1]


def test_pairs_are_built_with_their_kind_and_measured_contacts(raw):
    skipped: list = []
    clips = build_cmu_pairs(raw / "cmu-pairs", raw / "cmu-index" / "cmu_index.csv", skipped)
    assert [c.id for c in clips] == ["cmu-pair:18_01"] and skipped == []
    c = clips[0]
    assert len(c.people) == 2 and c.people[0].shape == c.people[1].shape
    assert c.meta["kind"] == "handshake" and c.prompt.startswith("two people")
    assert c.label == "walk, shake hands" and c.meta["index_fps"] == 120
    windows = c.meta["contact_windows"]
    assert windows and {w["hand"] for w in windows} <= {"left", "right"}
    json.dumps(c.meta)                                   # the index can store it


def test_staged_build_of_pairs_from_shared_and_its_absence(raw, tmp_path, capsys):
    out = tmp_path / "out"
    assert build.main(["--staged", "--only", "cmu-pairs", "--source", str(raw), "--mirror", str(tmp_path),
                       "--out", str(out)]) == 0
    clips = load_clips(out)
    assert [c.source for c in clips] == ["cmu-pairs"]
    card = (out / "README.md").read_text()
    assert "measured contact windows" in card and "cmu-pair:18_01" in card
    empty = tmp_path / "empty"
    empty.mkdir()
    assert build.main(["--staged", "--only", "cmu-pairs", "--source", str(empty), "--mirror", str(tmp_path),
                       "--out", str(tmp_path / "out2")]) == 2
    err = capsys.readouterr().err
    assert "una-dinosauria/cmu-mocap" in err and "cmu-pairs" in err


def test_kinds_from_cmu_descriptions():
    assert pair_kind("B sits; A pulls up B (subjects - subject B)")[0] == "help_up"
    assert pair_kind("A passes soda to B; both drink (2 subjects - subject A)")[0] == "hand_over"
    assert pair_kind("rush up, arm wrestle (2 subjects - subject A)")[0] == "arm_wrestle"
    assert pair_kind("football - throw, catch (2 subjects - subject A)")[0] == "throw_catch"
    assert pair_kind("high-five, walk (2 subjects - subject A)")[0] == "high_five"


def test_pairs_are_found_in_the_newer_data_layout_and_flat(raw, tmp_path):
    """una-dinosauria's newer commits keep the subjects under data/0SS/; a flat copy works too."""
    index = raw / "cmu-index" / "cmu_index.csv"
    for layout in ("data/{s:03d}", "flat"):
        root = tmp_path / layout.split("/")[0] / "copy"
        for s in (18, 19):
            folder = root / ("." if layout == "flat" else layout.format(s=s))
            folder.mkdir(parents=True, exist_ok=True)
            (folder / f"{s}_01.bvh").write_text((raw / "cmu-pairs" / f"{s:03d}" / f"{s}_01.bvh").read_text())
        assert [c.id for c in build_cmu_pairs(root, index)] == ["cmu-pair:18_01"]
