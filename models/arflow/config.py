"""Frozen configs of the ARFlow reaction model (scaled down from the paper's 8 × 512 decoder to
~20k pair frames and a shared 2-core CPU).

Representation (both people, one frame): the 22 joints (66 numbers) of each person in the
actor's heading frame at the first frame of the window (actor pelvis at the XZ origin facing +Z,
floor at y = 0). Joints rather than the 239-d rotation features because (a) the flow starts at
the actor's motion, so x₀ and x₁ must live in one space where "actor pose" and "reactor pose"
are comparable, (b) the penetration guidance needs the reactor's joints, and a joint
representation gives its gradient analytically with no decoder to differentiate, and
(c) the relation between the two people (distance, facing) is explicit in the shared frame.
Bones are restored afterwards by IK → FK on fixed bone lengths.

Checkpoints store {"model": state_dict, "config": asdict(cfg)} (`models.common.checkpoint`).
"""

from __future__ import annotations

from dataclasses import dataclass

POSE_DIM = 66              # 22 joints × xyz
TEXT_DIM = 384             # MiniLM sentence embedding


@dataclass(frozen=True)
class ARFlowConfig:
    window: int = 40              # L frames per training window (2 s); runtime sliding window
    d_model: int = 96
    layers: int = 3
    heads: int = 4
    ff: int = 192
    dropout: float = 0.1
    text: bool = True             # optional intent condition (MiniLM embedding of the prompt)
    text_dropout: float = 0.2     # condition dropped to zeros (the "no prompt" case)
    noise: float = 0.1            # σ of the noise added to x₀ (normalised units)
    velocity_weight: float = 0.5  # frame-difference term on the predicted clean reaction
    bone_weight: float = 0.1      # bone-length term (metres², unnormalised)


@dataclass(frozen=True)
class TrainConfig:
    steps: int = 4000
    batch_size: int = 32
    lr: float = 5e-4
    weight_decay: float = 0.01
    warmup: int = 200
    stride: int = 5               # window stride over the clips (frames)
    budget_s: float = 840.0       # wall-clock cap (the brief: ≤ ~15 min)
    eval_every: int = 500
    seed: int = 0
    threads: int = 2
