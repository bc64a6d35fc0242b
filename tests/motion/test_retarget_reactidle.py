"""ReActIdle's rigify-named BVH → 22 joints: a figure with the same joint names (offsets made
up here, a slow sway) is mapped, fitted and canonicalised with its rate recorded."""

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.retarget.reactidle import JOINT_MAP, load_reactidle, reactidle_prompt

# name, parent, offset (metres): the layout the module docstring describes.
JOINTS = [
    ("pelvis", None, (0.0, 0.0, 0.0)), ("spine", "pelvis", (0.0, 0.0, 0.0)),
    ("spine.001", "spine", (0.0, 0.22, 0.0)), ("neck", "spine.001", (0.0, 0.22, 0.0)),
    ("face", "neck", (0.0, 0.15, 0.02)),
    ("shoulder.L", "spine.001", (0.0, 0.22, 0.0)), ("upper_arm.L", "shoulder.L", (0.17, 0.0, 0.0)),
    ("forearm.L", "upper_arm.L", (0.0, -0.28, 0.0)),
    ("shoulder.R", "spine.001", (0.0, 0.22, 0.0)), ("upper_arm.R", "shoulder.R", (-0.17, 0.0, 0.0)),
    ("forearm.R", "upper_arm.R", (0.0, -0.28, 0.0)),
    ("thigh.L", "pelvis", (0.09, 0.0, 0.0)), ("shin.L", "thigh.L", (0.0, -0.4, 0.0)),
    ("foot.L", "shin.L", (0.0, -0.4, 0.0)),
    ("thigh.R", "pelvis", (-0.09, 0.0, 0.0)), ("shin.R", "thigh.R", (0.0, -0.4, 0.0)),
    ("foot.R", "shin.R", (0.0, -0.4, 0.0)),
]
ENDS = {"face": (0.0, 0.1, 0.0), "forearm.L": (0.0, -0.25, 0.0), "forearm.R": (0.0, -0.25, 0.0),
        "foot.L": (0.0, -0.06, 0.13), "foot.R": (0.0, -0.06, 0.13)}


def _bvh(frames: int = 72, fps: float = 24.0) -> str:
    kids: dict = {}
    for name, parent, _ in JOINTS:
        kids.setdefault(parent, []).append(name)
    offsets = {name: off for name, _, off in JOINTS}
    lines, order = ["HIERARCHY"], []

    def emit(name, depth):
        pad = "\t" * depth
        head = "ROOT" if depth == 0 else "JOINT"
        chans = "6 Xposition Yposition Zposition Zrotation Xrotation Yrotation" if depth == 0 else \
            "3 Zrotation Xrotation Yrotation"
        lines.extend([f"{pad}{head} {name}", f"{pad}{{", f"{pad}\tOFFSET {' '.join(map(str, offsets[name]))}",
                      f"{pad}\tCHANNELS {chans}"])
        order.append(name)
        for k in kids.get(name, []):
            emit(k, depth + 1)
        if name in ENDS:
            lines.extend([f"{pad}\tEnd Site", f"{pad}\t{{", f"{pad}\t\tOFFSET {' '.join(map(str, ENDS[name]))}",
                          f"{pad}\t}}"])
        lines.append(f"{pad}}}")

    emit("pelvis", 0)
    lines += ["MOTION", f"Frames: {frames}", f"Frame Time: {1 / fps:.6f}"]
    for t in range(frames):
        sway = 0.02 * np.sin(2 * np.pi * t / frames)
        row = [sway, 0.0, 0.0, 0.0, 0.0, 0.0] + [0.0] * 3 * (len(order) - 1)
        row[order.index("spine.001") * 3 + 3 + 1] = 3.0 * np.sin(2 * np.pi * t / frames)  # a slow lean
        lines.append(" ".join(f"{v:.5f}" for v in row))
    return "\n".join(lines) + "\n"


def test_a_reactidle_figure_maps_onto_22_joints_on_the_floor(tmp_path):
    path = tmp_path / "003_genuine.bvh"
    path.write_text(_bvh())
    joints, offsets, meta = load_reactidle(path)
    assert joints.shape == (60, sk.NUM_JOINTS, 3) and offsets.shape == (sk.NUM_JOINTS, 3)
    assert meta["source_fps"] == pytest.approx(24.0, abs=0.01) and meta["defects"] == []
    assert meta["fit_error_mean_mm"] < 20
    assert abs(float(joints[..., 1].min())) < 0.02                     # feet on the floor
    j = sk.JOINT_INDEX
    assert joints[0, j["head"], 1] > joints[0, j["neck"], 1] > joints[0, j["pelvis"], 1]
    assert joints[0, j["left_hip"], 0] > joints[0, j["right_hip"], 0]  # left is +X
    # The foot joint is ahead of the ankle: the figure faces +Z.
    assert joints[0, j["left_foot"], 2] > joints[0, j["left_ankle"], 2]


def test_every_smpl_joint_is_mapped_and_the_prompts_are_known():
    assert set(JOINT_MAP) == set(sk.JOINT_NAMES)
    assert "idle" in reactidle_prompt("acted") and "idle" in reactidle_prompt("genuine")
    with pytest.raises(ValueError):
        reactidle_prompt("other")


def test_a_file_of_another_skeleton_is_refused(tmp_path):
    path = tmp_path / "x.bvh"
    path.write_text(_bvh().replace("face", "skull"))
    with pytest.raises(ValueError, match="not a ReActIdle BVH"):
        load_reactidle(path)
