"""Synthetic forward-kinematics motions (walks, a jump, a two-person dance) and a tiny stand-in
clip set made of them, for testing retrieval and stitching mechanics without the processed
captures. (A uniquely named module, so test files can import it next to other conftests.)"""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import Caption, Clip
from interplay.motion.kinematics import forward_kinematics, rest_rotations
from interplay.motion.rotations import axis_rotation, yaw_matrix

J = sk.JOINT_INDEX


def fk_motion(frames: int, kind: str, speed: float = 1.3, yaw: float = 0.0,
              scale: float = 1.0, phase: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """(joints (T, 22, 3), offsets) of a simple FK motion: "walk" (legs and arms swing, pelvis
    moves forward along its facing), "jump" (crouch, flight, land), "dance" (steps in place)."""
    t = np.arange(frames) / sk.FPS
    offsets = sk.REST_OFFSETS * scale
    rot = rest_rotations(frames)
    root = np.zeros((frames, 3))
    root[:, 1] = offsets[0, 1]
    cyc = 2 * np.pi * 0.9 * t + phase
    if kind in ("walk", "dance"):
        swing = 0.45 * np.sin(cyc) if kind == "walk" else 0.25 * np.sin(2 * cyc)
        rot[:, J["left_hip"]] = axis_rotation("X", -swing)
        rot[:, J["right_hip"]] = axis_rotation("X", swing)
        rot[:, J["left_knee"]] = axis_rotation("X", 0.5 * np.maximum(0, np.sin(cyc + 1)))
        rot[:, J["right_knee"]] = axis_rotation("X", 0.5 * np.maximum(0, -np.sin(cyc + 1)))
        rot[:, J["left_shoulder"]] = axis_rotation("Z", -1.2) @ axis_rotation("X", swing)
        rot[:, J["right_shoulder"]] = axis_rotation("Z", 1.2) @ axis_rotation("X", -swing)
        root[:, 1] += 0.02 * np.cos(2 * cyc)
        if kind == "walk":
            root[:, 2] = speed * t
        else:
            root[:, 0] = 0.1 * np.sin(cyc)
            rot[:, J["spine1"]] = axis_rotation("Y", 0.3 * np.sin(cyc))
    elif kind == "jump":
        crouch = np.clip(np.sin(np.pi * t / t[-1]) * 1.5, 0, 1)
        flight = np.clip(np.sin(2 * np.pi * (t / t[-1] - 0.3)), 0, None)
        rot[:, J["left_knee"]] = rot[:, J["right_knee"]] = axis_rotation("X", 0.9 * crouch * (1 - flight))
        root[:, 1] += 0.45 * flight - 0.25 * crouch * (1 - flight)
        root[:, 2] = 0.3 * flight
    else:
        raise ValueError(kind)
    rot[:, 0] = yaw_matrix(np.full(frames, yaw))
    root[:, [0, 2]] = root[:, [0, 2]] @ yaw_matrix(yaw)[[0, 2]][:, [0, 2]].T
    joints, _ = forward_kinematics(rot, root, offsets)
    joints[..., 1] -= joints[..., 1].min()
    return joints.astype(np.float32), offsets.astype(np.float32)


def stand_in_clips() -> list[Clip]:
    clips = []
    for i, (frames, speed, split) in enumerate([(70, 1.3, "train"), (90, 1.1, "train"),
                                                (80, 1.4, "test")]):
        j, off = fk_motion(frames, "walk", speed=speed, scale=1.0 + 0.04 * i, phase=i)
        clips.append(Clip(id=f"synth:walk{i}", source="synthetic", people=[j], offsets=[off],
                          label="walk", prompt="a person walks forward", split=split,
                          captions=[Caption(10, 40, "body", "the person walks")], synthetic=True))
    j, off = fk_motion(40, "jump")
    clips.append(Clip(id="synth:jump", source="synthetic", people=[j], offsets=[off], label="jump",
                      prompt="a person jumps", synthetic=True))
    a, off_a = fk_motion(100, "dance")
    b, off_b = fk_motion(100, "dance", yaw=np.pi, scale=0.93, phase=np.pi)
    b[..., 2] += 0.7
    clips.append(Clip(id="synth:salsa", source="synthetic", people=[a, b], offsets=[off_a, off_b],
                      label="salsa dance", prompt="two people dance salsa", synthetic=True))
    return clips
